"""The command line cannot be broken (issue 12, items 4-6): every hostile input of the
campaign is one line and exit status 2 (130 on Ctrl-C), outputs are checked before the
solve and written whole or not at all, and a run can be stopped by a time limit."""

from __future__ import annotations

import io
import json
import os
import signal
import subprocess
import sys
from pathlib import Path

import pytest

from fronttrack import cli
from fronttrack.cli import main
from fronttrack.scene import SceneError
from fronttrack.scene_file import LIMITS, MAX_FILE_BYTES, load_scene, scene_from_dict

SCENE = """
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
[[probe]]
name = "rear"
at = "right"
"""

LONG_SCENE = """
t_end = "2 us"
[[layer]]
material = "Cu"
thickness = "1 mm"
velocity = "500 m/s"
[[layer]]
material = "Al2024"
thickness = "2 mm"
"""
"""A scene that needs tens of thousands of events (its spall zone rings for long)."""


def write(tmp_path: Path, text: str | bytes, name: str = "scene.toml") -> Path:
    path = tmp_path / name
    (path.write_bytes if isinstance(text, bytes) else path.write_text)(text)
    return path


def error_line(capsys) -> str:
    err = capsys.readouterr().err
    assert "Traceback" not in err
    lines = err.strip().splitlines()
    assert len(lines) == 1, err
    return lines[0]


@pytest.fixture
def no_solve(monkeypatch):
    """Make solving fail loudly: the checks under test must come before it."""
    def refuse(*_args, **_kwargs):
        raise AssertionError("the scene was solved before the check")
    monkeypatch.setattr(cli, "_solve", refuse)


# --- reading the scene --------------------------------------------------------------------
@pytest.mark.parametrize("data, message", [
    (SCENE.encode() + b'title = "\xff\xfe"\n', "not UTF-8 text (byte 0xff on line 16)"),
    (SCENE.encode() + b"x = " + b"[" * 100_000 + b"]" * 100_000 + b"\n",
     "nested too deep"),
    (b"#" * (MAX_FILE_BYTES + 1), "larger than 1024 KiB"),
    (SCENE.replace('"1 mm"', '"1e-30 mm"').encode(),
     'layer[0].thickness: "1e-30 mm" is outside the accepted magnitudes (0, or 1e-09 to '
     "1000 m"),
    (SCENE.replace('"600 m/s"', '"1e-300 m/s"').encode(),
     'layer[0].velocity: "1e-300 m/s" is outside the accepted magnitudes (0, or 1e-06 to '
     "100000 m/s"),
    (SCENE.replace('"Al6061"', '"M"').encode()
     + b'[materials.M]\nmodel = "mie-gruneisen"\nrho0 = "2700 kg/m3"\nc0 = "5000 m/s"\n'
       b"s = 1e-300\ngamma0 = 2.0\n", "materials.M: s must be in [0.1, 10.0]"),
    (SCENE.encode() + b'[spall]\ncriterion = "tuler-butcher"\nthreshold = "1 GPa"\n'
                      b'exponent = 1e300\ndamage = "1 GPa^1e+300 us"\n',
     "spall.exponent: 1e+300 makes spall.damage overflow"),
    (SCENE.replace('"rear"', '"re\\u0000ar"').encode(), "probe[0].name: 're\\x00ar' cannot"),
    (SCENE.replace('"rear"', '"' + "a" * 5000 + '"').encode(), "probe[0].name: 'aaaa"),
    (SCENE.replace('"rear"', '"a/b"').encode(), "probe[0].name: 'a/b' cannot be part of a "
                                                 "file name"),
    (SCENE.replace("rays_per_fan = 4", "rays_per_fan = 100000").encode(),
     "accuracy.rays_per_fan: 100000 is more than the 1000 a scene file may give"),
    (SCENE.encode() + b'[spall]\ncriterion = "incubation"\nthreshold = "1 GPa"\n'
                      b'incubation_time = "0.1 us"\nstations = 100000\n',
     "spall.stations: 100000 is more than the 10000"),
    (SCENE.replace('"1.2 us"', '"1 s"').encode(), "t_end: 1e+06 us is more than 1000 sound "
                                                   "transits of the stack"),
], ids=["non-utf8", "nested", "too-large", "thin", "slow", "tiny-s", "huge-exponent",
        "probe-nul", "probe-long", "probe-slash", "rays", "stations", "t_end"])
