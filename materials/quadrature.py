"""Gauss–Legendre quadrature on panels, for isentrope integrals.

The integrands met along isentropes (stress, sound speed) are analytic inside a
material's range of validity, so a 20-point Gauss–Legendre rule on panels no
wider than a few per cent of the reference volume integrates them to rounding.
"""

from __future__ import annotations

import functools
import math

import numpy as np

GAUSS_POINTS = 20
_NODES, _WEIGHTS = np.polynomial.legendre.leggauss(GAUSS_POINTS)
UNIT_NODES = 0.5 * (_NODES + 1.0)
"""Gauss–Legendre nodes mapped to [0, 1]."""
UNIT_WEIGHTS = 0.5 * _WEIGHTS
"""Weights for the nodes on [0, 1] (they sum to one)."""


def panel_edges(a: float, b: float, max_width: float) -> np.ndarray:
    """Edges of equal panels from ``a`` to ``b`` (either order), none wider than ``max_width``."""
    count = max(1, math.ceil(abs(b - a) / max_width))
    return np.linspace(a, b, count + 1)


@functools.cache
def unit_rule(points: int) -> tuple[np.ndarray, np.ndarray]:
    """``points``-point Gauss–Legendre nodes and weights mapped to [0, 1]."""
    nodes, weights = np.polynomial.legendre.leggauss(points)
    return 0.5 * (nodes + 1.0), 0.5 * weights


@functools.cache
def unit_rule_lists(points: int) -> tuple[tuple[float, ...], tuple[float, ...]]:
    """``unit_rule(points)`` as tuples of floats, for short quadratures done with floats."""
    nodes, weights = unit_rule(points)
    return tuple(nodes.tolist()), tuple(weights.tolist())


def points_for(width: float, singularity_distance: float) -> int:
    """Gauss–Legendre points that integrate an analytic function to rounding on a panel.

    The error of an ``n``-point rule on a panel of ``width`` whose integrand's
    nearest singularity lies ``singularity_distance`` away falls like
    ``(width / (4 distance))^(2n)``; the smallest even ``n`` (at most
    ``GAUSS_POINTS``) bringing that below 1e-17 is returned.  Short panels, the
    common case inside an iteration that has nearly converged, need only a few.
    """
    ratio = abs(width) / (4.0 * singularity_distance)
    if ratio <= 0.0:
        return 2
    points = math.ceil(-17.0 / (2.0 * math.log10(ratio))) if ratio < 1.0 else GAUSS_POINTS
    return min(GAUSS_POINTS, max(2, points + points % 2))
