"""Neglected entropy contacts may lose energy, never make it (``fronttrack.neglect``)."""

import itertools
import math

import pytest

from fronttrack.runner import run
from fronttrack.scene import Accuracy, Boundary, Layer, Scene
from materials import FinitePlastic, State, get


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
    from fronttrack.fronts import Front
    from fronttrack.kinds import FrontKind
    engine = Engine(_overtaking_scene())
    mo = get("Mo")
    left = State(sigma=1e9, u=50.0, v=mo.v0 * 0.99, e=1200.0)
    right = State(sigma=1e9, u=50.0, v=mo.v0 * 0.99, e=1000.0)
    # two waves meet at X = 1 mm of the Mo, between the interface (50 um) and the free
    # face (3.05 mm), with a ray of a fan between them and the face: no wave leaving the
    # event sweeps farther than the farther site, 2.05 mm away, before its next event
    chain = [Front(1, FrontKind.INTERFACE, 50e-6, 0.0),
             Front(2, FrontKind.SHOCK, 1e-3, 0.0), Front(3, FrontKind.RAY, 1e-3, 0.0),
             Front(4, FrontKind.RAY, 2e-3, 0.0), Front(5, FrontKind.BOUNDARY, 3.05e-3, 0.0)]
    for a, b in itertools.pairwise(chain):
        a.next, b.prev = b, a
    group = chain[1:3]
    assert neglect.neglect_cost(engine, mo, group, 1e-3, left, right, 0.0) == pytest.approx(
        mo.rho0 * 200.0 * 2.05e-3, rel=1e-12)
    # late in the run a wave sweeps at most the signal speed times the time left
    t = engine.t_end - 1e-9
    assert neglect.neglect_cost(engine, mo, group, 1e-3, left, right, t) == pytest.approx(
        mo.rho0 * 200.0 * engine.signal_speed * 1e-9, rel=1e-6)


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


def _wall_and_stress_scene() -> Scene:
    # campaign seed 28: 3 mm of Zn at -300 m/s against a wall, a 10 um finite-plastic
    # layer at 500 m/s pushed by a 2.4 GPa stress, 16 rays, Hugoniot release
    m1 = FinitePlastic("M1", 4796.59, 5869.06, 1.10488, 1.22510, 23.0576e9, 0.555785e9)
    return Scene(layers=(Layer(get("Zn"), 3e-3, -300.0, bond="unbonded"),
                         Layer(m1, 10e-6, 500.0)),
                 left=Boundary("wall"), right=Boundary("stress", ((0.0, 2.40228e9),)),
                 t_end=1.28297e-6,
                 accuracy=Accuracy(rays_per_fan=16, release="hugoniot", max_events=5000))


def test_neglects_that_lose_energy_are_held_to_the_budget_too():
    # before: only contacts whose neglect could make energy were budgeted; the
    # lower-energy state taken behind the shocks of this scene lost 0.40 % of the
    # energy against a promise of 0.2 %.  Every neglect is now held to the budget (a
    # quarter of the promise each, bounded by the width its waves can sweep before
    # meeting a site), and the balance is within the promise, still a loss
    solution = run(_wall_and_stress_scene())
    report = solution.accuracy_report
    balance = report["balance"]
    assert -balance["promised"] <= balance["energy_error"] < 0.0
    assert balance["momentum_error"] <= balance["promised"]
    assert report["neglected_contact_cost"] > 0.0
    assert not any("energy lost" in line for line in report["warnings"])


def test_a_thermal_neglect_costs_what_its_carrier_lost_by_its_next_event():
    # a contact whose energy jump (264 kPa, as in the spalled fragment of the symmetric
    # Al 2024 impact) is above the negligible stress is held in the sum at its bound,
    # 58 J/m^2 (the fragment's width), until the wave on its hotter side (5 400 m/s)
    # meets its next event 3 ns later: it then costs what that wave lost sweeping the
    # colder state, 264e3 x 5 400 x 3e-9 = 4.3 J/m^2
    from types import SimpleNamespace

    from fronttrack import neglect
    from fronttrack.counters import Counters
    engine = SimpleNamespace(counters=Counters(),
                             neglect_budget=neglect.NeglectBudget(limit=348.0,
                                                                  refresh=math.inf))
    carrier = SimpleNamespace(id=11, speed=-5400.0)
    assert neglect.affordable(engine, 58.0, 5e-6, history=True)
    neglect.hold(engine, carrier, 264e3, 5e-6, 58.0)
    assert engine.counters.history_cost == 58.0
    neglect.settle(engine, SimpleNamespace(id=12), 5.003e-6)  # another front: nothing
    assert engine.counters.history_cost == 58.0
    neglect.settle(engine, carrier, 5.003e-6)
    assert engine.counters.history_cost == pytest.approx(264e3 * 5400.0 * 3e-9, rel=1e-9)
    assert not engine.neglect_budget.held
    # without a carrier (its family dropped) the bound stays spent
    assert neglect.affordable(engine, 58.0, 5e-6, history=True)
    neglect.hold(engine, None, 264e3, 5e-6, 58.0)
    assert engine.counters.history_cost == pytest.approx(58.0 + 4.2768, rel=1e-9)


def test_a_contact_alone_may_cost_a_tenth_of_the_promise():
    """The symmetric Al 2024 impact (2 mm onto 4 mm at 500 m/s) at 16 rays per fan to
    2.25 us: a ray overtaking a shock at 1.42 us, 2.05 mm, leaves a contact whose bound
    is 187 J/m^2 (its carrier can cross the impactor), beyond a tenth of the promise
    (2e-3 of the 696 kJ/m^2 content: 139 J/m^2), within a quarter (348 J/m^2).
    Neglected, its carrier lost 171 J/m^2 (2.5e-4 of the content) and the run ended
    at -3.7e-4; kept (``neglect.ALONE``), at -2.6e-5.  1e-4 lies between the two, with
    the rest of the run's neglects and the rays' discretisation (2.6e-5) inside it."""
    scene = Scene(layers=(Layer("Al2024", "2 mm", velocity="500 m/s"),
                          Layer("Al2024", "4 mm", bond="unbonded")),
                  t_end=2.25e-6, accuracy=Accuracy(rays_per_fan=16))
    balance = run(scene).accuracy_report["balance"]
    assert balance["promised"] == pytest.approx(2e-3)
    assert abs(balance["energy_error"]) < 1e-4
