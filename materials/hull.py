"""The convex-hull construction as a wave curve (Davison ch. 9, 10; Lax–Oleinik).

Conventions of PHYSICS.md: stress ``sigma`` positive in compression (Pa),
compression ``eps = 1 - v/v0``, SI units.

For a solid whose stress along the path a wave follows from a state ``a`` is a
function of the compression alone, ``sigma = f(eps)`` (no energy dependence: the
energy is carried by the jump conditions and ``de = -sigma dv``), the admissible
wave from ``a`` to a target stress is read off a hull of the path (the
Oleinik/Lax construction for a scalar flux; Davison §10.2 for the elastic–plastic
split):

- compression from ``eps_a`` to ``eps_b > eps_a``: the *upper concave hull* of
  ``f`` on ``[eps_a, eps_b]``;
- release from ``eps_a`` to ``eps_b < eps_a``: the *lower convex hull* on
  ``[eps_b, eps_a]``.

Where the hull is a chord the wave is a shock at Lagrangian speed
``U = sqrt(slope / rho0)`` (exact jump conditions between the two end states);
where it runs on the path, a centred fan whose characteristics run at
``C = sqrt(f'(eps) / rho0)``.  Speeds decrease from the leading piece to the
last, so the pieces are separated in the X–t plane.  A chord that leaves or
joins a curved part of the path is tangent to it there (``f'(eps_T) = slope``).

Release is mapped onto compression by ``x = -eps``, ``F(x) = -f(-x)`` (the lower
convex hull of ``f`` is the upper concave hull of ``F``), so one construction
serves both.

How it is computed: the path is sampled once per wave curve (dense where the
path's owner says it bends, every corner a sample) and the upper hull of the
samples up to any ``x`` is kept as a persistent chain (``pred[k]``: the hull
vertex before sample ``k`` in the hull of samples ``0..k``, Andrew's monotone
chain), so the hull up to a target is a walk of a few links.  The sampled hull
fixes the *topology* (which pieces, in what order); every chord end that lies on
a smooth part of the path is then refined to the exact tangent point (bracketed
Newton on ``f'(x)(x_j - x) - (f(x_j) - f(x)) = 0``; alternately on both ends of
a bitangent), so the states, jump conditions and speeds are exact to rounding.
The velocity jump across a fan, ``int sqrt(f'/rho0) dx``, and its energy jump,
``v0 int f dx``, are Gauss–Legendre sums (6 points per sample interval,
the path being smooth between samples), exact to rounding for smooth paths.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from .errors import StateOutOfRangeError
from .quadrature import unit_rule
from .roots import bracketed_newton
from .state import State
from .wavecurves import StressRange, check_curve_arguments
from .waves import Fan, Shock

_QUAD_POINTS = 6
"""Gauss–Legendre points per sample interval for the fan integrals (the path is
smooth between samples, which are closest where it bends most)."""


@dataclass(frozen=True)
class StrainPath:
    """A monotone stress–compression path from a state, in hull coordinates.

    ``x`` is ``eps`` (compression) or ``-eps`` (release) and ``F(x) = +-sigma``, so
    ``F`` increases with ``x``.  ``stress(x)`` and ``slope(x, side)`` (``dF/dx =
    dsigma/deps`` > 0; at a corner the slope beyond it for ``side=1``, before it for
    ``side=-1``) take floats (returning floats) and numpy arrays; ``samples`` are the
    sample abscissae from the start ``x[0]`` to the end of the range, with every corner
    (slope jump) among them and flagged in ``corners`` (a boolean array, True at the
    ends too).
    """

    stress: Callable[[np.ndarray], np.ndarray]
    slope: Callable[[np.ndarray], np.ndarray]
    samples: np.ndarray
    corners: np.ndarray


class Hull:
    """The upper concave hull of a ``StrainPath`` from its start to any ``x``."""

    def __init__(self, path: StrainPath, rho0: float):
        self.path = path
        self.rho0 = rho0
        xs = np.asarray(path.samples, dtype=float)
        fs = np.asarray(path.stress(xs), dtype=float)
        if xs.ndim != 1 or xs.size < 2 or np.any(np.diff(xs) <= 0.0) or np.any(np.diff(fs) <= 0.0):
            raise StateOutOfRangeError("hull: the path must increase in strain and stress")
        self.xs, self.fs = xs, fs
        self.fixed = np.asarray(path.corners, dtype=bool)
        pred = np.full(xs.size, -1, dtype=int)
        for k in range(1, xs.size):        # persistent monotone chain
            top = k - 1
            while pred[top] >= 0 and self._turn(pred[top], top, xs[k], fs[k]) >= 0.0:
                top = pred[top]
            pred[k] = top
        self.pred = pred.tolist()
        self._tangents: dict[tuple, tuple[float, float]] = {}
        self._cumulative: tuple[np.ndarray, np.ndarray] | None = None
        mids = path.stress(0.5 * (xs[:-1] + xs[1:]))
        chords = 0.5 * (fs[:-1] + fs[1:])
        self._concave = mids > chords + 1e-13 * np.abs(chords)
        """Per sample interval: the path lies above its chord (a fan if on the hull)."""

    def _turn(self, i: int, j: int, x: float, f: float) -> float:
        """Cross product of (j - i) and (p - i): >= 0 when ``j`` is not above the chord i -> p."""
        xs, fs = self.xs, self.fs
        return (xs[j] - xs[i]) * (f - fs[i]) - (fs[j] - fs[i]) * (x - xs[i])

    # --- point queries --------------------------------------------------------------
    def f(self, x: float) -> float:
        return float(self.path.stress(x))

    def slope(self, x: float, side: int = 1) -> float:
        """``F'(x)``; at a corner the slope beyond it (``side=1``) or before it (``-1``)."""
        return float(self.path.slope(x, side))

    def x_at(self, f: float) -> float:
        """The abscissa where the path reaches ``F = f`` (bracketed Newton between samples)."""
        k = int(np.searchsorted(self.fs, f))
        if k == 0:
            return float(self.xs[0])
        if k >= self.xs.size:
            raise StateOutOfRangeError("hull: stress beyond the path's range")
        if self.fs[k] == f:
            return float(self.xs[k])
        lo, hi = float(self.xs[k - 1]), float(self.xs[k])
        return bracketed_newton(lambda x: (self.f(x) - f, self.slope(x)), lo, hi,
                                rel_tol=2e-16, f_lo=float(self.fs[k - 1]) - f,
                                f_hi=float(self.fs[k]) - f, f_tol=4e-16 * abs(f))

    def _tables(self) -> tuple[np.ndarray, np.ndarray]:
        """Cumulative ``G`` and ``W`` at the samples (Gauss–Legendre per interval; built
        when a fan first needs them)."""
        if self._cumulative is None:
            xs, path = self.xs, self.path
            nodes, weights = unit_rule(_QUAD_POINTS)
            width = np.diff(xs)
            points = (xs[:-1, None] + width[:, None] * nodes).ravel()
            shape = (width.size, nodes.size)
            speed = np.sqrt(path.slope(points, 1).reshape(shape) / self.rho0)
            stress = path.stress(points).reshape(shape)
            self._cumulative = (np.concatenate([[0.0], np.cumsum(width * (speed @ weights))]),
                                np.concatenate([[0.0], np.cumsum(width * (stress @ weights))]))
        return self._cumulative

    def _integral(self, table: np.ndarray, integrand, x: float) -> float:
        """``int_{x0}^{x}`` of the integrand: the table to the sample below, GL beyond."""
        k = min(max(int(np.searchsorted(self.xs, x, side="right")) - 1, 0), self.xs.size - 2)
        nodes, weights = unit_rule(_QUAD_POINTS)
        width = x - self.xs[k]
        points = self.xs[k] + width * nodes
        return float(table[k] + width * (integrand(points) @ weights))

    def riemann(self, x: float) -> float:
        """``G(x) = int_{x0}^{x} sqrt(F'/rho0) dx`` (m/s)."""
        return self._integral(self._tables()[0],
                              lambda p: np.sqrt(self.path.slope(p, 1) / self.rho0), x)

    def work(self, x: float) -> float:
        """``W(x) = int_{x0}^{x} F dx`` (Pa): ``v0 W`` is the energy along the path."""
        return self._integral(self._tables()[1], self.path.stress, x)

    # --- the hull --------------------------------------------------------------------
    def pieces(self, x: float) -> list[tuple[str, float, float]]:
        """The hull from the start to ``x``: ``(kind, x_start, x_end)``, leading first."""
        xs = self.xs
        f_end = self.f(x)
        k = int(np.searchsorted(xs, x, side="left")) - 1
        if k < 0:
            return []
        top = k
        while self.pred[top] >= 0 and self._turn(self.pred[top], top, x, f_end) >= 0.0:
            top = self.pred[top]
        chain = [top]
        while self.pred[chain[-1]] >= 0:
            chain.append(self.pred[chain[-1]])
        chain.reverse()
        raw: list[list] = []   # [kind, i, j] with j = None for the target
        for i, j in zip(chain[:-1], chain[1:], strict=True):
            raw.append(["fan" if j == i + 1 and self._concave[i] else "shock", i, j])
        last_kind = "shock"
        if top == k and self._curve_above(float(xs[k]), x):
            last_kind = "fan"
        raw.append([last_kind, top, None])
        merged: list[list] = []
        for kind, i, j in raw:
            # fans on either side of a corner stay two: the speed jumps there
            if merged and kind == "fan" and merged[-1][0] == "fan" and not self.fixed[i]:
                merged[-1][2] = j
            else:
                merged.append([kind, i, j])
        return self._refine(merged, x)

    def _curve_above(self, a: float, b: float) -> bool:
        """Whether the path at mid-interval lies above the chord (locally concave: a fan)."""
        mid = 0.5 * (a + b)
        chord = 0.5 * (self.f(a) + self.f(b))
        return self.f(mid) > chord + 1e-13 * abs(chord)

    def _refine(self, merged: list[list], x_end: float) -> list[tuple[str, float, float]]:
        """Abscissae of the pieces, chord ends on smooth parts moved to the tangent points."""
        ends = [[float(self.xs[i]), x_end if j is None else float(self.xs[j])]
                for _, i, j in merged]
        for n, (kind, i, j) in enumerate(merged):
            if kind != "shock":
                continue
            free_start = n > 0 and merged[n - 1][0] == "fan" and not self.fixed[i]
            free_end = (j is not None and n + 1 < len(merged) and merged[n + 1][0] == "fan"
                        and not self.fixed[j])
            if not (free_start or free_end):
                continue
            key = (i, j if j is not None else x_end)
            if key not in self._tangents:
                self._tangents[key] = self._tangent(i, j, x_end, free_start, free_end)
            start, end = self._tangents[key]
            ends[n] = [start, end]
            if free_start:
                ends[n - 1][1] = start
            if free_end:
                ends[n + 1][0] = end
        return [(kind, a, b) for (kind, _, _), (a, b) in zip(merged, ends, strict=True)
                if b > a]

    def _tangent(self, i, j, x_end, free_start, free_end) -> tuple[float, float]:
        """End points of a chord tangent to the path at its free end(s)."""
        xs = self.xs
        a = float(xs[i])
        b = x_end if j is None else float(xs[j])
        for _ in range(60):
            a_old, b_old = a, b
            if free_start:
                a = self._touch(b, i, before=False)
            if free_end:
                b = self._touch(a, j, before=True)
            if a == a_old and b == b_old:
                break
        return a, b

    def _touch(self, anchor: float, k: int, before: bool) -> float:
        """Point near sample ``k`` where the chord from ``anchor`` is tangent to the path."""
        lo = float(self.xs[max(k - 1, 0)])
        hi = float(self.xs[min(k + 1, self.xs.size - 1)])
        f_anchor = self.f(anchor)
        step = 1e-6 * (hi - lo)

        def residual(x):
            # r' = F''(x) (anchor - x); F'' by a central difference (Newton's step only)
            curvature = (self.slope(x + step) - self.slope(x - step)) / (2.0 * step)
            return (self.slope(x) * (anchor - x) - (f_anchor - self.f(x)),
                    curvature * (anchor - x))

        r_lo, r_hi = residual(lo)[0], residual(hi)[0]
        if r_lo * r_hi > 0.0:   # the tangent point sits at a sample: keep it
            return float(self.xs[k])
        return bracketed_newton(residual, lo, hi, rel_tol=2e-16, f_lo=r_lo, f_hi=r_hi)


