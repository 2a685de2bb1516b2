"""The material library, and materials built from plain specifications.

``materials/data/library.toml`` holds Mie–Grüneisen solids on linear Us–up fits
(SI values: ``rho0`` kg/m^3, ``c0`` m/s, ``s`` and ``gamma0`` dimensionless, ``cv``
J/(kg K), ``spall_strength`` Pa, ``up_max`` m/s) with a description, aliases and
the source of each number; ``materials/data/porous.toml`` holds porous solids (their
matrix's fit, distension and crush curve) and ``phase_change.toml`` solids with a
polymorphic transition, read after it.  ``get(name)`` builds the
material of an entry (a name is its table key, or any alias, matched without regard to case), and
``material_from_spec`` builds any model from a dict of SI floats: this is the
one place where specification fields are mapped to constructor arguments, for
library entries and for materials defined inline in scene files alike.

Models and fields (``MODELS``):

- ``"mie-gruneisen"``: ``rho0``, ``c0``, ``s``, ``gamma0``; optional ``cv``,
  ``spall_strength``, ``up_max``.
- ``"linear-elastic"``: ``rho0`` and one of: ``C`` (longitudinal speed, m/s);
  ``lambda`` and ``mu`` (Lamé constants, Pa); ``E`` (Young's modulus, Pa) and
  ``poisson``, converted to ``lambda = E nu / ((1 + nu)(1 - 2 nu))`` and
  ``mu = E / (2 (1 + nu))``.  Optional ``spall_strength``.
- ``"ideal-gas"``: ``gamma``, ``rho0``; optional ``cv``.
- ``"elastic-plastic"``: ``rho0``, ``yield_strength`` (Pa, the yield stress Y in
  simple tension) and exactly one pair of elastic constants: ``lambda`` and ``mu``
  (Lamé constants, Pa), ``shear_modulus`` and ``poisson``, or ``E`` and
  ``poisson`` (converted to Lamé constants); optional ``spall_strength``.  The
  small-strain ideal elastic–plastic solid of ``materials.elastic_plastic``.
- ``"finite-plastic"``: ``rho0``, ``c0``, ``s``, ``gamma0`` (the Mie–Grüneisen
  pressure), ``yield_strength`` (Pa) and exactly one of ``shear_modulus`` (Pa) or
  ``poisson`` (with ``K = rho0 c0^2``); optional ``hardening`` (Pa, linear:
  ``Y = Y0 + H eps_bar``) and ``spall_strength``.  The finite-deformation
  elastic–plastic solid of ``materials.finite_plastic``.

- ``"porous"``: the p–α porous solid of ``materials.porous`` on a Mie–Grüneisen
  matrix: ``solid_rho0`` (the matrix density, kg/m^3), ``c0``, ``s``, ``gamma0`` (the
  matrix's fit) and ``alpha0`` (distension, >= 1; the body's density is
  ``solid_rho0 / alpha0``); optional ``crush_stress`` (Pa, default 0), then
  ``compaction_stress`` (Pa) with ``crush_exponent`` (power-law crush curve) or
  ``crush_scale`` (Pa, exponential), and ``spall_strength``.  Without a crush curve
  every compression compacts fully (the strong-shock model of Davison §11.2).

- ``"saturating-plastic"``: the elastic–plastic solid with saturating (Voce) hardening
  of ``materials.saturating_plastic``, whose waves come from the hull construction:
  ``rho0``, ``c0``, ``s`` (a ``Gamma0 = 0`` pressure), ``shear_modulus``,
  ``yield_strength``, ``saturation_strength`` (Pa) and ``saturation_strain``; optional
  ``spall_strength``.
- ``"explosive-jwl"`` and ``"explosive-gamma"``: an explosive of ``materials.explosive``:
  the unreacted Mie–Grüneisen solid (``rho0``, ``c0``, ``s``, ``gamma0``) and its
  detonation products, JWL (``A``, ``B`` in Pa, ``R1``, ``R2``, ``omega``, ``E0`` the
  detonation energy per unit initial volume in Pa) or gamma law (``gamma``, ``q`` the heat
  of detonation in J/kg); optional ``D_cj``, ``p_cj`` (tabulated, for reports).
  ``materials/data/explosives.toml`` holds the library's explosives.

- ``"viscoplastic"``: the elastic–viscoplastic solid of ``materials.viscoplastic`` (an
  overstress law; solved on its characteristic grid, not by the engine): ``rho0``,
  ``yield_strength`` (Pa), ``relaxation_time`` (s, >= 0) and one pair of elastic
  constants as for ``"elastic-plastic"``; optional ``rate_exponent`` (>= 1, default 1)
  and ``hugoniot_slope`` (the Us–up slope of the convex equilibrium pressure, default 0).

- ``"phase-change"``: the two-phase solid of ``materials.phase_change``: ``rho0``,
  ``c1``, ``s1`` (low-pressure phase), ``c2``, ``s2`` (high-pressure phase),
  ``transition_stress`` (Pa) and ``transition_strain``; optional ``spall_strength``.

A solid without ``spall_strength`` never spalls (``math.inf``).  ``description``
and ``source`` (strings) may accompany any specification and are not used.

Strength from the library: an entry with ``shear_modulus`` and ``yield_strength``
(or ``hel``, the Hugoniot elastic limit, from which ``Y = hel 2G / (K + 4G/3)``
with ``K = rho0 c0^2``) can be built as an elastic–plastic solid (``lambda = K -
2G/3``, ``mu = G``) or a finite-plastic one (its Mie–Grüneisen pressure plus
strength): ``get(name, model="elastic-plastic")``, or, in a specification,
``library = "NAME"``, which takes every field the specification does not give
from that entry (``strength_spec``).

Names: a library key, or any of its aliases, without regard to case.  The
element's symbol and name resolve to the same entry ("Al", "aluminum" and
"aluminium" are Al 6061-T6; "Cu" and "copper" OFHC copper).  An unknown name is
answered with the entries whose name or alias begins like it or is close to it.
"""

