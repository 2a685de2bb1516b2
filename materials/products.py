"""Detonation products: the JWL equation of state and its gamma-law limit (Davison ch. 13).

Energies are measured from the *unreacted* explosive at rest (``e = 0`` there), so the
products carry the heat of detonation ``q`` (J/kg) as an offset: with ``e' = e + q``
the energy the products' own equation of state sees, ``V = v / v0`` the relative
volume and ``rho0 = 1/v0`` the explosive's initial density,

    JWL:        sigma = A (1 - omega/(R1 V)) exp(-R1 V) + B (1 - omega/(R2 V)) exp(-R2 V)
                        + omega e' / v,
    gamma law:  sigma = (Gamma - 1) e' / v        (A = B = 0, omega = Gamma - 1).

(The JWL energy per unit initial volume is ``E = rho0 e'``, so ``omega E / V = omega
e' / v``; ``E0 = rho0 q`` is the tabulated detonation energy.)  The stress is affine in
energy with Grüneisen coefficient ``(d sigma/d e)_v = omega / v``, so the Hugoniot
centred on any state ``a`` (the unreacted explosive included: that is the detonation
Hugoniot) is the closed form of ``materials.base``:

    e_H(v) = [e_a + 1/2 (sigma_a + a(v)) (v_a - v)] / [1 - 1/2 (omega/v) (v_a - v)],

``a(v) = sigma(v, e = 0)``, bounded by the limiting compression ``v > v_a omega /
(2 + omega)``.  Every isentrope is known in closed form: along ``de'/dv = -sigma``,

    e'(V) = (A v0/R1) exp(-R1 V) + (B v0/R2) exp(-R2 V) + K V^-omega,
    sigma(V) = A exp(-R1 V) + B exp(-R2 V) + omega rho0 K V^-(1 + omega),

one constant ``K`` (J/kg) per isentrope, and ``C_L^2 = -v0^2 (d sigma/dv)_s =
v0 [A R1 exp(-R1 V) + B R2 exp(-R2 V) + (1 + omega) omega rho0 K V^-(2 + omega)]``.
The products expand to vacuum: ``sigma -> 0`` and ``e -> -q`` as ``V -> inf``.

Riemann-invariant integral ``J = int rho0 C_L dv``: for the gamma law in closed form,
``J = 2 (c_start - c) / (Gamma - 1)`` with ``c = (v/v0) C_L`` the Eulerian sound speed;
for JWL from a Chebyshev table of the integrand in ``y = V^(-omega/2)``, in which it is
smooth on ``[0, y]`` (it tends to a constant as ``V -> inf``): one table per isentrope
(``materials.products_isentrope``), so the integral to vacuum is two series evaluations.
"""

from __future__ import annotations

import functools
import math

import numpy as np

from .base import Material, require_number, require_positive
from .errors import MaterialError
from .products_isentrope import ProductsIsentropeTable
from .state import State


