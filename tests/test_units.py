"""Quantity strings with units -> SI floats (``fronttrack.units``)."""

from __future__ import annotations

import math

import pytest

from fronttrack.scene import SceneError
from fronttrack.units import UNITS, allowed_units, parse_quantity

# (text, dimension, value in SI). Every unit of UNITS appears at least once (checked below).
CONVERSIONS = [
    ("2 m", "length", 2.0),
    ("3 mm", "length", 3e-3),
    ("250 um", "length", 250e-6),
    ("250 µm", "length", 250e-6),
    ("250 μm", "length", 250e-6),  # Greek mu, read as the micro sign
    ("20 nm", "length", 20e-9),
    ("1.5 cm", "length", 1.5e-2),
    ("1 in", "length", 0.0254),
    ("2 s", "time", 2.0),
    ("4 ms", "time", 4e-3),
    ("3 us", "time", 3e-6),
    ("3 µs", "time", 3e-6),
    ("20 ns", "time", 20e-9),
    ("230 m/s", "velocity", 230.0),
    ("2.6 km/s", "velocity", 2600.0),
    ("1.2 mm/us", "velocity", 1200.0),
    ("1.2 mm/µs", "velocity", 1200.0),
    ("100 ft/s", "velocity", 30.48),
    ("101325 Pa", "stress", 101325.0),
    ("1 kPa", "stress", 1e3),
    ("200 MPa", "stress", 2e8),
    ("-2.5 GPa", "stress", -2.5e9),
    ("1.3 Mbar", "stress", 1.3e11),
    ("300 kbar", "stress", 3e10),
    ("1 bar", "stress", 1e5),
    ("1186 kg/m3", "density", 1186.0),
    ("1186 kg/m^3", "density", 1186.0),
    ("8.93 g/cm3", "density", 8930.0),
    ("8.93 g/cm^3", "density", 8930.0),
    ("8.93 g/cc", "density", 8930.0),
    ("4.9e6 J/kg", "specific_energy", 4.9e6),
    ("4900 kJ/kg", "specific_energy", 4.9e6),
    ("4.9 MJ/kg", "specific_energy", 4.9e6),
    ("385 J/kg/K", "specific_heat", 385.0),
    ("385 J/(kg K)", "specific_heat", 385.0),
    ("293.15 K", "temperature", 293.15),
    ("1.52", "dimensionless", 1.52),
]


@pytest.mark.parametrize(("text", "dimension", "expected"), CONVERSIONS)
def test_conversion(text, dimension, expected):
    assert parse_quantity(text, dimension, "f") == pytest.approx(expected, rel=1e-15)


def test_every_unit_is_tested():
    tested = {(d, text.split(" ", 1)[1].replace("μ", "µ") if " " in text else "")
              for text, d, _ in CONVERSIONS}
    assert tested == {(d, unit) for d, units in UNITS.items() for unit in units}


def test_decimal_fractions_are_correctly_rounded():
    # "3 mm" is 3/1000, not 3 * 1e-3 (which is 0.0030000000000000001).
    assert parse_quantity("3 mm", "length", "f") == 3e-3
    assert parse_quantity("0.3 us", "time", "f") == 0.3e-6
    assert parse_quantity("7 ns", "time", "f") == 7e-9


@pytest.mark.parametrize(("text", "expected"), [
    ("1e3 m/s", 1000.0), ("1E3m/s", 1000.0), ("+2.5e-1 km/s", 250.0), (".5 km/s", 500.0),
    ("  230   m/s ", 230.0), ("-40 m/s", -40.0), ("0 m/s", 0.0), ("7. m/s", 7.0),
])
def test_number_formats(text, expected):
    assert parse_quantity(text, "velocity", "v") == expected


def test_unit_spacing_is_normalised():
    assert parse_quantity("385 J/(kg   K)", "specific_heat", "cv") == 385.0


def test_dimensionless_accepts_numbers():
    assert parse_quantity(1.52, "dimensionless", "s") == 1.52
    assert parse_quantity(2, "dimensionless", "s") == 2.0
    assert parse_quantity(" -0.25 ", "dimensionless", "s") == -0.25


def test_missing_units_message():
    with pytest.raises(SceneError) as info:
        parse_quantity("5", "length", "layer[0].thickness")
    assert str(info.value) == ('layer[0].thickness: missing units in "5" '
                               '(use one of m, mm, um, µm, nm, cm, in)')


def test_bare_toml_number_is_missing_units():
    with pytest.raises(SceneError, match=r'velocity: missing units in "1000\.0"'):
        parse_quantity(1000.0, "velocity", "velocity")


@pytest.mark.parametrize(("text", "dimension", "fragment"), [
    ("5 m", "time", 'unknown unit "m" in "5 m" (use one of s, ms, us, µs, ns)'),
    ("5 MM", "length", 'unknown unit "MM"'),
    ("5 mpa", "stress", 'unknown unit "mpa"'),
    ("1.5 s", "dimensionless", 'unknown unit "s"'),
    ("fast", "velocity", 'expected a number and a unit, got "fast"'),
    ("", "velocity", "expected a number and a unit"),
    ("abc", "dimensionless", 'expected a number, got "abc"'),
    ("nan m/s", "velocity", "not a finite number"),
    ("-inf GPa", "stress", "not a finite number"),
    ("1e400 Pa", "stress", "not a finite number"),
    (math.nan, "dimensionless", "not a finite number"),
    (math.inf, "dimensionless", "not a finite number"),
    (True, "dimensionless", "expected a number, got True"),
    (["5", "mm"], "length", 'expected a string such as "1 m"'),
    (None, "length", "expected a string"),
])
def test_errors_name_the_field_and_text(text, dimension, fragment):
    with pytest.raises(SceneError) as info:
        parse_quantity(text, dimension, "the.field")
    message = str(info.value)
    assert message.startswith("the.field: ")
    assert fragment in message


def test_scene_error_is_a_value_error():
    with pytest.raises(ValueError):
        parse_quantity("5", "length", "x")


def test_unknown_dimension_is_a_programming_error():
    with pytest.raises(ValueError, match="unknown dimension 'area'") as info:
        parse_quantity("1 m2", "area", "x")
    assert not isinstance(info.value, SceneError)
    assert allowed_units("stress")[:4] == ["Pa", "kPa", "MPa", "GPa"]
