"""Events solved as one Riemann problem: impacts, shocks, contacts, boundaries, spall.

At an event the engine has the state left of the group of fronts meeting there and
the state right of it; this module decides which Riemann problem that is and solves
it with ``materials.solve_contact`` or ``materials.solve_boundary``:

- at a boundary: the reflected wave from ``solve_boundary`` with the prescribed
  stress or velocity (a timer event when the prescribed value steps);
- at an interface or entropy contact: ``solve_contact`` with the contact's tensile
  strength (0 if unbonded, the weaker spall strength if bonded); beyond it the
  contact opens into a gap (two free surfaces);
- at an open gap: each face reflects as a free surface; the gap closes (a new
  impact) when the Eulerian positions of its two faces meet;
- inside a material (collisions and overtakings involving a shock, rays of
  different isentropes): ``solve_contact`` with the material's spall strength (rays
  crossing on one plastic release path of a finite-plastic solid: the closed form of
  ``materials.release_crossing``, the same solution); a
  tension beyond it fractures the material there, unless the point lies inside the
  zone of an earlier fracture (``fronttrack.spall``).

Prescribed boundary histories are followed by steps (``boundary_steps``); a ramp
launches a simple wave, one characteristic per step.
"""

from __future__ import annotations

import dataclasses
import math

from materials import (
    NoSolutionError,
    RiemannSolution,
    StateOutOfRangeError,
    solve_boundary,
    solve_contact,
)

from . import initiation, spall
from .fronts import Front
from .kinds import BoundaryKind, EventKind, FrontKind


def contact_strength(engine, site: Front | None, material) -> float:
    """Tension (Pa) the material or contact at an event can carry.

    Under a cumulative-damage criterion the material itself never fails instantly.  An
    unbonded contact carries tension up to the negligible stress: a rounding-level
    tension (a free-surface state is zero only to a few ulps of the stresses that made
    it) must not open a gap.
    """
    if site is None or site.kind == FrontKind.CONTACT:
        strength = (material.spall_strength if engine.scene.spall_criterion is None
                    else math.inf)
    else:
        strength = site.strength
    return max(strength, engine.resolution.negligible)


def solve(engine, site, region_left, region_right, t, x, incoming, timer):
    """Riemann problem at the event; returns ``(kind, solution, new_site)``."""
    release = engine.resolution.release
    lit = initiation.solve(engine, site, region_left, region_right, t, timer)
    if lit is not None:
        return (*lit, None)
    if site is not None and site.kind == FrontKind.BOUNDARY:
        kind, sol = _boundary(engine, site, region_left, region_right, t, incoming, timer)
        return kind, sol, None
    if site is not None and site.kind == FrontKind.GAP:
        if timer:  # the closure (any wave arriving at that instant joins the impact)
            site.kind = FrontKind.INTERFACE
            site.bond = "unbonded"
            site.strength = 0.0
            site.gap_version += 1
            site.history.append((t, site.kind))
            sol = solve_contact(region_left.material, region_left.state, region_right.material,
                                region_right.state, contact_strength(engine, site, None),
                                release)
            return EventKind.GAP_CLOSE, sol, None
        left = solve_boundary(region_left.material, region_left.state, "right", stress=0.0,
                              release=release)
        right = solve_boundary(region_right.material, region_right.state, "left", stress=0.0,
                               release=release)
        return EventKind.REFLECTION, combine(left, right), None
    strength = contact_strength(engine, site, region_left.material)
    sol = None
    if site is None and region_left.material is region_right.material:
        # rays crossing on one plastic release path: its closed form
        sol = engine.release_paths.crossing(region_left.material, region_left.state,
                                            region_right.state, strength, release)
    if sol is None:
        sol = solve_contact(region_left.material, region_left.state, region_right.material,
                            region_right.state, strength, release)
    if site is None:
        directions = {f.direction for f in incoming}
        kind = EventKind.COLLISION if directions == {-1, 1} else EventKind.OVERTAKE
    elif not incoming:
        kind = EventKind.IMPACT
    else:
        kind = EventKind.TRANSMISSION
    new_site = None
    inside = site is None or site.kind == FrontKind.CONTACT
    if sol.separated and inside and spall.suppressed(engine, x, region_left.layer):
        # inside the zone of an earlier fracture: carried as tension, and reported,
        # unless the tension would leave the equations of state (then it fractures)
        try:
            carried = solve_contact(region_left.material, region_left.state,
                                    region_right.material, region_right.state, math.inf,
                                    release)
        except NoSolutionError:
            carried = None
        if carried is not None and not carried.separated:
            spall.carry(engine, -sol.bonded_sigma)
            sol = carried
    if sol.separated:
        if inside:
            kind = EventKind.SPALL
            if not math.isfinite(strength):
                # no spall strength: pulled to the most tension its equation of state
                # carries, the material cavitates there
                strength = -sol.bonded_sigma
                engine.counters.cavitations += 1
            spall.record(engine, x, t, -sol.bonded_sigma, strength, region_left.layer)
        else:
            kind = EventKind.GAP_OPEN
        if site is None:
            new_site = engine.new_front(FrontKind.GAP, x, t, bond="unbonded")
            new_site.gap_time = t
        else:
            site.kind = FrontKind.GAP
            site.gap_width, site.gap_time = 0.0, t
            site.history.append((t, site.kind))
    return kind, sol, new_site


