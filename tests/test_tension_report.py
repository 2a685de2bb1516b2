"""The run summary names materials that carried tension with no spall strength to stop it.

A symmetric impact of linear elastic plates (every wave a shock, closed form): the
release waves from the two free surfaces meet in the target and pull it to minus the
impact stress, ``-rho0 C u/2``.
"""

from __future__ import annotations

import math

import pytest

from fronttrack.runner import run
from fronttrack.scene import Layer, Scene
from fronttrack.tension_report import TYPICAL_STRENGTH, unlimited_tension
from materials import LinearElastic

RHO, C, U = 2638.0, 6000.0, 200.0


def _impact(strength: float):
    window = LinearElastic("window", RHO, C, strength)
    flyer = LinearElastic("flyer", RHO, C, 10e9)
    return run(Scene(layers=(Layer(flyer, 1e-3, U), Layer(window, 2e-3, 0.0)),
                     t_end=0.8e-6))


def test_tension_without_spall_strength_is_reported():
    found = unlimited_tension(_impact(math.inf))
    assert [f.material for f in found] == ["window"]
    assert found[0].sigma == pytest.approx(-0.5 * RHO * C * U, rel=1e-9)
    assert 1e-3 < found[0].x < 3e-3
    assert "no spall strength" in found[0].message() and "window" in found[0].message()


def test_nothing_reported_with_a_strength_or_below_the_typical_one():
    assert unlimited_tension(_impact(5e9)) == []
    solution = _impact(math.inf)
    assert unlimited_tension(solution, threshold=0.6 * RHO * C * U) == []
    assert TYPICAL_STRENGTH < 0.5 * RHO * C * U
