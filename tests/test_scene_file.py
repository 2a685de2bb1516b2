"""Scenes read from TOML (``fronttrack.scene_file``)."""

from __future__ import annotations

import math
import tomllib
from importlib import resources

import pytest

from fronttrack.scene import Boundary, SceneError
from fronttrack.scene_file import load_scene, scene_from_dict
from materials import IdealGas, LinearElastic, MieGruneisen, get

FULL = """
title = "Cu on Al"
t_end = "3 us"

[accuracy]
rays_per_fan = 24
stress_tolerance = "0.05 GPa"
negligible_stress = "1 kPa"
release = "hugoniot"
entropy_contacts = false
max_events = 5000

[materials.MyPMMA]
model = "mie-gruneisen"
rho0 = "1186 kg/m3"
c0 = "2.6 km/s"
s = 1.52
gamma0 = 0.97
cv = "1450 J/kg/K"
spall_strength = "0.2 GPa"
up_max = "3 mm/us"
description = "inline PMMA"

[materials.gauge]
model = "linear-elastic"
rho0 = "2.649 g/cc"
C = "5749 m/s"

[materials.steel]
model = "linear-elastic"
rho0 = "7870 kg/m^3"
lambda = "123.1 GPa"
mu = "79.29 GPa"

[materials.air]
model = "ideal-gas"
gamma = 1.4
rho0 = "1.2 kg/m3"

[[layer]]
material = "Cu"
thickness = "1 mm"
velocity = "1000 m/s"
stress = "0 GPa"
name = "flyer"

[[layer]]
material = "Al2024"
thickness = "3 mm"
bond = "unbonded"

[[layer]]
material = "MyPMMA"
thickness = "2 mm"

[[layer]]
material = "gauge"
thickness = "500 um"
stress = "-0.1 GPa"

[[layer]]
material = "steel"
thickness = "0.1 in"

[[layer]]
material = "air"
thickness = "1 cm"

[left]
kind = "free"

[right]
kind = "velocity"
history = [["0 us", "0 m/s"], ["0.5 us", "200 m/s"]]

[[probe]]
name = "rear"
at = "right"

[[probe]]
name = "inside"
at = "2.5 mm"
"""

MINIMAL = {"t_end": "1 us", "layer": [{"material": "Cu", "thickness": "1 mm"}]}


def doc_with(**changes):
    """``MINIMAL`` with top-level keys replaced (a fresh copy each time)."""
    doc = {"t_end": MINIMAL["t_end"], "layer": [dict(MINIMAL["layer"][0])]}
    doc.update(changes)
    return doc


def layer_doc(**fields):
    return doc_with(layer=[{"material": "Cu", "thickness": "1 mm", **fields}])


def error_of(doc) -> str:
    with pytest.raises(SceneError) as info:
        scene_from_dict(doc, "test")
    return str(info.value)


# --- a complete file -------------------------------------------------------------------------
def test_full_example():
    scene = scene_from_dict(tomllib.loads(FULL), "full")
    assert scene.title == "Cu on Al"
    assert scene.t_end == 3e-6
    acc = scene.accuracy
    assert (acc.rays_per_fan, acc.stress_tolerance, acc.negligible_stress) == (24, 5e7, 1e3)
    assert (acc.release, acc.entropy_contacts, acc.max_events) == ("hugoniot", False, 5000)

    flyer, target, pmma, gauge, steel, air = scene.layers
    assert flyer.material is get("Cu") and target.material is get("Al2024")
    assert (flyer.thickness, flyer.velocity, flyer.stress, flyer.name) == (1e-3, 1000.0, 0.0,
                                                                          "flyer")
    assert (flyer.bond, target.bond, target.velocity) == ("bonded", "unbonded", 0.0)

    m = pmma.material
    assert isinstance(m, MieGruneisen) and m.name == "MyPMMA"
    assert (m.rho0, m.c0, m.s, m.gamma0, m.cv) == (1186.0, 2600.0, 1.52, 0.97, 1450.0)
    assert (m.spall_strength, m.up_max) == (2e8, 3000.0)
    assert isinstance(gauge.material, LinearElastic)
    assert (gauge.material.rho0, gauge.material.C) == (2649.0, 5749.0)
    assert (gauge.thickness, gauge.stress) == (5e-4, -1e8)
    assert steel.material.C == pytest.approx(math.sqrt((123.1e9 + 2 * 79.29e9) / 7870.0))
    assert steel.thickness == pytest.approx(2.54e-3, rel=1e-15)
    assert isinstance(air.material, IdealGas) and air.material.gamma == 1.4
    assert air.thickness == 1e-2

    assert scene.left == Boundary("free")
    assert scene.right == Boundary("velocity", ((0.0, 0.0), (0.5e-6, 200.0)))
    assert scene.right.value_at(0.25e-6) == pytest.approx(100.0)
    assert [(p.name, p.at) for p in scene.probes] == [("rear", "right"), ("inside", 2.5e-3)]


