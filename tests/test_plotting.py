"""Figures: region numbers are 1, 2, 3 … in reading order, agree between diagrams and
with the JSON, sit inside their regions, once each; labels stay inside their axes and
do not overlap; the colour bar is linear; the σ–u diagram spans its numbered states;
fans are light and shocks heavy; the attenuation curve is exact; axes carry units; the
standard set is written; nothing plotted is NaN.

Scenes: a Cu flyer on an Al target at 1 km/s with Hugoniot release (cheap: every
wave is a shock) and, for fans, the same impact with isentropic release and 4
rays per fan, plus a linear elastic stack against a rigid wall.
"""

from __future__ import annotations

import io
import math
import warnings

import matplotlib
import matplotlib.pyplot as plt
import numpy as np
import pytest
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.collections import LineCollection
from matplotlib.figure import Figure
from shapely.geometry import Point, Polygon

from fronttrack.plotting import (
    FIGURE_NAMES,
    number_list,
    peak_stress,
    peak_stress_steps,
    plot_free_surface_velocity,
    plot_histories,
    plot_peak_stress,
    plot_profiles,
    plot_sigma_rho,
    plot_sigma_u,
    plot_xt,
    region_numbers,
    save_standard_figures,
    xt_and_sigma_u,
)
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


def _xt(solution, eulerian=False):
    """The X–t diagram of a standard figure, with the standard numbers (of the JSON)."""
    figure = Figure(figsize=(7.0, 5.4))
    return plot_xt(solution, ax=figure.add_subplot(), eulerian=eulerian,
                   numbers=region_numbers(solution))


def _xt_axes(solution, eulerian=False):
    return _xt(solution, eulerian).ax


def _page_boxes(figure, texts):
    """Window extents (pixels) of texts after drawing the figure."""
    renderer = FigureCanvasAgg(figure).get_renderer()
    figure.draw_without_rendering()
    return [t.get_window_extent(renderer) for t in texts]


# --- region numbers ---------------------------------------------------------
@pytest.mark.parametrize("name", ["hugoniot", "isentrope", "wall"])
def test_numbers_are_consecutive_in_reading_order_and_in_the_json(request, name):
    solution = request.getfixturevalue(name)
    numbers = region_numbers(solution)
    assert sorted(numbers.values()) == list(range(1, len(numbers) + 1))
    regions = {r.id: r for r in solution.regions}
    starts = [(min(t for _, t in regions[i].vertices), i)
              for i in sorted(numbers, key=numbers.get)]
    assert [t for t, _ in starts] == sorted(t for t, _ in starts)
    # the layers at t = 0 are 1, 2, … from left to right
    initial = sorted((r for r in solution.regions if r.id in numbers
                      and sum(t == 0.0 for _, t in r.vertices) > 1),
                     key=lambda r: min(x for x, _ in r.vertices))
    assert len(initial) == len(solution.scene.layers)
    assert [numbers[r.id] for r in initial] == list(range(1, len(initial) + 1))
    doc = solution.to_dict(probes=False)
    assert {r["id"]: r["number"] for r in doc["regions"] if r["number"]} == numbers


@pytest.mark.parametrize("name", ["hugoniot", "isentrope", "wall"])
def test_xt_and_sigma_u_number_the_same_regions(request, name):
    solution = request.getfixturevalue(name)
    _, xt, su = xt_and_sigma_u(solution)
    assert xt.numbers == su.numbers == region_numbers(solution)
    assert set(xt.labels) == set(su.labels) == set(xt.numbers)
    written = sorted(int(t.get_text()) for t in xt.texts)
    assert written == list(range(1, len(xt.numbers) + 1))
    # every number appears once on the σ–u diagram, in one of the shared labels
    shown = [n for t in su.texts for n in _numbers_in(t.get_text())]
    assert sorted(shown) == written
    panels = plot_sigma_rho(solution, numbers=xt.numbers)
    assert set().union(*(p.labels for p in panels)) == set(xt.numbers)


def _numbers_in(text: str) -> list[int]:
    numbers = []
    for item in text.replace("\n", " ").split(","):
        item = item.strip()
        if "–" in item:
            lo, hi = (int(v) for v in item.split("–"))
            numbers += list(range(lo, hi + 1))
        elif item:
            numbers.append(int(item))
    return numbers


def test_number_list_groups_runs():
    assert number_list([3, 1, 2, 7, 9, 10]) == "1–3, 7, 9, 10"
    assert number_list([5]) == "5"
    assert _numbers_in(number_list(list(range(1, 40, 2)))) == list(range(1, 40, 2))
    assert number_list(list(range(1, 40, 2))).count("\n") == 3


