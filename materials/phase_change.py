"""A solid with a polymorphic phase change: two branches and a mixed-phase region.

Conventions of PHYSICS.md: stress ``sigma`` positive in compression (Pa),
compression ``eps = 1 - v/v0``, SI units.

The model
---------
The stress is a function of the compression alone (each phase a Mie–Grüneisen solid
with ``Gamma0 = 0``, i.e. its principal Hugoniot as its stress–strain law; the energy
is carried by the jump conditions and ``de = -sigma dv``, and does not change the
stress).  Along the equilibrium path

- low-pressure phase (iron's alpha): ``sigma_1 = K_1 eps / (1 - s_1 eps)^2`` up to the
  ``transition_stress`` ``sigma_t`` at ``eps_A``;
- mixed phase: the straight line from ``(eps_A, sigma_t)`` to ``(eps_B, sigma_2(eps_B))``,
  ``eps_B = eps_A + transition_strain`` (the volume change of the transformation over
  ``v0``): the mixture on the equilibrium boundary, whose stress rises a little as
  the fraction transformed grows;
- high-pressure phase (iron's epsilon): ``sigma_2 = K_2 eps / (1 - s_2 eps)^2`` beyond
  ``eps_B``;

with ``K_i = rho0 c_i^2``.  Each branch is convex; the slope drops at ``A`` (a concave
corner) and rises again at ``B``.  The transformation is reversible (equilibrium, no
hysteresis), so loading and release follow the same path.

Waves: the convex-hull construction
-----------------------------------
Because the stress depends on the strain alone, a compressive wave from ``a`` to
``b`` follows the upper concave hull of ``sigma(eps)`` on ``[eps_a, eps_b]`` and a
release wave the lower convex hull on ``[eps_b, eps_a]`` (as in
``materials.finite_plastic.concave_hull_waves``, which does it on samples; here the
pieces are known, so the hull is built exactly): where the hull is a chord the wave
is a shock at ``U = sqrt(slope / rho0)``, where it runs on a curved branch a centred
fan with characteristics at ``C = sqrt(sigma'(eps) / rho0)``; a straight stretch
of the path (the mixed line) is a shock.

- Loading across ``A``: the hull is the chords ``a -> A -> b``: the P1 shock to the
  transition stress exactly, then the slower P2 shock, unless the chord ``a -> b`` is
  steeper than ``a -> A`` (P2 overtakes P1: one shock).
- Release across ``A``: the lower hull bridges the corner by a chord ``Q -> P`` that
  touches the path at both ends (``P`` on the low-pressure branch where
  ``sigma_1'(P) = m``, or the target; ``Q`` on the high-pressure side where the slope
  brackets ``m``, or the ahead state): a fan down to ``Q``, the *rarefaction shock*
  of the reverse transformation from ``Q`` to ``P`` at ``sqrt(m / rho0)``, and a fan
  below ``P``.  The bridge's slope solves ``D(m) = 0`` with ``D`` the difference of the
  Legendre transforms ``min (sigma - m eps)`` of the two sides, increasing in ``m``.

Closed forms on a branch ``sigma = K eps / (1 - s eps)^2``: the inverse
``eps = 2 sigma / (2 s sigma + K + sqrt(K^2 + 4 s sigma K))``; the Riemann integral
``int sqrt(sigma'/rho0) d eps = (2c/s) (w - arctan w)`` with
``w = sqrt((1 + s eps)/(1 - s eps))``; the work ``int sigma d eps =
(K/s^2) [ln(1 - s eps) + 1/(1 - s eps)]``.  Every state and speed is exact to rounding.

Dissipation: a compressive chord lies above the path and a release chord below it,
so every shock leaves more energy than the reversible path: ``e - e_path >= 0``
(``dissipated_energy``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from .base import Material, require_number, require_positive
from .errors import MaterialError
from .linear_elastic import _strength
from .roots import bracketed_newton
from .state import State
from .wavecurves import StressRange, check_curve_arguments
from .waves import Fan, Shock

_TENSION_LIMIT = 0.3
"""Tension range of the low-pressure branch, ``eps > -0.3 / s_1`` (as ``MieGruneisen``)."""
_COMPRESSION_LIMIT = 0.95
"""Compression range of the high-pressure branch, ``eps < 0.95 / s_2``."""
_CORNER_SNAP = 1e-14
"""A compression within this of a corner of the path is at the corner (rounding of v)."""


@dataclass(frozen=True)
class _Branch:
    """``sigma = K eps / (1 - s eps)^2`` (``s > 0``), or the line ``sigma_0 + m (eps - eps_0)``
    (``s = 0``: ``K`` is the slope ``m``, through ``(eps_0, sigma_0)``)."""

    rho0: float
    modulus: float
    s: float
    eps0: float = 0.0
    sigma0: float = 0.0

    def stress(self, eps: float) -> float:
        if self.s == 0.0:
            return self.sigma0 + self.modulus * (eps - self.eps0)
        return self.modulus * eps / (1.0 - self.s * eps) ** 2

    def slope(self, eps: float) -> float:
        """``d sigma / d eps`` (Pa)."""
        if self.s == 0.0:
            return self.modulus
        x = self.s * eps
        return self.modulus * (1.0 + x) / (1.0 - x) ** 3

    def strain(self, sigma: float) -> float:
        """The inverse ``eps(sigma)`` (closed form, stable for both signs)."""
        if self.s == 0.0:
            return self.eps0 + (sigma - self.sigma0) / self.modulus
        k, s = self.modulus, self.s
        return 2.0 * sigma / (2.0 * s * sigma + k + math.sqrt(k * k + 4.0 * s * sigma * k))

    def strain_at_slope(self, m: float) -> float:
        """``eps`` where ``sigma'(eps) = m`` (curved branch; bracketed Newton in eps)."""
        lo, hi = -_TENSION_LIMIT / self.s, _COMPRESSION_LIMIT / self.s
        if self.slope(lo) >= m:
            return lo
        if self.slope(hi) <= m:
            return hi
        curvature = 2.0 * self.s * self.modulus
        return bracketed_newton(lambda e: (self.slope(e) - m, curvature * (2.0 + self.s * e)
                                           / (1.0 - self.s * e) ** 4), lo, hi, rel_tol=2e-16)

    def riemann(self, eps: float) -> float:
        """``G(eps) = int_0^eps sqrt(sigma' / rho0) d eps`` (m/s) up to a constant."""
        if self.s == 0.0:
            return math.sqrt(self.modulus / self.rho0) * eps
        w = math.sqrt((1.0 + self.s * eps) / (1.0 - self.s * eps))
        return 2.0 * math.sqrt(self.modulus / self.rho0) / self.s * (w - math.atan(w))

    def work(self, eps: float) -> float:
        """``int sigma d eps`` (Pa) up to a constant."""
        if self.s == 0.0:
            return (self.sigma0 - self.modulus * self.eps0) * eps + 0.5 * self.modulus * eps**2
        x = self.s * eps
        return self.modulus / self.s**2 * (math.log1p(-x) + 1.0 / (1.0 - x))


