"""Events that pile up: a cluster far below the resolution solved as one Riemann problem.

``fronttrack.cluster``: when events pile up within the cluster length (1 % of the
resolution length) the fronts there are gathered into one event whose strip change is
counted.  The scene is seed 8 of ``tests/random_scenes.py::strength_stack_scene``
(inline): 3 mm of a finite-plastic solid at 538.66 m/s onto 3 mm of another, free
ends.  At 0.916 us a train of shocks converges on the right free face; solved pair by
pair it spent thousands of events within picoseconds and nanometres of the face, and
with a tenfold smaller negligible stress it did not reach 0.9163 us in 60 000 events.
"""

from __future__ import annotations

from types import SimpleNamespace

import pytest

import fronttrack as ft
from fronttrack import cluster, coalesce
from fronttrack.engine import Engine
from fronttrack.kinds import FrontKind
from materials import FinitePlastic, LinearElastic, State

HEAVY = FinitePlastic("A", 18321.0, 2840.7, 1.198, 2.199, 43.03e9, 1.3196e9)
LIGHT = FinitePlastic("B", 11316.0, 2858.3, 1.1873, 1.024, 49.34e9, 0.8746e9,
                      spall_strength=2.723e9)


def converging(negligible: str | None = None, max_events: int = 200_000) -> ft.Scene:
    accuracy = ft.Accuracy(max_events=max_events) if negligible is None else ft.Accuracy(
        max_events=max_events, negligible_stress=negligible)
    return ft.Scene(layers=(ft.Layer(HEAVY, "3 mm", velocity="538.66 m/s"),
                            ft.Layer(LIGHT, "3 mm", bond="bonded")),
                    t_end="0.92 us", accuracy=accuracy)


def test_a_shock_train_converging_on_a_free_face_is_one_reflection():
    solution = ft.run(converging(max_events=1_500))  # 853 events; pair by pair 6 927
    report = solution.accuracy_report
    assert report["gathered_fronts"] > 0
    balance = report["balance"]
    assert balance["momentum_error"] <= balance["promised"]
    assert abs(balance["energy_error"]) <= balance["promised"]
    # the face velocity converges as the negligible stress shrinks (633.42, 633.35 and
    # 633.37 m/s at 1, 1/10 and 1/100 of the default), within the velocity tolerance of
    # the records (0.2017 m/s); pair by pair, the dropped echoes of the train left it
    # at 623.1 m/s
    finer = ft.run(converging(negligible="0.1237 MPa", max_events=5_000))
    face, reference = (s.history("right").at([0.92e-6], "u")[0] for s in (solution, finer))
    assert face == pytest.approx(reference, abs=report["velocity_tolerance"])
    assert finer.accuracy_report["balance"]["momentum_error"] <= 1e-5


def test_events_pile_up_only_within_the_cluster_length_and_time():
    resolution = SimpleNamespace(coalesce_length=1e-3)
    watch = cluster.ClusterWatch(resolution, signal_speed=5000.0)
    assert watch.length == pytest.approx(1e-5)
    assert watch.duration == pytest.approx(4e-9)
    spread = [watch.piling(k * 1e-9, k * 1e-4) for k in range(3 * cluster.PILE)]
    assert not any(spread)
    near = [watch.piling(1e-6 + k * 1e-12, 5e-3 + k * 1e-8) for k in range(cluster.PILE + 1)]
    assert near == [False] * cluster.PILE + [True]


def _front(kind, x, state=None, rho0=1000.0):
    region = None if state is None else SimpleNamespace(
        state=state, material=SimpleNamespace(rho0=rho0))
    return SimpleNamespace(kind=kind, is_site=kind.is_site, x0=x, region_right=region,
                           position=lambda t, x=x: x)


def _chain(fronts):
    for a, b in zip(fronts, fronts[1:], strict=False):
        a.next, b.prev = b, a
    fronts[0].prev, fronts[-1].next = None, None
    return fronts


def _state(u, e):
    return State(v=1e-3, e=e, sigma=0.0, u=u)


def test_the_strip_keeps_its_energy_inside_one_material():
    # left state | strip of two cells | right state, rho0 1000 kg/m3, 1 um cells
    left, a, b, right = _state(100.0, 0.0), _state(60.0, 500.0), _state(20.0, 900.0), \
        _state(0.0, 1000.0)
    fronts = _chain([_front(FrontKind.SHOCK, 0.0, left), _front(FrontKind.SHOCK, 1e-6, a),
                     _front(FrontKind.CONTACT, 2e-6, b), _front(FrontKind.SHOCK, 3e-6, right)])
    point, momentum, energy = cluster._strip_change(fronts[1:], 0.0, None)

    def total(s):
        return s.e + 0.5 * s.u ** 2

    before = 1000.0 * 1e-6 * (total(a) + total(b))
    e_l, e_r = total(left), total(right)
    share = (before / 1000.0 - 2e-6 * e_r) / (2e-6 * (e_l - e_r))
    assert point == pytest.approx(1e-6 + share * 2e-6, rel=1e-12)
    assert energy == pytest.approx(0.0, abs=1e-12 * before)
    gained = 1000.0 * ((point - 1e-6) * 100.0 - 1e-6 * (60.0 + 20.0))
    assert momentum == pytest.approx(abs(gained), rel=1e-12)


