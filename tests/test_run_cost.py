"""What keeps a long run's cost linear in its length: the time-sliced lookups of the
solution's segments (``Solution._live_at``) and the collector paused during a run
(``fronttrack.collector``).

The lookups must give what a scan over every segment gives: the segments live at an
instant are those with ``t0 <= t < t1`` (or ending at ``t_end``), and the cell at
``(x, t)`` is the region right of the rightmost live segment at or left of ``x``.
"""

from __future__ import annotations

import gc
import random

import numpy as np
import pytest

import fronttrack as ft
from fronttrack import collector

STEEL = ft.material("Davison steel", model="elastic-plastic", rho0="7870 kg/m3",
                    **{"lambda": "123.1 GPa"}, mu="79.29 GPa", yield_strength="1 GPa")


COLLECTOR_DURING_RUN = []


@pytest.fixture(scope="module")
def solution():
    # Davison's steel to 5 us: a few thousand segments, contacts, gap, reverse yielding
    scene = ft.Scene(layers=(ft.Layer(STEEL, "5 mm", velocity="230 m/s"),
                             ft.Layer(STEEL, "10 mm", bond="unbonded")), t_end="5 us")
    return ft.run(scene, progress=lambda events, t: COLLECTOR_DURING_RUN.append(gc.isenabled()))


def _scan(solution, x, t):
    """The region at ``(x, t)`` by a scan over every segment (no time slices)."""
    a = solution._segments()
    t_end = solution.scene.t_end
    live = (a["t0"] <= t) & ((a["t1"] > t) | (a["t1"] >= t_end))
    pos = np.where(a["speed"] == 0.0, a["x0"], a["x0"] + a["speed"] * (t - a["t0"]))
    left = np.nonzero(live & (pos <= x) & (a["right"] >= 0))[0]
    if left.size == 0:
        candidates = np.nonzero(live & (a["right"] >= 0))[0]
        return int(a["right"][candidates[np.argmin(pos[candidates])]])
    return int(a["right"][left[solution._spatial_order(left, pos, t)[-1]]])


def test_time_slices_find_what_a_scan_over_every_segment_finds(solution):
    a = solution._segments()
    index, start, width = solution._time_buckets()
    assert len(start) - 1 > 10  # the run is cut into many slices
    rnd = random.Random(13)
    t_end, length = solution.scene.t_end, solution.scene.length
    # random instants, and the ends of segments (where a lookup is most delicate)
    times = [rnd.uniform(0.0, t_end) for _ in range(150)] + [0.0, t_end]
    times += [float(t) for t in rnd.sample(list(a["t1"]), 100)]
    for t in times:
        live, _ = solution._live_at(t)
        every = np.nonzero((a["t0"] <= t) & ((a["t1"] > t) | (a["t1"] >= t_end)))[0]
        assert live.tolist() == every.tolist()
        for x in (0.0, rnd.uniform(0.0, length), 5e-3, length):
            assert solution._region_id_at(x, t) == _scan(solution, x, t)


def test_the_collector_is_paused_during_a_run_and_restored_after(solution):
    assert COLLECTOR_DURING_RUN and not any(COLLECTOR_DURING_RUN)
    assert gc.isenabled()
    with collector.paused():
        assert not gc.isenabled()
    assert gc.isenabled()
    gc.disable()
    try:
        with collector.paused():
            assert not gc.isenabled()
        assert not gc.isenabled()  # a caller's choice is kept
    finally:
        gc.enable()
