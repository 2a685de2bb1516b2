"""Chebyshev tables of one continuous wave path: stress, sound speed and path integral.

A centred fan follows a continuous path ``sigma(v)`` from its start ``v_s``; the
particle-velocity change across it is the path integral

    J(v) = int_{v_s}^{v} rho0 C(w) dw,        C = v0 sqrt(-dsigma/dv)   (Lagrangian).

A Riemann solve asks for ``sigma`` (to find the volume of a target stress by Newton's
method) and ``J`` (the velocity) a dozen times, at volumes close to one another.  When
the path has a closed form but ``J`` does not (``materials.finite_plastic``), each of
those calls used to cost a quadrature.  ``PathTable`` samples the path once per panel
instead and answers every later call by a short Clenshaw recurrence.

Method
------
From ``v_s`` towards the path's end ``v_e`` the volumes are cut into panels no wider
than ``width`` (built lazily, one at a time, as far as a call reaches).  On a panel
``[p0, p1]`` (``x = 2 (v - p0)/(p1 - p0) - 1``) the stress and the speed are sampled at
the ``n`` Chebyshev points of the first kind and replaced by their Chebyshev
interpolants; ``J`` is the exact integral of the speed's interpolant (``chebint``),
continued from the panel's start.  For a function analytic inside the Bernstein
ellipse of parameter ``rho`` around the panel the interpolation error falls like
``rho^-n`` (Trefethen, *Approximation Theory and Approximation Practice*, ch. 8);
a singularity at ``d`` from a panel of half-width ``h`` gives ``rho ~ 2 d/h``.  The
paths met here are analytic at least ``0.4 v0`` from the volumes of a panel
``0.05 v0`` wide (as for the isentrope quadratures of ``materials.base``), so
``rho >= 32`` and ``n = 20`` points leave an error of ``32^-20 ~ 1e-30``: the tables
agree with the direct evaluation and quadrature to rounding (``tests/test_path_table.py``
checks 1e-13 over random states).
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np

from .base import _clenshaw

CHEBYSHEV_POINTS = 20
"""Chebyshev points (and series length) per panel."""

_THETA = np.pi * (np.arange(CHEBYSHEV_POINTS) + 0.5) / CHEBYSHEV_POINTS
_NODES = np.cos(_THETA)
"""Chebyshev points of the first kind on [-1, 1] (decreasing)."""
_TRANSFORM = (2.0 / CHEBYSHEV_POINTS) * np.cos(np.outer(_THETA, np.arange(CHEBYSHEV_POINTS)))
_TRANSFORM[:, 0] *= 0.5
"""Values at ``_NODES`` times this matrix are the Chebyshev coefficients."""
_INTEGRATE = _TRANSFORM @ np.polynomial.chebyshev.chebint(
    np.eye(CHEBYSHEV_POINTS), lbnd=-1.0, axis=0).T
"""Values at ``_NODES`` times this matrix are the coefficients of the interpolant's
integral from ``x = -1`` (one more than the interpolant's)."""
_CUMULATIVE = _INTEGRATE @ np.cos(np.outer(np.arange(CHEBYSHEV_POINTS + 1), _THETA))
"""Values at ``_NODES`` times this matrix are the interpolant's integrals from ``x = -1``
to each node (spectral integration)."""


def panel_nodes(p0: float, p1: float) -> np.ndarray:
    """The volumes at which a table samples its panel ``[p0, p1]`` (Chebyshev points)."""
    half = 0.5 * (p1 - p0)
    return p0 + half * (_NODES + 1.0)


def panel_integral(values: np.ndarray, p0: float, p1: float) -> np.ndarray:
    """``int_{p0}^{w} f dv`` at the nodes ``w`` of the panel, from ``f`` at those nodes.

    The integral of the Chebyshev interpolant, exact to rounding for an ``f`` analytic
    well beyond the panel (as the table itself): a path given by an ordinary
    differential equation with an integrating factor is sampled with it.
    """
    return (0.5 * (p1 - p0)) * (values @ _CUMULATIVE)


_CHOP = 4.0 * 2.0**-52
"""Trailing coefficients below this fraction of a series' largest are dropped: the
rounding noise of the sampled values alone puts the coefficients of an interpolant that
has converged at a few ``2^-52`` of the largest, so the tail carries nothing but noise."""


_MAX_KEPT = 4096
"""Answers of ``PathTable.stress`` a table keeps; beyond it the store starts again."""


_SLIVER = 1e-9
"""A panel ending within this fraction of its width of the path's end ends there."""


def _series(coefficients: np.ndarray) -> tuple[float, tuple[float, ...]]:
    """``(c_0, (c_m, ..., c_1))``: a series, its negligible tail chopped (``_CHOP``), stored
    in the order Clenshaw uses it."""
    values = coefficients.tolist()
    floor = _CHOP * max(abs(c) for c in values)
    count = len(values)
    while count > 1 and abs(values[count - 1]) <= floor:
        count -= 1
    return values[0], tuple(values[count - 1:0:-1])


class PathTable:
    """Piecewise Chebyshev table of a path ``v -> (sigma, C)`` and of ``J = int rho0 C dv``.

    Parameters
    ----------
    sample : callable
        ``sample(p0, p1) -> (sigma, C)`` on the panel ``[p0, p1]`` at its
        ``panel_nodes`` (arrays, Pa and m/s).  It may raise ``StateOutOfRangeError`` (a
        path leaving its equation of state); a panel that raises is not stored.
    start, end : float
        The path's first and last volumes (m^3/kg); ``end`` may lie on either side.
    width : float
        Largest panel width (m^3/kg), chosen so that the path is analytic well
        beyond each panel (see the module notes).
    rho0 : float
        Reference density (kg/m^3) in ``J``.
    store : list, optional
        Panels shared with other tables of the same path (same ``sample``, ``start``,
        ``end``, ``width`` and ``rho0``): a panel one of them built is taken from it, not
        sampled again.  Each table still reaches only as far as its own calls have
        asked (``within``), so what it answers does not depend on the others.
    """

    def __init__(self, sample: Callable[[float, float], tuple[np.ndarray, np.ndarray]],
                 start: float, end: float, width: float, rho0: float,
                 store: list | None = None):
        self._sample = sample
        self._store = [] if store is None else store
        self.start = float(start)
        self.end = float(end)
        self._step = math.copysign(width, self.end - self.start)
        self._rho0 = rho0
        self._edges = [self.start]        # panel edges, from the start
        self._panels: list[tuple] = []    # (p0, p1, sigma series, C series, J series, J0)
        self._last: tuple | None = None   # (v, panel, x) of the last volume located
        self._stresses: dict[float, tuple[float, float]] = {}   # stress(v) by v

    def _build_next(self) -> None:
        index = len(self._panels)
        if index < len(self._store):   # built by a table of the same path
            panel = self._store[index]
            self._panels.append(panel)
            self._edges.append(panel[1])
            return
        p0 = self._edges[-1]
        p1 = p0 + self._step
        if (p1 - self.end) * self._step > -_SLIVER * self._step**2:   # no sliver at the end
            p1 = self.end
        half = 0.5 * (p1 - p0)
        sigma, speed = self._sample(p0, p1)
        c_sigma, c_speed = np.stack((sigma, speed)) @ _TRANSFORM
        c_j = (self._rho0 * half) * (speed @ _INTEGRATE)
        j0 = 0.0
        if self._panels:
            last = self._panels[-1]
            j0 = last[5] + _clenshaw(last[4], 1.0)
        panel = (p0, p1, _series(c_sigma), _series(c_speed), _series(c_j), j0)
        self._panels.append(panel)
        self._store.append(panel)
        self._edges.append(p1)

    def _panel(self, v: float) -> tuple:
        """The panel holding ``v``, built (with those before it) if needed."""
        step = self._step
        offset = (v - self.start) / step
        index = int(offset)
        panels = self._panels
        if 0 <= index < len(panels) - 1:   # a whole panel before the last edge: built
            return panels[index]
        while (v - self._edges[-1]) * step > 0.0 and self._edges[-1] != self.end:
            self._build_next()
        if not panels:
            self._build_next()
        return panels[min(max(index, 0), len(panels) - 1)]

    def within(self, v: float) -> bool:
        """True when ``v`` lies on the panels built so far (or on the first panel, which
        is then built): the table answers there without sampling more of the path.  A
        root finder probing far along the path is better served by the closed form."""
        if (v - self.start) * self._step < 0.0 or (v - self.end) * self._step > 0.0:
            return False
        reach = self._edges[-1] if self._panels else self.start + self._step
        return (v - reach) * self._step <= 0.0

    def _locate(self, v: float) -> tuple[tuple, float]:
        """``(panel, x)``: the panel holding ``v`` and ``v`` mapped to its ``[-1, 1]``;
        the last answer is kept (a Riemann solve asks ``integral`` at the volume it has
        just asked ``stress`` at)."""
        last = self._last
        if last is not None and last[0] == v:
            return last[1], last[2]
        panel = self._panel(v)
        p0, p1 = panel[0], panel[1]
        x = 2.0 * (v - p0) / (p1 - p0) - 1.0 if p1 != p0 else -1.0
        self._last = (v, panel, x)
        return panel, x

    def stress(self, v: float) -> tuple[float, float]:
        """``(sigma, dsigma/dv)`` on the path at ``v`` (Pa, Pa kg/m^3), the slope
        ``-(C/v0)^2 = -(rho0 C)^2``.  Answers are kept by volume (up to
        ``_MAX_KEPT``): root searches on one table ask the same volumes again."""
        kept = self._stresses.get(v)
        if kept is not None:
            return kept
        panel, x = self._locate(v)
        speed = self._rho0 * _clenshaw(panel[3], x)
        answer = _clenshaw(panel[2], x), -speed * speed
        if len(self._stresses) >= _MAX_KEPT:
            self._stresses.clear()
        self._stresses[v] = answer
        return answer

    def integral(self, v: float) -> float:
        """``J(v) = int_{start}^{v} rho0 C dw`` (m/s)."""
        if v == self.start:
            return 0.0
        panel, x = self._locate(v)
        return panel[5] + _clenshaw(panel[4], x)
