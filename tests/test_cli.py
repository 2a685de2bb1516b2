"""The command line: exit codes, one-line errors, the JSON documents it writes."""

from __future__ import annotations

import json

import pytest

from fronttrack.cli import main

SCENE = """
title = "Al on Cu"
t_end = "1.2 us"
[accuracy]
rays_per_fan = 4
[[layer]]
material = "Al6061"
thickness = "1 mm"
velocity = "600 m/s"
[[layer]]
material = "Cu"
thickness = "3 mm"
bond = "unbonded"
[left]
kind = "free"
[right]
kind = "free"
[[probe]]
name = "rear"
at = "right"
[[probe]]
name = "inside"
at = "2.5 mm"
"""


def write(tmp_path, text, name="scene.toml"):
    path = tmp_path / name
    path.write_text(text)
    return path


def test_run_writes_the_solution_document(tmp_path):
    scene = write(tmp_path, SCENE)
    out = tmp_path / "out.json"
    assert main(["run", str(scene), "--json", str(out), "--quiet"]) == 0
    doc = json.loads(out.read_text())
    for key in ("regions", "fronts", "events", "spall", "stats", "probes", "accuracy"):
        assert key in doc
    assert doc["stats"]["events"] == len(doc["events"]) > 3
    assert doc["stats"]["solve_time"] > 0.0
    rear = doc["probes"]["rear"]
    assert len(rear["t"]) == len(rear["sigma"]) == len(rear["u"]) >= 2
    assert rear["t"][0] == 0.0 and rear["u"][0] == 0.0
    # the rear free surface jumps at the shock's arrival and stays unstressed
    assert all(s == 0.0 for s in rear["sigma"])
    assert max(rear["u"]) > 0.0
    assert all(isinstance(s["x"], float) and isinstance(s["t"], float) for s in doc["spall"])


def test_run_writes_probe_csvs(tmp_path):
    scene = write(tmp_path, SCENE)
    outdir = tmp_path / "results"
    assert main(["run", str(scene), "-o", str(outdir), "--no-figures", "--quiet"]) == 0
    rows = (outdir / "probe_inside.csv").read_text().splitlines()
    assert rows[0] == "t_s,sigma_Pa,u_m_per_s,rho_kg_per_m3"
    assert len(rows) >= 3
    assert (outdir / "solution.json").exists()


@pytest.mark.parametrize("edit, message", [
    (('thickness = "1 mm"', 'thickness = "-1 mm"'), "layer[0].thickness"),
    (('thickness = "1 mm"', 'thickness = "1"'), "missing units"),
    (('material = "Cu"', 'material = "Copperr"'), "layer[1].material"),
    (('kind = "free"\n[right]', 'kind = "glue"\n[right]'), "left.kind"),
    (("rays_per_fan = 4", "rays_per_fan = 0"), "accuracy.rays_per_fan"),
    (('t_end = "1.2 us"', 't_end = "1.2 us"\ntend = "3 us"'), "tend"),
])
def test_malformed_scene_is_one_line_and_exit_2(tmp_path, capsys, edit, message):
    scene = write(tmp_path, SCENE.replace(*edit, 1))
    assert main(["run", str(scene), "--quiet", "--no-figures"]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1
    assert message in err


def test_event_limit_is_a_clear_error(tmp_path, capsys):
    scene = write(tmp_path, SCENE.replace("rays_per_fan = 4", "rays_per_fan = 4\nmax_events = 3"))
    assert main(["run", str(scene), "--quiet", "--no-figures"]) == 2
    assert "accuracy.max_events" in capsys.readouterr().err


def test_match_json(tmp_path, capsys):
    out = tmp_path / "match.json"
    assert main(["match", "Cu", "1000 m/s", "Al2024", "PMMA", "--json", str(out)]) == 0
    table = capsys.readouterr().out
    assert "Al2024" in table and "PMMA" in table
    doc = json.loads(out.read_text())
    rows = doc["rows"]
    assert [r["material"] for r in rows] == ["Cu", "Al2024", "PMMA"]
    for row in rows:
        assert row["sigma"] > 0.0 and row["u"] > 0.0 and row["rho"] > 0.0
    # stress and particle velocity are continuous across the impact plane
    assert rows[0]["sigma"] == pytest.approx(rows[1]["sigma"], rel=1e-12)


def test_match_beyond_the_fitted_data_warns_in_one_line_each(capsys):
    assert main(["match", "Cu", "100 km/s", "Al2024"]) == 0
    captured = capsys.readouterr()
    warnings = [line for line in captured.err.splitlines() if "warning" in line]
    assert len(warnings) == 2
    assert all(line.startswith("wavediagram: warning: ") and "up_max" in line
               for line in warnings)
    assert "Traceback" not in captured.err


def test_match_needs_units(capsys):
    assert main(["match", "Cu", "1000", "Al2024"]) == 2
    assert "missing units" in capsys.readouterr().err


def test_materials_lists_sources(capsys):
    assert main(["materials"]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert len(lines) >= 21
    assert all(line.split()[-1] for line in lines[1:])
    assert any(line.startswith("Cu ") and "LASL" in line for line in lines)
