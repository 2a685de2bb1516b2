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
    record (``None``: the tension of the region there, under a damage criterion)."""

    x: float
    t: float
    tension: float | None
    strength: float
    zone: tuple | None = None


@dataclass(frozen=True)
class Zone:
    """A fractured zone of ``layer`` from ``x_lo`` to ``x_hi`` (m), opened at ``t`` (s)."""

    layer: int
    x_lo: float
    x_hi: float
    t: float


def schedule(engine, lattice, layer: int, t_now: float) -> None:
    """Plan the fractures a lattice found: its first point and its zone's ends."""
    found: FractureZone = lattice.fracture
    strength = lattice_strength(engine, layer)
    zone = (found.x_lo, found.x_hi)
    engine.fracture_zones.append(Zone(layer=layer, x_lo=found.x_lo, x_hi=found.x_hi,
                                      t=found.t))
    points = [(found.x, found.t)]
    x_tol = max(engine.resolution.x_tol, 1e-6 * (found.x_hi - found.x_lo))
    if found.x_hi - found.x > x_tol:
        points.append((found.x_hi, found.t_hi))
    if found.x - found.x_lo > x_tol:
        points.append((found.x_lo, found.t_lo))
    for x, t in points:
        _push(engine, FracturePlan(x=x, t=max(t, t_now), tension=strength, strength=strength,
                                   zone=zone))


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


def beside_plane(engine, x: float, layer: int) -> bool:
    """True when ``x`` (m) lies closer than the spall spacing to a plane of ``layer``."""
    within = spacing(engine)
    return any(abs(s.x - x) < within for s in engine.spalls if s.layer == layer)


def record(engine, x: float, t: float, tension: float, strength: float, layer: int,
           zone: tuple | None = None) -> None:
    """Add a fracture to the solution's spall records."""
    engine.spalls.append(solution.SpallRecord(x=x, t=t, tension=tension,
                                              strength=strength, layer=layer, zone=zone))
