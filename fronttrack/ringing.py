"""Ringing layers ended at their limit: the rest of a geometric series summed at once.

A layer bounded by two sites (interfaces with *anvils* beyond them, or a free face, a
gap or a wall) rings: a wave in it reflects at each face with a stress
reflection coefficient ``R = (Z - z) / (Z + z)`` (``z`` the layer's acoustic impedance
``rho0 C_L``, ``Z`` the anvil's; ``R = -1`` at a free face or a gap, ``+1`` at a wall)
and sends the rest ``T = 1 + R`` into the anvil.  Echo ``n`` is ``a r^n`` with
``r = R_left R_right``: the series converges when ``|r| < 1``, and for linear elastic
solids its sum is exact and known in closed form.  A wave of amplitude ``a`` arriving
at the right face sends ``T_R a (1 + r + r^2 + ...) = T_R a / (1 - r)`` into the right
anvil and ``T_L R_R a / (1 - r)`` into the left one; summed, the layer and the anvils
next to it end in the state the two anvils would reach in direct contact (the
impedance match of the anvils' states through the layer, which drops out).  For a
layer on a free face the limit is that face at zero stress moving with the anvil's
answer; on a wall, at rest.

**When.**  At an event where the layer's waves reach one of its faces, with ``a`` the
largest stress jump inside the layer, ``tau = d / C`` the layer's transit time and
``C`` the fastest anvil sound speed, the rest of the series is replaced once

- its pointwise effect on any record is below the stress tolerance ``tol`` (at most
  ``DEFAULT_RECORD_FRACTION`` of the stress scale): every later echo together moves a
  stress by at most ``2 a / (1 - |r|)``; and every state of the layer and of the anvils
  next to it lies within ``tol`` and the velocity tolerance of the limit;
- its effect on a record's timing is within the visibility budget of coalescing
  (``fronttrack.coalesce``): replacing the staircase of echoes by one step at once
  moves echo ``n`` by ``2 n tau`` at most, an L1-in-time error of at most
  ``2 a 2 tau / (1 - |r|)^2``; as a length (times ``C``) it is held to
  ``VISIBILITY tol l`` with ``l`` the resolution length.

A scene that keeps every front (``coalesce_length = 0``) or every wave
(``negligible_stress = 0``) keeps every echo.

**What.**  The limit state is the one Riemann solver's answer for the anvils' states
(``materials.solve_contact``, or ``solve_boundary`` against the free face or wall).
The layer's waves end; the layer takes the limit stress and velocity; each anvil
receives one wave (the solver's, which carries the exact sum of the series for linear
elastic solids and the contact state of the anvils for any solid), so the anvils end
in the state their staircase of echoes converges to.

**Conservation.**  Mass is exact (Lagrangian layer).  The series would have taken the
remaining echoes' time to bring the layer to its limit, by the anvils' impulse and
work on it; ended at once, the layer's stress and velocity jump to the limit and what
the anvils would still have exchanged with it is not exchanged: its momentum changes by
``rho0 (d u* - sum w_i u_i)``, counted (``momentum``, kg/(m^2 s)).  Its internal energy
is chosen to keep its total energy ``rho0 sum w_i (e_i + u_i^2/2)`` exactly, at the
limit stress (``energy_offset``, J/kg: that internal energy minus the one the layer's
own wave curve reaches at the limit stress; positive where the remaining ringing is
kept as heat, negative where the anvils' remaining work on the layer is not done).
No energy is created or lost by the replacement itself; where the equation of state
admits no volume at that stress and energy the layer rings on.  Each replacement is
listed in ``accuracy["ringing_replaced"]``.
"""

from __future__ import annotations

import dataclasses
import itertools
import math

from materials import WavediagramError, solve_boundary, solve_contact
from materials.riemann import RiemannSolution

from . import coalesce, fragment
from .interactions import contact_strength
from .kinds import BoundaryKind, EventKind, FrontKind

MAX_WAVES = 8
"""A layer holding more waves than this is not taken for a ringing layer (the walk
across it stays cheap at every event)."""

ENERGY_ROUNDING = 1e-12
"""The energy-keeping volume is found when the stress there is within this fraction of
the stress scale of the limit stress."""

ANVIL_SITE = FrontKind.INTERFACE
"""The faces a layer rings between are interfaces between layers (or a free face, a gap
or a wall).  An entropy contact inside one material reflects next to nothing (``R``
near 0): a strip between two is not a ringing layer, and contacts may be coalesced
(``fronttrack.coalesce``) while the layer's faces must persist."""


@dataclasses.dataclass
class _Face:
    """One face of a layer: its site, the region beyond it (``None`` for a free face,
    a gap or a wall) and the condition there (``"anvil"``, ``"free"`` or ``"wall"``)."""

    site: object
    far: object
    condition: str


