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

from .errors import NoSolutionError, StateOutOfRangeError

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

    ``f(lo)`` and ``f(hi)`` must differ in sign (a zero at an end, or an end within
    ``f_tol`` of zero, is accepted).
    Iteration stops when the bracket is narrower than ``rel_tol * |x| + abs_tol``
    (or one ulp of x), or when ``|f| <= f_tol``: callers whose ``f`` is computed
    with a known rounding noise pass that noise as ``f_tol``, so that the iteration
    does not bisect through noise once Newton has converged.
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
        # an end within the caller's noise is the root (a jump of an ulp of stress ends
        # where it starts, and its residual there is rounding of either sign)
        end, f_end = (lo, f_lo) if abs(f_lo) <= abs(f_hi) else (hi, f_hi)
        if abs(f_end) <= f_tol:
            return end
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
        # never below one ulp: a bracket of two neighbouring floats cannot shrink, and
        # where the slope is steep |f| may stay above f_tol on both of them
        tol = max(rel_tol * abs(x) + abs_tol, math.ulp(x))
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


_LOCAL_TRIES = 6


def bracket_near(
    func: Callable[[float], tuple[float, float]],
    guess: float,
    lower: float = -math.inf,
    upper: float = math.inf,
    f_tol: float = 0.0,
) -> tuple[float, float, float, float, float] | None:
    """A bracket ``(lo, hi, start, f_lo, f_hi)`` around the root of a monotone ``func``
    nearest ``guess``, or ``None``.

    One Newton step from a good guess, overshot by half, almost always lands on the
    other side of the root: the bracket then costs two evaluations near the answer
    instead of evaluations at the far ends of the admissible interval, and ``start``
    (the Newton point) is where the bracketed iteration should begin.  The step
    doubles up to a few times while the sign does not change.  Returns ``None`` (the
    caller then brackets globally) when a trial leaves ``[lower, upper]``, when a
    trial leaves an equation of state's range, or when the slope at the guess is
    zero or not finite.  A guess with ``|f| <= f_tol`` (the caller's rounding noise, as in
    ``bracketed_newton``) is the root: the degenerate bracket ``(guess, guess, guess, 0,
    0)`` says so, and stepping through noise would only move it.
    """
    if not lower <= guess <= upper:
        return None
    try:
        f0, df0 = func(guess)
        if abs(f0) <= f_tol:
            return guess, guess, guess, 0.0, 0.0
        if df0 == 0.0 or not math.isfinite(df0):
            return None
        step = -1.5 * f0 / df0
        for _ in range(_LOCAL_TRIES):
            trial = guess + step
            if not lower <= trial <= upper:
                return None
            f1 = func(trial)[0]
            if (f1 > 0.0) != (f0 > 0.0) or f1 == 0.0:
                start = guess + step / 1.5
                if trial > guess:
                    return guess, trial, start, f0, f1
                return trial, guess, start, f1, f0
            guess, f0 = trial, f1
            step *= 2.0
    except (NoSolutionError, StateOutOfRangeError):
        return None
    return None
