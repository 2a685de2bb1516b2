"""Coalescing fronts that run together closer than the records resolve.

In a material whose waves of one family all move at one speed (the elastic and the
plastic waves of a small-strain elastic–plastic solid, whose stress is linear in
strain on each branch, or a linear-elastic solid), two waves of one family born a
little apart stay that little apart for ever.  Every later wave crosses each of them
in a separate event, and a crossing that yields splits them again: separated
elastic–plastic plates ring with trains of near-coincident waves whose count grows at
every yielding collision, while no record can tell a train from one wave.
Plastic-strain and entropy contacts left by such trains bunch the same way.

**Which pairs.**  Two neighbouring fronts ``a``, ``b`` with states ``L | M | R`` in one
material, a distance ``d`` apart, where ``l`` is the resolution length
(``Resolution.coalesce_length``) and ``tol`` the stress tolerance of the records (at
most 1e-3 of the stress scale):

- two waves of one direction and one speed, whose merged jump from ``L`` to ``R``
  satisfies the momentum jump condition ``sigma_L - sigma_R = +-rho0 C (u_L - u_R)``
  (on a linear branch it does, to rounding, and its energy jump is the trapezoid of a
  straight line, as each part's is: the merged wave is exact);
- two contacts whose outer states ``L`` and ``R`` differ in stress and velocity no
  more than across the wider of the two, or no more than a negligible wave
  (``Resolution.is_negligible``): a contact carries the mismatch a dropped wave
  leaves, and coalescing never leaves one wider than that (a comb of contacts whose
  mismatches add up, left by the rays of a fan each dropping a weak reflection, is
  one contact while their sum stays negligible);

and ``d <= l``, or, for a weak pair, ``w d <= VISIBILITY * tol * l`` with ``d <= REACH
* l``, where ``w`` is the weaker front's strength (a wave's stress jump; a contact's
offset of the yield stresses, ``Material.contact_reflection``). A record at a station
then sees a step of ``w`` displaced by ``d / C`` in time: its L1-in-time error per
passage, ``w d / C``, is held to ``VISIBILITY * tol * l / C``. A compression and a
release farther apart than ``l`` are a pulse whose peak a record (and a spall
criterion) reads: they are kept unless the pulse is weaker than ``tol``.

**Conservation.**  The strip ``[x_a, x_b]`` that held ``M`` is shared between ``L`` and
``R`` at the point ``x*`` that keeps its energy ``rho0 (e + u^2/2) d`` exactly.  Where
no point does because ``M`` holds more energy than either neighbour (a thin pulse),
the strip takes the neighbour of higher energy and energy is lost; where every point
would make energy (``M`` holds less than both) the pair is kept.  Mass is exact
(Lagrangian coordinates).  The momentum the strip gains or loses, ``rho0 [(x* - x_a)
u_L + (x_b - x*) u_R - d u_M]``, and the energy lost are counted
(``Counters.coalesced_momentum``, kg/(m^2 s); ``coalesced_energy``, J/m^2) and are part
of the run's balance.  All coalescing of a run together may move at most ``BUDGET`` of
the balance the accuracy settings promise (of the largest momentum and energy content
the run has held); beyond it every front is kept.  Half of that budget is open to any
pair, first come first served; the other half is held for pairs that spend at most
``SHARE`` of what is left of it.  Strong pairs cost much and save few events (a strong
wave is crossed by few others), while the trains of weak waves a ringing
elastic–plastic layer makes need thousands of cheap merges: spent first come first
served, a few merges of GPa waves at the impact of ``strength_stack_scene(7)`` took 90 %
of its momentum budget within 50 events, and every weak pair after them was kept.
"""

from __future__ import annotations

import math

from . import balance
from .fronts import MIXED, Front, inside_fan
from .kinds import FrontKind
from .resolution import DEFAULT_RECORD_FRACTION

VISIBILITY = 30.0
"""A weak pair farther apart than the resolution length is coalesced while the weaker
front's strength times the distance is at most this many ``tol * l`` (see the module
docstring)."""

REACH = 100.0
"""No pair farther apart than this many resolution lengths is coalesced."""

BUDGET = 0.5
"""Coalescing may move at most this fraction of the promised balance (see ``budget``);
beyond it, fronts are kept."""

OPEN = 0.5
"""The fraction of the budget any pair may spend, first come first served."""