def test_demo_scene():
    path = resources.files("fronttrack").joinpath("scenes/demo.toml")
    scene = load_scene(path)
    assert scene.title == "Cu flyer on Al 2024 at 1 km/s"
    assert scene.t_end == 3e-6
    flyer, target = scene.layers
    assert (flyer.material.name, flyer.thickness, flyer.velocity) == ("Cu", 2e-3, 1000.0)
    assert (target.material.name, target.thickness, target.velocity) == ("Al2024", 6e-3, 0.0)
    assert target.bond == "unbonded"
    assert scene.left.kind == scene.right.kind == "free"
    probes = {p.name: p.at for p in scene.probes}
    assert probes == {"rear": "right", "spall_plane": pytest.approx(5e-3, rel=1e-15)}
    assert probes["spall_plane"] == pytest.approx(flyer.thickness + target.thickness / 2)


def test_defaults():
    scene = scene_from_dict(doc_with(), "base")
    assert scene.title == "base"  # no title: the base name
    (layer,) = scene.layers
    assert (layer.velocity, layer.stress, layer.bond, layer.name) == (0.0, 0.0, "bonded", "")
    assert scene.left == scene.right == Boundary("free")
    assert scene.probes == ()
    assert scene.accuracy.rays_per_fan is None and scene.accuracy.stress_tolerance is None


def test_boundaries():
    scene = scene_from_dict(doc_with(left={"kind": "wall"},
                                     right={"kind": "stress", "value": "-1 GPa"}), "b")
    assert scene.left == Boundary("wall")
    assert scene.right == Boundary("stress", ((0.0, -1e9),))
    assert scene.right.value_at(1e-6) == -1e9


def test_inline_material_shadows_library_name():
    doc = doc_with(materials={"Cu": {"model": "linear-elastic", "rho0": "8930 kg/m3",
                                     "C": "4.7 km/s"}})
    (layer,) = scene_from_dict(doc, "x").layers
    assert isinstance(layer.material, LinearElastic) and layer.material.C == 4700.0


def test_layers_share_one_inline_material():
    doc = tomllib.loads(FULL)
    doc["layer"].append({"material": "MyPMMA", "thickness": "1 mm"})
    layers = scene_from_dict(doc, "x").layers
    assert layers[2].material is layers[-1].material


def test_load_scene_reads_a_file(tmp_path):
    path = tmp_path / "impact.toml"
    path.write_text(FULL.replace('title = "Cu on Al"\n', ""), encoding="utf-8")
    scene = load_scene(path)
    assert scene.title == "impact" and len(scene.layers) == 6


def test_load_scene_file_errors(tmp_path):
    with pytest.raises(SceneError, match="cannot read the scene file"):
        load_scene(tmp_path / "missing.toml")
    bad = tmp_path / "bad.toml"
    bad.write_text('t_end = "1 us"\n[[layer]\n', encoding="utf-8")
    with pytest.raises(SceneError, match="bad.toml: not valid TOML"):
        load_scene(bad)


