"""Finite-deformation elastic–plastic solid in uniaxial strain (Davison ch. 7, 10).

Conventions of PHYSICS.md: stress ``sigma`` positive in compression (Pa),
compression ``eps = 1 - v/v0`` (positive when compressed), SI units.

The model
---------
The longitudinal stress is a mean stress (pressure) plus a deviator,

    sigma = p + S,        S = sigma - p   (as in ``materials.elastic_plastic``).

*Deviator.*  Hypoelastic in the compression ``eps`` with a constant shear modulus
``G`` (``dS = (4/3) G d eps`` while elastic), isochoric plastic flow with the
longitudinal plastic strain ``eps_p`` (``State.plastic_strain``, compression
positive, tensor ``diag(eps_p, -eps_p/2, -eps_p/2)``):

    S = (4/3) G eps - 2 G eps_p,          |S| <= (2/3) Y.

``Y = Y0 + H eps_bar`` with ``eps_bar`` the accumulated (equivalent) plastic
strain, ``d eps_bar = |d eps_p|`` (``H = 0``: perfect plasticity).  On a
plastic branch ``S = +-(2/3) Y`` and ``d eps_p = 2 G d eps / (3 G + H)`` (2/3 d eps
without hardening), so ``dS = M_h d eps`` with ``M_h = (4/3) G H / (3 G + H)``.

*Energy and pressure.*  The specific internal energy ``e`` (what the jump
conditions carry) is split into the elastic shear energy and a "hydrostatic"
energy:

    W(S) = (3/8) v0 S^2 / G,      e_h = e - W(S),      p = p_MG(v, e_h),

``p_MG`` the Mie–Grüneisen law of ``materials.mie_gruneisen.MieGruneisen``
(linear Us–up principal Hugoniot, ``Gamma rho = Gamma0 rho0``), used as is.
Along an elastic path ``dW = -S dv`` exactly (because ``d eps = -dv/v0``), so
``de = -sigma dv`` gives ``de_h = -p dv``: **elastic paths are Mie–Grüneisen
isentropes in (v, e_h)** plus the linear deviator.  Along a plastic path the
plastic work ``v0 Y d eps_bar`` (= ``(3/2) v0 S d eps_p``) heats the solid:
``de_h = -p dv + v0 Y d eps_bar``.  The *thermal energy* of a state is its
hydrostatic energy above the reference isentrope at the same volume,
``e_h - e_s0(v)``; its *dissipated energy* is that referred to the reference
volume along its own isentrope, ``(e_h - e_s0(v)) exp(rho0 Gamma0 (v - v0))``,
the isentrope's label: an increasing function of the entropy, zero for the
virgin material and constant along any elastic path.  Plastic work and shock
heating raise it; nothing lowers it except a rarefaction *shock* (the
impedance-match shortcut ``release="hugoniot"``).

*Sound speeds* (Lagrangian, ``C^2 = -v0^2 dsigma/dv`` along the path):

    elastic:  C_e^2 = C_MG^2(v, e_h) + 4 G / (3 rho0)
    plastic:  C_p^2 = C_MG^2(v, e_h) + v0 M_h + v0^2 B kappa S,   B = rho0 Gamma0,
              kappa = 3 G / (3 G + H).

The last term is the heating of the plastic work (a fraction of a per cent).

Waves
-----
From an ahead state ``a`` the elastic range is ``eps_low <= eps <= eps_high``
(``S`` reaches ``+-(2/3) Y``), a closed form because ``S`` depends on the strain
only.  The elastic path is curved (nonlinear pressure) and convex, so:

- loading inside the elastic range: one elastic shock on the Hugoniot centred
  on ``a`` (the exact chord of the slightly curved elastic path);
- loading beyond it: the elastic precursor to the yield point (the Hugoniot
  elastic limit when ``a`` is the virgin material) and a plastic shock on the
  Hugoniot centred on the yield point, whose end states lie on the yield
  surface, ``sigma = p_H(v) + (2/3) Y``.  Every shock is computed from the
  Rankine–Hugoniot energy equation with this law, in closed form (the stress is
  affine in ``e`` at given ``v`` and ``S``).  When the plastic shock would be
  faster than its precursor (strong shocks, ``overdriven``) it overtakes it:
  the wave is one shock from ``a`` to the plastic branch;
- release: an elastic centred fan along the elastic isentrope down to reverse
  yield (``S = -(2/3) Y``, a stress drop of about two HEL from a plastically
  loaded state), then a plastic fan along the plastic path.  Both paths are
  convex and the slope drops at the knee, so the convex hull is the curve
  itself: fan + fan, never shocks.  ``release="hugoniot"`` replaces them by
  rarefaction shocks (elastic, then plastic).

Loading with linear hardening is convex beyond the knee too (a Mie–Grüneisen
Hugoniot plus a linear term), so precursor + plastic shock is again the whole
hull.  A hardening law that saturates makes the plastic branch concave just
beyond the HEL; ``concave_hull_waves`` shows the convex-hull construction that
then gives a shock–fan–shock wave on samples, and ``materials.hull.HullWaveCurve``
is that construction as a wave curve the engine runs (``materials.saturating_plastic``:
a ``Gamma0 = 0`` solid, where the stress is a function of the strain alone and the
construction is exact).

Engine fans
-----------
The characteristic speed of this solid depends on its deviator (plastic strain)
and on whether the path is elastic or plastic, which ``(v, e)`` cannot tell.
``characteristics.rays.discretise_fan`` therefore takes the ray speeds of a fan
from its wave curve: ``FinitePlasticWaveCurve.characteristic_speed(sigma)`` for
the states inside the fan and the fan's own ``head_speed``/``tail_speed`` at its
ends (the yield point between an elastic and a plastic release fan is the tail
of one at the elastic speed and the head of the other at the plastic speed).
States are plain ``State``/``HardenedState`` values.  ``sound_speed(v, e)`` is
only a state-free estimate (an impedance scale for guesses and tolerances): the
elastic speed of the virgin material at ``(v, e)`` with its deviator clamped to
the yield surface.

Tables
------
A Riemann solve asks a wave curve for a dozen stresses close together, and the rays
of a fan for one state each.  A release (fan) branch is therefore sampled once per
wave curve into a ``materials.path_table.PathTable``: Chebyshev panels (0.05 v0 wide,
20 points) of the stress and the characteristic speed, sampled by spectral integration
of ``de_h/dv`` (``_path_arrays``), and the exact integral ``J = int rho0 C dv`` of the
speed's interpolant.  The volume of a target stress is found by Newton's method on the
table (from the tangent at the branch's start, so the root depends on the target
alone); the state behind is then the closed form at that volume.  The tables agree
with the closed forms and with adaptive quadrature to rounding
(``tests/test_path_table.py``, 1e-12 over random states).  Two rays crossing on one
plastic release path need no wave curve at all: ``materials.release_crossing`` solves
them in closed form on that path's table, kept for the run.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable

import numpy as np

from .base import Material, require_number, require_positive
from .errors import MaterialError, NoSolutionError, StateOutOfRangeError
from .mie_gruneisen import MieGruneisen
from .path_table import PathTable, panel_integral, panel_nodes
from .roots import EPS as _EPS
from .roots import bracketed_newton
from .state import RIGHT, State
from .wavecurves import StressRange, check_curve_arguments
from .waves import Fan, Shock

_SNAP = 1e-12
"""A deviator within this fraction of its scale of the yield surface is on it, and a
target stress within this fraction of a yield stress is reached by the elastic wave
alone (no zero-strength wave from rounding)."""

_WEAK_JUMP = 1e-5
"""Relative volume jump below which a shock's speed is taken from the tangent of its
Hugoniot at the mid volume instead of the chord of the stored states."""

_PANEL_FRACTION = 0.05
"""Widest panel of a path table, as a fraction of v0 (as in ``base``): the paths are
analytic at least 0.4 v0 away, so the tables are exact to rounding
(``materials.path_table``)."""

_MAX_FAN_SPEEDS = 1024
"""Characteristic speeds of fan states a wave curve remembers (``characteristic_speed``
after ``state_at``, as the rays of a fan ask them)."""


_PHI_SERIES = 0.1
"""Below this |z| the functions ``_phi`` use their Taylor series (16 terms: exact to
rounding); above it the closed forms lose at most ~1e-15 to cancellation."""


def _phi(z: float, order: int) -> float:
    """``int_0^1 t^order exp(z t) dt`` for ``order`` 0 or 1."""
    if abs(z) <= _PHI_SERIES:
        total, term = 0.0, 1.0
        for n in range(16):
            total += term / (n + 1 + order)
            term *= z / (n + 1)
        return total
    em1 = math.expm1(z)
    return em1 / z if order == 0 else (z * math.exp(z) - em1) / (z * z)


@dataclasses.dataclass(frozen=True, slots=True)
class _Point:
    """A state on one branch of a path, before its velocity is known."""

    sigma: float
    v: float
    e: float
    plastic_strain: float
    accumulated: float
    slope: float          # d sigma / d v along the branch (Hugoniot or path)
    speed: float = math.nan   # characteristic speed there (paths only)

    def state(self, u: float, material) -> State:
        return material._make_state(self.sigma, u, self.v, self.e, self.plastic_strain,
                                    self.accumulated)

    def at_stress(self, sigma: float) -> _Point:
        """The point carrying the stress ``sigma`` (Pa) instead of its own (a target
        stress the branch reproduces to rounding); ``dataclasses.replace`` without its
        cost, asked at most Riemann solves."""
        return _Point(sigma, self.v, self.e, self.plastic_strain, self.accumulated,
                      self.slope, self.speed)

    def with_slope(self, slope: float, speed: float = math.nan) -> _Point:
        """The same state with the branch slope ``slope`` (Pa kg/m^3) and characteristic
        speed ``speed`` (m/s) of another branch through it."""
        return _Point(self.sigma, self.v, self.e, self.plastic_strain, self.accumulated,
                      slope, speed)


@dataclasses.dataclass(frozen=True, slots=True)
class HardenedState(State):
    """A ``State`` with the accumulated plastic strain ``eps_bar`` of a hardening solid.

    A plain ``State`` given to a hardening ``FinitePlastic`` is read with
    ``eps_bar = |plastic_strain|`` (exact for monotone loading).
    """

    equivalent_plastic_strain: float = 0.0


class FinitePlastic(Material):
    """Finite-deformation elastic–plastic solid: Mie–Grüneisen pressure plus a deviator.

    ``rho0`` (kg/m^3), ``c0`` (m/s), ``s``, ``gamma0``: the Mie–Grüneisen pressure on a
    linear Us–up Hugoniot; ``shear_modulus`` G (Pa); ``yield_strength`` Y0 (Pa, >= 0,
    ``math.inf`` for a solid that never yields); ``hardening`` H (Pa, >= 0):
    ``Y = Y0 + H eps_bar``; ``spall_strength`` (Pa).

    Derived: ``eos`` (the ``MieGruneisen`` pressure), ``C_elastic`` and ``C_bulk``
    (m/s, at the reference state), ``hel`` the Hugoniot elastic limit (Pa) and
    ``hel_strain`` the compression at it (``Y0 / (2 G)``).
    """

    is_linear = False
    splits_waves = True

    def __init__(self, name: str, rho0: float, c0: float, s: float, gamma0: float,
                 shear_modulus: float, yield_strength: float, hardening: float = 0.0,
                 spall_strength: float = math.inf):
        self.name = name
        self.eos = MieGruneisen(name, rho0, c0, s, gamma0)
        self.rho0 = self.eos.rho0
        self.shear_modulus = require_positive("shear_modulus", shear_modulus, name)
        strength = require_number("yield_strength", yield_strength, name)
        if not strength >= 0.0:
            raise MaterialError(f"{name}: yield_strength must be >= 0 Pa (or inf), "
                                f"got {yield_strength!r}")
        self.yield_strength = strength
        hardening = require_number("hardening", hardening, name)
        if not (hardening >= 0.0 and math.isfinite(hardening)):
            raise MaterialError(f"{name}: hardening must be finite and >= 0 Pa, "
                                f"got {hardening!r}")
        self.hardening = hardening
        spall = require_number("spall_strength", spall_strength, name)
        if not spall > 0.0:
            raise MaterialError(f"{name}: spall_strength must be > 0 Pa (or inf), "
                                f"got {spall_strength!r}")
        self.spall_strength = spall
        g, h = self.shear_modulus, self.hardening
        self._b = float(self.eos._b(self.eos.v0))
        self.plastic_modulus = 4.0 * g * h / (3.0 * (3.0 * g + h))
        """``M_h = dS/d eps`` on a plastic branch (Pa)."""
        self.heating_fraction = 3.0 * g / (3.0 * g + h)
        """``kappa``: the plastic path's energy source is ``kappa S`` per unit ``-dv``."""
        self.C_bulk = self.eos.c0
        self.C_elastic = math.sqrt(self.C_bulk**2 + 4.0 * g / (3.0 * self.rho0))
        self.hel_strain = self.yield_strength / (2.0 * g)
        ref = self.reference_state()
        if math.isfinite(self.yield_strength):
            curve = FinitePlasticWaveCurve(self, ref, RIGHT)
            self.hel = curve.yield_high
        else:
            self.hel = math.inf

    @classmethod
    def from_poisson(cls, name: str, rho0: float, c0: float, s: float, gamma0: float,
                     poisson: float, yield_strength: float, hardening: float = 0.0,
                     spall_strength: float = math.inf) -> FinitePlastic:
        """With ``G`` from Poisson's ratio and the bulk modulus ``K = rho0 c0^2``:
        ``G = 3 K (1 - 2 nu) / (2 (1 + nu))``."""
        nu = require_number("poisson", poisson, name)
        if not -1.0 < nu < 0.5:
            raise MaterialError(f"{name}: poisson must be in (-1, 0.5), got {poisson!r}")
        bulk = require_positive("rho0", rho0, name) * require_positive("c0", c0, name) ** 2
        return cls(name, rho0, c0, s, gamma0, 1.5 * bulk * (1.0 - 2.0 * nu) / (1.0 + nu),
                   yield_strength, hardening, spall_strength)

    # --- strains, deviator, energies -----------------------------------------------
    def strain(self, v: float) -> float:
        """Compression ``eps = 1 - v/v0``."""
        return 1.0 - v / self.v0

    def deviator_at(self, v: float, plastic_strain: float) -> float:
        """``S = (4/3) G eps - 2 G eps_p`` (Pa)."""
        g = self.shear_modulus
        return 4.0 * g * self.strain(v) / 3.0 - 2.0 * g * plastic_strain

    def deviator(self, state: State) -> float:
        """Stress deviator ``S = sigma - p`` of a state, from its strains (Pa)."""
        return self.deviator_at(state.v, state.plastic_strain)

    def accumulated_plastic_strain(self, state: State) -> float:
        """``eps_bar`` (``HardenedState``), else ``|plastic_strain|``."""
        return float(getattr(state, "equivalent_plastic_strain", abs(state.plastic_strain)))

    def yield_tolerance(self, deviator: float, radius: float) -> float:
        """Distance (Pa) within which a deviator lies on a yield surface of radius
        ``radius`` (``_SNAP`` of their scale): rounding, not an elastic range."""
        return _SNAP * (radius + abs(deviator)) + 1e-15 * self.shear_modulus

    def on_reverse_yield(self, state: State) -> bool:
        """Whether ``state`` lies on the reverse-yield surface ``S = -(2/3) Y`` (to
        ``yield_tolerance``): released plastically, it releases further along the
        plastic path at once."""
        radius = 2.0 * self.flow_stress(self.accumulated_plastic_strain(state)) / 3.0
        deviator = self.deviator(state)
        return math.isfinite(radius) and (
            radius + deviator <= self.yield_tolerance(deviator, radius))

    def flow_stress(self, accumulated: float) -> float:
        """Current yield stress ``Y = Y0 + H eps_bar`` (Pa)."""
        if self.hardening == 0.0:
            return self.yield_strength
        return self.yield_strength + self.hardening * accumulated

    def shear_energy(self, deviator: float) -> float:
        """Elastic shear energy ``W = (3/8) v0 S^2 / G`` (J/kg)."""
        return 0.375 * self.v0 * deviator * deviator / self.shear_modulus

    def hydrostatic_energy(self, state: State) -> float:
        """``e_h = e - W(S)`` (J/kg): the energy the Mie–Grüneisen pressure sees."""
        return state.e - self.shear_energy(self.deviator(state))

    def law(self, v: float, e: float, deviator: float) -> float:
        """``sigma = p_MG(v, e - W(S)) + S`` (Pa)."""
        return (float(self.eos._a(v)) + self._b * (e - self.shear_energy(deviator))
                + deviator)

    def stress_at(self, v: float, e: float, plastic_strain: float = 0.0) -> float:
        """Stress (Pa) at volume, energy and plastic strain."""
        return self.law(v, e, self.deviator_at(v, plastic_strain))

    def pressure(self, state: State) -> float:
        """Mean stress ``p = sigma - S`` from the Mie–Grüneisen law (Pa)."""
        return self.eos.stress(state.v, self.hydrostatic_energy(state))

    def thermal_energy(self, state: State) -> float:
        """Energy above the reference isentrope at the same volume (J/kg): ``e_h - e_s0(v)``."""
        e_s0 = self.eos.isentrope(self.eos.reference_state(), float(state.v))[1]
        return self.hydrostatic_energy(state) - e_s0

    def stored_energy(self, state: State) -> float:
        """Recoverable energy (J/kg): the reference isentrope's energy at ``v`` plus ``W``,
        so that ``e = stored_energy + thermal_energy``."""
        return state.e - self.thermal_energy(state)

    def dissipated_energy(self, state: State) -> float:
        """Heat added to the material (J/kg), referred to the reference volume.

        ``(e_h - e_s0(v)) exp(rho0 Gamma0 (v - v0))``: the label of the Mie–Grüneisen
        isentrope through ``(v, e_h)``, zero for the virgin material, constant along
        any elastic (isentropic) path and increasing with the entropy, so no physical
        wave lowers it; plastic work and shock heating raise it.  With ``Gamma0 = 0``
        it is the thermal energy itself, the accumulated ``v0 Y d eps_bar`` plus the
        shock heating.
        """
        return self.thermal_energy(state) * math.exp(self._b * (float(state.v) - self.v0))

    def elastic_speed(self, v: float, e_h: float) -> float:
        """``C_e = sqrt(C_MG^2(v, e_h) + 4G/(3 rho0))`` (m/s)."""
        c2 = self.eos.sound_speed_squared(v, e_h) + 4.0 * self.shear_modulus * self.v0 / 3.0
        return _root(c2, self.name, v)

    def plastic_speed(self, v: float, e_h: float, deviator: float) -> float:
        """``C_p = sqrt(C_MG^2 + v0 M_h + v0^2 B kappa S)`` on a plastic branch (m/s)."""
        c2 = (self.eos.sound_speed_squared(v, e_h) + self.v0 * self.plastic_modulus
              + self.v0**2 * self._b * self.heating_fraction * deviator)
        return _root(c2, self.name, v)

    def _make_state(self, sigma, u, v, e, plastic_strain, accumulated) -> State:
        if self.hardening > 0.0 and accumulated != abs(plastic_strain):
            return HardenedState(sigma=float(sigma), u=float(u), v=v, e=float(e),
                                 plastic_strain=float(plastic_strain),
                                 equivalent_plastic_strain=float(accumulated))
        return State(sigma=float(sigma), u=float(u), v=v, e=float(e),
                     plastic_strain=float(plastic_strain))

    def state_at_strains(self, v: float, e: float, plastic_strain: float = 0.0,
                         u: float = 0.0) -> State:
        """The state at ``(v, e, eps_p)`` moving at ``u``, checked against the yield surface."""
        self.check_volume(v)
        s = self.deviator_at(v, plastic_strain)
        limit = 2.0 * self.flow_stress(abs(plastic_strain)) / 3.0
        if abs(s) > limit * (1.0 + 1e-9):
            raise StateOutOfRangeError(
                f"{self.name}: deviator {s / 1e9:.6g} GPa is outside the yield surface "
                f"|S| <= 2Y/3 = {limit / 1e9:.6g} GPa")
        return State(sigma=self.law(v, e, s), u=u, v=v, e=e, plastic_strain=plastic_strain)

    # --- Material interface ------------------------------------------------------------
    def stress(self, v: float, e: float) -> float:
        """Stress of the *virgin* material (``eps_p = 0``) inside its elastic range.

        Beyond it the stress depends on the plastic strain (a history variable):
        ``StateOutOfRangeError`` rather than a wrong answer (use ``stress_at``).
        """
        eps = self.strain(v)
        if abs(eps) > self.hel_strain * (1.0 + _SNAP) + 4.0 * _EPS:
            raise StateOutOfRangeError(
                f"{self.name}: compression {eps:.6g} is beyond the elastic range "
                f"(+-{self.hel_strain:.6g}) of the virgin material; the stress depends on "
                f"the plastic strain there (use stress_at or the wave curves)")
        return self.stress_at(v, e, 0.0)

    def sound_speed(self, v: float, e: float) -> float:
        """Elastic longitudinal speed (m/s) of the virgin material at ``(v, e)``.

        ``C_e = sqrt(C_MG^2(v, e_h) + 4G/(3 rho0))`` with ``e_h = e - W(S)`` and the
        deviator of the virgin material, ``S = (4/3) G eps``, clamped to the yield
        surface ``|S| <= 2 Y0/3``.  ``(v, e)`` do not determine the state of this solid
        (the plastic strain is a history variable) nor the branch a wave follows, so
        this is a scale, exact for the virgin material inside its elastic range.  The
        characteristics of fans come from ``FinitePlasticWaveCurve.characteristic_speed``
        and the fan's head and tail speeds (``characteristics.rays.discretise_fan``).
        """
        limit = 2.0 * self.yield_strength / 3.0
        s = min(max(4.0 * self.shear_modulus * self.strain(v) / 3.0, -limit), limit)
        return self.elastic_speed(float(v), e - self.shear_energy(s))

    def volume_range(self) -> tuple[float, float]:
        return self.eos.volume_range()

    def hugoniot(self, ahead: State, v: float) -> tuple[float, float, float]:
        """``(sigma, e, dsigma/dv)`` behind the shock wave(s) from ``ahead`` to volume ``v``.

        Compression: precursor + plastic shock (or one overdriven shock); expansion:
        rarefaction shocks (elastic, then plastic).  ``e`` is that of the split wave.
        """
        curve = FinitePlasticWaveCurve(self, ahead, RIGHT, "hugoniot")
        p = curve.point_at_volume(v, shock=True)
        return p.sigma, p.e, p.slope

    def hugoniot_volume_limit(self, ahead: State) -> float:
        return self.eos.hugoniot_volume_limit(ahead)

    def isentrope(self, through: State, v: float) -> tuple[float, float]:
        """``(sigma, e)`` on the continuous (fan) path from ``through``: elastic isentrope
        to the yield point, then the plastic path (``de = -sigma dv`` all along)."""
        p = FinitePlasticWaveCurve(self, through, RIGHT).point_at_volume(v, shock=False)
        return p.sigma, p.e

    def riemann_integral(self, through: State, v: float, start: float | None = None) -> float:
        """``J = int rho0 C dv`` along the continuous path from ``through`` (m/s)."""
        curve = FinitePlasticWaveCurve(self, through, RIGHT)
        j = curve.path_integral(v)
        return j if start is None else j - curve.path_integral(start)

    def wave_curve(self, ahead: State, direction: int, release: str = "isentrope"):
        return FinitePlasticWaveCurve(self, ahead, direction, release)

    def contact_reflection(self, left: State, right: State, amplitude: float) -> float:
        """Bound (Pa) on the stress a wave of ``amplitude`` reflects from an entropy /
        plastic-strain jump between ``left`` and ``right`` (equal stress and velocity).

        Two parts, added.  *Acoustic*: the elastic impedances differ,
        ``|A| |C_l - C_r| / (C_l + C_r)``.  *Yield offset*: the two sides yield at
        stresses ``w`` apart (``yield_high`` or ``yield_low`` of their wave curves), so
        between the two knees one side's path has the elastic slope ``Z_e = rho0 C_e``
        and the other's the plastic slope ``Z_p = rho0 C_p``; at equal stress their
        velocities differ by at most ``min(|A|, w) (1/Z_p - 1/Z_e)``.  The reflected
        jump ``delta`` closes that gap along the reflected and transmitted paths,
        ``delta (1/Z_r + 1/Z_t) = du``, and both impedances are at most ``Z_e``, so

            delta <= min(|A|, w) (C_e / C_p - 1) / 2          (plastic_contrast)

        (a plastic wave crossing into material a yield offset ``w`` below yield
        reflects ``w (Z_e - Z_p)/(Z_e + Z_p)``, ``2 Z_p / (Z_e + Z_p)`` of the bound).
        A plastic-strain contact therefore reflects a fraction of its offset, not the
        offset itself: the factor is 0.04-0.76 (median 0.15) for the finite-plastic
        solids of the random strength stacks at rest.
        ``tests/test_contact_reflection.py`` checks the bound against the Riemann
        solver.
        """
        curve_l = FinitePlasticWaveCurve(self, left, RIGHT)
        curve_r = FinitePlasticWaveCurve(self, right, RIGHT)
        c_l, c_r = curve_l.head_speed, curve_r.head_speed
        acoustic = abs(amplitude) * abs(c_l - c_r) / (c_l + c_r)
        offset = _yield_offset(curve_l, curve_r)
        if offset == 0.0:
            return acoustic
        contrast = max(self.plastic_contrast(curve) for curve in (curve_l, curve_r))
        return acoustic + contrast * min(abs(amplitude), offset)

    def yield_offset(self, left: State, right: State) -> float:
        """The larger of the offsets (Pa) of the two states' loading and unloading yield
        stresses (``yield_high``, ``yield_low`` of their wave curves)."""
        return _yield_offset(FinitePlasticWaveCurve(self, left, RIGHT),
                             FinitePlasticWaveCurve(self, right, RIGHT))

    def plastic_contrast(self, curve: FinitePlasticWaveCurve) -> float:
        """``(C_e / C_p - 1) / 2`` over the elastic ranges of ``curve`` (dimensionless):
        ``C_e`` the largest elastic speed at its ahead state or a knee, ``C_p`` the
        smallest plastic speed at a knee (``contact_reflection``)."""
        radius = 2.0 * self.flow_stress(self.accumulated_plastic_strain(curve.ahead)) / 3.0
        c_e = curve.head_speed
        c_p = math.inf
        for knee, deviator in ((curve._knee_up, radius), (curve._knee_down, -radius)):
            if knee is None:
                continue
            e_h = knee.e - self.shear_energy(deviator)
            c_e = max(c_e, self.elastic_speed(knee.v, e_h))
            c_p = min(c_p, self.plastic_speed(knee.v, e_h, deviator))
        return 0.5 * (c_e / c_p - 1.0) if math.isfinite(c_p) else 0.0