def test_at_a_site_the_strip_meets_there_and_its_change_is_counted():
    left, a = _state(100.0, 0.0), _state(50.0, 200.0)
    boundary = _front(FrontKind.BOUNDARY, 2e-6)
    fronts = _chain([_front(FrontKind.SHOCK, 0.0, left), _front(FrontKind.RAY, 1e-6, a),
                     boundary])
    point, momentum, energy = cluster._strip_change(fronts[1:], 0.0, boundary.x0)
    assert point == 2e-6
    assert momentum == pytest.approx(1000.0 * 1e-6 * (100.0 - 50.0), rel=1e-12)
    assert energy == pytest.approx(1000.0 * 1e-6 * (5000.0 - (200.0 + 1250.0)), rel=1e-12)


def test_the_principal_site_is_the_interface_or_boundary():
    contact, other = (SimpleNamespace(kind=FrontKind.CONTACT) for _ in range(2))
    boundary = SimpleNamespace(kind=FrontKind.BOUNDARY)
    assert cluster.principal_site([contact, boundary, other]) is boundary
    assert cluster.principal_site([contact]) is contact
    assert cluster.principal_site([contact, other]) is None
    assert cluster.principal_site([]) is None


ELASTIC = LinearElastic("elastic", 2650.0, 5000.0)


def _contact_pair(mismatch: float):
    """An engine whose only layer holds two contacts 0.5 um apart at 0.5 mm, each with
    a stress mismatch ``mismatch`` (Pa, the same sign) and the velocity that goes with
    it on the right-going elastic branch (what a dropped echo leaves).  The strip between
    them moves a quarter of the coalescing budget when they are made one: the moving
    material is all beyond 0.5 mm, and a pair may spend half the budget at once."""
    scene = ft.Scene(layers=(ft.Layer(ELASTIC, "1 mm", velocity="10 m/s"),),
                     left=ft.Boundary("wall"), t_end="0.1 us",
                     accuracy=ft.Accuracy(negligible_stress="1 MPa"))
    engine = Engine(scene)
    engine._build()
    left_end, right_end = engine.head, engine.head.next
    states = [ELASTIC.initial_state(k * mismatch, -k * mismatch / (2650.0 * 5000.0))
              for k in range(3)]
    chain = [left_end]
    for k, x in enumerate((0.5e-3, 0.5005e-3)):
        front = engine.new_front(FrontKind.CONTACT, x, 0.0, bond="bonded")
        front.region_right = engine.new_region(states[k + 1], ELASTIC, 0, 0.0, (x, 0.0),
                                               (x, 0.0))
        chain.append(front)
    chain.append(right_end)
    left_end.region_right = engine.new_region(states[0], ELASTIC, 0, 0.0, (0.0, 0.0),
                                              (0.5e-3, 0.0))
    for a, b in zip(chain, chain[1:], strict=False):
        a.next, b.prev = b, a
    return engine, chain[1], chain[2]


@pytest.mark.parametrize(("mismatch", "merged"), [(0.4e6, True), (0.6e6, False)])
def test_a_comb_of_contacts_is_one_contact_while_its_mismatch_stays_negligible(
        mismatch, merged):
    # two mismatches of one sign add up: 0.8 MPa is below the 1 MPa negligible stress
    # (one contact then carries what one dropped echo could leave), 1.2 MPa is not
    engine, a, b = _contact_pair(mismatch)
    front = coalesce._coalesce(engine, a, b, 0.0)
    assert (front is not None) == merged
    assert engine.counters.coalesced == int(merged)
    if merged:
        assert front.kind == FrontKind.CONTACT and not a.alive and not b.alive
        assert front.prev.region_right.state.sigma == 0.0
        assert front.region_right.state.sigma == pytest.approx(2 * mismatch, rel=1e-9)
        # the strip's energy is kept (to rounding of its content)
        strip = ELASTIC.rho0 * 1e-6 * coalesce.specific_energy(a.region_right.state)
        assert abs(engine.counters.coalesced_energy) <= 1e-12 * strip
