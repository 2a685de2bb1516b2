"""The steady plastic wave of an elastic–viscoplastic solid (Davison §10.3.2).

The solid of ``materials.viscoplastic`` with a convex equilibrium pressure
(``hugoniot_slope > 0``), driven by a piston at ``u_B``.  Once the elastic precursor
has decayed to the Hugoniot elastic limit, the plastic wave behind it runs unchanged
at a speed ``D`` from the state ``A`` behind the precursor to the state ``B`` at the
piston.  With ``xi = X - D t`` and every field a function of ``xi``, mass and momentum
(``eps_t = -u_X``, ``rho0 u_t = -sigma_X``) integrate to the Rayleigh line,

    u - u_A = D (eps - eps_A),     sigma - sigma_A = rho0 D^2 (eps - eps_A),

and the end states satisfy the jump conditions between them:

    A:  sigma_A = HEL,  eps_A = sigma_A / M,  u_A = sigma_A / (rho0 C0)  (the precursor),
    B:  u_B given,  sigma_B = p(eps_B) + 2Y/3  (relaxed),
        (sigma_B - sigma_A)(eps_B - eps_A) = rho0 (u_B - u_A)^2,
        D = (u_B - u_A) / (eps_B - eps_A).

Inside the wave the plastic strain follows from the elastic law,
``eps_p = (M eps - sigma) / (2 mu)``, so ``d eps_p/dxi = (M - rho0 D^2)/(2 mu)
d eps/dxi`` and the flow law ``-D d eps_p/dxi = phi(S)`` gives the profile

    d xi / d eps = -D (M - rho0 D^2) / (2 mu phi(S(eps))),
    S(eps) = sigma_A + rho0 D^2 (eps - eps_A) - p(eps),

which needs ``rho0 D^2 < M`` (the wave slower than the elastic precursor) and the
Rayleigh line above the relaxed path ``p + 2Y/3`` between ``A`` and ``B`` (true for a
convex ``p``: the overstress ``S - 2Y/3`` is then positive inside).  The end states are
roots of monotone scalar equations (to rounding); the profile ``xi(eps)`` is
integrated (``scipy.integrate.solve_ivp``, DOP853, rtol 1e-10), its origin at the
midpoint ``eps = (eps_A + eps_B)/2``.  The tails approach ``A`` and ``B``
exponentially, so the wave's width is measured between fractions of the jump.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.integrate import solve_ivp

from .errors import MaterialError
from .roots import bracketed_newton
from .viscoplastic import Viscoplastic

_DOUBLINGS = 60


@dataclass(frozen=True)
class SteadyWave:
    """A steady plastic wave: end states ``(sigma Pa, u m/s, eps)`` ``ahead`` (A) and
    ``behind`` (B), and its Lagrangian ``speed`` D (m/s)."""

    material: Viscoplastic
    ahead: tuple[float, float, float]
    behind: tuple[float, float, float]
    speed: float

    def overstress(self, eps):
        """``S(eps) - 2Y/3`` along the Rayleigh line (Pa), positive inside the wave."""
        mat, (sigma_a, _, eps_a) = self.material, self.ahead
        sigma = sigma_a + mat.rho0 * self.speed**2 * (np.asarray(eps) - eps_a)
        return sigma - mat.pressure(eps) - 2.0 * mat.yield_strength / 3.0

    def position(self, fractions) -> np.ndarray:
        """``xi`` (m, relative to the midpoint) where the wave has covered ``fractions``
        (strictly between 0 and 1, increasing) of its jump from ``A`` to ``B``; ``xi``
        decreases as the fraction grows (the wave runs toward ``+X``)."""
        fractions = np.asarray(fractions, dtype=float)
        if not (np.all((fractions > 0.0) & (fractions < 1.0))
                and np.all(np.diff(fractions) > 0.0)):
            raise MaterialError("fractions must increase strictly inside (0, 1)")
        mat, eps_a, eps_b = self.material, self.ahead[2], self.behind[2]
        factor = -self.speed * (mat.modulus - mat.rho0 * self.speed**2) / (2.0 * mat.mu)

        def slope(eps, _):
            return [factor / float(mat.rate(self.overstress(eps) + 2.0 * mat.yield_strength
                                            / 3.0))]

        eps = eps_a + fractions * (eps_b - eps_a)
        mid = 0.5 * (eps_a + eps_b)
        out = np.zeros_like(eps)            # zero at the midpoint itself
        for part, sign in ((eps > mid, 1.0), (eps < mid, -1.0)):
            if not np.any(part):
                continue
            targets = eps[part]                 # increasing: integrate up from the midpoint
            order = np.argsort(sign * targets)  # decreasing: down from it
            end = targets[order][-1]
            solved = solve_ivp(slope, (mid, end), [0.0], method="DOP853",
                               t_eval=targets[order], rtol=1e-10, atol=1e-15)
            values = np.empty(targets.size)
            values[order] = solved.y[0]
            out[part] = values
        return out

    def width(self, low: float = 0.1, high: float = 0.9) -> float:
        """Distance (m) over which the wave rises from ``low`` to ``high`` of its jump."""
        xi_low, xi_high = self.position([low, high])
        return float(xi_low - xi_high)


def steady_wave(mat: Viscoplastic, piston_velocity: float) -> SteadyWave:
    """The steady plastic wave driven by ``piston_velocity`` (m/s) into ``mat`` at rest
    (see the module docstring).  Raises ``MaterialError`` naming the field when there is
    none: ``hugoniot_slope`` 0 (a linear relaxed path spreads), a piston velocity not
    above the precursor's, or a wave that would outrun the precursor."""
    if not mat.hugoniot_slope > 0.0:
        raise MaterialError(f"{mat.name}: hugoniot_slope must be > 0 for a steady wave "
                            f"(with a linear relaxed path the plastic wave keeps spreading)")
    if math.isinf(mat.relaxation_time) or mat.relaxation_time == 0.0:
        raise MaterialError(f"{mat.name}: relaxation_time must be finite and > 0 for a "
                            f"steady wave of finite width, got {mat.relaxation_time!r}")
    sigma_a = mat.hel
    eps_a, u_a = sigma_a / mat.modulus, sigma_a / mat.impedance
    du = float(piston_velocity) - u_a
    if not du > 0.0:
        raise MaterialError(f"piston_velocity must exceed the precursor's particle velocity "
                            f"{u_a:.6g} m/s for a plastic wave, got {piston_velocity!r}")
    s_y = 2.0 * mat.yield_strength / 3.0

    def mismatch(eps):
        return (float(mat.pressure(eps)) + s_y - sigma_a - mat.rho0 * du**2 / (eps - eps_a),
                float(mat.pressure_slope(eps)) + mat.rho0 * du**2 / (eps - eps_a) ** 2)

    lo, hi = eps_a, eps_a + du / mat.C0      # at hi the Rayleigh line is the elastic one
    for _ in range(_DOUBLINGS):
        if mismatch(hi)[0] > 0.0:
            break
        lo, hi = hi, eps_a + 2.0 * (hi - eps_a)
        if not hi < 1.0 / mat.hugoniot_slope:
            raise MaterialError(f"piston_velocity {piston_velocity!r} m/s is beyond the "
                                f"range of the equilibrium pressure")
    eps_b = bracketed_newton(mismatch, lo, hi)
    speed = du / (eps_b - eps_a)
    if not speed < mat.C0:
        raise MaterialError(f"piston_velocity {piston_velocity!r} m/s drives a plastic wave "
                            f"at {speed:.6g} m/s, not slower than the precursor "
                            f"({mat.C0:.6g} m/s): no two-wave structure")
    sigma_b = sigma_a + mat.rho0 * speed * du
    return SteadyWave(mat, (sigma_a, u_a, eps_a), (sigma_b, float(piston_velocity), eps_b),
                      speed)
