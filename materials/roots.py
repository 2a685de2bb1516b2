"""Bracketed scalar root finding.

Wave curves are monotone, so every root the project needs is bracketed.  The
method here is the safeguarded Newton iteration of Numerical Recipes
(``rtsafe``): a Newton step is taken only when it stays strictly inside the
current bracket and shrinks it fast enough, otherwise the step is a bisection.
It therefore never leaves the bracket and converges quadratically near the root.
"""

from __future__ import annotations

import math
from collections.abc import Callable

from .errors import NoSolutionError

_MAX_ITERATIONS = 200

EPS = 2.0**-52
"""Machine epsilon of a float: callers scale their ``f_tol`` noise estimates by it."""


def bracketed_newton(
    func: Callable[[float], tuple[float, float]],
    lo: float,
    hi: float,
    guess: float | None = None,
    rel_tol: float = 4e-16,
    abs_tol: float = 0.0,
    f_lo: float | None = None,
    f_hi: float | None = None,
    f_tol: float = 0.0,
) -> float:
    """Root of ``func`` in ``[lo, hi]``; ``func(x)`` returns ``(f, df/dx)``.

    ``f(lo)`` and ``f(hi)`` must differ in sign (a zero at an end is accepted).
    Iteration stops when the bracket is narrower than
    ``rel_tol * |x| + abs_tol``, or when ``|f| <= f_tol``: callers whose ``f`` is
    computed with a known rounding noise pass that noise as ``f_tol``, so that
    the iteration does not bisect through noise once Newton has converged.
    """
    if lo > hi:
        lo, hi = hi, lo
    if f_lo is None:
        f_lo = func(lo)[0]
    if f_lo == 0.0:
        return lo
    if f_hi is None:
        f_hi = func(hi)[0]
    if f_hi == 0.0:
        return hi
    if (f_lo > 0.0) == (f_hi > 0.0):
        raise NoSolutionError(
            f"root not bracketed in [{lo:.6g}, {hi:.6g}]: f = {f_lo:.6g}, {f_hi:.6g}"
        )
    increasing = f_hi > 0.0
    x = 0.5 * (lo + hi) if guess is None or not lo < guess < hi else guess
    step_old = hi - lo
    for _ in range(_MAX_ITERATIONS):
        f, df = func(x)
        if abs(f) <= f_tol:
            return x
        if (f > 0.0) == increasing:
            hi = x
        else:
            lo = x
        tol = rel_tol * abs(x) + abs_tol
        if hi - lo <= tol:
            return x
        newton_ok = df != 0.0 and math.isfinite(df)
        if newton_ok:
            x_new = x - f / df
            step = abs(x_new - x)
            if step <= tol:
                return x_new if lo <= x_new <= hi else x
            newton_ok = lo < x_new < hi and step < 0.5 * step_old
        if newton_ok:
            step_old = step
            x = x_new
        else:
            step_old = hi - lo
            x = 0.5 * (lo + hi)
    return x
