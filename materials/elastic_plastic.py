"""Ideal elastic–plastic solid in uniaxial strain (small strain; Davison ch. 7).

Conventions of PHYSICS.md: stress ``sigma`` positive in compression (Pa),
compression ``eps = 1 - v/v0`` (positive when compressed), SI units.

Strains and stresses
--------------------
In uniaxial strain the total strain tensor is ``diag(eps, 0, 0)`` (compression
positive).  Plastic flow is isochoric, so the plastic strain tensor is
``diag(eps_p, -eps_p/2, -eps_p/2)``: ``eps_p`` (``State.plastic_strain``) is its
longitudinal component, compression positive.  The elastic strain is the
difference, ``diag(eps - eps_p, eps_p/2, eps_p/2)``; its trace is ``eps`` and
its deviator has the longitudinal component ``2 eps/3 - eps_p``.  Hooke's law
on the elastic strain splits into a mean and a deviatoric part:

    p     = K eps,                          K = lambda + 2 mu/3   (mean stress)
    S     = sigma - p = 2 mu (2 eps/3 - eps_p) = (4/3) mu (eps - 3 eps_p/2)
    sigma = K eps + (4/3) mu (eps - 3 eps_p/2) = (lambda + 2 mu) eps - 2 mu eps_p.

(Written with the rescaled offset ``eps_p' = 3 eps_p/2`` this is the form
``sigma = (lambda + 2 mu)(eps - eps_p') + K eps_p' = K eps + (4/3) mu (eps - eps_p')``;
the stored ``plastic_strain`` is the tensor component ``eps_p``, the quantity
whose increments measure plastic work, see below.)

Yield (von Mises, ideal plasticity).  The principal deviators are ``S`` and
``-S/2`` twice, so ``sqrt(3 J2) = 3|S|/2`` and the yield condition reads

    |S| = |sigma - p| <= 2Y/3,      i.e.  |2 mu (2 eps/3 - eps_p)| <= 2Y/3.

Plastic flow keeps ``|S| = 2Y/3``, hence ``d eps_p = (2/3) d eps`` on a plastic
branch.  These reproduce the paths of PHYSICS.md:

- elastic (``eps_p`` fixed): slope ``lambda + 2 mu``, speed ``C0 = sqrt((lambda + 2 mu)/rho0)``;
- yield from the unstressed state at ``eps = Y/(2 mu)``, the Hugoniot elastic
  limit ``sigma_HEL = (lambda + 2 mu) Y/(2 mu)``;
- plastic loading on ``sigma = K eps + 2Y/3`` (``S = +2Y/3``), speed ``CB = sqrt(K/rho0)``;
- unloading from there is elastic until ``S = -2Y/3``: a strain ``Y/mu``, a
  stress drop of ``(lambda + 2 mu) Y/mu = 2 sigma_HEL``; then reverse plastic
  flow on ``sigma = K eps - 2Y/3``.

An admissible state has ``|S| <= 2Y/3``; its own yield stresses (the ends of
its elastic range) follow from its ``S``: a state already compressed
plastically reloads elastically only up to its own yield surface (memory).

Waves
-----
All branches are straight lines in the sigma–eps plane, so every wave is a
discontinuity (``Shock``) at the branch's constant speed: there are no fans,
and release waves are rarefaction shocks exactly.  A jump from an ahead state
to a stress beyond its elastic range splits into an elastic precursor (speed
``C0``) to the yield stress and a plastic shock (speed ``CB``) behind it.  The
Lax condition holds: ``CB < C0`` because ``mu > 0``, so the plastic shock always
trails its precursor.  With the linear plastic branch here the plastic shock
never overtakes the precursor at any stress; the "overdriven" single shock of
real metals (a plastic Hugoniot stiffening until ``Us > C0``) needs a nonlinear
pressure law, which this small-strain model does not have.

Energy
------
Stress does not depend on the internal energy ``e`` (a purely mechanical
model).  ``e`` (J/kg) is still carried and follows from the jump conditions,
``e_b - e_a = 1/2 (sigma_a + sigma_b)(v_a - v_b)``, so that the energy balance
of a scene closes.  The stored (elastic) strain energy per unit mass is

    W(eps, eps_p) = v0 [ K eps^2 / 2  +  (3/8) S^2 / mu ],

the work of the mean stress on the volumetric strain plus the shear energy of
the elastic deviator (``dW/d eps = v0 sigma`` at fixed ``eps_p``), and the
dissipated energy is ``e - W``, zero in the virgin state (``e = 0``).  Along
an elastic jump both ends lie on one straight line, the Rankine–Hugoniot
trapezoid is the exact work and the dissipation does not change.  A plastic
jump starts on the yield surface and stays on it (the wave curve always puts
the precursor first), so the trapezoid is again the exact work along the
plastic line and the dissipation grows by the plastic work,
``v0 S d eps = v0 Y |d eps_p|`` (J/kg) — never negative.
"""

