"""Riemann invariants on an isentrope of detonation products (JWL or gamma law).

The products' isentropes are closed forms in ``y = V^(-omega/2)`` (``materials.products``):

    sigma(y) = A exp(-R1 V) + B exp(-R2 V) + omega rho0 K y^(2 (1 + omega)/omega),
    e(y)     = (A v0/R1) exp(-R1 V) + (B v0/R2) exp(-R2 V) + K y^2 - q,

and the stress function ``phi = Phi(y) - Phi(y*)`` (``characteristics.isentrope``) comes
from the products' Chebyshev table of ``Phi`` (``materials.products_isentrope``), zero at
the labelling state ``*`` and ``-Phi(y*)`` at vacuum (``y = 0``, ``v = inf``, ``sigma =
0``, ``e = -q``, ``C_L = 0``).  ``y(sigma)`` is a safeguarded Newton inversion of the
closed form (``sigma`` increases with ``y``: ``d sigma/dy = (2/omega) rho0 C_L^2
V^(1 + omega/2)``).  States are marked as products (``materials.explosive.burnt``).

The engine discretises a products fan with this table (``outgoing``), so its
characteristics sit at equal steps of stress *and* of velocity: towards vacuum the last
steps of stress carry most of the velocity, and steps of stress alone would give the
last cell a state far from its neighbours (the balance then creates energy).
"""

from __future__ import annotations

import bisect
import math

import numpy as np

from materials import State, StateOutOfRangeError
from materials.explosive import ProductsCurve, burnt
from materials.products import Products

from .isentrope import LABEL_TOLERANCE, Isentrope

INVERSION_STEPS = 60
"""Safeguarded Newton steps of ``y(sigma)`` at most (bisection where Newton leaves the
bracket; from the sampled bracket, four or five in practice)."""

SAMPLE_STEP = 0.01
"""Step in ``y`` of the stress samples that bracket ``y(sigma)``."""


