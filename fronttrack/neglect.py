"""What neglecting an entropy contact may cost, and a budget for it.

An interaction inside a material (a ray overtaking a shock, two waves colliding) leaves
an entropy contact between its two star states.  ``Engine._entropy_contact`` does not
track one that reflects less than the negligible stress and whose energy jump
``rho0 |e_L - e_R|`` is below it too; the two states are then replaced by the one of
lower specific energy (``Engine._neglected_contact_state``).  That is cheap, but the
two thresholds compare the jump with a *stress*: the energy the neglect moves is not
bounded by them.  The waves that run on beside the replaced state meet material on the
other side of the contact that they take for the state they were solved against; a
wave at Lagrangian speed ``U`` then makes or loses energy at

    dE/dt = rho0 |U| (e_L - e_R)        (J/m^2/s, per unit area)

for as long as it runs in that material: a release ray overtaking a shock left a fan
cell 220 J/kg hotter than the weakened shock's Hugoniot state, a jump well below the
negligible stress, and the shock made 0.94 % of the scene's energy running on from it
(random stack seed 1); a lower-energy state taken behind a release running back
through the whole plate lost 10 % the same way.

So the neglect gets a budget.  Its worst cost is bounded by

    cost = rho0 |e_L - e_R| * min(L, c_s (t_end - t))      (J/m^2)

with ``L`` the distance from the event to the farther of the nearest sites (interface,
contact, gap or boundary) on either side (a wave cannot pass a site without an event,
where it is solved again against the states it meets) and ``c_s`` the scene's signal
speed (``Engine.signal_speed``).  A
contact is neglected only if its cost is within ``ALONE`` of the energy balance the
accuracy settings promise (``balance.promised_balance``) times the energy content of
the material ``sum rho0 (|e| + u^2/2) dX``; beyond it the contact is tracked.  The
bound holds whichever way the energy moves: a hotter region that continues through
the event, or the mean of two merged regions, makes energy; the lower-energy state
taken behind a wave that runs on loses it (campaign seeds 28 and 597 lost 0.40 % and
1.1 % of their energy that way, against a promise of 0.2 %, before losses were
budgeted too).  Each contact is judged on its own, never against what earlier ones
spent: a symmetric scene solves the mirror images of an event one after the other,
and must treat them alike.  So the costs of many neglects may add up past the budget
(campaign seed 355 loses 0.50 % with each of its contacts within a quarter of the 0.2 %
promise); a budget for their sum, tried, brought it to 0.28 % but kept so many contacts
that the symmetric Al 2024 impact at 16 rays to 2.25 us took more than 97 s of CPU
instead of 5.5 s.  The content is measured when a cost exceeds the budget
known (it never shrinks), at most once per ``REFRESH`` of the run's duration; the
costs of the contacts neglected are summed in ``accuracy.neglected_contact_cost``.

Why a tenth (``ALONE``), not a quarter: what the neglects of a run lose grows with its
length, and most of them lose a small part of their bound.  The symmetric Al 2024
impact at 16 rays to 18 us neglects 3 989 contacts (bounds 70 708 J/m^2 in all, 51
times the promise); they lose 1 494 J/m^2 (2.1 % of their bounds, 2.1e-3 of the
content against a promise of 2e-3), about 0.10e-3 of the content per us from 2 us on,
four fifths of it in the spalled fragment, where a ray overtakes the ringing shock at
the same place each ring period (bounds 34-58 J/m^2, the fragment's width; each loses
about 0.4 J/m^2 before its carrier meets a ray).  The largest loss is one contact's:
born at 1.42 us at 2.05 mm, its carrier runs across the impactor and loses 171 J/m^2 of
its bound of 187 (the limit at a quarter: 348 J/m^2).  A contact whose bound is beyond
a tenth of the promise (139 J/m^2) is now kept: that run takes 8 606 events instead of
8 499 and ends at -1.75e-3 instead of -2.09e-3 (within its promise), and to 2.25 us at
-2.6e-5 instead of -3.7e-4.  A budget for the sum of the contacts' realised costs
growing linearly in time to half the promise by ``t_end`` (tried, not kept) keeps the
fragment's contacts once the sum catches up: 22 099 events to 9.01 us instead of 4 486,
and the default-accuracy run reached the event limit at 14.7 us.

A contact whose yield stresses differ by more than the negligible stress though it
reflects less (a plastic-strain contact of a finite-plastic solid reflects a fraction
``(C_e/C_p - 1)/2`` of its offset: ``FinitePlastic.contact_reflection``) is plastic
history the run forgets.  Such contacts are many where release fans overtake shocks
(the random strength stacks), and their costs added up to 0.3 % of the energy against
a promise of 0.2 % when each was judged alone; so they are held to one budget for their
sum (``accuracy.neglected_history_cost``), beyond which they are kept, as every one of
them was before the bound.

So is a contact whose energy jump ``rho0 |e_L - e_R|`` is above the negligible stress
though it reflects less (thermal history; every such contact was kept before).  Its
cost is known better than its bound: the colder state taken for both sides loses
energy only where the wave on the hotter side sweeps it, at ``rho0 |U| |e_L - e_R|``,
until that wave's next event solves it again from the states it meets.  Its bound is
held in the sum until then (``hold``) and then settled at what it lost (``settle``),
as ``fronttrack.dropped`` settles a carried mismatch.  The symmetric Al 2024 impact at
16 rays per fan makes one such contact (264 kPa against a negligible stress of 246
kPa) once a ring period (87 ns) in its spalled fragment from 4.5 us on, each bounded
by 58 J/m^2 (the fragment's width) against a sum budget of 348 J/m^2; the shock that
carries it meets a ray within nanoseconds.  Kept, its reflections (0.25-0.3 MPa, weaker
than an isentrope table resolves, so shocks) filled the fragment and the run to 18 us
stopped at the event limit at 17.38 us; charged their bounds, five were neglected and
the sixth spent the sum.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from . import balance

BUDGET = 0.25
"""Fraction of the promised energy balance that the contacts carrying history may cost
together (``affordable``)."""

ALONE = 0.1
"""Fraction of the promised energy balance one neglected entropy contact may cost."""

REFRESH = 0.01
"""The energy content behind the budget is measured again at most once per this
fraction of ``t_end``."""


def neglect_cost(engine, material, group, x: float, left, right, t: float) -> float:
    """Bound (J/m^2) on the energy that neglecting the contact between star states
    ``left`` and ``right``, left by the fronts ``group`` meeting at ``(x, t)`` (m, s), can
    make or lose: ``rho0 |e_L - e_R|`` times the farthest a wave leaving the event or
    entering the continuing region can sweep before its next event."""
    limit = engine.signal_speed * max(engine.t_end - t, 0.0)
    sweep = max(_to_site(group[0].prev, "prev", x, t, limit),
                _to_site(group[-1].next, "next", x, t, limit))
    return material.rho0 * abs(left.e - right.e) * sweep


def _to_site(front, step: str, x: float, t: float, limit: float) -> float:
    """The distance (m) from ``x`` to the first site from ``front`` on in direction
    ``step`` (a wave cannot pass a site without an event), at most ``limit``."""
    while front is not None and not front.is_site:
        if abs(front.position(t) - x) >= limit:
            return limit
        front = getattr(front, step)
    return limit if front is None else min(abs(front.position(t) - x), limit)


@dataclass
class NeglectBudget:
    """The energy (J/m^2) the contacts carrying history may cost together (``limit``;
    one contact alone may cost ``ALONE / BUDGET`` of it) and when the
    content behind it may next be measured again (``refresh``, s); ``held``: the
    thermal contacts' costs awaiting their carriers' next events, by carrier front id,
    as ``(rate W/m^2, since s, bound J/m^2)``."""

    limit: float = 0.0
    refresh: float = 0.0
    held: dict = field(default_factory=dict)


def affordable(engine, cost: float, t: float, history: bool = False) -> bool:
    """Whether a neglect costing ``cost`` (J/m^2) at time ``t`` (s) is within the
    budget, ``ALONE`` of the promise; if so it is counted (``Counters.neglect_cost``).
    A contact that carries
    ``history`` (its yield offset or its energy jump above the negligible stress, though
    what it reflects is below it: ``Material.contact_reflection``) is also held, with
    all such contacts neglected before it, to one budget for their sum
    (``Counters.history_cost``; a thermal one's cost is settled later: ``hold``)."""
    counters = engine.counters
    spent = max(cost * BUDGET / ALONE, cost + (counters.history_cost if history else 0.0))
    if not within_budget(engine, spent, t):
        return False
    counters.neglect_cost += cost
    if history:
        counters.history_cost += cost
    return True


def within_budget(engine, cost: float, t: float) -> bool:
    """Whether ``cost`` (J/m^2) at time ``t`` (s) is within the neglect budget,
    ``BUDGET`` of the promised balance times the energy content (measured again, at most
    once per ``REFRESH`` of the run, when the cost exceeds the limit known); nothing is
    counted."""
    budget = engine.neglect_budget
    if cost > budget.limit and t >= budget.refresh:
        content = balance.live_content(engine, t)[1]
        promise = balance.promised_balance(engine.resolution.report())
        budget.limit = max(budget.limit, BUDGET * promise * content)
        budget.refresh = t + REFRESH * engine.t_end
    return cost <= budget.limit


def hold(engine, carrier, heat: float, t: float, cost: float) -> None:
    """A thermal contact neglected at ``t`` (s), its energy jump ``heat`` = ``rho0 |e_L -
    e_R|`` (J/m^3) and its bound ``cost`` (J/m^2) counted in the sum: ``carrier``, the
    wave on its hotter side, loses ``heat |U|`` (W/m^2) sweeping the colder state until
    its next event (``settle``).  Without a carrier (the hotter family dropped or
    empty), or for an earlier contact the same carrier still holds, the bound stays
    spent (the sum is charged more, never less, than was lost)."""
    if carrier is not None:
        engine.neglect_budget.held[carrier.id] = (heat * abs(carrier.speed), t, cost)


def settle(engine, front, t: float) -> None:
    """``front`` is solved again at an event at ``t`` (s): a thermal neglect it carried
    costs what it lost until then (at most its bound), not its bound."""
    entry = engine.neglect_budget.held.pop(front.id, None)
    if entry is not None:
        rate, since, cost = entry
        engine.counters.history_cost -= cost - min(rate * (t - since), cost)