from __future__ import annotations

import difflib
import functools
import math
import tomllib
from importlib import resources
from typing import Any

from .base import Material, require_positive
from .elastic_plastic import ElasticPlastic
from .errors import MaterialError
from .explosive import Explosive
from .finite_plastic import FinitePlastic
from .ideal_gas import IdealGas
from .linear_elastic import LinearElastic
from .mie_gruneisen import ExpandedMieGruneisen, MieGruneisen
from .phase_change import PhaseChangeSolid
from .porous import PorousSolid
from .products import Products
from .saturating_plastic import SaturatingPlastic
from .viscoplastic import Viscoplastic

MODELS: dict[str, dict[str, tuple[str, ...]]] = {
    "mie-gruneisen": {"required": ("rho0", "c0", "s", "gamma0"),
                      "optional": ("cv", "spall_strength", "up_max")},
    "linear-elastic": {"required": ("rho0",),
                       "optional": ("C", "lambda", "mu", "E", "poisson", "spall_strength")},
    "ideal-gas": {"required": ("gamma", "rho0"), "optional": ("cv",)},
    "elastic-plastic": {"required": ("rho0", "yield_strength"),
                        "optional": ("lambda", "mu", "shear_modulus", "E", "poisson",
                                     "spall_strength")},
    "finite-plastic": {"required": ("rho0", "c0", "s", "gamma0", "yield_strength"),
                       "optional": ("shear_modulus", "poisson", "hardening",
                                    "spall_strength")},
    "saturating-plastic": {"required": ("rho0", "c0", "s", "shear_modulus", "yield_strength",
                                        "saturation_strength", "saturation_strain"),
                           "optional": ("spall_strength",)},
    "viscoplastic": {"required": ("rho0", "yield_strength", "relaxation_time"),
                     "optional": ("lambda", "mu", "shear_modulus", "E", "poisson",
                                  "rate_exponent", "hugoniot_slope")},
    "phase-change": {"required": ("rho0", "c1", "s1", "c2", "s2", "transition_stress",
                                  "transition_strain"),
                     "optional": ("spall_strength",)},
    "explosive-jwl": {"required": ("rho0", "c0", "s", "gamma0", "A", "B", "R1", "R2",
                                   "omega", "E0"),
                      "optional": ("D_cj", "p_cj")},
    "explosive-gamma": {"required": ("rho0", "c0", "s", "gamma0", "gamma", "q"),
                        "optional": ("D_cj", "p_cj")},
    "porous": {"required": ("solid_rho0", "c0", "s", "gamma0", "alpha0"),
               "optional": ("crush_stress", "compaction_stress", "crush_exponent",
                            "crush_scale", "spall_strength")},
}
"""Numeric fields of each model (a linear-elastic solid also needs one of its
stiffness choices, see ``_LINEAR_ELASTIC_CHOICES``)."""

