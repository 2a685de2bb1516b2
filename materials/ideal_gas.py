"""Ideal (gamma-law) gas, in Lagrangian form: the validation material.

    p = sigma = (gamma - 1) e / v,    c^2 = gamma p v,    C_L = (v0 / v) c.

The Lagrangian coordinate is mass: ``rho0`` is the density a unit of ``X`` had
in the reference configuration (for a shock tube, each layer's initial density).
Isentrope: ``p v^gamma`` constant, ``e = e* (v*/v)^(gamma - 1)`` and the
Riemann-invariant integral is ``int rho0 C_L dv = -2 (c - c*) / (gamma - 1)``,
which is the classical ``u ± 2c/(gamma - 1)`` invariant.  The Hugoniot centred on
``a`` is bounded by the limiting compression ``v >= v_a (gamma - 1)/(gamma + 1)``.
A gas carries no tension; it expands to vacuum (``sigma = 0``, ``v = inf``).
"""

from __future__ import annotations

import math

import numpy as np

from .base import AffineEnergyMaterial, require_number, require_positive
from .errors import MaterialError, StateOutOfRangeError
from .state import State


class IdealGas(AffineEnergyMaterial):
    """Gamma-law gas: ``gamma`` (> 1), reference density ``rho0`` (kg/m^3), optional ``cv``."""

    relative_stress_precision = True
    """The isentrope ``p = p_a (v_a / v)^gamma`` is closed-form, good to a few ulps of p
    itself however far it expands (wave curves then resolve near-vacuum releases)."""

    gaseous = True
    """A gas: its stress vanishes with its energy (``Material.gaseous``)."""

    unbounded_hugoniot = True
    """The Hugoniot reaches any pressure at its limiting compression (wave curves then
    shock a cold gas to that compression: the snowplow)."""

    def __init__(self, name: str, gamma: float, rho0: float, cv: float | None = None):
        self.name = name
        gamma = require_number("gamma", gamma, name)
        if not 1.0 < gamma < 100.0:
            raise MaterialError(f"{name}: gamma must be in (1, 100), got {gamma!r}")
        self.gamma = gamma
        self.rho0 = require_positive("rho0", rho0, name)
        self.cv = None if cv is None else require_positive("cv", cv, name)
        self.spall_strength = 0.0

    def state_from_pressure(self, rho: float, p: float, u: float = 0.0) -> State:
        """State of density ``rho`` (kg/m^3) and pressure ``p`` (Pa) moving at ``u``."""
        rho = require_positive("rho", rho, self.name)
        if not p >= 0.0:
            raise MaterialError(f"{self.name}: pressure must be >= 0 Pa, got {p!r}")
        v = 1.0 / rho
        return State(sigma=float(p), u=float(u), v=v, e=p * v / (self.gamma - 1.0))

    def initial_state(self, stress: float = 0.0, u: float = 0.0,
                      density: float | None = None) -> State:
        """A gas layer at pressure ``stress`` (Pa) and ``density`` (kg/m^3, default
        ``rho0``) moving at ``u`` (m/s): a gas is given its state, not loaded into it.

        A gas at zero pressure has no sound speed (no wave can cross it in finite time),
        so the pressure must be positive.
        """
        if not stress > 0.0:
            raise StateOutOfRangeError(
                f"{self.name}: a gas layer needs an initial pressure > 0 Pa (a gas at zero "
                f"pressure has no sound speed), got {stress!r} Pa; set the layer's "
                '"pressure" (e.g. "101.325 kPa") or, with cv, its "temperature"')
        return self.state_from_pressure(self.rho0 if density is None else density, stress, u)

    def pressure_at(self, density: float, temperature: float) -> float:
        """Pressure (Pa) at ``density`` (kg/m^3) and ``temperature`` (K):
        ``p = (gamma - 1) rho cv T``."""
        if self.cv is None:
            raise MaterialError(f"{self.name}: a temperature needs the gas's cv (J/(kg K))")
        temperature = require_positive("temperature", temperature, self.name)
        return (self.gamma - 1.0) * density * self.cv * temperature

    def volume_range(self) -> tuple[float, float]:
        return (0.0, math.inf)

    def _a(self, v):
        return 0.0

    def _a_prime(self, v):
        return 0.0

    def _b(self, v):
        return (self.gamma - 1.0) / v

    def _b_prime(self, v):
        return -(self.gamma - 1.0) / (v * v)

    def eulerian_sound_speed(self, v: float, e: float) -> float:
        """Eulerian sound speed ``c = sqrt(gamma p v)`` (m/s)."""
        return math.sqrt(max(self.gamma * (self.gamma - 1.0) * e, 0.0))

    def sound_speed(self, v: float, e: float) -> float:
        if math.isinf(v):
            return 0.0
        return self.v0 / v * self.eulerian_sound_speed(v, e)

    def temperature(self, v: float, e: float) -> float | None:
        return None if self.cv is None else e / self.cv

    def hugoniot_volume_limit(self, ahead: State) -> float:
        return ahead.v * (self.gamma - 1.0) / (self.gamma + 1.0) * (1.0 + 1e-12)

    def isentrope(self, through: State, v: float) -> tuple[float, float]:
        if math.isinf(v):
            return 0.0, 0.0
        e = through.e * (through.v / v) ** (self.gamma - 1.0)
        return (self.gamma - 1.0) * e / v, e

    def isentrope_arrays(self, through: State, v):
        """``(sigma, e, C_L^2)`` on the isentrope ``p v^gamma = const`` at the volumes ``v``."""
        v = np.asarray(v, dtype=float)
        e = through.e * (through.v / v) ** (self.gamma - 1.0)
        sigma = (self.gamma - 1.0) * e / v
        return sigma, e, (self.v0 / v) ** 2 * self.gamma * (self.gamma - 1.0) * e

    def riemann_integral(self, through: State, v: float, start: float | None = None) -> float:
        start = through.v if start is None else start
        return 2.0 * (self._sound_on(through, start) - self._sound_on(through, v)) / (
            self.gamma - 1.0)

    def _sound_on(self, through: State, v: float) -> float:
        """Eulerian sound speed (m/s) at volume ``v`` on the isentrope through ``through``."""
        if math.isinf(v):
            return 0.0
        if v == through.v:
            return self.eulerian_sound_speed(through.v, through.e)
        return self.eulerian_sound_speed(v, self.isentrope(through, v)[1])
