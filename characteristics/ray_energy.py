"""The energy a ray creates: the flux residual of a jump, and why a ray creates energy.

A ray stands for a segment of a simple wave: a jump between two cells ``a`` (ahead) and
``b`` (behind) that lie on one isentrope.  Moving at Lagrangian speed ``U`` between its
left state ``l`` and right state ``r`` (``b`` and ``a`` for a right-going ray, ``a`` and
``b`` for a left-going one) it changes the total energy and momentum per unit area at

    R_E(U) = rho0 U (E_l - E_r) - (sigma_l u_l - sigma_r u_r)      (W/m^2)
    R_p(U) = rho0 U (u_l - u_r) - (sigma_l - sigma_r)              (Pa)

with ``E = e + u^2/2``: a shock makes both zero, a ray cannot (three jump conditions,
one speed, and states fixed on the isentrope).  With ``Delta = l - r`` and bars for the
means of the two sides these are, exactly,

    R_E(U) = [rho0 U Delta e - sigma_bar Delta u] + u_bar R_p(U).

At the characteristic speed ``C`` of the ray's middle state both are third order in the
step.  Along the isentrope ``de = -sigma dv``, ``dv = -d sigma / (rho0 C)^2`` and
``du = d sigma / (rho0 C)`` (sign per family); with ``f = 1/C`` expanded about the middle
stress ``sigma_m`` (``f0, f1 = df/d sigma, f2``) and ``h = Delta sigma / 2``,

    R_p(C) = f2 h^3 / (3 f0)
    R_E(C) = (h^3 / rho0) (4 f1 / 3 + 2 sigma_m f1^2 / (3 f0) + sigma_m f2 / 3)
             + u_bar R_p(C).

In a solid or gas whose sound speed grows with compression (``f1 < 0``) the leading term
``4 h^3 f1 / (3 rho0)`` is positive where ``h`` is negative for a right-going ray and
positive for a left-going one: an **expansion ray creates energy**, a compression ray
loses it, like a rarefaction shock and a shock.  Each ray of a fan adds its ``O(h^3)``,
so a fan of ``n`` rays creates ``O(Delta sigma^3 / n^2)`` per unit time; in a thin layer
that rings, the same large rays cross again and again (campaign seed 180: rays of up to
8.9 GPa, two per fan, in a 10 um LiF layer, +14.7 % of the energy).

Why not move the ray.  ``R_E`` is linear in ``U`` (slope ``rho0 Delta E``), so a speed
``U_E = (sigma_l u_l - sigma_r u_r) / (rho0 (E_l - E_r))`` meets the energy condition, and
it lies within a few per cent of ``C`` where ``Delta E`` is first order.  But with the
states fixed, no speed is both momentum-exact and energy-conserving: at the speed that
makes ``R_p = 0`` (the chord speed ``U_p``, inside the band of the two cells' speeds)

    R_E(U_p) = (2 h^3 f1 / (3 rho0)) (2 + sigma_m f1 / f0) + O(h^5),

positive for every expansion ray where ``sigma_m f1 / f0 > -2`` (for ``sigma >= 0`` in
ideal gases and Murnaghan-like solids, and in tension wherever ``f1 < 0``). Moving a ray
to ``U_E`` therefore turns the energy it creates into a momentum residual of the same
relative size, ``-R_E(C) Delta u / Delta E``. Measured (branch wt-ray): moving every ray
that creates energy to ``U_E`` within its band took campaign seed 180 from +14.7 %
energy, 0.39 % momentum to -6.4 %, 31.8 %; within 2 % of ``C``, single rays only, to
+10.8 %, 6.9 %; moving the characteristics of a fan spoils the record read between them
(Sod's fan at 8 rays: moves of 0.13 % at most made the L1 error of the pressure twenty
times larger); moving the characteristics of fans and lattices by up to 0.1 % changed
the demo's fracture from 12 spall planes to 6. ``Delta E`` also vanishes inside a wave
where ``sigma = +-Z u`` (``Z = rho0 C``), which makes ``U_E`` ill-conditioned there.

What was tried instead, and not kept: cutting a new fan finer where its characteristics
create more than a bound proportional to the step (relative to the energy they carry;
an inner characteristic's share falls as ``1/m^2`` with ``m`` times as many cells, the
head's and tail's as ``1/m``, since they carry the end states at the fan's exact head
and tail speeds).  It took campaign seed 327 (a gas fan to vacuum at eight rays) from
+0.63 % to +0.098 % (promise 0.2 %) and left the demo unchanged, but it multiplied
events where fans reach an equation of state's end: campaign seed 8 145 -> 1 304
events, the cavitation scene of ``tests/test_conservation_bugs.py`` 699 -> more than
3 000, seed 826 1 500 events in 30 ps until capped.  Seed 180 needs its fans cut four
times finer at two rays per fan (it then loses 3.6 %); a bound that low also cut the
demo's fans (803 instead of 523 events, twice the time), and a fixed bound (not
proportional to the step) made the error estimate's run at half the step identical to
the run it checks.

What is done instead: the state behind a ray carries the energy its jump conditions
need (``conserving_state``).  Its stress and velocity stay those of the isentrope (so
do its Riemann invariants and characteristic speed, read from ``(sigma, u)``); its
specific internal energy takes ``e_b - R_E / (rho0 |U|)`` and its volume the value that
keeps its stress at that energy: a jump on its Rayleigh line with an entropy offset
``O(h^3)``, the cell behind lying below the isentrope.  Only where the ray would create
energy (an expansion ray): a ray that loses energy keeps its state, as a dropped wave
loses it.  Raising the energy behind compression rays too (a weak shock's entropy rise)
was measured and rejected: the Cu/Al spall scene of ``tests/test_engine_fans.py``, which
loses 0.070, 0.020, 0.005 % at 4, 8, 16 rays, then created 0.072, 0.027, 0.007 %
(lattices give the deficits of their cells back, see below, and no loss was left to
cover it).  Where a family of waves leaves an event
(``fronttrack.outgoing``) each wave is so made to conserve energy from the (shifted)
state ahead of it, and the star state behind the last one carries the sum.  A shift
within the tolerance of the isentrope tables is neglected: the tables do not tell such
isentropes apart (a weak shock below it is taken as a ray), and shifting them anyway
put cells beside the tables' isentropes, split the demo's lattices and took it from
523 to 858 events (the same 12 spall planes).  A lattice keeps the energy of the cells
it starts from (``characteristics.lattice.Zone.e``); the cells its nodes make lie on the
isentrope, so a lattice's ray running into a cell below it gives that deficit back.
Campaign seed 180 went from +14.7 % to -4.8 % (promise 2.5 %), 327 from +0.63 % to
+0.050 % (promise 0.2 %); Sod's shock tube, whose fan has rays that create energy and
rays that lose it, from losing 7.2e-5, 2.0e-5, 5.5e-6 of it at 8, 16, 32 rays to losing
1.6e-4, 4.6e-5, 1.2e-5 (still second order; its left star, behind the fan, is that much
denser than the exact one); the demo and Davison steel are unchanged.

Not done (measured, branch wt-ray2): making the cells a lattice's nodes make conserve
energy too.  A cell above a crossing lies behind two rays and can meet one energy
condition only; taking the lower of the two (so that neither ray creates energy), with
every ray of a new fan shifted, took seed 180 to -5.6 % and 327 to -0.016 %, but the
offsets pile up node after node and leave the tolerance of the tables: the demo's
lattices fell apart into Riemann solves (the lattice rule alone: 2 804 events, 39
tables and 880 shocks by 1.6 us instead of 111 events; the whole demo did not finish
in 10 minutes).  A lattice that carries entropy needs a grid of states that does too.

What bounds it in gases instead: the step.  In an ideal gas a ray makes energy at
``(gamma + 1) rho du^3 / 16`` to leading order (``rho`` the density, ``du`` its velocity
step), a fraction ``(du/c)^3`` of the internal energy of the mass it sweeps: second
order per transit in ``du / c``.  A gas's characteristics span at most ``step /
stress_scale`` of its sound speed (not below half its initial one) over the square root
of its share of the energy (``fronttrack.resolution.sound_bound``); campaign seed 652
(three gas layers ringing against a wall, rays of 0.4-0.8 ``c``, +1.97 %, of which the
lattices' rays +1.85 %) went to -0.14 %, 327's momentum from 0.53 % to 0.057 %.
In solids the bound does not act.
"""