class PhaseChangeSolid(Material):
    """Two-phase solid on an equilibrium path (see the module docstring).

    ``rho0`` (kg/m^3); ``c1``, ``s1`` and ``c2``, ``s2`` the two phases' linear Us–up
    fits from the reference state (m/s, dimensionless); ``transition_stress`` (Pa) where
    the low-pressure phase starts to transform; ``transition_strain`` the volume
    change of the transformation over ``v0`` (> 0); ``spall_strength`` (Pa).
    """

    makes_fans = True
    splits_waves = True

    def __init__(self, name: str, rho0: float, c1: float, s1: float, c2: float, s2: float,
                 transition_stress: float, transition_strain: float,
                 spall_strength: float = math.inf):
        self.name = name
        self.rho0 = require_positive("rho0", rho0, name)
        self.low = _Branch(self.rho0, self.rho0 * require_positive("c1", c1, name) ** 2,
                           require_positive("s1", s1, name))
        self.high = _Branch(self.rho0, self.rho0 * require_positive("c2", c2, name) ** 2,
                            require_positive("s2", s2, name))
        self.transition_stress = require_positive("transition_stress", transition_stress, name)
        top = self.low.stress(_COMPRESSION_LIMIT / self.low.s * 0.999)
        if not self.transition_stress < top:
            raise MaterialError(
                f"{name}: transition_stress {transition_stress!r} Pa is above the range of "
                f"the low-pressure phase's Hugoniot (0 to {top:.6g} Pa)")
        self.transition_strain = require_number("transition_strain", transition_strain, name)
        self.eps_a = self.low.strain(self.transition_stress)
        self.eps_b = self.eps_a + self.transition_strain
        if not (0.0 < self.transition_strain and self.eps_b < _COMPRESSION_LIMIT / self.high.s):
            raise MaterialError(f"{name}: transition_strain must be > 0 and leave the "
                                f"high-pressure phase in its range, got {transition_strain!r}")
        self.sigma_b = self.high.stress(self.eps_b)
        mixed_slope = (self.sigma_b - self.transition_stress) / self.transition_strain
        if not 0.0 < mixed_slope < min(self.low.slope(self.eps_a), self.high.slope(self.eps_b)):
            raise MaterialError(
                f"{name}: the high-pressure phase at the end of the transformation "
                f"({self.sigma_b:.6g} Pa at compression {self.eps_b:.6g}) must lie above "
                f"transition_stress and below both phases' tangents (check c2, s2 and "
                f"transition_strain)")
        self.mixed = _Branch(self.rho0, mixed_slope, 0.0, self.eps_a, self.transition_stress)
        self.spall_strength = _strength(name, spall_strength)

    # --- the path --------------------------------------------------------------------------
    def branch(self, eps: float, upper: bool = False) -> _Branch:
        """The branch at ``eps``; at a corner the one below it (``upper``: above it)."""
        if eps < self.eps_a or (eps == self.eps_a and not upper):
            return self.low
        if eps < self.eps_b or (eps == self.eps_b and not upper):
            return self.mixed
        return self.high

    def strain(self, v: float) -> float:
        return 1.0 - v / self.v0

    def path_stress(self, eps: float) -> float:
        """``sigma(eps)`` on the equilibrium path (Pa)."""
        return self.branch(eps).stress(eps)

    def path_strain(self, sigma: float) -> float:
        """The inverse of the path (its stress increases strictly)."""
        if sigma <= self.transition_stress:
            return self.low.strain(sigma)
        if sigma <= self.sigma_b:
            return self.mixed.strain(sigma)
        return self.high.strain(sigma)

    def _along(self, eps: float, quantity: str) -> float:
        """Sum over the branches from 0 to ``eps`` of the branch integral ``quantity``
        ("riemann" or "work"), each taken between its own ends."""
        total = 0.0
        for piece, lo, hi in ((self.low, -math.inf, self.eps_a),
                              (self.mixed, self.eps_a, self.eps_b),
                              (self.high, self.eps_b, math.inf)):
            start, end = max(min(0.0, hi), lo), max(min(eps, hi), lo)
            if end != start:
                total += getattr(piece, quantity)(end) - getattr(piece, quantity)(start)
        return total

    def riemann(self, eps: float) -> float:
        """``G(eps) = int_0^eps sqrt(sigma'/rho0) d eps`` along the path (m/s)."""
        return self._along(eps, "riemann")

    def work(self, eps: float) -> float:
        """``int_0^eps sigma d eps`` along the path (Pa)."""
        return self._along(eps, "work")

    def dissipated_energy(self, state: State) -> float:
        """Energy above the reversible path from the virgin state (J/kg):
        ``e - v0 int_0^eps sigma d eps``; zero along fans, grown by every shock."""
        return state.e - self.v0 * self.work(self.strain(state.v))

    # --- Material interface ------------------------------------------------------------------
    def stress(self, v: float, e: float) -> float:
        """``sigma(eps)`` on the path: the stress does not depend on the energy."""
        self.check_volume(v)
        return self.path_stress(self.strain(v))

    def sound_speed(self, v: float, e: float) -> float:
        """``C = sqrt(sigma'(eps) / rho0)`` (m/s); at a corner, the branch below it."""
        return math.sqrt(self.branch(self.strain(v)).slope(self.strain(v)) / self.rho0)

    def volume_range(self) -> tuple[float, float]:
        return (self.v0 * (1.0 - _COMPRESSION_LIMIT / self.high.s),
                self.v0 * (1.0 + _TENSION_LIMIT / self.low.s))

    def hugoniot(self, ahead: State, v: float) -> tuple[float, float, float]:
        """The path's stress at ``v`` with the Rankine–Hugoniot energy from ``ahead`` (the
        states one shock or a hull of shocks reaches: the stress is a function of ``v``)."""
        eps = self.strain(v)
        sigma = self.path_stress(eps)
        e = ahead.e + 0.5 * (ahead.sigma + sigma) * (ahead.v - v)
        return sigma, e, -self.branch(eps).slope(eps) / self.v0

    def hugoniot_volume_limit(self, ahead: State) -> float:
        return self.volume_range()[0]

    def isentrope(self, through: State, v: float) -> tuple[float, float]:
        """``(sigma, e)`` along the path, ``de = -sigma dv = v0 sigma d eps``."""
        eps = self.strain(v)
        return (self.path_stress(eps),
                through.e + self.v0 * (self.work(eps) - self.work(self.strain(through.v))))

    def riemann_integral(self, through: State, v: float, start: float | None = None) -> float:
        """``J = int rho0 C dv = -(G(eps) - G(eps_start))`` (``rho0 v0 = 1``)."""
        origin = through.v if start is None else start
        return -(self.riemann(self.strain(v)) - self.riemann(self.strain(origin)))

    def wave_curve(self, ahead: State, direction: int, release: str = "isentrope"):
        return PhaseChangeWaveCurve(self, ahead, direction, release)


