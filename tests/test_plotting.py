"""Figures: region numbers agree between diagrams, sit inside their regions, once each;
axes carry units; the standard set is written; nothing plotted is NaN.

Scenes: a Cu flyer on an Al target at 1 km/s with Hugoniot release (cheap: every
wave is a shock) and, for fans, the same impact with isentropic release and 4
rays per fan, plus a linear elastic stack against a rigid wall.
"""

from __future__ import annotations

import math

import matplotlib
import matplotlib.pyplot as plt
import numpy as np
import pytest
from matplotlib.figure import Figure
from shapely.geometry import Point, Polygon

from fronttrack.plotting import (
    placed_labels,
    plot_free_surface_velocity,
    plot_histories,
    plot_peak_stress,
    plot_profiles,
    plot_sigma_u,
    plot_sigma_v,
    plot_xt,
    save_standard_figures,
    xt_and_sigma_u,
)
from fronttrack.plotting.attenuation import peak_stress
from fronttrack.plotting.eulerian import region_motions
from fronttrack.plotting.fans import fan_interior
from fronttrack.plotting.records import pullback
from fronttrack.plotting.sites import kind_segments
from fronttrack.plotting.xt_geometry import eulerian_view, lagrangian_view
from fronttrack.runner import run
from fronttrack.scene import Accuracy, Boundary, Layer, Probe, Scene
from materials import LinearElastic, MieGruneisen

matplotlib.use("Agg")  # headless: no figure is open yet, so the backend can still switch

UNITS = ("(mm)", "(µs)", "GPa", "m/s", "kg/m³")


def _impact(release: str, rays: int = 16, t_end: float = 2.5e-6) -> Scene:
    cu = MieGruneisen("Cu", 8930, 3940, 1.49, 2.0, cv=385, spall_strength=1.5e9)
    al = MieGruneisen("Al2024", 2785, 5328, 1.338, 2.0, cv=875, spall_strength=1.2e9)
    return Scene(layers=(Layer(cu, 2e-3, 1000.0, name="flyer"),
                         Layer(al, 6e-3, 0.0, bond="unbonded", name="target")),
                 t_end=t_end, probes=(Probe("rear", "right"), Probe("mid", 5e-3)),
                 accuracy=Accuracy(release=release, rays_per_fan=rays),
                 title="Cu on Al at 1 km/s")


@pytest.fixture(scope="module")
def hugoniot():
    return run(_impact("hugoniot"))


@pytest.fixture(scope="module")
def isentrope():
    return run(_impact("isentrope", rays=4, t_end=2.0e-6))


@pytest.fixture(scope="module")
def wall():
    steel = LinearElastic("steel", 7870, 5983)
    quartz = LinearElastic("quartz", 2649, 5749)
    scene = Scene(layers=(Layer(steel, 2e-3, 200.0, name="impactor"),
                          Layer(quartz, 3e-3, 0.0, name="gauge")),
                  t_end=2.0e-6, right=Boundary("wall"), probes=(Probe("gauge", 3.5e-3),),
                  title="steel on quartz against a wall")
    return run(scene)


@pytest.fixture(autouse=True)
def _close_figures():
    yield
    plt.close("all")


def _xt_axes(solution, eulerian=False):
    figure = Figure(figsize=(7.0, 5.4))
    return plot_xt(solution, ax=figure.add_subplot(), eulerian=eulerian)


# --- region numbers ---------------------------------------------------------
@pytest.mark.parametrize("name", ["hugoniot", "isentrope", "wall"])
def test_xt_and_sigma_u_number_the_same_regions(request, name):
    solution = request.getfixturevalue(name)
    figure = xt_and_sigma_u(solution)
    ax_xt, ax_su = [ax for ax in figure.axes if placed_labels(ax)]
    xt, su = set(placed_labels(ax_xt)), set(placed_labels(ax_su))
    assert xt and xt == su
    # the stand-alone σ–u diagram picks the numbers of the stand-alone X–t diagram
    assert set(placed_labels(plot_sigma_u(solution))) == set(placed_labels(_xt_axes(solution)))
    for panel in plot_sigma_v(solution, numbers=xt):
        assert set(placed_labels(panel)) <= xt
    assert set().union(*(placed_labels(p) for p in plot_sigma_v(solution, numbers=xt))) == xt


@pytest.mark.parametrize("eulerian", [False, True])
@pytest.mark.parametrize("name", ["hugoniot", "isentrope", "wall"])
def test_each_label_once_and_inside_its_region(request, name, eulerian):
    solution = request.getfixturevalue(name)
    ax = _xt_axes(solution, eulerian)
    labels = placed_labels(ax)
    assert labels
    view = eulerian_view(solution) if eulerian else lagrangian_view(solution)
    for region_id, (x, t) in labels.items():
        assert Polygon(view.polygons[region_id]).contains(Point(x, t)), region_id
    written = [t.get_text() for t in ax.texts if t.get_text().isdigit()]
    assert sorted(written) == sorted(str(i) for i in labels)
    assert not set(labels) & fan_interior(solution)


def test_small_and_fan_regions_are_not_numbered(isentrope):
    labels = placed_labels(_xt_axes(isentrope))
    interior = fan_interior(isentrope)
    assert interior, "the isentrope scene has fans"
    assert len(labels) < len(isentrope.regions) - len(interior)