class Products(Material):
    """Detonation products of an explosive of initial density ``rho0`` (kg/m^3).

    ``A``, ``B`` (Pa), ``R1``, ``R2``, ``omega`` (dimensionless): the JWL coefficients;
    ``q`` (J/kg): the heat of detonation, released between the unreacted explosive
    (``e = 0``) and the products.  ``A = B = 0`` is the gamma-law gas of
    ``Gamma = omega + 1`` (``gamma_law``).
    """

    relative_stress_precision = True
    """The isentropes are closed forms good to a few ulps of their own stress down to
    vacuum (the wave curves then resolve releases to near-vacuum)."""

    gaseous = True
    """A gas: its stress vanishes with its energy (``Material.gaseous``)."""

    def __init__(self, name: str, rho0: float, q: float, omega: float, A: float = 0.0,
                 B: float = 0.0, R1: float = 1.0, R2: float = 1.0):
        self.name = name
        self.rho0 = require_positive("rho0", rho0, name)
        self.q = require_positive("q", q, name)
        self.omega = require_positive("omega", omega, name)
        self.A = require_number("A", A, name)
        self.B = require_number("B", B, name)
        self.R1 = require_positive("R1", R1, name)
        self.R2 = require_positive("R2", R2, name)
        for field, value in (("A", self.A), ("B", self.B)):
            if value < 0.0:
                raise MaterialError(f"{name}: JWL {field} must be >= 0 Pa, got {value!r}")
        self.spall_strength = 0.0
        self.is_gamma_law = self.A == 0.0 and self.B == 0.0
        # A gamma-law gas's Hugoniot reaches any stress at its limiting compression, from
        # a cold state (e = -q, left by a release to zero stress) as from a hot one: wave
        # curves then shock it to that compression (the snowplow).  A JWL's exponential
        # terms can bend a cold state's Hugoniot back to tension: not claimed.
        self.unbounded_hugoniot = self.is_gamma_law

    @classmethod
    def gamma_law(cls, name: str, rho0: float, gamma: float, q: float) -> Products:
        """Gamma-law products ``sigma = (gamma - 1)(e + q)/v`` (``gamma`` > 1)."""
        gamma = require_number("gamma", gamma, name)
        if not 1.0 < gamma < 100.0:
            raise MaterialError(f"{name}: gamma must be in (1, 100), got {gamma!r}")
        return cls(name, rho0, q, gamma - 1.0)

    @property
    def gamma(self) -> float:
        """``omega + 1``: the adiabatic exponent of the gamma-law limit."""
        return self.omega + 1.0

    # --- equation of state ----------------------------------------------------------------
    def _terms(self, v):
        """``(a(v), a'(v))``: the stress at ``e' = 0`` less the energy term, and its slope."""
        big_v = v * self.rho0
        a = da = 0.0
        for coef, rate in ((self.A, self.R1), (self.B, self.R2)):
            if coef == 0.0:
                continue
            ex = coef * np.exp(-rate * big_v)
            a = a + ex * (1.0 - self.omega / (rate * big_v))
            da = da + ex * self.rho0 * (self.omega / (rate * big_v**2) + self.omega / big_v
                                        - rate)
        return a, da

    def stress(self, v: float, e: float) -> float:
        if math.isinf(v):
            return 0.0
        return float(self._terms(v)[0] + self.omega * (e + self.q) / v)

    def sound_speed_squared(self, v, e):
        """``C_L^2 = v0^2 (b sigma - a' - b' e')`` with ``b = omega/v`` (m^2/s^2)."""
        a, da = self._terms(v)
        energy = e + self.q
        sigma = a + self.omega * energy / v
        slope = da - self.omega * energy / v**2 - self.omega / v * sigma
        return -self.v0 * self.v0 * slope

    def sound_speed(self, v: float, e: float) -> float:
        if math.isinf(v):
            return 0.0
        return math.sqrt(max(float(self.sound_speed_squared(v, e)), 0.0))

    def volume_range(self) -> tuple[float, float]:
        return (0.0, math.inf)

    # --- Hugoniot ---------------------------------------------------------------------------
    def hugoniot(self, ahead: State, v: float) -> tuple[float, float, float]:
        """``(sigma, e, dsigma/dv)`` on the Hugoniot centred on ``ahead`` (any material's
        state of this explosive: the unreacted one gives the detonation Hugoniot)."""
        dv = ahead.v - v
        a, da = (float(x) for x in self._terms(v))
        b, db = self.omega / v, -self.omega / v**2
        # a(v) + b e' with e' = e + q: the constant part of sigma at e = 0 is a + b q
        a_e, da_e = a + b * self.q, da + db * self.q
        num = ahead.e + 0.5 * (ahead.sigma + a_e) * dv
        den = 1.0 - 0.5 * b * dv
        e = num / den
        dnum = 0.5 * da_e * dv - 0.5 * (ahead.sigma + a_e)
        dden = -0.5 * db * dv + 0.5 * b
        de = (dnum * den - num * dden) / (den * den)
        return a_e + b * e, e, da_e + db * e + b * de

    def hugoniot_volume_limit(self, ahead: State) -> float:
        return ahead.v * self.omega / (2.0 + self.omega) * (1.0 + 1e-12)

    # --- isentropes -------------------------------------------------------------------------
    def _cold(self, big_v):
        """``(e'_ref(V), sigma_ref(V))``: the exponential part of every isentrope."""
        e = s = 0.0
        for coef, rate in ((self.A, self.R1), (self.B, self.R2)):
            if coef != 0.0:
                ex = coef * np.exp(-rate * big_v)
                e = e + ex * self.v0 / rate
                s = s + ex
        return e, s

    def isentrope_constant(self, through: State) -> float:
        """``K`` (J/kg) of the isentrope through ``through``: ``e' = e'_ref(V) + K V^-omega``."""
        big_v = through.v * self.rho0
        return float((through.e + self.q - self._cold(big_v)[0]) * big_v**self.omega)

    def isentrope(self, through: State, v: float) -> tuple[float, float]:
        if math.isinf(v):
            return 0.0, -self.q
        k = self.isentrope_constant(through)
        big_v = v * self.rho0
        e_ref, s_ref = self._cold(big_v)
        e = float(e_ref + k * big_v**-self.omega) - self.q
        sigma = float(s_ref + self.omega * self.rho0 * k * big_v ** -(1.0 + self.omega))
        return sigma, e

    def riemann_integral(self, through: State, v: float, start: float | None = None) -> float:
        start = through.v if start is None else start
        if start == v:
            return 0.0
        k = self.isentrope_constant(through)
        if self.is_gamma_law:
            # C_L = sqrt(v0 (1 + omega) omega rho0 K) V^-(1 + omega/2): J in closed form
            scale = math.sqrt(self.v0 * (1.0 + self.omega) * self.omega * self.rho0 * k)
            return scale * 2.0 / self.omega * (self.y(start) - self.y(v))
        table = self.isentrope_table(k)
        return table.phi(self.y(start)) - table.phi(self.y(v))

    @functools.lru_cache(maxsize=256)  # noqa: B019 -- a material lives as long as its runs
    def isentrope_table(self, k: float) -> ProductsIsentropeTable:
        """The Chebyshev table of the stress function on the isentrope ``K = k`` (J/kg)."""
        return ProductsIsentropeTable(self, k)

    def y(self, v: float) -> float:
        """``y = V^(-omega/2)``: 0 at vacuum."""
        return 0.0 if math.isinf(v) else (v * self.rho0) ** (-0.5 * self.omega)

    def __repr__(self) -> str:
        return f"Products({self.name!r})"