# --- typos and unknown keys --------------------------------------------------------------------
@pytest.mark.parametrize(("doc", "fragments"), [
    (doc_with(t_ned="1 us"), ["t_ned: unknown key (allowed keys: title, t_end,",
                              "did you mean 't_end'?"]),
    (layer_doc(thicknes="1 mm"), ["layer[0].thicknes: unknown key",
                                  "did you mean 'thickness'?"]),
    (doc_with(layer=[{"material": "Cu", "thickness": "1 mm"},
                     {"material": "Cu", "thickness": "1 mm", "bonded": "unbonded"}]),
     ["layer[1].bonded: unknown key", "did you mean 'bond'?"]),
    (doc_with(accuracy={"rays_per_fans": 8}), ["accuracy.rays_per_fans: unknown key",
                                                "did you mean 'rays_per_fan'?"]),
    (doc_with(left={"knd": "free"}), ["left.knd: unknown key (allowed keys: kind, value, "
                                      "history, bond)"]),
    (doc_with(probe=[{"name": "p", "position": "1 mm"}]), ["probe[0].position: unknown key"]),
    (doc_with(materials={"X": {"model": "ideal-gas", "gamma": 1.4, "rho0": "1 kg/m3",
                               "rho00": "1 kg/m3"}}),
     ["materials.X: unknown field 'rho00' for model 'ideal-gas' (allowed: model, gamma, rho0"]),
])
def test_unknown_keys_are_named(doc, fragments):
    message = error_of(doc)
    for fragment in fragments:
        assert fragment in message


