"""Errors raised by equation-of-state models and the Riemann solver.

Every error names the quantity at fault and the range that is allowed, so a
user who mistypes a thickness or drives a material beyond its fit sees what to
change. They derive from ``ValueError`` so callers may catch either.
"""


class MaterialError(ValueError):
    """A material definition is invalid (unknown name, bad parameter)."""


class StateOutOfRangeError(ValueError):
    """A state lies outside the range in which an equation of state is valid."""


class NoSolutionError(ValueError):
    """A Riemann problem has no solution inside the materials' ranges of validity."""