_LINEAR_ELASTIC_CHOICES = (("C",), ("lambda", "mu"), ("E", "poisson"))
_ELASTIC_PLASTIC_CHOICES = (("lambda", "mu"), ("shear_modulus", "poisson"), ("E", "poisson"))

STRENGTH_MODELS = ("elastic-plastic", "finite-plastic")
"""Models a library entry with strength data can be built as (``get(name, model)``)."""

FIELD_DIMENSIONS: dict[str, str] = {
    "rho0": "density", "c0": "velocity", "s": "dimensionless", "gamma0": "dimensionless",
    "cv": "specific_heat", "spall_strength": "stress", "up_max": "velocity",
    "C": "velocity", "lambda": "stress", "mu": "stress", "E": "stress",
    "poisson": "dimensionless", "gamma": "dimensionless", "yield_strength": "stress",
    "shear_modulus": "stress", "hardening": "stress", "hel": "stress", "solid_rho0": "density",
    "alpha0": "dimensionless", "crush_stress": "stress", "compaction_stress": "stress",
    "crush_exponent": "dimensionless", "crush_scale": "stress", "c1": "velocity",
    "s1": "dimensionless", "c2": "velocity", "s2": "dimensionless",
    "transition_stress": "stress", "transition_strain": "dimensionless",
    "saturation_strength": "stress", "saturation_strain": "dimensionless",
    "A": "stress", "B": "stress", "R1": "dimensionless", "R2": "dimensionless",
    "omega": "dimensionless", "E0": "stress", "q": "specific_energy", "D_cj": "velocity",
    "p_cj": "stress", "relaxation_time": "time", "rate_exponent": "dimensionless",
    "hugoniot_slope": "dimensionless",
}
"""Physical dimension of every numeric specification field, for readers of files
that write quantities with units (the dimension names of ``fronttrack.units``)."""

TEXT_FIELDS = ("description", "source")
"""Descriptive string fields any specification may carry."""

_LIBRARY_ONLY_FIELDS = ("aliases", "shear_modulus", "yield_strength", "hel", "caution")
"""Fields of a library entry that its own (Mie–Grüneisen) model does not take."""

LIBRARY_FIELD = "library"
"""Specification field naming a library entry that supplies the fields not given."""


# --- the library file ----------------------------------------------------------------
DATA_FILES = ("library.toml", "porous.toml", "phase_change.toml", "explosives.toml")
"""The library's data files, read in this order."""


@functools.cache
def _library() -> dict[str, dict[str, Any]]:
    """The parsed library files, ``{name: entry}`` in file order (read once); a name in
    two files is a data error."""
    merged: dict[str, dict[str, Any]] = {}
    for file in DATA_FILES:
        text = resources.files(__package__).joinpath(f"data/{file}").read_text("utf-8")
        for key, data in tomllib.loads(text).items():
            if key in merged:
                raise MaterialError(f"{file}: {key!r} is already a library entry")
            merged[key] = data
    return merged


@functools.cache
def _lookup() -> dict[str, str]:
    """Case-folded names and aliases -> library key; a name used twice is a data error."""
    index: dict[str, str] = {}
    for key, data in _library().items():
        for label in (key, *data.get("aliases", ())):
            folded = label.casefold()
            if index.get(folded, key) != key:
                raise MaterialError(f"library.toml: {label!r} names both {index[folded]!r} "
                                    f"and {key!r}")
            index[folded] = key
    return index


def available(model: str | None = None) -> list[str]:
    """Names (table keys) of the library materials, in the files' order; only those of
    ``model`` (a key of ``MODELS``) when it is given."""
    return [key for key, data in _library().items()
            if model is None or data.get("model") == model]


def _resolve(name: str) -> str:
    """Library key of ``name`` (a key or an alias, any case); ``MaterialError`` if unknown."""
    if not isinstance(name, str):
        raise MaterialError(f"a material name must be a string, got {name!r}")
    if name in _library():
        return name
    key = _lookup().get(name.casefold())
    if key is not None:
        return key
    folded = name.casefold()
    starts = [label for label in _lookup() if label.startswith(folded) or folded.startswith(label)]
    close = difflib.get_close_matches(folded, list(_lookup()), n=5, cutoff=0.6)
    suggestions = list(dict.fromkeys(_lookup()[label] for label in [*starts, *close]))
    hint = f"; did you mean {', '.join(suggestions)}?" if suggestions else ""
    raise MaterialError(f"unknown material {name!r}{hint} (available: {', '.join(available())})")