def test_hostile_scene_is_one_line_and_exit_2(tmp_path, capsys, no_solve, data, message):
    out = tmp_path / "out"
    assert main(["run", str(write(tmp_path, data)), "-o", str(out)]) == 2
    line = error_line(capsys)
    assert line.startswith("wavediagram: error: ") and message in line, line
    assert len(line) < 300
    assert not out.exists()


def test_dev_zero_is_refused_at_the_size_cap(capsys, no_solve):
    assert main(["run", "/dev/zero"]) == 2
    assert "larger than 1024 KiB" in error_line(capsys)


def test_byte_order_mark_is_accepted(tmp_path):
    scene = load_scene(write(tmp_path, b"\xef\xbb\xbf" + SCENE.encode()))
    assert [layer.thickness for layer in scene.layers] == [1e-3, 3e-3]


@pytest.mark.parametrize("edit, key, message", [
    (lambda doc: doc.update(layer=doc["layer"] * 50_000), "layer",
     "layer: number of [[layer]] tables: 100000 is more than the 1000"),
    (lambda doc: doc.update(right={"kind": "velocity", "history": [
        [f"{i} ns", "1 m/s"] for i in range(200_000)]}), "history",
     "right.history: number of points: 200000 is more than the 10000"),
    (lambda doc: doc.update(accuracy={"max_events": 10**9}), "max_events",
     "accuracy.max_events: 1000000000 is more than the 2000000"),
])
def test_counts_are_capped(edit, key, message):
    doc = {"t_end": "1 us", "layer": [{"material": "Cu", "thickness": "1 mm"},
                                      {"material": "Al2024", "thickness": "1 mm"}]}
    edit(doc)
    with pytest.raises(SceneError, match="more than") as caught:
        scene_from_dict(doc)
    assert message in str(caught.value)
    assert str(LIMITS[key]) in str(caught.value)


# --- match ------------------------------------------------------------------------------------
@pytest.mark.parametrize("velocity", ["0 m/s", "-500 m/s"])
def test_match_without_impact_is_one_line(capsys, velocity):
    assert main(["match", "Cu", velocity, "Al2024"]) == 2
    line = error_line(capsys)
    assert line.startswith("wavediagram: error: velocity: the flyer velocity must be finite "
                           "and > 0 m/s (toward the stack), got ")


# --- outputs checked before the solve ---------------------------------------------------------
def test_output_dir_that_is_a_file(tmp_path, capsys, no_solve):
    existing = write(tmp_path, "keep", "existing")
    assert main(["run", str(write(tmp_path, SCENE)), "-o", str(existing)]) == 2
    assert f"-o: {existing} exists and is not a directory" in error_line(capsys)
    assert existing.read_text() == "keep"


def test_output_dir_that_is_a_dangling_link(tmp_path, capsys, no_solve):
    link = tmp_path / "link"
    link.symlink_to(tmp_path / "missing")
    assert main(["run", str(write(tmp_path, SCENE)), "-o", str(link)]) == 2
    assert "is a link to" in error_line(capsys)
    assert not (tmp_path / "missing").exists()


def test_output_dir_where_no_file_can_be_made(tmp_path, capsys, no_solve):
    # root may write into a mode-0o555 directory; nobody may create a file in /proc
    if os.geteuid() == 0:
        target = Path("/proc/wavediagram-out")
    else:
        locked = tmp_path / "locked"
        locked.mkdir(mode=0o555)
        target = locked / "out"
    assert main(["run", str(write(tmp_path, SCENE)), "-o", str(target)]) == 2
    assert "-o: cannot create files in" in error_line(capsys)


@pytest.mark.parametrize("json_path, message", [
    (lambda tmp: tmp, "is a directory; name a file"),
    (lambda tmp: Path("/dev/full"), "is not a regular file"),
    (lambda tmp: tmp / "scene.toml", "is the scene file itself"),
], ids=["directory", "device", "scene-itself"])
def test_json_path_refused(tmp_path, capsys, no_solve, json_path, message):
    scene = write(tmp_path, SCENE)
    assert main(["run", str(scene), "--json", str(json_path(tmp_path))]) == 2
    assert f"--json: {json_path(tmp_path)} {message}" in error_line(capsys)
    assert scene.read_text() == SCENE


def test_solution_json_named_like_the_scene_in_output_dir(tmp_path, capsys, no_solve):
    scene = write(tmp_path, SCENE, "solution.json")
    assert main(["run", str(scene), "-o", str(tmp_path)]) == 2
    assert "is the scene file itself" in error_line(capsys)