@pytest.mark.parametrize("name", ["hugoniot", "isentrope", "wall"])
def test_labels_inside_axes_and_not_overlapping(request, name):
    solution = request.getfixturevalue(name)
    figure, xt, su = xt_and_sigma_u(solution)
    for placed in (xt, su):
        boxes = _page_boxes(figure, placed.texts)
        axes_box = placed.ax.get_window_extent()
        for box in boxes:
            assert axes_box.x0 - 1 <= box.x0 and box.x1 <= axes_box.x1 + 1
            assert axes_box.y0 - 1 <= box.y0 and box.y1 <= axes_box.y1 + 1
        for k, a in enumerate(boxes):
            for b in boxes[k + 1:]:
                assert not a.overlaps(b), (placed.ax.get_title(), a, b)


@pytest.mark.parametrize("eulerian", [False, True])
@pytest.mark.parametrize("name", ["hugoniot", "isentrope", "wall"])
def test_each_label_once_and_inside_its_region(request, name, eulerian):
    solution = request.getfixturevalue(name)
    placed = _xt(solution, eulerian)
    labels = placed.labels
    assert labels and set(labels) == set(placed.numbers)
    view = eulerian_view(solution) if eulerian else lagrangian_view(solution)
    for region_id, (x, t) in labels.items():
        assert Polygon(view.polygons[region_id]).contains(Point(x, t)), region_id
    written = [t.get_text() for t in placed.ax.texts if t.get_text().isdigit()]
    assert sorted(written) == sorted(str(placed.numbers[i]) for i in labels)
    assert not set(labels) & fan_interior(solution)