def _boundary(engine, site, region_left, region_right, t, incoming, timer):
    spec = engine.scene.left if site.side == "left" else engine.scene.right
    region = region_right if site.side == "left" else region_left
    value = boundary_value(site, spec, t)
    if timer:
        _schedule_next_step(engine, site, t)
    release = engine.resolution.release
    kind = EventKind.REFLECTION if incoming else EventKind.BOUNDARY
    if spec.kind in (BoundaryKind.FREE, BoundaryKind.STRESS):
        return _traction(engine, site, region, value, t, kind)
    if pushes_only(engine, site, spec) or site.piston_velocity is not None:
        return _piston(engine, site, region, value, t, kind)
    try:
        sol = solve_boundary(region.material, region.state, site.side, velocity=value,
                             release=release)
    except NoSolutionError:
        if not _pulls(region, site.side, value, release):
            raise
    else:
        tension = -(sol.right_star if site.side == "left" else sol.left_star).sigma
        strength = contact_strength(engine, None, region.material)
        if tension <= strength:
            return kind, sol
        # the material at the face, pulled beyond its spall strength, tears off
        tear_face(engine, site, region, t, tension, strength)
        return _piston(engine, site, region, value, t, kind)
    # a wall or bonded piston pulling beyond the most tension the equation of state
    # carries: the material cavitates at the face, which comes free of the boundary
    engine.counters.cavitations += 1
    limit = _most_tension(region, site.side, release)
    spall.record(engine, site.x0, t, limit, limit, region.layer)
    return _piston(engine, site, region, value, t, kind)


def pushes_only(engine, site, spec) -> bool:
    """Whether a velocity boundary (``spec``: its scene entry) pushes its face but
    cannot pull it: an unbonded piston, or a wall or bonded piston whose face was torn
    off (``tear_face``)."""
    return (spec.kind == BoundaryKind.VELOCITY and spec.bond != "bonded"
            or site.id in engine.torn_faces)


def tear_face(engine, site, region, t: float, tension: float, strength: float,
              zone=None) -> None:
    """Record the fracture of the material at the face of a wall or bonded piston
    (``site``; ``region`` the cell at it) at ``t`` (s) under ``tension`` (Pa) beyond
    ``strength`` (Pa): the face comes free of the boundary (a gap opens between them,
    ``_piston``) and is held by it in compression only from then on (``pushes_only``)."""
    engine.torn_faces.add(site.id)
    spall.record(engine, site.x0, t, tension, strength, region.layer, zone)


def _fracture_face(engine, site, plan) -> None:
    """A fracture planned at the face of a wall or bonded piston (a lattice's zone
    reaching it, ``characteristics.fracture``): the face tears off (``tear_face``) and
    comes free at once; a face not in tension is left alone."""
    region = site.region_right if site.side == "left" else site.prev.region_right
    if region is None or region.state.sigma >= 0.0:
        return
    tension = plan.tension if plan.tension is not None else -region.state.sigma
    tear_face(engine, site, region, plan.t, tension, plan.strength, plan.zone)
    engine._process([site], plan.t, site.x0, timer=False)


