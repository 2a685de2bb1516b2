"""Changing one field of a scene by its path, for sweeps and Monte Carlo.

A path names a field the way a scene file nests it:

- ``t_end``;
- ``layer.N.FIELD``: ``thickness``, ``velocity``, ``stress``, ``bond`` or
  ``material`` (a name or a ``Material``) of layer ``N`` (negative counts from
  the end);
- ``layer.N.material.FIELD``: a field of layer ``N``'s material (``rho0``,
  ``c0``, ``s``, ``gamma0``, ``spall_strength``, ...: the arguments of its
  model's constructor);
- ``material.NAME.FIELD``: that field of every layer made of material ``NAME``;
- ``left.value`` / ``right.value``: a constant boundary velocity or stress;
- ``accuracy.FIELD``.

Values are SI numbers or strings with units, as everywhere in the API.  Materials
are rebuilt from their constructor's fields (``material_fields``), which is also
how a scene is sent to another process (``portable`` and ``restored``).
"""

from __future__ import annotations

import dataclasses
import inspect
import io
import pickle
from typing import Any

from materials import Material, MaterialError
from materials.library import FIELD_DIMENSIONS

from .errors import SceneError, located
from .scene import Boundary, Scene
from .units import to_si


def material_fields(material: Material) -> dict[str, Any]:
    """The constructor arguments that rebuild ``material`` (its model's fields, SI)."""
    fields = {}
    for name in list(inspect.signature(type(material).__init__).parameters)[1:]:
        for holder in (material, getattr(material, "eos", None)):
            if holder is not None and name in vars(holder):
                fields[name] = vars(holder)[name]
                break
        else:
            raise SceneError(f"material.{name}: {material.name!r} ({type(material).__name__}) "
                             f"does not keep its field {name!r}; it cannot be rebuilt")
    return fields


def with_material_field(material: Material, field: str, value: Any) -> Material:
    """``material`` rebuilt with ``field`` set to ``value`` (SI or a string with a unit)."""
    fields = material_fields(material)
    _material_field(material, field, f"material.{field}")
    if isinstance(value, str) or field in FIELD_DIMENSIONS:
        value = to_si(value, FIELD_DIMENSIONS.get(field, "dimensionless"), f"material.{field}")
    try:
        return type(material)(**(fields | {field: value}))
    except MaterialError as error:
        raise SceneError(f"material.{field}: {error}") from None


def field_value(scene: Scene, path: str) -> Any:
    """The value (SI) of the field at ``path`` in ``scene``."""
    head, *rest = path.split(".")
    if head == "t_end" and not rest:
        return scene.t_end
    if head == "layer" and len(rest) in (2, 3):
        layer = scene.layers[_index(scene, rest[0], path)]
        if len(rest) == 2:
            return getattr(layer, _layer_field(rest[1], path))
        return _material_field(layer.material, rest[2], path)
    if head == "material" and len(rest) == 2:
        layer = next((lay for lay in scene.layers if lay.material.name == rest[0]), None)
        if layer is None:
            raise SceneError(f"{path}: no layer is made of {rest[0]!r}")
        return _material_field(layer.material, rest[1], path)
    if head in ("left", "right") and rest == ["value"]:
        return getattr(scene, head).value_at(0.0)
    if head == "accuracy" and len(rest) == 1:
        return getattr(scene.accuracy, _accuracy_field(scene, rest[0], path))
    raise SceneError(f"{path}: not a scene field (see fronttrack.parameters for the paths)")


def _material_field(material: Material, name: str, path: str) -> Any:
    """The field ``name`` of ``material`` (SI); raises ``SceneError`` naming ``path``."""
    fields = material_fields(material)
    if name not in fields or name == "name":
        raise SceneError(f"{path}: not a field of {material.name!r} (fields: "
                         f"{', '.join(f for f in fields if f != 'name')})")
    return fields[name]


