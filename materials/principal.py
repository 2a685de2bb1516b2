"""The principal Hugoniot of a linear Us–up solid in closed form.

A Mie–Grüneisen solid (``materials.mie_gruneisen``) at its reference state
(``v = v0``, ``e = 0``, ``sigma = 0``) is shocked along its principal Hugoniot,
on which, by construction of the model,

    Us = c0 + s up,      sigma = rho0 Us up,      v = v0 (1 - up / Us),      e = up^2 / 2.

For a wave curve centred on that state, ``g(sigma) = sqrt(sigma (v0 - v)) = up``,
so the compressive branch needs no root in volume: ``up`` is the positive root
of ``s up^2 + c0 up - sigma / rho0 = 0``, written without cancellation as

    up = 2 q / (c0 + R),   R = sqrt(c0^2 + 4 s q),   q = sigma / rho0,

and ``dg/dsigma = 1 / (rho0 R)`` because ``R = c0 + 2 s up``.  The shock speed is
``Us`` itself, not a chord quotient of two rounded jumps.  Release from the
reference state (tension) follows the generic curve.

Every impact of a plate at rest (and of a flyer, whose reference state merely
moves) starts here, so the two wave curves of an impact cost no inner root.
"""

from __future__ import annotations

import math

from .state import State
from .wavecurves import HydrodynamicWaveCurve
from .waves import Shock


class PrincipalHugoniotCurve(HydrodynamicWaveCurve):
    """Wave curve of a ``MieGruneisen`` solid centred on its reference state.

    Compression is the closed-form principal Hugoniot of the module docstring;
    everything else (release, the stress range) is ``HydrodynamicWaveCurve``.
    """

    def __init__(self, material, ahead: State, direction: int, release: str = "isentrope"):
        super().__init__(material, ahead, direction, release)
        self._v_limit = material.hugoniot_volume_limit(ahead)
        self._last_shock: tuple | None = None

    def _shock(self, sigma: float) -> tuple[float, float, float, float]:
        """``(up, Us, R, v)`` of the principal shock to ``sigma`` > 0 (SI)."""
        if self._last_shock is not None and self._last_shock[0] == sigma:
            return self._last_shock[1]
        mat = self.material
        q = sigma / mat.rho0
        root = math.sqrt(mat.c0 * mat.c0 + 4.0 * mat.s * q)
        up = 2.0 * q / (mat.c0 + root)
        speed = mat.c0 + mat.s * up
        v = mat.v0 * (1.0 - up / speed)
        if v < self._v_limit:
            # beyond the equation of state (the error names the range), or at its edge
            # within rounding: the volume is the edge's
            self.check_stress(sigma)
            v = self._v_limit
        self._last_shock = (sigma, (up, speed, root, v))
        return self._last_shock[1]

    def velocity_change(self, sigma: float) -> tuple[float, float]:
        """``(g, dg/dsigma) = (up, 1 / (rho0 R))`` in compression; the generic curve below."""
        if sigma <= self.ahead.sigma:
            return super().velocity_change(sigma)
        up, _, root, _ = self._shock(sigma)
        return up, 1.0 / (self.material.rho0 * root)

    def _state_at(self, sigma: float) -> State:
        if sigma <= self.ahead.sigma:
            return super()._state_at(sigma)
        up, _, _, v = self._shock(sigma)
        a = self.ahead
        return State(sigma=float(sigma), u=a.u + self.direction * up, v=v, e=0.5 * up * up)

    def waves(self, sigma: float) -> tuple:
        """The principal shock at ``direction * Us`` in compression; the generic curve below."""
        if sigma <= self.ahead.sigma:
            return super().waves(sigma)
        speed = self._shock(sigma)[1]
        return (Shock(ahead=self.ahead, behind=self.state_at(sigma),
                      speed=self.direction * speed, direction=self.direction),)
