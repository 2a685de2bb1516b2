"""The public API: ``import fronttrack as ft``, unit strings, self-validating scene parts,
and every Python snippet of the README run as written."""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

import pytest

import fronttrack as ft
from materials.library import get

ROOT = Path(__file__).resolve().parent.parent


def test_import_is_light_and_all_names_resolve():
    """``import fronttrack`` loads neither matplotlib nor shapely; every name of
    ``__all__`` is there (figure functions on first use)."""
    code = ("import sys, fronttrack; "
            "print(sorted(m for m in ('matplotlib', 'shapely') if m in sys.modules))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True, cwd=ROOT).stdout.strip()
    assert out == "[]"
    missing = [name for name in ft.__all__ if getattr(ft, name, None) is None]
    assert missing == []
    assert ft.plot_xt.__module__ == "fronttrack.plotting.xt"
    with pytest.raises(AttributeError, match="no attribute 'plot_nothing'"):
        ft.plot_nothing  # noqa: B018


def test_unit_strings_equal_si_floats():
    by_units = ft.Layer("Cu", "1 mm", velocity="1 km/s", stress="0.5 GPa")
    by_si = ft.Layer(get("Cu"), 1e-3, velocity=1000.0, stress=5e8)
    assert by_units == by_si
    assert (by_units.thickness, by_units.velocity, by_units.stress) == (1e-3, 1000.0, 5e8)
    assert ft.Boundary("stress", "1 GPa").history == ((0.0, 1e9),)
    pulse = ft.Boundary("velocity", [("0 us", "100 m/s"), ("1 us", "0.1 km/s")])
    assert pulse.history == ((0.0, 100.0), (1e-6, 100.0))
    assert ft.Probe("p", "2.5 mm").at == 2.5e-3
    acc = ft.Accuracy(stress_tolerance="10 MPa", spall_spacing="0.2 mm")
    assert (acc.stress_tolerance, acc.spall_spacing) == (1e7, 2e-4)
    assert ft.Scene([by_si], "3 us").t_end == 3e-6
    assert ft.SpallCriterion.incubation("1 GPa", "50 ns").damage == 50e-9
    assert ft.material("Cu") is get("Cu")
    inline = ft.material("MyPMMA", model="mie-gruneisen", rho0="1.186 g/cm3",
                         c0="2.6 km/s", s=1.52, gamma0=0.97)
    assert (inline.rho0, inline.c0) == (1186.0, 2600.0)


@pytest.mark.parametrize("build, message", [
    (lambda: ft.Layer("Cu", "-1 mm"), "layer.thickness: must be > 0 m"),
    (lambda: ft.Layer("Cu", "1 m/s"), 'layer.thickness: unknown unit "m/s"'),
    (lambda: ft.Layer("Unobtainium", "1 mm"), "layer.material: .*Unobtainium"),
    (lambda: ft.Layer("Cu", 1e-3, bond="glued"), "layer.bond: must be one of"),
    (lambda: ft.Boundary("free", "1 GPa"), "boundary.history: a free boundary takes no"),
    (lambda: ft.Boundary("stress"), "boundary.history: a stress boundary needs"),
    (lambda: ft.Boundary("piston"), "boundary.kind: must be one of"),
    (lambda: ft.Probe("p", "1 mm", kind="interface", side="up"), "probe.side"),
    (lambda: ft.Probe("p", "1 mm", window="LiF"), "probe.window: only an interface"),
    (lambda: ft.Probe("p", "1 mm", kind="interface", side="right", window="glass"),
     "probe.window: no refractive-index fit for 'glass'"),
    (lambda: ft.Accuracy(rays_per_fan=0), "accuracy.rays_per_fan: must be an integer"),
    (lambda: ft.Accuracy(negligible_stress="-1 MPa"), "accuracy.negligible_stress: must be >="),
    (lambda: ft.SpallCriterion("1 GPa", 1.0, exponent=11), "spall.exponent: must be in 0..10"),
    (lambda: ft.Scene([], "1 us"), "layer: a scene needs at least one layer"),
    (lambda: ft.Scene([ft.Layer("Cu", "1 mm")], "1 mm"), 't_end: unknown unit "mm"'),
    (lambda: ft.Scene([ft.Layer("Cu", "1 mm")], "1 us", probes=[ft.Probe("p", "2 mm")]),
     r"probe\[p\]\.at: position 2 mm is outside the stack"),
    (lambda: ft.Scene([ft.Layer("Cu", "1 mm"), ft.Layer("LiF", "1 mm")], "1 us",
                      probes=[ft.Probe("p", "0.5 mm", kind="interface", side="right")]),
     r"probe\[p\]\.at: an interface probe must sit on a contact"),
])
def test_each_part_validates_itself(build, message):
    with pytest.raises(ft.SceneError, match=message):
        build()
    assert issubclass(ft.SceneError, ft.WavediagramError)


def test_scene_files_name_the_layer_index():
    """Errors a part raises are restated at its place in a file: ``layer[1].thickness``."""
    doc = {"t_end": "1 us", "layer": [{"material": "Cu", "thickness": "1 mm"},
                                      {"material": "Cu", "thickness": "-1 mm"}]}
    with pytest.raises(ft.SceneError, match=r"^layer\[1\]\.thickness: must be > 0 m"):
        ft.scene_from_dict(doc)
    doc = {"t_end": "1 us", "layer": [{"material": "Cu", "thickness": "1 mm"}],
           "probe": [{"name": "p", "at": "right", "kind": "interface", "side": "sideways"}]}
    with pytest.raises(ft.SceneError, match=r"^probe\[0\]\.side"):
        ft.scene_from_dict(doc)


def readme_snippets() -> list[str]:
    text = (ROOT / "README.md").read_text()
    return re.findall(r"```python\n(.*?)```", text, flags=re.DOTALL)


def test_readme_has_python_snippets():
    assert len(readme_snippets()) >= 2


@pytest.mark.parametrize("index", range(len(readme_snippets())))
def test_readme_snippet_runs(index, tmp_path, monkeypatch, capsys):
    """Every Python snippet of the README runs as written (in a scratch directory), and
    prints what the comment line after each ``print`` says it prints."""
    import matplotlib

    matplotlib.use("Agg")
    monkeypatch.chdir(tmp_path)
    snippet = readme_snippets()[index]
    exec(compile(snippet, f"README.md python snippet {index}", "exec"), {})
    lines = snippet.splitlines()
    expected = [after[2:] for before, after in zip(lines, lines[1:], strict=False)
                if before.startswith("print(") and after.startswith("# ")]
    assert capsys.readouterr().out.splitlines() == expected
