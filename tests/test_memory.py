"""Memory a solution keeps per event, counted by ``tracemalloc`` (deterministic, no timing).

Davison's steel, 5 mm onto 10 mm at 230 m/s, to 6 µs: 4 199 events, 8 134 fronts and
5 345 regions; the engine compacts its objects into columns (``fronttrack.archive``)
twice during the run and once at its end.  What the diagram, the records and the outputs
need, per event of this scene:

- 1.94 fronts of 92 B of columns (7 floats, 8 int32, 4 int8): 178 B;
- 1.27 regions of 105 B of columns and 6.3 chain points of 16 B: 262 B;
- the event: 49 B of packed arrays and 8 B for each of its 3.0 front ids: 73 B;
- the query segments the balance cached (``Solution._segments``), 2.5 of 58 B: 145 B;

about 660 B (685 B measured, with what does not grow with the events: isentrope
tables, counters, the scene), against 2 300 B when the engine's objects were kept: the
fronts as objects took 830 B per event, the regions 600 B, the event records 390 B.  The
bound, 850 B, fails if any of the three is kept as objects again.  Writing the JSON
streams it: its peak above what the solution holds stays within the same bound (it was
2 300 B per event when every region's record and polygon were built first to number
them).
"""

from __future__ import annotations

import gc
import json
import tracemalloc

import pytest

import fronttrack as ft
from fronttrack.event_log import EventLog, EventRecord
from fronttrack.kinds import EventKind

STEEL = ft.material("Davison steel", model="elastic-plastic", rho0="7870 kg/m3",
                    **{"lambda": "123.1 GPa"}, mu="79.29 GPa", yield_strength="1 GPa")

BYTES_PER_EVENT = 850
"""Bound on the memory a solution keeps per event, and on the JSON writer's peak above
it (see the module docstring)."""


def steel(t_end: float) -> ft.Scene:
    return ft.Scene(layers=(ft.Layer(STEEL, "5 mm", velocity="230 m/s"),
                            ft.Layer(STEEL, "10 mm", bond="unbonded")),
                    t_end=t_end, title="Davison steel")


@pytest.fixture(scope="module")
def traced():
    """The 6 µs run: its solution, the bytes it holds and the JSON writer's peak above."""
    ft.run(steel(1e-6))  # warm-up: what is loaded once, not per run
    gc.collect()
    tracemalloc.start(1)
    try:
        base = tracemalloc.get_traced_memory()[0]
        solution = ft.run(steel(6e-6))
        gc.collect()
        retained = tracemalloc.get_traced_memory()[0] - base
        tracemalloc.reset_peak()
        solution.write_json(_Sink())
        json_peak = tracemalloc.get_traced_memory()[1] - base - retained
    finally:
        tracemalloc.stop()
    return solution, retained, json_peak


class _Sink:
    """A text stream that keeps nothing."""

    def write(self, text: str) -> int:
        return len(text)


def test_retained_memory_per_event_is_bounded(traced):
    solution, retained, _ = traced
    events = solution.stats["events"]
    assert events > 4000  # long enough that the per-run constants are small
    assert retained / events < BYTES_PER_EVENT


def test_json_writer_peak_per_event_is_bounded(traced):
    solution, _, json_peak = traced
    assert json_peak / solution.stats["events"] < BYTES_PER_EVENT


def test_compacted_records_are_whole(traced):
    """Every front and region made survives the compactions: ids unique, each front's
    neighbouring regions among the regions, counts as the stats say."""
    solution = traced[0]
    fronts, regions = solution.fronts, solution.regions
    assert len(fronts) == solution.stats["fronts"] and len(regions) == solution.stats["regions"]
    region_ids = {r.id for r in regions}
    assert len(region_ids) == len(regions) and len({f.id for f in fronts}) == len(fronts)
    for front in fronts:
        neighbours = [front.left_region, front.right_region_id,
                      *(rid for _, rid in front.earlier_regions)]
        assert all(rid is None or rid in region_ids for rid in neighbours)
    assert [f.id for f in fronts] == sorted(f.id for f in fronts)


def test_event_log_reads_back_what_was_logged():
    log = EventLog()
    logged = [EventRecord(t=1.5e-6, x=2e-3, kind=EventKind.IMPACT, incoming=[],
                          outgoing=[3, 4], site=2),
              EventRecord(t=2.0e-6, x=0.1, kind=EventKind.LATTICE, incoming=[5, 6, 7],
                          outgoing=[8], nodes=120)]
    for event in logged:
        log.append(event)
    assert list(log) == logged and log[-1] == logged[1] and log[:1] == logged[:1]
    assert len(log) == 2
    with pytest.raises(IndexError):
        log[2]


def test_json_writing_shows_its_progress(tmp_path, capsys):
    """``wavediagram run --json`` reports on stderr how much of the file it has written,
    the last report on a line of its own (in a log, as here, every report is a line)."""
    from fronttrack.cli import main

    scene = tmp_path / "scene.toml"
    scene.write_text('t_end = "1 us"\n[[layer]]\nmaterial = "Cu"\nthickness = "1 mm"\n'
                     'velocity = "300 m/s"\n[[layer]]\nmaterial = "Al2024"\n'
                     'thickness = "2 mm"\nbond = "unbonded"\n')
    out = tmp_path / "solution.json"
    code = main(["run", str(scene), "--json", str(out)])
    err = capsys.readouterr().err
    assert code == 0, err
    lines = err.splitlines()
    document = json.loads(out.read_text())
    total = sum(len(document[key]) for key in ("regions", "fronts", "events"))
    assert f"  writing {out}: 100 % of {total} records" in lines
