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