from __future__ import annotations

import math

from .base import Material, require_number, require_positive
from .errors import MaterialError, StateOutOfRangeError
from .state import RIGHT, State
from .wavecurves import StressRange, check_curve_arguments
from .waves import Shock

_SNAP = 1e-12
"""A state whose deviator is within this fraction of its stress scale of the yield
surface is on it (no zero-strength precursor from rounding)."""

_EPS = 2.0**-52
"""Machine epsilon: the rounding of a strain computed from a volume."""

_CONSISTENCY = 1e-9
"""Relative slack for a state's stress against the law at its strains, and for a
deviator just outside the yield surface (clamped onto it)."""


class ElasticPlastic(Material):
    """Small-strain ideal elastic–plastic solid in uniaxial strain.

    ``rho0`` reference density (kg/m^3); ``lam``, ``mu`` the Lamé constants (Pa);
    ``yield_strength`` the yield stress ``Y`` in simple tension (Pa, >= 0;
    ``math.inf`` for a solid that never yields, i.e. linear elastic);
    ``spall_strength`` the tension (Pa) at which it fractures.

    Derived: ``bulk_modulus`` K, ``longitudinal_modulus`` lambda + 2 mu, ``C0``
    and ``CB`` (m/s), ``hel`` the Hugoniot elastic limit (Pa).
    """

    is_linear = False
    makes_fans = False
    splits_waves = True
    linear_branches = True
    """Not a single-speed solid: waves travel at C0 or CB (``HydrodynamicWaveCurve``
    reads ``is_linear`` to force Hugoniot release at one speed)."""

    def __init__(self, name: str, rho0: float, lam: float, mu: float, yield_strength: float,
                 spall_strength: float = math.inf):
        self.name = name
        self.rho0 = require_positive("rho0", rho0, name)
        self.lam = require_number("lambda", lam, name)
        self.mu = require_positive("mu", mu, name)
        self.yield_strength = _yield_strength(name, yield_strength)
        self.spall_strength = _spall_strength(name, spall_strength)
        self.longitudinal_modulus = self.lam + 2.0 * self.mu
        self.bulk_modulus = self.lam + 2.0 * self.mu / 3.0
        if not (self.bulk_modulus > 0.0 and math.isfinite(self.longitudinal_modulus)):
            raise MaterialError(f"{name}: the bulk modulus lambda + 2 mu/3 must be finite and "
                                f"> 0, got {self.bulk_modulus:.6g} Pa")
        self.C0 = math.sqrt(self.longitudinal_modulus / self.rho0)
        self.CB = math.sqrt(self.bulk_modulus / self.rho0)
        self.hel = self.longitudinal_modulus * self.yield_strength / (2.0 * self.mu)
        # read at every event of a ringing plate (``yield_stresses``, the wave curves,
        # ``materials.elastic_contact``): computed once
        self.impedance = self.rho0 * self.C0
        """Elastic impedance ``rho0 C0`` (kg/(m^2 s))."""
        self.bulk_impedance = self.rho0 * self.CB
        """Plastic impedance ``rho0 CB`` (kg/(m^2 s))."""
        self._two_mu = 2.0 * self.mu
        self._yield_limit = 2.0 * self.yield_strength / 3.0  # |S| on the yield surface
        self._yield_factor = 0.75 * self.longitudinal_modulus / self.mu  # d sigma / d S
        # near zero strain the slack of the law is the rounding of the strain itself (a
        # few ulps of the volume: 1e-15 of strain is 3e-4 Pa in steel, above 1e-9 of M 1e-6)
        self._law_rounding = 64.0 * _EPS * self.longitudinal_modulus

    @classmethod
    def from_speeds(cls, name: str, rho0: float, c0: float, poisson: float,
                    yield_strength: float, spall_strength: float = math.inf) -> ElasticPlastic:
        """From the longitudinal speed ``c0`` (m/s) and Poisson's ratio.

        ``lambda + 2 mu = rho0 c0^2``, ``lambda = rho0 c0^2 nu/(1 - nu)``,
        ``mu = rho0 c0^2 (1 - 2 nu)/(2 (1 - nu))``.
        """
        rho0 = require_positive("rho0", rho0, name)
        modulus = rho0 * require_positive("c0", c0, name) ** 2
        nu = require_number("poisson", poisson, name)
        if not -1.0 < nu < 0.5:
            raise MaterialError(f"{name}: poisson must be in (-1, 0.5), got {poisson!r}")
        return cls(name, rho0, modulus * nu / (1.0 - nu),
                   modulus * (1.0 - 2.0 * nu) / (2.0 * (1.0 - nu)), yield_strength,
                   spall_strength)

    # --- strains, stress, yield -------------------------------------------------
    def strain(self, v: float) -> float:
        """Compression ``eps = 1 - v/v0`` (exactly 0 at ``v0``)."""
        return 1.0 - v / self.v0

    def stress_at(self, v: float, plastic_strain: float = 0.0) -> float:
        """``sigma = (lambda + 2 mu) eps - 2 mu eps_p`` (Pa) at volume ``v`` and plastic strain."""
        return self.longitudinal_modulus * self.strain(v) - 2.0 * self.mu * plastic_strain

    def deviator(self, state: State) -> float:
        """Stress deviator ``S = sigma - p = 2 mu (2 eps/3 - eps_p)`` (Pa, compression positive).

        Computed from the strains (``v`` and ``plastic_strain``), not from ``sigma``.
        """
        return 2.0 * self.mu * (2.0 * self.strain(state.v) / 3.0 - state.plastic_strain)

    def mean_stress(self, v: float) -> float:
        """Mean stress (pressure) ``p = K eps`` (Pa): plastic flow does not change it."""
        return self.bulk_modulus * self.strain(v)

    def strained_state(self, v: float, plastic_strain: float = 0.0, e: float = 0.0,
                       u: float = 0.0) -> State:
        """The state at volume ``v`` with ``plastic_strain``, checked against the yield surface."""
        self.check_volume(v)
        state = State(sigma=self.stress_at(v, plastic_strain), u=u, v=v, e=e,
                      plastic_strain=plastic_strain)
        self.yield_stresses(state)
        return state

    def yield_stresses(self, state: State, check: bool = True) -> tuple[float, float]:
        """``(low, high)``: the stresses (Pa) at which ``state`` yields on unloading and loading.

        They bound its elastic range: ``high = sigma + (2Y/3 - S) 3 (lambda + 2 mu)/(4 mu)``
        and ``low = sigma - (2Y/3 + S) 3 (lambda + 2 mu)/(4 mu)``; ``high == sigma``
        (or ``low == sigma``) on the yield surface.  Raises ``StateOutOfRangeError``
        if the state's stress disagrees with the law at its strains (a plastically
        strained state without its ``plastic_strain``) or lies outside the yield
        surface.  ``check=False`` skips the comparison with the law, for states this
        model's own jumps made (the hot path of ``materials.elastic_contact``).
        """
        # the arithmetic of strain() and deviator(), inlined (the hot path of a ringing plate)
        eps, ep, sigma = 1.0 - state.v / self.v0, state.plastic_strain, state.sigma
        scale = abs(sigma) + self.longitudinal_modulus * (abs(eps) + 1e-6) + self._two_mu * abs(ep)
        if check and not abs(self.longitudinal_modulus * eps - self._two_mu * ep - sigma) \
                <= _CONSISTENCY * scale + self._law_rounding:
            self._check_law(state, scale)  # raises, naming the law's stress
        limit = self._yield_limit
        if limit == math.inf:
            return -math.inf, math.inf
        s = self._two_mu * (2.0 * eps / 3.0 - ep)
        room_up, room_down = limit - s, limit + s
        if min(room_up, room_down) < -_CONSISTENCY * scale:
            raise StateOutOfRangeError(
                f"{self.name}: the state's stress deviator {s / 1e9:.6g} GPa is outside the "
                f"yield surface |sigma - p| <= 2Y/3 = {limit / 1e9:.6g} GPa")
        snap = _SNAP * scale
        room_up = 0.0 if room_up <= snap else room_up
        room_down = 0.0 if room_down <= snap else room_down
        factor = self._yield_factor
        return sigma - room_down * factor, sigma + room_up * factor

    def _check_law(self, state: State, scale: float) -> None:
        """Raise ``StateOutOfRangeError`` if ``state.sigma`` is not the law's stress at
        its volume and plastic strain (within ``_CONSISTENCY`` of ``scale``, Pa)."""
        ep = state.plastic_strain
        law = self.stress_at(state.v, ep)
        if not abs(law - state.sigma) <= _CONSISTENCY * scale + self._law_rounding:
            raise StateOutOfRangeError(
                f"{self.name}: stress {state.sigma / 1e9:.9g} GPa disagrees with the "
                f"elastic–plastic law at that volume and plastic strain {ep:.6g} "
                f"({law / 1e9:.9g} GPa); is the state's plastic_strain missing?")

    # --- energy -------------------------------------------------------------------
    def stored_energy(self, state: State) -> float:
        """Elastic strain energy (J/kg): ``v0 (K eps^2/2 + (3/8) S^2/mu)``."""
        eps, s = self.strain(state.v), self.deviator(state)
        return self.v0 * (0.5 * self.bulk_modulus * eps * eps + 0.375 * s * s / self.mu)

    def dissipated_energy(self, state: State) -> float:
        """Energy dissipated by plastic work (J/kg): ``e - stored_energy``.

        It is the accumulated ``v0 Y |d eps_p|`` along the states' history when
        ``e`` started at 0 in the virgin material and came from the jump conditions.
        """
        return state.e - self.stored_energy(state)

    # --- Material interface ---------------------------------------------------------
    def stress(self, v: float, e: float) -> float:
        """Stress of the *virgin* material (``plastic_strain = 0``): ``(lambda + 2 mu) eps``.

        ``(v, e)`` does not determine the stress of an elastic–plastic solid: it
        depends on the plastic strain, a history variable (use ``stress_at``).
        This answer is the only unambiguous one, valid inside the virgin elastic
        range ``|eps| <= Y/(2 mu)``; beyond it a state without plastic strain is
        inadmissible and ``StateOutOfRangeError`` is raised rather than a wrong stress.
        """
        eps = self.strain(v)
        limit = self.yield_strength / (2.0 * self.mu)
        if abs(eps) > limit * (1.0 + _SNAP) + 4.0 * _EPS:
            raise StateOutOfRangeError(
                f"{self.name}: compression {eps:.6g} is beyond the elastic range "
                f"(+-{limit:.6g}) of the virgin material; the stress depends on the plastic "
                f"strain there (use stress_at(v, plastic_strain) or the wave curves)")
        return self.longitudinal_modulus * eps

    def sound_speed(self, v: float, e: float) -> float:
        """The elastic longitudinal speed ``C0`` (m/s): small disturbances of a state inside
        the yield surface, and any unloading, travel at ``C0``; plastic waves at ``CB``."""
        return self.C0

    def contact_reflection(self, left: State, right: State, amplitude: float) -> float:
        """Stress (Pa) a wave of ``amplitude`` reflects from a jump in plastic strain.

        Both sides have the elastic impedance ``rho0 C0``, but at equal stress a
        plastic-strain jump ``d eps_p`` offsets their yield stresses by
        ``(3/2) K d eps_p``: a wave that yields one side and not the other splits
        differently on the two sides, and the difference it reflects is at most
        that offset (and at most the wave itself).
        """
        if math.isinf(self.yield_strength):
            return 0.0
        (low_l, high_l), (low_r, high_r) = self.yield_stresses(left), self.yield_stresses(right)
        return min(abs(amplitude), max(abs(low_l - low_r), abs(high_l - high_r)))

    def volume_range(self) -> tuple[float, float]:
        # As for LinearElastic: the law has no spinodal; the upper bound must be finite
        # (wave curves read an infinite one as expansion to vacuum).
        return (1e-9 * self.v0, 1e3 * self.v0)

    def hugoniot(self, ahead: State, v: float) -> tuple[float, float, float]:
        """``(sigma, e, dsigma/dv)`` reached from ``ahead`` at volume ``v`` by the split wave.

        This is the elastic–plastic path (precursor to the yield stress, then the
        plastic shock), with ``e`` the sum of the Rankine–Hugoniot energies of the
        two jumps — what the wave curve and the engine produce.  Where the path
        crosses a yield stress this ``e`` is *not* that of a single (unstable,
        overdriven) shock from ``ahead``; ``sigma`` is the same, since it does not
        depend on ``e``.  At a yield volume the slope is the plastic one.
        """
        return ElasticPlasticWaveCurve(self, ahead, RIGHT).at_volume(v)

    def hugoniot_volume_limit(self, ahead: State) -> float:
        return self.volume_range()[0]

    def isentrope(self, through: State, v: float) -> tuple[float, float]:
        """``(sigma, e)`` on the quasi-static elastic–plastic path from ``through`` to ``v``.

        ``de = -sigma dv`` along it.  Its branches are straight, so it coincides
        with the states of the split waves (``hugoniot``).  The elastic parts are
        isentropic; the plastic parts dissipate (the model has no entropy, so
        "isentrope" names the reversible-looking path the release waves follow).
        """
        return ElasticPlasticWaveCurve(self, through, RIGHT).at_volume(v)[:2]

    def riemann_integral(self, through: State, v: float, start: float | None = None) -> float:
        """``J = int rho0 C dv`` along the elastic–plastic path from ``through`` (m/s).

        ``C`` is ``C0`` on the elastic part and ``CB`` on the plastic part, so
        ``u - u_through = -J`` across a right-going wave, as for a fluid.
        """
        curve = ElasticPlasticWaveCurve(self, through, RIGHT)
        j = curve.riemann_integral(v)
        return j if start is None else j - curve.riemann_integral(start)

    def wave_curve(self, ahead: State, direction: int, release: str = "isentrope"):
        """The composite elastic–plastic wave curve from ``ahead`` (see the module docstring).

        ``release`` is accepted for the common interface and ignored: every branch
        is straight, so isentropic and Hugoniot release coincide and are exact
        rarefaction shocks.
        """
        return ElasticPlasticWaveCurve(self, ahead, direction, release)