def try_end(engine, group, t: float) -> bool:
    """End the ringing of the layer whose waves in ``group`` reach its face at ``t``, if
    the rest of its series is below what the records resolve (module docstring);
    ``True`` if it was ended (the event is then done)."""
    res = engine.resolution
    if res.coalesce_length <= 0.0 or res.negligible <= 0.0:
        return False
    found = _layer(engine, group)
    if found is None:
        return False
    left, right, waves = found
    bounds = [left.site, *waves, right.site]
    regions = [f.region_right for f in bounds[:-1]]
    material = regions[0].material
    if any(r.material is not material for r in regions) or hasattr(material, "ignited"):
        return False
    tol, u_tol = coalesce.record_tolerance(res), res.velocity_tolerance
    states = [r.state for r in regions] + [f.far.state for f in (left, right) if f.far]
    if (max(s.sigma for s in states) - min(s.sigma for s in states) > 2.0 * tol
            or max(s.u for s in states) - min(s.u for s in states) > 2.0 * u_tol):
        return False
    limit = _limit(engine, left, right)
    if limit is None:
        return False
    sol, star = limit
    if any(abs(s.sigma - star.sigma) > tol or abs(s.u - star.u) > u_tol for s in states):
        return False
    widths = [max(q.position(t) - p.position(t), 0.0) for p, q in itertools.pairwise(bounds)]
    rep = regions[widths.index(max(widths))]
    r = _converging(engine, left, right, regions, rep, tol)
    if r is None:
        return False
    kept = _energy_keeping(engine, material, rep.state, star, regions, widths)
    if kept is None:
        return False
    layer_state, offset = kept
    _replace(engine, left, right, waves, regions, sol, layer_state, t)
    xa, xb = left.site.x0, right.site.x0
    momentum = material.rho0 * ((xb - xa) * star.u - sum(
        w * region.state.u for w, region in zip(widths, regions, strict=True)))
    engine.counters.ringing.append({
        "layer": regions[0].layer, "t": t, "x_lo": xa, "x_hi": xb, "reflection": r,
        "remaining_stress": max(abs(s.sigma - star.sigma) for s in states),
        "remaining_velocity": max(abs(s.u - star.u) for s in states),
        "sigma": star.sigma, "u": star.u, "momentum": momentum, "energy_offset": offset,
    })
    return True


def _converging(engine, left, right, regions, rep, tol: float) -> float | None:
    """The layer's round-trip reflection ``r = R_left R_right`` if its series converges
    and its rest is below the records' resolution (module docstring), else ``None``."""
    res = engine.resolution
    material = rep.material
    z = material.rho0 * material.sound_speed(rep.state.v, rep.state.e)
    r = _reflection(engine, left, z, -1) * _reflection(engine, right, z, +1)
    if not abs(r) < 1.0:
        return None
    # the next echo: the largest stress jump of the layer's waves
    a = max(abs(q.state.sigma - p.state.sigma) for p, q in itertools.pairwise(regions))
    tau = (right.site.x0 - left.site.x0) * material.rho0 / z
    fastest = max([f.far.material.sound_speed(f.far.state.v, f.far.state.e)
                   for f in (left, right) if f.far] + [z / material.rho0])
    if 2.0 * a / (1.0 - abs(r)) > tol or (
            4.0 * a * tau * fastest / (1.0 - abs(r)) ** 2
            > coalesce.VISIBILITY * tol * res.coalesce_length):
        return None
    return r


def _layer(engine, group):
    """``(left face, right face, waves)`` of the layer whose waves reach a face in
    ``group`` (every other front of ``group`` one of those waves), or ``None``."""
    if len(group) < 2:
        return None
    first, last = group[0].is_site, group[-1].is_site
    if last and not first:
        site, step, side, other_side = group[-1], "prev", "right", "left"
    elif first and not last:
        site, step, side, other_side = group[0], "next", "left", "right"
    else:
        return None
    if any(f.is_site for f in group[1:-1]):
        return None
    face = _face(engine, site, side)
    if face is None:
        return None
    waves, front = [], getattr(site, step)
    while front is not None and not front.is_site:
        waves.append(front)
        if len(waves) > MAX_WAVES:
            return None
        front = getattr(front, step)
    other = _face(engine, front, other_side) if front is not None else None
    if other is None or "anvil" not in (face.condition, other.condition):
        return None
    if step == "prev":
        waves.reverse()
        return other, face, waves
    return face, other, waves


def _face(engine, site, side: str) -> _Face | None:
    """The face of a layer at ``site`` on its ``side`` (``"left"``: the layer lies to the
    right of the site), or ``None`` if the site is not one a ringing layer ends at."""
    if site.kind == ANVIL_SITE:
        far = site.prev.region_right if side == "left" else site.region_right
        return _Face(site, far, "anvil") if far is not None else None
    if site.kind == FrontKind.GAP:
        return _Face(site, None, "free")
    if site.kind == FrontKind.BOUNDARY and site.piston_velocity is None:
        spec = engine.scene.left if site.side == "left" else engine.scene.right
        later = [s for s, _ in site.boundary_steps if s > site.t0]
        if spec.kind == BoundaryKind.FREE and not later:
            return _Face(site, None, "free")
        if spec.kind == BoundaryKind.WALL:
            return _Face(site, None, "wall")
    return None


