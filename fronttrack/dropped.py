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
rate is first order in the dropped jump but scales with the particle velocity: a
0.17 GPa echo dropped where a 158 GPa shock crossed it at 1.5 km/s (campaign seed 380)
made the shock create 0.28 % of the scene's energy in 0.27 us, while its momentum
residual, the dropped stress itself, stayed within the budget of
``fronttrack.mismatch``.  A wave of a few kPa in a gas moving at 120 m/s carries
metres per second (seed 592): dropped at an entropy contact, it made the contact's
faces move apart at that speed under the gas pressure, creating 0.5 % of the energy
over the run.

So a dropped family whose mismatch would *create* energy is judged like a neglected
entropy contact (``fronttrack.neglect``): its cost is bounded by the rate times the
time the mismatch can last,

    cost = dE/dt * min(t_end - t, L / c)           (J/m^2)

with ``L`` the thickness of the layer and ``c`` the carrier's speed (a wave leaving
the layer is solved again from the states it meets), or the layer's sound speed for a
site (a site inside a layer is reached by a wave within about a transit).  The family
is kept if that cost exceeds the neglect budget.  A mismatch that loses energy costs
accuracy, not conservation, and is dropped as before.  The costs of the drops allowed
are summed in ``accuracy.dropped_wave_cost``.
"""

from __future__ import annotations

import math

from materials import Fan, WavediagramError

from . import neglect
from .outgoing import negligible


def must_keep(engine, sol, direction: int, region_left, region_right, site,
              t: float) -> bool:
    """Whether the weak family of ``sol`` leaving the event at time ``t`` (s) in
    ``direction`` (-1 left, +1 right) must be kept although it is negligible: dropping
    it would create more energy than the neglect budget allows (module docstring).
    ``site``: the event's site or ``None``.  ``False`` for a family that is not
    negligible (it is kept anyway)."""
    waves, other = ((sol.left_waves, sol.right_waves) if direction < 0
                    else (sol.right_waves, sol.left_waves))
    region = region_left if direction < 0 else region_right
    if engine.keep_weak_waves or region is None or not negligible(engine, waves):
        return False
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
    if not rate > 0.0:
        return False
    cost = rate * duration(engine, region, speed, t)
    if neglect.within_budget(engine, cost, t):
        engine.counters.dropped_cost += cost
        return False
    return True


def creation_rate(rho0: float, speed: float, old, star, direction: int) -> float:
    """Energy (W/m^2, positive: created) made by a front at Lagrangian ``speed`` (m/s)
    whose side ``direction`` keeps the state ``old`` where its jump conditions want
    ``star``: the flux residual ``rho0 U (E_l - E_r) - (sigma_l u_l - sigma_r u_r)`` of
    the jump from ``old`` to ``star`` (``rho0`` in kg/m^3)."""
    left, right = (old, star) if direction < 0 else (star, old)

    def energy(s):
        return s.e + 0.5 * s.u * s.u

    return (rho0 * speed * (energy(left) - energy(right))
            - (left.sigma * left.u - right.sigma * right.u))


def duration(engine, region, speed: float, t: float) -> float:
    """Bound (s) on how long a mismatch carried at ``speed`` (m/s) beside ``region``
    lasts: until ``t_end``, or until its carrier crosses the region's layer (for a site,
    a transit of the layer at its sound speed)."""
    remaining = max(engine.t_end - t, 0.0)
    thickness = engine.scene.layers[region.layer].thickness
    carrier = abs(speed)
    if carrier == 0.0:
        try:
            carrier = region.material.sound_speed(region.state.v, region.state.e)
        except (ArithmeticError, ValueError, WavediagramError):
            return remaining
    return min(remaining, thickness / carrier) if carrier > 0.0 else remaining
