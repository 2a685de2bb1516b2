"""The teaching gallery: its scenes load, its scripts are listed and its README shows them.

Fast checks only (no scene is run): every ``gallery/scenes/*.toml`` is read and
validated by ``load_scene`` and belongs to a script (``NN_short_name.toml`` or
``NN_short_name_variant.toml``); every ``gallery/NN_short_name.py`` compiles and
imports (without running), and its figures are shown in ``gallery/README.md``,
whose images all exist.
"""

from __future__ import annotations

import importlib.util
import re
import sys
from pathlib import Path

import pytest

from fronttrack.scene_file import load_scene

GALLERY = Path(__file__).resolve().parent.parent / "gallery"
SCRIPT = re.compile(r"^\d\d_[a-z0-9_]+\.py$")
SCRIPTS = sorted(p for p in GALLERY.glob("*.py") if SCRIPT.match(p.name))
SCENES = sorted((GALLERY / "scenes").glob("*.toml"))
README = GALLERY / "README.md"
IMAGE = re.compile(r"!\[[^\]]*\]\((figures/[^)]+\.png)\)")


def test_gallery_has_scripts_and_scenes():
    assert len(SCRIPTS) >= 12
    assert SCENES
    assert (GALLERY / "make_all.py").is_file()
    assert (GALLERY / "common.py").is_file()


@pytest.mark.parametrize("path", SCENES, ids=lambda p: p.name)
def test_scene_loads_and_validates(path):
    scene = load_scene(path)
    assert scene.layers
    assert scene.t_end > 0.0
    assert scene.title, f"{path.name}: give the scene a title (it is printed on the figures)"


@pytest.mark.parametrize("path", SCENES, ids=lambda p: p.name)
def test_scene_belongs_to_a_script(path):
    stems = [s.stem for s in SCRIPTS]
    assert any(path.stem == s or path.stem.startswith(f"{s}_") for s in stems), (
        f"scene {path.name} has no script gallery/<prefix>.py")


@pytest.mark.parametrize("script", SCRIPTS, ids=lambda p: p.stem)
def test_script_compiles_and_imports(script, monkeypatch):
    compile(script.read_text(encoding="utf-8"), str(script), "exec")
    monkeypatch.syspath_prepend(str(GALLERY))
    spec = importlib.util.spec_from_file_location(f"gallery_{script.stem}", script)
    module = importlib.util.module_from_spec(spec)
    try:
        spec.loader.exec_module(module)   # defines main(); runs nothing
    finally:
        sys.modules.pop(f"gallery_{script.stem}", None)
    assert callable(getattr(module, "main", None)), f"{script.name}: no main()"


def test_readme_shows_every_script_and_its_images_exist():
    text = README.read_text(encoding="utf-8")
    images = IMAGE.findall(text)
    assert images, "README.md shows no figure"
    for image in images:
        assert (GALLERY / image).is_file(), f"README.md shows missing {image}"
    for script in SCRIPTS:
        assert any(Path(image).stem.startswith(script.stem) for image in images), (
            f"README.md shows no figure of {script.name} (figures/{script.stem}*.png)")
    assert "python gallery/make_all.py" in text
