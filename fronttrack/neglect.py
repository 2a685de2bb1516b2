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
contact is neglected only if its cost is within ``BUDGET`` of the energy balance the
accuracy settings promise (``balance.promised_balance``) times the energy content of
the material ``sum rho0 (|e| + u^2/2) dX``; beyond it the contact is tracked.  The
bound holds whichever way the energy moves: a hotter region that continues through
the event, or the mean of two merged regions, makes energy; the lower-energy state
taken behind a wave that runs on loses it (campaign seeds 28 and 597 lost 0.40 % and
1.1 % of their energy that way, against a promise of 0.2 %, before losses were
budgeted too).  The costs of many neglects, each within the budget, still add up
(campaign seed 355 lost 0.57 %, seed 89 0.205 %, with every contact within a quarter of
the 0.2 % promise).  The bounds themselves cannot be held to one budget for their sum:
they are ten times what the neglects lose (355: 0.66 % of the content against a loss
of 0.23 %; 89: 1.9 % against 0.20 %), and a sum of bounds, tried, kept so many contacts
that the symmetric Al 2024 impact at 16 rays to 2.25 us took more than 97 s of CPU
instead of 5.5 s.  What a neglect moves is known as it happens: the colder state is
taken behind the innermost wave on the hotter side, which loses energy at the rate
``rho0 |U| |e_L - e_R|`` above for as long as it runs (``follow``; where the hotter
side's family was dropped, the colder side's wave borders the hotter region and makes
energy at that rate).  So a contact is also tracked while what the neglects so far
have moved (``moved_so_far``) and the bound of this one exceed ``TOTAL`` of the
promised balance times the content.  That sum grows continuously in time: the mirror
images of an event, solved one after the other at one time, see the same sum and are
treated alike.  The content is measured when a cost exceeds the budget known (it never
shrinks), at most once per ``REFRESH`` of the run's duration; the bounds of the
contacts neglected are summed in ``accuracy.neglected_contact_cost`` and what they
moved in ``accuracy.neglected_contact_moved``.

A contact whose yield stresses differ by more than the negligible stress though it
reflects less (a plastic-strain contact of a finite-plastic solid reflects a fraction
``(C_e/C_p - 1)/2`` of its offset: ``FinitePlastic.contact_reflection``) is plastic
history the run forgets.  Such contacts are many where release fans overtake shocks
(the random strength stacks), and their costs added up to 0.3 % of the energy against
a promise of 0.2 % when each was judged alone; so they are held to one budget for their
sum (``accuracy.neglected_history_cost``), beyond which they are kept, as every one of
them was before the bound.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from . import balance

BUDGET = 0.25
"""Fraction of the promised energy balance one neglected entropy contact may cost."""

TOTAL = 0.5
"""Fraction of the promised energy balance all neglected entropy contacts together may
have moved so far (``moved_so_far``) with the cost of the next one."""

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
    """The energy (J/m^2) one neglected contact may cost (``limit``) and when the
    content behind it may next be measured again (``refresh``, s); the waves that run
    beside a state their neglected contact changed, each with the rate (W/m^2) at which
    it moves energy (``moving``), and what the ones that ended moved (``moved``, J/m^2)."""

    limit: float = 0.0
    refresh: float = 0.0
    moving: list = field(default_factory=list)
    moved: float = 0.0


def follow(engine, left, right, material, left_fronts, right_fronts) -> None:
    """Follow the wave that runs beside the wrong state after a neglected contact between
    star states ``left`` and ``right`` (``left_fronts``/``right_fronts``: the fronts of
    the families leaving the event, innermost last).  The innermost wave on the hotter
    side runs with a colder state behind it than its jump wants (the star of lower
    specific energy taken for both, ``Engine._neglected_contact_state``, or the colder
    side's own region where that family was dropped, which then borders the wave) and
    loses energy; where the hotter side's family was dropped, the innermost wave on the
    colder side borders the hotter region and makes it.  Either moves ``rho0 |U| |e_L -
    e_R|`` (W/m^2) for as long as it runs."""
    hot, cold = (left_fronts, right_fronts) if left.e > right.e else (right_fronts, left_fronts)
    wave = hot[-1] if hot else cold[-1] if cold else None
    rate = material.rho0 * abs(left.e - right.e) * abs(wave.speed) if wave is not None else 0.0
    if rate > 0.0:
        engine.neglect_budget.moving.append((wave, rate))


def moved_so_far(budget: NeglectBudget, t: float) -> float:
    """The energy (J/m^2) the waves followed (``follow``) have moved by time ``t`` (s):
    each its rate over its life until ``t`` or its end.  Continuous in ``t``: a symmetric
    scene's mirror-image events, solved one after the other at one time, see one sum."""
    live, running = [], 0.0
    for wave, rate in budget.moving:
        if wave.alive:
            live.append((wave, rate))
            running += rate * max(t - wave.t0, 0.0)
        else:
            budget.moved += rate * max(wave.t1 - wave.t0, 0.0)
    budget.moving = live
    return budget.moved + running


def affordable(engine, cost: float, t: float, history: bool = False) -> bool:
    """Whether a neglect costing ``cost`` (J/m^2) at time ``t`` (s) is within the
    budget, and with what the neglects so far have moved (``moved_so_far``, J/m^2) within
    ``TOTAL / BUDGET`` of it; if so it is counted (``Counters.neglect_cost``).  A
    contact that carries plastic ``history`` (its yield offset above the negligible
    stress, though what it reflects is below it: ``Material.contact_reflection``) is
    also held, with all such contacts neglected before it, to one budget for their sum
    (``Counters.history_cost``)."""
    counters = engine.counters
    spent = cost + (counters.history_cost if history else 0.0)
    budget = engine.neglect_budget
    total = moved_so_far(budget, t) + cost
    if _beyond(budget, spent, total) and t >= budget.refresh:
        content = balance.live_content(engine, t)[1]
        promise = balance.promised_balance(engine.resolution.report())
        budget.limit = max(budget.limit, BUDGET * promise * content)
        budget.refresh = t + REFRESH * engine.t_end
    if _beyond(budget, spent, total):
        return False
    counters.neglect_cost += cost
    if history:
        counters.history_cost += cost
    return True


def _beyond(budget: NeglectBudget, spent: float, total: float) -> bool:
    """Whether a neglect's cost ``spent`` (J/m^2) exceeds the budget's ``limit`` or the
    neglects' ``total`` (what they moved, with it) exceeds ``TOTAL / BUDGET`` of it."""
    return spent > budget.limit or BUDGET * total > TOTAL * budget.limit
