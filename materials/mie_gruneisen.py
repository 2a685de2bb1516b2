"""Mie–Grüneisen solid on a linear Us–up reference Hugoniot.

Principal Hugoniot (from rest, unstressed), with ``eps = 1 - v/v0``:

    Us = c0 + s up,   sigma_H(v) = rho0 c0^2 eps / (1 - s eps)^2,   e_H = 1/2 sigma_H (v0 - v).

Mie–Grüneisen form with ``Gamma / v = Gamma0 / v0`` (so ``B = rho0 Gamma0``):

    sigma(v, e) = sigma_H(v) + rho0 Gamma0 (e - e_H(v)) = A(v) + B e,
    A(v) = sigma_H(v) (1 - Gamma0 eps / 2).

Temperature with a constant ``cv``: along an isentrope ``T = T* exp(Gamma0 (eps - eps*))``
(because ``dT/T = -(Gamma/v) dv``), and off the reference isentrope ``s0`` (through
``v0``, ``e = 0``, ``T0 = 298.15 K``) the energy is ``cv (T - T_s0(v))`` above it:

    T(v, e) = T0 exp(Gamma0 eps) + (e - e_s0(v)) / cv.

Range of validity: ``eps`` below ``0.95 / s`` (the fit is singular at ``1/s``) and
above ``-0.3 / s`` in tension (the spinodal of the extrapolated Hugoniot is at
``-1/s``).  ``up_max`` records the top of the fitted data; states beyond it are
allowed but flagged by ``beyond_fit``.
"""

from __future__ import annotations

import math
from functools import lru_cache

from .base import ROOM_TEMPERATURE, AffineEnergyMaterial, require_number, require_positive
from .errors import MaterialError
from .linear_elastic import _strength
from .principal import PrincipalHugoniotCurve

MIN_SLOPE, MAX_SLOPE = 0.1, 10.0
"""Range of the Hugoniot slope ``s``: fits of real solids lie within 0.5 to 3; below 0.1
the tension limit ``v0 (1 + 0.3 / s)`` leaves any table of the isentropes unbounded."""