SHARE = 0.01
"""Beyond ``OPEN``, one pair may spend at most this fraction of the budget still unspent,
in momentum and in energy: the rest lasts for many cheap pairs, not a few costly ones."""

SAME_SPEED = 1e-12
"""Two waves move at one speed when their speeds differ by less than this fraction."""

_SHOCK, _CONTACT = FrontKind.SHOCK, FrontKind.CONTACT  # read once: asked at every event

JUMP_TOLERANCE = 1e-9
"""A merged wave must satisfy its momentum jump condition to this fraction of the
stress scale (it does to rounding on a linear branch)."""


def coalesce_around(engine, fronts, t: float) -> None:
    """Coalesce each of ``fronts`` that is still alive with a neighbour when the pair
    qualifies (module docstring); a merged front is tried again with its neighbours."""
    res = engine.resolution
    if res.coalesce_length <= 0.0:
        return
    for front in fronts:
        if not front.alive:
            continue
        for a, b in ((front.prev, front), (front, front.next)):
            if a is None or b is None or not _similar(a, b) or a.prev is None:
                continue
            merged = _coalesce(engine, a, b, t)
            if merged is not None:
                coalesce_around(engine, [merged], t)
                break


def _similar(a: Front, b: Front) -> bool:
    """Both waves of one direction and one speed, or both contacts."""
    kind = a.kind
    if kind != b.kind:
        return False
    if kind == _SHOCK:
        return a.direction == b.direction and abs(a.speed - b.speed) <= SAME_SPEED * abs(a.speed)
    return kind == _CONTACT


def _coalesce(engine, a: Front, b: Front, t: float) -> Front | None:
    """Replace ``a`` and ``b`` by one front if the pair qualifies; the new front."""
    res = engine.resolution
    left, middle, right = a.prev.region_right, a.region_right, b.region_right
    if right is None or not (left.material is middle.material is right.material):
        return None
    xa, xb = a.position(t), b.position(t)
    distance = xb - xa
    if distance > res.coalesce_length:
        weaker = _weaker(a, b, left, middle, right, res.stress_scale)
        tolerance = record_tolerance(res)
        pulse = a.jump * b.jump < 0.0
        if distance > REACH * res.coalesce_length or (pulse and weaker > tolerance) or \
                weaker * distance > VISIBILITY * tolerance * res.coalesce_length:
            return None
    sl, sm, sr = left.state, middle.state, right.state
    rho0 = middle.material.rho0
    if a.kind == FrontKind.SHOCK:
        mismatch = (sl.sigma - sr.sigma) - a.direction * rho0 * abs(a.speed) * (sl.u - sr.u)
        if abs(mismatch) > JUMP_TOLERANCE * res.stress_scale:
            return None
    elif not (_no_wider(sl, sm, sr, 1e-12 * res.stress_scale)
              or res.is_negligible(sl.sigma - sr.sigma, sl.u - sr.u)):
        return None
    share = _energy_share(sl, sm, sr)
    if share is None:
        return None
    x = xa + share * distance
    momentum = abs(rho0 * ((x - xa) * sl.u + (xb - x) * sr.u - distance * sm.u))
    energy = rho0 * ((x - xa) * specific_energy(sl) + (xb - x) * specific_energy(sr)
                     - distance * specific_energy(sm))
    counters = engine.counters
    if not _within(engine.coalesce_budget, counters, momentum, energy) and \
            not _within(budget(engine, t), counters, momentum, energy):
        return None
    counters.coalesced += 1
    counters.coalesced_momentum += momentum
    counters.coalesced_energy += energy
    return _replace(engine, a, b, x, t)


def _within(budget, counters, momentum: float, energy: float) -> bool:
    """Whether one pair that moves ``momentum`` (kg/(m^2 s), absolute) and ``energy``
    (J/m^2, signed: lost is negative) may spend that much of ``budget`` (``None``: not
    known yet): within its open part (``OPEN``), or at most ``SHARE`` of what is left."""
    if budget is None:
        return False
    left = (budget[0] - counters.coalesced_momentum, budget[1] + counters.coalesced_energy)
    if (left[0] - momentum >= (1.0 - OPEN) * budget[0]
            and left[1] + energy >= (1.0 - OPEN) * budget[1]):
        return True
    return momentum <= SHARE * left[0] and -energy <= SHARE * left[1]


