"""Explosives: the unreacted solid, its detonation products and the detonation between them
(Davison ch. 13).

An explosive is one material with two phases.  The unreacted explosive is a
Mie–Grüneisen solid (``materials.mie_gruneisen``); the products follow
``materials.products`` (JWL or gamma law), with energies measured from the unreacted
explosive at rest so that the heat of detonation ``q`` is in the products' equation of
state.  ``State.plastic_strain`` carries the history variable, as the porous model's
compaction strain does: ``0`` for unreacted explosive, ``1`` (``BURNT``) for products.

Detonation.  A detonation is a reactive shock from an unreacted state ``a`` to a
products state ``b``: the mass, momentum and energy jumps of PHYSICS.md hold exactly,
with ``e_b`` on the products' equation of state, so ``b`` lies on the products'
Hugoniot centred on ``a`` (the detonation Hugoniot; it passes above ``a`` at ``v_a``
because of the heat released).  The Rayleigh line of a detonation of Lagrangian speed
``D`` (for ``a`` at rest and at ``v0`` the laboratory speed) is

    sigma - sigma_a = rho0^2 D^2 (v_a - v),

and ``D^2 = (sigma_H(v) - sigma_a) / (rho0^2 (v_a - v))`` along the Hugoniot has one
minimum: the Chapman–Jouguet point, where the Rayleigh line is tangent to the Hugoniot,

    sigma_H'(v) (v_a - v) + sigma_H(v) - sigma_a = 0,

the root found here (``cj_state``) whatever ``sigma_a`` is.  There the products move at
the sound speed relative to the front (``C_L = D``).  For gamma-law products and
``sigma_a = 0`` the root is the closed form ``D^2 = 2 (Gamma^2 - 1) q``, ``p_CJ = rho0
D^2/(Gamma + 1)``, ``u_CJ = D/(Gamma + 1)``, ``v_CJ = v0 Gamma/(Gamma + 1)``.  A stronger
drive than CJ (a flyer, a shock) gives an *overdriven* (strong) detonation: the state on
the Hugoniot above the CJ point, at the stress the neighbour imposes, with its speed
from the jump conditions.

The detonation's wave curve (``DetonationCurve``) from an unreacted state: above
``p_CJ`` the overdriven detonation; below it the CJ detonation followed by the products'
centred rarefaction (the Taylor wave, a fan on the products' isentrope through the CJ
state, whose head moves with the front).  ``u_b - u_a = d g(sigma)`` with ``g``
increasing and continuous (the Rayleigh line is tangent at CJ), so it meets any other
material's curve in ``materials.riemann``.  It does not pass through ``a``: an
explosive is metastable.  From an unreacted state the explosive's curve
(``UnreactedCurve``) therefore has two branches, the inert solid's for ``sigma <=
sigma_a`` and the detonation for ``sigma > sigma_a``; the Riemann solver takes the
detonation when the contact is compressed (``settle``), so any compression detonates
the explosive at once.  The reaction zone is infinitely thin and there is no run to
detonation: shock-to-detonation transition is not modelled.  An initiation (a
detonator) is the detonation branch imposed at a face (``Explosive.ignited``).
"""

from __future__ import annotations

import dataclasses
import functools
import math

from .base import Material, require_positive
from .errors import MaterialError, StateOutOfRangeError
from .mie_gruneisen import MieGruneisen
from .products import Products
from .roots import bracketed_newton
from .state import State
from .wavecurves import HydrodynamicWaveCurve, StressRange, check_curve_arguments
from .waves import Shock

BURNT = 1.0
"""``State.plastic_strain`` of detonation products (unreacted explosive: 0)."""


HEAD_LAG = 1e-12
"""Relative amount by which the Taylor wave's head characteristic is slower than the CJ
detonation it follows (equal in exact arithmetic)."""


def is_burnt(state: State) -> bool:
    """Whether ``state`` is a products state of an explosive (the flag survives the
    engine's weighted means of two products states, which may round it by an ulp)."""
    return state.plastic_strain > 0.5 * BURNT


def burnt(state: State) -> State:
    """``state`` marked as products."""
    return state if state.plastic_strain == BURNT else dataclasses.replace(
        state, plastic_strain=BURNT)


