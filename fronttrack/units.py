"""Quantities with units, as written in scene files, converted to SI floats.

A scene file writes every dimensional number with its unit (``"1 mm"``,
``"2.6 km/s"``, ``"0.2 GPa"``) so that a millimetre is never read as a metre.
``parse_quantity`` turns such a string into a float in the project's internal
units (m, s, m/s, Pa, kg/m^3, J/kg, J/(kg K)); a bare number is accepted only
for dimensionless quantities.  Stress keeps the project's sign convention:
positive in compression, so ``"-0.5 GPa"`` is a tension.

``to_si`` is the rule of the Python API: a number is already SI, a string is
parsed as in a file.  Errors raise ``SceneError`` naming the field, the text received and the units
allowed, for example::

    layer[0].thickness: missing units in "5" (use one of m, mm, um, µm, cm, in)
"""

from __future__ import annotations

import math
import numbers
import re
from fractions import Fraction

from .errors import SceneError

_F = Fraction

UNITS: dict[str, dict[str, Fraction]] = {
    "length": {"m": _F(1), "mm": _F(1, 10**3), "um": _F(1, 10**6), "µm": _F(1, 10**6),
               "nm": _F(1, 10**9), "cm": _F(1, 100), "in": _F("0.0254")},
    "time": {"s": _F(1), "ms": _F(1, 10**3), "us": _F(1, 10**6), "µs": _F(1, 10**6),
             "ns": _F(1, 10**9)},
    "velocity": {"m/s": _F(1), "km/s": _F(10**3), "mm/us": _F(10**3), "mm/µs": _F(10**3),
                 "ft/s": _F("0.3048")},
    "stress": {"Pa": _F(1), "kPa": _F(10**3), "MPa": _F(10**6), "GPa": _F(10**9),
               "Mbar": _F(10**11), "kbar": _F(10**8), "bar": _F(10**5)},
    "density": {"kg/m3": _F(1), "kg/m^3": _F(1), "g/cm3": _F(10**3), "g/cm^3": _F(10**3),
                "g/cc": _F(10**3)},
    "specific_energy": {"J/kg": _F(1), "kJ/kg": _F(10**3), "MJ/kg": _F(10**6)},
    "specific_heat": {"J/kg/K": _F(1), "J/(kg K)": _F(1)},
    "temperature": {"K": _F(1)},
    "dimensionless": {"": _F(1)},
}
"""Allowed units of each dimension and their exact factors to SI (1 in = 0.0254 m and
1 ft = 0.3048 m by definition, 1 bar = 1e5 Pa, 1 Mbar = 100 GPa).  The factors are
fractions so that a value is multiplied by an integer and divided by another:
``"3 mm"`` is exactly the float ``3 / 1000``, with no rounding of ``1e-3`` in it."""

MAGNITUDES: dict[str, tuple[float, float]] = {
    "length": (1e-9, 1e3),
    "time": (1e-15, 1e3),
    "velocity": (1e-6, 1e5),
    "stress": (1.0, 1e13),
    "density": (1e-3, 1e5),
    "specific_energy": (1e-3, 1e10),
    "specific_heat": (1e-3, 1e6),
}
"""The smallest and largest magnitude (SI) of a nonzero quantity of each dimension: 1 nm
to 1 km, 1 fs to 1000 s, 1 um/s to 100 km/s, 1 Pa to 10 TPa, and so on.  Zero is always
accepted; a value outside is a typing error or beyond what the solvers resolve (a
thickness of 1e-30 mm, a velocity of 1e-300 m/s that no root finder brackets).
Dimensionless numbers are checked by the field that uses them."""

_NUMBER_AND_UNIT = re.compile(
    r"\s*(?P<number>[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?)\s*(?P<unit>.*?)\s*\Z")

_NOT_FINITE = re.compile(r"\s*[+-]?(?:nan|inf)", re.IGNORECASE)