def _yield_offset(curve_l: FinitePlasticWaveCurve, curve_r: FinitePlasticWaveCurve) -> float:
    """The larger offset (Pa) of the finite yield stresses of two wave curves (0 when the
    solid never yields)."""
    pairs = ((curve_l.yield_low, curve_r.yield_low), (curve_l.yield_high, curve_r.yield_high))
    return max((abs(x - y) for x, y in pairs if math.isfinite(x) and math.isfinite(y)),
               default=0.0)


def _root(c2: float, name: str, v: float) -> float:
    if not c2 > 0.0:
        raise StateOutOfRangeError(f"{name}: no real sound speed at density {1.0 / v:.6g} "
                                   f"kg/m3 (beyond the spinodal)")
    return math.sqrt(c2)


_BASIS = ("_v_a", "_eps_a", "_s_a", "_acc_a", "_radius", "_e_h", "_offset", "_start",
          "head_speed", "_v_min", "_v_max", "_v_high", "_v_low", "_knee_up", "_knee_down",
          "yield_high", "yield_low", "_g_high", "_g_low_value")
"""What a ``FinitePlasticWaveCurve`` computes from its ahead state alone (not from its
direction), as it stands after construction: shared by the curves of one ahead state."""

_MAX_BASES = 4096
"""Ahead states whose curve bases (and path-table panels) a material keeps; beyond it
the store starts again (a basis is rebuilt identically when asked again)."""


