"""The thermodynamic and kinematic state of a material point.

Conventions (see PHYSICS.md): ``sigma`` is the longitudinal stress, positive in
compression (Pa); ``u`` the particle velocity, positive toward +X (m/s); ``v``
the specific volume (m^3/kg); ``e`` the specific internal energy (J/kg), zero
in the unstressed reference state.  ``plastic_strain`` is the accumulated
uniaxial plastic strain of elastic–plastic solids (compression positive) and
stays zero for the other models.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

from .frozen import slot_init

RIGHT = +1
"""Direction of a right-going wave (Lagrangian speed U > 0)."""
LEFT = -1
"""Direction of a left-going wave (U < 0)."""


@slot_init
@dataclass(frozen=True, slots=True)
class State:
    """A uniform state: stress (Pa), particle velocity (m/s), volume (m^3/kg), energy (J/kg)."""

    sigma: float
    u: float
    v: float
    e: float
    plastic_strain: float = 0.0

    @property
    def rho(self) -> float:
        """Density (kg/m^3)."""
        return 1.0 / self.v

    def moving(self, u: float) -> State:
        """The same thermodynamic state carried at particle velocity ``u``."""
        return replace(self, u=u)
