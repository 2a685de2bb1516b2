"""Elastic–plastic solid with saturating (Voce) hardening, through the hull construction.

Conventions of PHYSICS.md: stress ``sigma`` positive in compression (Pa),
compression ``eps = 1 - v/v0``, SI units.

The model
---------
The stress is a pressure plus a deviator, as in ``materials.finite_plastic``:

    sigma = p(eps) + S,          p(eps) = K eps / (1 - s eps)^2,   K = rho0 c0^2,
    S = (4/3) G eps - 2 G eps_p,  |S| <= (2/3) Y(eps_bar),

with the pressure on the principal Hugoniot of a linear Us–up fit and no thermal
part (``Gamma0 = 0``): the stress is a function of the strains alone, the energy
is carried by the jump conditions and ``de = -sigma dv``, and the hull
construction of ``materials.hull`` is exact.  The flow stress saturates
(Voce's law):

    Y(eps_bar) = Y_s - (Y_s - Y_0) exp(-eps_bar / eps_s),

``Y_0`` the initial yield strength, ``Y_s >= Y_0`` the saturation strength,
``eps_s > 0`` the saturation strain, ``eps_bar`` the accumulated plastic strain
(``d eps_bar = |d eps_p|``).  On a plastic branch ``d eps_bar = 2G d|eps| /
(3G + Y')`` and ``dsigma/deps = p'(eps) + (4/3) G Y' / (3G + Y')``: the hardening
term is largest at yield and fades as ``Y`` saturates, so the plastic branch is
*concave* just beyond the yield point (when ``(4/3) G Y'/(3G + Y')`` falls faster
than ``p'`` rises) and convex further on, where the pressure's convexity wins.

Waves (``materials.hull.HullWaveCurve``)
-----------------------------------------
A compression from the virgin state follows the upper concave hull of the path:
an elastic precursor shock to the Hugoniot elastic limit, then along the concave
stretch a plastic *fan*, then a plastic shock from the point where the chord to
the final state is tangent to the path (shock–fan–shock); a weak load reaches
only the fan, a strong one a single plastic shock from the HEL (or one
overdriven shock).  Release follows the lower convex hull: elastic unloading
(convex: a fan) to reverse yield at ``S = -(2/3) Y``, then reverse plastic flow,
whose hardening fades as ``eps_bar`` grows (convex again: a fan).  Dissipation
``v0 Y d eps_bar`` along plastic paths and the excess of every chord over the
path (``dissipated_energy``) never decrease.

Numbers: the model takes any ``Y_0``, ``Y_s``, ``eps_s``; the tests and the
gallery use illustrative values (stated where they are used), not a fit to a metal.
"""

from __future__ import annotations

import math

import numpy as np

from .base import Material, require_number, require_positive
from .errors import MaterialError, StateOutOfRangeError
from .finite_plastic import HardenedState
from .hull import HullWaveCurve, StrainPath

_COMPRESSION_LIMIT = 0.9
"""Largest compression, as a fraction of ``1/s`` (the pressure's pole)."""
_TENSION_LIMIT = 0.3
"""Largest tension, ``eps > -0.3 / s`` (as ``MieGruneisen``)."""
_ELASTIC_SAMPLES = 32
_PLASTIC_SAMPLES = 512
"""Samples of the elastic and plastic parts of a path; the plastic ones are
quadratically graded toward the yield point, where the path bends most."""
_NEWTON_STEPS = 60
_SNAP = 1e-12
"""A deviator within this fraction of its scale of the yield surface is on it."""