@dataclasses.dataclass(frozen=True, slots=True)
class Detonation:
    """The CJ point of the detonation from an unreacted state.

    ``speed``: Lagrangian detonation speed ``D`` (m/s; the laboratory speed for an
    explosive at rest at its initial density); ``state``: the CJ products state (moving
    in the detonation's direction, relative to the state ahead).
    """

    speed: float
    state: State


class Explosive(Material):
    """An explosive: unreacted Mie–Grüneisen solid ``unreacted`` and detonation products
    ``products`` of the same initial density (see the module docstring).

    ``D_cj``, ``p_cj`` (m/s, Pa): the tabulated CJ speed and pressure, kept for reports
    (the engine uses the CJ point of the products' equation of state).
    """

    splits_waves = True

    def __init__(self, name: str, unreacted: MieGruneisen, products: Products,
                 D_cj: float | None = None, p_cj: float | None = None):
        if abs(unreacted.rho0 - products.rho0) > 1e-12 * unreacted.rho0:
            raise MaterialError(f"{name}: the unreacted explosive ({unreacted.rho0:g} kg/m3) "
                                f"and its products ({products.rho0:g} kg/m3) must share rho0")
        self.name = name
        self.rho0 = unreacted.rho0
        self.unreacted = unreacted
        self.products = products
        self.D_cj = None if D_cj is None else require_positive("D_cj", D_cj, name)
        self.p_cj = None if p_cj is None else require_positive("p_cj", p_cj, name)
        # products carry no tension (their isentropes end at vacuum, sigma = 0), and the
        # unreacted explosive's small tensile strength is neglected: an interface of an
        # explosive layer opens under any tension (a plate driven off its products flies
        # free and the products expand into the gap)
        self.spall_strength = 0.0
        self.cj_state(self.reference_state())  # raises if the products have no CJ point

    def phase(self, state: State) -> Material:
        """The equation of state of ``state``: the products or the unreacted solid."""
        return self.products if is_burnt(state) else self.unreacted

    @property
    def ignited(self) -> Explosive:
        """This explosive as seen by a detonator: from an unreacted state every wave is
        the detonation (``DetonationCurve``), whatever the stress at the face."""
        return _Ignited(self)

    # --- Material interface (the history variable chooses the phase) ----------------------
    def initial_state(self, stress: float = 0.0, u: float = 0.0) -> State:
        if stress != 0.0:
            raise MaterialError(f"{self.name}: an explosive layer starts unstressed (a "
                                f"prestress would detonate it); got {stress!r} Pa")
        return self.reference_state(u)

    def stress(self, v: float, e: float) -> float:
        """Stress (Pa) of the unreacted explosive: ``(v, e)`` does not say the phase; the
        wave curves and the methods taking a state do."""
        return self.unreacted.stress(v, e)

    def sound_speed(self, v: float, e: float) -> float:
        """A speed scale (m/s): the larger of the two phases' Lagrangian sound speeds at
        ``(v, e)`` where each is defined (the phase is not a function of ``(v, e)``)."""
        speeds = [0.0]
        for phase in (self.unreacted, self.products):
            lo, hi = phase.volume_range()
            if lo < v < hi:
                try:
                    speeds.append(phase.sound_speed(v, e))
                except StateOutOfRangeError:
                    continue
        return max(speeds)

    def volume_range(self) -> tuple[float, float]:
        return self.products.volume_range()

    def hugoniot(self, ahead: State, v: float) -> tuple[float, float, float]:
        """The Hugoniot centred on ``ahead`` in its own phase (the detonation is on
        ``DetonationCurve``)."""
        return self.phase(ahead).hugoniot(ahead, v)

    def hugoniot_volume_limit(self, ahead: State) -> float:
        return self.phase(ahead).hugoniot_volume_limit(ahead)

    def isentrope(self, through: State, v: float) -> tuple[float, float]:
        return self.phase(through).isentrope(through, v)

    def riemann_integral(self, through: State, v: float, start: float | None = None) -> float:
        return self.phase(through).riemann_integral(through, v, start)

    def contact_reflection(self, left: State, right: State, amplitude: float) -> float:
        c_l = self.phase(left).sound_speed(left.v, left.e)
        c_r = self.phase(right).sound_speed(right.v, right.e)
        total = c_l + c_r
        return amplitude * abs(c_l - c_r) / total if total > 0.0 else abs(amplitude)

    def wave_curve(self, ahead: State, direction: int, release: str = "isentrope"):
        if is_burnt(ahead):
            return ProductsCurve(self.products, ahead, direction, release)
        return UnreactedCurve(self, ahead, direction, release)

    # --- detonation ---------------------------------------------------------------------------
    def cj_state(self, ahead: State) -> Detonation:
        """The CJ detonation from the unreacted state ``ahead`` (at rest relative to it).

        Raises ``MaterialError`` when the products' Hugoniot has no tangent Rayleigh line
        (no CJ point: the heat of detonation or the products' stiffness is not physical).
        """
        return self._cj(ahead.sigma, ahead.v, ahead.e)

    @functools.lru_cache(maxsize=64)  # noqa: B019 -- a material lives as long as its runs
    def _cj(self, sigma_a: float, v_a: float, e_a: float) -> Detonation:
        products = self.products
        a = State(sigma=sigma_a, u=0.0, v=v_a, e=e_a)

        def tangency(v):
            sigma, _, slope = products.hugoniot(a, v)
            return slope * (v_a - v) + sigma - sigma_a

        lo, hi = products.hugoniot_volume_limit(a), v_a * (1.0 - 1e-12)
        f_lo, f_hi = tangency(lo), tangency(hi)
        if not (f_lo < 0.0 < f_hi):
            self._no_cj_field(v_a)
            raise MaterialError(
                f"{self.name}: the products' Hugoniot has no Chapman-Jouguet point (no "
                f"Rayleigh line from {sigma_a / 1e9:.6g} GPa is tangent to it); check the "
                f"products parameters q, omega (or gamma), A, B, R1, R2")
        v = _bisect_secant(tangency, lo, hi, f_lo, f_hi)
        sigma, e, _ = products.hugoniot(a, v)
        if not (sigma > sigma_a and math.isfinite(sigma)):
            raise MaterialError(f"{self.name}: the products' CJ point is not compressive "
                                f"(p_CJ = {sigma / 1e9:.6g} GPa); check the products parameters")
        u = math.sqrt((sigma - sigma_a) * (v_a - v))
        speed = (sigma - sigma_a) / (self.rho0 * u)
        return Detonation(speed=speed,
                          state=State(sigma=sigma, u=u, v=v, e=e, plastic_strain=BURNT))

    def _no_cj_field(self, v_a: float) -> None:
        """Raise naming the JWL field that makes the products' stress negative at the
        explosive's own density (a term ``A (1 - omega/(R1 V)) exp(-R1 V)`` with ``R1 V <
        omega`` pulls the whole Hugoniot below the state ahead), if one does."""
        products, big_v = self.products, v_a * self.rho0
        for coef, rate, field in ((products.A, products.R1, "R1"),
                                  (products.B, products.R2, "R2")):
            if coef > 0.0 and rate * big_v < products.omega \
                    and products.stress(v_a, 0.0) <= 0.0:
                raise MaterialError(
                    f"{self.name}: the products' Hugoniot has no Chapman-Jouguet point: "
                    f"{field} = {rate:g} makes the products' stress at the explosive's "
                    f"density {products.stress(v_a, 0.0) / 1e9:.6g} GPa; {field} must be > "
                    f"omega = {products.omega:g}")

    def overdriven_state(self, ahead: State, sigma: float, direction: int = 1) -> State:
        """The products state behind an overdriven detonation to stress ``sigma`` (Pa, at
        least the CJ stress) from the unreacted ``ahead``: on the strong branch of the
        detonation Hugoniot, ``u_b - u_a = d sqrt((sigma - sigma_a)(v_a - v))``."""
        return DetonationCurve(self, ahead, direction).state_at(sigma)

    def __repr__(self) -> str:
        return f"Explosive({self.name!r})"


