"""Scenes read from TOML files.

Every dimensional number is a string with its unit (``fronttrack.units``), so a
file reads as a lab notebook and converts to the SI ``Scene`` of
``fronttrack.scene``.  Shape of a file (all tables but ``[[layer]]`` optional)::

    title = "Cu on Al"
    t_end = "3 us"
    [accuracy]              # stress_tolerance, velocity_tolerance (records),
                            # rays_per_fan or characteristic_step (overrides),
                            # negligible_stress, release, entropy_contacts,
                            # max_events, spall_spacing, contact_resolution,
                            # estimate_error
    [materials.MyPMMA]      # inline material: model and its fields with units
    model = "mie-gruneisen"
    rho0 = "1186 kg/m3"
    ...
    [[layer]]               # left to right: material, thickness, velocity,
    material = "Cu"         # stress (compression positive), name, bond; a gas
                            # layer: pressure (or temperature, with cv), density
    thickness = "1 mm"
    [left]                  # kind = free | wall | velocity | stress, with a
    kind = "free"           # constant value or a history [[t, value], ...];
                            # a velocity (a piston) may be bond = "bonded" (pulls)
    [[probe]]
    name = "rear"
    at = "right"            # "left", "right" or a Lagrangian position
    [spall]                 # optional cumulative-damage spall (fronttrack.damage):
    criterion = "tuler-butcher"  # threshold, exponent, damage = "0.05 GPa^2 us"
                            # or "incubation": threshold, incubation_time = "0.1 us"

A layer's material is a ``[materials.NAME]`` table of the same file (these
shadow library names) or a library name (``materials.library``).  Unknown keys,
values of the wrong type and bad values raise ``SceneError`` naming the key
path (``layer[1].thickness``) and, for keys, the allowed ones.
"""

from __future__ import annotations

import difflib
import tomllib
from pathlib import Path
from typing import Any

from materials import IdealGas, Material, MaterialError, State, StateOutOfRangeError
from materials.library import FIELD_DIMENSIONS, get, material_from_spec

from .scene import (
    BOUNDARY_KINDS,
    Accuracy,
    Boundary,
    Layer,
    Probe,
    Scene,
    SceneError,
    SpallCriterion,
    located,
)
from .units import parse_quantity

_TOP_KEYS = ("title", "t_end", "accuracy", "materials", "layer", "left", "right", "probe",
             "spall")
_LAYER_KEYS = ("material", "thickness", "velocity", "stress", "name", "bond", "pressure",
               "density", "temperature")
_GAS_KEYS = ("pressure", "density", "temperature")
"""Keys that give a gas layer its state (a gas is given a state, not loaded into one)."""
_BOUNDARY_KEYS = ("kind", "value", "history", "bond")
_PROBE_KEYS = ("name", "at", "kind", "side", "window")
_ACCURACY_KEYS = ("rays_per_fan", "stress_tolerance", "velocity_tolerance",
                  "characteristic_step", "negligible_stress", "release",
                  "entropy_contacts", "max_events", "spall_spacing", "contact_resolution",
                  "estimate_error")
_SPALL_KEYS = ("criterion", "threshold", "exponent", "damage", "incubation_time", "stations")
_SPALL_CRITERIA = ("tuler-butcher", "incubation")
_BOUNDARY_DIMENSION = {"velocity": "velocity", "stress": "stress"}


def load_scene(path: str | Path) -> Scene:
    """Read and validate the scene in the TOML file ``path``; its stem is the default title."""
    path = Path(path)
    try:
        with path.open("rb") as stream:
            doc = tomllib.load(stream)
    except OSError as exc:
        raise SceneError(f"{path}: cannot read the scene file ({exc.strerror})") from exc
    except tomllib.TOMLDecodeError as exc:
        raise SceneError(f"{path}: not valid TOML: {exc}") from exc
    return scene_from_dict(doc, path.stem)