def _basis_key(material: FinitePlastic, ahead: State, release: str) -> tuple | None:
    """The exact key of an ahead state's curve basis: the bits of every field the basis
    reads (``-0.0`` apart from ``0.0``), or ``None`` (not shared) for a state whose
    fields are not plain floats."""
    fields = (ahead.sigma, ahead.v, ahead.e, ahead.plastic_strain,
              material.accumulated_plastic_strain(ahead))
    if any(type(x) is not float for x in fields):
        return None
    return (release, *(x.hex() for x in fields))


class FinitePlasticWaveCurve(StressRange):
    """Wave curve of a ``FinitePlastic`` solid (same interface as ``HydrodynamicWaveCurve``).

    ``u = u_a + d g(sigma)`` with ``g`` continuous and increasing:

    - ``sigma > sigma_a``: ``g = sqrt((sigma_Y - sigma_a)(v_a - v_Y)) +
      sqrt((sigma - sigma_Y)(v_Y - v))`` (precursor to the yield point ``Y`` and plastic
      shock), a single chord inside the elastic range or when overdriven;
    - ``sigma < sigma_a``: ``g = -int rho0 C dv`` along the elastic isentrope and then the
      plastic path (``release="hugoniot"``: chords of rarefaction shocks).

    ``yield_high``/``yield_low`` are the stresses at which loading and unloading from
    ``a`` yield (``+-inf`` if the solid never yields).
    """

    def __init__(self, material: FinitePlastic, ahead: State, direction: int,
                 release: str = "isentrope"):
        check_curve_arguments(direction, release)
        self.material = material
        self.ahead = ahead
        self.direction = direction
        self.release = release
        self._limits: tuple[float, float] | None = None
        self._last: tuple[float, tuple] | None = None
        self._last_root: tuple[float, tuple] | None = None
        self._last_states: tuple[float, tuple] | None = None
        self._fan_speeds: dict[float, float] = {}
        self._tables: dict[tuple[str, bool], PathTable] = {}
        self._ends: dict[tuple, tuple[tuple[float, float], float]] = {}
        key = _basis_key(material, ahead, release)
        bases = material.__dict__.setdefault("_curve_bases", {})
        basis = bases.get(key) if key is not None else None
        if basis is None:
            self._knees(material, ahead, release)
            basis = ({name: getattr(self, name) for name in _BASIS}, {})
            if key is not None:
                if len(bases) >= _MAX_BASES:
                    bases.clear()
                bases[key] = basis
        else:
            self.__dict__.update(basis[0])
        self._panel_stores: dict[tuple[str, bool], list] = basis[1]

    def _knees(self, mat: FinitePlastic, ahead: State, release: str) -> None:
        """The curve's basis (``_BASIS``): the ahead state's strain, deviator, yield
        radius (Pa), hydrostatic energy (J/kg) and elastic speed (m/s), and the yield
        points reached by loading and unloading elastic waves, with their stresses."""
        v_a = float(ahead.v)
        self._v_a = v_a
        self._eps_a = mat.strain(v_a)
        self._s_a = mat.deviator(ahead)
        self._acc_a = mat.accumulated_plastic_strain(ahead)
        self._radius = 2.0 * mat.flow_stress(self._acc_a) / 3.0
        self._e_h = ahead.e - mat.shear_energy(self._s_a)
        self._offset = mat.law(v_a, ahead.e, self._s_a) - ahead.sigma
        self._start = _Point(ahead.sigma, v_a, ahead.e, ahead.plastic_strain, self._acc_a,
                             math.nan)
        self.head_speed = mat.elastic_speed(v_a, self._e_h)
        self._v_min, self._v_max = mat.volume_range()
        self._v_max *= 1.0 - 1e-12
        g, r = mat.shear_modulus, self._radius
        if math.isfinite(r):
            tol = mat.yield_tolerance(self._s_a, r)
            up, down = r - self._s_a, r + self._s_a
            up = 0.0 if up <= tol else up
            down = 0.0 if down <= tol else down
            self._v_high = mat.v0 * (1.0 - (self._eps_a + 0.75 * up / g))
            self._v_low = mat.v0 * (1.0 - (self._eps_a - 0.75 * down / g))
            self._v_high = v_a if up == 0.0 else self._v_high
            self._v_low = v_a if down == 0.0 else self._v_low
        else:
            self._v_high, self._v_low = -math.inf, math.inf
        # the two knees: the yield points reached by the elastic waves
        self._knee_up = self._knee_down = None
        self.yield_high, self.yield_low = math.inf, -math.inf
        self._g_high = math.nan
        self._g_low_value: float | None = math.nan
        if self._v_high > self._v_min:
            self._knee_up = (self._start if self._v_high == v_a else
                             self._shock(self._start, self._v_high, radius=r, on_yield=+1))
            self.yield_high = self._knee_up.sigma
            self._g_high = self._chord(self._start, self._knee_up)
        if self._v_low < self._v_max:
            if self._v_low == v_a:
                self._knee_down = self._start
                self._g_low_value = 0.0
            elif release == "hugoniot":
                self._knee_down = self._shock(self._start, self._v_low, radius=r, on_yield=-1)
                self._g_low_value = self._chord(self._start, self._knee_down)
            else:
                self._knee_down = self._elastic_path(self._v_low, on_yield=True)
                self._g_low_value = None   # the elastic fan's integral, when first asked
            self.yield_low = self._knee_down.sigma

    @property
    def _g_low(self) -> float:
        """Velocity change (signed like the stress jump) across the elastic release to
        the reverse-yield point (m/s), integrated on first use: a loading curve never
        needs it."""
        if self._g_low_value is None:
            self._g_low_value = -self._integral("elastic", self._v_low)
        return self._g_low_value

    # --- elementary branches ------------------------------------------------------------
    def _shock(self, start: _Point, v: float, radius: float, on_yield: int = 0) -> _Point:
        """State behind a shock from ``start`` to volume ``v`` (Rankine–Hugoniot, closed form).

        The deviator follows the elastic trial ``S_a + (4/3) G d eps`` and is returned to
        the yield surface of radius ``radius`` if beyond it (linear hardening).
        ``on_yield = +-1`` puts the end exactly on that side of the yield surface (the
        yield points, whose volume was computed for that).
        """
        mat, g = self.material, self.material.shear_modulus
        v0, b = mat.v0, mat._b
        s_start = mat.deviator_at(start.v, start.plastic_strain)
        trial = s_start + 4.0 * g * (mat.strain(v) - mat.strain(start.v)) / 3.0
        ep, acc = start.plastic_strain, start.accumulated
        ds_dv = -4.0 * g / (3.0 * v0)
        if on_yield:
            s = on_yield * radius
        elif abs(trial) > radius:
            sign = math.copysign(1.0, trial)
            dep = (trial - sign * radius) / (2.0 * g + 2.0 * mat.hardening / 3.0)
            s = trial - 2.0 * g * dep
            ep, acc = ep + dep, acc + abs(dep)
            ds_dv = -mat.plastic_modulus / v0
        else:
            s = trial
        w = mat.shear_energy(s)
        dw_dv = 0.75 * v0 * s * ds_dv / g
        a, a1 = float(mat.eos._a(v)), float(mat.eos._a_prime(v))
        dv = start.v - v
        x = start.sigma + a + s - b * w - self._offset
        num = start.e + 0.5 * x * dv
        den = 1.0 - 0.5 * b * dv
        e = num / den
        dnum = 0.5 * (a1 + ds_dv - b * dw_dv) * dv - 0.5 * x
        de = (dnum * den - num * 0.5 * b) / (den * den)
        sigma = a + b * (e - w) + s - self._offset
        slope = a1 + b * (de - dw_dv) + ds_dv
        if v == start.v:   # no jump: the start itself (not its stress re-rounded)
            return start.with_slope(slope, start.speed)
        return _Point(sigma, v, e, ep, acc, slope)

    def _elastic_path(self, v: float, on_yield: bool = False) -> _Point:
        """Point of the elastic isentrope through ``a`` (MG isentrope in ``(v, e_h)``)."""
        mat, a = self.material, self.ahead
        p, e_h = mat.eos.isentrope(State(0.0, 0.0, self._v_a, self._e_h), v)
        if on_yield:
            s = -self._radius if v > self._v_a else self._radius
        else:
            s = self._s_a + 4.0 * mat.shear_modulus * (mat.strain(v) - self._eps_a) / 3.0
        c = mat.elastic_speed(v, e_h)
        if v == self._v_a and not on_yield:
            return self._start.with_slope(-c * c / mat.v0**2, c)
        return _Point(p + s - self._offset, v, e_h + mat.shear_energy(s), a.plastic_strain,
                      self._acc_a, -c * c / mat.v0**2, c)

    def _plastic_energy(self, knee: _Point, sign: int, v: float) -> tuple[float, float]:
        """``(e_h, S)`` along the plastic path from the yield point ``knee``.

        ``de_h/dv = -(A + B e_h) - kappa S(v)`` with ``S`` linear in ``v``: closed form
        with the Mie–Grüneisen material function ``F`` and the integrals ``_phi``.
        """
        mat = self.material
        eos, b, v0 = mat.eos, mat._b, mat.v0
        s_k = sign * self._radius
        x = v - knee.v
        s = s_k - mat.plastic_modulus * x / v0
        e_h_k = knee.e - mat.shear_energy(s_k)
        a0 = mat.heating_fraction * s_k
        a1 = -mat.heating_fraction * mat.plastic_modulus / v0
        e_k = float(eos._energy_factor(float(knee.v)))
        f_diff = eos._f(x + knee.v) - eos._f(float(knee.v))
        z = b * x
        e_h = (e_h_k - f_diff / e_k - a0 * x * _phi(z, 0) - a1 * x * x * _phi(z, 1)) * math.exp(-z)
        return e_h, s

    def _plastic_path(self, knee: _Point, sign: int, v: float) -> _Point:
        mat = self.material
        e_h, s = self._plastic_energy(knee, sign, v)
        e_h, s = float(e_h), float(s)
        c = mat.plastic_speed(v, e_h, s)
        dep = 2.0 * mat.shear_modulus * (mat.strain(v) - mat.strain(knee.v)) / (
            3.0 * mat.shear_modulus + mat.hardening)
        sigma = float(mat.eos.stress(v, e_h)) + s - self._offset
        return _Point(sigma, v, e_h + mat.shear_energy(s), knee.plastic_strain + dep,
                      knee.accumulated + abs(dep), -c * c / mat.v0**2, c)

    def _path_arrays(self, branch: str, p0: float, p1: float) -> tuple[np.ndarray, np.ndarray]:
        """``(sigma, C)`` on a continuous branch at the ``panel_nodes`` of ``[p0, p1]``.

        The hydrostatic energy obeys ``de_h/dv = -(A + B e_h) - q(v)`` with the source
        ``q = kappa S(v)`` on a plastic branch (0 on the elastic one), so with the
        Mie–Grüneisen factor ``E = exp(B (v - v0))``

            e_h(v) E(v) = e_h(p0) E(p0) - int_{p0}^{v} (A + q) E dw,

        ``e_h(p0)`` from the closed form (``_plastic_energy``, the isentrope) and the
        integral by spectral integration on the panel (``panel_integral``): the same path
        to rounding, with a handful of array operations.  Then ``sigma = A + B e_h + S``
        and ``C^2`` as in ``elastic_speed``/``plastic_speed``.
        """
        mat = self.material
        eos, b, v0, g = mat.eos, mat._b, mat.v0, mat.shear_modulus
        nodes = panel_nodes(p0, p1)
        factor = eos._energy_factor(nodes)
        a = eos._a(nodes)
        if branch == "elastic":
            e_h0 = eos.isentrope(State(0.0, 0.0, self._v_a, self._e_h), p0)[1]
            s = self._s_a + 4.0 * g * (mat.strain(nodes) - self._eps_a) / 3.0
            source = a
            extra = 4.0 * g * v0 / 3.0
        else:
            knee, sign = ((self._knee_down, -1) if branch == "plastic-down"
                          else (self._knee_up, 1))
            e_h0, s0 = self._plastic_energy(knee, sign, p0)
            s = s0 - mat.plastic_modulus * (nodes - p0) / v0
            source = a + mat.heating_fraction * s
            extra = v0 * mat.plastic_modulus + v0 * v0 * b * mat.heating_fraction * s
        e_h = (e_h0 * eos._energy_factor(p0) - panel_integral(source * factor, p0, p1)) / factor
        pressure = a + b * e_h
        c2 = -v0 * v0 * (eos._a_prime(nodes) - b * pressure) + extra
        if not np.min(c2) > 0.0:
            raise StateOutOfRangeError(f"{mat.name}: the release path leaves the region "
                                       f"of real sound speed near density "
                                       f"{1.0 / max(p0, p1):.6g}")
        return pressure + s - self._offset, np.sqrt(c2)

    def _table(self, branch: str, expanding: bool) -> PathTable:
        """The Chebyshev table of a continuous branch towards larger volumes
        (``expanding``) or smaller ones from its start (the elastic branch runs both
        ways from the ahead state, a plastic one only away from its yield point)."""
        if branch == "elastic":
            start = self._v_a
            end = (min(self._v_low, self._v_max) if expanding
                   else max(self._v_high, self._v_min))
        elif branch == "plastic-down":
            start, end = self._knee_down.v, self._v_max
        else:
            start, end = self._knee_up.v, self._v_min
        key = (branch, expanding)
        table = self._tables.get(key)
        if table is None:
            mat = self.material
            table = PathTable(lambda p0, p1: self._path_arrays(branch, p0, p1), start, end,
                              _PANEL_FRACTION * mat.v0, mat.rho0,
                              store=self._panel_stores.setdefault(key, []))
            self._tables[key] = table
        return table

    def _integral(self, branch: str, v: float) -> float:
        """``int rho0 C dv`` from the branch's start to ``v`` (m/s), from its table."""
        expanding = branch == "plastic-down" or (branch == "elastic" and v > self._v_a)
        return self._table(branch, expanding).integral(v)

    @staticmethod
    def _chord(a: _Point, b: _Point) -> float:
        """``|u_b - u_a| = sqrt((sigma_b - sigma_a)(v_a - v_b))``, signed like the stress jump."""
        jump = (b.sigma - a.sigma) * (a.v - b.v)
        return math.copysign(math.sqrt(max(jump, 0.0)), b.sigma - a.sigma)

    # --- the composite path by volume -----------------------------------------------------
    def _overdriven(self, plastic: _Point) -> bool:
        """Would the plastic shock to ``plastic`` catch its precursor (U2 >= U1)?"""
        a, k = self._start, self._knee_up
        if k is self._start:
            return False
        # U1^2 = v0^2 (sigma_k - sigma_a)/(v_a - v_k), U2^2 = v0^2 (sigma - sigma_k)/(v_k - v)
        u1 = (k.sigma - a.sigma) * (k.v - plastic.v)
        u2 = (plastic.sigma - k.sigma) * (a.v - k.v)
        return u2 >= u1

    def _loading(self, v: float) -> tuple[_Point, _Point | None, bool]:
        """``(behind, yield point or None, overdriven)`` of the shock wave to ``v < v_a``."""
        if v == self._v_high:
            return self._knee_up, None, False
        if self._knee_up is None or v > self._v_high:
            return self._shock(self._start, v, self._radius), None, False
        plastic = self._shock(self._knee_up, v, self._radius)
        if self._overdriven(plastic):
            return self._shock(self._start, v, self._radius), None, True
        return plastic, self._knee_up, False

    def _release_shock(self, v: float) -> tuple[_Point, _Point | None]:
        if v == self._v_low:
            return self._knee_down, None
        if self._knee_down is None or v < self._v_low:
            return self._shock(self._start, v, self._radius), None
        return self._shock(self._knee_down, v, self._radius), self._knee_down

    def _release_path(self, v: float) -> tuple[_Point, str]:
        if v == self._v_low and self.release != "hugoniot":
            return self._knee_down, "elastic"
        if self._knee_down is None or v <= self._v_low:
            return self._elastic_path(v), "elastic"
        return self._plastic_path(self._knee_down, -1, v), "plastic-down"

    def _loading_path(self, v: float) -> tuple[_Point, str]:
        if self._knee_up is None or v >= self._v_high:
            return self._elastic_path(v), "elastic"
        return self._plastic_path(self._knee_up, 1, v), "plastic-up"

    def point_at_volume(self, v: float, shock: bool) -> _Point:
        """The state at volume ``v`` reached by shocks (``shock``) or along the fan path."""
        if v == self._v_a:
            return self._start
        if shock:
            return (self._loading(v) if v < self._v_a else self._release_shock(v))[0]
        return (self._loading_path(v) if v < self._v_a else self._release_path(v))[0]

    def path_integral(self, v: float) -> float:
        """``J = int_{v_a}^{v} rho0 C dv`` along the continuous path (m/s)."""
        if v == self._v_a:
            return 0.0
        if v > self._v_a:
            if self._knee_down is None or v <= self._v_low:
                return self._integral("elastic", v)
            return -self._g_low + self._integral("plastic-down", v)
        if self._knee_up is None or v >= self._v_high:
            return self._integral("elastic", v)
        return self._integral("elastic", self._v_high) + self._integral("plastic-up", v)

    # --- the plastic release path from a state on the reverse-yield surface ---------------
    @property
    def on_reverse_yield(self) -> bool:
        """Whether the ahead state lies on the reverse-yield surface (to ``_SNAP``), so
        that its release is plastic from the start: no elastic fan."""
        return self._knee_down is self._start and self.release != "hugoniot"

    def release_table(self) -> PathTable:
        """The table of the plastic release path from the reverse-yield point towards
        larger volumes (its ``start`` the point's volume; ``materials.release_crossing``)."""
        return self._table("plastic-down", expanding=True)

    def release_state(self, v: float, sigma: float, u: float) -> State:
        """The state at volume ``v`` (m^3/kg) on the plastic release path (closed form),
        carrying the stress ``sigma`` (Pa, the path's to rounding) and velocity ``u`` (m/s)."""
        point = self._plastic_path(self._knee_down, -1, v)
        return point.at_stress(float(sigma)).state(u, self.material)

    # --- range ---------------------------------------------------------------------------
    def sigma_limits(self) -> tuple[float, float]:
        if self._limits is None:
            v_lim = self.material.hugoniot_volume_limit(self.ahead)
            high = max(self._loading(v_lim)[0].sigma, self.ahead.sigma)
            v_top = self._v_max
            if self.release == "hugoniot":
                low = self._release_shock(v_top)[0].sigma
            else:
                low = self._release_path(v_top)[0].sigma
            self._limits = (min(low, self.ahead.sigma), high)
        return self._limits

    def sigma_min(self) -> float:
        return self.sigma_limits()[0]

    def sigma_max(self) -> float:
        return self.sigma_limits()[1]

    @property
    def impedance(self) -> float:
        """Elastic impedance ``rho0 C_e`` of the ahead state (the curve's slope at its centre)."""
        return self.material.rho0 * self.head_speed

    # --- solving for a stress ----------------------------------------------------------------
    def _region(self, sigma: float) -> str:
        """Where ``sigma`` lies: "elastic", "snap" (within rounding of a yield stress, on
        either side: reached by the elastic wave alone, ending on the yield point) or
        "plastic".  Within rounding below it too: the elastic branch's closed form ends
        a few hundred ulps from ``yield_high`` (campaign seed 426: 2e-5 Pa at 2.357 GPa),
        and a target between the two lay on neither branch."""
        a = self.ahead
        knee = self.yield_high if sigma > a.sigma else self.yield_low
        if not math.isfinite(knee):
            return "elastic"
        if knee != a.sigma and abs(sigma - knee) <= _SNAP * abs(knee):
            return "snap"
        return "elastic" if (sigma < knee if sigma > a.sigma else sigma > knee) else "plastic"

    def _path_function(self, branch: Callable[[float], _Point], kind: str,
                       plastic: bool) -> Callable[[float], tuple[float, float]]:
        """``v -> (sigma, dsigma/dv)`` on one branch: from the branch's table for a fan
        where the table reaches (rounding-exact and far cheaper), else the closed form."""
        if kind != "fan":
            def closed(v):
                p = branch(v)
                return p.sigma, p.slope
            return closed
        table = self._table("plastic-down" if plastic else "elastic", expanding=True)

        def tabulated(v):
            if table.within(v):
                return table.stress(v)
            p = branch(v)
            return p.sigma, p.slope
        return tabulated

    def _branch(self, loading: bool, plastic: bool, kind: str):
        """``(lo, hi, branch)``: the volumes bracketing one branch and its closed form
        ``v -> _Point``."""
        mat, a = self.material, self.ahead
        if loading:
            v_lim = mat.hugoniot_volume_limit(a)
            if plastic:
                return v_lim, self._v_high, lambda v: self._loading(v)[0]
            return (max(self._v_high, v_lim), self._v_a,
                    lambda v: self._shock(self._start, v, self._radius))
        lo, hi = (self._v_low, self._v_max) if plastic else (
            self._v_a, min(self._v_max, self._v_low))
        if kind == "shock":
            return lo, hi, lambda v: self._release_shock(v)[0]
        return lo, hi, lambda v: self._release_path(v)[0]

    def _root(self, sigma: float) -> tuple:
        """``(v, plastic, kind, branch)`` for a target stress outside the "snap" region:
        the volume behind the wave, found on the branch's table (a fan) or its closed
        form (a shock), with the closed form of the branch (cached)."""
        if self._last_root is not None and self._last_root[0] == sigma:
            return self._last_root[1]
        a = self.ahead
        loading = sigma > a.sigma
        kind = "shock" if loading or self.release == "hugoniot" else "fan"
        plastic = self._region(sigma) == "plastic"
        lo, hi, branch = self._branch(loading, plastic, kind)
        path = self._path_function(branch, kind, plastic)

        def residual(v):
            stress, slope = path(v)
            return stress - sigma, slope

        key = (loading, plastic, kind)
        noise = 16.0 * _EPS * (abs(sigma) + abs(a.sigma))
        try:
            ends = self._ends.get(key)
            if ends is None:
                # the stresses at the ends from the closed form (the ahead state and the
                # yield point exactly, as ``_region`` compares with), the slope at the
                # start from the path (a fan's start tangent is the Newton guess)
                ends = self._ends[key] = ((branch(lo).sigma, path(lo)[1]), branch(hi).sigma)
            (sigma_lo, slope_lo), sigma_hi = ends
            f_lo, f_hi = sigma_lo - sigma, sigma_hi - sigma
            if kind == "fan":
                # the tangent at the fan's start: the path is convex, so this lands
                # between the start and the root and Newton then converges monotonically
                # (and the root depends on the target alone, not on earlier solves)
                guess = lo - f_lo / slope_lo if slope_lo < 0.0 else None
            else:
                guess = self._v_a - (sigma - a.sigma) / self.impedance**2
            if abs(f_hi) <= noise or abs(f_lo) <= noise:   # a jump within rounding of an end
                v = hi if abs(f_hi) <= abs(f_lo) else lo
            else:
                v = bracketed_newton(residual, lo, hi, guess, rel_tol=2e-16, f_lo=f_lo,
                                     f_hi=f_hi, f_tol=noise)
        except (NoSolutionError, StateOutOfRangeError):
            self.check_stress(sigma)
            raise
        result = (v, plastic, kind, branch)
        self._last_root = (sigma, result)
        return result

    def _solve(self, sigma: float) -> tuple:
        """``(behind point, knee point or None, kind)`` for a target stress (cached)."""
        if self._last is not None and self._last[0] == sigma:
            return self._last[1]
        loading = sigma > self.ahead.sigma
        if self._region(sigma) == "snap":
            kind = "shock" if loading or self.release == "hugoniot" else "fan"
            result = ((self._knee_up if loading else self._knee_down).at_stress(float(sigma)),
                      None, kind)
            self._last = (sigma, result)
            return result
        v, plastic, kind, branch = self._root(sigma)
        # the state carries the target stress itself (the branch reproduces it to rounding)
        point = branch(v).at_stress(float(sigma))
        knee_point = None
        if plastic:
            knee_point = self._knee_up if loading else self._knee_down
            if loading and self._loading(v)[2]:
                knee_point = None  # overdriven: one shock
        result = (point, knee_point, kind)
        self._last = (sigma, result)
        return result

    def velocity_change(self, sigma: float) -> tuple[float, float]:
        """``(g, dg/dsigma)``: the particle-velocity change ``u - u_a = d * g``."""
        if sigma == self.ahead.sigma:
            return 0.0, 1.0 / self.impedance
        if (sigma < self.ahead.sigma and self.release != "hugoniot"
                and self._region(sigma) != "snap"):
            # a fan: its volume, integral and speed from the branch's table alone
            v, plastic, _, _ = self._root(sigma)
            table = self._table("plastic-down" if plastic else "elastic", expanding=True)
            g0 = self._g_low if plastic else 0.0
            return g0 - table.integral(v), 1.0 / math.sqrt(-table.stress(v)[1])
        point, knee, kind = self._solve(sigma)
        if kind == "fan":   # a release snapped to the reverse-yield point
            return self._g_low, 1.0 / (self.material.rho0 * point.speed)
        start = self._start if knee is None else knee
        g0 = 0.0 if knee is None else (self._g_high if sigma > self.ahead.sigma else self._g_low)
        g = self._chord(start, point)
        if g == 0.0:
            return g0, 1.0 / self.impedance
        slope = ((start.v - point.v) - (point.sigma - start.sigma) / point.slope) / (2.0 * g)
        return g0 + g, slope

    def _states(self, sigma: float) -> tuple[State | None, State]:
        """``(state at the knee or None, state behind)``, with their velocities."""
        cached = self._last_states
        if cached is not None and cached[0] == sigma:
            return cached[1]
        a, d, mat = self.ahead, self.direction, self.material
        point, knee, kind = self._solve(sigma)
        g, _ = self.velocity_change(sigma)
        behind = point.state(a.u + d * g, mat)
        if kind == "fan":   # remembered for the rays through the states of a fan
            if len(self._fan_speeds) >= _MAX_FAN_SPEEDS:
                self._fan_speeds.clear()
            self._fan_speeds[sigma] = point.speed
        knee_state = None
        if knee is not None:
            g_knee = self._g_high if sigma > a.sigma else self._g_low
            knee_state = knee.state(a.u + d * g_knee, mat)
        self._last_states = (sigma, (knee_state, behind))
        return knee_state, behind

    def state_at(self, sigma: float) -> State:
        """The state behind the wave that reaches ``sigma``."""
        if sigma == self.ahead.sigma:
            return self.ahead
        return self._states(sigma)[1]

    def characteristic_speed(self, sigma: float) -> float:
        """Speed (m/s, unsigned, Lagrangian) of the characteristic through the state of
        stress ``sigma`` on this curve: ``C = v0 sqrt(-dsigma/dv)`` along the path there.

        Along the release path (the fans) this is ``C_e`` on the elastic isentrope
        down to reverse yield and ``C_p`` on the plastic path beyond; on the loading
        (shock) side, the elastic speed inside the elastic range and the plastic one
        beyond it.  At the ahead state it is the elastic ``head_speed``; at the yield
        point itself it is the elastic speed (the end of the elastic branch): the
        plastic fan that starts there carries its own ``head_speed``.  This is what
        ``characteristics.rays.discretise_fan`` uses for the rays inside this curve's
        fans.
        """
        if sigma == self.ahead.sigma:
            return self.head_speed
        speed = self._fan_speeds.get(sigma)
        if speed is not None:
            return speed
        point, knee, kind = self._solve(sigma)
        if kind == "fan":
            return point.speed
        mat = self.material
        e_h = point.e - mat.shear_energy(mat.deviator_at(point.v, point.plastic_strain))
        if knee is None and self._region(sigma) != "plastic":
            return mat.elastic_speed(point.v, e_h)
        return mat.plastic_speed(point.v, e_h, mat.deviator_at(point.v, point.plastic_strain))

    def waves(self, sigma: float) -> tuple:
        """Elementary waves realising the jump to ``sigma``, leading wave first."""
        a, d, mat = self.ahead, self.direction, self.material
        if sigma == a.sigma:
            return ()
        point, knee_point, kind = self._solve(sigma)
        knee, behind = self._states(sigma)
        if kind == "fan":
            if knee is None:
                return (Fan(ahead=a, behind=behind, head_speed=d * self.head_speed,
                            tail_speed=d * point.speed, direction=d, curve=self),)
            # the yield point ends the elastic fan (elastic speed) and starts the plastic
            # one (plastic speed): one state, two characteristic speeds
            k_pl_speed = mat.plastic_speed(knee.v, knee.e - mat.shear_energy(
                -self._radius), -self._radius)
            waves = []
            if self._knee_down is not self._start:
                waves.append(Fan(ahead=a, behind=knee, head_speed=d * self.head_speed,
                                 tail_speed=d * self._knee_down.speed, direction=d, curve=self))
            waves.append(Fan(ahead=knee, behind=behind, head_speed=d * k_pl_speed,
                             tail_speed=d * point.speed, direction=d, curve=self))
            return tuple(waves)
        if knee is None or knee_point is self._start:
            return (self._shock_wave(a, behind),)
        return (self._shock_wave(a, knee), self._shock_wave(knee, behind))

    def _shock_wave(self, ahead: State, behind: State) -> Shock:
        d, mat = self.direction, self.material
        dv = float(ahead.v) - float(behind.v)
        if abs(dv) > _WEAK_JUMP * float(ahead.v):
            speed = (behind.sigma - ahead.sigma) / (mat.rho0 * (behind.u - ahead.u))
        else:
            mid = 0.5 * (float(ahead.v) + float(behind.v))
            plastic = behind.plastic_strain != ahead.plastic_strain
            start = _Point(ahead.sigma, float(ahead.v), ahead.e, ahead.plastic_strain,
                           mat.accumulated_plastic_strain(ahead), math.nan)
            slope = self._shock(start, mid, self._radius).slope
            if slope < 0.0:
                speed = d * mat.v0 * math.sqrt(-slope)
            else:
                speed = d * (self.head_speed if not plastic else mat.C_bulk)
        return Shock(ahead=ahead, behind=behind, speed=speed, direction=d)