def _bisect_secant(func, lo: float, hi: float, f_lo: float, f_hi: float) -> float:
    """Root of an increasing ``func`` bracketed by ``lo < hi`` (Illinois false position,
    then bisection), to a few ulps of ``v``."""
    for _ in range(200):
        if hi - lo <= 4.0 * math.ulp(hi):
            break
        mid = hi - f_hi * (hi - lo) / (f_hi - f_lo)
        if not lo < mid < hi:
            mid = 0.5 * (lo + hi)
        f_mid = func(mid)
        if f_mid == 0.0:
            return mid
        if f_mid < 0.0:
            lo, f_lo = mid, f_mid
            f_hi *= 0.5
        else:
            hi, f_hi = mid, f_mid
            f_lo *= 0.5
    return lo if abs(f_lo) < abs(f_hi) else hi


class _Ignited(Explosive):
    """An ``Explosive`` whose unreacted states detonate whatever the wave (a detonator)."""

    def __init__(self, explosive: Explosive):  # noqa: D107 -- shares the explosive's data
        self.__dict__.update(explosive.__dict__)
        self.base = explosive

    def wave_curve(self, ahead: State, direction: int, release: str = "isentrope"):
        if is_burnt(ahead):
            return self.base.wave_curve(ahead, direction, release)
        return DetonationCurve(self.base, ahead, direction, release)

    def cj_state(self, ahead: State) -> Detonation:
        return self.base.cj_state(ahead)


