"""Cumulative-damage spall (Tuler–Butcher, incubation time) against closed forms.

Scene: an elastic flyer (1 mm, 200 m/s) on an elastic target (3 mm, unbonded),
Z = rho0 C = 1.35e7 kg/(m^2 s).  The releases from the two free surfaces meet at
X = 3 mm at 0.8 us; behind them the tension is exactly Z V / 2 = 1.35 GPa.  A
station at X < 3 mm enters tension when the target's rear release reaches it,
at t = 0.6 us + (4 mm - X)/C, and stays there until relief arrives: a failure
time is that entry time plus the incubation time, or plus K / (T - sigma_0)^lambda.
"""

from __future__ import annotations

import dataclasses

import pytest

from fronttrack.damage import failure_time, first_failure, stations
from fronttrack.runner import run
from fronttrack.scene import Accuracy, Layer, Probe, Scene, SceneError, SpallCriterion
from fronttrack.scene_file import scene_from_dict
from materials import LinearElastic

BAR = LinearElastic("bar", rho0=2700.0, C=5000.0)
TENSION = 2700.0 * 5000.0 * 100.0
STATION = 1e-3 + 266.5 * 3e-3 / 400  # the target's station nearest X = 3 mm (2.99875 mm)


def entry_time(x: float) -> float:
    """When the station ``x`` (m, < 3 mm) enters the tension zone (s)."""
    return 0.6e-6 + (4e-3 - x) / BAR.C


def scene(criterion, spacing=0.5e-3, t_end=1.5e-6) -> Scene:
    return Scene(layers=(Layer(BAR, 1e-3, 200.0), Layer(BAR, 3e-3, bond="unbonded")),
                 t_end=t_end, probes=(Probe("rear", "right"),), spall_criterion=criterion,
                 accuracy=Accuracy(spall_spacing=spacing))


def test_incubation_time_fracture_is_exact():
    solution = run(scene(SpallCriterion.incubation(0.5e9, 0.1e-6)))
    first = solution.spalls[0]
    assert first.x == pytest.approx(STATION, rel=1e-15)
    assert first.t == pytest.approx(entry_time(STATION) + 0.1e-6, rel=1e-12)
    assert first.tension == pytest.approx(TENSION, rel=1e-12)
    report = solution.accuracy_report["spall_criterion"]
    assert report["kind"] == "incubation time" and report["runs"] == len(solution.spalls) + 1


def test_tuler_butcher_fracture_is_exact():
    damage = 0.025e18 * 1e-6  # 0.025 GPa^2 us
    solution = run(scene(SpallCriterion(threshold=0.5e9, damage=damage, exponent=2.0)))
    first = solution.spalls[0]
    assert first.x == pytest.approx(STATION, rel=1e-15)
    expected = entry_time(STATION) + damage / (TENSION - 0.5e9) ** 2
    assert first.t == pytest.approx(expected, rel=1e-12)


def test_fracture_conserves_momentum_and_energy_exactly():
    solution = run(scene(SpallCriterion.incubation(0.5e9, 0.1e-6)))
    balance = solution.conservation()
    assert abs(balance["momentum_relative_error"]) < 1e-12
    assert abs(balance["energy_relative_error"]) < 1e-12
    # the new free surfaces carry no stress
    after = solution.spalls[0].t + 1e-9
    x = solution.spalls[0].x
    assert solution.state_at(x - 1e-9, after).sigma == pytest.approx(0.0, abs=1e-3)


def test_no_fracture_when_the_pulse_is_too_short_or_too_weak():
    # the tension lasts 0.4 us at the spall plane: 0.5 us of incubation is never reached
    assert run(scene(SpallCriterion.incubation(0.5e9, 0.5e-6))).spalls == []
    # a threshold above the tension never accumulates damage
    assert run(scene(SpallCriterion.incubation(1.4e9, 1e-9))).spalls == []


def test_damage_is_integrated_exactly_on_step_histories():
    criterion = SpallCriterion(threshold=1.0, damage=10.0, exponent=1.0)
    history = type("H", (), {})()
    history.t = [0.0, 1.0, 3.0]
    history.states = [dataclasses.replace(BAR.reference_state(), sigma=s)
                      for s in (0.0, -3.0, -6.0)]
    # rate 2 on [1, 3] (damage 4), then rate 5: 10 is reached 1.2 s later
    assert failure_time(history, 10.0, criterion) == pytest.approx(4.2, rel=1e-15)
    assert failure_time(history, 4.0, criterion) is None


def test_fractures_keep_the_spall_spacing():
    """Stations closer than ``accuracy.spall_spacing`` to a fracture do not fail; the
    next plane is the first station beyond the spacing that reaches the incubation time
    before the relief from the first plane arrives."""
    solution = run(scene(SpallCriterion.incubation(0.5e9, 0.1e-6), spacing=0.5e-3))
    planes = sorted(s.x for s in solution.spalls)
    assert len(planes) == 2
    assert planes[1] - planes[0] > 0.5e-3
    assert first_failure(solution, 0.5e-3, [(s.x, s.t) for s in solution.spalls]) is None


def test_stations_are_cell_centres_of_every_layer():
    points = stations(scene(SpallCriterion.incubation(0.5e9, 0.1e-6, stations=4)))
    assert points == pytest.approx([0.125e-3, 0.375e-3, 0.625e-3, 0.875e-3,
                                    1.375e-3, 2.125e-3, 2.875e-3, 3.625e-3])


BASE = {"t_end": "1.5 us",
        "materials": {"bar": {"model": "linear-elastic", "rho0": "2700 kg/m3",
                              "C": "5000 m/s"}},
        "layer": [{"material": "bar", "thickness": "1 mm", "velocity": "200 m/s"},
                  {"material": "bar", "thickness": "3 mm", "bond": "unbonded"}]}


def test_scene_file_reads_both_criteria():
    tb = scene_from_dict({**BASE, "spall": {"criterion": "tuler-butcher", "threshold": "0.5 GPa",
                                            "exponent": 2, "damage": "0.025 GPa^2 us"}})
    assert tb.spall_criterion == SpallCriterion(threshold=0.5e9, damage=0.025e18 * 1e-6,
                                                exponent=2.0)
    inc = scene_from_dict({**BASE, "spall": {"criterion": "incubation", "threshold": "1 GPa",
                                             "incubation_time": "50 ns", "stations": 100}})
    assert inc.spall_criterion == SpallCriterion.incubation(1e9, 50e-9, 100)


@pytest.mark.parametrize("spall, field", [
    ({"criterion": "grady", "threshold": "1 GPa"}, "spall.criterion"),
    ({"criterion": "incubation", "threshold": "1 GPa"}, "spall.incubation_time"),
    ({"criterion": "tuler-butcher", "threshold": "1 GPa", "exponent": 2,
      "damage": "0.1 GPa^3 us"}, "spall.damage"),
    ({"criterion": "tuler-butcher", "threshold": "1 GPa", "exponent": 2,
      "damage": "0.1"}, "spall.damage"),
    ({"criterion": "incubation", "threshold": "-1 GPa", "incubation_time": "1 us"},
     "spall.threshold"),
    ({"criterion": "incubation", "threshold": "1 GPa", "incubation_time": "1 us",
      "stations": 1}, "spall.stations"),
    ({"criterion": "tuler-butcher", "threshold": "1 GPa", "exponent": 20,
      "damage": "0.1 GPa^20 us"}, "spall.exponent"),
])
def test_bad_spall_tables_name_the_field(spall, field):
    with pytest.raises(SceneError, match=field.replace(".", r"\.")):
        scene_from_dict({**BASE, "spall": spall})
