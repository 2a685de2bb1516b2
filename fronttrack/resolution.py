"""The resolution a scene asks for, derived once from its ``[accuracy]`` and its materials.

A scene states the accuracy it needs: tolerances on its stress and velocity records
(``accuracy.stress_tolerance``, ``accuracy.velocity_tolerance``).  Simple waves are
families of characteristics a stress step apart, and the records read them
continuously (second order in the step), so a record's error is about

    error ~ RECORD_ERROR_CONSTANT * step^2 / stress_scale

(measured on plate-impact scenes, see ``benchmarks/``); the step follows from the
tolerance.  No step may exceed ``STRENGTH_FRACTION`` of the smallest spall strength
or yield stress in the scene, so that a threshold is never crossed by one step.
``rays_per_fan`` (characteristics per fan spanning the stress scale) and
``characteristic_step`` (Pa) override both rules.

A gas turns a small stress into a large velocity (a gas released to vacuum drops a
few MPa and gains its escape speed ``2 c / (gamma - 1)``), so the same relative
resolution holds in velocity too: ``velocity_step = step * velocity_scale /
stress_scale`` with ``velocity_scale`` the largest velocity jump of the initial Riemann
problems (at least ``stress_scale`` over the smallest impedance of a solid, so that a
solid's waves, whose velocity and stress go together, are resolved and neglected as
before by their stress alone), and no characteristic
of a fan, and no compression wave taken for a characteristic, spans more than that, nor
more than ``step / stress_scale`` of its sound speed (not below half the material's
initial one) over the square root of the material's share of the energy
(``sound_bound``: a gas's characteristics make energy second order in their step
relative to the gas's own sound speed, which an escape speed overstates three to five
times).

Waves weaker than the negligible stress are dropped (and counted).  The default is
``NEGLIGIBLE_FRACTION`` of the stress scale, raised to ``NEGLIGIBLE_STEP_FRACTION`` of
the step where fans can form (their echoes a thousand times below the resolution
change nothing) and to ``NEGLIGIBLE_SPLIT_FRACTION`` of the scale where small-strain
elastic–plastic solids split every wave in two (``NEGLIGIBLE_NONLINEAR_SPLIT_FRACTION``
where other solids split waves).  A wave is negligible only when its velocity jump is
too, below ``negligible * velocity_scale / stress_scale``: a wave of a few MPa in a
gas can carry hundreds of m/s.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from materials import (
    IdealGas,
    State,
    StateOutOfRangeError,
    WavediagramError,
    solve_boundary,
    solve_contact,
)

from .kinds import BoundaryKind, Release
from .scene import Scene

DEFAULT_RECORD_FRACTION = 1e-3
"""Default tolerance on stress records, as a fraction of the scene's stress scale."""

RECORD_ERROR_CONSTANT = 0.05
"""``error ~ RECORD_ERROR_CONSTANT * step^2 / stress_scale`` for the records of a
lattice-and-fan scene (the L1-in-time error of a stress history per unit time,
fitted on the plate-impact benchmarks)."""

DETONATION_RECORD_CONSTANT = 0.4
"""The same constant for a scene with an explosive layer.  Its Taylor wave spans the CJ
stress down to rest or vacuum, its products have no lattice (every crossing of their
characteristics is a Riemann problem), and its balance residual is larger: measured
``residual = 2 C step^2 / stress_scale^2`` with ``C`` = 0.27, 0.30, 0.30 (momentum) at
steps of 2, 1 and 0.5 GPa for 10 mm of TNT (JWL) initiated at a wall, 0.03 to 0.2 at a
free face (``tests/test_gurney.py``); 0.4 keeps that margin."""

STRENGTH_FRACTION = 0.25
"""No characteristic step exceeds this fraction of the weakest spall strength or yield
stress in the scene."""

MAX_CHARACTERISTICS = 256
"""Characteristics for a fan spanning the stress scale are capped here: a threshold
far below the scene's stresses does not buy an unbounded lattice (the cap is
reported)."""

MIN_CHARACTERISTICS = 4
"""At least this many cells for a fan spanning the stress scale."""

NEGLIGIBLE_FRACTION = 1e-6
"""Default negligible wave, as a fraction of the scene's stress scale."""