class SaturatingPlastic(Material):
    """Elastic–plastic solid with Voce hardening on a ``Gamma0 = 0`` Us–up pressure.

    ``rho0`` (kg/m^3), ``c0`` (m/s), ``s``: the pressure's linear Us–up fit;
    ``shear_modulus`` G (Pa); ``yield_strength`` Y_0 (Pa, >= 0);
    ``saturation_strength`` Y_s (Pa, >= Y_0); ``saturation_strain`` eps_s (> 0);
    ``spall_strength`` (Pa).  Derived: ``hel`` (Pa), ``C_elastic`` (m/s).
    """

    is_linear = False
    makes_fans = True
    splits_waves = True

    def __init__(self, name: str, rho0: float, c0: float, s: float, shear_modulus: float,
                 yield_strength: float, saturation_strength: float, saturation_strain: float,
                 spall_strength: float = math.inf):
        self.name = name
        self.rho0 = require_positive("rho0", rho0, name)
        self.c0 = require_positive("c0", c0, name)
        self.s = require_positive("s", s, name)
        self.shear_modulus = require_positive("shear_modulus", shear_modulus, name)
        y0 = require_number("yield_strength", yield_strength, name)
        if not (0.0 <= y0 < math.inf):
            raise MaterialError(f"{name}: yield_strength must be finite and >= 0 Pa, "
                                f"got {yield_strength!r}")
        ys = require_number("saturation_strength", saturation_strength, name)
        if not (y0 <= ys < math.inf):
            raise MaterialError(f"{name}: saturation_strength must be finite and >= "
                                f"yield_strength ({y0:.6g} Pa), got {saturation_strength!r}")
        self.yield_strength, self.saturation_strength = y0, ys
        self.saturation_strain = require_positive("saturation_strain", saturation_strain, name)
        spall = require_number("spall_strength", spall_strength, name)
        if not spall > 0.0:
            raise MaterialError(f"{name}: spall_strength must be > 0 Pa (or inf), "
                                f"got {spall_strength!r}")
        self.spall_strength = spall
        self.bulk_modulus = self.rho0 * self.c0**2
        self.C_elastic = math.sqrt((self.bulk_modulus + 4.0 * self.shear_modulus / 3.0)
                                   / self.rho0)
        self.hel_strain = y0 / (2.0 * self.shear_modulus)
        self.hel = float(self.pressure(self.hel_strain)) + 2.0 * y0 / 3.0

    # --- the law ---------------------------------------------------------------------
    def strain(self, v) -> float:
        """Compression ``eps = 1 - v/v0``."""
        return 1.0 - v / self.v0

    def pressure(self, eps):
        """``p = K eps / (1 - s eps)^2`` (Pa; floats or arrays)."""
        return self.bulk_modulus * eps / (1.0 - self.s * eps) ** 2

    def pressure_slope(self, eps):
        """``p'(eps) = K (1 + s eps) / (1 - s eps)^3`` (Pa)."""
        x = self.s * eps
        return self.bulk_modulus * (1.0 + x) / (1.0 - x) ** 3

    def pressure_work(self, eps: float) -> float:
        """``int_0^eps p d eps = (K/s^2) [ln(1 - s eps) + 1/(1 - s eps) - 1]`` (Pa)."""
        x = self.s * eps
        return self.bulk_modulus / self.s**2 * (math.log1p(-x) + x / (1.0 - x))

    def flow_stress(self, accumulated):
        """Voce's law ``Y = Y_s - (Y_s - Y_0) exp(-eps_bar/eps_s)`` (Pa)."""
        return self.saturation_strength - (self.saturation_strength - self.yield_strength) \
            * np.exp(-np.asarray(accumulated) / self.saturation_strain)

    def hardening_rate(self, accumulated):
        """``Y' = dY/d eps_bar = (Y_s - Y_0)/eps_s exp(-eps_bar/eps_s)`` (Pa)."""
        return (self.saturation_strength - self.yield_strength) / self.saturation_strain \
            * np.exp(-np.asarray(accumulated) / self.saturation_strain)

    def accumulated_plastic_strain(self, state) -> float:
        """``eps_bar`` (``HardenedState``), else ``|plastic_strain|``."""
        return float(getattr(state, "equivalent_plastic_strain", abs(state.plastic_strain)))

    def deviator(self, state) -> float:
        """``S = (4/3) G eps - 2 G eps_p`` (Pa)."""
        g = self.shear_modulus
        return 4.0 * g * self.strain(state.v) / 3.0 - 2.0 * g * state.plastic_strain

    def dissipated_energy(self, state) -> float:
        """Plastic work and shock heating (J/kg): ``e - v0 [int_0^eps p d eps + (3/8) S^2/G]``."""
        s = self.deviator(state)
        stored = self.v0 * (self.pressure_work(self.strain(state.v))
                            + 0.375 * s * s / self.shear_modulus)
        return state.e - stored

    # --- paths for the hull ----------------------------------------------------------
    def _start(self, ahead):
        eps = self.strain(ahead.v)
        bar = self.accumulated_plastic_strain(ahead)
        return eps, ahead.plastic_strain, bar, self.deviator(ahead), float(self.flow_stress(bar))

    def _knee(self, ahead, sign: float) -> float:
        """Compression where the elastic path from ``ahead`` meets the yield surface."""
        eps, _, _, dev, y = self._start(ahead)
        room = 2.0 * y / 3.0 - sign * dev
        # a state on its yield surface to rounding has no elastic stretch on that side
        room = 0.0 if room <= _SNAP * (abs(dev) + y) else room
        return eps + sign * room * 0.75 / self.shear_modulus

    def _hardening(self, ahead, sign: float, eps):
        """``Delta = eps_bar - eps_bar_a`` on the plastic branch at ``eps`` (float or array).

        Newton on ``h(D) = sign ((4/3) G eps - 2 G eps_p_a) - 2 G D - (2/3) Y(eps_bar_a + D)``,
        decreasing and convex in ``D``, so the iterates rise monotonically from ``D = 0``
        to the root; stopped when a step is below 1e-15 of ``D`` (the error is ~ step^2).
        """
        _, ep, bar, _, _ = self._start(ahead)
        g = self.shear_modulus
        y0, ys, scale = self.yield_strength, self.saturation_strength, self.saturation_strain
        if np.ndim(eps) == 0:
            drive = sign * (4.0 * g * float(eps) / 3.0 - 2.0 * g * ep)
            delta = 0.0
            for _ in range(_NEWTON_STEPS):
                decay = (ys - y0) * math.exp(-(bar + delta) / scale)
                h = drive - 2.0 * g * delta - 2.0 * (ys - decay) / 3.0
                step = h / (2.0 * g + 2.0 * decay / (3.0 * scale))
                delta = max(delta + step, 0.0)
                if abs(step) <= 1e-15 * delta or (delta == 0.0 and step <= 0.0):
                    break
            return delta
        drive = sign * (4.0 * g * eps / 3.0 - 2.0 * g * ep)
        delta = np.zeros_like(eps)
        active = np.arange(eps.size)
        for _ in range(_NEWTON_STEPS):
            d = delta[active]
            decay = (ys - y0) * np.exp(-(bar + d) / scale)
            h = drive[active] - 2.0 * g * d - 2.0 * (ys - decay) / 3.0
            step = h / (2.0 * g + 2.0 * decay / (3.0 * scale))
            d = np.maximum(d + step, 0.0)
            delta[active] = d
            active = active[(np.abs(step) > 1e-15 * d) & ~((d == 0.0) & (step <= 0.0))]
            if active.size == 0:
                break
        return delta

    def strain_path(self, ahead, loading: bool) -> StrainPath:
        """The compression (``loading``) or release path from ``ahead`` in hull coordinates."""
        sign = 1.0 if loading else -1.0
        eps_a, _, _, dev_a, _ = self._start(ahead)
        knee = self._knee(ahead, sign)
        end = _COMPRESSION_LIMIT / self.s if loading else -_TENSION_LIMIT / self.s
        if not sign * (end - eps_a) > 0.0:
            raise StateOutOfRangeError(f"{self.name}: compression {eps_a:.6g} is outside the "
                                       f"model's range")
        g = self.shear_modulus

        _, _, bar, _, _ = self._start(ahead)

        def stress(x):
            eps = sign * x
            if np.ndim(x) == 0:
                if sign * (eps - knee) > 0.0:
                    dev = sign * 2.0 * float(self.flow_stress(
                        bar + self._hardening(ahead, sign, eps))) / 3.0
                else:
                    dev = dev_a + 4.0 * g * (eps - eps_a) / 3.0
                return sign * (float(self.pressure(eps)) + dev)
            eps = np.asarray(eps, dtype=float)
            plastic = sign * (eps - knee) > 0.0
            dev = dev_a + 4.0 * g * (eps - eps_a) / 3.0
            if np.any(plastic):
                delta = self._hardening(ahead, sign, eps[plastic])
                dev[plastic] = sign * 2.0 * self.flow_stress(bar + delta) / 3.0
            return sign * (self.pressure(eps) + dev)

        def slope(x, side=1):
            eps = sign * np.asarray(x, dtype=float)
            plastic = (sign * (eps - knee) > 0.0) | ((eps == knee) & (side > 0))
            out = self.pressure_slope(eps) + 4.0 * g / 3.0
            if np.ndim(x) == 0:
                if plastic:
                    rate = float(self.hardening_rate(bar + self._hardening(ahead, sign,
                                                                            float(eps))))
                    out = self.pressure_slope(float(eps)) + 4.0 * g * rate / (
                        3.0 * (3.0 * g + rate))
                return float(out)
            if np.any(plastic):
                rate = self.hardening_rate(bar + self._hardening(ahead, sign, eps[plastic]))
                out[plastic] = self.pressure_slope(eps[plastic]) + 4.0 * g * rate / (
                    3.0 * (3.0 * g + rate))
            return out

        x_a, x_k, x_e = sign * eps_a, sign * knee, sign * end
        x_k = min(max(x_k, x_a), x_e)
        parts = []
        if x_k > x_a:
            parts.append(np.linspace(x_a, x_k, _ELASTIC_SAMPLES + 1))
        if x_e > x_k:
            t = np.linspace(0.0, 1.0, _PLASTIC_SAMPLES + 1) ** 2
            parts.append(x_k + (x_e - x_k) * t[1:] if parts else x_k + (x_e - x_k) * t)
        samples = np.concatenate(parts)
        corners = np.zeros(samples.size, dtype=bool)
        corners[[0, -1]] = True
        corners[samples == x_k] = True
        return StrainPath(stress=stress, slope=slope, samples=samples, corners=corners)

    def path_state(self, ahead, loading: bool, x: float, sigma: float, u: float, e: float):
        """The state at abscissa ``x`` of the path from ``ahead`` (with its plastic strains)."""
        sign = 1.0 if loading else -1.0
        eps = sign * x
        _, ep, bar, _, _ = self._start(ahead)
        if sign * (eps - self._knee(ahead, sign)) > 0.0:
            delta = self._hardening(ahead, sign, eps)
            ep, bar = ep + sign * delta, bar + delta
        return HardenedState(sigma=float(sigma), u=float(u), v=self.v0 * (1.0 - eps),
                             e=float(e), plastic_strain=float(ep),
                             equivalent_plastic_strain=float(bar))

    # --- Material interface -----------------------------------------------------------
    def stress(self, v: float, e: float) -> float:
        """Stress of the *virgin* material inside its elastic range (Pa).

        Beyond it the stress depends on the plastic strains (history variables):
        ``StateOutOfRangeError`` rather than a wrong answer (use the wave curves).
        """
        eps = self.strain(v)
        if abs(eps) > self.hel_strain * (1.0 + 1e-12) + 1e-15:
            raise StateOutOfRangeError(
                f"{self.name}: compression {eps:.6g} is beyond the elastic range "
                f"(+-{self.hel_strain:.6g}) of the virgin material; the stress depends on "
                f"the plastic strain there (use the wave curves)")
        return float(self.pressure(eps) + 4.0 * self.shear_modulus * eps / 3.0)

    def sound_speed(self, v: float, e: float) -> float:
        """Elastic longitudinal speed ``sqrt((p'(eps) + 4G/3) / rho0)`` at ``v`` (m/s); fans
        take their characteristic speeds from the wave curve."""
        return math.sqrt((float(self.pressure_slope(self.strain(v)))
                          + 4.0 * self.shear_modulus / 3.0) / self.rho0)

    def volume_range(self) -> tuple[float, float]:
        return (self.v0 * (1.0 - _COMPRESSION_LIMIT / self.s),
                self.v0 * (1.0 + _TENSION_LIMIT / self.s))

    def hugoniot(self, ahead, v: float) -> tuple[float, float, float]:
        """The path's stress at ``v`` from ``ahead``, the Rankine–Hugoniot energy of one jump
        there and the path's ``dsigma/dv`` (the stress depends on the strains alone)."""
        loading = v <= ahead.v
        sign = 1.0 if loading else -1.0
        path = self.strain_path(ahead, loading)
        x = sign * self.strain(v)
        sigma = sign * path.stress(x)
        e = ahead.e + 0.5 * (ahead.sigma + sigma) * (ahead.v - v)
        return sigma, e, -path.slope(x) / self.v0

    def hugoniot_volume_limit(self, ahead) -> float:
        return self.volume_range()[0]

    def isentrope(self, through, v: float) -> tuple[float, float]:
        """``(sigma, e)`` along the path from ``through`` (``de = -sigma dv``)."""
        curve = HullWaveCurve(self, through, 1)
        loading = v <= through.v
        sign = 1.0 if loading else -1.0
        hull = curve.hull(loading)
        x = sign * self.strain(v)
        return sign * hull.f(x), through.e + self.v0 * hull.work(x)

    def riemann_integral(self, through, v: float, start: float | None = None) -> float:
        """``J = int rho0 C dv`` along the path from ``through`` (m/s)."""
        curve = HullWaveCurve(self, through, 1)

        def along(w):
            loading = w <= through.v
            sign = 1.0 if loading else -1.0
            return -sign * curve.hull(loading).riemann(sign * self.strain(w))

        return along(v) - (0.0 if start is None else along(start))

    def wave_curve(self, ahead, direction: int, release: str = "isentrope"):
        """The hull wave curve (``materials.hull.HullWaveCurve``) from ``ahead``."""
        return HullWaveCurve(self, ahead, direction, release)
