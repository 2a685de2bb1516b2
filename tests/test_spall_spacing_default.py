"""No spall plane closer to another of its layer than the records resolve.

An Al 2024 plate 1 mm thick at 300 m/s welded to a 2 mm one (one 3 mm plate, bonded),
run to 1 us: after a zone at 1.966-2.124 mm and a plane at 2.942 mm, the threshold
fractures a zone 2.1269-2.1274 mm wide at 0.9388 us.  Before the default spall
spacing it made a plane at each end, 0.5 um apart, and the 0.5 um fragment between
rang one transit at a time: 2 558 events to 1 us (25 218 and 70 s of CPU to 2 us)
where the run now takes 277 (706 to 2 us).

A Cu flyer (2 mm, 1 km/s) on an unbonded Al 2024 plate (6 mm), the demo's plate
impact, run to 1.6 us: the release fans meet in the plate and the threshold fractures
zones near 5.39 mm and 5.30 mm.  Before the default spall spacing the lattices made
planes 4.9 um (5.3841 / 5.3890 mm) and 1.6 um (5.3023 / 5.3007 mm) apart, slabs below
the records' resolution length (8 um here: the stress tolerance's fraction of the
8 mm stack).  By default no plane is made closer than that to another of its layer
(``fronttrack.spall.spacing``); the tension there is carried and counted as a
suppressed spall.
"""

from __future__ import annotations

import itertools

from fronttrack.runner import run
from fronttrack.scene import Accuracy, Layer, Scene
from materials import get


def _plate_impact(**accuracy) -> Scene:
    """The demo's Cu-on-Al 2024 impact (free faces, unbonded contact) to 1.6 us."""
    return Scene(layers=(Layer(get("Cu"), 2e-3, 1000.0),
                         Layer(get("Al2024"), 6e-3, bond="unbonded")),
                 t_end=1.6e-6, accuracy=Accuracy(rays_per_fan=8, **accuracy))


def test_no_fragment_below_the_resolution_length():
    """The bonded Al 2024 plate: no plane closer than the resolution to another (a zone
    0.5 um wide made one plane at each end before); the run stays cheap."""
    al = get("Al2024")
    scene = Scene(layers=(Layer(al, 1e-3, 300.0), Layer(al, 2e-3)), t_end=1e-6,
                  accuracy=Accuracy(max_events=1000))
    solution = run(scene)  # EventLimitError before the default spacing (2 558 events)
    report = solution.accuracy_report
    # 548 (277 before neglect.ALONE kept the contacts whose cost alone exceeds a tenth
    # of the promise: to 2 us 3 982 events within the promise, against 706 beyond it)
    assert solution.stats["events"] < 800
    assert [round(s.x * 1e3, 3) for s in solution.spalls] == [1.966, 2.942, 2.127]
    # the zone there: 2.1269-2.1274 mm before ALONE, one point now; either way one plane
    zone = report["fracture_zones"][-1]
    assert abs(zone["x_lo"] - 2.1269e-3) < 1e-7
    assert zone["x_hi"] - zone["x_lo"] < report["coalesce_length"]
    assert report["suppressed_spalls"] >= 1  # 7
    assert _closest(solution.spalls, 1) >= report["coalesce_length"]
    balance = report["balance"]
    assert balance["energy_error"] < 1e-12  # -1.0e-3: waves neglected, none created
    assert abs(balance["energy_error"]) < balance["promised"]
    assert balance["momentum_error"] < balance["promised"]


def _closest(spalls, layer: int) -> float:
    """The smallest distance (m) between two planes of ``layer``."""
    xs = sorted(s.x for s in spalls if s.layer == layer)
    return min(b - a for a, b in itertools.pairwise(xs))


def test_planes_keep_the_resolution_length():
    solution = run(_plate_impact())
    report = solution.accuracy_report
    length = report["coalesce_length"]
    assert abs(length - 8e-6) < 1e-9
    # the zones near 5.39 and 5.30 mm stay, without planes closer than 8 um
    assert len(solution.spalls) == 6
    assert _closest(solution.spalls, 1) >= length
    assert report["suppressed_spalls"] >= 1
    # carrying the tension of a sub-resolution slab neither creates energy nor costs
    # balance: within the promise, energy not created beyond rounding of the total
    balance = report["balance"]
    assert balance["energy_error"] < 1e-12
    assert abs(balance["momentum_error"]) < balance["promised"]
    assert abs(balance["energy_error"]) < balance["promised"]


def test_explicit_spacing_still_rules():
    """``accuracy.spall_spacing = 0`` keeps the planes the lattices find (the old default)."""
    solution = run(_plate_impact(spall_spacing=0.0))
    assert _closest(solution.spalls, 1) < 2e-6