class ElasticPlasticWaveCurve(StressRange):
    """Wave curve of an ``ElasticPlastic`` solid: elastic precursor plus plastic shock.

    From the ahead state ``a`` with yield stresses ``low <= sigma_a <= high``
    (``ElasticPlastic.yield_stresses``), a target ``sigma`` is reached by

    - one elastic shock at ``C0`` if ``low < sigma < high``;
    - an elastic shock at ``C0`` to ``high`` then a plastic shock at ``CB`` if
      ``sigma > high`` (loading), or to ``low`` then on at ``CB`` if ``sigma < low``
      (unloading and reverse yield).

    With ``Z0 = rho0 C0`` and ``ZB = rho0 CB``, ``u = u_a + d g(sigma)`` with the
    continuous, piecewise-linear, increasing

        g = (sigma_knee - sigma_a)/Z0 + (sigma - sigma_knee)/ZB,

    ``sigma_knee`` the yield stress crossed (or ``sigma`` itself inside the
    elastic range).  ``dg/dsigma`` is ``1/Z0`` or ``1/ZB``; at a yield stress it is
    that of the branch beyond it, at ``sigma_a`` itself ``1/Z0``.
    """

    def __init__(self, material: ElasticPlastic, ahead: State, direction: int,
                 release: str = "isentrope"):
        check_curve_arguments(direction, release)
        self.material = material
        self.ahead = ahead
        self.direction = direction
        self.release = release  # recorded only: isentrope and Hugoniot release coincide
        self.yield_low, self.yield_high = material.yield_stresses(ahead)
        self._last: tuple[float, tuple[State, State]] | None = None
        self._limits: tuple[float, float] | None = None

    @property
    def impedance(self) -> float:
        """Elastic impedance ``rho0 C0``: the slope of the curve at its centre."""
        return self.material.impedance

    # --- range ------------------------------------------------------------------------
    def sigma_limits(self) -> tuple[float, float]:
        """Stress range ``(lowest, highest)`` reachable inside the model's volume range."""
        if self._limits is None:  # every velocity_change checks it: computed once per curve
            self._limits = (self.sigma_min(), self.sigma_max())
        return self._limits

    def linear_breaks(self) -> tuple[float, ...]:
        """The stresses (Pa) where ``g`` changes slope: the finite yield stresses.

        Between them, and beyond them up to the range's ends, ``g`` is linear in
        ``sigma`` (slopes ``1/Z0`` inside the elastic range, ``1/ZB`` beyond), so a
        contact between two such curves has a closed-form stress
        (``materials.riemann``).
        """
        return tuple(s for s in (self.yield_low, self.yield_high) if math.isfinite(s))

    def sigma_max(self) -> float:
        """Stress at the smallest volume of the model's range."""
        return max(self.at_volume(self.material.volume_range()[0])[0], self.ahead.sigma)

    def sigma_min(self) -> float:
        """Stress at the largest volume of the model's range (a tension)."""
        return min(self.at_volume(self.material.volume_range()[1])[0], self.ahead.sigma)

    # --- the curve ----------------------------------------------------------------------
    def _knee(self, sigma: float) -> float:
        """End stress of the elastic part of the jump to ``sigma``.

        A target within rounding (``_SNAP`` relative) of a yield stress is reached
        by the elastic wave alone, never with a zero-strength plastic shock.
        """
        if sigma >= self.yield_high:
            knee = self.yield_high
        elif sigma <= self.yield_low:
            knee = self.yield_low
        else:
            return sigma
        return sigma if abs(sigma - knee) <= _SNAP * abs(knee) else knee

    def velocity_change(self, sigma: float) -> tuple[float, float]:
        """``(g, dg/dsigma)``: the particle-velocity change ``u - u_a = d * g`` (m/s, m/s/Pa)."""
        mat, sa = self.material, self.ahead.sigma
        if sigma == sa:
            return 0.0, 1.0 / mat.impedance
        self.check_stress(sigma)
        knee = self._knee(sigma)
        g = (knee - sa) / mat.impedance + (sigma - knee) / mat.bulk_impedance
        elastic = self.yield_low < sigma < self.yield_high
        return g, 1.0 / (mat.impedance if elastic else mat.bulk_impedance)

    def _states(self, sigma: float) -> tuple[State, State]:
        """``(yield, behind)``: the state behind the precursor and behind the whole wave."""
        if self._last is not None and self._last[0] == sigma:
            return self._last[1]
        self.check_stress(sigma)
        a = self.ahead
        knee = self._knee(sigma)
        middle = a if knee == a.sigma else self._jump(a, knee, plastic=False)
        behind = middle if sigma == knee else self._jump(middle, sigma, plastic=True)
        self._last = (sigma, (middle, behind))
        return middle, behind

    def _jump(self, a: State, sigma: float, plastic: bool) -> State:
        """The state a shock of one branch reaches from ``a`` (``branch_jump``)."""
        return branch_jump(self.material, a, sigma, self.direction, plastic)

    def state_at(self, sigma: float) -> State:
        """The state behind the wave that reaches stress ``sigma``."""
        if sigma == self.ahead.sigma:
            return self.ahead
        return self._states(sigma)[1]

    def waves(self, sigma: float) -> tuple:
        """The precursor and the plastic shock (leading first), zero-strength parts omitted."""
        a = self.ahead
        if sigma == a.sigma:
            return ()
        mat, d = self.material, self.direction
        middle, behind = self._states(sigma)
        waves = []
        if middle is not a:
            waves.append(Shock(ahead=a, behind=middle, speed=d * mat.C0, direction=d))
        if behind is not middle:
            waves.append(Shock(ahead=middle, behind=behind, speed=d * mat.CB, direction=d))
        return tuple(waves)

    # --- the same path by volume (Material.hugoniot, isentrope, riemann_integral) ---------
    def _volume_knee(self, v: float) -> tuple[float, float]:
        """``(sigma_knee, v_knee)``: the yield point the path to volume ``v`` crosses.

        ``(nan, nan)`` if the path stays elastic.  At a yield volume the knee is
        returned (the plastic branch beyond it is the one reported).
        """
        a, mat = self.ahead, self.material
        deps = (a.v - v) * mat.rho0
        for knee, sign in ((self.yield_high, 1.0), (self.yield_low, -1.0)):
            deps_knee = (knee - a.sigma) / mat.longitudinal_modulus
            if math.isfinite(knee) and sign * (deps - deps_knee) >= 0.0 and sign * deps > 0.0:
                return knee, a.v - deps_knee / mat.rho0
        return math.nan, math.nan

    def at_volume(self, v: float) -> tuple[float, float, float]:
        """``(sigma, e, dsigma/dv)`` on the path from ``ahead`` to volume ``v`` (m^3/kg)."""
        a, mat = self.ahead, self.material
        knee, v_knee = self._volume_knee(v)
        if math.isnan(knee):
            sigma = a.sigma + mat.longitudinal_modulus * (a.v - v) * mat.rho0
            e = a.e + 0.5 * (a.sigma + sigma) * (a.v - v)
            return sigma, e, -mat.longitudinal_modulus * mat.rho0
        e_knee = a.e + 0.5 * (a.sigma + knee) * (a.v - v_knee)
        sigma = knee + mat.bulk_modulus * (v_knee - v) * mat.rho0
        e = e_knee + 0.5 * (knee + sigma) * (v_knee - v)
        return sigma, e, -mat.bulk_modulus * mat.rho0

    def riemann_integral(self, v: float) -> float:
        """``J = int_{v_a}^{v} rho0 C dv`` along the path (m/s): ``g = -J`` at that volume."""
        a, mat = self.ahead, self.material
        knee, v_knee = self._volume_knee(v)
        if math.isnan(knee):
            return mat.impedance * (v - a.v)
        return mat.impedance * (v_knee - a.v) + mat.bulk_impedance * (v - v_knee)


