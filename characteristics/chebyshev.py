"""Chebyshev interpolants on panels: the tables behind the invariants.

A function analytic on ``[a, b]`` and some way around it is represented by its
interpolant at the ``n`` Chebyshev points of the first kind,

    f(x) ~ sum_k c_k T_k(z),    z = (2x - a - b) / (b - a),

whose coefficients fall geometrically; when the last ones are at rounding the
interpolant *is* the function to rounding.  Evaluation is Clenshaw's recurrence.
The antiderivative of the interpolant is again a Chebyshev series, so an
integral such as ``phi(v) = -rho0 int C_L dv`` costs no quadrature once ``C_L``
is tabulated.
"""

from __future__ import annotations

import numpy as np

POINTS = 24
"""Chebyshev points per panel.  The isentrope functions are analytic over several
panel widths, so their coefficients reach rounding well before the 24th."""

_THETA = np.pi * (np.arange(POINTS) + 0.5) / POINTS
UNIT_POINTS = np.cos(_THETA)
"""The Chebyshev points of the first kind on ``[-1, 1]`` (descending)."""
_TRANSFORM = (2.0 / POINTS) * np.cos(np.outer(_THETA, np.arange(POINTS)))
_TRANSFORM[:, 0] *= 0.5


def points(a: float, b: float) -> np.ndarray:
    """The Chebyshev points of ``[a, b]``."""
    return 0.5 * (a + b) + 0.5 * (b - a) * UNIT_POINTS


def coefficients(values: np.ndarray) -> np.ndarray:
    """Chebyshev coefficients of the interpolant through ``values`` at ``points(a, b)``."""
    return values @ _TRANSFORM


def converged(coefs: np.ndarray, scale: float) -> bool:
    """True when the last three coefficients are below 1e-14 of ``scale``: the
    interpolant matches the function to about that relative accuracy."""
    return bool(np.max(np.abs(coefs[-3:])) <= 1e-14 * scale)


def antiderivative(coefs: np.ndarray, a: float, b: float) -> np.ndarray:
    """Coefficients of ``int_a^x f`` (zero at ``x = a``) for the series ``coefs`` on ``[a, b]``."""
    return np.polynomial.chebyshev.chebint(coefs, scl=0.5 * (b - a), lbnd=-1.0)


def evaluate(coefs, a: float, b: float, x: float) -> float:
    """The series ``coefs`` (a list of floats) on ``[a, b]`` at a float ``x`` (Clenshaw)."""
    z2 = 2.0 * (2.0 * x - a - b) / (b - a)
    b1 = b2 = 0.0
    for c in coefs[:0:-1]:
        b1, b2 = z2 * b1 - b2 + c, b1
    return 0.5 * z2 * b1 - b2 + coefs[0]


def values(coefs: np.ndarray, a: float, b: float, x: np.ndarray) -> np.ndarray:
    """One series on ``[a, b]`` at an array ``x`` inside it, as ``T_k(z) = cos(k arccos z)``
    (three array operations instead of a recurrence over the coefficients)."""
    z = np.clip((2.0 * x - a - b) / (b - a), -1.0, 1.0)
    return np.cos(np.outer(np.arccos(z), np.arange(len(coefs)))) @ coefs


def derivative(coefs: np.ndarray, a: float, b: float) -> np.ndarray:
    """Coefficients of ``df/dx`` for the series ``coefs`` on ``[a, b]``."""
    return np.polynomial.chebyshev.chebder(coefs, scl=2.0 / (b - a))


def evaluate_many(coefs: np.ndarray, a: np.ndarray, b: np.ndarray, x: np.ndarray) -> np.ndarray:
    """Series ``coefs[i]`` on ``[a[i], b[i]]`` at ``x[i]`` for arrays (one row per point)."""
    z2 = 2.0 * (2.0 * x - a - b) / (b - a)
    b1 = np.zeros_like(z2)
    b2 = np.zeros_like(z2)
    for k in range(coefs.shape[-1] - 1, 0, -1):
        b1, b2 = z2 * b1 - b2 + coefs[..., k], b1
    return 0.5 * z2 * b1 - b2 + coefs[..., 0]
