"""The material library file and materials built from specifications (``materials.library``)."""

from __future__ import annotations

import math

import pytest

import materials
from materials import (
    RIGHT,
    IdealGas,
    LinearElastic,
    MaterialError,
    MieGruneisen,
    Shock,
    solve_boundary,
)
from materials.library import available, caution, entry, get, listing, material_from_spec

MG_FIELDS = ("rho0", "c0", "s", "gamma0", "cv", "up_max")


def test_available_names():
    names = available("mie-gruneisen")
    assert len(names) == 27
    assert len(set(names)) == 27
    assert {"Al2024", "Cu", "PMMA", "W", "LiF", "water"} <= set(names)
    assert materials.available is available and materials.get is get


@pytest.mark.parametrize("name", available("mie-gruneisen"))
def test_entry_builds_the_material_with_its_fields(name):
    data = entry(name)
    assert data["model"] == "mie-gruneisen"
    assert data["source"] and data["description"]
    material = get(name)
    assert isinstance(material, MieGruneisen)
    assert material.name == name
    for field in MG_FIELDS:
        assert getattr(material, field) == data.get(field)
    assert material.spall_strength == data.get("spall_strength", math.inf)


@pytest.mark.parametrize("name", available("mie-gruneisen"))
def test_principal_hugoniot_at_500_m_per_s(name):
    """A piston at 500 m/s drives a shock with Us = c0 + s up and sigma = rho0 Us up."""
    material, up = get(name), 500.0
    us = material.c0 + material.s * up
    sigma = material.rho0 * us * up
    solution = solve_boundary(material, material.reference_state(), "left", velocity=up)
    star = solution.right_star
    assert star.sigma == pytest.approx(sigma, rel=1e-10)
    assert star.u == pytest.approx(up, rel=1e-12)
    assert star.rho == pytest.approx(material.rho0 * us / (us - up), rel=1e-10)
    (shock,) = solution.right_waves
    assert isinstance(shock, Shock) and shock.direction == RIGHT
    assert shock.speed == pytest.approx(us, rel=1e-10)
    # The EOS's closed-form Hugoniot at the same volume.
    v = material.v0 * (1.0 - up / us)
    assert material.hugoniot(material.reference_state(), v)[0] == pytest.approx(sigma, rel=1e-12)


def test_entry_is_a_copy():
    data = entry("Cu")
    data["rho0"] = 1.0
    data["aliases"].append("brass")
    assert entry("Cu")["rho0"] == 8930.0
    assert "brass" not in entry("Cu")["aliases"]


def test_aliases_and_case():
    assert get("copper") is get("Cu")
    assert get("CU") is get("Cu")
    assert get("Plexiglas") is get("PMMA")
    assert get("aluminium").name == "Al6061"
    assert entry("lithium fluoride")["rho0"] == 2638.0


def test_get_is_cached():
    assert get("W") is get("W")


def test_unknown_material_suggests_close_names():
    with pytest.raises(MaterialError) as info:
        get("Cu2")
    message = str(info.value)
    assert "unknown material 'Cu2'" in message
    assert "did you mean Cu?" in message
    assert "available: Al1100, Al2024" in message


def test_unknown_alias_typo_suggests_the_entry():
    with pytest.raises(MaterialError, match="did you mean .*Al6061"):
        get("alumnium")


def test_no_suggestion_for_nonsense():
    with pytest.raises(MaterialError) as info:
        entry("zzzzzzzz")
    assert "did you mean" not in str(info.value)


def test_material_name_must_be_a_string():
    with pytest.raises(MaterialError, match="must be a string"):
        get(3)


# --- specifications ---------------------------------------------------------------------------
def test_mie_gruneisen_spec():
    m = material_from_spec("MyPMMA", {"model": "mie-gruneisen", "rho0": 1186, "c0": 2600.0,
                                      "s": 1.52, "gamma0": 0.97, "spall_strength": 0.2e9,
                                      "description": "a polymer"})
    assert isinstance(m, MieGruneisen)
    assert (m.name, m.rho0, m.c0, m.s, m.gamma0) == ("MyPMMA", 1186.0, 2600.0, 1.52, 0.97)
    assert m.spall_strength == 0.2e9
    assert m.cv is None and m.up_max is None