def entry(name: str) -> dict[str, Any]:
    """A copy of the library entry of ``name``: SI values, description, aliases, source."""
    data = _library()[_resolve(name)]
    return {key: list(value) if isinstance(value, list) else value
            for key, value in data.items()}


def get(name: str, model: str | None = None) -> Material:
    """The library material ``name`` (key or alias, any case); one shared instance per entry.

    Parameters
    ----------
    name : str
        A library key or alias.
    model : str, optional
        ``None`` for the entry's own model (Mie–Grüneisen), or one of
        ``STRENGTH_MODELS`` to build the entry with its strength data
        (``strength_spec``).

    Raises
    ------
    MaterialError
        An unknown name (with the close matches and all names), an unknown
        model, or an entry without strength data for a strength model.
    """
    return _build(_resolve(name), model)


@functools.cache
def _build(key: str, model: str | None) -> Material:
    if model is None:
        spec = {field: value for field, value in _library()[key].items()
                if field not in _LIBRARY_ONLY_FIELDS}
        return material_from_spec(key, spec)
    return material_from_spec(key, {"model": model, LIBRARY_FIELD: key})


def listing() -> str:
    """The library as a table for ``wavediagram materials``: every entry's data, strength,
    aliases and source, with its caution (if any) on a line of its own."""
    lines = [f"{'name':<12} {'rho0 kg/m3':>10} {'c0 m/s':>8} {'s':>6} {'Gamma0':>6} "
             f"{'spall GPa':>9} {'G GPa':>6} {'Y GPa':>6}  aliases; source"]

    def gpa(value, width):
        return f"{value / 1e9:{width}.3g}" if value is not None else f"{'-':>{width}}"

    for name in available("mie-gruneisen"):
        e = _library()[name]
        try:
            strength = strength_spec(name, STRENGTH_MODELS[0])["yield_strength"]
        except MaterialError:  # no strength data, or none usable (see the caution)
            strength = None
        aliases = ", ".join(e.get("aliases", ()))
        lines.append(f"{name:<12} {e['rho0']:>10.0f} {e['c0']:>8.0f} {e['s']:>6.3f} "
                     f"{e['gamma0']:>6.2f} {gpa(e.get('spall_strength'), 9)} "
                     f"{gpa(e.get('shear_modulus'), 6)} {gpa(strength, 6)}  "
                     f"{aliases}; {e.get('source', '')}")
        if "caution" in e:
            lines.append(f"{'':<12} ! {e['caution']}")
    porous = available("porous")
    if porous:
        lines.append(f"{'porous':<12} {'rho0 kg/m3':>10} {'alpha0':>8} {'crush GPa':>9}  source")
        for name in porous:
            e = _library()[name]
            lines.append(f"{name:<12} {e['solid_rho0'] / e['alpha0']:>10.0f} "
                         f"{e['alpha0']:>8.3f} {e.get('crush_stress', 0.0) / 1e9:>9.3f}  "
                         f"{e.get('source', '')}")
            if "caution" in e:
                lines.append(f"{'':<12} ! {e['caution']}")
    for name in available("phase-change"):
        e = _library()[name]
        lines.append(f"{name:<12} {e['rho0']:>10.0f}  phase change at "
                     f"{e['transition_stress'] / 1e9:.4g} GPa; {e.get('source', '')}")
    explosives = available("explosive-jwl") + available("explosive-gamma")
    if explosives:
        lines.append(f"{'explosive':<12} {'rho0 kg/m3':>10} {'D_CJ m/s':>8} {'p_CJ GPa':>8}  "
                     f"(CJ point of the products' equation of state); source")
        for name in explosives:
            explosive = get(name)
            cj = explosive.cj_state(explosive.reference_state())
            lines.append(f"{name:<12} {explosive.rho0:>10.0f} {cj.speed:>8.0f} "
                         f"{cj.state.sigma / 1e9:>8.2f}  {_library()[name].get('source', '')}")
    lines.append("Names and aliases match without regard to case.  G and Y (yield stress; from "
                 "the HEL where the entry gives one) let a scene use an entry as "
                 "model = \"elastic-plastic\" or \"finite-plastic\" (library = \"NAME\").")
    return "\n".join(lines)


