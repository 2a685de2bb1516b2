"""Wave curves: the states one wave can reach from a given state.

For a state ``a`` ahead of a wave of direction ``d`` (+1 right-going, -1
left-going) the wave curve is the set of states behind it.  It is written as

    u = u_a + d * g(sigma),     g increasing, g(sigma_a) = 0,

so that in the sigma–u plane a right-going curve rises (slope ``+rho0 U``) and a
left-going curve falls, as in PHYSICS.md.  ``g`` does not depend on ``d`` for an
isotropic material, which is what lets one Riemann solver intersect any two
curves: the contact stress solves ``g_L(sigma) + g_R(sigma) = u_L - u_R``.

Every wave-curve class offers the same four things, and the solver uses
nothing else, so a composite curve (elastic precursor + plastic shock, split
release, phase transitions) plugs in unchanged:

- ``sigma_limits()``: the open stress range the curve covers inside the
  material's validity;
- ``velocity_change(sigma)``: ``(g, dg/dsigma)``;
- ``state_at(sigma)``: the exact state behind the wave;
- ``waves(sigma)``: the elementary waves (``Shock``/``Fan``) that realise it,
  ordered from the fastest (leading) to the slowest.

``HydrodynamicWaveCurve`` is the curve of a convex fluid-like solid: a shock on
the Hugoniot centred on ``a`` for compression; for release, a centred fan on the
isentrope (or, on request, a rarefaction shock on that Hugoniot).  For the
Hugoniot branch ``g = sqrt((sigma - sigma_a)(v_a - v))`` from the mass and
momentum jumps; for the isentrope ``g = -int_{v_a}^{v} rho0 C_L dv``.
"""

from __future__ import annotations

import functools
import math

from .errors import NoSolutionError, StateOutOfRangeError
from .roots import EPS as _EPS
from .roots import bracket_near, bracketed_newton
from .state import State
from .waves import Fan, Shock

WEAK_VOLUME_JUMP = 1e-5
"""Relative volume jump below which a wave curve takes a wave's velocity and energy
jumps from its exact stress jump (``HydrodynamicWaveCurve._weak_wave``), free of the
rounding of the stored volumes."""

RELEASE_PATHS = ("isentrope", "hugoniot")

SPINODAL_FRACTION = 0.05
"""Isentrope tables end where ``C_L`` falls below this fraction of its value at the label
state: past it the isentrope nears the spinodal, where the Riemann integral is no
longer analytic (``characteristics.isentrope``)."""

SNOWPLOW_CEILING = 1e15
"""Highest stress (Pa, 1 PPa, far beyond any plane-wave experiment) a shock into a gas is
sought up to: a cold gas's Hugoniot reaches any stress at its limiting compression
(``HydrodynamicWaveCurve._snowplow``), but a root search needs a finite bracket."""


def check_curve_arguments(direction: int, release: str) -> None:
    """Raise ``ValueError`` unless ``direction`` is +1/-1 and ``release`` a known path."""
    if direction not in (1, -1):
        raise ValueError(f"direction must be +1 or -1, got {direction!r}")
    if release not in RELEASE_PATHS:
        raise ValueError(f"release must be one of {RELEASE_PATHS}, got {release!r}")


class StressRange:
    """The range check every wave curve shares; the curve provides ``sigma_limits()``,
    ``material`` and ``ahead``."""

    def check_stress(self, sigma: float) -> None:
        """Raise ``StateOutOfRangeError`` if ``sigma`` is beyond the curve's range."""
        low, high = self.sigma_limits()
        if not low <= sigma <= high:
            raise StateOutOfRangeError(
                f"{self.material.name}: stress {sigma / 1e9:.6g} GPa is outside the range "
                f"reachable from {self.ahead.sigma / 1e9:.6g} GPa inside its equation of state "
                f"({low / 1e9:.6g} to {high / 1e9:.6g} GPa)"
            )