def branch_jump(material: ElasticPlastic, a: State, sigma: float, direction: int,
                plastic: bool) -> State:
    """The state a shock on one straight branch reaches from ``a`` at stress ``sigma`` (Pa).

    On the elastic branch ``d sigma = (lambda + 2 mu) d eps`` at speed ``C0``, on the
    plastic one ``d sigma = K d eps`` at ``CB`` with ``d eps_p = (2/3) d eps``; the jump
    conditions give ``u_b = u_a + d (sigma - sigma_a)/(rho0 C)`` for a wave running in
    ``direction`` ``d`` and ``e_b = e_a + (sigma_a + sigma)(v_a - v_b)/2``.  Written as
    increments from ``a``, so the jumps are exact to rounding.
    """
    modulus = material.bulk_modulus if plastic else material.longitudinal_modulus
    impedance = material.bulk_impedance if plastic else material.impedance
    ds = sigma - a.sigma
    deps = ds / modulus
    dv = deps / material.rho0  # v_a - v_b
    ep = a.plastic_strain + 2.0 * deps / 3.0 if plastic else a.plastic_strain
    return State(sigma=float(sigma), u=a.u + direction * ds / impedance, v=a.v - dv,
                 e=a.e + 0.5 * (a.sigma + sigma) * dv, plastic_strain=ep)


def _yield_strength(name: str, value: float) -> float:
    strength = require_number("yield_strength", value, name)
    if not strength >= 0.0:
        raise MaterialError(f"{name}: yield_strength must be >= 0 Pa (or inf), got {value!r}")
    return strength


def _spall_strength(name: str, value: float) -> float:
    strength = require_number("spall_strength", value, name)
    if not strength > 0.0:
        raise MaterialError(f"{name}: spall_strength must be > 0 Pa (or inf), got {value!r}")
    return strength