def _limit(engine, left: _Face, right: _Face):
    """The Riemann solution between the two faces' anvils (or an anvil and a free face or
    wall) and the limit state (stress and velocity) the layer converges to; ``None``
    where there is none the contacts carry."""
    release = engine.resolution.release
    try:
        if left.condition == right.condition == "anvil":
            sol = solve_contact(left.far.material, left.far.state, right.far.material,
                                right.far.state, math.inf, release)
            star = sol.left_star
        elif left.condition == "anvil":
            sol = _against(left.far, "right", right.condition, release)
            star = sol.left_star
        else:
            sol = _against(right.far, "left", left.condition, release)
            star = sol.right_star
    except (WavediagramError, ValueError):
        return None
    for face in (left, right):
        if face.condition == "anvil" and star.sigma < -contact_strength(
                engine, face.site, face.far.material):
            return None
    return sol, star


def _against(region, boundary_at: str, condition: str, release) -> RiemannSolution:
    """An anvil's answer to a free face (zero stress) or a wall (at rest) at its side."""
    if condition == "free":
        return solve_boundary(region.material, region.state, boundary_at, stress=0.0,
                              release=release)
    return solve_boundary(region.material, region.state, boundary_at, velocity=0.0,
                          release=release)


def _reflection(engine, face: _Face, z: float, side: int) -> float:
    """Stress reflection coefficient of a wave in the layer (impedance ``z``) at ``face``
    (``side`` -1: the left face, the wave going left)."""
    if face.condition == "free":
        return -1.0
    if face.condition == "wall":
        return 1.0
    curve = face.far.material.wave_curve(face.far.state, side, engine.resolution.release)
    big_z = curve.impedance
    return (big_z - z) / (big_z + z)


def _on_curve(engine, material, state, star):
    """The layer's state on its own wave curve from ``state`` at the limit stress."""
    curve = material.wave_curve(state, +1, engine.resolution.release)
    return dataclasses.replace(curve.state_at(star.sigma), sigma=star.sigma, u=star.u)


def _energy_keeping(engine, material, rep, star, regions, widths):
    """The layer's limit state and its energy offset (J/kg): stress and velocity of
    ``star``, internal energy keeping the layer's total energy, volume where the
    equation of state gives that stress at that energy (the wave curve's volume where
    the stress does not depend on the energy); the offset is that internal energy less
    the wave curve's at the limit stress.  ``None`` if no such volume is found."""
    try:
        on_curve = _on_curve(engine, material, rep, star)
    except (WavediagramError, ValueError):
        return None
    mass = sum(widths)
    if not mass > 0.0:
        return None
    total = sum(w * (r.state.e + 0.5 * r.state.u ** 2)
                for w, r in zip(widths, regions, strict=True)) / mass
    e = total - 0.5 * star.u ** 2
    scale = max(abs(star.sigma), engine.resolution.stress_scale)
    if hasattr(material, "stress_at"):  # elastic-plastic: stress does not depend on e
        return dataclasses.replace(on_curve, e=e), e - on_curve.e
    v = material.volume_at(on_curve, star.sigma, e, ENERGY_ROUNDING * scale)
    if v is None:
        return None
    return dataclasses.replace(on_curve, v=v, e=e), e - on_curve.e


def _replace(engine, left: _Face, right: _Face, waves, regions, sol, layer_state,
             t: float) -> None:
    """End the layer's waves and regions at ``t``, start the layer's limit region and
    send each anvil its one wave (``engine.replace`` at each anvil face)."""
    a, b = left.site, right.site
    xa, xb = a.x0, b.x0
    for gap in (a, b):
        if gap.kind == FrontKind.GAP:  # the faces moved with the states next to them
            fragment.advance_gap(engine, gap, t)
    bounds = [a, *waves, b]
    for k, region in enumerate(regions):
        region.left_points.append((bounds[k].position(t), t))
        region.right_points.append((bounds[k + 1].position(t), t))
        region.t_end = t
    for wave in waves:
        wave.alive = False
        wave.t1, wave.x1 = t, wave.position(t)
        wave.right_region_id = wave.region_right.id
    layer = engine.new_region(layer_state, regions[0].material, regions[0].layer, t,
                              (xa, t), (xb, t))
    a.next, b.prev = b, a
    if left.condition == "anvil":
        engine.replace([a], a, None, RiemannSolution(sol.left_waves, (), sol.left_star,
                                                     layer_state),
                       left.far, layer, t, xa, waves, EventKind.RINGING)
    else:
        a.earlier_regions.append((t, regions[0].id))
        a.region_right = layer
        engine.push_pair(a, b, t)
    if right.condition == "anvil":
        engine.replace([b], b, None, RiemannSolution((), sol.right_waves, layer_state,
                                                     sol.right_star),
                       layer, right.far, t, xb, waves, EventKind.RINGING)
    for gap in (a, b):
        if gap.kind == FrontKind.GAP:
            engine.push_gap_closure(gap)