def caution(name: str) -> str:
    """The entry's caution (a trap in its data, e.g. a fit good in a narrow range), or ``""``."""
    return str(_library()[_resolve(name)].get("caution", ""))


def strength_spec(name: str, model: str) -> dict[str, Any]:
    """The specification of library entry ``name`` as a ``model`` solid (SI floats).

    ``model`` is one of ``STRENGTH_MODELS``.  Elastic–plastic: ``rho0``, Lamé
    constants ``lambda = K - 2G/3`` and ``mu = G`` (``K = rho0 c0^2``),
    ``yield_strength``; finite-plastic: the Mie–Grüneisen fields, ``shear_modulus``
    and ``yield_strength``.  ``spall_strength`` is carried when the entry has one.
    Raises ``MaterialError`` if the entry has no shear modulus or yield strength.
    """
    key = _resolve(name)
    data = _library()[key]
    if model not in STRENGTH_MODELS:
        raise MaterialError(f"{key}: a library entry can be built as model "
                            f"{' or '.join(STRENGTH_MODELS)} (or its own); got {model!r}")
    if "shear_modulus" not in data or not ("yield_strength" in data or "hel" in data):
        with_strength = [k for k, d in _library().items() if "shear_modulus" in d]
        raise MaterialError(f"{key}: the library gives no shear_modulus and yield_strength "
                            f"for it (entries with strength: {', '.join(with_strength)})")
    bulk = data["rho0"] * data["c0"] ** 2
    shear = data["shear_modulus"]
    poisson = (3.0 * bulk - 2.0 * shear) / (2.0 * (3.0 * bulk + shear))
    if not 0.0 < poisson < 0.5:
        raise MaterialError(f"{key}: rho0*c0^2 = {bulk / 1e9:.3g} GPa with shear_modulus "
                            f"{shear / 1e9:.3g} GPa gives Poisson's ratio {poisson:.2f}, outside "
                            f"(0, 0.5): its c0 is a fitting intercept, not a bulk sound speed, "
                            f"so it has no strength model ({caution(key) or 'see its entry'})")
    yield_strength = data.get("yield_strength")
    if yield_strength is None:
        yield_strength = data["hel"] * 2.0 * shear / (bulk + 4.0 * shear / 3.0)
    spec: dict[str, Any] = {"model": model, "rho0": data["rho0"],
                            "yield_strength": yield_strength}
    if model == "elastic-plastic":
        spec |= {"lambda": bulk - 2.0 * shear / 3.0, "mu": shear}
    else:
        spec |= {field: data[field] for field in ("c0", "s", "gamma0")}
        spec["shear_modulus"] = shear
    if "spall_strength" in data:
        spec["spall_strength"] = data["spall_strength"]
    return spec


