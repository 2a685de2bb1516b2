"""``wavediagram sweep`` from the shell: ranges, lists, the table written, bad input."""

from __future__ import annotations

import json

import pytest

import fronttrack as ft
from fronttrack.cli import main
from fronttrack.cli_sweep import sweep_values

SCENE = '''t_end = "0.6 us"
[accuracy]
release = "hugoniot"
[[layer]]
material = "Cu"
thickness = "1 mm"
velocity = "500 m/s"
[[layer]]
material = "Al2024"
thickness = "2 mm"
[[probe]]
name = "gauge"
at = "1.5 mm"
'''


def test_range_and_list_values():
    assert sweep_values("200..1200 m/s/11", "v") == [f"{v!r} m/s" for v in
                                                      [200.0 + 100.0 * k for k in range(11)]]
    assert sweep_values("1 mm, 2 mm", "t") == ["1 mm", "2 mm"]
    assert sweep_values("1..2/3", "x") == ["1.0", "1.5", "2.0"]
    with pytest.raises(ft.SceneError, match="COUNT must be in 1..100000"):
        sweep_values("1..2 mm/0", "t")


def test_sweep_command_writes_the_table(tmp_path, capsys):
    scene = tmp_path / "impact.toml"
    scene.write_text(SCENE)
    out = tmp_path / "out"
    status = main(["sweep", str(scene), "--set", "layer.0.velocity=200..1200 m/s/11",
                   "--set", "layer.1.thickness=2 mm,3 mm", "--quantity", "peak_sigma:gauge",
                   "--backend", "serial", "-o", str(out)])
    assert status == 0
    assert capsys.readouterr().out.startswith("22 points, 0 failed; wrote")
    doc = json.loads((out / "sweep.json").read_text())
    assert doc["columns"] == ["layer.0.velocity", "layer.1.thickness", "peak_sigma:gauge",
                              "error"]
    expected = ft.sweep(ft.load_scene(scene), {"layer.0.velocity": ["1200.0 m/s"]},
                        ["peak_sigma:gauge"], backend="serial").rows[0]["peak_sigma:gauge"]
    assert doc["rows"][-1]["peak_sigma:gauge"] == expected
    assert len((out / "sweep.csv").read_text().splitlines()) == 23


def test_bad_assignment_is_one_line_exit_2(tmp_path, capsys):
    scene = tmp_path / "impact.toml"
    scene.write_text(SCENE)
    status = main(["sweep", str(scene), "--set", "layer.9.velocity=1 m/s", "-o",
                   str(tmp_path / "out")])
    assert status == 2
    assert capsys.readouterr().err.strip() == (
        "wavediagram: error: layer.9.velocity: no layer '9' (the scene has 2: 0 to 1)")