def _most_tension(region, side: str, release: str) -> float:
    """The most tension (Pa, positive) the material at a boundary's face can reach from
    its state: the tensile end of the range of the wave curve it reflects along."""
    direction = 1 if side == "left" else -1
    low, _ = region.material.wave_curve(region.state, direction, release).sigma_limits()
    return -low


def _traction(engine, site, region, stress: float, t: float, kind):
    """A prescribed stress ``stress`` (Pa, tension negative) on the face at time ``t`` (s).

    Tension beyond what the material can carry, its spall strength or else the most
    tension its equation of state reaches, fractures it at the face: the skin the load
    pulls on tears off (a ``SPALL`` event at the face, in ``spall``; a material without
    a spall strength cavitates), and the face is free from then on.  A torn face still
    takes compression, which presses the torn skin back onto it, but no tension.
    """
    release = engine.resolution.release
    torn = any(kind == FrontKind.GAP for _, kind in site.history)  # apart from its load
    if torn:
        stress = max(stress, 0.0)
    strength = contact_strength(engine, None, region.material)
    if stress >= -strength:
        try:
            return kind, solve_boundary(region.material, region.state, site.side,
                                        stress=stress, release=release)
        except StateOutOfRangeError:
            if stress >= 0.0:
                raise
        engine.counters.cavitations += 1  # beyond the equation of state: cavitation
        strength = _most_tension(region, site.side, release)
    if not torn:
        site.history.append((t, FrontKind.GAP))
    spall.record(engine, site.x0, t, -stress, strength, region.layer)
    return EventKind.SPALL, solve_boundary(region.material, region.state, site.side,
                                           stress=0.0, release=release)


def _pulls(region, side: str, velocity: float, release) -> bool:
    """Whether holding the face at ``velocity`` needs tension: the boundary moves away
    from the face faster than the face would move free (``False`` where its equation of
    state cannot reach zero stress: then the face cannot come free either)."""
    try:
        free = solve_boundary(region.material, region.state, side, stress=0.0,
                              release=release)
    except StateOutOfRangeError:
        return False
    face = free.right_star if side == "left" else free.left_star
    outward = -1.0 if side == "left" else 1.0
    return outward * (velocity - face.u) > 0.0


def _piston(engine, site, region, velocity: float, t: float, kind):
    """A velocity boundary that pushes but cannot pull (an unbonded piston).

    In contact, the face moves with the piston unless that needs tension: then the face
    unloads to a free surface and a gap opens between it and the piston.  While apart,
    the gap's width changes at the difference of the face's and the piston's velocities
    (both piecewise constant between events: the boundary's history is stepped), and the
    two meet again when it closes: the piston strikes the face (a velocity reflection).
    Opening and closing are ``GAP_OPEN`` and ``GAP_CLOSE`` events of the boundary.
    """
    release = engine.resolution.release
    outward = -1.0 if site.side == "left" else 1.0  # direction from the face to the piston
    if site.piston_velocity is not None:
        opening = outward * (site.piston_velocity - region.state.u)
        site.gap_width += opening * (t - site.gap_time)
        site.gap_time = t
        if site.gap_width > engine.resolution.x_tol:
            site.piston_velocity = velocity
            _push_piston_closure(engine, site, region.state.u, t)
            return kind, solve_boundary(region.material, region.state, site.side, stress=0.0,
                                        release=release)
        site.piston_velocity = None  # the piston meets the face again
        site.gap_version += 1
        site.history.append((t, FrontKind.BOUNDARY))
        _schedule_next_step(engine, site, t)
        kind = EventKind.GAP_CLOSE
    try:
        sol = solve_boundary(region.material, region.state, site.side, velocity=velocity,
                             release=release)
        tension = sol.bonded_sigma
    except NoSolutionError:
        if not _pulls(region, site.side, velocity, release):
            raise
        tension = -math.inf  # beyond the most tension the equation of state carries
    if tension >= 0.0:
        return kind, sol
    free = solve_boundary(region.material, region.state, site.side, stress=0.0,
                          release=release)
    free = dataclasses.replace(free, separated=True,
                               bonded_sigma=tension if math.isfinite(tension) else 0.0)
    site.piston_velocity, site.gap_width, site.gap_time = velocity, 0.0, t
    site.history.append((t, FrontKind.GAP))
    face = free.right_star if site.side == "left" else free.left_star
    _push_piston_closure(engine, site, face.u, t)
    return EventKind.GAP_OPEN, free


