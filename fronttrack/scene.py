"""The scene: what a plane-wave experiment is made of.

A scene is a stack of plane layers along the Lagrangian coordinate ``X`` (the
first layer starts at ``X = 0``), the conditions at its two ends, the contacts
between neighbouring layers, the time to follow it to, the probes to record and
the accuracy wanted.  Every class takes quantities as numbers in SI units or as
strings with a unit, exactly as a scene file writes them (``Layer("Cu", "1 mm",
velocity="1 km/s")`` is ``Layer(get("Cu"), 1e-3, velocity=1000.0)``), stores them
in SI, and validates itself when it is built: a bad field raises ``SceneError``
naming it (``layer.thickness: must be > 0 m``).  ``Scene`` checks what needs the
whole scene (probes inside the stack, unique names).  Scenes read from TOML
(``fronttrack.scene_file``) are built by the same classes.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from dataclasses import dataclass, field

from materials import Material, MaterialError, State, StateOutOfRangeError
from materials.library import get as library_material
from materials.viscoplastic import Viscoplastic

from . import initiation
from .errors import SceneError, located
from .initiation import Initiation
from .units import to_si
from .windows import OpticalWindow, optical_window

BOUNDARY_KINDS = ("free", "wall", "velocity", "stress")
BONDS = ("bonded", "unbonded")
RELEASE_PATHS = ("isentrope", "hugoniot")
PROBE_KINDS = ("point", "interface")
SIDES = ("left", "right")

__all__ = ["BONDS", "BOUNDARY_KINDS", "PROBE_KINDS", "RELEASE_PATHS", "SIDES", "Accuracy",
           "Boundary", "Layer", "Probe", "Scene", "SceneError", "SpallCriterion", "located"]


def _set(obj, name: str, value) -> None:
    """Store a converted field on a frozen dataclass (inside ``__post_init__`` only)."""
    object.__setattr__(obj, name, value)


def _material(where: str, value) -> Material | Viscoplastic:
    """A material given as an object or by library name (a viscoplastic solid is run on
    its characteristic grid, ``fronttrack.viscoplastic_scene``)."""
    if isinstance(value, Material | Viscoplastic):
        return value
    if isinstance(value, str):
        try:
            return library_material(value)
        except MaterialError as error:
            raise SceneError(f"{where}: {error}") from None
    raise SceneError(f"{where}: expected a material or a library name, got {value!r}")


@dataclass(frozen=True)
class Layer:
    """One plate: ``material``, ``thickness`` (m), initial ``velocity`` (m/s) and ``stress`` (Pa).

    ``material`` is a ``Material`` or a library name (``"Cu"``); quantities are SI
    numbers or strings with units (``"1 mm"``, ``"1 km/s"``, ``"0.5 GPa"``).
    ``bond`` is the contact with the previous layer: ``"bonded"`` (carries
    tension up to the weaker material's spall strength) or ``"unbonded"`` (opens
    a gap under any tension).  An initial stress is reached from the reference
    state along the material's wave curve (a shock if compressive, the
    isentrope if tensile).  ``initial``, if given, is the exact initial state
    (``State`` with stress, velocity, volume and energy) and replaces
    ``velocity`` and ``stress``: a gas at a given density and pressure, or a
    layer already shocked.  ``initiate`` puts a detonator on an explosive layer:
    ``"left"`` or ``"right"`` (the face), a time (``"1 us"``: the left face then), or both
    (``"right 0.5 us"``); see ``fronttrack.initiation``.
    """

    material: Material | str
    thickness: float | str
    velocity: float | str = 0.0
    stress: float | str = 0.0
    bond: str = "bonded"
    name: str = ""
    initial: State | None = None
    initiate: Initiation | str | float | None = None

    def __post_init__(self) -> None:
        _set(self, "material", _material("layer.material", self.material))
        _set(self, "thickness", to_si(self.thickness, "length", "layer.thickness"))
        _set(self, "velocity", to_si(self.velocity, "velocity", "layer.velocity"))
        _set(self, "stress", to_si(self.stress, "stress", "layer.stress"))
        if not self.thickness > 0.0:
            raise SceneError(f"layer.thickness: must be > 0 m, got {self.thickness!r}")
        if self.bond not in BONDS:
            raise SceneError(f"layer.bond: must be one of {BONDS}, got {self.bond!r}")
        if not isinstance(self.name, str):
            raise SceneError(f"layer.name: expected a string, got {self.name!r}")
        if self.initial is not None:
            _check_initial_state(self.material, self.initial)
        _set(self, "initiate", initiation.parse(self.initiate))


def _check_initial_state(material: Material, state: State) -> None:
    """An explicit initial state must be finite, inside the EOS and self-consistent."""
    if not isinstance(state, State):
        raise SceneError(f"layer.initial: expected a State, got {state!r}")
    for name in ("sigma", "u", "v", "e"):
        value = getattr(state, name)
        if not isinstance(value, (int, float)) or not math.isfinite(value):
            raise SceneError(f"layer.initial.{name}: must be a finite number (SI), "
                             f"got {value!r}")
    try:
        material.check_volume(state.v)
    except (MaterialError, StateOutOfRangeError) as error:
        raise SceneError(f"layer.initial.v: {error}") from None
    sigma = material.stress(state.v, state.e)
    if abs(sigma - state.sigma) > 1e-12 * max(abs(sigma), abs(state.sigma), 1.0):
        raise SceneError(f"layer.initial.sigma: {state.sigma!r} Pa differs from the "
                         f"equation of state's {sigma!r} Pa at that volume and energy")


_BOUNDARY_DIMENSION = {"velocity": "velocity", "stress": "stress"}


@dataclass(frozen=True)
class Boundary:
    """Condition at one end of the stack.

    ``kind``: ``"free"`` (sigma = 0), ``"wall"`` (u = 0), ``"velocity"`` or
    ``"stress"`` (a prescribed history).  ``history`` is one value (a constant:
    ``Boundary("stress", "1 GPa")``) or a sequence of ``(t, value)`` points (s, and
    m/s or Pa, or strings with units), linear in between and constant after the
    last point.  Two points at one time make a step (a square pulse is ``(0, P),
    (tau, P), (tau, 0)``): the later value holds from that time on.  It is stored
    as a tuple of SI pairs.  A velocity boundary is a piston: it pushes, and unless
    ``bond`` is ``"bonded"`` a piston that pulls away faster than the material can
    follow separates from it; the face is then free until the two meet again.
    """

    kind: str = "free"
    history: tuple[tuple[float, float], ...] | float | str = ()
    bond: str = "unbonded"

    def __post_init__(self) -> None:
        if self.kind not in BOUNDARY_KINDS:
            raise SceneError(f"boundary.kind: must be one of {BOUNDARY_KINDS}, "
                             f"got {self.kind!r}")
        if self.bond not in BONDS:
            raise SceneError(f"boundary.bond: must be one of {BONDS}, got {self.bond!r}")
        dimension = _BOUNDARY_DIMENSION.get(self.kind)
        if dimension is None:
            if self.history != ():
                raise SceneError(f"boundary.history: a {self.kind} boundary takes no "
                                 f"history, got {self.history!r}")
            return
        points = self.history
        if isinstance(points, (str, int, float)):
            points = ((0.0, points),)
        if not points:
            raise SceneError(f"boundary.history: a {self.kind} boundary needs a value "
                             f"or a history")
        history = []
        for k, point in enumerate(points):
            if isinstance(point, str) or len(point) != 2:
                raise SceneError(f"boundary.history[{k}]: expected a (time, value) pair, "
                                 f"got {point!r}")
            history.append((to_si(point[0], "time", f"boundary.history[{k}] time"),
                            to_si(point[1], dimension, f"boundary.history[{k}] value")))
        times = [t for t, _ in history]
        steps = zip(times[:-1], times[1:], strict=True)
        triples = zip(times[:-2], times[2:], strict=True)
        if times[0] < 0.0 or any(b < a for a, b in steps) or any(a == c for a, c in triples):
            raise SceneError(f"boundary.history: times must start at >= 0 s and increase "
                             f"(two equal times make a step, three may not), got {times}")
        _set(self, "history", tuple(history))

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
    """A recording station.

    ``at`` is ``"left"``, ``"right"`` or a Lagrangian position (m, or a string with
    a unit).  ``kind = "interface"`` marks a station on a contact between layers
    (or an end of the stack) that an interferometer looks at through the layer on
    ``side`` (``"left"`` or ``"right"``); ``window`` then names the optical window
    (or is an ``OpticalWindow``) whose refractive index turns the interface velocity
    into the apparent velocity the interferometer reports (``fronttrack.windows``),
    recorded beside the true one.  The layer on ``side`` is the window.
    """

    name: str
    at: str | float
    kind: str = "point"
    side: str | None = None
    window: str | OpticalWindow | None = None

    def __post_init__(self) -> None:
        if not isinstance(self.name, str) or not self.name:
            raise SceneError(f"probe.name: expected a non-empty string, got {self.name!r}")
        if not (isinstance(self.at, str) and self.at in SIDES):
            _set(self, "at", to_si(self.at, "length", "probe.at"))
            if self.at < 0.0:
                raise SceneError(f"probe.at: must be 'left', 'right' or a position >= 0 m, "
                                 f"got {self.at!r}")
        if self.kind not in PROBE_KINDS:
            raise SceneError(f"probe.kind: must be one of {PROBE_KINDS}, got {self.kind!r}")
        if self.kind == "point":
            if self.side is not None or self.window is not None:
                raise SceneError("probe.window: only an interface probe (kind = "
                                 "'interface') has a side and a window")
            return
        if self.side not in SIDES:
            raise SceneError(f"probe.side: an interface probe looks through the layer on "
                             f"one side, one of {SIDES}; got {self.side!r}")
        if self.window is not None:
            with located("window", "probe.window"):
                _set(self, "window", optical_window(self.window))


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
    earlier one of its layer (the tension there is carried and reported, unless it would
    leave the equations of state); ``None`` takes the records' resolution length
    (``coalesce_length``): a slab thinner than that between two planes is not resolved.
    ``contact_resolution`` (m): an entropy contact born closer than this to the
    neighbouring contact is merged like a negligible one (counted in the report);
    0, the default, keeps every one.  ``coalesce_length`` (m): the resolution length of
    the records: two waves of one family moving at one speed, or two contacts, closer
    than this become one front, and weak ones farther apart too while the weaker jump
    times the distance stays small (``fronttrack.coalesce``); ``None`` takes the
    tolerance's fraction of the stack's length, 0 keeps every front. ``estimate_error``: run
    the scene again at half the characteristic step and report the estimated error of the
    records (``fronttrack.error_estimate``) when it has fans. ``max_seconds`` (s): stop the
    run after this much wall-clock time and return the solution up to the time reached,
    saying so in ``stats["stopped"]``; ``None`` (the default) runs to ``t_end``.
    Quantities are SI numbers or strings with units.
    """

    stress_tolerance: float | str | None = None
    velocity_tolerance: float | str | None = None
    rays_per_fan: int | None = None
    characteristic_step: float | str | None = None
    negligible_stress: float | str | None = None
    release: str = "isentrope"
    entropy_contacts: bool = True
    max_events: int = 200_000
    spall_spacing: float | str | None = None
    contact_resolution: float | str = 0.0
    coalesce_length: float | str | None = None
    estimate_error: bool = False
    max_seconds: float | None = None

    def __post_init__(self) -> None:
        for name, dimension, lowest in _ACCURACY_QUANTITIES:
            value = getattr(self, name)
            if value is None:
                continue
            value = to_si(value, dimension, f"accuracy.{name}")
            _set(self, name, value)
            if not (value > 0.0 if lowest == ">" else value >= 0.0):
                raise SceneError(f"accuracy.{name}: must be {lowest} 0 "
                                 f"{_SI_UNITS[dimension]}, got {value!r}")
        if self.rays_per_fan is not None and not (
                _is_int(self.rays_per_fan) and 1 <= self.rays_per_fan <= 100_000):
            raise SceneError(f"accuracy.rays_per_fan: must be an integer in 1..100000, "
                             f"got {self.rays_per_fan!r}")
        if self.release not in RELEASE_PATHS:
            raise SceneError(f"accuracy.release: must be one of {RELEASE_PATHS}, "
                             f"got {self.release!r}")
        for name in ("entropy_contacts", "estimate_error"):
            if not isinstance(getattr(self, name), bool):
                raise SceneError(f"accuracy.{name}: expected true or false, "
                                 f"got {getattr(self, name)!r}")
        if not (_is_int(self.max_events) and self.max_events >= 1):
            raise SceneError(f"accuracy.max_events: must be a positive integer, "
                             f"got {self.max_events!r}")


