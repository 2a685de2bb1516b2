"""The README's scene snippets load and its quick commands run (the demo itself is slow:
``benchmarks/demo_phases.py`` times it).

Every ```toml block of the README is read with ``load_scene``: a complete scene as it
is, a fragment (the ``[spall]`` table, the library-strength material) appended to the
first complete scene.  ``wavediagram materials`` and ``wavediagram match`` run and exit 0.
"""

from __future__ import annotations

import re
import shlex
from pathlib import Path

import pytest

from fronttrack.cli import main
from fronttrack.scene_file import load_scene
from materials import ElasticPlastic

README = Path(__file__).resolve().parent.parent / "README.md"
BLOCKS = re.findall(r"```toml\n(.*?)```", README.read_text(encoding="utf-8"), re.S)
COMMANDS = [line.strip() for line in README.read_text(encoding="utf-8").splitlines()
            if line.startswith("    wavediagram ") and "[" not in line and "demo" not in line
            and "SCENE" not in line]  # placeholders are not commands


def test_readme_has_snippets():
    assert len(BLOCKS) >= 3
    assert "[[layer]]" in BLOCKS[0]


@pytest.mark.parametrize("index", range(len(BLOCKS)))
def test_toml_snippet_loads(tmp_path, index):
    block = BLOCKS[index]
    text = block if "[[layer]]" in block else BLOCKS[0] + "\n" + block
    defined = re.findall(r"^\[materials\.(\w+)\]", block, re.M)
    if defined:  # use the snippet's material in the first layer
        text = text.replace('material = "Cu"', f'material = "{defined[0]}"', 1)
    path = tmp_path / "scene.toml"
    path.write_text(text, encoding="utf-8")
    scene = load_scene(path)
    assert scene.layers
    if defined:
        assert isinstance(scene.layers[0].material, ElasticPlastic)
        assert scene.layers[0].material.mu == pytest.approx(47.7e9)


def test_quick_commands_run(capsys):
    assert main(["materials"]) == 0
    assert "fused_silica" in capsys.readouterr().out
    assert main(["match", "Cu", "1000 m/s", "Al2024", "PMMA"]) == 0
    for command in COMMANDS:
        assert main(shlex.split(command)[1:]) == 0, command