class PhaseChangeWaveCurve(StressRange):
    """Wave curve of a ``PhaseChangeSolid``: the hull construction of the module docstring.

    ``u = u_a + d g(sigma)`` with ``g`` the sum over the hull's pieces of
    ``sqrt(dsigma deps / rho0)`` (chords) and ``G(eps_end) - G(eps_start)`` (fans).
    ``release="hugoniot"`` replaces every fan by a chord (one rarefaction shock per piece).
    """

    def __init__(self, material: PhaseChangeSolid, ahead: State, direction: int,
                 release: str = "isentrope"):
        check_curve_arguments(direction, release)
        self.material = material
        self.ahead = ahead
        self.direction = direction
        self.release = release
        eps = material.strain(ahead.v)
        # a state at a corner of the path is on it, not a rounding away (no zero-strength P1)
        for corner in (material.eps_a, material.eps_b):
            if abs(eps - corner) <= _CORNER_SNAP:
                eps = corner
        self.eps_a = eps
        self._last: tuple[float, tuple] | None = None

    @property
    def impedance(self) -> float:
        """``rho0 C`` at the ahead state on the side of the path a compression takes."""
        mat = self.material
        return math.sqrt(mat.rho0 * mat.branch(self.eps_a, upper=True).slope(self.eps_a))

    def sigma_limits(self) -> tuple[float, float]:
        mat = self.material
        v_lo, v_hi = mat.volume_range()
        return (min(mat.path_stress(mat.strain(v_hi)), self.ahead.sigma),
                max(mat.path_stress(mat.strain(v_lo)), self.ahead.sigma))

    def sigma_min(self) -> float:
        return self.sigma_limits()[0]

    def sigma_max(self) -> float:
        return self.sigma_limits()[1]

    # --- the hull ------------------------------------------------------------------------------
    def pieces(self, sigma: float) -> list[tuple[str, float, float]]:
        """The hull from the ahead state to ``sigma``: ``(kind, eps_start, eps_end)`` with
        ``kind`` "shock" or "fan", leading piece first."""
        mat = self.material
        a, b = self.eps_a, mat.path_strain(sigma)
        if b == a or (sigma > self.ahead.sigma) != (b > a):
            # a stress jump within the rounding of the ahead state's own stress
            return [("shock", a, b)]
        if sigma > self.ahead.sigma:
            if a < mat.eps_a < b:
                s_a = mat.transition_stress
                p1 = (s_a - self.ahead.sigma) / (mat.eps_a - a)
                p2 = (sigma - s_a) / (b - mat.eps_a)
                if p2 < p1:
                    return [("shock", a, mat.eps_a), ("shock", mat.eps_a, b)]
            return [("shock", a, b)]
        pieces: list[tuple[str, float, float]] = []
        if b < mat.eps_a < a:
            top, bottom = self._bridge(b, a)
        else:
            top = bottom = b
        self._path_pieces(a, top, pieces)
        if top != bottom:
            pieces.append(("shock", top, bottom))
        self._path_pieces(bottom, b, pieces)
        if self.release == "hugoniot":
            return [("shock", p[1], p[2]) for p in pieces]
        return pieces

    def _path_pieces(self, start: float, end: float, out: list) -> None:
        """Release along the path from ``start`` down to ``end`` (no concave corner between):
        fans on curved branches, a shock on the straight mixed line."""
        mat = self.material
        edges = [start] + [c for c in (mat.eps_b, mat.eps_a) if end < c < start] + [end]
        for hi, lo in zip(edges[:-1], edges[1:], strict=True):
            if hi == lo:
                continue
            straight = mat.branch(0.5 * (hi + lo)) is mat.mixed
            out.append(("shock" if straight else "fan", hi, lo))

    def _bridge(self, low: float, high: float) -> tuple[float, float]:
        """``(Q, P)``: the chord of the lower convex hull over the corner ``A`` between the
        strains ``low < eps_A < high`` (``Q`` above ``A``, ``P`` below)."""
        mat = self.material

        def lower_side(m):
            return min(max(mat.low.strain_at_slope(m), low), mat.eps_a)

        def upper_side(m):
            if m <= mat.mixed.modulus:
                return mat.eps_a
            if m <= mat.high.slope(mat.eps_b):
                return min(mat.eps_b, high)
            return min(max(mat.high.strain_at_slope(m), mat.eps_b), high)

        def gap(m):
            p, q = lower_side(m), upper_side(m)
            return (mat.path_stress(p) - m * p) - (mat.path_stress(q) - m * q), q - p

        lo = mat.mixed.modulus
        hi = max(mat.low.slope(high), mat.high.slope(high), mat.low.slope(mat.eps_a)) * 2.0
        m = bracketed_newton(gap, lo, hi, rel_tol=2e-16)
        q, p = upper_side(m), lower_side(m)
        return q, p

    def _solve(self, sigma: float) -> tuple:
        """``(states, waves-as-tuples, g, dg/dsigma)`` along the hull (cached)."""
        if self._last is not None and self._last[0] == sigma:
            return self._last[1]
        mat, a, d = self.material, self.ahead, self.direction
        pieces = self.pieces(sigma)
        state, g = a, 0.0
        out = []
        for index, (kind, start, end) in enumerate(pieces):
            s_end = sigma if index == len(pieces) - 1 else mat.path_stress(end)
            if kind == "shock":
                # a product of rounding-level jumps may come out negative: no jump
                jump = math.sqrt(max((s_end - state.sigma) * (end - start), 0.0) / mat.rho0)
                dv = (start - end) * mat.v0          # v_end - v_start
                e = state.e - 0.5 * (state.sigma + s_end) * dv
                speed = abs(s_end - state.sigma) / (mat.rho0 * jump) if jump > 0.0 else \
                    math.sqrt(mat.branch(start, upper=end > start).slope(start) / mat.rho0)
            else:
                jump = mat.riemann(start) - mat.riemann(end)
                e = state.e + mat.v0 * (mat.work(end) - mat.work(start))
                speed = math.nan
            g += math.copysign(abs(jump), s_end - state.sigma)
            behind = State(sigma=float(s_end), u=a.u + d * g, v=mat.v0 * (1.0 - end), e=e)
            out.append((kind, state, behind, speed, start, end))
            state = behind
        kind, first, last, _, start, end = out[-1]
        slope = mat.branch(end, upper=end > start).slope(end)
        if kind == "fan" or last.u == first.u:
            dg = 1.0 / math.sqrt(mat.rho0 * slope)
        else:
            # the last chord from a fixed start: g = sqrt(dsigma deps / rho0)
            dg = ((end - start) + (last.sigma - first.sigma) / slope) / (
                2.0 * mat.rho0 * abs(last.u - first.u))
        result = (out, g, dg)
        self._last = (sigma, result)
        return result

    def velocity_change(self, sigma: float) -> tuple[float, float]:
        """``(g, dg/dsigma)``: ``u - u_a = d g`` (m/s, m/s/Pa)."""
        if sigma == self.ahead.sigma:
            return 0.0, 1.0 / self.impedance
        self.check_stress(sigma)
        _, g, dg = self._solve(sigma)
        return g, dg

    def state_at(self, sigma: float) -> State:
        if sigma == self.ahead.sigma:
            return self.ahead
        self.check_stress(sigma)
        return self._solve(sigma)[0][-1][2]

    def characteristic_speed(self, sigma: float) -> float:
        """``C = sqrt(sigma'(eps)/rho0)`` (m/s) at the state of ``sigma`` on the path (on a
        fan of this curve: a curved branch, not a corner)."""
        mat = self.material
        eps = mat.path_strain(sigma)
        return math.sqrt(mat.branch(eps).slope(eps) / mat.rho0)

    def waves(self, sigma: float) -> tuple:
        """The hull's shocks and fans, leading first."""
        if sigma == self.ahead.sigma:
            return ()
        self.check_stress(sigma)
        mat, d = self.material, self.direction
        waves = []
        for kind, ahead, behind, speed, start, end in self._solve(sigma)[0]:
            if kind == "shock":
                waves.append(Shock(ahead=ahead, behind=behind, speed=d * speed, direction=d))
                continue
            head = math.sqrt(mat.branch(start, upper=False).slope(start) / mat.rho0)
            tail = math.sqrt(mat.branch(end, upper=True).slope(end) / mat.rho0)
            waves.append(Fan(ahead=ahead, behind=behind, head_speed=d * head,
                             tail_speed=d * tail, direction=d, curve=self))
        return tuple(waves)