def test_fan_interior_excludes_constant_states_beside_fans(isentrope):
    interior = fan_interior(isentrope)
    first_fan = [f for f in isentrope.fronts if f.kind == "ray" and f.ray_count > 1][0]
    rays = [f for f in isentrope.fronts if f.kind == "ray" and f.fan == first_fan.fan
            and (f.x0, f.t0) == (first_fan.x0, first_fan.t0)]
    head = min(rays, key=lambda f: f.ray_index)
    tail = max(rays, key=lambda f: f.ray_index)
    ahead = head.right_region_id if head.direction > 0 else head.left_region
    behind = tail.left_region if tail.direction > 0 else tail.right_region_id
    assert ahead not in interior and behind not in interior
    between = {f.left_region if f.direction > 0 else f.right_region_id for f in rays} - {behind}
    assert between and between <= interior


# --- units, NaN, files --------------------------------------------------------
def _all_axes(solution):
    axes = [_xt_axes(solution), _xt_axes(solution, eulerian=True), plot_sigma_u(solution),
            *plot_sigma_v(solution), plot_profiles(solution, [0.5e-6, 1.5e-6]),
            plot_profiles(solution, [1e-6], quantity="u"), *plot_histories(solution),
            plot_free_surface_velocity(solution), plot_peak_stress(solution)]
    return axes


def test_axis_labels_carry_units(hugoniot):
    for ax in _all_axes(hugoniot):
        for label in (ax.get_xlabel(), ax.get_ylabel()):
            if label:
                assert any(unit in label for unit in UNITS), label
        assert ax.get_ylabel() or ax.get_xlabel()


@pytest.mark.parametrize("name", ["hugoniot", "isentrope", "wall"])
def test_nothing_plotted_is_nan(request, name):
    solution = request.getfixturevalue(name)
    for ax in _all_axes(solution):
        for line in ax.get_lines():
            assert np.all(np.isfinite(np.asarray(line.get_xydata(), dtype=float)))
        for collection in ax.collections:
            for path in collection.get_paths():
                assert np.all(np.isfinite(path.vertices))
        for patch in ax.patches:
            assert np.all(np.isfinite(patch.get_path().vertices))
        for text in ax.texts:
            assert all(math.isfinite(v) for v in text.get_position())
        for region_id, position in placed_labels(ax).items():
            assert all(math.isfinite(v) for v in position), region_id


def test_save_standard_figures_writes_png(tmp_path, hugoniot):
    paths = save_standard_figures(hugoniot, tmp_path, prefix="cu_")
    names = {p.name for p in paths}
    assert names == {f"cu_{n}.png" for n in ("xt", "xt_eulerian", "sigma_u", "sigma_v",
                                              "profiles", "probes", "free_surface",
                                              "peak_stress", "xt_su")}
    for path in paths:
        data = path.read_bytes()
        assert data[:8] == b"\x89PNG\r\n\x1a\n" and len(data) > 10_000, path


def test_no_probe_figure_without_probes(tmp_path, wall, monkeypatch):
    scene = wall.scene
    bare = run(Scene(layers=scene.layers, t_end=scene.t_end, right=scene.right))
    # only the list of files matters here: skip the (slow) rendering
    monkeypatch.setattr(Figure, "savefig", lambda self, path, **kw: path.write_bytes(b"x"))
    names = {p.name for p in save_standard_figures(bare, tmp_path)}
    assert "probes.png" not in names and "xt.png" in names


# --- geometry and records -------------------------------------------------------
@pytest.mark.parametrize("name", ["hugoniot", "wall"])
def test_eulerian_positions_are_continuous_and_match_the_solution(request, name):
    solution = request.getfixturevalue(name)
    motions = region_motions(solution)
    scale = solution.scene.length
    for front in solution.fronts:
        if front.kind == "shock":
            left, right = motions[front.left_region], motions[front.right_region_id]
            for x, t in ((front.x0, front.t0), (front.x1, front.t1)):
                assert left(x, t) == pytest.approx(right(x, t), abs=1e-12 * scale)
    rng = np.random.default_rng(1)
    for _ in range(20):
        x, t = rng.uniform(0, scale), rng.uniform(0, solution.scene.t_end)
        region = solution.region_at(x, t)
        assert motions[region.id](x, t) == pytest.approx(solution.eulerian_position(x, t),
                                                         abs=1e-12 * scale)


def test_opened_interface_is_drawn_as_interface_then_gap(hugoniot):
    interface = [f for f in hugoniot.fronts if f.x0 == 2e-3 and f.t0 == 0.0
                 and f.kind in ("interface", "gap")][0]
    pieces = kind_segments(interface)
    assert [kind for _, _, kind in pieces] == ["interface", "gap"]
    assert pieces[0][1] == pieces[1][0] == interface.history[0][0]


def test_peak_stress_matches_station_histories(hugoniot):
    x, top, bottom = peak_stress(hugoniot, n=41)
    for k in (0, 7, 20, 33, 40):
        sigma = hugoniot.history(float(x[k])).sigma
        assert top[k] == pytest.approx(sigma.max(), rel=1e-12)
        assert bottom[k] <= sigma.min() + 1e-6


def test_pullback_finds_first_peak_and_low_before_rebound():
    assert pullback([0.0, 300.0, 280.0, 250.0, 270.0, 200.0]) == (1, 3, True)
    assert pullback([0.0, 300.0, 250.0]) == (1, 2, False)
    assert pullback([0.0, 100.0, 300.0]) == (2, None, False)


def test_profiles_are_the_solution_profiles(hugoniot):
    ax = plot_profiles(hugoniot, [1.0e-6])
    x, values = ax.lines[0].get_data()
    expected_x, expected = hugoniot.profile(1.0e-6).samples("sigma")
    assert np.allclose(values, expected * 1e-9) and np.allclose(x, expected_x * 1e3)
