"""Sweeps equal separate runs bit for bit on every backend; failing points are rows;
Monte Carlo collapses to the deterministic answer and matches first-order propagation."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

import fronttrack as ft
from fronttrack.parameters import field_value, portable, restored, with_field
from fronttrack.sweep import evaluate

OUTPUTS = ["peak_sigma:gauge", "arrival:gauge", "window:gauge", "events", "max_tension"]
VELOCITIES = [f"{v} m/s" for v in np.linspace(200.0, 1200.0, 11)]


def impact() -> ft.Scene:
    return ft.Scene([ft.Layer("Cu", "1 mm", velocity="500 m/s"), ft.Layer("Al2024", "2 mm")],
                    t_end="0.6 us", probes=[ft.Probe("gauge", "1.5 mm")],
                    accuracy=ft.Accuracy(release="hugoniot"))


def separate_runs(scene: ft.Scene) -> list[list[float]]:
    rows = []
    for velocity in VELOCITIES:
        solution = ft.run(with_field(scene, "layer.0.velocity", velocity))
        rows.append([evaluate(solution, output) for output in OUTPUTS])
    return rows


def values(table: ft.Table) -> list[list[float]]:
    return [[row[output] for output in OUTPUTS] for row in table.rows]


@pytest.mark.parametrize("backend", ["serial", "processes"])
def test_sweep_equals_separate_runs(backend):
    scene = impact()
    table = ft.sweep(scene, {"layer.0.velocity": VELOCITIES}, OUTPUTS, backend=backend,
                     workers=2)
    assert table.columns == ["layer.0.velocity", *OUTPUTS, "error"]
    assert table.column("layer.0.velocity") == VELOCITIES
    assert table.column("error") == [None] * 11
    assert values(table) == separate_runs(scene)


def test_sweep_on_a_dask_local_cluster():
    distributed = pytest.importorskip("dask.distributed")
    scene = impact()
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        table = ft.sweep(scene, {"layer.0.velocity": VELOCITIES}, OUTPUTS, backend="dask",
                         client=client)
    assert values(table) == separate_runs(scene)


def test_failing_point_is_a_row_with_its_error(tmp_path):
    scene = impact()
    # an initial stress outside the equation of state (a 100 km/s impact used to fail
    # here; its release now stops at the end of the equation of state and runs)
    table = ft.sweep(scene, {"layer.0.velocity": ["500 m/s"],
                             "layer.1.stress": ["0 GPa", "-50 GPa"]}, ["peak_sigma:gauge"],
                     backend="serial")
    good, bad = table.rows
    assert good["error"] is None and good["peak_sigma:gauge"] > 5e9
    assert bad["error"].startswith("StateOutOfRangeError: layer[1].stress = -50 GPa: Al2024")
    assert math.isnan(bad["peak_sigma:gauge"])
    doc = json.loads(table.to_json(tmp_path / "sweep.json"))
    assert doc["rows"][1]["peak_sigma:gauge"] is None
    lines = table.to_csv(tmp_path / "sweep.csv").read_text().splitlines()
    assert lines[0] == "layer.0.velocity,layer.1.stress,peak_sigma:gauge,error"
    assert float(lines[1].split(",")[2]) == good["peak_sigma:gauge"]


def test_table_as_a_dataframe():
    pytest.importorskip("pandas")
    table = ft.sweep(impact(), {"layer.0.velocity": VELOCITIES[:3]}, ["events"],
                     backend="serial")
    frame = table.to_pandas()
    assert list(frame.columns) == table.columns
    assert frame["events"].tolist() == table.column("events")


def test_unknown_paths_and_outputs_fail_before_running():
    with pytest.raises(ft.SceneError, match="layer.7.velocity: no layer '7'"):
        ft.sweep(impact(), {"layer.7.velocity": [1.0]}, ["events"], backend="serial")
    with pytest.raises(ft.SceneError, match="outputs: unknown output 'peak'"):
        ft.sweep(impact(), {"layer.0.velocity": [1.0]}, ["peak"], backend="serial")


def test_scene_survives_the_trip_to_a_worker():
    scene = impact()
    again = restored(portable(scene))
    assert again.layers[0].material.c0 == scene.layers[0].material.c0
    assert evaluate(ft.run(again), "peak_sigma:gauge") == evaluate(ft.run(scene),
                                                                    "peak_sigma:gauge")


def test_monte_carlo_without_uncertainty_is_deterministic():
    scene = impact()
    result = ft.monte_carlo(scene, {"material.Al2024.c0": 0.0, "material.Cu.s": 0.0},
                            ["peak_sigma:gauge"], samples=5, backend="serial")
    exact = evaluate(ft.run(scene), "peak_sigma:gauge")
    assert set(result.quantiles["peak_sigma:gauge"].values()) == {exact}
    assert result.std["peak_sigma:gauge"] == 0.0 and result.failed == 0


def test_monte_carlo_spread_matches_first_order_propagation():
    """Impact stress with c0 of Al 2024 known to 50 m/s and s of Cu to 0.02 (independent):
    the sample spread matches sqrt(sum (d sigma/d p)^2 sd_p^2) within sampling error
    (400 samples: a relative error of the standard deviation of about 1/sqrt(800))."""
    scene = impact()
    deviations = {"material.Al2024.c0": 50.0, "material.Cu.s": 0.02}
    result = ft.monte_carlo(scene, deviations, ["peak_sigma:gauge"], samples=400, seed=1,
                            backend="processes", workers=2)
    first_order = 0.0
    for path, sd in deviations.items():
        step = 1e-3 * sd
        base = float(field_value(scene, path))
        up = evaluate(ft.run(with_field(scene, path, base + step)), "peak_sigma:gauge")
        down = evaluate(ft.run(with_field(scene, path, base - step)), "peak_sigma:gauge")
        first_order += ((up - down) / (2 * step) * sd) ** 2
    spread = result.std["peak_sigma:gauge"]
    print(f"Monte Carlo spread {spread:.6g} Pa, first order {math.sqrt(first_order):.6g} Pa")
    assert spread == pytest.approx(math.sqrt(first_order), rel=3 / math.sqrt(800))
    assert result.quantiles["peak_sigma:gauge"][0.05] < result.mean["peak_sigma:gauge"] \
        < result.quantiles["peak_sigma:gauge"][0.95]