class ProductsCurve(HydrodynamicWaveCurve):
    """Wave curve of detonation products: the hydrodynamic curve of the products'
    equation of state, its states marked ``BURNT``."""

    def __init__(self, products: Products, ahead: State, direction: int,
                 release: str = "isentrope"):
        super().__init__(products, burnt(ahead), direction, release)

    def _state_at(self, sigma: float) -> State:
        return burnt(super()._state_at(sigma))

    def _energy(self, sigma: float, v: float) -> float:
        if math.isinf(v):
            return -self.material.q  # vacuum: the products' thermal energy is spent
        return super()._energy(sigma, v)

    def characteristic_speed(self, sigma: float) -> float:
        """Lagrangian sound speed (m/s) of the state of stress ``sigma`` on the curve."""
        state = self.state_at(sigma)
        return self.material.sound_speed(state.v, state.e)


class DetonationCurve(StressRange):
    """The detonation's wave curve from an unreacted state (module docstring): the CJ
    detonation and its Taylor wave below ``p_CJ``, the overdriven detonation above."""

    def __init__(self, explosive: Explosive, ahead: State, direction: int,
                 release: str = "isentrope"):
        check_curve_arguments(direction, release)
        self.material = explosive
        self.ahead = ahead
        self.direction = direction
        self.release = release
        self.cj = explosive.cj_state(ahead)
        self.cj_state = dataclasses.replace(self.cj.state, u=ahead.u + direction * self.cj.state.u)
        self.g_cj = self.cj.state.u
        self.fan = ProductsCurve(explosive.products, self.cj_state, direction, release)
        self.impedance = explosive.rho0 * self.cj.speed
        self._last: tuple[float, float] | None = None

    # --- range ----------------------------------------------------------------------------
    def sigma_limits(self) -> tuple[float, float]:
        return self.sigma_min(), self.sigma_max()

    def sigma_min(self) -> float:
        return self.fan.sigma_min()

    def sigma_max(self) -> float:
        products, a = self.material.products, self.ahead
        return products.hugoniot(a, products.hugoniot_volume_limit(a))[0]

    # --- the curve --------------------------------------------------------------------------
    def _overdriven_volume(self, sigma: float) -> float:
        """Volume on the strong branch of the detonation Hugoniot at ``sigma``."""
        if self._last is not None and self._last[0] == sigma:
            return self._last[1]
        products, a = self.material.products, self.ahead
        if sigma == self.cj.state.sigma:
            return self.cj.state.v

        def residual(v):
            s, _, ds = products.hugoniot(a, v)
            return s - sigma, ds

        self.check_stress(sigma)
        lo = products.hugoniot_volume_limit(a)
        v = bracketed_newton(residual, lo, self.cj.state.v, rel_tol=2e-16)
        self._last = (sigma, v)
        return v

    def velocity_change(self, sigma: float) -> tuple[float, float]:
        """``(g, dg/dsigma)``: ``u - u_a = d g``."""
        if sigma < self.cj.state.sigma:
            g, dg = self.fan.velocity_change(sigma)
            return self.g_cj + g, dg
        a = self.ahead
        v = self._overdriven_volume(sigma)
        g = math.sqrt((sigma - a.sigma) * (a.v - v))
        slope = self.material.products.hugoniot(a, v)[2]
        return g, ((a.v - v) - (sigma - a.sigma) / slope) / (2.0 * g)

    def state_at(self, sigma: float) -> State:
        """The products state behind the detonation (and its Taylor wave) at ``sigma``."""
        if sigma < self.cj.state.sigma:
            return self.fan.state_at(sigma)
        a = self.ahead
        v = self._overdriven_volume(sigma)
        e = self.material.products.hugoniot(a, v)[1]
        g = math.sqrt((sigma - a.sigma) * (a.v - v))
        return State(sigma=float(sigma), u=a.u + self.direction * g, v=v, e=e,
                     plastic_strain=BURNT)

    def waves(self, sigma: float) -> tuple:
        """The detonation (a reactive ``Shock``), then the Taylor fan below ``p_CJ``."""
        a, d = self.ahead, self.direction
        if sigma < self.cj.state.sigma:
            front = Shock(ahead=a, behind=self.cj_state, speed=d * self.cj.speed, direction=d)
            (fan,) = self.fan.waves(sigma)
            if isinstance(fan, Shock):
                # ``release = "hugoniot"``: the Taylor wave is one rarefaction shock, its
                # chord under the Rayleigh line's tangency slower than D
                return (front, fan)
            # the Taylor wave's head is sonic, C_L(CJ) = D; it is given a speed a hair
            # (HEAD_LAG) below D, never an ulp above, so that it never overtakes the
            # detonation and the CJ cell between them keeps its place in X
            return (front, dataclasses.replace(fan, head_speed=front.speed * (1.0 - HEAD_LAG)))
        behind = self.state_at(sigma)
        speed = (behind.sigma - a.sigma) / (self.material.rho0 * (behind.u - a.u))
        return (Shock(ahead=a, behind=behind, speed=speed, direction=d),)

    def characteristic_speed(self, sigma: float) -> float:
        """Lagrangian sound speed (m/s) of the products at ``sigma`` on the Taylor wave."""
        return self.fan.characteristic_speed(sigma)