from __future__ import annotations

import math
from dataclasses import replace

from materials import State


def energy_residual(rho0: float, speed: float, left: tuple, right: tuple) -> float:
    """Energy (W/m^2, positive: created) that a jump at Lagrangian ``speed`` (m/s) between
    the ``left`` and ``right`` states ``(sigma Pa, u m/s, e J/kg)`` makes per unit time:
    ``rho0 U (E_l - E_r) - (sigma_l u_l - sigma_r u_r)`` (``rho0`` in kg/m^3)."""
    jump = (left[2] + 0.5 * left[1] * left[1]) - (right[2] + 0.5 * right[1] * right[1])
    return rho0 * speed * jump - (left[0] * left[1] - right[0] * right[1])


def energy_behind(rho0: float, speed: float, ahead: tuple, behind: tuple) -> float:
    """Specific internal energy (J/kg) the state ``behind`` a jump at Lagrangian ``speed``
    (m/s, signed) must have for the jump to conserve energy, its stress and velocity held:
    ``e_b - R_E / (rho0 |U|)`` (states ``(sigma Pa, u m/s, e J/kg)``; ``rho0`` kg/m^3).  A
    jump that does not move (``U = 0``) keeps ``e_b``: no mass crosses it."""
    if speed == 0.0 or not math.isfinite(speed):
        return behind[2]
    left, right = (behind, ahead) if speed > 0.0 else (ahead, behind)
    return behind[2] - energy_residual(rho0, speed, left, right) / (rho0 * abs(speed))