# --- the convex-hull construction (non-convex loading paths) -------------------------------
def concave_hull_waves(strain: np.ndarray, stress: np.ndarray, rho0: float) -> list[dict]:
    """Waves of a compressive jump along a sampled loading path ``stress(strain)``.

    For a stress that is a function of the compression alone (a ``Gamma0 = 0`` solid on a
    monotone loading path) the admissible compressive wave from ``strain[0]`` to
    ``strain[-1]`` follows the *upper concave hull* of the curve: where the hull is a
    chord the wave is a shock at ``U = sqrt(slope / rho0)``; where it runs on the curve,
    a centred fan whose characteristics have ``C = sqrt(dsigma/deps / rho0)``.  Speeds
    decrease along the hull, so the pieces are returned leading wave first, each a dict
    with ``kind`` ("shock" or "fan"), ``start``/``end`` sample indices and ``speeds``
    (head and tail, m/s; equal for a shock).  ``strain`` must increase.
    """
    eps = np.asarray(strain, dtype=float)
    sig = np.asarray(stress, dtype=float)
    if eps.ndim != 1 or eps.shape != sig.shape or eps.size < 2 or np.any(np.diff(eps) <= 0):
        raise ValueError("strain must increase and match stress in shape")
    hull: list[int] = []
    for i in range(eps.size):   # Andrew's monotone chain, upper hull
        while len(hull) >= 2:
            o, p = hull[-2], hull[-1]
            cross = (eps[p] - eps[o]) * (sig[i] - sig[o]) - (sig[p] - sig[o]) * (eps[i] - eps[o])
            if cross >= 0.0:
                hull.pop()
            else:
                break
        hull.append(i)
    pieces: list[dict] = []
    for i, j in zip(hull[:-1], hull[1:], strict=True):
        speed = math.sqrt((sig[j] - sig[i]) / (eps[j] - eps[i]) / rho0)
        kind = "fan" if j == i + 1 else "shock"
        if kind == "fan" and pieces and pieces[-1]["kind"] == "fan":
            pieces[-1]["end"] = j
            pieces[-1]["speeds"] = (pieces[-1]["speeds"][0], speed)
        else:
            pieces.append({"kind": kind, "start": i, "end": j, "speeds": (speed, speed)})
    return pieces


