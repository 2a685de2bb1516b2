"""Stress mismatches left by dropped waves at sites are solved again before they cost
more than their share of the promised balance (``fronttrack.mismatch``, issues 12-13).

The reproduction (from campaign seed 78): a slow foam strikes a thin plate at rest while
an impact elsewhere in the stack sets a stress scale whose negligible stress (71 MPa)
is above the wave the foam sends into the plate.  Before, that wave was dropped: the
foam pushed on a plate that never moved, and nothing came to the contact to solve it
again.  The run created energy beyond its promise (+0.21 % against 0.2 %); with the
deadlines it balances energy to 6e-5.
"""

import fronttrack as ft
from fronttrack import dropped, mismatch
from materials import IdealGas, LinearElastic
from materials.finite_plastic import FinitePlastic


def _foam_on_a_thin_plate() -> ft.Scene:
    hard = LinearElastic("hard", 19000.0, 5000.0)
    thin = LinearElastic("thin", 2700.0, 6000.0)
    return ft.Scene(layers=(ft.Layer(hard, "1 mm", velocity="1500 m/s"),
                            ft.Layer(hard, "1 mm", bond="unbonded"),
                            ft.Layer("PS_foam", "3 mm", velocity="800 m/s", bond="unbonded"),
                            ft.Layer(thin, "200 um", bond="unbonded")), t_end="1 us")


def test_a_mismatch_no_wave_clears_is_solved_again_within_its_budget(monkeypatch):
    # the deadlines alone (the dropped-wave budget, fronttrack.dropped, would keep the
    # foam's wave too: see the next test)
    monkeypatch.setattr(dropped, "_must_keep", lambda *args: False)
    solution = ft.run(_foam_on_a_thin_plate())
    report = solution.accuracy_report
    balance = report["balance"]
    promised = balance["promised"]
    assert report["mismatches_resolved"] >= 1
    # the impulse all mismatches made stays within their budget (each of the pending
    # ones draws on what is left: at most 1 + pending / SHARES of it)
    assert 0.0 < report["mismatch_impulse"] <= 1.5 * mismatch.BUDGET * promised
    assert balance["momentum_error"] <= promised
    assert abs(balance["energy_error"]) <= 0.1 * promised
    # the deadlines are what keeps the balance: without them the dropped waves'
    # mismatches act for the whole run, and energy is created beyond the promise
    monkeypatch.setattr(mismatch, "_note", lambda *args: None)
    drifting = ft.run(_foam_on_a_thin_plate()).accuracy_report["balance"]
    assert drifting["energy_error"] > 10.0 * abs(balance["energy_error"])
    assert drifting["energy_error"] > promised


def test_without_deadlines_the_dropped_wave_budget_keeps_the_foams_wave(monkeypatch):
    # the mismatch the dropped wave leaves at the contact would create energy for the
    # rest of the run: fronttrack.dropped keeps the wave once the energy it could make
    # exceeds its budget, and the energy balances within a tenth of the promise (it
    # created 0.21 % against 0.2 % with neither rule).  The rule bounds energy, not
    # momentum: the mismatches it allows still push (0.25 % of the momentum content
    # here), which is what the deadlines bound.
    monkeypatch.setattr(mismatch, "_note", lambda *args: None)
    balance = ft.run(_foam_on_a_thin_plate()).accuracy_report["balance"]
    assert abs(balance["energy_error"]) <= 0.1 * balance["promised"]


def test_an_unbonded_piston_pulling_away_sets_no_stress_scale():
    """A velocity boundary that pulls away from its face separates at once (the face is
    free): its would-be tension must not set the scale the negligible stress is taken
    from (campaign seed 78 dropped 27 MPa waves because of a 44.6 GPa tension that
    never happened)."""
    def scale(right: ft.Boundary) -> float:
        scene = ft.Scene(layers=(ft.Layer("Cu", "1 mm", velocity="100 m/s"),
                                 ft.Layer("Al2024", "1 mm", velocity="100 m/s")),
                         left=ft.Boundary("velocity", "150 m/s"), right=right, t_end="0.2 us")
        return ft.run(scene).accuracy_report["stress_scale"]

    # the piston pulls away at 500 m/s from a face moving at 100 m/s: a free face
    assert scale(ft.Boundary("velocity", "500 m/s")) == scale(ft.Boundary("free"))
    # a bonded piston does pull (in tension), and that sets the scale
    assert scale(ft.Boundary("velocity", "500 m/s", bond="bonded")) > 2.0 * scale(
        ft.Boundary("free"))


def _gas_plate_and_a_lif_fragment_on_a_wall() -> ft.Scene:
    """Campaign seed 433, rounded: a gas (10 mm at 2.6 MPa) releasing to vacuum, a
    finite-plastic plate (3 mm at -300 m/s) and a LiF plate (3 mm at 100 m/s, in tension)
    unbonded from it and from a wall.  The LiF rings as a free fragment solved by lattices
    (its gap face to the plate is a lattice end) while weak waves crossing in the plate
    are dropped and put their mismatch on that gap face."""
    gas = IdealGas("M0", 5.0 / 3.0, 47.177)
    plate = FinitePlastic("M1", 13336.0, 5848.8, 1.034, 1.113, 126.0e9, 0.822e9)
    return ft.Scene(layers=(ft.Layer(gas, "10 mm", stress=2.633e6),
                            ft.Layer(plate, "3 mm", velocity="-300 m/s"),
                            ft.Layer("LiF", "3 mm", velocity="100 m/s", stress=-107.7e6,
                                     bond="unbonded")),
                    t_end="31 us", left=ft.Boundary("free"),
                    right=ft.Boundary("wall", bond="unbonded"))


def test_a_mismatch_beside_a_lattice_solved_ahead_waits_for_its_cut(monkeypatch):
    # before, the gap was solved again at its deadline, 31 ns before the lattice's cut,
    # from the cells the lattice had left there: the waves sent into the LiF ran into
    # what the lattice had already solved, out of order, 26 segments past the wall
    # (up to 0.56 mm beyond the stack), and the momentum balance was off by 0.49 %
    deferred = []
    original = mismatch.deferred

    def counting(engine, entry):
        deferred.append(original(engine, entry))
        return deferred[-1]

    monkeypatch.setattr(mismatch, "deferred", counting)
    solution = ft.run(_gas_plate_and_a_lif_fragment_on_a_wall())
    assert any(deferred) and solution.stats["lattices"] > 0
    length = solution.scene.length
    rounding = 1e-9 * length
    for front in solution.front_records():
        for x in (front.x0, front.x1):
            assert -rounding <= x <= length + rounding, (front.kind, front.id, x)
    balance = solution.accuracy_report["balance"]
    assert balance["momentum_error"] <= balance["promised"]
    # the lattices' rays in the gas lose energy (third order per ray); none is created
    assert balance["energy_error"] <= 0.0
