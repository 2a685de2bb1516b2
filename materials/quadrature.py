"""Gauss–Legendre quadrature on panels, for isentrope integrals.

The integrands met along isentropes (stress, sound speed) are analytic inside a
material's range of validity, so a 20-point Gauss–Legendre rule on panels no
wider than a few per cent of the reference volume integrates them to rounding.
"""

from __future__ import annotations

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