NEGLIGIBLE_STEP_FRACTION = 1e-3
"""In a scene with fans the negligible wave is at least this fraction of the step."""

NEGLIGIBLE_SPLIT_FRACTION = 1e-4
"""In a scene with small-strain elastic–plastic solids the negligible wave is at least
this fraction of the stress scale: there every interaction splits waves into an
elastic and a plastic part, and the weakest parts are not worth an event; the trains
they form are coalesced (``fronttrack.coalesce``), which keeps their count bounded."""

NEGLIGIBLE_NONLINEAR_SPLIT_FRACTION = 1e-3
"""The same for scenes with other splitting solids (finite-strain plasticity, porous
compaction, phase change, explosives), whose wave trains are not coalesced: their
weak waves would otherwise multiply."""


@dataclass(frozen=True)
class Resolution:
    """What the engine resolves and what it neglects, for one scene (SI units).

    ``stress_scale``: the largest stress the initial Riemann problems make (Pa);
    ``step``: the largest stress step between two characteristics of a family (Pa);
    ``velocity_step``: the largest velocity step between them (m/s);
    ``step_rule``: which rule set it; ``stress_tolerance``/``velocity_tolerance``: the
    record tolerances asked for (Pa, m/s); ``negligible``: waves weaker than this are
    dropped (Pa); ``length``: the stack's length (m) and ``x_tol`` the distance below
    which two fronts meet at one point; ``release``: the unloading path;
    ``negligible_velocity``: the velocity jump (m/s) below which a wave whose stress
    jump is negligible is dropped; ``coalesce_length``: the resolution length (m) of
    the records, below which two fronts of one family become one
    (``fronttrack.coalesce``; by default the record tolerance's fraction of the stress
    scale, at most ``DEFAULT_RECORD_FRACTION``, times the stack's length: 15 um for a
    15 mm stack).  ``sound_bounds``: ``(material, factor, c0)`` triples: a material's
    characteristics span at most ``factor`` times the sound speed of the states they
    join, not below ``SOUND_FLOOR`` times its initial sound speed ``c0`` (m/s)
    (``sound_bound``, ``velocity_step_of``).
    """

    stress_scale: float
    step: float
    velocity_step: float
    negligible_velocity: float
    step_rule: str
    stress_tolerance: float
    velocity_tolerance: float
    negligible: float
    length: float
    x_tol: float
    release: Release
    makes_fans: bool
    coalesce_length: float = 0.0
    record_constant: float = RECORD_ERROR_CONSTANT
    sound_bounds: tuple = ()

    def report(self) -> dict:
        """The resolution as the ``accuracy`` section of a solution reports it."""
        return {
            "release": str(self.release),
            "stress_scale": self.stress_scale,
            "characteristic_step": self.step,
            "characteristic_step_rule": self.step_rule,
            "ray_stress_step": self.step,
            "ray_velocity_step": self.velocity_step,
            "stress_tolerance": self.stress_tolerance,
            "velocity_tolerance": self.velocity_tolerance,
            "estimated_record_error": (self.record_constant * self.step**2 / self.stress_scale
                                       if self.makes_fans else 0.0),
            "negligible_stress": self.negligible,
            "negligible_velocity": self.negligible_velocity,
            "coalesce_length": self.coalesce_length,
        }

    def velocity_step_of(self, material, *states: State) -> float:
        """The largest velocity step (m/s) one characteristic of a wave of ``material``
        between ``states`` spans: ``velocity_step``, and for a material listed in
        ``sound_bounds`` at most its factor times the larger Eulerian sound speed of the
        states, taken no lower than ``SOUND_FLOOR`` of its initial one (``sound_bound``)."""
        for listed, factor, c0 in self.sound_bounds:
            if listed is material:
                c = max([_eulerian_sound_speed(material, s) for s in states] + [0.0])
                return min(self.velocity_step, factor * max(c, SOUND_FLOOR * c0))
        return self.velocity_step

    def is_negligible(self, stress_jump: float, velocity_jump: float) -> bool:
        """Whether a wave of these jumps (Pa, m/s) is weaker than the run resolves."""
        return (abs(stress_jump) <= self.negligible
                and abs(velocity_jump) <= self.negligible_velocity)


