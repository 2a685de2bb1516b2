"""Errors raised by equation-of-state models and the Riemann solver.

Every error names the quantity at fault and the range that is allowed, so a
user who mistypes a thickness or drives a material beyond its fit sees what to
change. Every error that is the user's input's fault derives from
``WavediagramError``, the one class the command line catches (exit status 2);
the ones raised here also derive from ``ValueError`` so callers may catch either.
"""


class WavediagramError(Exception):
    """Base of every user-facing error: bad input, a state beyond a model, a limit reached."""


class MaterialError(WavediagramError, ValueError):
    """A material definition is invalid (unknown name, bad parameter)."""


class StateOutOfRangeError(WavediagramError, ValueError):
    """A state lies outside the range in which an equation of state is valid."""


class NoSolutionError(WavediagramError, ValueError):
    """A Riemann problem has no solution inside the materials' ranges of validity."""