def _push_piston_closure(engine, site, face_velocity: float, t: float) -> None:
    """Queue the time the piston reaches its face again, if it is closing in on it
    (a new version of the site's events: the boundary's next step is queued again)."""
    site.gap_version += 1
    _schedule_next_step(engine, site, t)
    outward = -1.0 if site.side == "left" else 1.0
    closing = outward * (face_velocity - site.piston_velocity)
    if closing > 0.0:
        engine.push_site(site, t + site.gap_width / closing)


def combine(left_solution, right_solution) -> RiemannSolution:
    """Two independent free-surface reflections on either side of an open gap."""
    return RiemannSolution(left_waves=left_solution.left_waves,
                           right_waves=right_solution.right_waves,
                           left_star=left_solution.left_star,
                           right_star=right_solution.right_star, separated=True,
                           bonded_sigma=0.0, release_floor=(left_solution.release_floor
                                                            or right_solution.release_floor))


def fracture(engine, plan) -> None:
    """Fracture the material at ``plan.x``, ``plan.t``: two free surfaces, an opening gap.

    The region there is cut in two and the two halves become the faces of a new gap;
    each face then reflects as a free surface.  A point on a front, or not in tension,
    is left alone; so is a point of a lattice's zone closer than the spall spacing to an
    earlier plane of its layer (``spall.beside_plane``: counted as a suppressed spall),
    and a zone's open end that the zone has since grown past (``spall.outgrown``).
    A point at the face of a wall or bonded piston tears the face off
    (``_fracture_face``).
    """
    x, t = plan.x, plan.t
    x_tol = engine.resolution.x_tol
    before = engine.head
    while before.next is not None and before.next.position(t) <= x:
        before = before.next
    if before.kind == FrontKind.BOUNDARY and abs(before.position(t) - x) <= x_tol:
        spec = engine.scene.left if before.side == "left" else engine.scene.right
        if spec.kind in (BoundaryKind.WALL, BoundaryKind.VELOCITY) and not pushes_only(
                engine, before, spec):
            _fracture_face(engine, before, plan)
        return
    after = before.next
    if after is None:
        return
    if x - before.position(t) <= x_tol or after.position(t) - x <= x_tol:
        # on a front (the first point of a level set often is a ray): in the more
        # tensile of the two cells beside it, a hair from the front
        on = before if x - before.position(t) <= x_tol else after
        if on.is_site or on.prev is None or on.region_right is None:
            return
        left, right = on.prev.region_right, on.region_right
        width = min(on.position(t) - on.prev.position(t), on.next.position(t) - on.position(t))
        shift = min(1e-6 * engine.resolution.length, 0.5 * width)
        if right.state.sigma <= left.state.sigma:
            before, after, x = on, on.next, on.position(t) + shift
        else:
            before, after, x = on.prev, on, on.position(t) - shift
    region = before.region_right
    if region is None or region.state.sigma >= 0.0 or not (
            x - before.position(t) > x_tol and after.position(t) - x > x_tol):
        return
    if spall.outgrown(engine, plan, region.layer):
        return  # the zone's end moved on (a later lattice extended the zone)
    if plan.zone is not None and spall.beside_plane(engine, x, region.layer):
        spall.carry(engine, -region.state.sigma)
        return
    x_left, x_right = before.position(t), after.position(t)
    region.left_points.append((x_left, t))
    region.right_points.append((x_right, t))
    region.t_end = t
    left = engine.new_region(region.state, region.material, region.layer, t, (x_left, t),
                             (x, t), table=region.table, in_fan=region.in_fan)
    right = engine.new_region(region.state, region.material, region.layer, t, (x, t),
                              (x_right, t), table=region.table, in_fan=region.in_fan)
    left.invariants = right.invariants = region.invariants
    gap = engine.new_front(FrontKind.GAP, x, t, bond="unbonded")
    gap.gap_time, gap.region_right = t, right
    before.earlier_regions.append((t, region.id))
    before.region_right = left
    before.next, gap.prev, gap.next, after.prev = gap, before, after, gap
    tension = plan.tension if plan.tension is not None else -region.state.sigma
    spall.record(engine, x, t, tension, plan.strength, region.layer, plan.zone)
    material, state = region.material, region.state
    release = engine.resolution.release
    sol = combine(solve_boundary(material, state, "right", stress=0.0, release=release),
                  solve_boundary(material, state, "left", stress=0.0, release=release))
    engine.replace([gap], gap, None, sol, left, right, t, x, [], EventKind.SPALL)


