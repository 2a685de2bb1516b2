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

with ``L`` the thickness of the layer (a wave leaving it is solved again against the
states it meets) and ``c_s`` the scene's signal speed (``Engine.signal_speed``).  Where
the neglect can make energy (``creates``) a contact is neglected only if its cost is
within ``BUDGET`` of the energy balance the accuracy settings promise
(``balance.promised_balance``) times the energy content of the material
``sum rho0 (|e| + u^2/2) dX``; beyond it the contact is tracked.  Each contact is judged
on its own, never against what earlier ones spent: a symmetric scene solves the mirror
images of an event one after the other, and must treat them alike.  The content is
measured when a cost exceeds the budget known (it never shrinks), at most once per
``REFRESH`` of the run's duration; the costs of the contacts neglected are summed in
``accuracy.neglected_contact_cost``.
"""

from __future__ import annotations

from dataclasses import dataclass

from . import balance

BUDGET = 0.25
"""Fraction of the promised energy balance one neglected entropy contact may cost."""

REFRESH = 0.01
"""The energy content behind the budget is measured again at most once per this
fraction of ``t_end``."""


def creates(left, right, left_continues: bool, right_continues: bool) -> bool:
    """Whether neglecting the contact between star states ``left`` and ``right`` can
    make energy: a side that sends no wave continues through the event with its own
    state, and if that state is the hotter one, the lower-energy state taken for the
    neglected contact cannot replace it; two regions that both continue are merged
    (``Engine._merge``), the mean hotter than one of them."""
    if left_continues and right_continues:
        return True
    return (left_continues and left.e > right.e) or (right_continues and right.e > left.e)


def neglect_cost(engine, material, layer: int, left, right, t: float) -> float:
    """Bound (J/m^2) on the energy that neglecting the contact between star states
    ``left`` and ``right`` at time ``t`` (s) in ``layer`` can make or lose."""
    sweep = min(engine.scene.layers[layer].thickness,
                engine.signal_speed * max(engine.t_end - t, 0.0))
    return material.rho0 * abs(left.e - right.e) * sweep


@dataclass
class NeglectBudget:
    """The energy (J/m^2) one neglected contact may cost (``limit``) and when the
    content behind it may next be measured again (``refresh``, s)."""

    limit: float = 0.0
    refresh: float = 0.0


def affordable(engine, cost: float, t: float) -> bool:
    """Whether a neglect costing ``cost`` (J/m^2) at time ``t`` (s) is within the
    budget; if so it is counted (``Counters.neglect_cost``)."""
    budget = engine.neglect_budget
    if cost > budget.limit and t >= budget.refresh:
        content = balance.live_content(engine, t)[1]
        promise = balance.promised_balance(engine.resolution.report())
        budget.limit = max(budget.limit, BUDGET * promise * content)
        budget.refresh = t + REFRESH * engine.t_end
    if cost > budget.limit:
        return False
    engine.counters.neglect_cost += cost
    return True
