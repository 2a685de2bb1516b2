"""Linear elastic (acoustic) solid in uniaxial strain.

    sigma = rho0 C^2 eps,    eps = 1 - v/v0,    C^2 = (lambda + 2 mu) / rho0.

Stress does not depend on energy, so the Hugoniot, the isentrope and the
release path coincide: every wave is a discontinuity at the constant Lagrangian
speed ``C`` and the wave curves are straight lines of slope ``±rho0 C`` (the
impedance ``Z``).  At an interface a wave reflects with ``R = (Z2 - Z1)/(Z2 + Z1)``.
Energy still obeys the jump condition; for this linear law the Rankine–Hugoniot
trapezoid is exactly the isentropic work, so release conserves it too.
"""

from __future__ import annotations

import math

from .base import AffineEnergyMaterial, require_number, require_positive
from .errors import MaterialError
from .state import State


class LinearElastic(AffineEnergyMaterial):
    """Acoustic solid: ``rho0`` (kg/m^3) and longitudinal speed ``C`` (m/s)."""

    is_linear = True
    makes_fans = False

    def __init__(self, name: str, rho0: float, C: float, spall_strength: float = math.inf):
        self.name = name
        self.rho0 = require_positive("rho0", rho0, name)
        self.C = require_positive("C", C, name)
        self.spall_strength = _strength(name, spall_strength)

    @classmethod
    def from_lame(cls, name: str, rho0: float, lam: float, mu: float,
                  spall_strength: float = math.inf) -> LinearElastic:
        """From the Lamé constants ``lambda``, ``mu`` (Pa): ``C^2 = (lambda + 2 mu)/rho0``."""
        modulus = require_number("lambda", lam, name) + 2.0 * require_number("mu", mu, name)
        if not (modulus > 0.0 and math.isfinite(modulus)):
            raise MaterialError(f"{name}: lambda + 2 mu must be > 0, got {modulus:.6g} Pa")
        rho0 = require_positive("rho0", rho0, name)
        return cls(name, rho0, math.sqrt(modulus / rho0), spall_strength)

    @property
    def impedance(self) -> float:
        """Acoustic impedance ``Z = rho0 C`` (kg/(m^2 s))."""
        return self.rho0 * self.C

    def volume_range(self) -> tuple[float, float]:
        # The law has no spinodal and carries any tension, but the upper bound must be
        # finite: the wave curves read an infinite one as a gas expanding to vacuum
        # (sigma = 0 at v = inf).  1e3 v0 is a tension of ~1e3 rho0 C^2, beyond any solid.
        return (1e-9 * self.v0, 1e3 * self.v0)

    def _a(self, v):
        return self.rho0 * self.C**2 * (1.0 - v / self.v0)

    def _a_prime(self, v):
        return -self.rho0 * self.C**2 / self.v0

    def _b(self, v):
        return 0.0

    def _b_prime(self, v):
        return 0.0

    def sound_speed(self, v: float, e: float) -> float:
        return self.C

    def isentrope(self, through: State, v: float) -> tuple[float, float]:
        sigma = float(self._a(v))
        return sigma, through.e + 0.5 * (through.sigma + sigma) * (through.v - v)

    def riemann_integral(self, through: State, v: float, start: float | None = None) -> float:
        return self.rho0 * self.C * (v - (through.v if start is None else start))


def _strength(name: str, value: float) -> float:
    strength = require_number("spall_strength", value, name)
    if not strength > 0.0:
        raise MaterialError(f"{name}: spall_strength must be > 0 Pa (or inf), got {value!r}")
    return strength
