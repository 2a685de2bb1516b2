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
                            # coalesce_length, estimate_error
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

A file is refused before it can exhaust the machine: it is read up to
``MAX_FILE_BYTES`` (so ``/dev/zero`` is not read for ever), decoded as UTF-8 (a
byte-order mark is skipped), and the counts that set the work of a run are capped
(``LIMITS``; the bound on ``t_end`` is ``MAX_TRANSITS`` sound transits of the stack).
A run that is still too long for its user is stopped by ``accuracy.max_seconds``.
"""

from __future__ import annotations

import difflib
import math
import re
import reprlib
import tomllib
from pathlib import Path
from typing import Any

from materials import (
    IdealGas,
    Material,
    MaterialError,
    State,
    StateOutOfRangeError,
    WavediagramError,
)
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
               "density", "temperature", "initiate")
_GAS_KEYS = ("pressure", "density", "temperature")
"""Keys that give a gas layer its state (a gas is given a state, not loaded into one)."""
_BOUNDARY_KEYS = ("kind", "value", "history", "bond")
_PROBE_KEYS = ("name", "at", "kind", "side", "window")
_ACCURACY_KEYS = ("rays_per_fan", "stress_tolerance", "velocity_tolerance",
                  "characteristic_step", "negligible_stress", "release",
                  "entropy_contacts", "max_events", "spall_spacing", "contact_resolution",
                  "coalesce_length", "estimate_error", "max_seconds")
_SPALL_KEYS = ("criterion", "threshold", "exponent", "damage", "incubation_time", "stations")
_SPALL_CRITERIA = ("tuler-butcher", "incubation")
_BOUNDARY_DIMENSION = {"velocity": "velocity", "stress": "stress"}

MAX_FILE_BYTES = 1 << 20
"""A scene file is at most 1 MiB (a 10 000-point history takes about 400 kB)."""

LIMITS = {
    "layer": 1000,
    "probe": 100,
    "history": 10_000,
    "rays_per_fan": 1000,
    "max_events": 2_000_000,
    "spall.stations": 10_000,
}
"""The largest count of each entry a scene file may give: layers, probes, points of one
boundary history, characteristics per fan, events, damage stations per layer.  Each is
far beyond what a diagram can show; a run with them all at the limit would still be
stopped by the event limit or by ``accuracy.max_seconds``."""

MAX_TRANSITS = 1000
"""``t_end`` is at most this many sound transits of the stack (the sum over its layers
of thickness over reference sound speed): the waves have long spread into thousands
of characteristics by then."""

PROBE_NAME = re.compile(r"(?! )[A-Za-z0-9_.+ -]{1,64}(?<! )\Z")
"""A probe name becomes part of a file name (``probe_<name>.csv``): 1 to 64 letters,
digits, spaces or ``_ . + -``, not starting or ending with a space."""

_SHOWN = reprlib.Repr()
"""How a bad value is quoted in an error message: long strings, lists and deep nests cut."""
_SHOWN.maxlevel, _SHOWN.maxstring, _SHOWN.maxother, _SHOWN.maxlist = 3, 60, 60, 6


def load_scene(path: str | Path) -> Scene:
    """Read and validate the scene in the TOML file ``path``; its stem is the default title.

    Raises ``SceneError`` for a file that cannot be read, is larger than
    ``MAX_FILE_BYTES``, is not UTF-8, is not TOML (or nests deeper than it can be
    read), or describes an invalid scene.
    """
    path = Path(path)
    try:
        with path.open("rb") as stream:
            data = stream.read(MAX_FILE_BYTES + 1)
    except OSError as exc:
        raise SceneError(f"{path}: cannot read the scene file ({exc.strerror})") from exc
    if len(data) > MAX_FILE_BYTES:
        raise SceneError(f"{path}: larger than {MAX_FILE_BYTES // 1024} KiB, the most a "
                         f"scene file may have")
    try:
        text = data.decode("utf-8").removeprefix("\ufeff")
    except UnicodeDecodeError as exc:
        line = data.count(b"\n", 0, exc.start) + 1
        raise SceneError(f"{path}: not UTF-8 text (byte {data[exc.start]:#04x} on line "
                         f"{line}); save the scene as UTF-8") from None
    try:
        doc = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise SceneError(f"{path}: not valid TOML: {exc}") from exc
    except RecursionError:
        raise SceneError(f"{path}: arrays or tables nested too deep to read") from None
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
    scene = Scene(
        layers=layers,
        t_end=parse_quantity(doc["t_end"], "time", "t_end"),
        left=_boundary(doc.get("left", {}), "left"),
        right=_boundary(doc.get("right", {}), "right"),
        probes=probes,
        accuracy=_accuracy(_table(doc.get("accuracy", {}), "accuracy")),
        title=_string(doc, "title", "title", base_name),
        spall_criterion=_spall(_table(doc["spall"], "spall")) if "spall" in doc else None,
    )
    return _check_duration(scene)


def _check_duration(scene: Scene) -> Scene:
    """``scene`` if its ``t_end`` is at most ``MAX_TRANSITS`` sound transits of the stack.

    The transit time is the sum over the layers of thickness over the reference
    Lagrangian sound speed (s); a layer without a positive one (a gas at zero
    pressure) makes it unbounded.
    """
    transit = 0.0
    for layer in scene.layers:
        material = layer.material
        try:
            speed = material.sound_speed(material.v0, 0.0)
        except WavediagramError:
            return scene
        if not (math.isfinite(speed) and speed > 0.0):
            return scene
        transit += layer.thickness / speed
    if scene.t_end > MAX_TRANSITS * transit:
        raise SceneError(f"t_end: {scene.t_end * 1e6:.6g} us is more than {MAX_TRANSITS} "
                         f"sound transits of the stack (each {transit * 1e6:.4g} us); "
                         f"allowed up to {MAX_TRANSITS * transit * 1e6:.6g} us")
    return scene


def _at_most(count: int, key: str, path: str) -> None:
    """Raise ``SceneError`` if ``count`` entries of ``key`` exceed ``LIMITS[key]``."""
    if count > LIMITS[key]:
        raise SceneError(f"{path}: {count} is more than the {LIMITS[key]} a scene file may "
                         f"give")


# --- structure -----------------------------------------------------------------------------
def _table(value: Any, path: str) -> dict[str, Any]:
    if not isinstance(value, dict):
        raise SceneError(f"{path or 'document'}: expected a table, got {_SHOWN.repr(value)}")
    return value


def _check_keys(table: dict[str, Any], allowed: tuple[str, ...], path: str) -> None:
    """Raise ``SceneError`` naming the first key of ``table`` not in ``allowed``."""
    for key in table:
        if key not in allowed:
            close = difflib.get_close_matches(key, allowed, n=1)
            hint = f"; did you mean {close[0]!r}?" if close else ""
            shown = key if len(key) <= _SHOWN.maxstring else _SHOWN.repr(key)
            where = f"{path}.{shown}" if path else shown
            raise SceneError(f"{where}: unknown key (allowed keys: {', '.join(allowed)}){hint}")


def _array_of_tables(doc: dict[str, Any], key: str, required: bool = False) -> list[dict]:
    """The ``[[key]]`` tables of ``doc`` (an empty list if absent and not required)."""
    if key not in doc and required:
        raise SceneError(f"{key}: missing (give at least one [[{key}]] table)")
    tables = doc.get(key, [])
    if not isinstance(tables, list) or not all(isinstance(t, dict) for t in tables):
        raise SceneError(f"{key}: expected an array of tables written [[{key}]], "
                         f"got {_SHOWN.repr(tables)}")
    _at_most(len(tables), key, f"{key}: number of [[{key}]] tables")
    return tables


def _string(table: dict[str, Any], key: str, path: str, default: str | None = None) -> str:
    """The string ``table[key]``; ``default`` when absent (``None``: the key is required)."""
    if key not in table:
        if default is None:
            raise SceneError(f"{path}: missing")
        return default
    value = table[key]
    if not isinstance(value, str):
        raise SceneError(f"{path}: expected a string, got {_SHOWN.repr(value)}")
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
        initiate=table.get("initiate"),
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
                         f"got {_SHOWN.repr(kind)}")
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
                         f'[["0 us", "0 m/s"], ["1 us", "100 m/s"]], got {_SHOWN.repr(points)}')
    _at_most(len(points), "history", f"{side}.history: number of points")
    history = []
    for i, point in enumerate(points):
        where = f"{side}.history[{i}]"
        if not isinstance(point, list) or len(point) != 2:
            raise SceneError(f"{where}: expected a [time, value] pair, got {_SHOWN.repr(point)}")
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
    name = _string(table, "name", f"{path}.name")
    if not PROBE_NAME.match(name):
        raise SceneError(f"{path}.name: {_SHOWN.repr(name)} cannot be part of a file name "
                         f"(use 1 to 64 letters, digits, inner spaces or _ . + -)")
    return _built(path, "probe", Probe, name=name, at=at,
                  kind=_string(table, "kind", f"{path}.kind", "point"),
                  side=table.get("side"), window=table.get("window"))


def _accuracy(table: dict[str, Any]) -> Accuracy:
    _check_keys(table, _ACCURACY_KEYS, "accuracy")
    defaults = Accuracy()
    rays = table.get("rays_per_fan")
    rays = None if rays is None else _typed(table, "rays_per_fan", int, None)
    if rays is not None:
        _at_most(rays, "rays_per_fan", "accuracy.rays_per_fan")
    max_events = _typed(table, "max_events", int, defaults.max_events)
    _at_most(max_events, "max_events", "accuracy.max_events")
    return Accuracy(
        rays_per_fan=rays,
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
        max_events=max_events,
        spall_spacing=_optional_quantity(table, "spall_spacing", "length",
                                         "accuracy.spall_spacing", None),
        contact_resolution=_optional_quantity(table, "contact_resolution", "length",
                                              "accuracy.contact_resolution",
                                              defaults.contact_resolution),
        coalesce_length=_optional_quantity(table, "coalesce_length", "length",
                                           "accuracy.coalesce_length", None),
        estimate_error=_typed(table, "estimate_error", bool, defaults.estimate_error),
        max_seconds=_optional_quantity(table, "max_seconds", "time", "accuracy.max_seconds",
                                       defaults.max_seconds),
    )


def _typed(table: dict[str, Any], key: str, kind: type, default: Any,
           path: str = "accuracy") -> Any:
    """``path.key`` checked to be of TOML type ``kind`` (a bool is not an int here)."""
    value = table.get(key, default)
    if not isinstance(value, kind) or (kind is int and isinstance(value, bool)):
        expected = getattr(kind, "__name__", "number")
        raise SceneError(f"{path}.{key}: expected {expected}, got {_SHOWN.repr(value)}")
    return value


def _spall(table: dict[str, Any]) -> SpallCriterion:
    """The ``[spall]`` table: a Tuler–Butcher or incubation-time criterion."""
    _check_keys(table, _SPALL_KEYS, "spall")
    criterion = _required(table, "criterion", "spall")
    if criterion not in _SPALL_CRITERIA:
        raise SceneError(f"spall.criterion: must be one of {_SPALL_CRITERIA}, "
                         f"got {_SHOWN.repr(criterion)}")
    threshold = parse_quantity(_required(table, "threshold", "spall"), "stress",
                               "spall.threshold")
    stations = _typed(table, "stations", int, SpallCriterion.stations, "spall")
    _at_most(stations, "spall.stations", "spall.stations")
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
                         f'"0.05 GPa^{exponent:g} us"; got {_SHOWN.repr(text)}')
    stress = parse_quantity(f"1 {stress_unit}", "stress", "spall.damage stress unit")
    time = parse_quantity(f"1 {parts[2]}", "time", "spall.damage time unit")
    try:
        return value * stress**exponent * time
    except OverflowError:
        raise SceneError(f"spall.exponent: {exponent:g} makes spall.damage overflow a float "
                         f"in SI units (Pa^exponent s)") from None
