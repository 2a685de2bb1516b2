"""Spall: fractures where the tension reaches the strength, and the zones they open.

With an instantaneous threshold a material point fractures when its tension reaches
the spall strength.  Inside a lattice the tension field is continuous, and the first
point where it reaches the strength, with the zone the threshold model fractures
around it, is found on the field (``characteristics.fracture``): the engine fractures
the first point, and the two ends of the zone when the field reaches them.  Inside
the zone the model would fracture every point (the level set of the strength
outruns the relief); the material there is reported as a fractured zone and its
tension is carried, not split into plates one characteristic apart.

Outside lattices (a tension made by a shock, at a contact) the Riemann problem at the
event separates; there too a point inside an earlier zone, or closer than the spall
spacing (``spacing``) to an earlier plane, carries the tension instead.

No plane is made closer than the spall spacing to an earlier plane of its layer, be it
from a Riemann problem or from a lattice's zone (a zone's end that close to its first
point, or a first point that close to an earlier plane): the slab between would be a
fragment thinner than the records resolve.  ``accuracy.spall_spacing`` sets the
spacing; by default it is the records' resolution length (``coalesce_length``).
"""

from __future__ import annotations

import heapq
import math
from dataclasses import dataclass

from characteristics.fracture import FractureZone

from . import solution


@dataclass(frozen=True)
class FracturePlan:
    """A fracture to make at ``x`` (m), ``t`` (s); ``tension`` and ``strength`` (Pa) for the
    record (``None``: the tension of the region there, under a damage criterion);
    ``open_end``: the open end of a lattice's zone (not made if the zone grew past it)."""

    x: float
    t: float
    tension: float | None
    strength: float
    zone: tuple | None = None
    open_end: bool = False


@dataclass(frozen=True)
class Zone:
    """A fractured zone of ``layer`` from ``x_lo`` to ``x_hi`` (m), opened at ``t`` (s); the
    level set reached its ends at ``t_lo``/``t_hi`` (s); an open end (``open_lo``/``open_hi``,
    see ``characteristics.fracture``) gets no plane and may be continued by a later lattice."""

    layer: int
    x_lo: float
    x_hi: float
    t: float
    t_lo: float = math.nan
    t_hi: float = math.nan
    open_lo: bool = False
    open_hi: bool = False


def schedule(engine, lattice, layer: int, t_now: float) -> None:
    """Plan the fractures a lattice found: its first point and its zone's ends.

    A first point beyond an earlier zone's open end (``characteristics.fracture``),
    reached from that end faster than sound and within a spall spacing's sound transit
    of it (``_continued``), is the level set going on, not a new fracture: the earlier
    zone is extended over the new one (``_extend``), the first point is no plane
    (counted as a suppressed spall) and only the extended zone's new ends are planned.
    The open ends of an extended zone are planned that transit late
    (``spacing * slowness``): the level set is known to be moving there, a relief that
    much late is below the records' resolution, and the next lattice finding it going
    on in that time extends the zone again (the pending plane, now inside the zone, is
    not made: ``outgrown``).  A zone the lattices find one window at a time is then one
    zone, as one lattice spanning it finds it, not a plane every window (stack of
    Cu/Al 2024 at 1 km/s: a plane every 5-12 um of the Cu before)."""
    found: FractureZone = lattice.fracture
    strength = lattice_strength(engine, layer)
    earlier = _continued(engine, layer, found)
    if earlier is None:
        zone = Zone(layer=layer, x_lo=found.x_lo, x_hi=found.x_hi, t=found.t, t_lo=found.t_lo,
                    t_hi=found.t_hi, open_lo=found.open_lo, open_hi=found.open_hi)
        engine.fracture_zones.append(zone)
        points = [(found.x, found.t, False)]
        x_tol = max(engine.resolution.x_tol, 1e-6 * (zone.x_hi - zone.x_lo))
    else:
        zone = _extend(engine, earlier, found)
        points, x_tol = [], -math.inf  # no plane at the first point: any new end is one
        carry(engine, strength)
    delay = spacing(engine) * found.slowness if earlier is not None else 0.0
    if zone.x_hi == found.x_hi and found.x_hi - found.x > x_tol:
        points.append((found.x_hi, found.t_hi + delay * zone.open_hi, zone.open_hi))
    if zone.x_lo == found.x_lo and found.x - found.x_lo > x_tol:
        points.append((found.x_lo, found.t_lo + delay * zone.open_lo, zone.open_lo))
    for x, t, open_end in points:
        _push(engine, FracturePlan(x=x, t=max(t, t_now), tension=strength, strength=strength,
                                   zone=(zone.x_lo, zone.x_hi), open_end=open_end))


