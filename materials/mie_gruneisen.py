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

import numpy as np

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


class ExpandedMieGruneisen(MieGruneisen):
    """A Mie–Grüneisen solid whose states may expand far beyond ``v0``: the matrix of a
    porous body, compacted hot.

    In compression (``v <= v0``) it is ``MieGruneisen``.  In expansion the linear Us–up
    fit's extrapolated Hugoniot has a spinodal at ``eps = -1/s``, beyond which it has no
    meaning; the reference curve there is instead the hydrocodes' linear form
    (Autodyn's and LS-DYNA's Grüneisen law for ``mu = v0/v - 1 < 0``),

        A(v) = rho0 c0^2 (v0/v - 1),    sigma = A(v) + rho0 Gamma0 e,

    which joins ``MieGruneisen``'s ``A`` with its slope at ``v0``, decreases
    monotonically to ``-rho0 c0^2`` (the cold matrix's tension never turns back), and
    gives a real sound speed, ``C_L^2 = v0^2 (rho0 Gamma0 sigma + rho0 c0^2 v0/v^2)``, to
    every state whose thermal pressure carries its stress (``sigma >= 0``).  Those are
    the hot compacted states of a highly porous body: its Hugoniot is anomalous, the
    shock heating holding the matrix at ``v > v0`` (Davison §11.2).  In tension an
    isentrope ends at its spinodal, ``rho0 Gamma0 sigma = -rho0 c0^2 v0 / v^2``
    (``C_L = 0``): the most tension the matrix carries on it.

    ``max_expansion``: the largest ``v/v0`` the model is asked for (the end of its volume
    range, at least ``MieGruneisen``'s; isentrope tables are built up to it).
    """

    def __init__(self, name: str, rho0: float, c0: float, s: float, gamma0: float,
                 max_expansion: float, **kwargs):
        super().__init__(name, rho0, c0, s, gamma0, **kwargs)
        max_expansion = require_positive("max_expansion", max_expansion, name)
        if not math.isfinite(max_expansion):
            raise MaterialError(f"{name}: max_expansion (largest v/v0) must be finite, "
                                f"got {max_expansion!r}")
        self.max_expansion = max(max_expansion, 1.0 + self.TENSION_LIMIT / self.s)

    def volume_range(self) -> tuple[float, float]:
        """``MieGruneisen``'s compressed end; in expansion ``max_expansion`` ``v0``, or
        ``MieGruneisen``'s own end if that is further."""
        return (super().volume_range()[0], self.v0 * self.max_expansion)

    def _a(self, v):
        if isinstance(v, float):
            return self._expanded_a(v) if v > self.v0 else super()._a(v)
        v = np.asarray(v, dtype=float)
        return np.where(v > self.v0, self._expanded_a(v), super()._a(np.minimum(v, self.v0)))

    def _a_prime(self, v):
        if isinstance(v, float):
            return self._expanded_a_prime(v) if v > self.v0 else super()._a_prime(v)
        v = np.asarray(v, dtype=float)
        return np.where(v > self.v0, self._expanded_a_prime(v),
                        super()._a_prime(np.minimum(v, self.v0)))

    def _expanded_a(self, v):
        """The reference curve in expansion, ``rho0 c0^2 (v0/v - 1) = rho0 c0^2 eps /
        (1 - eps)`` (Pa), written in ``eps`` as ``MieGruneisen``'s is, so that the two
        round alike at ``v0``."""
        eps = 1.0 - v / self.v0
        return self.rho0 * self.c0**2 * eps / (1.0 - eps)

    def _expanded_a_prime(self, v):
        """Its slope, ``-rho0 c0^2 v0 / v^2`` (Pa kg/m^3)."""
        return -self.rho0 * self.c0**2 * self.v0 / (v * v)

    def sound_speed_squared(self, v, e):
        """As ``AffineEnergyMaterial.sound_speed_squared`` (``MieGruneisen``'s inlined form
        holds in compression only)."""
        if isinstance(v, float) and v <= self.v0:
            return super().sound_speed_squared(v, e)
        return AffineEnergyMaterial.sound_speed_squared(self, v, e)

    def riemann_integral(self, through, v: float, start: float | None = None) -> float:
        """As ``AffineEnergyMaterial.riemann_integral``, split at ``v0``, where the
        reference curve's curvature jumps (each piece's quadrature is then exact)."""
        start = through.v if start is None else start
        if (start - self.v0) * (v - self.v0) < 0.0:
            return (super().riemann_integral(through, self.v0, start)
                    + super().riemann_integral(through, v, self.v0))
        return super().riemann_integral(through, v, start)