# --- specifications -------------------------------------------------------------------
def material_from_spec(name: str, spec: dict[str, Any]) -> Material:
    """Build material ``name`` from ``spec``: ``model`` plus that model's fields in SI floats.

    Raises ``MaterialError`` naming the field at fault (unknown model, missing,
    unknown or non-numeric field) and the allowed set; the constructors then
    check the values' ranges.
    """
    if not isinstance(spec, dict):
        raise MaterialError(f"{name}: a material specification must be a table, got {spec!r}")
    if LIBRARY_FIELD in spec:
        spec = _with_library(name, spec)
    model = spec.get("model")
    if not isinstance(model, str) or model not in MODELS:
        got = "no model" if model is None else f"model {model!r}"
        raise MaterialError(f"{name}: model must be one of {', '.join(MODELS)}; got {got}")
    fields = MODELS[model]
    allowed = ("model", *fields["required"], *fields["optional"], *TEXT_FIELDS)
    for field, value in spec.items():
        if field not in allowed:
            raise MaterialError(f"{name}: unknown field {field!r} for model {model!r} "
                                f"(allowed: {', '.join(allowed)})")
        if field in TEXT_FIELDS and not isinstance(value, str):
            raise MaterialError(f"{name}: {field} must be a string, got {value!r}")
    missing = [field for field in fields["required"] if field not in spec]
    if missing:
        raise MaterialError(f"{name}: missing field {missing[0]!r} for model {model!r} "
                            f"(required: {', '.join(fields['required'])})")
    values = {field: _number(name, field, value) for field, value in spec.items()
              if field != "model" and field not in TEXT_FIELDS}
    if model == "mie-gruneisen":
        return MieGruneisen(name, values["rho0"], values["c0"], values["s"], values["gamma0"],
                            cv=values.get("cv"),
                            spall_strength=values.get("spall_strength", math.inf),
                            up_max=values.get("up_max"))
    if model == "linear-elastic":
        return _linear_elastic(name, values)
    if model == "elastic-plastic":
        lam, mu = _lame(name, values, _ELASTIC_PLASTIC_CHOICES, "an elastic-plastic")
        return ElasticPlastic(name, values["rho0"], lam, mu, values["yield_strength"],
                              spall_strength=values.get("spall_strength", math.inf))
    if model == "finite-plastic":
        return _finite_plastic(name, values)
    if model == "porous":
        return _porous(name, values)
    if model == "saturating-plastic":
        return SaturatingPlastic(name, values["rho0"], values["c0"], values["s"],
                                 values["shear_modulus"], values["yield_strength"],
                                 values["saturation_strength"], values["saturation_strain"],
                                 spall_strength=values.get("spall_strength", math.inf))
    if model in ("explosive-jwl", "explosive-gamma"):
        return _explosive(name, model, values)
    if model == "viscoplastic":
        lam, mu = _lame(name, values, _ELASTIC_PLASTIC_CHOICES, "a viscoplastic")
        return Viscoplastic(name, values["rho0"], lam, mu, values["yield_strength"],
                            values["relaxation_time"], values.get("rate_exponent", 1.0),
                            values.get("hugoniot_slope", 0.0))
    if model == "phase-change":
        return PhaseChangeSolid(name, values["rho0"], values["c1"], values["s1"], values["c2"],
                                values["s2"], values["transition_stress"],
                                values["transition_strain"],
                                spall_strength=values.get("spall_strength", math.inf))
    return IdealGas(name, values["gamma"], values["rho0"], cv=values.get("cv"))


def _with_library(name: str, spec: dict[str, Any]) -> dict[str, Any]:
    """``spec`` completed from the library entry its ``library`` field names.

    Fields the specification gives win; the entry supplies the rest, built as the
    specification's model (``strength_spec``; for other models, the entry's own
    fields).  Only ``model`` and the fields of one elastic choice are taken, so a
    specification giving ``poisson`` is not contradicted by the entry's ``mu``.
    """
    source = spec[LIBRARY_FIELD]
    model = spec.get("model")
    if not isinstance(source, str):
        raise MaterialError(f"{name}: {LIBRARY_FIELD} must be a library name, got {source!r}")
    try:
        base = (strength_spec(source, model) if model in STRENGTH_MODELS else
                {k: v for k, v in entry(source).items()
                 if k not in (*_LIBRARY_ONLY_FIELDS, *TEXT_FIELDS, "up_max")})
    except MaterialError as exc:
        if name == source:  # a library entry built as a strength model: already named
            raise
        raise MaterialError(f"{name}: {LIBRARY_FIELD} = {source!r}: {exc}") from exc
    given = {k: v for k, v in spec.items() if k != LIBRARY_FIELD}
    if any(k in given for k in ("poisson", "E", "shear_modulus", "lambda", "mu")):
        for k in ("poisson", "E", "shear_modulus", "lambda", "mu"):
            base.pop(k, None)
    return base | given


def _lame(name: str, values: dict[str, float], choices, what: str) -> tuple[float, float]:
    """Lamé constants ``(lambda, mu)`` (Pa) from exactly one of ``choices`` of elastic constants."""
    given = [choice for choice in choices if all(field in values for field in choice)]
    present = sorted({f for choice in choices for f in choice if f in values})
    used = {f for choice in given for f in choice}
    if len(given) != 1 or set(present) != used:
        options = " or ".join(" and ".join(choice) for choice in choices)
        raise MaterialError(f"{name}: {what} material needs exactly one of: {options}; "
                            f"got {', '.join(present) or 'none of them'}")
    choice = given[0]
    if choice == ("lambda", "mu"):
        return values["lambda"], values["mu"]
    nu = values["poisson"]
    if not -1.0 < nu < 0.5:
        raise MaterialError(f"{name}: poisson must be in (-1, 0.5), got {nu!r}")
    if choice == ("E", "poisson"):
        youngs = require_positive("E", values["E"], name)
        return youngs * nu / ((1.0 + nu) * (1.0 - 2.0 * nu)), youngs / (2.0 * (1.0 + nu))
    shear = require_positive("shear_modulus", values["shear_modulus"], name)
    return 2.0 * shear * nu / (1.0 - 2.0 * nu), shear


