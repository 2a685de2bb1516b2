"""A free fragment ringing in closed form (fronttrack.fragment) against the tracked run.

The scenes are Al 2024 plates free on both faces, ringing with weak waves after a
velocity step inside (an impact at t = 0).  The records tolerance is loosened
(1 MPa, resolution length 50 um) so that waves of 75 MPa are linear within it; the
tracked run is the same scene with the replacement switched off.  Tolerances follow
from the linearisation error each replacement states (``drift``: how far the closed
form's pattern can lie from the material's, m): a record at a station sees each jump
``du`` displaced by at most ``drift / C`` in time, an L1-in-time error of
``du drift / C`` per passage.
"""

import numpy as np
import pytest

import fronttrack as ft
from fronttrack import fragment

LOOSE = {"stress_tolerance": "1 MPa", "coalesce_length": "50 um"}


def _plate(velocity="20 m/s", t_end="4 us", **accuracy):
    return ft.Scene(layers=(ft.Layer("Al2024", "1 mm", velocity=velocity),
                            ft.Layer("Al2024", "1.5 mm")), t_end=t_end,
                    accuracy=ft.Accuracy(**accuracy))


def _three(t_end="3 us"):
    """A 1 mm flyer at 40 m/s on a free 1.5 mm plate, beyond a gap a 1 mm plate at
    25 m/s: the middle plate separates, rings free, and catches the last one."""
    return ft.Scene(layers=(ft.Layer("Al2024", "1 mm", velocity="40 m/s"),
                            ft.Layer("Al2024", "1.5 mm", bond="unbonded"),
                            ft.Layer("Al2024", "1 mm", velocity="25 m/s", bond="unbonded")),
                    t_end=t_end, accuracy=ft.Accuracy(**LOOSE))


def _tracked(monkeypatch, scene):
    with monkeypatch.context() as m:
        m.setattr(fragment, "try_replace", lambda *args: False)
        return ft.run(scene)


def _total_variation(history, quantity="u"):
    _, values = history.samples(quantity)
    return float(np.abs(np.diff(values)).sum())


def test_free_face_velocity_matches_the_tracked_run(monkeypatch):
    ringing = ft.run(_plate(**LOOSE))
    tracked = _tracked(monkeypatch, _plate(**LOOSE))
    (entry,) = ringing.accuracy_report["fragments_ringing"]
    assert entry["x_lo"] == 0.0 and entry["x_hi"] == pytest.approx(2.5e-3)
    assert entry["t_end"] is None  # rings to the end of the run
    # over four periods, the faces' records and one inside
    assert ringing.scene.t_end > 4.0 * entry["period"]
    assert ringing.stats["events"] < tracked.stats["events"]
    shift = entry["drift"] / entry["sound_speed"]
    for where in ("left", "right", 1.7e-3):
        a, b = ringing.history(where), tracked.history(where)
        bound = _total_variation(a) * shift
        assert a.l1_distance(b, "u") <= bound, where
    # the free faces stay free
    assert np.all(ringing.history("right").sigma == 0.0)


def test_momentum_and_energy_kept_exactly():
    solution = ft.run(_plate(**LOOSE))
    (entry,) = solution.accuracy_report["fragments_ringing"]
    start = solution.conservation(entry["t"] * (1.0 + 1e-9))
    end = solution.conservation(solution.scene.t_end)
    assert end["momentum"][1] == pytest.approx(start["momentum"][1], rel=1e-12)
    assert end["energy"][1] == pytest.approx(start["energy"][1], rel=1e-12)
    # the ringing energy is carried as the fragment's internal energy, not lost
    assert entry["ringing_energy"] > 0.0
    assert solution.accuracy_report["balance"]["energy_error"] == pytest.approx(
        0.0, abs=1e-4)


