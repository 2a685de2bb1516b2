"""A fan's characteristics spread apart (``characteristics.simple_waves.diverging``).

Campaign seed 826 (a 10 um gas layer in a stack of solids): a right-going release fan
in the gas took its interior states from the table of a colder isentrope, within the
table tolerance of its own (a fraction of the gas pressure, the tolerance being set by
the solids' stress scale).  Its head, on the fan's own isentrope, was slower than the
characteristic behind it; the two crossed where they left, the event there solved the
same Riemann problem again, and the clock stopped at 24.507 ns (20 000 events, all at
one point).  A fan whose table would make its characteristics cross takes the exact
states of its own wave curve instead.
"""

from __future__ import annotations

import dataclasses

import pytest
from random_scenes import campaign_scene

from characteristics.isentrope import isentrope_for
from characteristics.simple_waves import discretise_fan, diverging
from fronttrack.runner import run
from materials import RIGHT, IdealGas

GAS = IdealGas("gas", 5.0 / 3.0, 21.68)


def _release_fan():
    """A right-going release fan from 10.42 MPa at 0.01479 m3/kg to 9.88 MPa (the states
    of seed 826), and a state at the fan's head stress on a colder isentrope (10 % less
    volume, 10 % less internal energy: the same stress)."""
    ahead = GAS.state_from_pressure(1.0 / 0.01479, 10.42e6, 18.8)
    (fan,) = GAS.wave_curve(ahead, RIGHT).waves(9.88e6)
    colder = dataclasses.replace(ahead, v=0.9 * ahead.v, e=0.9 * ahead.e)
    assert GAS.stress(colder.v, colder.e) == pytest.approx(ahead.sigma, rel=1e-12)
    return fan, colder


def test_a_fan_on_its_own_isentrope_diverges():
    fan, _ = _release_fan()
    for table in (None, isentrope_for(GAS, fan.ahead)):
        rays = discretise_fan(fan, GAS, 0.1e6, table)
        assert len(rays) == 7 and diverging(rays)
        # head first: the head is the fastest, the tail the slowest
        assert rays[0].speed == max(r.speed for r in rays)


def test_a_table_of_a_colder_isentrope_makes_the_head_slower_than_the_ray_behind():
    fan, colder = _release_fan()
    rays = discretise_fan(fan, GAS, 0.1e6, isentrope_for(GAS, colder))
    assert not diverging(rays)
    # each speed is C_L = (v0/v) sqrt(gamma p v) of the state the ray carries: the head
    # its own (v = 0.01479), the next ray the colder isentrope's (0.9 v: C_L larger by
    # 0.9^-1/2 at equal stress, 4.7 % faster at its 0.9 % lower stress)
    for ray in rays[:2]:
        s = ray.state
        assert ray.speed == pytest.approx(GAS.v0 / s.v * (GAS.gamma * s.sigma * s.v) ** 0.5,
                                          rel=1e-9)
    assert rays[1].state.v == pytest.approx(0.9 * rays[0].state.v, rel=0.01)
    assert rays[1].speed > 1.04 * rays[0].speed


def test_seed_826_runs_past_the_point_where_its_clock_stopped():
    scene = dataclasses.replace(campaign_scene(826, max_events=1500), t_end=24.6e-9)
    solution = run(scene)
    assert solution.stats["events"] < 1500
    balance = solution.accuracy_report["balance"]
    assert abs(balance["energy_error"]) < balance["promised"]
    assert balance["momentum_error"] < balance["promised"]