def _accuracy_field(scene: Scene, name: str, path: str) -> str:
    """``name`` if it is a field of ``Accuracy``; raises ``SceneError`` naming ``path``."""
    names = [f.name for f in dataclasses.fields(scene.accuracy)]
    if name not in names:
        raise SceneError(f"{path}: not a field of accuracy (fields: {', '.join(names)})")
    return name


def with_field(scene: Scene, path: str, value: Any) -> Scene:
    """``scene`` with the field at ``path`` set to ``value``; errors name ``path``."""
    head, *rest = path.split(".")
    if head == "t_end" and not rest:
        with located("t_end", path):
            return dataclasses.replace(scene, t_end=value)
    if head == "layer" and len(rest) in (2, 3):
        index = _index(scene, rest[0], path)
        layer = scene.layers[index]
        if len(rest) == 2:
            with located("layer", f"layer.{rest[0]}"):
                changed = dataclasses.replace(layer, **{_layer_field(rest[1], path): value})
        else:
            with located("material", f"layer.{rest[0]}.material"):
                changed = dataclasses.replace(
                    layer, material=with_material_field(layer.material, rest[2], value))
        layers = list(scene.layers)
        layers[index] = changed
        return dataclasses.replace(scene, layers=tuple(layers))
    if head == "material" and len(rest) == 2:
        field_value(scene, path)  # the material must be in the scene
        rebuilt = {}
        layers = []
        for layer in scene.layers:
            if layer.material.name == rest[0]:
                if id(layer.material) not in rebuilt:
                    with located("material", f"material.{rest[0]}"):
                        rebuilt[id(layer.material)] = with_material_field(
                            layer.material, rest[1], value)
                layer = dataclasses.replace(layer, material=rebuilt[id(layer.material)])
            layers.append(layer)
        return dataclasses.replace(scene, layers=tuple(layers))
    if head in ("left", "right") and rest == ["value"]:
        with located("boundary", head):
            return dataclasses.replace(scene, **{head: Boundary(getattr(scene, head).kind,
                                                                value)})
    if head == "accuracy" and len(rest) == 1:
        name = _accuracy_field(scene, rest[0], path)
        with located("accuracy", "accuracy"):
            return dataclasses.replace(
                scene, accuracy=dataclasses.replace(scene.accuracy, **{name: value}))
    raise SceneError(f"{path}: not a scene field (see fronttrack.parameters for the paths)")


_LAYER_FIELDS = ("thickness", "velocity", "stress", "bond", "material", "name")


def _layer_field(name: str, path: str) -> str:
    if name not in _LAYER_FIELDS:
        raise SceneError(f"{path}: a layer's fields are {', '.join(_LAYER_FIELDS)} (and "
                         f"material.FIELD)")
    return name


def _index(scene: Scene, text: str, path: str) -> int:
    try:
        index = int(text)
        scene.layers[index]
    except (ValueError, IndexError):
        raise SceneError(f"{path}: no layer {text!r} (the scene has {len(scene.layers)}: "
                         f"0 to {len(scene.layers) - 1})") from None
    return index


# --- sending a scene to another process --------------------------------------------------
class _ScenePickler(pickle.Pickler):
    """Pickles materials as their model and fields (they hold caches that do not pickle)."""

    def reducer_override(self, obj):
        if isinstance(obj, Material):
            return _rebuilt_material, (type(obj), material_fields(obj))
        return NotImplemented


def _rebuilt_material(cls: type, fields: dict[str, Any]) -> Material:
    return cls(**fields)


def portable(scene: Scene) -> bytes:
    """``scene`` as bytes any worker process can load with ``restored``."""
    buffer = io.BytesIO()
    _ScenePickler(buffer, protocol=pickle.HIGHEST_PROTOCOL).dump(scene)
    return buffer.getvalue()


def restored(data: bytes) -> Scene:
    """The scene ``portable`` made bytes of."""
    return pickle.loads(data)


__all__ = ["field_value", "material_fields", "portable", "restored", "with_field",
           "with_material_field"]