SOUND_FLOOR = 0.5
"""The sound speed that bounds a characteristic's velocity step (``sound_bound``) is
taken no lower than this fraction of the material's initial one."""


def sound_bound(scene: Scene, states: list[State], material,
                relative: float) -> tuple[float, float] | None:
    """``(factor, c0)``: a characteristic of ``material`` spans at most ``factor`` times
    the Eulerian sound speed ``c`` of the states it joins, ``relative`` (the step over
    the stress scale) over the square root of the material's ``share`` of the initial
    energy (its layers' internal energy ``sum rho0 L |e|`` over the content of all layers
    ``sum rho0 L (|e| + u^2/2)``, J/m^2), with ``c`` no lower than ``SOUND_FLOOR`` of
    its largest initial one ``c0`` (m/s); ``None`` for a material without initial
    internal energy or sound speed.

    A characteristic is a jump between two states of one isentrope at one speed, so it
    makes energy at a rate third order in its step (``characteristics.ray_energy``); in
    an ideal gas that rate is ``(gamma + 1) rho du^3 / 16`` to leading order (``rho`` the
    density, ``du`` the velocity step), a fraction of order ``(du/c)^3`` of the internal
    energy (order ``c^2`` per unit mass) of the mass it sweeps, and a layer's ``~c/du``
    characteristics sweep its mass once a transit: relative to the run's energy,
    ``share (du/c)^2`` per transit, second order as the records are in ``step /
    stress_scale``.  The scene's ``velocity_step`` is relative to the largest velocity
    jump instead, a gas's escape speed ``2 c / (gamma - 1)``, three to five times ``c``,
    and stays fixed while an expanding gas's ``c`` falls (campaign seed 652: rays of
    0.4-0.8 ``c`` created 2 % of the energy).  Near vacuum ``c`` goes to zero, and so do
    the density and the rate: bounded by their own ``c``, fans of a few Pa to vacuum
    were cut into five rays at every reflection (seed 458: from 7 909 events to the time
    limit); ``SOUND_FLOOR`` stops that (at half its sound speed a gas has an eighth of
    its density or less).  A material with a small share is not refined for it (a 50 um
    gas layer behind 13 mm of water and lead, seed 758, holds 1e-5).  In a solid ``du /
    c = d sigma / (rho0 C_L^2)`` is the step over the modulus, far below ``relative``:
    the bound does not act."""
    content = internal = c0 = 0.0
    for layer, state in zip(scene.layers, states, strict=True):
        mass = layer.material.rho0 * layer.thickness
        content += mass * (abs(state.e) + 0.5 * state.u * state.u)
        if layer.material is material:
            internal += mass * abs(state.e)
            c0 = max(c0, _eulerian_sound_speed(material, state))
    if not (internal > 0.0 and c0 > 0.0):
        return None
    return relative / math.sqrt(internal / content), c0


def _materials(scene: Scene) -> list:
    """The distinct materials of ``scene``'s layers, in order."""
    found = []
    for layer in scene.layers:
        if not any(m is layer.material for m in found):
            found.append(layer.material)
    return found


def _eulerian_sound_speed(material, state: State) -> float:
    """The Eulerian sound speed ``c = C_L v / v0`` (m/s) of ``state``; zero at vacuum
    (infinite volume) or where ``material`` has none (beyond its range or spinodal)."""
    if not math.isfinite(state.v):
        return 0.0
    try:
        return material.sound_speed(state.v, state.e) * state.v / material.v0
    except StateOutOfRangeError:
        return 0.0


def initial_state(layer, where: str = "layer") -> State:
    """A layer's initial state: its stress reached along its wave curve, moving at ``velocity``.

    A stress the material's equation of state cannot reach is a ``StateOutOfRangeError``
    that names the field, ``where`` + ``.stress`` (e.g. ``layer[2].stress``).
    """
    if layer.initial is not None:
        return layer.initial
    try:
        return layer.material.initial_state(layer.stress, layer.velocity)
    except StateOutOfRangeError as error:
        raise StateOutOfRangeError(f"{where}.stress = {layer.stress / 1e9:.6g} GPa: "
                                   f"{error}") from None