def scene_from_dict(doc: dict[str, Any], base_name: str = "") -> Scene:
    """The validated ``Scene`` described by a parsed TOML document ``doc``.

    ``base_name`` (usually the file's stem) becomes the title when ``doc`` has none.
    """
    _check_keys(_table(doc, ""), _TOP_KEYS, "")
    if "t_end" not in doc:
        raise SceneError('t_end: missing (the time to follow the scene to, e.g. "3 us")')
    materials = _inline_materials(_table(doc.get("materials", {}), "materials"))
    layer_tables = _array_of_tables(doc, "layer", required=True)
    layers = tuple(_layer(table, i, materials) for i, table in enumerate(layer_tables))
    probes = tuple(_probe(table, i) for i, table in enumerate(_array_of_tables(doc, "probe")))
    return Scene(
        layers=layers,
        t_end=parse_quantity(doc["t_end"], "time", "t_end"),
        left=_boundary(doc.get("left", {}), "left"),
        right=_boundary(doc.get("right", {}), "right"),
        probes=probes,
        accuracy=_accuracy(_table(doc.get("accuracy", {}), "accuracy")),
        title=_string(doc, "title", "title", base_name),
        spall_criterion=_spall(_table(doc["spall"], "spall")) if "spall" in doc else None,
    )


# --- structure -----------------------------------------------------------------------------
def _table(value: Any, path: str) -> dict[str, Any]:
    if not isinstance(value, dict):
        raise SceneError(f"{path or 'document'}: expected a table, got {value!r}")
    return value


def _check_keys(table: dict[str, Any], allowed: tuple[str, ...], path: str) -> None:
    """Raise ``SceneError`` naming the first key of ``table`` not in ``allowed``."""
    for key in table:
        if key not in allowed:
            close = difflib.get_close_matches(key, allowed, n=1)
            hint = f"; did you mean {close[0]!r}?" if close else ""
            where = f"{path}.{key}" if path else key
            raise SceneError(f"{where}: unknown key (allowed keys: {', '.join(allowed)}){hint}")


def _array_of_tables(doc: dict[str, Any], key: str, required: bool = False) -> list[dict]:
    """The ``[[key]]`` tables of ``doc`` (an empty list if absent and not required)."""
    if key not in doc and required:
        raise SceneError(f"{key}: missing (give at least one [[{key}]] table)")
    tables = doc.get(key, [])
    if not isinstance(tables, list) or not all(isinstance(t, dict) for t in tables):
        raise SceneError(f"{key}: expected an array of tables written [[{key}]], got {tables!r}")
    return tables


def _string(table: dict[str, Any], key: str, path: str, default: str | None = None) -> str:
    """The string ``table[key]``; ``default`` when absent (``None``: the key is required)."""
    if key not in table:
        if default is None:
            raise SceneError(f"{path}: missing")
        return default
    value = table[key]
    if not isinstance(value, str):
        raise SceneError(f"{path}: expected a string, got {value!r}")
    return value


def _optional_quantity(table: dict[str, Any], key: str, dimension: str, path: str,
                       default: float | None) -> float | None:
    """``table[key]`` converted to SI (``default`` when absent)."""
    return parse_quantity(table[key], dimension, path) if key in table else default


def _material_error(path: str, name: str, exc: MaterialError) -> SceneError:
    """``exc`` restated as a ``SceneError`` about ``path`` (dropping the ``name:`` prefix)."""
    message = str(exc)
    if message.startswith(f"{name}: "):
        message = message[len(name) + 2:]
    return SceneError(f"{path}: {message}")


# --- sections ------------------------------------------------------------------------------
def _inline_materials(tables: dict[str, Any]) -> dict[str, Material]:
    """Materials of the ``[materials.NAME]`` tables; quantities converted to SI first."""
    built = {}
    for name, table in tables.items():
        path = f"materials.{name}"
        spec = {}
        for key, value in _table(table, path).items():
            dimension = FIELD_DIMENSIONS.get(key)
            spec[key] = value if dimension is None else parse_quantity(
                value, dimension, f"{path}.{key}")
        try:
            built[name] = material_from_spec(name, spec)
        except MaterialError as exc:
            raise _material_error(path, name, exc) from exc
    return built


def _layer(table: dict[str, Any], index: int, inline: dict[str, Material]) -> Layer:
    path = f"layer[{index}]"
    _check_keys(_table(table, path), _LAYER_KEYS, path)
    name = _string(table, "material", f"{path}.material")
    if name in inline:
        material = inline[name]
    else:
        try:
            material = get(name)
        except MaterialError as exc:
            extra = f" (materials defined in this file: {', '.join(inline)})" if inline else ""
            raise SceneError(f"{path}.material: {exc}{extra}") from exc
    bond = _string(table, "bond", f"{path}.bond", "bonded")
    if index == 0 and "bond" in table:
        raise SceneError(f"{path}.bond: the first layer has no previous layer to bond to")
    velocity = _optional_quantity(table, "velocity", "velocity", f"{path}.velocity", 0.0)
    stress = _optional_quantity(table, "stress", "stress", f"{path}.stress", 0.0)
    return _built(
        path, "layer", Layer,
        material=material,
        thickness=parse_quantity(_required(table, "thickness", path), "length",
                                 f"{path}.thickness"),
        velocity=velocity,
        stress=stress,
        bond=bond,
        name=_string(table, "name", f"{path}.name", ""),
        initial=_gas_state(table, path, material, stress, velocity),
    )


