"""Elastic–viscoplastic solid in uniaxial strain (small strain; Davison §7.3, §10.3).

Conventions of PHYSICS.md: stress ``sigma`` positive in compression (Pa),
compression ``eps = 1 - v/v0``, SI units.

The elastic law is that of ``materials.elastic_plastic``,

    sigma = M eps - 2 mu eps_p,      M = lambda + 2 mu,
    S = sigma - p = 2 mu (2 eps/3 - eps_p)     (the stress deviator),

but the plastic strain no longer follows the strain instantly: it *relaxes*
toward the yield surface at a finite rate (an overstress law, Perzyna's form):

    d eps_p / dt = phi(S) = sign(S) (2Y/3) / (2 mu tau) < |S| / (2Y/3) - 1 >^n,

``< x > = max(x, 0)``, ``Y`` the quasi-static yield strength, ``tau`` the relaxation
time (s, >= 0) and ``n >= 1`` the rate exponent.  With ``n = 1`` the overstress
``|S| - 2Y/3`` of a material element held at fixed strain decays as
``exp(-t / tau)`` (since ``dS/dt = -2 mu phi``).  ``tau -> 0`` is the rate-independent
elastic–plastic solid, ``tau -> inf`` the linear elastic one.

Waves: every discontinuity is elastic and runs at ``C0 = sqrt(M / rho0)`` (the
plastic strain cannot jump), so the characteristics are the straight lines
``dX/dt = +-C0`` and along them (derived from ``rho0 u_t = -sigma_X``,
``eps_t = -u_X`` and the law)

    d(sigma + Z u) = -2 mu phi dt   on dX/dt = +C0,
    d(sigma - Z u) = -2 mu phi dt   on dX/dt = -C0,     Z = rho0 C0,
    d eps_p = phi dt                on dX = 0.

The elastic precursor into material at rest carries ``sigma = Z u`` (its jump
condition) and ``eps_p = 0``, so the C+ relation along its own path gives the
precursor decay law (§10.3.1):

    d sigma_p / dt = -mu phi(S_p),    S_p = (4 mu / (3 M)) sigma_p,

or ``d sigma_p / dX = -(mu / C0) phi`` along ``X = C0 t``: the precursor decays
toward the Hugoniot elastic limit ``sigma_HEL = M Y / (2 mu)``, where ``phi`` vanishes.
``characteristics.viscoplastic_grid`` integrates these relations on the
characteristic grid.

The equilibrium pressure (§10.3.2).  ``p`` above is ``K eps`` in the small-strain
solid (``K = lambda + 2 mu/3``): then the rate-independent loading path is the straight
line ``sigma = K eps + 2Y/3`` and the plastic wave keeps spreading as it runs.  With a
``hugoniot_slope`` ``s > 0`` the equilibrium pressure is the principal Hugoniot pressure
of a linear ``Us = CB + s up`` solid (Γ0 = 0, ``CB = sqrt(K / rho0)``),

    p(eps) = K eps / (1 - s eps)^2,      S = sigma - p(eps),
    eps = (sigma + 2 mu eps_p) / M       (the elastic law above, unchanged),

so that the relaxed path ``sigma = p(eps) + 2Y/3`` is convex while the instantaneous
(frozen) response stays the straight line of slope ``M``: the characteristics are
still ``dX/dt = +-C0``.  A chord of the convex path lies above it, so the plastic wave
steepens against its own spreading and runs as a steady wave (§10.3.2): between the
state ``A`` behind the decayed precursor (the HEL) and the final state ``B`` on the
relaxed path, every state of the wave lies on the Rayleigh line

    sigma - sigma_A = rho0 D^2 (eps - eps_A),    u - u_A = D (eps - eps_A),

with ``D`` from the jump conditions between ``A`` and ``B``, and, in ``xi = X - D t``,

    d eps / d xi = -2 mu phi(S) / (D (M - rho0 D^2)),   S = sigma_R(eps) - p(eps).

The model needs ``p'(eps) < M`` (the frozen response stiffer than the relaxed one; the
grid checks it where the strain goes): it is a frozen-linear, relaxed-convex model, not
the finite-strain elastic–plastic solid.  ``s = 0`` is the small-strain solid exactly.

Not modelled: the dislocation-based rate law (Davison §7.3): no book excerpt with its
parameters was available to this project, so only the overstress law is implemented.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .base import require_number, require_positive
from .errors import MaterialError
from .roots import bracketed_newton

_NEWTON_STEPS = 60
_RATE_RTOL = 1e-13
"""Change of the rate, relative to its bracket, at which the implicit step stops: the
rate equation is evaluated with a rounding noise of about 1e-15 of the stresses, which
makes the last Newton steps oscillate by an ulp or two of the rate."""


@dataclass(frozen=True)
class Viscoplastic:
    """Small-strain elastic–viscoplastic solid (see the module docstring).

    ``rho0`` (kg/m^3); ``lam``, ``mu`` Lamé constants (Pa); ``yield_strength`` Y (Pa,
    > 0); ``relaxation_time`` tau (s, >= 0, ``math.inf`` for an elastic solid);
    ``rate_exponent`` n (>= 1); ``hugoniot_slope`` s (>= 0) of the equilibrium pressure
    (0: the small-strain solid).
    """

    name: str
    rho0: float
    lam: float
    mu: float
    yield_strength: float
    relaxation_time: float
    rate_exponent: float = 1.0
    hugoniot_slope: float = 0.0

    def __post_init__(self):
        require_positive("rho0", self.rho0, self.name)
        require_number("lambda", self.lam, self.name)
        require_positive("mu", self.mu, self.name)
        y = require_number("yield_strength", self.yield_strength, self.name)
        if not 0.0 < y < math.inf:
            raise MaterialError(f"{self.name}: yield_strength must be finite and > 0 Pa (the "
                                f"overstress is measured in units of 2Y/3), "
                                f"got {self.yield_strength!r}")
        tau = require_number("relaxation_time", self.relaxation_time, self.name)
        if not tau >= 0.0:
            raise MaterialError(f"{self.name}: relaxation_time must be >= 0 s (inf: "
                                f"elastic), got {self.relaxation_time!r}")
        n = require_number("rate_exponent", self.rate_exponent, self.name)
        if not 1.0 <= n < math.inf:
            raise MaterialError(f"{self.name}: rate_exponent must be >= 1, "
                                f"got {self.rate_exponent!r}")
        if not self.lam + 2.0 * self.mu / 3.0 > 0.0:
            raise MaterialError(f"{self.name}: the bulk modulus lambda + 2 mu/3 must be > 0")
        slope = require_number("hugoniot_slope", self.hugoniot_slope, self.name)
        if not 0.0 <= slope < math.inf:
            raise MaterialError(f"{self.name}: hugoniot_slope must be finite and >= 0, "
                                f"got {self.hugoniot_slope!r}")

    @property
    def v0(self) -> float:
        """Reference specific volume (m^3/kg)."""
        return 1.0 / self.rho0

    def sound_speed(self, v: float, e: float) -> float:
        """Lagrangian speed of every wave (m/s): the elastic ``C0`` (the plastic strain
        cannot jump); ``v`` and ``e`` are not used."""
        return self.C0

    @property
    def modulus(self) -> float:
        """Longitudinal modulus ``M = lambda + 2 mu`` (Pa)."""
        return self.lam + 2.0 * self.mu

    @property
    def C0(self) -> float:
        """Elastic longitudinal speed (m/s)."""
        return math.sqrt(self.modulus / self.rho0)

    @property
    def impedance(self) -> float:
        """``Z = rho0 C0`` (kg/(m^2 s))."""
        return self.rho0 * self.C0

    @property
    def bulk_modulus(self) -> float:
        """``K = lambda + 2 mu / 3`` (Pa): the slope of ``p(eps)`` at ``eps = 0``."""
        return self.lam + 2.0 * self.mu / 3.0

    def pressure(self, eps):
        """Equilibrium pressure ``p(eps) = K eps / (1 - s eps)^2`` (Pa; floats or arrays)."""
        eps = np.asarray(eps, dtype=float)
        return self.bulk_modulus * eps / (1.0 - self.hugoniot_slope * eps) ** 2

    def pressure_slope(self, eps):
        """``p'(eps) = K (1 + s eps) / (1 - s eps)^3`` (Pa)."""
        eps = np.asarray(eps, dtype=float)
        s = self.hugoniot_slope
        return self.bulk_modulus * (1.0 + s * eps) / (1.0 - s * eps) ** 3

    def strain(self, sigma, plastic_strain):
        """Compression ``eps = (sigma + 2 mu eps_p) / M`` of a state (the elastic law)."""
        return (np.asarray(sigma, dtype=float) + 2.0 * self.mu * np.asarray(plastic_strain)) \
            / self.modulus

    @property
    def hel(self) -> float:
        """Hugoniot elastic limit (Pa): the stress on the elastic line ``sigma = M eps``
        where ``S = M eps - p(eps) = 2Y/3``; ``M Y / (2 mu)`` when ``s = 0``."""
        s_y = 2.0 * self.yield_strength / 3.0
        lo = self.yield_strength / (2.0 * self.mu)    # p(eps) >= K eps: S(lo) <= 2Y/3
        if self.hugoniot_slope == 0.0:
            return self.modulus * lo

        def excess(eps):
            return (self.modulus * eps - float(self.pressure(eps)) - s_y,
                    self.modulus - float(self.pressure_slope(eps)))

        hi = lo
        while excess(hi)[0] < 0.0:
            hi *= 2.0
            if not self.pressure_slope(hi) < self.modulus:
                raise MaterialError(f"{self.name}: yield_strength {self.yield_strength!r} "
                                    f"Pa is beyond the elastic range of hugoniot_slope "
                                    f"{self.hugoniot_slope!r} (p'(eps) reaches M first)")
        return self.modulus * bracketed_newton(excess, lo, hi)

    def deviator(self, sigma, plastic_strain):
        """``S = sigma - p(eps)`` (Pa), ``eps = (sigma + 2 mu eps_p) / M``: the deviator of
        a state given by its stress and plastic strain (``(4 mu / (3 M)) sigma + 2 mu
        (4 mu / (3 M) - 1) eps_p`` when ``s = 0``)."""
        return np.asarray(sigma, dtype=float) - self.pressure(self.strain(sigma,
                                                                          plastic_strain))

    def rate(self, deviator):
        """Plastic strain rate ``phi(S)`` (1/s; floats or arrays)."""
        s_y = 2.0 * self.yield_strength / 3.0
        s = np.asarray(deviator, dtype=float)
        if math.isinf(self.relaxation_time):
            return np.zeros_like(s)
        over = np.maximum(np.abs(s) / s_y - 1.0, 0.0)
        return np.sign(s) * s_y / (2.0 * self.mu * self.relaxation_time) * over**self.rate_exponent

    def implicit_rate(self, sigma0, ks, plastic0, kp):
        """The rate ``phi`` solving ``phi = rate(S(sigma0 - ks phi, plastic0 + kp phi))``.

        This is the implicit (trapezoidal) step of the grid: at the new node the stress
        falls by ``ks phi`` and the plastic strain grows by ``kp phi`` (``ks, kp >= 0``,
        arrays).  Along this line ``dS/dphi = -ks - p'(eps) (2 mu kp - ks) / M < 0``
        while ``0 < p' < M``, so ``|S|`` falls as ``|phi|`` grows and ``g(q) = q -
        |rate|`` (``q = |phi|``) increases from ``g(0) <= 0``: the root is bracketed by
        ``[0, |rate(S0)|]`` and found by a safeguarded Newton iteration (bisection when
        the Newton step leaves the bracket).  ``tau = 0`` returns the rate that puts the
        deviator exactly on the yield surface (a return mapping: the elastic–plastic
        limit), ``tau = inf`` zero.
        """
        sigma0, ks, plastic0, kp = np.broadcast_arrays(
            *(np.asarray(a, dtype=float) for a in (sigma0, ks, plastic0, kp)))
        s_y = 2.0 * self.yield_strength / 3.0
        if math.isinf(self.relaxation_time):
            return np.zeros_like(sigma0)
        sign = np.sign(self.deviator(sigma0, plastic0))
        over_tau = self.relaxation_time > 0.0
        a = s_y / (2.0 * self.mu * self.relaxation_time) if over_tau else 0.0
        n = self.rate_exponent

        def g(q):
            """``(g, dg/dq)``: the rate equation (tau > 0) or ``s_y - |S|`` (tau = 0)."""
            sigma, plastic = sigma0 - ks * sign * q, plastic0 + kp * sign * q
            eps = self.strain(sigma, plastic)
            size = sign * (sigma - self.pressure(eps))
            slope = -ks - self.pressure_slope(eps) * (2.0 * self.mu * kp - ks) / self.modulus
            if not over_tau:
                return s_y - size, -slope
            over = np.maximum(size / s_y - 1.0, 0.0)
            return q - a * over**n, 1.0 - a * n * over ** (n - 1.0) * slope / s_y

        lo = np.zeros_like(sigma0)
        g_lo, dg_lo = g(lo)
        active = g_lo < 0.0
        if over_tau:
            hi = -g_lo
        else:                       # double a linear estimate until |S| is below yield
            hi = np.where(active, 2.0 * np.maximum(-g_lo, 0.0) / np.where(active, dg_lo, 1.0),
                          0.0)
            for _ in range(_NEWTON_STEPS):
                g_hi = g(hi)[0]
                if not np.any(active & (g_hi < 0.0)):
                    break
                hi = np.where(active & (g_hi < 0.0), 2.0 * hi, hi)
        scale = hi.copy()         # the rate's scale: the root lies in [0, hi]
        q = lo.copy()
        for _ in range(_NEWTON_STEPS):
            value, slope = g(q)
            lo = np.where(value < 0.0, q, lo)
            hi = np.where(value > 0.0, q, hi)
            with np.errstate(divide="ignore", invalid="ignore"):
                newton = q - value / slope
            inside = (newton >= lo) & (newton <= hi)
            new = np.where(active, np.where(inside, newton, 0.5 * (lo + hi)), 0.0)
            done = np.abs(new - q) <= _RATE_RTOL * scale
            q = new
            if np.all(done):
                break
        return sign * q