def monotone_loading_path(rho0: float, c0: float, s: float, shear_modulus: float,
                          flow_stress: Callable[[float], float],
                          strain: np.ndarray) -> np.ndarray:
    """Stress (Pa) on the monotone loading path of a ``Gamma0 = 0`` finite-plastic solid
    from the virgin state, with a general hardening law ``Y = flow_stress(eps_bar)``.

    With ``Gamma0 = 0`` the pressure is the principal Hugoniot stress
    ``p = rho0 c0^2 eps / (1 - s eps)^2`` whatever the energy, so the stress depends
    on the strain alone: ``sigma = p + S`` with ``S = (4/3) G eps`` up to yield and
    ``S = (2/3) Y(eps_bar)``, ``(4/3) G eps - 2 G eps_bar = S``, beyond it.
    """
    g = shear_modulus
    out = []
    for eps in np.asarray(strain, dtype=float).tolist():
        p = rho0 * c0 * c0 * eps / (1.0 - s * eps) ** 2
        trial = 4.0 * g * eps / 3.0
        if trial <= 2.0 * flow_stress(0.0) / 3.0:
            out.append(p + trial)
            continue

        def residual(ep, eps=eps):
            return 4.0 * g * eps / 3.0 - 2.0 * g * ep - 2.0 * flow_stress(ep) / 3.0

        lo, hi = 0.0, 2.0 * eps / 3.0
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            lo, hi = (mid, hi) if residual(mid) > 0.0 else (lo, mid)
            if hi - lo <= 1e-16 * max(hi, 1e-300):
                break
        out.append(p + 2.0 * flow_stress(0.5 * (lo + hi)) / 3.0)
    return np.asarray(out)