def _gas_state(table: dict[str, Any], path: str, material: Material, stress: float,
               velocity: float) -> State | None:
    """A gas layer's initial state from ``pressure`` (or ``stress``), ``density`` (default
    the material's ``rho0``) and ``temperature`` (with the gas's cv): ``None`` when
    the layer gives none of them (the layer's stress then sets its pressure)."""
    given = [key for key in _GAS_KEYS if key in table]
    if not given:
        return None
    if not isinstance(material, IdealGas):
        raise SceneError(f"{path}.{given[0]}: only gas layers take "
                         f"{', '.join(_GAS_KEYS)}; {material.name} is a solid (use stress)")
    if "pressure" in table and "stress" in table:
        raise SceneError(f"{path}.pressure: give the gas's pressure or its stress, not both")
    density = _optional_quantity(table, "density", "density", f"{path}.density",
                                 material.rho0)
    pressure = _optional_quantity(table, "pressure", "stress", f"{path}.pressure", stress)
    try:
        if "temperature" in table:
            if "pressure" in table or "stress" in table:
                raise SceneError(f"{path}.temperature: give the gas's pressure or its "
                                 "temperature, not both")
            temperature = parse_quantity(table["temperature"], "temperature",
                                         f"{path}.temperature")
            pressure = material.pressure_at(density, temperature)
        return material.initial_state(pressure, velocity, density)
    except (MaterialError, StateOutOfRangeError) as error:
        raise SceneError(f"{path}: {error}") from None


def _required(table: dict[str, Any], key: str, path: str) -> Any:
    if key not in table:
        raise SceneError(f"{path}.{key}: missing")
    return table[key]


def _boundary(table: Any, side: str) -> Boundary:
    """``[left]``/``[right]``: ``kind`` (default free) and, for velocity/stress, the values."""
    _check_keys(_table(table, side), _BOUNDARY_KEYS, side)
    kind = _string(table, "kind", f"{side}.kind", "free")
    if kind not in BOUNDARY_KINDS:
        raise SceneError(f"{side}.kind: must be one of {', '.join(BOUNDARY_KINDS)}, "
                         f"got {kind!r}")
    given = [key for key in ("value", "history") if key in table]
    if kind not in _BOUNDARY_DIMENSION:
        if given:
            raise SceneError(f"{side}.{given[0]}: a {kind} boundary takes no {given[0]}")
        return _built(side, "boundary", Boundary, kind)
    bond = _string(table, "bond", f"{side}.bond", "unbonded")
    if "bond" in table and kind != "velocity":
        raise SceneError(f"{side}.bond: only a velocity boundary (a piston) takes a bond")
    if len(given) != 1:
        raise SceneError(f"{side}: a {kind} boundary needs exactly one of value or history")
    dimension = _BOUNDARY_DIMENSION[kind]
    if "value" in table:
        return _built(side, "boundary", Boundary, kind,
                      ((0.0, parse_quantity(table["value"], dimension, f"{side}.value")),),
                      bond)
    points = table["history"]
    if not isinstance(points, list) or not points:
        raise SceneError(f'{side}.history: expected a list of [time, value] pairs such as '
                         f'[["0 us", "0 m/s"], ["1 us", "100 m/s"]], got {points!r}')
    history = []
    for i, point in enumerate(points):
        where = f"{side}.history[{i}]"
        if not isinstance(point, list) or len(point) != 2:
            raise SceneError(f"{where}: expected a [time, value] pair, got {point!r}")
        history.append((parse_quantity(point[0], "time", f"{where} time"),
                        parse_quantity(point[1], dimension, f"{where} value")))
    return _built(side, "boundary", Boundary, kind, tuple(history), bond)


def _built(path: str, prefix: str, cls: type, *args: Any, **kwargs: Any) -> Any:
    """``cls(*args, **kwargs)``, its errors about ``prefix.*`` restated about ``path.*``."""
    with located(prefix, path):
        return cls(*args, **kwargs)