def budget(engine, t: float) -> tuple[float, float]:
    """The momentum (kg/(m^2 s)) and energy (J/m^2) all coalescing of a run may move:
    ``BUDGET`` of the balance the accuracy settings promise, times the largest momentum
    content ``sum rho0 |u| dX`` and energy content ``sum rho0 (|e| + u^2/2) dX`` the
    material has held so far (the scales the balance is measured on), measured again
    only when a coalescing would exceed the budget known (it never shrinks)."""
    momentum, energy = balance.live_content(engine, t)
    promise = BUDGET * balance.promised_balance(engine.resolution.report())
    held = engine.coalesce_budget or (0.0, 0.0)
    engine.coalesce_budget = (max(held[0], promise * momentum), max(held[1], promise * energy))
    return engine.coalesce_budget


def _no_wider(left, middle, right, rounding: float) -> bool:
    """Whether the stress and velocity mismatch across one contact from ``left`` to
    ``right`` is no wider than across the wider of the two it replaces (contacts carry
    the mismatch a dropped wave leaves; coalescing must not add to it)."""
    for name, slack in (("sigma", rounding), ("u", 0.0)):
        a, b, c = (getattr(s, name) for s in (left, middle, right))
        if abs(a - c) > max(abs(a - b), abs(b - c)) + slack:
            return False
    return True


def record_tolerance(res) -> float:
    """The stress tolerance (Pa) weak pairs are measured against: the records', at most
    ``DEFAULT_RECORD_FRACTION`` of the stress scale (a scene that asks for no stress
    accuracy at all still keeps its pulses and plateaus)."""
    return min(res.stress_tolerance, DEFAULT_RECORD_FRACTION * res.stress_scale)


def _weaker(a: Front, b: Front, left, middle, right, scale: float) -> float:
    """The strength (Pa) of the weaker of two waves (stress jump) or two contacts (the
    offset of the yield stresses across it, the most it can reflect)."""
    if a.kind == FrontKind.SHOCK:
        return min(abs(a.jump), abs(b.jump))
    material = middle.material
    return min(material.contact_reflection(left.state, middle.state, scale),
               material.contact_reflection(middle.state, right.state, scale))


def specific_energy(state) -> float:
    """Specific total energy ``e + u^2/2`` (J/kg)."""
    return state.e + 0.5 * state.u * state.u


def _energy_share(left, middle, right) -> float | None:
    """The fraction of the strip given to the left state so that the strip keeps its
    energy, clamped to lose energy rather than make it; ``None`` if any share makes it."""
    el, em, er = specific_energy(left), specific_energy(middle), specific_energy(right)
    if em < min(el, er) or not math.isfinite(el + em + er):
        return None
    if el == er:
        return 0.5
    return min(max((em - er) / (el - er), 0.0), 1.0)


def _replace(engine, a: Front, b: Front, x: float, t: float) -> Front:
    """Kill ``a`` and ``b`` at ``t`` and link one front from ``(x, t)`` in their place."""
    before, after = a.prev, b.next
    left, middle, right = before.region_right, a.region_right, b.region_right
    xa, xb = a.position(t), b.position(t)
    for front in (a, b):
        front.alive = False
        front.t1, front.x1 = t, front.position(t)
        front.right_region_id = front.region_right.id
    middle.left_points.append((xa, t))
    middle.right_points.append((xb, t))
    middle.t_end = t
    left.right_points.extend(((xa, t), (x, t)))
    right.left_points.extend(((xb, t), (x, t)))
    if a.kind == FrontKind.SHOCK:
        behind, ahead = (left, right) if a.direction > 0 else (right, left)
        merged = engine.new_front(
            FrontKind.SHOCK, x, t, speed=a.speed, direction=a.direction,
            wave=engine.next_wave_id(), lineage=a.lineage if a.lineage == b.lineage else MIXED,
            jump=behind.state.sigma - ahead.state.sigma)
    else:
        merged = engine.new_front(FrontKind.CONTACT, x, t, bond=a.bond)
    merged.left_region = left.id
    merged.region_right = right
    before.next, merged.prev, merged.next = merged, before, after
    if after is not None:
        after.prev = merged
        right.in_fan = inside_fan(merged, after)
    engine.push_pair(before, merged, t)
    if after is not None:
        engine.push_pair(merged, after, t)
    return merged