class HydrodynamicWaveCurve(StressRange):
    """Wave curve of a material with a convex Hugoniot and isentropic release."""

    _WEAK_JUMP = WEAK_VOLUME_JUMP
    """Relative volume jump below which a wave's velocity jump, energy jump and (shock)
    speed come from its impedance at mid-wave rather than from the stored volumes (see
    ``_weak_wave``)."""

    _MAX_KNOWN_INTEGRALS = 16
    """Riemann integrals remembered per curve (one root search needs a handful)."""

    def __init__(self, material, ahead: State, direction: int, release: str = "isentrope"):
        check_curve_arguments(direction, release)
        self.material = material
        self.ahead = ahead
        self.direction = direction
        self.release = "hugoniot" if getattr(material, "is_linear", False) else release
        self._impedance = material.rho0 * material.sound_speed(ahead.v, ahead.e)
        self._sigma_min: float | None = None
        self._last_state: State | None = None
        self._last_point: tuple[float, float, float] | None = None
        self._last_weak: tuple | None = None
        self._tangent: tuple[float, float, float] | None = None
        self._last_isentrope: tuple | None = None
        self._integrals = [(ahead.v, 0.0)]

    @property
    def _compliance(self) -> float:
        """``1 / (rho0 C_L)`` at the centre: the curve's slope dg/dsigma there (inf if C_L = 0)."""
        return 1.0 / self._impedance if self._impedance > 0.0 else math.inf

    @property
    def impedance(self) -> float:
        """Acoustic impedance ``rho0 C_L`` of the ahead state: the curve's slope at its centre."""
        return self._impedance

    def _on_hugoniot(self, sigma: float) -> bool:
        return sigma > self.ahead.sigma or self.release == "hugoniot"

    # --- range ----------------------------------------------------------------
    def sigma_limits(self) -> tuple[float, float]:
        """Stress range ``(lowest, highest)`` reachable inside the model's validity."""
        return self.sigma_min(), self.sigma_max()

    def sigma_max(self) -> float:
        """Highest stress on the curve: the Hugoniot at its limiting compression."""
        mat, a = self.material, self.ahead
        # Shifted by the same rounding offset as the residual in ``_volume``, so that
        # ``state_at(sigma_max())`` is bracketed.
        offset = mat.hugoniot(a, a.v)[0] - a.sigma if math.isfinite(a.v) else 0.0
        top = max(mat.hugoniot(a, mat.hugoniot_volume_limit(a))[0] - offset, a.sigma)
        if getattr(mat, "unbounded_hugoniot", False):
            return max(top, SNOWPLOW_CEILING)  # a gas: any stress at its limiting compression
        return top

    def sigma_min(self) -> float:
        """Lowest stress on the release path inside the model's validity (cached)."""
        if self._sigma_min is None:
            v_max = self.material.volume_range()[1]
            if math.isinf(v_max):
                low = 0.0
            else:
                # Shifted by the rounding offset the residual in ``_volume`` subtracts
                # (path stress at v_a minus sigma_a), so ``state_at(sigma_min())`` is bracketed.
                offset = self._release_stress(self.ahead.v) - self.ahead.sigma
                low = self._release_stress(
                    self._last_valid_volume(v_max * (1.0 - 1e-12))) - offset
            self._sigma_min = min(low, self.ahead.sigma)
        return self._sigma_min

    def _release_point(self, v: float) -> tuple[float, float]:
        """``(sigma, e)`` at volume ``v`` on the release path."""
        if self.release == "hugoniot":
            return self.material.hugoniot(self.ahead, v)[:2]
        return self.material.isentrope(self.ahead, v)

    def _release_stress(self, v: float) -> float:
        return self._release_point(v)[0]

    def release_floor(self) -> float:
        """Lowest stress (Pa) a release from the ahead state reaches where its fan can be
        drawn: ``sigma_min``, or on an isentrope the stress 1e-8 inside the end of the
        volume range or where the Lagrangian sound speed falls to twice
        ``SPINODAL_FRACTION`` of its value ahead, if higher (the
        characteristics' isentrope tables end at ``SPINODAL_FRACTION`` of the speed at the
        state labelling them, which may be another, faster state of the isentrope)."""
        lowest = self.sigma_min()
        if self.release == "hugoniot" or lowest <= 0.0:
            return lowest
        a, mat = self.ahead, self.material
        c2_floor = (2.0 * SPINODAL_FRACTION) ** 2 * mat.sound_speed_squared(a.v, a.e)
        # inside the tables' own margin at the end of the volume range (1e-9)
        v = self._last_valid_volume(mat.volume_range()[1] * (1.0 - 1e-8), c2_floor)
        offset = self._release_stress(a.v) - a.sigma
        return min(max(self._release_stress(v) - offset, lowest), a.sigma)

    def _last_valid_volume(self, v_edge: float, c2_floor: float = 0.0) -> float:
        """Largest volume up to ``v_edge`` where the release path's squared sound speed is
        above ``c2_floor`` (by default: where it is real)."""

        def valid(v):
            return self.material.sound_speed_squared(v, self._release_point(v)[1]) > c2_floor

        if valid(v_edge):
            return v_edge
        lo, hi = self.ahead.v, v_edge
        for _ in range(60):
            mid = 0.5 * (lo + hi)
            lo, hi = (mid, hi) if valid(mid) else (lo, mid)
        return lo


    # --- the curve ------------------------------------------------------------
    def _volume(self, sigma: float) -> float:
        """Volume behind the wave that reaches ``sigma`` (bracketed root in ``v``)."""
        a, mat = self.ahead, self.material
        if sigma == a.sigma:
            return a.v
        # The path's own stress at v_a differs from the recorded sigma_a by rounding;
        # subtracting it makes the residual at v_a exactly sigma_a - sigma.
        # Rounding of the residual: a few ulps of the stresses it subtracts.
        noise_floor = abs(a.sigma)
        on_path = (mat.hugoniot(a, a.v)[0] if mat.gaseous and sigma < a.sigma
                    and self._on_hugoniot(sigma) else 0.0)
        if on_path > 0.0:
            # A gas released along its Hugoniot reaches zero stress where its energy
            # does, at v_a + 2 e_a / sigma_a: the rounding is corrected by a factor, so
            # that zero stress stays that point (a shift as large as a near-vacuum
            # state's own stress would move it past the path's reach, seed 467).
            scale = a.sigma / on_path

            def residual(v):
                s, _, ds = mat.hugoniot(a, v)
                return s * scale - sigma, ds * scale
        elif self._on_hugoniot(sigma):
            offset = self._hugoniot_offset
            noise_floor += abs(offset)

            def residual(v):
                s, _, ds = mat.hugoniot(a, v)
                return s - offset - sigma, ds
        elif getattr(mat, "relative_stress_precision", False):
            # A closed-form isentrope good to a few ulps of its own stress down to vacuum:
            # the rounding is corrected by a factor, not a shift, so that a release to
            # 1e-15 of the initial pressure is not swamped by an ulp of it.
            on_path = mat.isentrope(a, a.v)[0]
            scale = a.sigma / on_path if on_path != 0.0 else 1.0
            noise_floor = 0.0

            def residual(v):
                s, e = mat.isentrope(a, v)
                return (s * scale - sigma,
                        -mat.sound_speed_squared(v, e) * mat.rho0**2 * scale)
        else:
            offset = self._isentrope_offset
            noise_floor += abs(offset)

            def residual(v):
                s, e = self._isentrope_point(v)
                return s - offset - sigma, -mat.sound_speed_squared(v, e) * mat.rho0**2
        # A target within the rounding of the residual (the stresses it subtracts, the
        # offset included) is the state ahead: near vacuum a gas's recorded stress
        # (1e-52 Pa) is far below the rounding of its equation of state's own (1e-9 Pa),
        # and the residual's sign at v_a is noise (campaign seeds 265, 274).
        if abs(sigma - a.sigma) <= 4.0 * _EPS * (abs(a.sigma) + noise_floor):
            return a.v
        if sigma > a.sigma:
            lo, hi = mat.hugoniot_volume_limit(a), a.v
            if self._snowplow(sigma):
                return lo
        else:
            lo, hi = a.v, mat.volume_range()[1] * (1.0 - 1e-12)
            if math.isinf(hi):
                if self._on_hugoniot(sigma):
                    # along its Hugoniot a gas reaches zero stress at a finite volume,
                    # v_a + 2 e_a / sigma_a (an ideal gas: v_a (gamma + 1) / (gamma - 1)),
                    # and carries no tension: below zero it is out of range, and a
                    # contact pulled further opens (vacuum forms, ``materials.riemann``)
                    self.check_stress(sigma)
                elif sigma <= 0.0:
                    return math.inf  # a gas expanding to vacuum along its isentrope
                hi = 2.0 * a.v
                while residual(hi)[0] > 0.0:
                    hi *= 4.0
                    if math.isinf(hi):  # a state off its equation of state (e <= 0)
                        raise StateOutOfRangeError(
                            f"{mat.name}: no volume releases the state at "
                            f"{a.sigma / 1e9:.6g} GPa (e = {a.e:.6g} J/kg) to "
                            f"{sigma / 1e9:.6g} GPa")
        # First guess: a Newton step from the last point solved on the same branch (a
        # root search on the curve evaluates converging stresses), else the acoustic
        # one, dv = -(dsigma) / (rho0 C)^2.
        tangent = self._tangent
        noise = 4.0 * _EPS * (abs(sigma) + noise_floor)
        if tangent is not None and (tangent[0] > a.sigma) == (sigma > a.sigma):
            guess = tangent[1] + (sigma - tangent[0]) / tangent[2]
            # nor can the residual be resolved finer than what one ulp of v changes
            noise += abs(tangent[2]) * math.ulp(guess)
        elif self._impedance > 0.0:
            guess = a.v - (sigma - a.sigma) / self._impedance**2
        else:
            guess = None
        local = (bracket_near(residual, guess, min(lo, hi), max(lo, hi), noise)
                 if guess is not None else None)
        if local is not None:
            lo, hi, start, f_lo, f_hi = local
            return bracketed_newton(residual, lo, hi, start, rel_tol=2e-16, f_lo=f_lo,
                                    f_hi=f_hi, f_tol=noise)
        try:
            return bracketed_newton(residual, lo, hi, guess, rel_tol=2e-16, f_tol=noise)
        except (NoSolutionError, StateOutOfRangeError):
            self.check_stress(sigma)  # names the range the stress is outside
            if sigma > a.sigma or not math.isfinite(hi):
                raise
        # a release path that passes its spinodal inside the volume range (an expanded
        # matrix's isentrope: C_L = 0 at its most tension, ``sigma_min``) turns back to
        # lower tension beyond it: the root lies before the spinodal
        return bracketed_newton(residual, lo, self._last_valid_volume(hi), guess,
                                rel_tol=2e-16, f_tol=noise)

    def _snowplow(self, sigma: float) -> bool:
        """Whether a shock to ``sigma`` compresses a gas to its limiting volume.

        The Hugoniot of an ideal gas centred on ``a`` reaches any stress as ``v`` tends to
        ``v_a (gamma - 1) / (gamma + 1)``; its stress near that limit is proportional to
        ``e_a + sigma_a v_a / (gamma + 1)``.  For a cold gas (a gas released along its
        Hugoniot to zero stress keeps ``e`` within rounding of 0) the stress at the
        representable limit is a few kPa: every stronger shock is the snowplow, the
        gas swept to its limiting compression, ``v_b = v_lim``, with the jump conditions
        ``u_b - u_a = sqrt((sigma_b - sigma_a)(v_a - v_lim))`` and
        ``e_b = e_a + (sigma_a + sigma_b)(v_a - v_lim) / 2`` (exact for ``e_a = 0``).
        """
        mat, a = self.material, self.ahead
        if not getattr(mat, "unbounded_hugoniot", False) or not self._on_hugoniot(sigma):
            return False
        limit = mat.hugoniot_volume_limit(a)
        return mat.hugoniot(a, limit)[0] - self._hugoniot_offset < sigma

    def _energy(self, sigma: float, v: float) -> float:
        if math.isinf(v):
            return 0.0
        if self._snowplow(sigma):
            a = self.ahead
            return a.e + 0.5 * (a.sigma + sigma) * (a.v - v)
        if self._on_hugoniot(sigma):
            return self.material.hugoniot(self.ahead, v)[1]
        return self._isentrope_point(v)[1]

    def _isentrope_point(self, v: float) -> tuple[float, float]:
        """``(sigma, e)`` on the isentrope of ``ahead`` at ``v``; the last one is kept, as
        the energy behind a fan is asked at the volume its stress root ended on."""
        known = self._last_isentrope
        if known is None or known[0] != v:
            known = self._last_isentrope = (v, self.material.isentrope(self.ahead, v))
        return known[1]

    @functools.cached_property
    def _hugoniot_offset(self) -> float:
        """The Hugoniot's own stress at ``v_a`` minus the recorded ``sigma_a`` (rounding)."""
        return self.material.hugoniot(self.ahead, self.ahead.v)[0] - self.ahead.sigma

    @functools.cached_property
    def _isentrope_offset(self) -> float:
        """The isentrope's own stress at ``v_a`` minus the recorded ``sigma_a`` (rounding)."""
        return self.material.isentrope(self.ahead, self.ahead.v)[0] - self.ahead.sigma

    def _g_at(self, sigma: float, v: float) -> tuple[float, float]:
        a, mat = self.ahead, self.material
        if self._is_weak(v):
            return self._weak_wave(sigma, v)[:2]
        if self._on_hugoniot(sigma):
            jump = (sigma - a.sigma) * (a.v - v)
            g = math.copysign(math.sqrt(max(jump, 0.0)), sigma - a.sigma)
            if self._snowplow(sigma):  # v stays at the limit: dv/dsigma = 0
                return g, (a.v - v) / (2.0 * g)
            ds_dv = mat.hugoniot(a, v)[2]
            self._remember_tangent(sigma, v, ds_dv)
            return g, ((a.v - v) - (sigma - a.sigma) / ds_dv) / (2.0 * g)
        c = mat.sound_speed(v, self._energy(sigma, v))
        self._remember_tangent(sigma, v, -(mat.rho0 * c) ** 2)
        slope = 1.0 / (mat.rho0 * c) if c > 0.0 else math.inf
        return -self._riemann_integral(v), slope

    def _remember_tangent(self, sigma: float, v: float, slope: float) -> None:
        """Keep ``(sigma, v, dsigma/dv)`` of a solved point: the next volume root starts
        one Newton step from it."""
        if slope < 0.0 and math.isfinite(slope):
            self._tangent = (sigma, v, slope)

    def _is_weak(self, v: float) -> bool:
        """A wave to volume ``v`` so weak (``|v - v_a| <= 1e-5 v_a``) that the stored
        volumes resolve its jump only to ``ulp(v) / |dv| > 1e-11``."""
        return abs(self.ahead.v - v) <= self._WEAK_JUMP * self.ahead.v

    def _weak_wave(self, sigma: float, v: float) -> tuple[float, float, float]:
        """``(g, dg/dsigma, e_b - e_a)`` of a weak wave to stress ``sigma`` (volume ``v``).

        Computed from the rounded volumes, a weak wave's velocity jump (``sqrt(dsigma
        dv)`` on the Hugoniot, the Riemann integral over ``[v_a, v]`` on the isentrope)
        and its energy jump carry ``ulp(v) / |dv|`` of noise, with a bias where a
        negative product is clipped (1000 echoes of rounding-level waves drifted a
        ring-up by 1e-11; a 1 nm/s fan lost 3e-4 of its velocity).  They are taken from
        the exact ``dsigma`` instead:

        - shock: ``g = dsigma / (rho0 U)`` with ``(rho0 U)^2`` the Hugoniot's tangent
          ``-dsigma/dv`` at the mid volume (the chord to O(dv^2)), and the jump condition
          ``e_b - e_a = (sigma_a + sigma_b) dv / 2`` with ``dv = dsigma / (rho0 U)^2``;
        - fan: ``g = int dsigma / Z`` and ``e_b - e_a = int sigma dsigma / Z^2``
          (``Z = rho0 C_L``, ``de = -sigma dv``, ``dv = -dsigma / Z^2``) by Simpson's
          rule in sigma, Z at the end volumes and at the volume of the mean stress.

        A linear elastic solid: exactly ``Z = rho0 C`` for every wave.
        """
        if self._last_weak is not None and self._last_weak[:2] == (sigma, v):
            return self._last_weak[2]
        self._last_weak = (sigma, v, self._weak_wave_jumps(sigma, v))
        return self._last_weak[2]

    def _weak_wave_jumps(self, sigma: float, v: float) -> tuple[float, float, float]:
        """``_weak_wave`` computed."""
        a, mat = self.ahead, self.material
        jump = sigma - a.sigma
        if not self._impedance > 0.0:
            # a gas at zero pressure has no sound speed: a wave within the rounding of
            # its stress (the only weak one it admits) moves nothing
            return 0.0, self._compliance, 0.0
        if getattr(mat, "is_linear", False) or self._on_hugoniot(sigma):
            impedance = self._impedance
            if not getattr(mat, "is_linear", False):
                slope = mat.hugoniot(a, 0.5 * (a.v + v))[2]
                impedance = math.sqrt(-slope) if slope < 0.0 else impedance
            return (jump / impedance, 1.0 / impedance,
                    0.5 * (a.sigma + sigma) * jump / impedance**2)
        z_a, z_b = self._impedance, self._isentrope_impedance(v)
        # the volume at sigma_mid: the mean volume less the curvature term of
        # v(sigma), v'' = 2 Z' / Z^3 with Z' = (Z_b - Z_a) / dsigma (else O(dv^2) in g)
        middle = 0.5 * (a.v + v) - jump * (z_b - z_a) / (4.0 * z_a**3)
        z_m = self._isentrope_impedance(middle)
        g = jump / 6.0 * (1.0 / z_a + 4.0 / z_m + 1.0 / z_b)
        energy = jump / 6.0 * (a.sigma / z_a**2 + 2.0 * (a.sigma + sigma) / z_m**2
                               + sigma / z_b**2)
        return g, 1.0 / z_b, energy

    def _isentrope_impedance(self, v: float) -> float:
        """``rho0 C_L`` on the isentrope of ``ahead`` at volume ``v``."""
        mat = self.material
        return mat.rho0 * mat.sound_speed(v, mat.isentrope(self.ahead, v)[1])

    def _riemann_integral(self, v: float) -> float:
        """``J(v)`` along the isentrope of ``ahead``, extended from the nearest known value.

        A root search evaluates the curve at volumes that converge on the answer;
        continuing the integral from the closest volume already done makes each
        later evaluation a short (few-point) quadrature instead of a full one.
        """
        if math.isinf(v):
            return self.material.riemann_integral(self.ahead, v)
        v_near, j_near = min(self._integrals, key=lambda known: abs(known[0] - v))
        j = j_near + self.material.riemann_integral(self.ahead, v, start=v_near)
        if len(self._integrals) < self._MAX_KNOWN_INTEGRALS:
            self._integrals.append((v, j))
        return j

    def velocity_change(self, sigma: float) -> tuple[float, float]:
        """``(g, dg/dsigma)``: the particle-velocity change ``u - u_a = d * g``."""
        if sigma == self.ahead.sigma:
            return 0.0, self._compliance
        v = self._volume(sigma)
        g = self._g_at(sigma, v)
        # The solver's last evaluation is usually at the stress it returns, whose state
        # it asks for next: remember the point so ``state_at`` does not solve it again.
        self._last_point = (sigma, v, g[0])
        return g

    def state_at(self, sigma: float) -> State:
        """The state behind the wave that reaches stress ``sigma``."""
        a = self.ahead
        if sigma == a.sigma:
            return a
        if self._last_state is not None and self._last_state.sigma == sigma:
            return self._last_state
        self._last_state = self._state_at(sigma)
        return self._last_state

    def _state_at(self, sigma: float) -> State:
        a = self.ahead
        if self._last_point is not None and self._last_point[0] == sigma:
            _, v, g = self._last_point
        else:
            v = self._volume(sigma)
            g, _ = self._g_at(sigma, v)
        if self._is_weak(v):
            e = a.e + self._weak_wave(sigma, v)[2]
        else:
            e = self._energy(sigma, v)
        return State(sigma=float(sigma), u=float(a.u + self.direction * g), v=float(v),
                     e=float(e))

    def waves(self, sigma: float) -> tuple:
        """Elementary waves realising the jump to ``sigma``, leading wave first."""
        a = self.ahead
        if sigma == a.sigma:
            return ()
        behind = self.state_at(sigma)
        d = self.direction
        if self._on_hugoniot(sigma):
            mat = self.material
            if getattr(mat, "is_linear", False):
                speed = d * mat.sound_speed(a.v, a.e)  # exactly C, every wave
            elif self._is_weak(behind.v):
                speed = d / (mat.rho0 * self._weak_wave(sigma, behind.v)[1])
            else:
                speed = (behind.sigma - a.sigma) / (mat.rho0 * (behind.u - a.u))
            return (Shock(ahead=a, behind=behind, speed=speed, direction=d),)
        head = d * self.material.sound_speed(a.v, a.e)
        tail = d * self.material.sound_speed(behind.v, behind.e)
        return (Fan(ahead=a, behind=behind, head_speed=head, tail_speed=tail, direction=d,
                    curve=self),)