class ProductsIsentrope(Isentrope):
    """The isentrope of ``products`` through ``through`` (see the module docstring)."""

    def __init__(self, products: Products, through: State):
        self.material = products
        self.through = burnt(through)
        self.k = products.isentrope_constant(through)
        self.phi_table = products.isentrope_table(self.k)
        self._y_star = products.y(through.v)
        self._phi_star = self.phi_table.phi(self._y_star)
        self._sample(1.25 * self._y_star)

    # --- closed forms in y ----------------------------------------------------------
    def _point(self, y):
        """``(sigma, v, e, C_L)`` at ``y`` (arrays; vacuum at ``y = 0``)."""
        p = self.material
        y = np.asarray(y, dtype=float)
        inside = y > 0.0
        big_v = np.where(inside, y, 1.0) ** (-2.0 / p.omega)
        e_ref, s_ref = p._cold(big_v)
        sigma = s_ref + p.omega * p.rho0 * self.k * big_v ** -(1.0 + p.omega)
        e = e_ref + self.k * big_v**-p.omega - p.q
        c2 = p.v0 * (p.A * p.R1 * np.exp(-p.R1 * big_v) + p.B * p.R2 * np.exp(-p.R2 * big_v)
                     ) + p.v0 * (1.0 + p.omega) * p.omega * p.rho0 * self.k * big_v ** -(
                         2.0 + p.omega)
        return (np.where(inside, sigma, 0.0), np.where(inside, p.v0 * big_v, math.inf),
                np.where(inside, e, -p.q), np.where(inside, np.sqrt(np.maximum(c2, 0.0)), 0.0))

    def _stress_and_slope(self, y: float) -> tuple[float, float]:
        """``(sigma, d sigma/dy)`` at ``y > 0`` (floats)."""
        p = self.material
        big_v = y ** (-2.0 / p.omega)
        ex1, ex2 = p.A * math.exp(-p.R1 * big_v), p.B * math.exp(-p.R2 * big_v)
        gas = p.omega * p.rho0 * self.k * big_v ** -(1.0 + p.omega)
        # d sigma/dV = -(R1 ex1 + R2 ex2) - (1 + omega) gas / V; dV/dy = -(2/omega) V / y
        slope = (p.R1 * ex1 + p.R2 * ex2 + (1.0 + p.omega) * gas / big_v) * 2.0 / p.omega \
            * big_v / y
        return ex1 + ex2 + gas, slope

    def _y_at_stress(self, sigma: float) -> float:
        """``y`` where the isentrope's stress is ``sigma >= 0`` (Pa)."""
        if sigma < 0.0:
            raise StateOutOfRangeError(f"{self.material.name}: detonation products carry no "
                                       f"tension ({sigma / 1e9:.6g} GPa asked)")
        if sigma == 0.0:
            return 0.0
        while sigma > self._sigma_samples[-1]:
            self._sample(2.0 * self._y_samples[-1])
        i = bisect.bisect_left(self._sigma_samples, sigma)
        lo, hi = self._y_samples[i - 1], self._y_samples[i]
        s_lo, s_hi = self._sigma_samples[i - 1], self._sigma_samples[i]
        y = lo + (hi - lo) * (sigma - s_lo) / (s_hi - s_lo)
        for _ in range(INVERSION_STEPS):
            s, slope = self._stress_and_slope(y)
            lo, hi = (lo, y) if s > sigma else (y, hi)
            new = y - (s - sigma) / slope
            if not lo <= new <= hi:
                new = 0.5 * (lo + hi)
            if abs(new - y) <= 1e-15 * y:
                return new
            y = new
        return y

    def _sample(self, top: float) -> None:
        """Stresses at ``SAMPLE_STEP`` steps of ``y`` up to ``top``: the brackets of
        ``_y_at_stress``."""
        y = np.arange(1, math.ceil(top / SAMPLE_STEP) + 1) * SAMPLE_STEP
        self._y_samples = [0.0, *y.tolist()]
        self._sigma_samples = [0.0, *self._point(y)[0].tolist()]

    # --- the Isentrope interface ------------------------------------------------------
    def phi_at_stress(self, sigma: float) -> float:
        if sigma == self.through.sigma:
            return 0.0
        return self.phi_table.phi(self._y_at_stress(float(sigma))) - self._phi_star

    def volume_at_phi(self, phi: float) -> float:
        y = self.phi_table.y_at_phi(float(phi + self._phi_star))
        return self.material.v0 * y ** (-2.0 / self.material.omega) if y > 0.0 else math.inf

    def arrays_at_phi(self, phi: np.ndarray) -> tuple[np.ndarray, ...]:
        return self._point(self.phi_table.y_at_phi(np.asarray(phi, dtype=float)
                                                   + self._phi_star))

    def arrays_at_stress(self, sigma: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        sigma = np.asarray(sigma, dtype=float)
        y = np.reshape([self._y_at_stress(s) for s in sigma.ravel().tolist()], sigma.shape)
        return self.phi_table.phi(y) - self._phi_star, self._point(y)[3]

    def point_at_volume(self, v: float) -> tuple[float, float, float]:
        sigma, e = self.material.isentrope(self.through, v)
        return sigma, e, self.material.sound_speed(v, e)

    def stress_gap(self, state: State) -> float:
        return abs(self.point_at_volume(state.v)[0] - state.sigma)

    def rounding(self, state: State) -> float:
        return LABEL_TOLERANCE * abs(state.sigma)

    def state(self, j_plus: float, j_minus: float) -> State:
        return burnt(super().state(j_plus, j_minus))

    def state_at_stress(self, sigma: float, j: float, direction: int) -> State:
        return burnt(super().state_at_stress(sigma, j, direction))


def fan_table(fan) -> ProductsIsentrope | None:
    """The table of a products fan's isentrope (through its state ahead), or ``None`` for
    a fan of another material."""
    if not isinstance(fan.curve, ProductsCurve) or not math.isfinite(fan.ahead.v):
        return None
    return ProductsIsentrope(fan.curve.material, fan.ahead)
