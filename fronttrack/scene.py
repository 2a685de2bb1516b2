"""The scene: what a plane-wave experiment is made of.

A scene is a stack of plane layers along the Lagrangian coordinate ``X`` (the
first layer starts at ``X = 0``), the conditions at its two ends, the contacts
between neighbouring layers, the time to follow it to, the probes to record and
the accuracy wanted.  All quantities are SI.  An impact is two neighbouring
layers with different initial velocities.  Scenes are built in Python or read
from TOML (``fronttrack.scene_file``); both paths end in ``Scene.validate``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from materials import Material, MaterialError, State, StateOutOfRangeError, WavediagramError

BOUNDARY_KINDS = ("free", "wall", "velocity", "stress")
BONDS = ("bonded", "unbonded")
RELEASE_PATHS = ("isentrope", "hugoniot")


class SceneError(WavediagramError, ValueError):
    """A scene field is missing or outside its allowed range; the message names the field."""


@dataclass(frozen=True)
class Layer:
    """One plate: ``material``, ``thickness`` (m), initial ``velocity`` (m/s) and ``stress`` (Pa).

    ``bond`` is the contact with the previous layer: ``"bonded"`` (carries
    tension up to the weaker material's spall strength) or ``"unbonded"`` (opens
    a gap under any tension).  An initial stress is reached from the reference
    state along the material's wave curve (a shock if compressive, the
    isentrope if tensile).  ``initial``, if given, is the exact initial state
    (``State`` with stress, velocity, volume and energy) and replaces
    ``velocity`` and ``stress``: a gas at a given density and pressure, or a
    layer already shocked.
    """

    material: Material
    thickness: float
    velocity: float = 0.0
    stress: float = 0.0
    bond: str = "bonded"
    name: str = ""
    initial: State | None = None


@dataclass(frozen=True)
class Boundary:
    """Condition at one end of the stack.

    ``kind``: ``"free"`` (sigma = 0), ``"wall"`` (u = 0), ``"velocity"`` or
    ``"stress"`` (a prescribed history).  ``history`` is a tuple of ``(t, value)``
    points (s, and m/s or Pa), linear in between and constant after the last
    point; one point means a constant value.  Two points at one time make a
    step (a square pulse is ``(0, P), (tau, P), (tau, 0)``): the later value holds
    from that time on.
    """

    kind: str = "free"
    history: tuple[tuple[float, float], ...] = ()

    def value_at(self, t: float) -> float:
        """Prescribed velocity (m/s) or stress (Pa) at time ``t`` (s)."""
        if self.kind == "free" or self.kind == "wall":
            return 0.0
        points = self.history
        if t <= points[0][0]:
            return points[0][1]
        last = max(i for i, (ti, _) in enumerate(points) if ti <= t)
        if last == len(points) - 1:
            return points[-1][1]
        (t0, y0), (t1, y1) = points[last], points[last + 1]
        return y0 + (y1 - y0) * (t - t0) / (t1 - t0)


@dataclass(frozen=True)
class Probe:
    """A recording station: ``at`` is ``"left"``, ``"right"`` or a Lagrangian position (m)."""

    name: str
    at: str | float


@dataclass(frozen=True)
class Accuracy:
    """How exactly to compute, and what to neglect.

    ``stress_tolerance`` (Pa) and ``velocity_tolerance`` (m/s): the accuracy wanted of
    stress and velocity records; ``None`` means 1e-3 of the scene's stress scale (and
    that over the largest impedance).  The spacing of the characteristics of every
    simple wave follows from them and from the materials' thresholds
    (``fronttrack.resolution``).  ``rays_per_fan`` (characteristics for a fan spanning
    the scene's largest stress) or ``characteristic_step`` (Pa, the largest stress step
    between characteristics) override that choice.  ``negligible_stress`` (Pa): waves
    weaker than this are dropped (and the dropped total reported); ``None`` chooses one
    from the resolution.  ``release``: ``"isentrope"`` (physical) or ``"hugoniot"``
    (rarefaction shocks, the impedance-match shortcut).  ``entropy_contacts``: keep the
    contacts that interactions leave inside a material (neglecting them changes volume
    and energy, never stress or velocity).  ``max_events``: stop with an error beyond
    this many events.  ``spall_spacing`` (m): no new spall plane closer than this to an
    earlier one (the tension there is carried and reported, unless it would leave the
    equations of state); ``None`` leaves it to the fracture zone the threshold model
    predicts.  ``contact_resolution`` (m): an entropy contact born closer than this to
    the neighbouring contact is merged like a negligible one (counted in the report);
    0, the default, keeps every one.  ``estimate_error``: run the scene again at half the
    characteristic step and report the estimated error of the records
    (``fronttrack.error_estimate``) when it has fans.  ``max_seconds`` (s): stop the run
    after this much wall-clock time and return the solution up to the time reached,
    saying so in ``stats["stopped"]``; ``None`` (the default) runs to ``t_end``.
    """

    stress_tolerance: float | None = None
    velocity_tolerance: float | None = None
    rays_per_fan: int | None = None
    characteristic_step: float | None = None
    negligible_stress: float | None = None
    release: str = "isentrope"
    entropy_contacts: bool = True
    max_events: int = 200_000
    spall_spacing: float | None = None
    contact_resolution: float = 0.0
    estimate_error: bool = False
    max_seconds: float | None = None


@dataclass(frozen=True)
class SpallCriterion:
    """Cumulative-damage spall, in place of the materials' instantaneous thresholds.

    Tuler and Butcher (Int. J. Fract. Mech. 4, 431, 1968): a material point
    fractures when ``integral of (T - threshold)^exponent dt`` over the time its
    tension ``T = -sigma`` exceeds ``threshold`` (Pa) reaches ``damage``
    (Pa^exponent s).  ``exponent = 0`` is the incubation-time criterion: the
    tension must stay beyond the threshold for ``damage`` seconds.  ``stations``
    is the number of Lagrangian stations per layer at which the damage is
    integrated exactly (the fracture plane is the first station to fail).
    """

    threshold: float
    damage: float
    exponent: float = 2.0
    stations: int = 400

    @classmethod
    def incubation(cls, threshold: float, time: float, stations: int = 400) -> SpallCriterion:
        """Tension beyond ``threshold`` (Pa) held for ``time`` (s) fractures the point."""
        return cls(threshold=threshold, damage=time, exponent=0.0, stations=stations)

    def validate(self) -> None:
        """Raise ``SceneError`` naming the first bad field."""
        _finite("spall.threshold", self.threshold, "Pa")
        if self.threshold < 0.0:
            raise SceneError(f"spall.threshold: must be >= 0 Pa, got {self.threshold!r}")
        _finite_positive("spall.damage", self.damage, "Pa^exponent s")
        _finite("spall.exponent", self.exponent, "dimensionless")
        if not 0.0 <= self.exponent <= 10.0:
            raise SceneError(f"spall.exponent: must be in 0..10, got {self.exponent!r}")
        if not (isinstance(self.stations, int) and 2 <= self.stations <= 100_000):
            raise SceneError(f"spall.stations: must be an integer in 2..100000, "
                             f"got {self.stations!r}")


@dataclass(frozen=True)
class Scene:
    """A complete plane-wave scene (SI units).

    ``spall_criterion``, if given, replaces the materials' instantaneous spall
    thresholds inside every layer by a cumulative-damage criterion.
    """

    layers: tuple[Layer, ...]
    t_end: float
    left: Boundary = field(default_factory=Boundary)
    right: Boundary = field(default_factory=Boundary)
    probes: tuple[Probe, ...] = ()
    accuracy: Accuracy = field(default_factory=Accuracy)
    title: str = ""
    spall_criterion: SpallCriterion | None = None

    @property
    def length(self) -> float:
        """Total Lagrangian length of the stack (m)."""
        return sum(layer.thickness for layer in self.layers)

    def interfaces(self) -> list[float]:
        """Lagrangian positions (m) of the contacts between layers."""
        positions, x = [], 0.0
        for layer in self.layers[:-1]:
            x += layer.thickness
            positions.append(x)
        return positions

    def validate(self) -> Scene:
        """Check every field; raise ``SceneError`` naming the first bad one. Returns self."""
        if not self.layers:
            raise SceneError("layer: a scene needs at least one layer")
        _finite_positive("t_end", self.t_end, "s")
        for i, layer in enumerate(self.layers):
            where = f"layer[{i}]"
            if not isinstance(layer.material, Material):
                raise SceneError(f"{where}.material: expected a material, got {layer.material!r}")
            _finite_positive(f"{where}.thickness", layer.thickness, "m")
            _finite(f"{where}.velocity", layer.velocity, "m/s")
            _finite(f"{where}.stress", layer.stress, "Pa")
            if layer.initial is not None:
                _check_initial_state(where, layer)
            if layer.bond not in BONDS:
                raise SceneError(f"{where}.bond: must be one of {BONDS}, got {layer.bond!r}")
        for side, boundary in (("left", self.left), ("right", self.right)):
            if boundary.kind not in BOUNDARY_KINDS:
                raise SceneError(
                    f"{side}.kind: must be one of {BOUNDARY_KINDS}, got {boundary.kind!r}")
            if boundary.kind in ("velocity", "stress"):
                if not boundary.history:
                    raise SceneError(f"{side}.{boundary.kind}: a {boundary.kind} boundary "
                                     f"needs a value or a history")
                times = [t for t, _ in boundary.history]
                steps = zip(times[:-1], times[1:], strict=True)
                triples = zip(times[:-2], times[2:], strict=True)
                if (times[0] < 0.0 or any(b < a for a, b in steps)
                        or any(a == c for a, c in triples)):
                    raise SceneError(f"{side}.history: times must start at >= 0 s and "
                                     f"increase (two equal times make a step, three may "
                                     f"not), got {times}")
                for t, value in boundary.history:
                    _finite(f"{side}.history time", t, "s")
                    _finite(f"{side}.history value", value, "SI")
        names = set()
        for probe in self.probes:
            if probe.name in names:
                raise SceneError(f"probe.name: duplicate probe name {probe.name!r}")
            names.add(probe.name)
            if isinstance(probe.at, str):
                if probe.at not in ("left", "right"):
                    raise SceneError(f"probe[{probe.name}].at: must be 'left', 'right' or a "
                                     f"position in 0..{self.length * 1e3:.6g} mm")
            elif not 0.0 <= probe.at <= self.length:
                raise SceneError(f"probe[{probe.name}].at: position {probe.at * 1e3:.6g} mm is "
                                 f"outside the stack (0 to {self.length * 1e3:.6g} mm)")
        acc = self.accuracy
        if acc.rays_per_fan is not None and not (
                isinstance(acc.rays_per_fan, int) and 1 <= acc.rays_per_fan <= 100_000):
            raise SceneError(f"accuracy.rays_per_fan: must be an integer in 1..100000, "
                             f"got {acc.rays_per_fan!r}")
        for name, unit in (("stress_tolerance", "Pa"), ("velocity_tolerance", "m/s"),
                           ("characteristic_step", "Pa")):
            if getattr(acc, name) is not None:
                _finite_positive(f"accuracy.{name}", getattr(acc, name), unit)
        if acc.negligible_stress is not None and not acc.negligible_stress >= 0.0:
            raise SceneError(f"accuracy.negligible_stress: must be >= 0 Pa, "
                             f"got {acc.negligible_stress!r}")
        if acc.release not in RELEASE_PATHS:
            raise SceneError(f"accuracy.release: must be one of {RELEASE_PATHS}, "
                             f"got {acc.release!r}")
        if acc.spall_spacing is not None and not acc.spall_spacing >= 0.0:
            raise SceneError(f"accuracy.spall_spacing: must be >= 0 m, "
                             f"got {acc.spall_spacing!r}")
        if not acc.contact_resolution >= 0.0:
            raise SceneError(f"accuracy.contact_resolution: must be >= 0 m, "
                             f"got {acc.contact_resolution!r}")
        if not (isinstance(acc.max_events, int) and acc.max_events >= 1):
            raise SceneError(f"accuracy.max_events: must be a positive integer, "
                             f"got {acc.max_events!r}")
        if acc.max_seconds is not None:
            _finite_positive("accuracy.max_seconds", acc.max_seconds, "s")
        if self.spall_criterion is not None:
            self.spall_criterion.validate()
        return self


def _finite(name: str, value, unit: str) -> None:
    if not isinstance(value, (int, float)) or not math.isfinite(value):
        raise SceneError(f"{name}: must be a finite number ({unit}), got {value!r}")


def _finite_positive(name: str, value, unit: str) -> None:
    _finite(name, value, unit)
    if not value > 0.0:
        raise SceneError(f"{name}: must be > 0 {unit}, got {value!r}")


def _check_initial_state(where: str, layer: Layer) -> None:
    """An explicit initial state must be finite, inside the EOS and self-consistent."""
    state, material = layer.initial, layer.material
    if not isinstance(state, State):
        raise SceneError(f"{where}.initial: expected a State, got {state!r}")
    for name in ("sigma", "u", "v", "e"):
        _finite(f"{where}.initial.{name}", getattr(state, name), "SI")
    try:
        material.check_volume(state.v)
    except (MaterialError, StateOutOfRangeError) as error:
        raise SceneError(f"{where}.initial.v: {error}") from None
    sigma = material.stress(state.v, state.e)
    if abs(sigma - state.sigma) > 1e-12 * max(abs(sigma), abs(state.sigma), 1.0):
        raise SceneError(f"{where}.initial.sigma: {state.sigma!r} Pa differs from the "
                         f"equation of state's {sigma!r} Pa at that volume and energy")
