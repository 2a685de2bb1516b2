"""Discretising a centred simple wave into rays.

A centred fan from ``ahead`` to ``behind`` is replaced by ``n`` rays issuing from
its centre.  The states between rays are exact points of the isentrope (so the
Riemann invariant carried across the fan is exact at every ray) and each ray
moves at the mean of the Lagrangian characteristic speeds of its two
neighbouring states, which is second-order accurate in the stress step it
carries.  Fans are split at equal steps of stress; the number of rays is chosen
from the largest stress step a ray may carry.

The characteristic speed of a state is ``material.sound_speed(v, e)`` for a
material whose stress is a function of ``(v, e)``.  A fan whose wave curve has
a method ``characteristic_speed(sigma)`` (a solid whose speed also depends on a
history variable such as the plastic strain, and on the branch of the path)
takes its speeds from the curve instead; see ``discretise_fan``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from materials import Fan, State


@dataclass(frozen=True, slots=True)
class Ray:
    """One characteristic of a discretised fan: ``ahead`` -> ``behind`` at ``speed`` (m/s)."""

    ahead: State
    behind: State
    speed: float
    index: int
    count: int


def ray_count(fan: Fan, max_stress_step: float) -> int:
    """Rays needed so that none carries more than ``max_stress_step`` (Pa); at least one."""
    jump = abs(fan.behind.sigma - fan.ahead.sigma)
    if not max_stress_step > 0.0 or not math.isfinite(max_stress_step):
        return 1
    return max(1, math.ceil(jump / max_stress_step - 1e-9))


def discretise_fan(fan: Fan, material, count: int) -> list[Ray]:
    """The fan as ``count`` rays, leading ray (the head) first.

    A ray is a characteristic ``dX/dt = +-C`` of the path the fan follows, ``C``
    the Lagrangian speed with ``C^2 = -v0^2 dsigma/dv`` along that path; each ray
    moves at the mean of ``C`` at the two states it separates.

    For a fluid-like material ``C`` is a function of the state's ``(v, e)``:
    ``material.sound_speed(v, e)``.  For a solid it also depends on the deviator
    (plastic strain) and on whether the path is elastic or plastic, which
    ``(v, e)`` cannot tell; such a fan's ``curve`` provides
    ``characteristic_speed(sigma)``, the speed magnitude (m/s) of the
    characteristic through the state of stress ``sigma`` on that curve, and it
    is used for the interior states.  The two end states are those of the fan
    itself: ``abs(fan.head_speed)`` and ``abs(fan.tail_speed)``, because an end
    state may be shared by two fans on different branches (the yield point
    between an elastic and a plastic release fan is the tail of one at the
    elastic speed and the head of the other at the plastic speed).
    """
    states = fan.states(count)
    speed_on_curve = getattr(fan.curve, "characteristic_speed", None)
    if callable(speed_on_curve):
        speeds = [abs(fan.head_speed),
                  *(speed_on_curve(s.sigma) for s in states[1:-1]),
                  abs(fan.tail_speed)]
    else:
        speeds = [material.sound_speed(s.v, s.e) for s in states]
    return [
        Ray(ahead=states[k], behind=states[k + 1],
            speed=fan.direction * 0.5 * (speeds[k] + speeds[k + 1]), index=k, count=count)
        for k in range(count)
    ]