def _finite_plastic(name: str, values: dict[str, float]) -> FinitePlastic:
    """A finite-deformation elastic–plastic solid with ``shear_modulus`` or ``poisson``."""
    given = [field for field in ("shear_modulus", "poisson") if field in values]
    if len(given) != 1:
        raise MaterialError(f"{name}: a finite-plastic material needs exactly one of "
                            f"shear_modulus or poisson; got {', '.join(given) or 'neither'}")
    args = (values["rho0"], values["c0"], values["s"], values["gamma0"])
    rest = {"hardening": values.get("hardening", 0.0),
            "spall_strength": values.get("spall_strength", math.inf)}
    if given[0] == "poisson":
        return FinitePlastic.from_poisson(name, *args, values["poisson"],
                                          values["yield_strength"], **rest)
    return FinitePlastic(name, *args, values["shear_modulus"], values["yield_strength"], **rest)


POROUS_MATRIX_EXPANSION = 2.0
"""Largest matrix volume of a porous body, in its initial volumes ``v00 = alpha0 v_s0``: its
hot compacted states lie below ``v00`` (at most ``v00 - 2 v_s0 / Gamma0``, the pole of the
anomalous Hugoniot), and a release to zero stress from them expands the matrix further
(PS_foam: to 0.24 v00 from 1 GPa, 1.15 v00 from 10 GPa, 1.48 v00 from 100 GPa)."""


def _porous(name: str, values: dict[str, float]) -> PorousSolid:
    """A p–α porous solid on a Mie–Grüneisen matrix named ``<name> matrix``, defined in
    expansion up to ``POROUS_MATRIX_EXPANSION`` times the body's initial volume
    (``ExpandedMieGruneisen``: the shock heats the matrix of a highly porous body past
    its solid volume)."""
    solid = ExpandedMieGruneisen(f"{name} matrix", values["solid_rho0"], values["c0"],
                                 values["s"], values["gamma0"],
                                 max_expansion=POROUS_MATRIX_EXPANSION * values["alpha0"])
    return PorousSolid(name, solid, values["alpha0"],
                       crush_stress=values.get("crush_stress", 0.0),
                       compaction_stress=values.get("compaction_stress"),
                       crush_exponent=values.get("crush_exponent", 2.0),
                       crush_scale=values.get("crush_scale"),
                       spall_strength=values.get("spall_strength", math.inf))


def _explosive(name: str, model: str, values: dict[str, float]) -> Explosive:
    """An explosive: its unreacted Mie-Gruneisen solid and JWL or gamma-law products."""
    rho0 = values["rho0"]
    unreacted = MieGruneisen(f"{name} (unreacted)", rho0, values["c0"], values["s"],
                             values["gamma0"])
    if model == "explosive-gamma":
        products = Products.gamma_law(f"{name} products", rho0, values["gamma"], values["q"])
    else:
        products = Products(f"{name} products", rho0, require_positive("E0", values["E0"], name)
                            / rho0, values["omega"], A=values["A"], B=values["B"],
                            R1=values["R1"], R2=values["R2"])
    return Explosive(name, unreacted, products, D_cj=values.get("D_cj"),
                     p_cj=values.get("p_cj"))


def _number(name: str, field: str, value: Any) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise MaterialError(f"{name}: {field} must be a number (SI units), got {value!r}")
    return float(value)


def _linear_elastic(name: str, values: dict[str, float]) -> LinearElastic:
    """A linear elastic solid from exactly one of the stiffness choices."""
    given = [choice for choice in _LINEAR_ELASTIC_CHOICES
             if any(field in values for field in choice)]
    options = " or ".join(" and ".join(choice) for choice in _LINEAR_ELASTIC_CHOICES)
    if len(given) != 1 or any(field not in values for field in given[0]):
        present = [field for choice in given for field in choice if field in values]
        raise MaterialError(f"{name}: a linear-elastic material needs rho0 and exactly one "
                            f"of: {options}; got {', '.join(present) or 'none of them'}")
    strength = values.get("spall_strength", math.inf)
    if "C" in values:
        return LinearElastic(name, values["rho0"], values["C"], strength)
    lam, mu = _lame(name, values, _LINEAR_ELASTIC_CHOICES[1:], "a linear-elastic")
    return LinearElastic.from_lame(name, values["rho0"], lam, mu, strength)