def resolve(scene: Scene, states: list[State]) -> Resolution:
    """The resolution of ``scene`` whose layers start in ``states``."""
    acc = scene.accuracy
    release = Release(acc.release)
    scale, velocity_jump = initial_scales(scene, states)
    makes_fans = release == Release.ISENTROPE and any(
        layer.material.makes_fans for layer in scene.layers)
    impedance = max(layer.material.rho0 * layer.material.sound_speed(s.v, s.e)
                    for layer, s in zip(scene.layers, states, strict=True))
    stress_tol = (acc.stress_tolerance if acc.stress_tolerance is not None
                  else DEFAULT_RECORD_FRACTION * scale)
    velocity_tol = (acc.velocity_tolerance if acc.velocity_tolerance is not None
                    else stress_tol / impedance)
    stress_tol = min(stress_tol, velocity_tol * impedance)
    constant = (DETONATION_RECORD_CONSTANT if any(
        hasattr(layer.material, "ignited") for layer in scene.layers) else RECORD_ERROR_CONSTANT)
    step, rule = _step(scene, scale, stress_tol, constant)
    negligible = _negligible(scene, scale, step, makes_fans)
    velocity_ratio = max(velocity_jump, scale / _softest_solid(scene, states, impedance)
                         ) / scale  # (m/s) per Pa
    length = scene.length
    return Resolution(stress_scale=scale, step=step, step_rule=rule,
                      velocity_step=step * velocity_ratio,
                      negligible_velocity=negligible * velocity_ratio,
                      stress_tolerance=stress_tol, velocity_tolerance=velocity_tol,
                      negligible=negligible, length=length, x_tol=1e-10 * length,
                      release=release, makes_fans=makes_fans, record_constant=constant,
                      coalesce_length=(acc.coalesce_length if acc.coalesce_length is not None
                                       else min(stress_tol / scale, DEFAULT_RECORD_FRACTION)
                                       * length),
                      sound_bounds=tuple(
                          (material, *bound) for material in _materials(scene)
                          if (bound := sound_bound(scene, states, material, step / scale))))


def _step(scene: Scene, scale: float, stress_tol: float, constant: float
          ) -> tuple[float, str]:
    """The characteristic step (Pa) and the rule that set it (``constant``: the record
    error constant of the scene)."""
    acc = scene.accuracy
    if acc.characteristic_step is not None:
        return acc.characteristic_step, "accuracy.characteristic_step"
    if acc.rays_per_fan is not None:
        return scale / acc.rays_per_fan, "accuracy.rays_per_fan"
    step = scale * math.sqrt(stress_tol / (constant * scale))
    rule = "record tolerance"
    weakest = weakest_threshold(scene)
    if weakest is not None and STRENGTH_FRACTION * weakest[0] < step:
        step, rule = STRENGTH_FRACTION * weakest[0], f"a quarter of the {weakest[1]}"
    if step > scale / MIN_CHARACTERISTICS:
        step = scale / MIN_CHARACTERISTICS
        rule = f"at least {MIN_CHARACTERISTICS} characteristics per fan"
    if step < scale / MAX_CHARACTERISTICS:
        step = scale / MAX_CHARACTERISTICS
        rule = f"capped at {MAX_CHARACTERISTICS} characteristics per fan"
    return step, rule


def weakest_threshold(scene: Scene) -> tuple[float, str] | None:
    """The smallest spall strength or yield stress (Pa) a wave of the scene can meet, and
    what it is; ``None`` if the materials have neither."""
    found = []
    for layer in scene.layers:
        material = layer.material
        if scene.spall_criterion is None and math.isfinite(material.spall_strength) \
                and material.spall_strength > 0.0:
            found.append((material.spall_strength, f"spall strength of {material.name}"))
        strength = getattr(material, "yield_strength", math.inf)
        if math.isfinite(strength) and strength > 0.0:
            found.append((strength, f"yield stress of {material.name}"))
    if scene.spall_criterion is not None and scene.spall_criterion.threshold > 0.0:
        found.append((scene.spall_criterion.threshold, "spall threshold"))
    return min(found) if found else None