def _probe(table: dict[str, Any], index: int) -> Probe:
    path = f"probe[{index}]"
    _check_keys(table, _PROBE_KEYS, path)
    at = _required(table, "at", path)
    if at not in ("left", "right"):
        at = parse_quantity(at, "length", f"{path}.at")
    return _built(path, "probe", Probe, name=_string(table, "name", f"{path}.name"), at=at,
                  kind=_string(table, "kind", f"{path}.kind", "point"),
                  side=table.get("side"), window=table.get("window"))


def _accuracy(table: dict[str, Any]) -> Accuracy:
    _check_keys(table, _ACCURACY_KEYS, "accuracy")
    defaults = Accuracy()
    rays = table.get("rays_per_fan")
    return Accuracy(
        rays_per_fan=None if rays is None else _typed(table, "rays_per_fan", int, None),
        stress_tolerance=_optional_quantity(table, "stress_tolerance", "stress",
                                            "accuracy.stress_tolerance", None),
        velocity_tolerance=_optional_quantity(table, "velocity_tolerance", "velocity",
                                              "accuracy.velocity_tolerance", None),
        characteristic_step=_optional_quantity(table, "characteristic_step", "stress",
                                               "accuracy.characteristic_step", None),
        negligible_stress=_optional_quantity(table, "negligible_stress", "stress",
                                             "accuracy.negligible_stress", None),
        release=_typed(table, "release", str, defaults.release),
        entropy_contacts=_typed(table, "entropy_contacts", bool, defaults.entropy_contacts),
        max_events=_typed(table, "max_events", int, defaults.max_events),
        spall_spacing=_optional_quantity(table, "spall_spacing", "length",
                                         "accuracy.spall_spacing", None),
        contact_resolution=_optional_quantity(table, "contact_resolution", "length",
                                              "accuracy.contact_resolution",
                                              defaults.contact_resolution),
        estimate_error=_typed(table, "estimate_error", bool, defaults.estimate_error),
    )


def _typed(table: dict[str, Any], key: str, kind: type, default: Any,
           path: str = "accuracy") -> Any:
    """``path.key`` checked to be of TOML type ``kind`` (a bool is not an int here)."""
    value = table.get(key, default)
    if not isinstance(value, kind) or (kind is int and isinstance(value, bool)):
        expected = getattr(kind, "__name__", "number")
        raise SceneError(f"{path}.{key}: expected {expected}, got {value!r}")
    return value


def _spall(table: dict[str, Any]) -> SpallCriterion:
    """The ``[spall]`` table: a Tuler–Butcher or incubation-time criterion."""
    _check_keys(table, _SPALL_KEYS, "spall")
    criterion = _required(table, "criterion", "spall")
    if criterion not in _SPALL_CRITERIA:
        raise SceneError(f"spall.criterion: must be one of {_SPALL_CRITERIA}, "
                         f"got {criterion!r}")
    threshold = parse_quantity(_required(table, "threshold", "spall"), "stress",
                               "spall.threshold")
    stations = _typed(table, "stations", int, SpallCriterion.stations, "spall")
    if criterion == "incubation":
        time = parse_quantity(_required(table, "incubation_time", "spall"), "time",
                              "spall.incubation_time")
        return SpallCriterion.incubation(threshold, time, stations)
    exponent = _typed(table, "exponent", (int, float), SpallCriterion.exponent, "spall")
    damage = _damage_integral(_required(table, "damage", "spall"), float(exponent))
    return SpallCriterion(threshold=threshold, damage=damage, exponent=float(exponent),
                          stations=stations)


def _damage_integral(text: Any, exponent: float) -> float:
    """A Tuler–Butcher constant such as ``"0.05 GPa^2 us"`` in SI (Pa^exponent s)."""
    parts = text.split() if isinstance(text, str) else []
    stress_unit, _, power = parts[1].partition("^") if len(parts) == 3 else ("", "", "")
    try:
        value, power = float(parts[0]), float(power)
    except (ValueError, IndexError):
        value = power = None
    if value is None or power != exponent:
        raise SceneError(f"spall.damage: expected a number, a stress unit to the power "
                         f"spall.exponent ({exponent:g}) and a time unit, for example "
                         f'"0.05 GPa^{exponent:g} us"; got {text!r}')
    stress = parse_quantity(f"1 {stress_unit}", "stress", "spall.damage stress unit")
    time = parse_quantity(f"1 {parts[2]}", "time", "spall.damage time unit")
    return value * stress**exponent * time