def test_spall_strength_defaults_to_infinity():
    m = material_from_spec("X", {"model": "mie-gruneisen", "rho0": 1000.0, "c0": 1500.0,
                                 "s": 1.5, "gamma0": 1.0})
    assert m.spall_strength == math.inf
    e = material_from_spec("Y", {"model": "linear-elastic", "rho0": 2649.0, "C": 5749.0})
    assert e.spall_strength == math.inf


# Davison's reference steel: lambda 123.1 GPa, mu 79.29 GPa, rho0 7870 kg/m^3.
LAM, MU, RHO = 123.1e9, 79.29e9, 7870.0
C_STEEL = math.sqrt((LAM + 2.0 * MU) / RHO)


def test_linear_elastic_from_speed():
    m = material_from_spec("quartz", {"model": "linear-elastic", "rho0": 2649.0, "C": 5749.0,
                                      "spall_strength": 1e9})
    assert isinstance(m, LinearElastic)
    assert (m.rho0, m.C, m.spall_strength) == (2649.0, 5749.0, 1e9)


def test_linear_elastic_from_lame():
    m = material_from_spec("steel", {"model": "linear-elastic", "rho0": RHO, "lambda": LAM,
                                     "mu": MU})
    assert m.C == pytest.approx(C_STEEL, rel=1e-15)
    assert m.C == pytest.approx(5983.0, abs=1.0)


def test_linear_elastic_from_youngs_modulus_and_poisson():
    youngs = MU * (3.0 * LAM + 2.0 * MU) / (LAM + MU)
    nu = LAM / (2.0 * (LAM + MU))
    m = material_from_spec("steel", {"model": "linear-elastic", "rho0": RHO, "E": youngs,
                                     "poisson": nu})
    assert m.C == pytest.approx(C_STEEL, rel=1e-14)


def test_ideal_gas_spec():
    m = material_from_spec("air", {"model": "ideal-gas", "gamma": 1.4, "rho0": 1.2,
                                   "cv": 718.0})
    assert isinstance(m, IdealGas)
    assert (m.gamma, m.rho0, m.cv, m.spall_strength) == (1.4, 1.2, 718.0, 0.0)


@pytest.mark.parametrize(("spec", "fragments"), [
    ({"rho0": 1.0}, ["X: model must be one of mie-gruneisen, linear-elastic, ideal-gas",
                     "got no model"]),
    ({"model": "tillotson"}, ["model 'tillotson'"]),
    ({"model": "mie-gruneisen", "rho0": 1e3, "c0": 1e3, "s": 1.5},
     ["missing field 'gamma0'", "required: rho0, c0, s, gamma0"]),
    ({"model": "mie-gruneisen", "rho0": 1e3, "c0": 1e3, "s": 1.5, "gamma0": 1.0, "Gamma": 2},
     ["unknown field 'Gamma'", "allowed: model, rho0, c0, s, gamma0, cv, spall_strength"]),
    ({"model": "ideal-gas", "gamma": 1.4, "rho0": 1.2, "spall_strength": 1.0},
     ["unknown field 'spall_strength' for model 'ideal-gas'"]),
    ({"model": "mie-gruneisen", "rho0": "1e3", "c0": 1e3, "s": 1.5, "gamma0": 1.0},
     ["rho0 must be a number (SI units), got '1e3'"]),
    ({"model": "ideal-gas", "gamma": True, "rho0": 1.2}, ["gamma must be a number"]),
    ({"model": "ideal-gas", "gamma": 1.4, "rho0": 1.2, "description": 3},
     ["description must be a string"]),
    ({"model": "mie-gruneisen", "rho0": -1e3, "c0": 1e3, "s": 1.5, "gamma0": 1.0},
     ["rho0 must be finite and > 0"]),
    ({"model": "mie-gruneisen", "rho0": 1e3, "c0": 1e3, "s": 1.5, "gamma0": 1.0,
      "spall_strength": -1e9}, ["spall_strength must be > 0"]),
    ({"model": "ideal-gas", "gamma": 0.9, "rho0": 1.2}, ["gamma must be in (1, 100)"]),
    ({"model": "linear-elastic", "rho0": RHO}, ["exactly one of: C or lambda and mu or E and "
                                                "poisson; got none of them"]),
    ({"model": "linear-elastic", "rho0": RHO, "C": 5e3, "lambda": LAM, "mu": MU},
     ["got C, lambda, mu"]),
    ({"model": "linear-elastic", "rho0": RHO, "lambda": LAM}, ["got lambda"]),
    ({"model": "linear-elastic", "rho0": RHO, "E": 200e9, "poisson": 0.5},
     ["poisson must be in (-1, 0.5)"]),
    ({"model": "linear-elastic", "rho0": RHO, "E": -200e9, "poisson": 0.3},
     ["E must be finite and > 0"]),
    ("not a table", ["must be a table"]),
])
def test_spec_errors_name_the_field(spec, fragments):
    with pytest.raises(MaterialError) as info:
        material_from_spec("X", spec)
    for fragment in fragments:
        assert fragment in str(info.value)


