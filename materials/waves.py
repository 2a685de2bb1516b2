"""Elementary waves: what a wave curve hands to the engine.

A wave carries the material from the state *ahead* of it (the state it runs
into) to the state *behind* it.  ``direction`` is ``+1`` for a right-going wave
(Lagrangian speed ``U > 0``) and ``-1`` for a left-going one.

- ``Shock``: a discontinuity satisfying the jump conditions
  ``rho0 U (u_b - u_a) = sigma_b - sigma_a``,
  ``U (v_b - v_a) / v0 = -(u_b - u_a)``,
  ``e_b - e_a = 1/2 (sigma_a + sigma_b)(v_a - v_b)``.
  A *rarefaction shock* (``sigma_b < sigma_a``) appears when release is modelled
  along the Hugoniot, and in linear elastic solids, where it is exact.
- ``Fan``: a centred simple wave along the isentrope through ``ahead``; its
  characteristics run at ``direction * C_L`` from the head (ahead state) to the
  tail (behind state).  ``curve`` is the wave curve it lies on, which gives
  exact intermediate states.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from .frozen import slot_init
from .state import State


@slot_init
@dataclass(frozen=True, slots=True)
class Shock:
    """A discontinuity: ``ahead`` -> ``behind`` at Lagrangian speed ``speed`` (m/s, signed)."""

    ahead: State
    behind: State
    speed: float
    direction: int

    @property
    def is_compressive(self) -> bool:
        return self.behind.sigma > self.ahead.sigma


@dataclass(frozen=True, slots=True)
class Fan:
    """A centred simple (isentropic) wave from ``ahead`` to ``behind``.

    ``head_speed`` and ``tail_speed`` are the signed Lagrangian speeds of its
    first and last characteristics (m/s).  ``curve`` (a wave curve centred on
    ``ahead``) returns exact intermediate states via ``curve.state_at(sigma)``.
    """

    ahead: State
    behind: State
    head_speed: float
    tail_speed: float
    direction: int
    curve: Any

    def states(self, count: int) -> list[State]:
        """``count + 1`` states from ``ahead`` to ``behind`` at equal steps of stress."""
        step = (self.behind.sigma - self.ahead.sigma) / count
        inner = [self.curve.state_at(self.ahead.sigma + k * step) for k in range(1, count)]
        return [self.ahead, *inner, self.behind]
