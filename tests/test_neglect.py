"""Neglected entropy contacts may lose energy, never make it (``fronttrack.neglect``)."""

import pytest

from fronttrack.runner import run
from fronttrack.scene import Accuracy, Boundary, Layer, Scene
from materials import State, get


def _overtaking_scene() -> Scene:
    # random stack seed 1: a 50 um Nb flyer at 500 m/s on 3 mm of Mo, free ends; the
    # flyer's release fan overtakes the shock in the Mo, each ray leaving an entropy
    # jump of about 220 J/kg, far below the negligible stress
    return Scene(layers=(Layer(get("Nb"), 50e-6, 500.0),
                         Layer(get("Mo"), 3e-3, 0.0, bond="unbonded")),
                 left=Boundary("free"), right=Boundary("free"), t_end=3.05e-3 / 3000.0,
                 accuracy=Accuracy(rays_per_fan=4, max_events=3000))


def test_a_fan_overtaking_a_shock_makes_no_energy():
    # before: the fan cell behind each overtaking ray, hotter than the weakened
    # shock's Hugoniot state, went on behind the shock, which made 0.94 % of the energy
    # against a promise of 0.63 %; the contact is now kept once its cost bound exceeds
    # the budget, and the 4-ray fans lose energy (0.60 %), within the promise
    solution = run(_overtaking_scene())
    report = solution.accuracy_report
    balance = report["balance"]
    assert balance["energy_error"] < 0.0
    assert -balance["energy_error"] <= balance["promised"]
    assert balance["momentum_error"] <= balance["promised"]
    assert solution.stats["contacts"] >= 1
    assert report["warnings"] == []
    # the weaker jumps were neglected, and counted (the last few, 1e-5 J/m^2 each, are
    # now contact-node reflections inside lattices, dropped below the negligible stress:
    # characteristics.grid; their budgeted cost is tested on the Al impact below)
    assert report["neglected_entropy_contacts"] > 0


def test_contacts_within_the_budget_are_neglected_and_counted():
    # the symmetric Al 2024 impact (2 mm onto 4 mm at 500 m/s) at 16 rays to 1.2 us:
    # release rays overtaking the spall-plane shocks leave jumps of 14-23 J/kg, each
    # bounded by rho0 |de| x 4 mm = 23-42 J/m^2, within a quarter of the 2e-3 promise
    # of the 6.95e5 J/m^2 the flyer brings: none is tracked, each cost is counted
    import fronttrack as ft
    from fronttrack import neglect
    scene = ft.Scene(layers=(ft.Layer("Al2024", "2 mm", velocity="500 m/s"),
                             ft.Layer("Al2024", "4 mm", bond="unbonded")),
                     t_end=1.2e-6, accuracy=ft.Accuracy(rays_per_fan=16))
    solution = ft.run(scene)
    report = solution.accuracy_report
    al = get("Al2024")
    content = 0.5 * al.rho0 * 500.0**2 * 2e-3
    limit = neglect.BUDGET * report["balance"]["promised"] * content
    assert solution.stats["contacts"] == 0
    assert 0.0 < report["neglected_contact_cost"] < 3 * limit
    assert report["balance"]["energy_error"] < 0.0


def test_the_cost_of_a_neglected_contact_is_its_energy_jump_over_the_width_swept():
    from fronttrack import neglect
    from fronttrack.engine import Engine
    engine = Engine(_overtaking_scene())
    mo = get("Mo")
    left = State(sigma=1e9, u=50.0, v=mo.v0 * 0.99, e=1200.0)
    right = State(sigma=1e9, u=50.0, v=mo.v0 * 0.99, e=1000.0)
    # late in the run a wave sweeps at most the signal speed times the time left ...
    t = engine.t_end - 1e-9
    assert neglect.neglect_cost(engine, mo, 1, left, right, t) == pytest.approx(
        mo.rho0 * 200.0 * engine.signal_speed * 1e-9, rel=1e-6)
    # ... early on, at most its layer (3 mm of Mo)
    assert neglect.neglect_cost(engine, mo, 1, left, right, 0.0) == pytest.approx(
        mo.rho0 * 200.0 * 3e-3, rel=1e-12)


@pytest.mark.parametrize(("left_continues", "right_continues", "hotter", "creates"), [
    (False, False, "left", False),  # waves on both sides: the cooler state fills between
    (True, False, "left", True),    # the hotter left region goes on behind the waves
    (True, False, "right", False),  # the cooler one does: the waves can only lose
    (False, True, "right", True),
    (False, True, "left", False),
    (True, True, "left", True),     # merged: the mean is hotter than one side
])
def test_only_a_hotter_region_that_continues_can_make_energy(left_continues,
                                                            right_continues, hotter,
                                                            creates):
    from fronttrack import neglect
    hot = State(sigma=1e9, u=0.0, v=1e-4, e=2000.0)
    cold = State(sigma=1e9, u=0.0, v=1e-4, e=1000.0)
    left, right = (hot, cold) if hotter == "left" else (cold, hot)
    assert neglect.creates(left, right, left_continues, right_continues) is creates


def test_regions_merged_behind_shocks_make_no_energy():
    # campaign seed 355 (PMMA, Fe alpha-epsilon and Mo, Hugoniot release, 16 rays):
    # where both families of an interaction were dropped the two regions were merged,
    # the mean hotter than one of them, and the shocks beside it made 3.1 % of the
    # energy; such contacts are now kept when their cost exceeds the budget, and the
    # neglects left lose energy (1.8 %, beyond the 0.2 % promise: said in one line)
    from random_scenes import campaign_scene
    solution = run(campaign_scene(355))
    report = solution.accuracy_report
    balance = report["balance"]
    assert balance["energy_error"] < 0.0
    assert balance["momentum_error"] <= balance["promised"]
    assert any(line.startswith("energy lost") for line in report["warnings"])
