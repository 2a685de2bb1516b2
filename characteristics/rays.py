"""Discretising a centred simple wave into rays.

A centred fan from ``ahead`` to ``behind`` is replaced by ``n`` rays issuing from
its centre.  The states between rays are exact points of the isentrope (so the
Riemann invariant carried across the fan is exact at every ray) and each ray
moves at the mean of the Lagrangian sound speeds of its two neighbouring
states, which is second-order accurate in the stress step it carries.  Fans
are split at equal steps of stress; the number of rays is chosen from the
largest stress step a ray may carry.
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
    """The fan as ``count`` rays, leading ray (the head) first."""
    states = fan.states(count)
    speeds = [material.sound_speed(s.v, s.e) for s in states]
    return [
        Ray(ahead=states[k], behind=states[k + 1],
            speed=fan.direction * 0.5 * (speeds[k] + speeds[k + 1]), index=k, count=count)
        for k in range(count)
    ]