def _continued(engine, layer: int, found: FractureZone) -> Zone | None:
    """The earlier zone of ``layer`` whose open end the first point of ``found`` continues:
    beyond that end, reached from it faster than sound (``|dt| < dx / C``) and within a
    spall spacing's sound transit of it (``schedule``)."""
    transit = spacing(engine) * found.slowness
    for zone in engine.fracture_zones:
        if zone.layer != layer:
            continue
        if zone.open_lo and _goes_on(found, zone.x_lo - found.x, zone.t_lo, transit):
            return zone
        if zone.open_hi and _goes_on(found, found.x - zone.x_hi, zone.t_hi, transit):
            return zone
    return None


def _goes_on(found: FractureZone, distance: float, t_end: float, transit: float) -> bool:
    """Whether the first point of ``found``, ``distance`` (m) beyond a zone's end reached at
    ``t_end`` (s), continues its level set: beyond it, faster than sound, in time."""
    return (distance > 0.0 and found.t < t_end + transit
            and abs(found.t - t_end) < found.slowness * distance)


def _extend(engine, zone: Zone, found: FractureZone) -> Zone:
    """``zone`` extended over ``found`` (its ends where they reach further), in place in
    ``engine.fracture_zones``."""
    lo = ((found.x_lo, found.t_lo, found.open_lo) if found.x_lo < zone.x_lo
          else (zone.x_lo, zone.t_lo, zone.open_lo))
    hi = ((found.x_hi, found.t_hi, found.open_hi) if found.x_hi > zone.x_hi
          else (zone.x_hi, zone.t_hi, zone.open_hi))
    extended = Zone(layer=zone.layer, x_lo=lo[0], x_hi=hi[0], t=zone.t, t_lo=lo[1], t_hi=hi[1],
                    open_lo=lo[2], open_hi=hi[2])
    engine.fracture_zones[engine.fracture_zones.index(zone)] = extended
    return extended


def schedule_point(engine, x: float, t: float, strength: float) -> None:
    """Plan a fracture at ``(x, t)`` found by a cumulative-damage criterion (``damage``)."""
    _push(engine, FracturePlan(x=x, t=t, tension=None, strength=strength))


def lattice_strength(engine, layer: int) -> float:
    return engine.scene.layers[layer].material.spall_strength


def _push(engine, plan: FracturePlan) -> None:
    heapq.heappush(engine.planned_fractures, plan.t)
    engine.push_fracture(plan)


def next_scheduled(engine, t: float) -> float:
    """The earliest planned fracture after ``t`` (s), inf if none (one at ``t`` itself has
    been made: fractures come first among the events of one instant)."""
    pending = engine.planned_fractures
    while pending and pending[0] <= t:
        heapq.heappop(pending)
    return pending[0] if pending else math.inf


def spacing(engine) -> float:
    """The distance (m) from a plane within which no other plane of its layer is made:
    ``accuracy.spall_spacing``, by default the records' resolution length (a plane
    closer than that would bound a fragment the records do not resolve)."""
    if engine.acc.spall_spacing is not None:
        return engine.acc.spall_spacing
    return engine.resolution.coalesce_length


def carried_intervals(engine, layer: int) -> tuple:
    """``(x_lo, x_hi)`` intervals of ``layer`` (m) where tension is carried, not fractured:
    the fracture zones, and the spall spacing (``spacing``) around each plane."""
    intervals = [(z.x_lo, z.x_hi) for z in engine.fracture_zones if z.layer == layer]
    width = spacing(engine)
    if width > 0.0:
        intervals += [(s.x - width, s.x + width) for s in engine.spalls
                      if s.layer == layer]
    return tuple(intervals)


def suppressed(engine, x: float, layer: int) -> bool:
    """True when a fracture at ``x`` (m) would fall inside a carried interval."""
    return any(lo < x < hi for lo, hi in carried_intervals(engine, layer))


def outgrown(engine, plan: FracturePlan, layer: int) -> bool:
    """True when ``plan`` is a zone's open end that a later lattice's zone grew past: the
    point now lies inside a fracture zone of ``layer`` (``schedule``)."""
    return plan.open_end and any(z.x_lo < plan.x < z.x_hi for z in engine.fracture_zones
                                 if z.layer == layer)


def carry(engine, tension: float) -> None:
    """Count a fracture not made, its ``tension`` (Pa, positive) carried instead."""
    counters = engine.counters
    counters.suppressed_spalls += 1
    counters.suppressed_tension = max(counters.suppressed_tension, tension)


def beside_plane(engine, x: float, layer: int) -> bool:
    """True when ``x`` (m) lies closer than the spall spacing to a plane of ``layer``."""
    within = spacing(engine)
    return any(abs(s.x - x) < within for s in engine.spalls if s.layer == layer)


def record(engine, x: float, t: float, tension: float, strength: float, layer: int,
           zone: tuple | None = None) -> None:
    """Add a fracture to the solution's spall records."""
    engine.spalls.append(solution.SpallRecord(x=x, t=t, tension=tension,
                                              strength=strength, layer=layer, zone=zone))