# --- values and types ----------------------------------------------------------------------------
@pytest.mark.parametrize(("doc", "fragments"), [
    (layer_doc(thickness="5"), ['layer[0].thickness: missing units in "5" (use one of m, mm']),
    (layer_doc(thickness=5), ['layer[0].thickness: missing units in "5"']),
    (layer_doc(thickness="-1 mm"), ["layer[0].thickness: must be > 0 m, got -0.001"]),
    (layer_doc(thickness="0 mm"), ["layer[0].thickness: must be > 0 m"]),
    (layer_doc(velocity="1 km"), ['layer[0].velocity: unknown unit "km"']),
    (layer_doc(stress="nan GPa"), ["layer[0].stress:", "not a finite number"]),
    (layer_doc(name=3), ["layer[0].name: expected a string, got 3"]),
    (layer_doc(material=["Cu"]), ["layer[0].material: expected a string"]),
    (doc_with(layer=[{"thickness": "1 mm"}]), ["layer[0].material: missing"]),
    (doc_with(layer=[{"material": "Cu"}]), ["layer[0].thickness: missing"]),
    (layer_doc(bond="unbonded"), ["layer[0].bond: the first layer has no previous layer"]),
    (doc_with(layer=[{"material": "Cu", "thickness": "1 mm"},
                     {"material": "Cu", "thickness": "1 mm", "bond": "glued"}]),
     ["layer[1].bond: must be one of"]),
    (doc_with(layer=[{"material": "Cu", "thickness": "1 mm"},
                     {"material": "Cu2", "thickness": "1 mm"}]),
     ["layer[1].material: unknown material 'Cu2'; did you mean Cu?", "available: Al1100"]),
    (doc_with(layer={"material": "Cu", "thickness": "1 mm"}),
     ["layer: expected an array of tables written [[layer]]"]),
    (doc_with(layer=[]), ["layer: a scene needs at least one layer"]),
    ({"layer": MINIMAL["layer"]}, ["t_end: missing"]),
    ({"t_end": "1 us"}, ["layer: missing"]),
    (doc_with(t_end="1 mm"), ['t_end: unknown unit "mm"']),
    (doc_with(t_end="-1 us"), ["t_end: must be > 0 s"]),
    (doc_with(title=7), ["title: expected a string"]),
    (doc_with(accuracy={"rays_per_fan": "16"}), ["accuracy.rays_per_fan: expected int"]),
    (doc_with(accuracy={"rays_per_fan": True}), ["accuracy.rays_per_fan: expected int"]),
    (doc_with(accuracy={"rays_per_fan": 0}), ["accuracy.rays_per_fan: must be an integer"]),
    (doc_with(accuracy={"entropy_contacts": 1}), ["accuracy.entropy_contacts: expected bool"]),
    (doc_with(accuracy={"release": "adiabat"}), ["accuracy.release: must be one of"]),
    (doc_with(accuracy={"stress_tolerance": 5e7}),
     ['accuracy.stress_tolerance: missing units in "50000000.0"']),
    (doc_with(accuracy=[1]), ["accuracy: expected a table"]),
    (doc_with(left={"kind": "piston"}),
     ["left.kind: must be one of free, wall, velocity, stress, got 'piston'"]),
    (doc_with(left={"kind": "free", "value": "0 GPa"}), ["left.value: a free boundary takes "
                                                         "no value"]),
    (doc_with(right={"kind": "velocity"}), ["right: a velocity boundary needs exactly one of "
                                            "value or history"]),
    (doc_with(right={"kind": "velocity", "value": "1 m/s", "history": [["0 s", "1 m/s"]]}),
     ["needs exactly one of value or history"]),
    (doc_with(right={"kind": "velocity", "value": "1 GPa"}), ['right.value: unknown unit "GPa"']),
    (doc_with(right={"kind": "stress", "history": [["0 us", "1 GPa"], ["1 us"]]}),
     ["right.history[1]: expected a [time, value] pair"]),
    (doc_with(right={"kind": "stress", "history": [["0 us", "1 m/s"]]}),
     ['right.history[0] value: unknown unit "m/s"']),
    (doc_with(right={"kind": "stress", "history": []}), ["right.history: expected a list"]),
    (doc_with(right={"kind": "stress", "history": [["2 us", "1 GPa"], ["1 us", "2 GPa"]]}),
     ["right.history: times must start at >= 0 s and increase"]),
    (doc_with(probe=[{"name": "p"}]), ["probe[0].at: missing"]),
    (doc_with(probe=[{"at": "left"}]), ["probe[0].name: missing"]),
    (doc_with(probe=[{"name": "p", "at": "middle"}]), ['probe[0].at: expected a number and a '
                                                       'unit, got "middle"']),
    (doc_with(probe=[{"name": "p", "at": "2 mm"}]), ["probe[p].at: position 2 mm is outside"]),
    (doc_with(probe=[{"name": "p", "at": "left"}, {"name": "p", "at": "right"}]),
     ["duplicate probe name 'p'"]),
    (doc_with(materials={"X": {"model": "mie-gruneisen", "rho0": 1186, "c0": "2.6 km/s",
                               "s": 1.5, "gamma0": 1.0}}),
     ['materials.X.rho0: missing units in "1186"']),
    (doc_with(materials={"X": {"model": "mie-gruneisen", "rho0": "1186 kg/m3",
                               "c0": "2.6 km/s", "s": 1.5}}),
     ["materials.X: missing field 'gamma0' for model 'mie-gruneisen'"]),
    (doc_with(materials={"X": {"model": "mie-gruneisen", "rho0": "-1186 kg/m3",
                               "c0": "2.6 km/s", "s": 1.5, "gamma0": 1.0}}),
     ["materials.X: rho0 must be finite and > 0"]),
    (doc_with(materials={"X": {"rho0": "1 kg/m3"}}), ["materials.X: model must be one of"]),
    (doc_with(materials={"X": "Cu"}), ["materials.X: expected a table"]),
    (doc_with(materials={"X": {"model": "ideal-gas", "gamma": 1.4, "rho0": "1 kg/m3"}},
              layer=[{"material": "Y", "thickness": "1 mm"}]),
     ["layer[0].material: unknown material 'Y'", "(materials defined in this file: X)"]),
])
def test_bad_values_are_named(doc, fragments):
    message = error_of(doc)
    for fragment in fragments:
        assert fragment in message, message


def test_document_must_be_a_table():
    with pytest.raises(SceneError, match="document: expected a table"):
        scene_from_dict([], "x")


def test_contact_resolution_is_a_length():
    scene = scene_from_dict(doc_with(accuracy={"contact_resolution": "2 nm"}), "res")
    assert scene.accuracy.contact_resolution == pytest.approx(2e-9, rel=1e-15)
    assert scene_from_dict(doc_with(), "base").accuracy.contact_resolution == 0.0
    assert "accuracy.contact_resolution" in error_of(doc_with(
        accuracy={"contact_resolution": "-1 nm"}))
    assert "accuracy.contact_resolution" in error_of(doc_with(
        accuracy={"contact_resolution": "1 GPa"}))
