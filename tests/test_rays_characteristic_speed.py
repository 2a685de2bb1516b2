"""``characteristics.rays.discretise_fan``: where ray speeds come from.

A material whose stress is a function of ``(v, e)`` gives its characteristic speed
through ``material.sound_speed(v, e)``; a fan whose wave curve has
``characteristic_speed(sigma)`` (a solid with a history variable) takes it from the
curve inside the fan and from its own head and tail speeds at the ends.
"""

from __future__ import annotations

import dataclasses

import pytest

from characteristics.rays import discretise_fan
from materials import LEFT, RIGHT, FinitePlastic, MieGruneisen, State

MG = MieGruneisen("Cu", 8930.0, 3940.0, 1.49, 2.0)
AL = FinitePlastic("Al6061", 2703.0, 5350.0, 1.34, 2.0, 26.0e9, 0.29e9)


def test_fluid_fans_use_the_sound_speed_of_each_state():
    a = MG.wave_curve(MG.reference_state(), RIGHT).state_at(20e9)
    (fan,) = MG.wave_curve(a, LEFT).waves(0.0)
    assert not hasattr(fan.curve, "characteristic_speed")
    states = fan.states(6)
    c = [MG.sound_speed(s.v, s.e) for s in states]
    rays = discretise_fan(fan, MG, 6)
    assert [r.speed for r in rays] == [-0.5 * (c[k] + c[k + 1]) for k in range(6)]


class _Curve:
    """A wave curve that knows its characteristic speeds (a linear law in stress)."""

    def __init__(self, inner):
        self.inner = inner

    def state_at(self, sigma):
        return self.inner.state_at(sigma)

    def characteristic_speed(self, sigma):
        return 1000.0 + sigma * 1e-6


def test_fans_of_a_curve_with_characteristic_speed_use_it_inside_and_fan_speeds_at_ends():
    a = MG.wave_curve(MG.reference_state(), RIGHT).state_at(20e9)
    (fan,) = MG.wave_curve(a, LEFT).waves(0.0)
    fan = dataclasses.replace(fan, curve=_Curve(fan.curve), head_speed=-7000.0,
                              tail_speed=-3000.0)
    states = fan.states(4)
    c = [7000.0, *(1000.0 + s.sigma * 1e-6 for s in states[1:-1]), 3000.0]
    rays = discretise_fan(fan, MG, 4)
    assert [r.speed for r in rays] == [-0.5 * (c[k] + c[k + 1]) for k in range(4)]
    (one,) = discretise_fan(fan, MG, 1)
    assert one.speed == -5000.0 and one.ahead == fan.ahead and one.behind == fan.behind


def test_shared_knee_gets_the_speed_of_each_fan():
    """The yield point ends the elastic fan and starts the plastic one: one state, whose
    ray speeds are the elastic speed in the first fan and the plastic one in the second
    (a state-only ``sound_speed`` could give at most one of them)."""
    a = AL.wave_curve(AL.reference_state(), RIGHT).state_at(10e9)
    elastic, plastic = AL.wave_curve(a, LEFT).waves(0.0)
    knee = elastic.behind
    assert knee == plastic.ahead and type(knee) is State
    last = discretise_fan(elastic, AL, 3)[-1]
    first = discretise_fan(plastic, AL, 3)[0]
    inner_el = elastic.curve.characteristic_speed(elastic.states(3)[2].sigma)
    inner_pl = plastic.curve.characteristic_speed(plastic.states(3)[1].sigma)
    assert last.speed == pytest.approx(-0.5 * (inner_el - elastic.tail_speed), rel=1e-15)
    assert first.speed == pytest.approx(-0.5 * (-plastic.head_speed + inner_pl), rel=1e-15)
    assert -elastic.tail_speed > -plastic.head_speed
    assert AL.sound_speed(knee.v, knee.e) == pytest.approx(-elastic.tail_speed, rel=1e-12)
