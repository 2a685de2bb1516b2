"""What dropping a weak wave may create, and when the wave must be kept instead.

A family of waves weaker than the negligible stress and velocity is dropped
(``fronttrack.outgoing``).  The region on its side then keeps the state ``O`` it had
before the event, where the Riemann problem put the star state ``S``: the front that
now borders that region (the site of the event, or the trailing wave of the other
family) separates states that do not satisfy its jump conditions.  Moving at
Lagrangian speed ``U`` (zero for a site) it changes the total energy, per unit area, at

    dE/dt = rho0 U (E_l - E_r) - (sigma_l u_l - sigma_r u_r)      (W/m^2)

with ``E = e + u^2/2`` and ``l``, ``r`` its left and right states; only the part the
dropped jump ``O - S`` makes is new (the rest is the front's own jump, exact).  That
rate is first order in the dropped jump and grows with the particle velocity: a
0.17 GPa echo dropped where a 158 GPa shock crossed it at 1.5 km/s (campaign seed 380)
made the shock create 0.28 % of the scene's energy in 0.27 us, while its momentum
residual, the dropped stress itself, stayed within the budget of ``fronttrack.mismatch``.
A wave of a few kPa in a gas carries metres per second (seed 592): dropped at an
entropy contact or at the gas's interface, it leaves the faces there moving apart
under the gas pressure, and a thin layer ringing beside the gas drops such a wave
every few nanoseconds.

So the mismatches that *create* energy share one budget, ``BUDGET`` of the energy
balance the accuracy settings promise (``balance.promised_balance``) times the energy
content ``sum rho0 (|e| + u^2/2) dX`` (measured as ``fronttrack.neglect`` does).  A
drop is allowed only if what all of them can make stays within it:

- a mismatch carried by a wave lasts until the wave's next event solves it again from
  the states it meets, at most until ``t_end`` or until the wave has crossed its layer:
  its bound, ``dE/dt * min(t_end - t, L / |U|)``, is held until that event, and then
  settled at the energy it made (a wave ringing in a spalled fragment of the symmetric
  Al 2024 impact meets its next event within a ring period, 87 ns, against 0.75 us to
  cross its 4 mm layer: charged their bounds, the drops spent the budget by 5 us and
  every later weak reflection was kept, 26 929 events to 9 us; settled, they made
  19 J/m^2 of the 348 by then, and 8 721 events);
- a mismatch at a site lasts until the next event there solves the site again (a wave
  need never come): it is pending, bounded by ``dE/dt * (t_end - t)``, and settled at
  the energy it made when the site's next event comes.

A family whose drop would take the total beyond the budget is kept.  A mismatch that
loses energy costs accuracy, not conservation, and is dropped as before; at a site, the
energy it lost by the time the site is solved again is credited to the budget (so the
budget bounds the net energy created, not the sum of both signs).  The energy
the allowed drops made or may still make is reported in ``accuracy.dropped_wave_cost``
(J/m^2, net: site mismatches that lost energy are credited for what they lost, so it
may be negative).

Measured: seed 380 +0.25 % -> -0.05 % of the energy (68 -> 79 events); seed 592
+0.52 % -> +0.05 % (2 499 -> 2 930 events: the gas's weak waves are followed once the
budget is spent); Davison's steel to 6 us 4 010 -> 4 158 events; the demo unchanged
(522 -> 523 events, 12 spall planes); the Gurney sandwich of ``tests/test_gurney.py``
10 072 -> 12 432 events (its products drop many waves; the budget runs out at 2.3 us).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from characteristics.ray_energy import energy_residual
from materials import Fan

from . import balance
from .outgoing import negligible

BUDGET = 0.25
"""Fraction of the promised energy balance that the mismatches of dropped waves may
create in all."""

INSTANT = 1e-12
"""Events less than this fraction of ``t_end`` apart are one instant for the budget
(the mirror images of a symmetric scene's events differ in time by rounding)."""

REFRESH = 0.01
"""The energy content behind the budget is measured again at most once per this
fraction of ``t_end``."""


@dataclass
class Ledger:
    """The energy (J/m^2) dropped waves made (``made``), the pending mismatches at sites
    by site id as ``(rate W/m^2, since s)`` and the most they may make by ``t_end``
    (``pending_bound``, J/m^2, kept as a running sum), the budget (J/m^2; measured when needed,
    never shrinking) and the time (s) it may next be measured again; ``before``: what
    was committed before the events of time ``instant`` (s), which those events are
    judged against (the mirror images of a symmetric scene's events come one after the
    other at one time, and must be treated alike)."""

    made: float = 0.0
    pending: dict = field(default_factory=dict)
    fresh: list = field(default_factory=list)
    pending_bound: float = 0.0
    budget: float = 0.0
    refresh: float = 0.0
    instant: float = -math.inf
    before: float = 0.0


def drops(engine, sol, direction: int, region_left, region_right, site, t: float) -> bool:
    """Whether the family of ``sol`` leaving the event at time ``t`` (s) in ``direction``
    (-1 left, +1 right) is dropped: it is weaker than the negligible stress and velocity
    (``outgoing.negligible``), weak waves are not being kept, and what its mismatch may
    create fits the budget (module docstring).  ``site``: the event's site or ``None``.
    The event settles its site's pending mismatch first."""
    ledger = engine.drop_ledger
    if site is not None:
        _settle(ledger, site, t)
    waves, other = ((sol.left_waves, sol.right_waves) if direction < 0
                    else (sol.right_waves, sol.left_waves))
    if engine.keep_weak_waves or not waves or not negligible(engine, waves):
        return False
    region = region_left if direction < 0 else region_right
    return region is None or not _must_keep(engine, ledger, sol, direction, region, other,
                                            site, t)


def _must_keep(engine, ledger: Ledger, sol, direction: int, region, other, site,
               t: float) -> bool:
    """Whether a negligible family must be kept: dropping it would create more energy
    than the budget allows."""
    old, star = region.state, (sol.left_star if direction < 0 else sol.right_star)
    if not all(math.isfinite(q) for q in (old.sigma, old.u, old.e, star.sigma, star.u,
                                          star.e)):
        return False
    if site is not None:
        speed = 0.0
    elif other and not negligible(engine, other):
        trailing = other[-1]
        speed = trailing.tail_speed if isinstance(trailing, Fan) else trailing.speed
    else:
        return False  # both families dropped: the two regions are merged
    rate = creation_rate(region.material.rho0, speed, old, star, direction)
    if site is not None:  # pending, a loss too: it is credited for what it lost
        if rate > 0.0 and rate * (engine.t_end - t) > _available(engine, ledger, t):
            return True
        _add_pending(engine, ledger, site.id, rate, t)  # the other side's, this event
        return False
    until = _carried_until(engine, speed, region, t)
    if rate > 0.0 and rate * (until - t) > _available(engine, ledger, t):
        return True
    _hold(ledger, direction, rate, t, until)
    return False


def merge_allowed(engine, before, after, region_left, region_right, merged,
                  t: float) -> bool:
    """Whether both families of an event inside a material may be dropped.

    No front then leaves the event and the regions beside it, ``region_left`` and
    ``region_right``, become one in the state ``merged`` (mass-weighted: the totals are
    kept at that instant).  The fronts bordering them, ``before`` and ``after``, keep
    ``merged`` where their jump conditions want the old states, and each makes energy
    at its ``creation_rate``.  A wave's next event solves it again from the states it
    meets, within a crossing of the layer (free, as before: a layer ringing with weak
    waves merges at most crossings); a site's may never come, so a site's rate is
    pending, as its own mismatch, until its next event.  Campaign seed 308: a
    9.2 MPa echo ringing beside a gap face and its reflection were both dropped where
    they crossed 0.4 um from the face; merged with the thicker compressed region, the
    free face carried 9.1 MPa at 100 m/s for the last 0.9 us (+0.43 % of the energy, the
    momentum 0.2 % off) and no wave came to solve it.  Allowed, and its cost committed,
    if what the sites may create fits the budget."""
    ledger = engine.drop_ledger
    sites = [(front, creation_rate(region.material.rho0, 0.0, merged, region.state, side))
             for front, region, side in ((before, region_left, +1), (after, region_right, -1))
             if front is not None and front.is_site]
    bound = sum(max(rate, 0.0) for _, rate in sites) * (engine.t_end - t)
    if bound > 0.0 and bound > _available(engine, ledger, t):
        return False
    for site, rate in sites:
        _add_pending(engine, ledger, site.id, rate, t)
    return True


def _carried_until(engine, speed: float, region, t: float) -> float:
    """When (s) a wave at Lagrangian ``speed`` (m/s) bordering ``region``, leaving an event
    at ``t`` (s), has crossed the region's layer, or ``t_end`` if that is sooner: the
    latest its carried mismatch may last."""
    # a wave at rest (zero sound speed: a gas at zero pressure) carries it to t_end
    crossing = (engine.scene.layers[region.layer].thickness / abs(speed) if speed
                else math.inf)
    return t + min(max(engine.t_end - t, 0.0), crossing)


def _hold(ledger: Ledger, direction: int, rate: float, t: float, until: float) -> None:
    """Hold a mismatch carried by a wave of the event at ``t`` (s) that makes ``rate``
    (W/m^2) until ``until`` (s) at most: its bound is committed now, and it waits in
    ``ledger.fresh`` for the front that carries it (``attach``).  A loss is not held: it
    costs accuracy, not conservation."""
    if rate > 0.0:
        ledger.fresh.append((direction, rate, t, until))
        ledger.pending_bound += _bound(rate, t, until)


def attach(engine, carriers: dict) -> None:
    """Give the mismatches held at this event to the waves that carry them:
    ``carriers[direction]`` is the front bordering the region that kept its old state
    on the ``direction`` side (-1 left, +1 right), or ``None`` where none does (an
    entropy contact borders it): the bound is then spent at once.  A carried mismatch
    is settled at its front's next event (``settle``)."""
    ledger = engine.drop_ledger
    for direction, rate, since, until in ledger.fresh:
        bound = _bound(rate, since, until)
        ledger.pending_bound -= bound
        carrier = carriers.get(direction)
        if carrier is None:
            ledger.made += bound
        else:
            _set_pending(ledger, carrier.id, rate, since, until)
    ledger.fresh.clear()


def settle(engine, front, t: float) -> None:
    """``front`` (a wave or a site) is solved again at an event at ``t`` (s) from the
    states it meets: the mismatch it carried or held ends, and the energy it made until
    then is counted as made."""
    _settle(engine.drop_ledger, front, t)


def creation_rate(rho0: float, speed: float, old, star, direction: int) -> float:
    """Energy (W/m^2, positive: created) made by a front at Lagrangian ``speed`` (m/s)
    whose side ``direction`` keeps the state ``old`` where its jump conditions want
    ``star``: the flux residual ``rho0 U (E_l - E_r) - (sigma_l u_l - sigma_r u_r)`` of
    the jump from ``old`` to ``star`` (``rho0`` in kg/m^3)."""
    left, right = (old, star) if direction < 0 else (star, old)
    return energy_residual(rho0, speed, (left.sigma, left.u, left.e),
                           (right.sigma, right.u, right.e))


def cost(engine) -> float:
    """The energy (J/m^2) the dropped waves' mismatches made, and may still make (the
    pending ones until ``t_end``)."""
    ledger = engine.drop_ledger
    return ledger.made + ledger.pending_bound


def _bound(rate: float, since: float, until: float) -> float:
    """The most (J/m^2) a pending mismatch of ``rate`` (W/m^2) from ``since`` to
    ``until`` (s) may create."""
    return max(rate, 0.0) * (until - since)


def _set_pending(ledger: Ledger, front_id: int, rate: float, since: float,
                 until: float) -> None:
    old = ledger.pending.get(front_id)
    if old is not None:
        ledger.pending_bound -= _bound(*old)
    ledger.pending[front_id] = (rate, since, until)
    ledger.pending_bound += _bound(rate, since, until)


def _add_pending(engine, ledger: Ledger, site_id: int, rate: float, t: float) -> None:
    """Add ``rate`` (W/m^2) from ``t`` (s) to a site's pending mismatch: what the one it
    has made until ``t`` is counted as made, and it goes on at the sum."""
    previous, since, _ = ledger.pending.get(site_id, (0.0, t, engine.t_end))
    ledger.made += previous * (t - since)
    _set_pending(ledger, site_id, previous + rate, t, engine.t_end)


def _settle(ledger: Ledger, front, t: float) -> None:
    entry = ledger.pending.get(front.id)
    if entry is not None and entry[1] < t:  # made by an earlier event: solved again now
        rate, since, until = entry
        del ledger.pending[front.id]
        ledger.pending_bound = (0.0 if not ledger.pending else
                                ledger.pending_bound - _bound(*entry))
        ledger.made += rate * (min(t, until) - since)


def _available(engine, ledger: Ledger, t: float) -> float:
    """The energy (J/m^2) dropped waves may still create at time ``t`` (s): the budget
    less what they made and what the pending mismatches may make until ``t_end``, as
    committed before this instant (the budget is measured again when this runs short:
    it never shrinks)."""
    if abs(t - ledger.instant) > INSTANT * engine.t_end:
        ledger.instant, ledger.before = t, cost(engine)
    committed = ledger.before
    if ledger.budget - committed <= 0.0 and t >= ledger.refresh:
        promise = balance.promised_balance(engine.resolution.report())
        ledger.budget = max(ledger.budget, BUDGET * promise
                            * balance.live_content(engine, t)[1])
        ledger.refresh = t + REFRESH * engine.t_end
    return ledger.budget - committed