def _softest_solid(scene: Scene, states: list[State], largest: float) -> float:
    """The smallest initial impedance ``rho0 C_L`` (Pa s/m) of a layer that is not a gas
    (``largest``, the largest of all, if every layer is a gas)."""
    solids = [layer.material.rho0 * layer.material.sound_speed(s.v, s.e)
              for layer, s in zip(scene.layers, states, strict=True)
              if not isinstance(layer.material, IdealGas)]
    return min(solids, default=largest)


def _negligible(scene: Scene, scale: float, step: float, makes_fans: bool) -> float:
    acc = scene.accuracy
    if acc.negligible_stress is not None:
        return acc.negligible_stress
    negligible = NEGLIGIBLE_FRACTION * scale
    if makes_fans:
        negligible = max(negligible, NEGLIGIBLE_STEP_FRACTION * step)
    splitting = [layer.material for layer in scene.layers if layer.material.splits_waves]
    if splitting:
        fraction = (NEGLIGIBLE_SPLIT_FRACTION if all(m.linear_branches for m in splitting)
                    else NEGLIGIBLE_NONLINEAR_SPLIT_FRACTION)
        negligible = max(negligible, fraction * scale)
    return negligible


def _values_until(boundary, t_end: float) -> list[float]:
    """The values a boundary history takes up to ``t_end`` (s): its points before then and
    its value at ``t_end`` (the history is linear between points, so these bound it); a
    free surface's zero stress and a wall's zero velocity."""
    if boundary.kind in (BoundaryKind.FREE, BoundaryKind.WALL):
        return [0.0]
    if not boundary.history:
        return []
    return [value for t, value in boundary.history if t <= t_end] + [
        boundary.value_at(t_end)]


def _separates(boundary, solution) -> bool:
    """Whether an unbonded piston (a velocity boundary) would pull on its face: it comes
    away from it and launches no wave (``fronttrack.interactions``)."""
    return (boundary.kind == BoundaryKind.VELOCITY and boundary.bond != "bonded"
            and solution.bonded_sigma < 0.0)


def stress_scale(scene: Scene, states: list[State]) -> float:
    """Largest stress the initial Riemann problems produce (Pa): scales steps and thresholds."""
    return initial_scales(scene, states)[0]


def initial_scales(scene: Scene, states: list[State]) -> tuple[float, float]:
    """The largest stress (Pa) and the largest velocity jump (m/s) the initial Riemann
    problems produce (contacts and boundaries, over the boundary histories to ``t_end``)."""
    release = scene.accuracy.release
    scale, jump = max(abs(s.sigma) for s in states), 0.0
    layers = scene.layers
    for i in range(len(states) - 1):
        a, b = states[i], states[i + 1]
        if a.u != b.u or a.sigma != b.sigma:
            sol = solve_contact(layers[i].material, a, layers[i + 1].material, b, 0.0, release)
            scale = max(scale, abs(sol.bonded_sigma))
            jump = max(jump, abs(sol.left_star.u - a.u), abs(sol.right_star.u - b.u))
    ends = ((scene.left, states[0], layers[0].material, "left"),
            (scene.right, states[-1], layers[-1].material, "right"))
    for spec, state, material, side in ends:
        for value in _values_until(spec, scene.t_end):
            by_stress = spec.kind in (BoundaryKind.STRESS, BoundaryKind.FREE)
            if by_stress:
                scale = max(scale, abs(value))
            try:
                sol = solve_boundary(material, state, side, release=release,
                                     **{"stress" if by_stress else "velocity": value})
            except WavediagramError:  # beyond the equation of state: the engine says how
                continue
            if _separates(spec, sol):
                continue
            scale = max(scale, abs(sol.bonded_sigma))
            star = sol.left_star if side == "right" else sol.right_star
            jump = max(jump, abs(star.u - state.u))
    for layer, s in zip(layers, states, strict=True):
        if hasattr(layer.material, "cj_state"):  # an explosive can detonate: its CJ stress
            scale = max(scale, layer.material.cj_state(s).state.sigma)
    if scale == 0.0:
        scale = max(layer.material.rho0 * layer.material.sound_speed(s.v, s.e)
                    for layer, s in zip(layers, states, strict=True))
    return scale, jump