_MICRO_SIGNS = str.maketrans({"\u03bc": "\u00b5"})
"""Greek small mu (U+03BC) is read as the micro sign (U+00B5) used in ``UNITS``."""


def allowed_units(dimension: str) -> list[str]:
    """The unit symbols accepted for ``dimension`` (a key of ``UNITS``)."""
    try:
        return list(UNITS[dimension])
    except KeyError:
        raise ValueError(f"unknown dimension {dimension!r}; use one of "
                         f"{', '.join(UNITS)}") from None


def parse_quantity(text: str | float, dimension: str, field: str) -> float:
    """Value of ``text`` (a number followed by a unit of ``dimension``) in SI units.

    ``field`` names the quantity in error messages (e.g. ``"layer[0].thickness"``).
    Spaces between number and unit are optional and runs of spaces inside a unit
    count as one (``"J/(kg K)"``).  For ``dimension="dimensionless"`` the text is a
    bare number, and an int or float is accepted as is.  NaN and infinities are
    rejected, and so is a nonzero value outside ``MAGNITUDES``.  Raises ``SceneError``.
    """
    units = allowed_units(dimension)
    hint = "a plain number" if dimension == "dimensionless" else f"use one of {', '.join(units)}"
    if isinstance(text, (int, float)) and not isinstance(text, bool):
        if dimension != "dimensionless":
            raise SceneError(f'{field}: missing units in "{_cut(text)}" ({hint})')
        number, unit = float(text), ""
    elif isinstance(text, str):
        match = _NUMBER_AND_UNIT.match(text)
        if match is None:
            if _NOT_FINITE.match(text):
                raise SceneError(f'{field}: "{_cut(text)}" is not a finite number')
            what = "a number" if dimension == "dimensionless" else "a number and a unit"
            raise SceneError(f'{field}: expected {what}, got "{_cut(text)}" ({hint})')
        number = float(match["number"])
        unit = " ".join(match["unit"].split()).translate(_MICRO_SIGNS)
    else:
        example = "a number" if dimension == "dimensionless" else f'a string such as "1 {units[0]}"'
        raise SceneError(f"{field}: expected {example}, got {text!r}")
    if not math.isfinite(number):
        raise SceneError(f'{field}: "{_cut(text)}" is not a finite number')
    if unit not in UNITS[dimension]:
        if unit == "":
            raise SceneError(f'{field}: missing units in "{_cut(text)}" ({hint})')
        raise SceneError(f'{field}: unknown unit "{_cut(unit)}" in "{_cut(text)}" ({hint})')
    factor = UNITS[dimension][unit]
    value = number * factor.numerator / factor.denominator
    low, high = MAGNITUDES.get(dimension, (0.0, math.inf))
    if value != 0.0 and not low <= abs(value) <= high:
        si_unit = units[0]
        raise SceneError(f'{field}: "{_cut(text)}" is outside the accepted magnitudes '
                         f"(0, or {low:g} to {high:g} {si_unit} either sign)")
    return value


def _cut(text: str | float) -> str:
    """``text`` as quoted in an error message: at most 60 characters."""
    text = str(text)
    return text if len(text) <= 60 else f"{text[:57]}..."


def to_si(value: str | float, dimension: str, field: str) -> float:
    """``value`` in SI: a number is taken as SI already, a string is parsed with its unit.

    The rule of the Python API (``Layer(cu, "1 mm")`` and ``Layer(cu, 1e-3)`` are the
    same layer); files use ``parse_quantity``, which insists on units.  NaN and
    infinities are rejected.  Raises ``SceneError`` naming ``field``.
    """
    if isinstance(value, str):
        return parse_quantity(value, dimension, field)
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise SceneError(f"{field}: expected a number (SI) or a string with a unit such as "
                         f'"1 {allowed_units(dimension)[0]}", got {value!r}')
    if not math.isfinite(value):
        raise SceneError(f"{field}: must be a finite number, got {value!r}")
    return float(value)