class MieGruneisen(AffineEnergyMaterial):
    """Mie–Grüneisen solid: rho0 (kg/m^3), c0 (m/s), s, gamma0, optional cv (J/(kg K))."""

    COMPRESSION_LIMIT = 0.95
    TENSION_LIMIT = 0.3

    def __init__(self, name: str, rho0: float, c0: float, s: float, gamma0: float,
                 cv: float | None = None, spall_strength: float = math.inf,
                 up_max: float | None = None):
        self.name = name
        self.rho0 = require_positive("rho0", rho0, name)
        self.c0 = require_positive("c0", c0, name)
        self.s = require_positive("s", s, name)
        if not MIN_SLOPE <= self.s <= MAX_SLOPE:
            raise MaterialError(f"{name}: s must be in [{MIN_SLOPE}, {MAX_SLOPE}] (the slope "
                                f"dUs/dup of the Hugoniot fit), got {s!r}")
        gamma0 = require_number("gamma0", gamma0, name)
        if not 0.0 <= gamma0 < 10.0:
            raise MaterialError(f"{name}: gamma0 must be in [0, 10), got {gamma0!r}")
        self.gamma0 = gamma0
        self.cv = None if cv is None else require_positive("cv", cv, name)
        self.spall_strength = _strength(name, spall_strength)
        self.up_max = None if up_max is None else require_positive("up_max", up_max, name)
        eps_max = self.COMPRESSION_LIMIT / self.s
        if self.gamma0 * eps_max >= 2.0:
            # The Hugoniot energy denominator 1 - Gamma0 eps / 2 must stay positive.
            eps_max = min(eps_max, 0.95 * 2.0 / self.gamma0)
        self._eps_max = eps_max
        self._reference_isentrope = lru_cache(maxsize=4096)(self._reference_isentrope_energy)

    def volume_range(self) -> tuple[float, float]:
        return (self.v0 * (1.0 - self._eps_max), self.v0 * (1.0 + self.TENSION_LIMIT / self.s))

    def hugoniot_volume_limit(self, ahead) -> float:
        # The energy denominator 1 - B (v_a - v) / 2 must stay positive on a reshock Hugoniot.
        singular = ahead.v - 2.0 / (self.rho0 * self.gamma0) if self.gamma0 > 0 else -math.inf
        v_min = self.volume_range()[0]
        return max(v_min, ahead.v - 0.95 * (ahead.v - singular)) if singular > v_min else v_min

    def wave_curve(self, ahead, direction: int, release: str = "isentrope"):
        """As ``Material.wave_curve``; from the reference state, compression is the
        closed-form principal Hugoniot (``materials.principal``)."""
        if ahead.v == self.v0 and ahead.e == 0.0 and ahead.sigma == 0.0:
            return PrincipalHugoniotCurve(self, ahead, direction, release)
        return super().wave_curve(ahead, direction, release)

    def beyond_fit(self, up: float) -> bool:
        """True when a principal-Hugoniot particle velocity exceeds the fitted range."""
        return self.up_max is not None and abs(up) > self.up_max

    # --- sigma = A(v) + B e ----------------------------------------------------
    def _sigma_h(self, v):
        eps = 1.0 - v / self.v0
        return self.rho0 * self.c0**2 * eps / (1.0 - self.s * eps) ** 2

    def _a(self, v):
        eps = 1.0 - v / self.v0
        return self._sigma_h(v) * (1.0 - 0.5 * self.gamma0 * eps)

    def _a_prime(self, v):
        eps = 1.0 - v / self.v0
        k = self.rho0 * self.c0**2
        dsh_deps = k * (1.0 + self.s * eps) / (1.0 - self.s * eps) ** 3
        da_deps = dsh_deps * (1.0 - 0.5 * self.gamma0 * eps) - 0.5 * self.gamma0 * self._sigma_h(v)
        return -da_deps / self.v0

    def sound_speed_squared(self, v, e):
        """As ``AffineEnergyMaterial.sound_speed_squared``, with the same operations
        inlined for a float volume (the isentrope quadratures call it at every node)."""
        if not isinstance(v, float):
            return super().sound_speed_squared(v, e)
        v0, s, half_gamma = self.v0, self.s, 0.5 * self.gamma0
        eps = 1.0 - v / v0
        k = self.rho0 * self.c0**2
        sigma_h = k * eps / (1.0 - s * eps) ** 2
        a = sigma_h * (1.0 - half_gamma * eps)
        dsh_deps = k * (1.0 + s * eps) / (1.0 - s * eps) ** 3
        a_prime = -(dsh_deps * (1.0 - half_gamma * eps) - half_gamma * sigma_h) / v0
        b = self.rho0 * self.gamma0
        slope = a_prime + 0.0 * e - b * (a + b * e)
        return -v0 * v0 * slope

    def _b(self, v):
        return self.rho0 * self.gamma0

    def _b_prime(self, v):
        return 0.0

    # --- temperature -------------------------------------------------------------
    def _reference_isentrope_energy(self, v: float) -> float:
        return self.isentrope(self.reference_state(), v)[1]

    def temperature(self, v: float, e: float) -> float | None:
        """Temperature (K) from the reference isentrope's temperature
        ``T_s(v) = T_room exp(Gamma0 (1 - v/v0))`` and a constant ``cv``:
        ``T = T_s(v) + (e - e_s(v)) / cv``.  ``None`` without ``cv``, and where this
        model gives no positive temperature (far beyond the fitted range, where the
        extrapolated isentrope lies above the state's energy)."""
        if self.cv is None:
            return None
        eps = 1.0 - v / self.v0
        t_s0 = ROOM_TEMPERATURE * math.exp(self.gamma0 * eps)
        temperature = t_s0 + (e - self._reference_isentrope(v)) / self.cv
        return temperature if temperature > 0.0 else None
