"""Simple waves as families of characteristics.

A simple wave borders a constant state: across it one Riemann invariant is
constant (``J-`` across a right-going wave, ``J+`` across a left-going one) and the
other varies, so its states lie on one isentrope and each of its characteristics is
a straight line of constant state (Davison ch. 8).  A *centred* wave (fan) issues
from one point; a wave launched by a boundary ramp issues from the boundary over an
interval of time.

The family is represented by ``n + 1`` characteristics carrying the exact states
``s_0 ... s_n`` at equal steps of stress (``s_0`` the state ahead, ``s_n`` the state
behind), or of velocity where that takes more steps (a gas expanding towards
vacuum).  Between characteristics ``k`` and ``k + 1`` the engine keeps the constant
state ``s_{k+1/2}`` (the midpoint in stress): a staggered pair of grids, as in the
method of characteristics, where each ray is a characteristic and each cell carries
the state at its middle.  A ray moves at the characteristic speed of its own state
(exact for a centred wave: each ray is one of its characteristics).  Moving rays at
the speed that conserves energy between the cells beside them instead was measured
and rejected: that speed is ill-conditioned where ``sigma = Z u`` inside a wave, and
in Sod's fan it made the L1 record error four to ten times larger.  Queries read the solution
continuously by interpolating the invariants between characteristics
(``characteristics.reconstruct``).

A wave weaker than one step is a single ray from ``s_0`` to ``s_1`` at the speed of
the middle state.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from materials import Fan, State

from .isentrope import Isentrope


@dataclass(frozen=True, slots=True)
class Characteristic:
    """One characteristic of a discretised simple wave.

    ``state``: the state it carries (exact on the wave's isentrope); ``speed``: its signed
    Lagrangian speed (m/s); ``ahead`` and ``behind``: the cell states on the side it runs
    into and on the side it leaves; ``index`` counts from the head (0) to the tail.
    """

    state: State
    speed: float
    ahead: State
    behind: State
    index: int
    count: int


def cell_count(jump: float, max_step: float) -> int:
    """Cells (stress steps) needed so that none exceeds ``max_step`` (Pa); at least one."""
    if not max_step > 0.0 or not math.isfinite(max_step):
        return 1
    return max(1, math.ceil(abs(jump) / max_step - 1e-9))


def discretise_fan(fan: Fan, material, max_step: float,
                   table: Isentrope | None = None,
                   max_velocity_step: float = math.inf) -> list[Characteristic]:
    """The fan as characteristics, head first (see the module docstring).

    No cell spans more than ``max_step`` (Pa) of stress nor ``max_velocity_step`` (m/s)
    of particle velocity.  With ``table`` (the isentrope of ``fan.ahead``) the interior
    states come from the invariants: across a fan of direction ``d`` the invariant
    ``J_{-d}`` of the ahead state is constant.  They are equal steps of stress, or of
    the stress function ``phi`` (equal steps of velocity, ``u = J_{-d} + d phi``) where
    the velocity needs more cells than the stress: a gas released towards vacuum, whose
    last steps of stress carry most of its velocity.  Without a table (a solid whose
    release path is a branch of its yield surface) they come at equal steps of stress
    from ``fan.curve.state_at`` and the speeds from ``fan.curve.characteristic_speed``
    where the curve has it, else from ``material.sound_speed``.
    """
    a, b = fan.ahead, fan.behind
    by_stress = cell_count(b.sigma - a.sigma, max_step)
    n = max(by_stress, cell_count(b.u - a.u, max_velocity_step))
    if table is not None and not table.resolves(abs(b.u - a.u)):
        table = None  # a wave too weak for the table's rounding: the curve's exact states
    step = (b.sigma - a.sigma) / n
    stresses = [a.sigma + 0.5 * k * step for k in range(1, 2 * n)]  # half steps inside
    if table is not None and n > by_stress:
        inner, inner_speeds = _by_velocity(fan, table, n)
    elif table is not None:
        fixed = table.invariants(a)[0 if fan.direction < 0 else 1]
        inner = [table.state_at_stress(s, fixed, fan.direction) for s in stresses]
        inner_speeds = [table.speed_at_stress(s) for s in stresses]
    else:
        inner = [fan.curve.state_at(s) for s in stresses]
        speed_on_curve = getattr(fan.curve, "characteristic_speed", None)
        inner_speeds = ([speed_on_curve(s) for s in stresses] if callable(speed_on_curve)
                        else [material.sound_speed(s.v, s.e) for s in inner])
    d = fan.direction
    head, tail = fan.head_speed, fan.tail_speed
    if n == 1:
        # one ray: the whole jump at the speed of the middle state
        return [Characteristic(state=inner[0], speed=d * abs(inner_speeds[0]),
                               ahead=a, behind=b, index=0, count=1)]
    # states[j] and speeds[j] at half step j (j = 0 ... 2n): even j on characteristics,
    # odd j in cells
    states = [a, *inner, b]
    speeds = [abs(head), *(abs(c) for c in inner_speeds), abs(tail)]
    rays = []
    for k in range(n + 1):
        i_ahead, i_behind = max(2 * k - 1, 0), min(2 * k + 1, 2 * n)
        ahead, behind = states[i_ahead], states[i_behind]
        rays.append(Characteristic(state=states[2 * k], speed=d * speeds[2 * k], ahead=ahead,
                                   behind=behind, index=k, count=n + 1))
    return rays


def _by_velocity(fan: Fan, table: Isentrope, n: int) -> tuple[list[State], list[float]]:
    """The ``2 n - 1`` interior half-step states of ``fan`` and their Lagrangian sound
    speeds at equal steps of the stress function ``phi`` (of velocity), from ``table``."""
    a, b = fan.ahead, fan.behind
    j_plus, j_minus = table.invariants(a)
    phi_a = 0.5 * (j_plus - j_minus)
    phi_b = table.phi_at_stress(b.sigma)
    states, speeds = [], []
    for k in range(1, 2 * n):
        phi = phi_a + 0.5 * k * (phi_b - phi_a) / n
        # the invariant the fan carries is fixed: J- across a right-going fan, J+ else
        pair = (j_minus + 2.0 * phi, j_minus) if fan.direction > 0 else \
            (j_plus, j_plus - 2.0 * phi)
        states.append(table.state(*pair))
        speeds.append(table.speed(*pair))
    return states, speeds