def boundary_value(site: Front, spec, t: float) -> float:
    """Prescribed stress (Pa) or velocity (m/s) of a boundary at time ``t`` (s)."""
    if spec.kind in (BoundaryKind.FREE, BoundaryKind.WALL):
        return 0.0
    value = spec.value_at(0.0)
    for step_time, step_value in site.boundary_steps:
        if step_time <= t * (1.0 + 1e-15):
            value = step_value
    return value


def next_step_time(site: Front, t: float) -> float:
    """The boundary's first prescribed step after ``t`` (s), inf if none."""
    later = (step_time for step_time, _ in site.boundary_steps
             if step_time > t * (1.0 + 1e-15))
    return next(later, math.inf)


def _schedule_next_step(engine, site: Front, t: float) -> None:
    """Queue the boundary's first prescribed step after ``t`` (its timer event)."""
    step_time = next_step_time(site, t)
    if math.isfinite(step_time):
        engine.push_site(site, step_time)


def boundary_steps(engine, spec, boundary: Front) -> list[tuple[float, float]]:
    """Times (s) and values at which a prescribed history changes the boundary value.

    A ramp is followed in steps that each carry at most one characteristic step of
    stress and of velocity (estimated with the impedance of the initial state): the value
    changes at the knots ``t_k`` of the ramp to its value at the
    middle of the next interval (the staggered cells of ``characteristics.simple_waves``)
    and reaches the end value at the ramp's end.
    """
    if spec.kind not in (BoundaryKind.VELOCITY, BoundaryKind.STRESS) or len(spec.history) < 2:
        return []
    end = 0 if boundary.side == "left" else -1
    material, state = engine.scene.layers[end].material, engine.initial_states[end]
    impedance = material.rho0 * material.sound_speed(state.v, state.e)  # of the initial state
    res = engine.resolution
    steps = []
    for (t0, y0), (t1, y1) in zip(spec.history[:-1], spec.history[1:], strict=True):
        if t1 == t0:  # a step
            steps.append((t1, y1))
            continue
        velocity = spec.kind == BoundaryKind.VELOCITY
        stress_jump = abs(y1 - y0) * (impedance if velocity else 1.0)
        velocity_jump = (abs(y1 - y0) if velocity
                         else abs(y1 - y0) / impedance if impedance > 0.0 else 0.0)
        count = (max(1, math.ceil(stress_jump / res.step - 1e-9),
                     math.ceil(velocity_jump / res.velocity_step - 1e-9))
                 if y1 != y0 else 0)
        for k in range(count):
            ta = t0 + (t1 - t0) * k / count
            tb = t0 + (t1 - t0) * (k + 1) / count
            steps.append((ta if k else max(ta, 0.0), spec.value_at(0.5 * (ta + tb))))
        if count:
            steps.append((t1, y1))
    # the value before the first step is value_at(0); drop steps with no change
    result, last = [], spec.value_at(0.0)
    for t, value in steps:
        if value != last and t <= engine.t_end:
            result.append((t, value))
            last = value
    return result