_ACCURACY_QUANTITIES = (("stress_tolerance", "stress", ">"),
                        ("velocity_tolerance", "velocity", ">"),
                        ("characteristic_step", "stress", ">"),
                        ("negligible_stress", "stress", ">="),
                        ("spall_spacing", "length", ">="),
                        ("contact_resolution", "length", ">="),
                        ("coalesce_length", "length", ">="),
                        ("max_seconds", "time", ">"))
"""Dimensional fields of ``Accuracy``: name, dimension, and the bound on their value."""

_SI_UNITS = {"stress": "Pa", "velocity": "m/s", "length": "m", "time": "s"}


def _is_int(value) -> bool:
    return isinstance(value, int) and not isinstance(value, bool)


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
    ``threshold`` may be a string with a unit.
    """

    threshold: float | str
    damage: float
    exponent: float = 2.0
    stations: int = 400

    def __post_init__(self) -> None:
        _set(self, "threshold", to_si(self.threshold, "stress", "spall.threshold"))
        if self.threshold < 0.0:
            raise SceneError(f"spall.threshold: must be >= 0 Pa, got {self.threshold!r}")
        damage = to_si(self.damage, "dimensionless", "spall.damage")
        if not damage > 0.0:
            raise SceneError(f"spall.damage: must be > 0 Pa^exponent s, got {damage!r}")
        exponent = to_si(self.exponent, "dimensionless", "spall.exponent")
        if not 0.0 <= exponent <= 10.0:
            raise SceneError(f"spall.exponent: must be in 0..10, got {exponent!r}")
        _set(self, "damage", damage)
        _set(self, "exponent", exponent)
        if not (_is_int(self.stations) and 2 <= self.stations <= 100_000):
            raise SceneError(f"spall.stations: must be an integer in 2..100000, "
                             f"got {self.stations!r}")

    @classmethod
    def incubation(cls, threshold: float | str, time: float | str,
                   stations: int = 400) -> SpallCriterion:
        """Tension beyond ``threshold`` (Pa) held for ``time`` (s) fractures the point."""
        return cls(threshold=threshold, damage=to_si(time, "time", "spall.incubation_time"),
                   exponent=0.0, stations=stations)


@dataclass(frozen=True)
class Scene:
    """A complete plane-wave scene (SI units).

    ``layers`` is a sequence of ``Layer`` (stored as a tuple), ``t_end`` the time to
    follow it to (s, or a string such as ``"3 us"``).  ``spall_criterion``, if given,
    replaces the materials' instantaneous spall thresholds inside every layer by a
    cumulative-damage criterion.
    """

    layers: tuple[Layer, ...]
    t_end: float | str
    left: Boundary = field(default_factory=Boundary)
    right: Boundary = field(default_factory=Boundary)
    probes: tuple[Probe, ...] = ()
    accuracy: Accuracy = field(default_factory=Accuracy)
    title: str = ""
    spall_criterion: SpallCriterion | None = None

    def __post_init__(self) -> None:
        for name, field_name, kind in (("layers", "layer", Layer), ("probes", "probe", Probe)):
            parts = getattr(self, name)
            if isinstance(parts, (str, bytes, kind)) or not isinstance(parts, Iterable):
                raise SceneError(f"{field_name}: expected a list of {kind.__name__}, "
                                 f"got {parts!r:.60}")
            _set(self, name, tuple(parts))
        _set(self, "t_end", to_si(self.t_end, "time", "t_end"))
        self.validate()

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
        """Check what needs the whole scene (each part checked itself when built).

        Raises ``SceneError`` naming the first bad field; returns ``self``.
        """
        if not self.layers:
            raise SceneError("layer: a scene needs at least one layer")
        if not self.t_end > 0.0:
            raise SceneError(f"t_end: must be > 0 s, got {self.t_end!r}")
        for name, value, kind in (*((f"layer[{i}]", layer, Layer)
                                    for i, layer in enumerate(self.layers)),
                                  ("left", self.left, Boundary), ("right", self.right, Boundary),
                                  ("accuracy", self.accuracy, Accuracy),
                                  *((f"probe[{i}]", p, Probe)
                                    for i, p in enumerate(self.probes))):
            if not isinstance(value, kind):
                raise SceneError(f"{name}: expected a {kind.__name__}, got {value!r}")
        if self.spall_criterion is not None and not isinstance(self.spall_criterion,
                                                                 SpallCriterion):
            raise SceneError(f"spall: expected a SpallCriterion, got {self.spall_criterion!r}")
        names = set()
        for probe in self.probes:
            if probe.name in names:
                raise SceneError(f"probe.name: duplicate probe name {probe.name!r}")
            names.add(probe.name)
            self._check_probe(probe)
        initiation.check(self)
        return self

    def _check_probe(self, probe: Probe) -> None:
        """A probe must lie in the stack; an interface probe on a contact or an end."""
        where = f"probe[{probe.name}].at"
        x = {"left": 0.0, "right": self.length}.get(probe.at, probe.at)
        if not 0.0 <= x <= self.length:
            raise SceneError(f"{where}: position {x * 1e3:.6g} mm is outside the stack "
                             f"(0 to {self.length * 1e3:.6g} mm)")
        if probe.kind != "interface":
            return
        edges = [0.0, *self.interfaces(), self.length]
        if not any(abs(x - edge) <= 1e-12 * self.length for edge in edges):
            raise SceneError(f"{where}: an interface probe must sit on a contact or an end "
                             f"of the stack ({', '.join(f'{e * 1e3:.6g}' for e in edges)} "
                             f"mm), got {x * 1e3:.6g} mm")
        if (probe.side == "left" and x <= 0.0) or (probe.side == "right" and x >= self.length):
            raise SceneError(f"probe[{probe.name}].side: there is no layer on the "
                             f"{probe.side} of {x * 1e3:.6g} mm")