def test_small_and_fan_regions_are_not_numbered(isentrope):
    labels = _xt(isentrope).labels
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
    axes = [_xt_axes(solution), _xt_axes(solution, eulerian=True), plot_sigma_u(solution).ax,
            *(p.ax for p in plot_sigma_rho(solution)), plot_profiles(solution, [0.5e-6, 1.5e-6]),
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
            data = np.asarray(line.get_xydata(), dtype=float)
            separators = np.isnan(data).all(axis=1)  # fan rays: one NaN-separated polyline
            assert np.all(np.isfinite(data[~separators]))
        for collection in ax.collections:
            for path in collection.get_paths():
                assert np.all(np.isfinite(path.vertices))
        for patch in ax.patches:
            assert np.all(np.isfinite(patch.get_path().vertices))
        for text in ax.texts:
            assert all(math.isfinite(v) for v in text.get_position())


def test_save_standard_figures_writes_png(tmp_path, hugoniot):
    reported = []
    paths = save_standard_figures(hugoniot, tmp_path, prefix="cu_", parallel=False,
                                  progress=lambda name, k, n: reported.append((k, n)))
    assert reported == [(k, len(paths)) for k in range(1, len(paths) + 1)]
    names = {p.name for p in paths}
    assert names == {f"cu_{n}.png" for n in FIGURE_NAMES}
    for path in paths:
        data = path.read_bytes()
        assert data[:8] == b"\x89PNG\r\n\x1a\n" and len(data) > 10_000, path


def test_forked_figure_is_written_and_reported(tmp_path, wall, monkeypatch):
    # only which files exist and what is reported matters here: skip the (slow) rendering;
    # the forked process inherits the patch
    monkeypatch.setattr(Figure, "savefig", lambda self, path, **kw: path.write_bytes(b"x"))
    reported = []
    paths = save_standard_figures(wall, tmp_path, parallel=True,
                                  progress=lambda name, k, n: reported.append((name, k)))
    assert all(p.read_bytes() == b"x" for p in paths)
    assert reported[0] == ("xt_eulerian.png (in a second process)", 2)
    assert sorted(k for _, k in reported) == list(range(1, len(paths) + 1))


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


# --- colour scale, σ–u extent, fans, σ–ρ, attenuation ---------------------------
@pytest.mark.parametrize("name", ["isentrope", "wall"])
def test_colour_bar_is_one_linear_scale_centred_on_zero(request, name):
    solution = request.getfixturevalue(name)
    bar = _xt(solution).colorbar
    norm = bar.norm
    assert norm.vmin == pytest.approx(-norm.vmax)
    ticks = np.array(bar.get_ticks())
    assert 0.0 in ticks and len(ticks) >= 3
    steps = np.diff(ticks)
    assert np.allclose(steps, steps[0])
    # equal stress steps are equal colour steps on both sides of zero
    assert np.allclose(np.diff(norm(ticks)), steps[0] / (norm.vmax - norm.vmin))
    sigma = [r.state.sigma * 1e-9 for r in solution.regions]
    low, high = bar.ax.get_ylim()
    assert high == pytest.approx(max(sigma))
    assert low == pytest.approx(min(min(sigma), 0.0), abs=1e-9)


@pytest.mark.parametrize("name", ["hugoniot", "isentrope"])
def test_sigma_u_spans_the_numbered_states_only(request, name):
    solution = request.getfixturevalue(name)
    placed = plot_sigma_u(solution)
    u = [p[0] for p in placed.labels.values()]
    sigma = [p[1] for p in placed.labels.values()] + [0.0]
    (u0, u1), (s0, s1) = placed.ax.get_xlim(), placed.ax.get_ylim()
    span_u, span_s = max(u) - min(u), max(sigma) - min(sigma)
    assert u0 == pytest.approx(min(u) - 0.08 * span_u)
    assert u1 == pytest.approx(max(u) + 0.08 * span_u)
    assert s0 == pytest.approx(min(sigma) - 0.08 * span_s)
    assert s1 == pytest.approx(max(sigma) + 0.08 * span_s)
    # by default only the waves joining two numbered states are drawn
    drawn = [c for c in placed.ax.collections if len(c.get_paths())]
    assert drawn and all(c.get_alpha() == pytest.approx(0.95) for c in drawn)
    more = plot_sigma_u(solution, all_paths=True)
    assert sum(len(c.get_paths()) for c in more.ax.collections) >= sum(
        len(c.get_paths()) for c in drawn)


def test_fans_are_light_and_shocks_heavy(isentrope):
    ax = _xt_axes(isentrope)
    rays = [line for line in ax.get_lines() if line.get_alpha() is not None
            and line.get_alpha() < 0.5]
    assert rays and all(line.get_linewidth() <= 0.5 for line in rays)
    edges = [line for line in ax.get_lines() if line.get_linestyle() == "--"]
    assert edges, "head and tail rays are marked"
    shocks = [c for c in ax.collections if isinstance(c, LineCollection)
              and np.allclose(c.get_colors()[0][:3], 0.0)]
    assert shocks and max(max(c.get_linewidths()) for c in shocks) >= 1.5


def test_sigma_rho_of_one_material_has_one_title_and_room(tmp_path):
    cu = MieGruneisen("Cu", 8930, 3940, 1.49, 2.0)
    solution = run(Scene(layers=(Layer(cu, 1e-3, 500.0), Layer(cu, 3e-3, 0.0)),
                         t_end=6.0e-6, accuracy=Accuracy(release="hugoniot")))
    assert len(region_numbers(solution)) > 20  # a plate ringing: many states, one material
    figure = Figure(figsize=(6.4, 5.0), layout="constrained")
    panels = plot_sigma_rho(solution, ax=[figure.add_subplot()])
    assert len(panels) == 1 and figure.get_suptitle() == ""
    titles = [t.get_text() for t in figure.findobj(matplotlib.text.Text) if "σ–ρ" in t.get_text()]
    assert len(titles) == 1
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # e.g. "constrained_layout not applied"
        figure.savefig(io.BytesIO(), format="png")
    axes_box = panels[0].ax.get_window_extent()
    legend_box = panels[0].ax.get_legend().get_window_extent()
    for box in _page_boxes(figure, panels[0].texts):
        assert axes_box.x0 - 1 <= box.x0 and box.x1 <= axes_box.x1 + 1
    assert axes_box.width > 0.6 * figure.bbox.width
    assert axes_box.x0 <= legend_box.x0 and legend_box.x1 <= axes_box.x1


def test_peak_stress_steps_are_exact_up_to_the_surfaces(hugoniot):
    edges, top, bottom = peak_stress_steps(hugoniot)
    assert edges[0] == 0.0 and edges[-1] == pytest.approx(hugoniot.scene.length)
    assert np.all(np.isfinite(top)) and np.all(bottom <= top)
    middles = 0.5 * (edges[1:] + edges[:-1])
    for k in (0, len(middles) // 3, len(middles) - 1):
        sigma = hugoniot.history(float(middles[k])).sigma
        assert top[k] == pytest.approx(sigma.max(), rel=1e-12)
    # no sampling ramp at the free surfaces: the first and last steps keep their value
    assert top[0] > 0.5 * top.max() and top[-1] > 0.5 * top.max()
    ax = plot_peak_stress(hugoniot)
    assert any("exact" in t.get_text() for t in ax.texts)