def test_no_import_cycle():
    """``materials.library`` imports on its own, before the package's other modules."""
    import subprocess
    import sys
    from pathlib import Path

    code = "import materials.library as l; print(len(l.available(\"mie-gruneisen\")))"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True, cwd=Path(__file__).resolve().parents[1])
    assert out.stdout.strip() == "27"


# --- strength, aliases, cautions ----------------------------------------------------
STRENGTH = ("Al2024", "Al6061", "Cu", "W", "Ta", "SS304", "Ti6Al4V", "LiF", "sapphire")


@pytest.mark.parametrize("name", STRENGTH)
def test_strength_entries_build_as_elastic_plastic_and_finite_plastic(name):
    data = entry(name)
    ep = get(name, model="elastic-plastic")
    assert ep.mu == data["shear_modulus"]
    bulk = data["rho0"] * data["c0"] ** 2
    assert ep.lam + 2.0 * ep.mu / 3.0 == pytest.approx(bulk, rel=1e-12)
    hel = (ep.lam + 2.0 * ep.mu) * ep.yield_strength / (2.0 * ep.mu)
    if "hel" in data:
        assert hel == pytest.approx(data["hel"], rel=1e-12)
    else:
        assert ep.yield_strength == data["yield_strength"]
    fp = get(name, model="finite-plastic")
    assert fp.shear_modulus == data["shear_modulus"]
    assert "strength" in data["source"]


def test_library_field_fills_a_specification():
    built = material_from_spec("CuEP", {"model": "elastic-plastic", "library": "copper",
                                        "yield_strength": 0.3e9})
    assert built.yield_strength == 0.3e9 and built.mu == entry("Cu")["shear_modulus"]
    nu = 0.34
    by_poisson = material_from_spec("CuP", {"model": "elastic-plastic", "rho0": 8930.0,
                                            "shear_modulus": 47.7e9, "poisson": nu,
                                            "yield_strength": 0.12e9})
    assert by_poisson.lam == pytest.approx(2.0 * 47.7e9 * nu / (1.0 - 2.0 * nu), rel=1e-12)
    with pytest.raises(MaterialError, match="exactly one of"):
        material_from_spec("X", {"model": "elastic-plastic", "rho0": 8930.0, "mu": 1e9,
                                 "lambda": 1e9, "poisson": 0.3, "yield_strength": 1e8})


def test_entries_without_usable_strength_are_refused_with_a_reason():
    with pytest.raises(MaterialError, match="no shear_modulus"):
        get("PMMA", model="elastic-plastic")
    with pytest.raises(MaterialError, match="fitting intercept"):
        get("fused_silica", model="elastic-plastic")


def test_aliases_are_consistent_and_misses_suggest():
    assert get("Al") is get("aluminum") is get("aluminium") is get("Al6061")
    assert get("copper") is get("Cu")
    with pytest.raises(MaterialError, match="did you mean Ti6Al4V"):
        get("Ti")
    with pytest.raises(MaterialError, match="Al2024"):
        get("alu")


def test_listing_shows_strength_and_cautions():
    text = listing()
    assert "fitting intercept" in caution("fused_silica")
    assert "! " + caution("fused_silica") in text
    cu = next(line for line in text.splitlines() if line.startswith("Cu "))
    assert "47.7" in cu and "0.12" in cu and "copper" in cu
