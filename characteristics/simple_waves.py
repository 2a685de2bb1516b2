"""Simple waves as families of characteristics.

A simple wave borders a constant state: across it one Riemann invariant is
constant (``J-`` across a right-going wave, ``J+`` across a left-going one) and the
other varies, so its states lie on one isentrope and each of its characteristics is
a straight line of constant state (Davison ch. 8).  A *centred* wave (fan) issues
from one point; a wave launched by a boundary ramp issues from the boundary over an
interval of time.

The family is represented by ``n + 1`` characteristics carrying the exact states ``s_0
... s_n`` at equal steps of stress (``s_0`` the state ahead, ``s_n`` the state behind),
or of a measure that bounds the velocity steps too where stress alone would not (a gas
expanding towards vacuum). Between characteristics ``k`` and ``k + 1`` the engine keeps
the constant state ``s_{k+1/2}`` (the midpoint): a staggered pair of grids, as in the
method of characteristics, where each ray is a characteristic and each cell carries the
state at its middle. A ray moves at the characteristic speed of its own state (exact for
a centred wave: each ray is one of its characteristics). Moving rays at the speed that
conserves energy between the cells beside them instead was measured and rejected: that
speed is ill-conditioned where ``sigma = Z u`` inside a wave, and in Sod's fan it made
the L1 record error four to ten times larger. Queries read the solution continuously by
interpolating the invariants between characteristics (``characteristics.reconstruct``).

A wave weaker than one step is a single ray from ``s_0`` to ``s_1`` at the speed of
the middle state.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

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
    ``J_{-d}`` of the ahead state is constant.  They lie at equal steps of stress unless
    a step of velocity would then exceed its limit (a gas released towards vacuum, whose
    last steps of stress carry most of its velocity): then at equal steps of the measure
    ``max(|d sigma| / max_step, |d u| / max_velocity_step)`` along the isentrope.  Without
    a table (a solid whose release path is a branch of its yield surface) they come at
    equal steps of stress from ``fan.curve.state_at`` and the speeds from
    ``fan.curve.characteristic_speed`` where the curve has it, else from
    ``material.sound_speed``.
    """
    a, b = fan.ahead, fan.behind
    n = cell_count(b.sigma - a.sigma, max_step)
    if table is not None and not table.resolves(abs(b.u - a.u)):
        table = None  # a wave too weak for the table's rounding: the curve's exact states
    step = (b.sigma - a.sigma) / n
    stresses = [a.sigma + 0.5 * k * step for k in range(1, 2 * n)]  # half steps inside
    if table is not None:
        fixed = table.invariants(a)[0 if fan.direction < 0 else 1]
        inner = [table.state_at_stress(s, fixed, fan.direction) for s in stresses]
        inner_speeds = [table.speed_at_stress(s) for s in stresses]
        on_rays = [a, *inner[1::2], b]
        if max(abs(q.u - p.u) for p, q in zip(on_rays, on_rays[1:], strict=False)) \
                > max_velocity_step:
            n, inner, inner_speeds = _by_measure(fan, table, max_step, max_velocity_step)
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


SPEED_ROUNDING = 1e-12
"""Characteristics of one fan whose speeds differ by less than this fraction move
together (rounding, not crossing)."""


def diverging(characteristics: list[Characteristic]) -> bool:
    """Whether a fan's characteristics (head first) spread apart, as those of a centred
    simple wave must: each no faster than the one ahead of it, ``|c_{k+1}| <= |c_k|``
    (to ``SPEED_ROUNDING``).

    A fan whose interior states come from a table of a neighbouring isentrope (one
    within the table tolerance of ``fan.ahead``'s, ``IsentropeTables``) has its head on
    the true isentrope and its interior on the table's; where the two differ more than
    a step of the fan spans, the head can be slower than the characteristic behind it.
    Such rays cross at the point they leave, and the event there solves the same
    Riemann problem again: the run's clock stops (campaign seeds 749 and 826, gas
    layers in solid stacks, whose table tolerance is a fraction of their pressure).
    """
    speeds = [abs(ch.speed) for ch in characteristics]
    return all(behind <= ahead * (1.0 + SPEED_ROUNDING)
               for ahead, behind in zip(speeds, speeds[1:], strict=False))


MEASURE_SAMPLES = 32
"""Samples of the isentrope per cell when cells are placed at equal steps of the measure
``max(|d sigma| / max_step, |d u| / max_velocity_step)`` (``_by_measure``)."""


def _by_measure(fan: Fan, table: Isentrope, max_step: float, max_velocity_step: float
                ) -> tuple[int, list[State], list[float]]:
    """The cell count ``n``, the ``2 n - 1`` interior half-step states of ``fan`` and their
    Lagrangian sound speeds, at equal steps of the measure ``max(|d sigma| / max_step,
    |d u| / max_velocity_step)`` along the fan's isentrope (each step of the measure is at
    most one cell in stress and in velocity).  Along the fan the invariant ``J_{-d}`` is
    fixed and the stress function ``phi`` varies: ``u = J_{-d} + d phi``."""
    a, b = fan.ahead, fan.behind
    j_plus, j_minus = table.invariants(a)
    phi_a, phi_b = 0.5 * (j_plus - j_minus), table.phi_at_stress(b.sigma)
    rough = cell_count(b.sigma - a.sigma, max_step) + cell_count(b.u - a.u, max_velocity_step)
    phi = np.linspace(phi_a, phi_b, MEASURE_SAMPLES * rough + 1)
    sigma = table.arrays_at_phi(phi)[0]
    measure = np.concatenate(([0.0], np.cumsum(np.maximum(
        np.abs(np.diff(sigma)) / max_step, np.abs(np.diff(phi)) / max_velocity_step))))
    n = max(1, math.ceil(measure[-1] - 1e-9))
    targets = measure[-1] * np.arange(1, 2 * n) / (2 * n)
    states, speeds = [], []
    for value in np.interp(targets, measure, phi):
        # the invariant the fan carries is fixed: J- across a right-going fan, J+ else
        pair = (j_minus + 2.0 * value, j_minus) if fan.direction > 0 else \
            (j_plus, j_plus - 2.0 * value)
        states.append(table.state(*pair))
        speeds.append(table.speed(*pair))
    return n, states, speeds