def test_gap_closure_time_matches_the_tracked_run(monkeypatch):
    ringing = ft.run(_three())
    tracked = _tracked(monkeypatch, _three())
    closes = [e for e in ringing.events if str(e.kind) == "gap-close"]
    closes_tracked = [e for e in tracked.events if str(e.kind) == "gap-close"]
    (ended,) = [r for r in ringing.accuracy_report["fragments_ringing"]
                if r["t_end"] is not None]
    assert len(closes) == len(closes_tracked) == 1
    assert closes[0].t == ended["t_end"]
    # a face whose velocity swings by du at most, shifted by drift / C in time, is at
    # most du drift / C out of place; the gap closes at the closing speed v
    ring = next(r for r in ringing.rings if r.t_end == ended["t_end"])
    swing = 2.0 * float(np.ptp(ring.slab.values)) / ring.slab.z
    before = closes[0].t * (1.0 - 1e-9)
    closing = (tracked.state_at(ring.slab.x_hi * (1.0 - 1e-6), before).u
               - tracked.state_at(ring.slab.x_hi * (1.0 + 1e-6), before).u)
    assert closing > 0.0
    bound = swing * ended["drift"] / ended["sound_speed"] / closing
    assert closes[0].t == pytest.approx(closes_tracked[0].t, abs=bound)
    # handed back with the energy it held: the balance does not move at the hand-back
    assert ended["handed_back_waves"] > 0
    at = ringing.conservation(ended["t_end"] * (1.0 - 1e-9))
    after = ringing.conservation(ended["t_end"] * (1.0 + 1e-9))
    assert after["energy"][1] == pytest.approx(at["energy"][1], rel=1e-9)
    assert after["momentum"][1] == pytest.approx(at["momentum"][1], rel=1e-9)


@pytest.mark.parametrize(("velocity", "accuracy"), [("50 m/s", LOOSE), ("20 m/s", {})])
def test_refused_when_waves_too_strong_for_the_tolerance(velocity, accuracy):
    # 50 m/s: its waves' speeds differ by more than the 50 um resolution length allows
    # over a period; 20 m/s at the default resolution length (2.5 um) likewise
    solution = ft.run(_plate(velocity, "2 us", **accuracy))
    assert solution.accuracy_report["fragments_ringing"] == []


def _thin_ring_gap(closing: float, width: float):
    """A 10 um fragment ringing (16 jumps of P, period 4 ns) left of a gap of ``width``
    (m), a region right of it moving ``closing`` (m/s) slower than the fragment's mean
    velocity, run to 1 ms: 250 000 periods, four million face changes."""
    from types import SimpleNamespace

    from characteristics.free_slab import FreeSlab

    rng = np.random.default_rng(7)
    edges = np.linspace(0.0, 10e-6, 9)
    slab = FreeSlab.from_cells(edges, rng.normal(0.0, 5e7, 8), 10.0 + rng.normal(0.0, 2.0, 8),
                               0.0, 5000.0, 4e7)
    engine = SimpleNamespace(t_end=1e-3, free_rings=SimpleNamespace(by_region={}))
    far = SimpleNamespace(id=2, state=SimpleNamespace(u=slab.u0 - closing))
    gap = SimpleNamespace(prev=SimpleNamespace(region_right=SimpleNamespace(id=1)),
                          region_right=far, gap_time=1e-7, gap_width=width)
    return engine, gap, slab


def test_gap_closure_over_many_periods_is_found_window_by_window(monkeypatch):
    """A thin fragment closing its gap after 120 000 of its periods: the closing is found
    exactly (the width, in closed form, is zero there and positive a moment before),
    without listing the faces' changes over the whole run at once (which took 3.3 GB in
    a random stack), and a gap the mean motions keep open is open for ever."""
    from characteristics.free_slab import FreeSlab

    listed = []
    changes = FreeSlab.face_changes

    def counted(self, side, t_from, t_to):
        out = changes(self, side, t_from, t_to)
        listed.append(out.size)
        return out

    monkeypatch.setattr(FreeSlab, "face_changes", counted)
    engine, gap, slab = _thin_ring_gap(closing=0.1, width=50e-6)
    t = fragment.closure_time(engine, gap, ("left", slab))
    assert max(listed) <= 2 * fragment.MAX_FACE_CHANGES
    u_far = gap.region_right.state.u

    def width(at):
        return (gap.gap_width + u_far * (at - gap.gap_time)
                - slab.face_displacement("right", gap.gap_time, at))

    # closes within (w -+ wander) / closing, after ~120 000 periods
    lo = gap.gap_time + (50e-6 - 2 * slab.face_wander) / 0.1
    hi = gap.gap_time + (50e-6 + 2 * slab.face_wander) / 0.1
    assert lo <= t <= hi and t / slab.period > 1e5
    # zero to the rounding of displacements of 5 mm summed over the run
    assert abs(float(width(t))) < 1e-15
    before = np.linspace(t - 3 * slab.period, t, 3001)[:-1]
    assert np.all(width(before) > 0.0)
    engine, gap, slab = _thin_ring_gap(closing=-2.0, width=1e-6)
    assert fragment.closure_time(engine, gap, ("left", slab)) == np.inf
