"""The Riemann problem of two states of one elastic–plastic solid that stay elastic.

Two uniform states ``L`` and ``R`` of one small-strain elastic–plastic solid
(``materials.elastic_plastic``) meet.  Both sides have the elastic impedance
``Z0 = rho0 C0``.  If the contact stress of the acoustic problem,

    sigma* = (sigma_L + sigma_R)/2 + Z0 (u_L - u_R)/2,

lies strictly inside the elastic range of both states (between the yield stresses
``ElasticPlastic.yield_stresses`` of each), each side is reached by one elastic shock
at ``C0`` on the straight elastic branch, ``u = u_L - (sigma - sigma_L)/Z0`` on the
left and ``u = u_R + (sigma - sigma_R)/Z0`` on the right, and ``sigma*`` is the exact
root of the impedance match (``materials.riemann``), not an estimate: the waves are
the superposition of the incoming ones, as in a linear-elastic solid.  This is the
outcome of most events in a ringing elastic–plastic plate (waves crossing each other
and plastic-strain contacts, which have one impedance on both sides), found here with
no wave curve, no root search and no range scan.  Anything else (a side that yields,
a tension below the contact's floor, a volume beyond the model's range) returns
``None`` and goes to the general solver, which gives the same answer where both apply.
"""

from __future__ import annotations

from .elastic_plastic import ElasticPlastic, branch_jump
from .state import LEFT, RIGHT, State
from .waves import Shock


def elastic_contact(material: ElasticPlastic, left: State, right: State, floor: float):
    """``(left_waves, right_waves, left_star, right_star, sigma)`` when both sides stay
    elastic, else ``None``.

    ``floor`` (Pa): the lowest contact stress the contact carries (a root below it
    separates; that is left to the general solver).  A side whose stress is already
    ``sigma*`` sends no wave and keeps its state.
    """
    sigma = 0.5 * (left.sigma + right.sigma) + 0.5 * material.impedance * (left.u - right.u)
    if not sigma >= floor:
        return None
    for state in (left, right):  # states the engine's jumps made: consistent with the law
        low, high = material.yield_stresses(state, check=False)
        if not low < sigma < high:
            return None
    v_min, v_max = material.volume_range()
    sides = []
    for state, direction in ((left, LEFT), (right, RIGHT)):
        if sigma == state.sigma:
            sides.append(((), state))
            continue
        star = branch_jump(material, state, sigma, direction, plastic=False)
        if not v_min <= star.v <= v_max:
            return None
        sides.append(((Shock(ahead=state, behind=star, speed=direction * material.C0,
                             direction=direction),), star))
    (left_waves, left_star), (right_waves, right_star) = sides
    return left_waves, right_waves, left_star, right_star, sigma
