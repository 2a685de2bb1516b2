"""The bracketed root finder and the local bracket: termination and economy."""

from __future__ import annotations

import math

import pytest

from materials.errors import NoSolutionError
from materials.roots import bracket_near, bracketed_newton


def counted(func):
    calls = []

    def wrapper(x):
        calls.append(x)
        return func(x)

    return wrapper, calls


def test_root_between_two_neighbouring_floats_ends_at_once():
    """A steep residual (the volume root of a wave curve: slope -1.2e15 Pa kg/m^3) whose
    root lies between two adjacent floats, with f_tol below one ulp step of f: the
    bracket of two neighbours cannot shrink, and the search must stop there instead
    of bisecting in place until its iteration cap (it did, 200 evaluations a root)."""
    x_lo = 0.00025010446806610076
    x_hi = math.nextafter(x_lo, 1.0)
    slope = -1.228693e15

    def residual(x):  # the values the float evaluation of the steep residual gave
        if x in (x_lo, x_hi):
            return (3.468990e-05 if x == x_lo else -3.373623e-05), slope
        return slope * (x - x_lo) + 3.468990e-05, slope

    func, calls = counted(residual)
    x = bracketed_newton(func, 0.00025009908768166775, 0.00025010715792555253,
                         0.0002501044678442576, rel_tol=2e-16, f_tol=9.071131932781972e-07)
    assert x in (x_lo, x_hi)
    assert len(calls) < 10


def test_newton_converges_quadratically_from_a_good_guess():
    func, calls = counted(lambda x: (x * x - 2.0, 2.0 * x))
    assert bracketed_newton(func, 1.0, 2.0, 1.4) == pytest.approx(math.sqrt(2.0), rel=4e-16)
    assert len(calls) <= 8  # two ends, then a handful of Newton steps


def test_unbracketed_root_is_a_named_error():
    with pytest.raises(NoSolutionError, match="not bracketed"):
        bracketed_newton(lambda x: (x * x + 1.0, 2.0 * x), -1.0, 1.0)


def test_bracket_near_costs_two_evaluations_near_a_good_guess():
    func, calls = counted(lambda x: (math.exp(x) - 3.0, math.exp(x)))
    lo, hi, start, f_lo, f_hi = bracket_near(func, 1.0)
    assert lo < math.log(3.0) < hi and f_lo < 0.0 < f_hi and lo <= start <= hi
    assert len(calls) == 2


def test_bracket_near_declines_outside_its_limits():
    assert bracket_near(lambda x: (x - 10.0, 1.0), 0.0, upper=5.0) is None
    assert bracket_near(lambda x: (x - 1.0, 0.0), 0.0) is None  # no slope, no step