VOLUME_ROUNDING = 1e-9
"""Relative stress mismatch within which the volume of a shifted state is found."""


def volume_at_energy(material, v: float, e: float, e_new: float) -> float | None:
    """Specific volume (m^3/kg) near ``v`` at which ``material`` at energy ``e_new`` (J/kg)
    has the stress it has at ``(v, e)`` (``Material.volume_at``, to ``VOLUME_ROUNDING``);
    ``None`` where there is none near (a gas whose energy would fall below zero)."""
    target = material.stress(v, e)
    tolerance = VOLUME_ROUNDING * (abs(target) + material.rho0 * abs(e_new - e))
    return material.volume_at(State(sigma=target, u=0.0, v=v, e=e), target, e_new,
                              tolerance)


def conserving_state(material, speed: float, ahead: State, behind: State) -> State:
    """``behind`` with the specific internal energy that makes its jump from ``ahead`` at
    Lagrangian ``speed`` (m/s) conserve energy (``energy_behind``), and the volume that
    keeps its stress (``volume_at_energy``), where the jump would create energy; its
    stress and velocity unchanged.  A jump that conserves or loses energy, or a state at
    vacuum (infinite volume) or with no state of that stress at the lower energy, returns
    ``behind`` itself: a ray may lose energy (as a dropped wave does), never make it; the
    rest is energy the ray still creates."""
    e_new = energy_behind(material.rho0, speed, (ahead.sigma, ahead.u, ahead.e),
                          (behind.sigma, behind.u, behind.e))
    if not e_new < behind.e or not (math.isfinite(behind.v) and math.isfinite(e_new)):
        return behind
    v = volume_at_energy(material, behind.v, behind.e, e_new)
    return behind if v is None else replace(behind, v=v, e=e_new)