_CACHED_HULLS = 256
"""Hulls a material keeps (by ahead state): an engine run asks for the wave curves of
the same few states at every ray crossing."""


def _cached_hull(material, ahead: State, loading: bool) -> Hull:
    """The hull of ``material``'s path from ``ahead``, from the material's bounded cache."""
    cache = material.__dict__.setdefault("_hull_cache", {})
    key = (ahead.sigma, ahead.v, ahead.plastic_strain,
           getattr(ahead, "equivalent_plastic_strain", None), loading)
    hull = cache.get(key)
    if hull is None:
        if len(cache) >= _CACHED_HULLS:
            cache.pop(next(iter(cache)))   # the oldest
        hull = cache[key] = Hull(material.strain_path(ahead, loading), material.rho0)
    return hull


class HullWaveCurve(StressRange):
    """A wave curve built by the hull construction on a material's strain paths.

    ``material`` provides ``rho0``, ``v0`` and ``strain_path(ahead, loading)`` (a
    ``StrainPath`` in hull coordinates) and ``path_state(ahead, loading, x, sigma, u,
    e)`` (the ``State`` at abscissa ``x`` of that path, with the history variables
    the model carries).  ``release="hugoniot"`` turns every fan into a chord between
    its ends (one rarefaction shock per piece).

    ``u = u_a + d g(sigma)``, ``g`` the sum over the pieces of ``sqrt(dF dx / rho0)``
    (chords) and ``G(x_end) - G(x_start)`` (fans), negative for release.
    """

    def __init__(self, material, ahead: State, direction: int, release: str = "isentrope"):
        check_curve_arguments(direction, release)
        self.material = material
        self.ahead = ahead
        self.direction = direction
        self.release = release
        self._hulls: dict[bool, Hull] = {}
        self._last: tuple[float, tuple] | None = None

    def hull(self, loading: bool) -> Hull:
        """The hull of the compression (``loading``) or release path (built once)."""
        if loading not in self._hulls:
            self._hulls[loading] = _cached_hull(self.material, self.ahead, loading)
        return self._hulls[loading]

    @property
    def impedance(self) -> float:
        """``rho0 C`` of the ahead state along the compression path."""
        return math.sqrt(self.material.rho0 * self.hull(True).slope(self.hull(True).xs[0]))

    def sigma_limits(self) -> tuple[float, float]:
        up, down = self.hull(True), self.hull(False)
        return float(-down.fs[-1]), float(up.fs[-1])

    def sigma_min(self) -> float:
        return self.sigma_limits()[0]

    def sigma_max(self) -> float:
        return self.sigma_limits()[1]

    def _solve(self, sigma: float) -> tuple:
        """``(pieces as (kind, ahead, behind, speed, x0, x1), g, dg/dsigma)`` (cached)."""
        if self._last is not None and self._last[0] == sigma:
            return self._last[1]
        self.check_stress(sigma)
        mat, a, d = self.material, self.ahead, self.direction
        loading = sigma > a.sigma
        sign = 1.0 if loading else -1.0
        hull = self.hull(loading)
        x_end = hull.x_at(sign * sigma)
        pieces = hull.pieces(x_end)
        if self.release == "hugoniot":
            pieces = [("shock", p[1], p[2]) for p in pieces]
        state, total, out = a, 0.0, []
        for n, (kind, x0, x1) in enumerate(pieces):
            f1 = sign * sigma if n == len(pieces) - 1 else hull.f(x1)
            f0 = sign * state.sigma
            if kind == "shock":
                jump = math.sqrt(max((f1 - f0) * (x1 - x0), 0.0) / mat.rho0)
                e = state.e + mat.v0 * 0.5 * (f0 + f1) * (x1 - x0)
            else:
                jump = hull.riemann(x1) - hull.riemann(x0)
                e = state.e + mat.v0 * (hull.work(x1) - hull.work(x0))
            total += jump
            u = a.u + d * sign * total
            behind = mat.path_state(a, loading, x1, sign * f1, u, e)
            speed = (abs(behind.sigma - state.sigma) / (mat.rho0 * jump) if jump > 0.0
                     else math.sqrt(hull.slope(x0) / mat.rho0))
            out.append((kind, state, behind, speed, x0, x1))
            state = behind
        if not out:
            result = ([], 0.0, 1.0 / self.impedance)
        else:
            kind, first, last, _, x0, x1 = out[-1]
            slope = hull.slope(x1, -1)
            if kind == "fan":
                dg = 1.0 / math.sqrt(mat.rho0 * slope)
            else:
                df = abs(last.sigma - first.sigma)
                chord = math.sqrt(df * (x1 - x0) / mat.rho0)
                dg = ((x1 - x0) + df / slope) / (2.0 * mat.rho0 * chord) if chord > 0.0 \
                    else 1.0 / math.sqrt(mat.rho0 * slope)
            result = (out, sign * total, dg)
        self._last = (sigma, result)
        return result

    def velocity_change(self, sigma: float) -> tuple[float, float]:
        """``(g, dg/dsigma)``: the particle-velocity change ``u - u_a = d g`` (m/s, m/s/Pa)."""
        if sigma == self.ahead.sigma:
            return 0.0, 1.0 / self.impedance
        _, g, dg = self._solve(sigma)
        return g, dg

    def state_at(self, sigma: float) -> State:
        """The state behind the wave that reaches ``sigma``."""
        if sigma == self.ahead.sigma:
            return self.ahead
        out = self._solve(sigma)[0]
        return out[-1][2] if out else self.ahead

    def characteristic_speed(self, sigma: float) -> float:
        """``C = sqrt(dsigma/deps / rho0)`` (m/s) at the path's state of stress ``sigma``."""
        loading = sigma >= self.ahead.sigma
        hull = self.hull(loading)
        sign = 1.0 if loading else -1.0
        return math.sqrt(hull.slope(hull.x_at(sign * sigma)) / self.material.rho0)

    def waves(self, sigma: float) -> tuple:
        """The hull's shocks and fans, leading first."""
        if sigma == self.ahead.sigma:
            return ()
        d, rho0 = self.direction, self.material.rho0
        loading = sigma > self.ahead.sigma
        hull = self.hull(loading)
        waves = []
        for kind, ahead, behind, speed, x0, x1 in self._solve(sigma)[0]:
            if kind == "shock":
                waves.append(Shock(ahead=ahead, behind=behind, speed=d * speed, direction=d))
            else:
                waves.append(Fan(ahead=ahead, behind=behind,
                                 head_speed=d * math.sqrt(hull.slope(x0) / rho0),
                                 tail_speed=d * math.sqrt(hull.slope(x1, -1) / rho0),
                                 direction=d, curve=self))
        return tuple(waves)
