"""A notebook user's wrong inputs to the queries, design functions and sweeps: each is a
``WavediagramError`` whose one-line message starts with the field it is about (no
``IndexError``, ``KeyError``, ``StopIteration`` or ``AttributeError`` from inside)."""

from __future__ import annotations

import pytest

import fronttrack as ft


@pytest.fixture(scope="module")
def impact() -> ft.Scene:
    return ft.Scene([ft.Layer("Cu", "1 mm", velocity="500 m/s"), ft.Layer("Al2024", "2 mm")],
                    t_end="0.6 us", probes=[ft.Probe("gauge", "1.5 mm")],
                    accuracy=ft.Accuracy(release="hugoniot"))


@pytest.fixture(scope="module")
def solution(impact) -> ft.Solution:
    return ft.run(impact)


def fails(call, field: str) -> str:
    """Run ``call``; it must raise a one-line ``WavediagramError`` about ``field``."""
    with pytest.raises(ft.WavediagramError) as caught:
        call()
    message = str(caught.value)
    assert message.startswith(field) and "\n" not in message, message
    return message


def test_stations_by_name_position_or_length_string(solution):
    """``at`` is a probe, an end, X in metres or a length with its unit; nothing else."""
    assert solution.station("gauge") == solution.station("1.5 mm") == 1.5e-3
    assert solution.station("right") == solution.station(3e-3) == 3e-3
    assert "'gauge'" in fails(lambda: solution.history("gague"), "at: expected")
    assert "0 to 3 mm" in fails(lambda: solution.history("4 mm"), "at: X = 4 mm is outside")
    fails(lambda: solution.history(-1e-4), "at: X = -0.1 mm is outside")
    fails(lambda: ft.one_dimensional_window(solution, "nope"), "at:")
    fails(lambda: solution.arrivals(None), "at:")


def test_instants_inside_the_run(solution):
    at_end = solution.profile("0.6 us")  # t_end itself is inside, given with a unit
    assert at_end.stop == 3e-3 and list(at_end.sigma) == list(solution.profile(0.6e-6).sigma)
    assert "0 to 0.6 us" in fails(lambda: solution.profile(1e-6), "t: 1 us is outside")
    fails(lambda: solution.profile(-1e-9), "t:")
    fails(lambda: solution.state_at(1e-3, "2 us"), "t:")
    fails(lambda: solution.state_at(1.0, 1e-7), "at:")


def test_window_records_name_the_probe(solution):
    assert "'gauge'" in fails(lambda: ft.window_record(solution, "visar"),
                              "probe: no probe named 'visar'")


def test_design_functions_check_their_layer_indices(impact):
    fails(lambda: ft.velocity_for("20 GPa", "Cu", ["Cu"], layer=1),
          "layer: must be a layer index from -1 to 0, got 1")
    fails(lambda: ft.velocity_for("20 GPa", "Cu", []), "stack: needs at least one layer")
    fails(lambda: ft.thickness_for_window(impact, "gauge", "0.1 us", layer=2), "layer:")
    fails(lambda: ft.thickness_for_window(impact, "gauge", "-1 us"),
          "duration: must be > 0 s")
    fails(lambda: ft.flyer_for_spall(impact, "1 mm", target=5), "target:")
    fails(lambda: ft.flyer_for_spall(impact, "1 mm", flyer=1), "target: must be another")
    # the index may count from the end, as for the stack of velocity_for
    v = ft.velocity_for("20 GPa", "Cu", ["Cu", "Al2024"], layer=-2)
    assert v == ft.velocity_for("20 GPa", "Cu", ["Cu", "Al2024"], layer=0)


def test_sweeps_reject_inputs_no_run_could_take(impact):
    fails(lambda: ft.sweep(impact, {"layer.0.velocity": "500 m/s"}, ["events"],
                           backend="serial"), "parameters[layer.0.velocity]: expected a list")
    fails(lambda: ft.sweep(impact, {"layer.0.velocity": ["500 m/s", "fast"]}, ["events"],
                           backend="serial"), "layer.0.velocity: expected a number")
    fails(lambda: ft.sweep(impact, {"layer.1.thickness": ["-2 mm"]}, ["events"],
                           backend="serial"), "layer.1.thickness: must be > 0")
    fails(lambda: ft.sweep(impact, {"layer.0.velocity": ["500 m/s"]}, ["peak_sigma:gague"],
                           backend="serial"), "outputs: 'peak_sigma:gague': at:")
    fails(lambda: ft.sweep(impact, {"material.Cu.zz": [1.0]}, ["events"], backend="serial"),
          "material.Cu.zz: not a field of 'Cu'")
    fails(lambda: ft.sweep(impact, {"accuracy.rays": [4]}, ["events"], backend="serial"),
          "accuracy.rays: not a field of accuracy")
    one = ft.sweep(impact, {"layer.0.velocity": ["500 m/s"]}, "events", backend="serial")
    assert one.columns == ["layer.0.velocity", "events", "error"]


def test_monte_carlo_rejects_inputs_no_run_could_take(impact):
    fails(lambda: ft.monte_carlo(impact, {"material.Cu.zz": 1.0}, ["events"], samples=3,
                                 backend="serial"), "material.Cu.zz: not a field")
    fails(lambda: ft.monte_carlo(impact, {"layer.0.bond": 1.0}, ["events"], samples=3,
                                 backend="serial"),
          "uncertainties[layer.0.bond]: not a numeric field")
    fails(lambda: ft.monte_carlo(impact, {"material.Cu.c0": "1 m/s"}, ["events"], samples=0,
                                 backend="serial"), "samples: must be an integer >= 1")


def test_run_and_scene_say_what_they_expected():
    fails(lambda: ft.run("scene.toml"), "scene: expected a Scene (ft.load_scene")
    fails(lambda: ft.Scene(ft.Layer("Cu", "1 mm"), "1 us"), "layer: expected a list of Layer")
    fails(lambda: ft.Scene([ft.Layer("Cu", "1 mm")], "1 us", probes=ft.Probe("p", "1 mm")),
          "probe: expected a list of Probe")