# --- whole or absent ----------------------------------------------------------------------------
def test_interrupt_while_writing_keeps_the_previous_outputs(tmp_path, capsys, monkeypatch):
    scene, out = write(tmp_path, SCENE), tmp_path / "out"
    assert main(["run", str(scene), "-o", str(out), "--no-figures", "--quiet"]) == 0
    before = {path.name: path.read_bytes() for path in out.iterdir()}
    assert sorted(before) == ["probe_rear.csv", "solution.json"]

    def interrupted(self, stream, probes=True, progress=None, polygons=True):
        stream.write('{"title":')
        raise KeyboardInterrupt
    monkeypatch.setattr("fronttrack.solution.Solution.write_json", interrupted)
    assert main(["run", str(scene), "-o", str(out), "--no-figures", "--quiet"]) == 130
    assert error_line(capsys) == "wavediagram: interrupted; no output written"
    assert {path.name: path.read_bytes() for path in out.iterdir()} == before


def test_interrupt_during_the_solve(tmp_path, capsys, monkeypatch):
    def interrupted(*_args, **_kwargs):
        raise KeyboardInterrupt
    monkeypatch.setattr(cli, "run", interrupted)
    out = tmp_path / "out"
    assert main(["run", str(write(tmp_path, SCENE)), "-o", str(out)]) == 130
    assert error_line(capsys) == "wavediagram: interrupted; no output written"
    assert not out.exists() or not any(out.iterdir())


def test_sigint_exits_130_without_traceback(tmp_path):
    scene, out = write(tmp_path, LONG_SCENE), tmp_path / "out.json"
    # a process started in the background inherits SIGINT ignored, and Python then never
    # raises KeyboardInterrupt: give the child the default disposition, as a terminal does
    process = subprocess.Popen([sys.executable, "-m", "fronttrack.cli", "run", str(scene),
                                "--json", str(out)], stderr=subprocess.PIPE, text=True,
                               preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    first = process.stderr.readline()  # a progress line: the solve is under way
    process.send_signal(signal.SIGINT)
    rest = process.communicate(timeout=60)[1]
    assert "events, t =" in first
    assert process.returncode == 130
    assert "Traceback" not in rest and "interrupted; no output written" in rest
    assert list(tmp_path.iterdir()) == [scene]


def test_internal_error_is_one_line_and_exit_3(tmp_path, capsys, monkeypatch):
    def broken(*_args, **_kwargs):
        return 1 / 0
    monkeypatch.setattr(cli, "run", broken)
    assert main(["run", str(write(tmp_path, SCENE)), "--quiet"]) == 3
    line = error_line(capsys)
    assert line.startswith("wavediagram: internal error (ZeroDivisionError: division by zero)")


# --- time limit and streamed JSON -----------------------------------------------------------------
def test_time_limit_writes_the_partial_solution_and_says_so(tmp_path, capsys):
    scene, out = write(tmp_path, LONG_SCENE), tmp_path / "out"
    assert main(["run", str(scene), "-o", str(out), "--no-figures",
                 "--time-limit", "1 ns"]) == 0
    err = capsys.readouterr().err
    assert "Traceback" not in err
    assert "wavediagram: warning: time limit of 1e-09 s reached; the solution ends at t =" in err
    doc = json.loads((out / "solution.json").read_text())
    stopped = doc["stats"]["stopped"]
    assert stopped["t_end"] == 2e-6 and 0.0 <= stopped["t"] < 2e-6
    assert doc["t_end"] == stopped["t"]
    assert doc["stats"]["events"] == len(doc["events"]) <= 1


def test_max_seconds_is_read_from_the_scene(tmp_path):
    text = SCENE.replace("rays_per_fan = 4", 'rays_per_fan = 4\nmax_seconds = "90 s"')
    assert load_scene(write(tmp_path, text)).accuracy.max_seconds == 90.0
    with pytest.raises(SceneError, match="accuracy.max_seconds: must be > 0 s"):
        load_scene(write(tmp_path, text.replace('"90 s"', '"-1 s"')))


def test_streamed_json_is_the_document(tmp_path):
    from fronttrack.runner import run

    solution = run(load_scene(write(tmp_path, SCENE)))
    stream, reports = io.StringIO(), []
    solution.write_json(stream, progress=lambda done, total: reports.append((done, total)))
    assert json.loads(stream.getvalue()) == json.loads(json.dumps(solution.to_dict()))
    total = solution.stats["regions"] + solution.stats["fronts"] + solution.stats["events"]
    assert reports[-1] == (total, total)
    assert all(done % 10_000 == 0 for done, _ in reports[:-1])