class UnreactedCurve(StressRange):
    """Wave curve of an unreacted explosive: the inert solid's curve for ``sigma <=
    sigma_a``, the detonation's above (a jump at ``sigma_a``: the explosive is
    metastable).  ``settle`` picks the branch a Riemann problem takes."""

    def __init__(self, explosive: Explosive, ahead: State, direction: int,
                 release: str = "isentrope"):
        check_curve_arguments(direction, release)
        self.material = explosive
        self.ahead = ahead
        self.direction = direction
        self.release = release
        self.inert = explosive.unreacted.wave_curve(ahead, direction, release)
        self.impedance = self.inert.impedance

    @functools.cached_property
    def detonation(self) -> DetonationCurve:
        return DetonationCurve(self.material, self.ahead, self.direction, self.release)

    def settle(self, other_g: float) -> StressRange:
        """The branch a Riemann problem takes: ``other_g`` is the velocity mismatch at
        ``sigma_a`` (``g_other(sigma_a) + u_R - u_L``, m/s, or the required ``-g`` at a
        boundary); negative means the contact is compressed, and the explosive
        detonates."""
        return self.detonation if other_g < 0.0 else self.inert

    def _branch(self, sigma: float):
        return self.inert if sigma <= self.ahead.sigma else self.detonation

    def sigma_limits(self) -> tuple[float, float]:
        return self.inert.sigma_min(), self.detonation.sigma_max()

    def sigma_min(self) -> float:
        return self.inert.sigma_min()

    def sigma_max(self) -> float:
        return self.detonation.sigma_max()

    def velocity_change(self, sigma: float) -> tuple[float, float]:
        return self._branch(sigma).velocity_change(sigma)

    def state_at(self, sigma: float) -> State:
        return self._branch(sigma).state_at(sigma)

    def waves(self, sigma: float) -> tuple:
        return self._branch(sigma).waves(sigma)


def gamma_law_explosive(name: str, rho0: float, gamma: float, q: float,
                        unreacted: MieGruneisen) -> Explosive:
    """An explosive with gamma-law products (Davison §13.1): ``sigma = (gamma - 1)(e +
    q)/v``."""
    return Explosive(name, unreacted, Products.gamma_law(name, rho0, gamma, q))
