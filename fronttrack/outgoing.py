"""The waves a Riemann problem sends out, as fronts of the queue.

A shock is one front; a shock weaker than the characteristic step (in stress and in
velocity) is a compression characteristic (``_weak_shock_ray``).  A simple wave (fan) is a family of
characteristics (``characteristics.simple_waves``): one ray per characteristic, each
with its own Riemann invariant, the cells between them on the fan's isentrope.  A
family weaker than the negligible stress and velocity is dropped and counted.

Every wave carries a lineage (``lineage``): which wave it descends from, so that a
station can tell the reflections of the first shock that reached it (they inherit its
lineage) from a release of another origin (``design.one_dimensional_window``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

from characteristics.products_table import fan_table
from characteristics.ray_energy import conserving_state
from characteristics.simple_waves import discretise_fan, diverging
from materials import Fan, State, StateOutOfRangeError
from materials.frozen import slot_init

from .fronts import MIXED, UNKNOWN, Front
from .kinds import FrontKind

EDGES = (FrontKind.BOUNDARY, FrontKind.GAP)
"""Sites at an edge of the material: the waves they send out start a lineage."""


def lineage(engine, incoming, site) -> int:
    """The lineage of the waves an event sends out in one direction.

    A new one (a new id) where no wave came in (an impact, a boundary's own step) or
    where the event is at an edge of the material (a free surface, a wall, a prescribed
    boundary, a gap's faces): what an edge reflects is a release or reflection from that
    edge.  Otherwise the lineage shared by the waves that met, ``MIXED`` if they differ:
    transmitted and reflected waves at an interface, the continuation of a shock or ray,
    descend from the waves that made them.
    """
    if not incoming or (site is not None and site.kind in EDGES):
        return engine.next_wave_id()
    first = incoming[0].lineage
    for front in incoming:
        if front.lineage != first:
            return MIXED
    return first


@slot_init
@dataclass(frozen=True, slots=True)
class WaveSpec:
    """A new front with the states ahead of and behind it, and the isentrope table of
    the cell behind it when the wave is a simple wave (``UNKNOWN`` otherwise).
    ``shifted``: the state behind carries the energy the jumps of the family's rays
    took (``_conserving``), off the state the Riemann solution gave."""

    front: Front
    ahead: State
    behind: State
    table: object
    shifted: bool = False


def wave_fronts(engine, waves, material, t: float, x: float, incoming,
                direction: int, site=None, drop: bool = False) -> list[WaveSpec] | None:
    """Fronts for the waves of one direction leaving an event at ``(x, t)``, leading first.

    ``None`` when the family is dropped (``drop``: weaker than the negligible stress and
    velocity, and affordable, as ``fronttrack.dropped.drops`` decides).  A single-ray
    wave leaving a ray's event keeps that ray's fan, so the rays of a fan stay one fan
    through the events that continue them.  ``site``: the
    event's site, if any (its kind decides the waves' ``lineage``).
    """
    if not waves:
        return []
    if drop:
        engine.counters.dropped_stress += sum(abs(w.behind.sigma - w.ahead.sigma)
                                              for w in waves)
        engine.counters.dropped_waves += 1
        return None
    parent = None
    for front in incoming:
        if front.direction == direction:
            parent = front
            break
    origin = lineage(engine, incoming, site)
    specs = []
    for wave in waves:
        if isinstance(wave, Fan):
            specs += _fan_fronts(engine, wave, material, t, x, parent, direction, origin)
            continue
        ray = _weak_shock_ray(engine, wave, material, t, x, parent, direction, origin)
        if ray is not None:
            specs.append(ray)
        else:
            wave_id = (parent.wave if parent is not None and parent.kind == FrontKind.SHOCK
                       else engine.next_wave_id())
            front = engine.new_front(FrontKind.SHOCK, x, t, speed=wave.speed, wave=wave_id,
                                     direction=direction, lineage=origin,
                                     jump=wave.behind.sigma - wave.ahead.sigma)
            specs.append(WaveSpec(front, wave.ahead, wave.behind, UNKNOWN))
    return _conserving(specs, material, engine.tables.tolerance)


def _conserving(specs: list[WaveSpec], material, tolerance: float) -> list[WaveSpec]:
    """The family ``specs`` (leading first) with the state behind each ray that would
    create energy carrying the energy its jump conditions need instead
    (``characteristics.ray_energy.conserving_state``).

    A ray is a jump between two states of one isentrope; at its speed an expansion ray
    creates energy, third order in its step.  A ray whose conserving state lies within
    ``tolerance`` (Pa, a stress gap at equal volume) of its isentrope table keeps the
    table's state: the tables do not tell such isentropes apart, as they do not tell a
    weak shock from a ray (``_weak_shock_ray``).  From the first ray shifted on, every
    wave of the family runs into a shifted state, and the state behind it is shifted
    too where its jump from there would create energy.  The last wave's behind state is
    the star state (``shifted`` from the first shift on)."""
    out, ahead, shifted = [], None, False
    for spec in specs:
        if shifted:
            spec = replace(spec, ahead=ahead)
        if shifted or (spec.front.kind == FrontKind.RAY and spec.table is not UNKNOWN):
            behind = conserving_state(material, spec.front.speed, spec.ahead, spec.behind)
            if not shifted and spec.table.matches(behind, tolerance):
                behind = spec.behind
            if shifted or behind is not spec.behind:
                shifted = True
                spec = replace(spec, behind=behind, shifted=True)
        out.append(spec)
        ahead = spec.behind
    return out


def negligible(engine, waves) -> bool:
    """Whether a family of ``waves`` (leading first) is weaker than the run resolves, by
    its total variation in stress and in velocity: a detonation and its Taylor wave to a
    free face (up to p_CJ and back to zero) is not a wave of zero strength."""
    if len(waves) == 1:  # most events: one wave, no sums to build
        (wave,) = waves
        return engine.resolution.is_negligible(wave.behind.sigma - wave.ahead.sigma,
                                               wave.behind.u - wave.ahead.u)
    return bool(waves) and engine.resolution.is_negligible(
        sum(abs(w.behind.sigma - w.ahead.sigma) for w in waves),
        sum(abs(w.behind.u - w.ahead.u) for w in waves))


def _weak_shock_ray(engine, shock, material, t, x, parent, direction,
                    origin) -> WaveSpec | None:
    """A shock weaker than the characteristic step, as a compression characteristic.

    At the resolution of the run it cannot be told from a compression wave: its entropy
    jump is third order in its strength, below the tolerance within which states share
    an isentrope table.  "Weaker than the step" is measured where the shock runs
    (``_step_at``): a characteristic keeps its jump of Riemann invariant, not of stress,
    as it crosses other waves.  As a ray it joins the lattices of the fans around it instead
    of meeting each of their rays in a Riemann problem; compression rays that converge
    form a shock again where they meet.  ``None`` if the shock is stronger than the
    step, or its states have no common table (or one lies past the table's end: a face
    whose release stopped at the end of its equation of state, ``release_target``).
    """
    res = engine.resolution
    if not getattr(material, "makes_fans", False):
        return None  # no isentrope table (characteristics.isentrope): its shocks stay shocks
    if res.release != "isentrope" or abs(shock.behind.u - shock.ahead.u) > \
            res.velocity_step_of(material, shock.ahead, shock.behind):
        return None
    table = engine.tables.table(material, shock.ahead)
    if table is None or not table.matches(shock.behind, engine.tables.tolerance):
        return None
    try:
        ahead, behind = table.invariants(shock.ahead), table.invariants(shock.behind)
        step = _step_at(table, shock.behind, res.step)
    except StateOutOfRangeError:  # a state at the end of the table's equation of state
        return None
    if abs(shock.behind.sigma - shock.ahead.sigma) > step:
        return None
    if not table.resolves(abs(ahead[0] - behind[0]) + abs(ahead[1] - behind[1])):
        return None
    middle = (0.5 * (ahead[0] + behind[0]), 0.5 * (ahead[1] + behind[1]))
    fan_id = parent.fan if parent is not None and parent.kind == FrontKind.RAY else \
        engine.next_wave_id()
    speed = direction * table.speed(*middle)
    front = engine.new_front(FrontKind.RAY, x, t, speed=speed,
                             fan=fan_id, ray_count=1, direction=direction, lineage=origin,
                             jump=shock.behind.sigma - shock.ahead.sigma,
                             invariant=middle[0 if direction > 0 else 1])
    return WaveSpec(front, shock.ahead, shock.behind, table)


def _step_at(table, state: State, step: float) -> float:
    """The stress jump (Pa) across one characteristic step at ``state`` on ``table``'s
    isentrope: ``step`` (Pa) scaled by the impedance ``rho0 C_L`` there over that at zero
    stress, where the free faces cut their release fans into steps of at most ``step``.

    A characteristic keeps its jump of Riemann invariant ``2 du = 2 d sigma / (rho0
    C_L)`` as it crosses other waves, so its stress jump grows with the impedance of the
    states it enters: a step of a release fan born at a free face carries 8 % more
    stress in Al 2024 at 3 GPa, and a compression step that crossed a shock there is
    still one step (the symmetric Al 2024 impact at 16 rays: the steps of 246 MPa came
    out of their Riemann solves as shocks of 250-270 MPa, every one then a Riemann
    solve with each ray it met).  Never less than ``step``."""
    at_zero = table.speed_at_stress(0.0)
    if not at_zero > 0.0:
        return step
    return step * max(1.0, table.speed_at_stress(state.sigma) / at_zero)


def _fan_fronts(engine, fan: Fan, material, t, x, parent, direction,
                origin) -> list[WaveSpec]:
    # a one-ray wave uses the table of its isentrope if there is one already; a family
    # of several characteristics (which lattices will cross) builds one
    res = engine.resolution
    velocity_step = res.velocity_step_of(material, fan.ahead, fan.behind)
    several = (abs(fan.behind.sigma - fan.ahead.sigma) > res.step
               or abs(fan.behind.u - fan.ahead.u) > velocity_step)
    table = (engine.tables.table(material, fan.ahead, build=several)
             if res.release == "isentrope" else None)
    # vacuum (a gas expanded to zero pressure) ends every isentrope of the gas
    if table is not None and math.isfinite(fan.behind.v) \
            and not table.matches(fan.behind, engine.tables.tolerance):
        table = None
    # a fan near the end of an equation of state's range, on an isentrope within the
    # tolerance of the table's, may reach stresses past the table's end
    if table is not None and not table.covers(fan.behind.sigma):
        table = None
    # detonation products: their own table places the characteristics (equal steps of
    # stress and velocity towards vacuum); the cells keep none (no lattice, no reading)
    own = fan_table(fan) if table is None and res.release == "isentrope" else None
    characteristics = discretise_fan(fan, material, res.step, table or own, velocity_step)
    if table is not None and not diverging(characteristics):
        # the table's isentrope is too far from the fan's own for its steps: the curve's
        # exact states (characteristics.simple_waves.diverging)
        table = None
        characteristics = discretise_fan(fan, material, res.step, None, velocity_step)
    if len(characteristics) == 1 and parent is not None and parent.kind == FrontKind.RAY:
        fan_id, index, count = parent.fan, parent.ray_index, parent.ray_count
    else:
        fan_id, index, count = engine.next_wave_id(), None, len(characteristics)
    which = 0 if direction > 0 else 1
    specs = []
    for ch in characteristics:
        invariant = table.invariants(ch.state)[which] if table is not None else math.nan
        front = engine.new_front(FrontKind.RAY, x, t, speed=ch.speed, fan=fan_id,
                                 ray_index=ch.index if index is None else index,
                                 ray_count=count, direction=direction, lineage=origin,
                                 jump=ch.behind.sigma - ch.ahead.sigma, invariant=invariant)
        specs.append(WaveSpec(front, ch.ahead, ch.behind,
                              table if table is not None else UNKNOWN))
    return specs
