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

Not modelled here: the finite-strain (convex) pressure that turns the plastic
wave into a steady wave (§10.3.2).  In this linear-elastic, small-strain model the
plastic wave keeps spreading as it runs.  Nor the dislocation-based rate law,
whose parameters are not given here.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .base import require_number, require_positive
from .errors import MaterialError

_NEWTON_STEPS = 60


@dataclass(frozen=True)
class Viscoplastic:
    """Small-strain elastic–viscoplastic solid (see the module docstring).

    ``rho0`` (kg/m^3); ``lam``, ``mu`` Lamé constants (Pa); ``yield_strength`` Y (Pa,
    > 0); ``relaxation_time`` tau (s, >= 0, ``math.inf`` for an elastic solid);
    ``rate_exponent`` n (>= 1).
    """

    name: str
    rho0: float
    lam: float
    mu: float
    yield_strength: float
    relaxation_time: float
    rate_exponent: float = 1.0

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
    def hel(self) -> float:
        """Hugoniot elastic limit ``M Y / (2 mu)`` (Pa)."""
        return self.modulus * self.yield_strength / (2.0 * self.mu)

    def deviator(self, sigma, plastic_strain):
        """``S = (4 mu / (3 M)) sigma + 2 mu (4 mu / (3 M) - 1) eps_p`` (Pa): the deviator
        of a state given by its stress and plastic strain."""
        c = 4.0 * self.mu / (3.0 * self.modulus)
        return c * sigma + 2.0 * self.mu * (c - 1.0) * plastic_strain

    def rate(self, deviator):
        """Plastic strain rate ``phi(S)`` (1/s; floats or arrays)."""
        s_y = 2.0 * self.yield_strength / 3.0
        s = np.asarray(deviator, dtype=float)
        if math.isinf(self.relaxation_time):
            return np.zeros_like(s)
        over = np.maximum(np.abs(s) / s_y - 1.0, 0.0)
        return np.sign(s) * s_y / (2.0 * self.mu * self.relaxation_time) * over**self.rate_exponent

    def implicit_rate(self, s0, k):
        """The rate ``phi`` solving ``phi = rate(s0 - k phi)`` (``k > 0``, arrays).

        This is the implicit (trapezoidal) step of the grid: the deviator at the new
        node falls by ``k phi`` as plastic strain relaxes it.  ``g(phi) = phi -
        rate(s0 - k phi)`` increases and is concave on the side of ``s0``'s sign, so
        Newton from ``phi = 0`` converges monotonically.  ``tau = 0`` returns the
        rate that puts the deviator exactly on the yield surface (a return mapping:
        the elastic–plastic limit).
        """
        s0 = np.asarray(s0, dtype=float)
        k = np.broadcast_to(np.asarray(k, dtype=float), s0.shape)
        s_y = 2.0 * self.yield_strength / 3.0
        excess = np.maximum(np.abs(s0) - s_y, 0.0)
        if math.isinf(self.relaxation_time):
            return np.zeros_like(s0)
        if self.relaxation_time == 0.0:
            return np.sign(s0) * excess / k
        sign = np.sign(s0)
        a = s_y / (2.0 * self.mu * self.relaxation_time)
        n = self.rate_exponent
        phi = np.zeros_like(s0)
        for _ in range(_NEWTON_STEPS):
            over = np.maximum((np.abs(s0) - k * phi) / s_y - 1.0, 0.0)
            g = phi - a * over**n
            dg = 1.0 + a * n * over ** (n - 1.0) * k / s_y
            step = -g / dg
            phi = np.minimum(np.maximum(phi + step, 0.0), excess / k)
            if np.all(np.abs(step) <= 1e-15 * phi):
                break
        return sign * phi
