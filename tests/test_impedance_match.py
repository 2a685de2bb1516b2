"""Impedance matching through a stack (``fronttrack.impedance_match``).

Closed forms used: for a linear Us–up solid shocked from rest,
``sigma_H(up) = rho0 (c0 + s up) up`` and ``rho = rho0 Us / (Us - up)``; the flyer
(moving at V) reaches the contact velocity ``u`` through ``sigma_H,flyer(V - u)``.
"""

from __future__ import annotations

import json
import math
import warnings
from itertools import pairwise

import pytest

from fronttrack.fits import FitExtrapolationWarning
from fronttrack.impedance_match import (
    EXACT,
    MIRRORED,
    MatchRow,
    format_table,
    impedance_match,
    match,
    to_json_dict,
)
from materials import LinearElastic, get


def sigma_h(material, up):
    """Principal Hugoniot stress (Pa) at particle velocity ``up`` of a linear Us–up solid."""
    return material.rho0 * (material.c0 + material.s * up) * up


def test_symmetric_impact_gives_half_the_velocity():
    cu = get("Cu")
    flyer, target = impedance_match(cu, 1000.0, [cu])
    assert target.u == pytest.approx(500.0, rel=1e-12)
    # The two sides of the contact agree to rounding (each side's state is its own curve's).
    assert flyer.u == pytest.approx(target.u, rel=1e-14) and flyer.sigma == target.sigma
    assert target.sigma == pytest.approx(sigma_h(cu, 500.0), rel=1e-12)
    assert flyer.shock_speed == pytest.approx(-target.shock_speed, rel=1e-12)
    assert flyer.shock_speed_eulerian == pytest.approx(1000.0 + flyer.shock_speed, rel=1e-12)
    assert flyer.rho == pytest.approx(target.rho, rel=1e-12)
    assert (flyer.layer, target.layer) == ("flyer", 0)


def test_cu_flyer_on_al2024_matches_the_closed_form():
    """Solve rho_A (c_A + s_A u) u = rho_B (c_B + s_B (V - u)) (V - u) for u by hand.

    A: Al2024 target, B: Cu flyer.  Expanded: a u^2 + b u + c = 0 with
    a = rho_A s_A - rho_B s_B, b = rho_A c_A + rho_B c_B + 2 rho_B s_B V,
    c = -rho_B V (c_B + s_B V); the physical root (0 < u < V) is
    u = -2c / (b + sqrt(b^2 - 4ac)) (the cancellation-free form, b > 0).
    """
    al, cu, velocity = get("Al2024"), get("Cu"), 1000.0
    a = al.rho0 * al.s - cu.rho0 * cu.s
    b = al.rho0 * al.c0 + cu.rho0 * cu.c0 + 2.0 * cu.rho0 * cu.s * velocity
    c = -cu.rho0 * velocity * (cu.c0 + cu.s * velocity)
    u = -2.0 * c / (b + math.sqrt(b * b - 4.0 * a * c))
    assert 0.0 < u < velocity

    flyer, target = impedance_match(cu, velocity, [al])
    us_al, us_cu = al.c0 + al.s * u, cu.c0 + cu.s * (velocity - u)
    assert target.u == pytest.approx(u, rel=1e-10)
    assert target.sigma == pytest.approx(al.rho0 * us_al * u, rel=1e-10)
    assert flyer.sigma == pytest.approx(cu.rho0 * us_cu * (velocity - u), rel=1e-10)
    assert target.shock_speed == pytest.approx(us_al, rel=1e-10)
    assert target.shock_speed_eulerian == target.shock_speed  # the target was at rest
    assert flyer.shock_speed == pytest.approx(-us_cu, rel=1e-10)
    assert flyer.shock_speed_eulerian == pytest.approx(velocity - us_cu, rel=1e-10)
    assert target.rho == pytest.approx(al.rho0 * us_al / (us_al - u), rel=1e-10)
    assert flyer.rho == pytest.approx(cu.rho0 * us_cu / (us_cu - (velocity - u)), rel=1e-10)
    assert target.temperature > 298.15 and flyer.temperature > 298.15
    assert target.reflected is None and flyer.reflected is None
    assert target.method == flyer.method == EXACT


def test_linear_elastic_stack_follows_the_transmission_coefficients():
    """Acoustic layers: sigma_k+1 = sigma_k 2 Z_k+1 / (Z_k + Z_k+1); mirrored is then exact."""
    stack = [LinearElastic("a", 2649.0, 5749.0), LinearElastic("b", 7870.0, 5983.0),
             LinearElastic("c", 1186.0, 2700.0)]
    velocity = 200.0
    z = [m.impedance for m in stack]
    expected = [z[0] * velocity / 2.0]
    for k in range(2):
        expected.append(expected[-1] * 2.0 * z[k + 1] / (z[k] + z[k + 1]))
    for mirrored in (False, True):
        rows = impedance_match(stack[0], velocity, stack, mirrored=mirrored)
        for row, sigma, layer in zip(rows[1:], expected, stack, strict=True):
            assert row.sigma == pytest.approx(sigma, rel=1e-12)
            assert row.u == pytest.approx(sigma / layer.impedance, rel=1e-12)
            assert row.shock_speed == pytest.approx(layer.C, rel=1e-12)
            assert row.temperature is None
    # b is stiffer than a: a reshock; c is softer than b: a release (a shock in this solid).
    exact = impedance_match(stack[0], velocity, stack)
    assert exact[1].reflected.compressive and not exact[2].reflected.compressive
    assert exact[2].reflected.speed == pytest.approx(-stack[1].C, rel=1e-12)


def momentum_jump_error(row: MatchRow, material) -> float:
    """Relative error of rho0 U (u_b - u_a) = sigma_b - sigma_a across the reflected wave."""
    wave = row.reflected
    lhs = material.rho0 * wave.speed * (wave.u - row.u)
    return abs(lhs - (wave.sigma - row.sigma)) / abs(wave.sigma - row.sigma)


def test_stiffer_next_layer_reflects_a_reshock():
    al, cu = get("Al2024"), get("Cu")
    flyer, first, second = impedance_match(al, 1000.0, [al, cu])
    wave = first.reflected
    assert wave.kind == "shock" and wave.compressive
    assert wave.speed < 0.0 and wave.head_speed is None
    assert wave.sigma == second.sigma and wave.u == pytest.approx(second.u, rel=1e-14)
    assert second.sigma > first.sigma and second.u < first.u
    assert wave.rho > first.rho and wave.temperature > first.temperature
    assert momentum_jump_error(first, al) < 1e-10
    # The transmitted state lies on copper's principal Hugoniot.
    assert second.sigma == pytest.approx(sigma_h(cu, second.u), rel=1e-10)
    assert first.u == pytest.approx(500.0, rel=1e-12)  # Al on Al


def test_softer_next_layer_reflects_a_release_fan():
    cu, pmma = get("Cu"), get("PMMA")
    _, first, second = impedance_match(cu, 1000.0, [cu, pmma])
    wave = first.reflected
    assert wave.kind == "fan" and not wave.compressive
    assert wave.speed is None
    assert wave.head_speed < wave.tail_speed < 0.0  # the head (at the higher stress) is faster
    assert second.sigma < first.sigma and second.u > first.u
    assert wave.rho < first.rho
    assert second.sigma == pytest.approx(sigma_h(pmma, second.u), rel=1e-10)
    # With release along the Hugoniot the release is a rarefaction shock.
    _, first_h, second_h = impedance_match(cu, 1000.0, [cu, pmma], release="hugoniot")
    assert first_h.reflected.kind == "shock" and not first_h.reflected.compressive
    assert momentum_jump_error(first_h, cu) < 1e-10
    assert second_h.sigma != second.sigma


def test_mirrored_rows_solve_the_mirrored_hugoniot():
    """sigma_H,k+1(u) = sigma_H,k(2 u_k - u) at each interface, and the rows are labelled."""
    stack = [get("Al2024"), get("Cu"), get("PMMA")]
    rows = impedance_match(get("W"), 1500.0, stack, mirrored=True)
    assert [r.method for r in rows] == [EXACT, MIRRORED, MIRRORED, MIRRORED]
    for k in range(2):
        row, nxt = rows[k + 1], rows[k + 2]
        mirrored = sigma_h(stack[k], 2.0 * row.u - nxt.u)
        assert nxt.sigma == pytest.approx(mirrored, rel=1e-10)
        assert nxt.sigma == pytest.approx(sigma_h(stack[k + 1], nxt.u), rel=1e-10)
        assert row.reflected.kind == "shock" and row.reflected.rho is None
        assert momentum_jump_error(row, stack[k]) < 1e-10
    assert rows[1].reflected.compressive and not rows[2].reflected.compressive
    # One layer: nothing is mirrored.
    assert all(r.method == EXACT for r in impedance_match(get("W"), 1500.0, stack[:1],
                                                          mirrored=True))


@pytest.mark.parametrize(("flyer", "stack"), [
    ("Al2024", ["Al2024", "Cu"]),  # stiffer: reshock
    ("Cu", ["Cu", "PMMA"]),  # softer: release
])
def test_mirrored_error_grows_with_velocity(flyer, stack):
    materials = [get(name) for name in stack]
    errors = []
    for velocity in (250.0, 500.0, 1000.0, 2000.0):
        exact = impedance_match(get(flyer), velocity, materials)[-1]
        mirrored = impedance_match(get(flyer), velocity, materials, mirrored=True)[-1]
        errors.append(abs(mirrored.sigma - exact.sigma) / exact.sigma)
    # Al -> Cu: 5.6e-5, 1.8e-4, 4.9e-4, 8.2e-4; Cu -> PMMA: 7.7e-5, 3.3e-4, 1.4e-3, 5.2e-3.
    assert errors[0] > 1e-5  # far above rounding already at 250 m/s
    assert all(later > 1.5 * earlier for earlier, later in pairwise(errors))
    assert errors[-1] > 10.0 * errors[0]
    assert errors[-1] < 0.01  # still a good approximation at 2 km/s


def test_json_dict():
    rows = impedance_match(get("Cu"), 1000.0, [get("Al2024"), get("PMMA")])
    data = json.loads(json.dumps(to_json_dict(rows)))
    assert data["units"]["sigma"] == "Pa" and data["units"]["rho"] == "kg/m3"
    assert [r["layer"] for r in data["rows"]] == ["flyer", 0, 1]
    keys = {"layer", "material", "method", "sigma", "u", "rho", "temperature", "shock_speed",
            "shock_speed_eulerian", "reflected"}
    for row, record in zip(rows, data["rows"], strict=True):
        assert set(record) == keys
        assert (record["sigma"], record["u"], record["rho"]) == (row.sigma, row.u, row.rho)
        assert record["shock_speed"] == row.shock_speed
    reflected = data["rows"][1]["reflected"]
    assert set(reflected) == {"kind", "compressive", "speed", "head_speed", "tail_speed",
                              "sigma", "u", "rho", "temperature"}
    assert reflected["kind"] == "fan" and reflected["speed"] is None
    assert data["rows"][2]["reflected"] is None


def test_format_table():
    rows = impedance_match(get("Cu"), 1000.0, [get("Al2024"), get("PMMA")])
    lines = format_table(rows).splitlines()
    assert len(lines) == 2 + len(rows)
    assert lines[0].split()[:4] == ["layer", "material", "sigma", "GPa"]
    assert set(lines[1]) <= {"-", " "}
    al = lines[3].split()
    assert al[:2] == ["0", "Al2024"]
    assert float(al[2]) == pytest.approx(rows[1].sigma / 1e9, abs=1e-4)
    assert float(al[3]) == pytest.approx(rows[1].u, abs=0.01)
    assert float(al[4]) == pytest.approx(rows[1].rho / 1e3, abs=1e-4)
    assert float(al[5]) == pytest.approx(rows[1].shock_speed / 1e3, abs=1e-4)
    assert "release fan" in lines[3] and lines[3].endswith("exact")


@pytest.mark.parametrize("velocity", [0.0, -10.0, math.nan, math.inf])
def test_bad_velocity(velocity):
    with pytest.raises(ValueError, match="flyer velocity"):
        impedance_match(get("Cu"), velocity, [get("Al2024")])


def test_empty_stack():
    with pytest.raises(ValueError, match="at least one layer"):
        impedance_match(get("Cu"), 1000.0, [])


def test_an_explosive_flyer_or_layer_detonates_and_is_matched():
    """An explosive striking copper, or struck by it, detonates at once: the waves into
    it are the CJ detonation and its Taylor wave (below p_CJ), so its row reports the
    state behind both and the detonation's speed, and the stresses still match across
    every contact (found by a new user: this was an internal error)."""
    explosive, copper = get("PBX9501"), get("Cu")
    detonation = explosive.cj_state(explosive.reference_state())
    rows = impedance_match(explosive, 500.0, [copper])
    assert rows[0].shock_speed == pytest.approx(-detonation.speed, rel=1e-12)
    assert rows[0].sigma == pytest.approx(rows[1].sigma, rel=1e-12)
    assert 0.0 < rows[1].sigma < detonation.state.sigma
    rows = impedance_match(copper, 2000.0, [explosive, copper])
    assert rows[1].shock_speed == pytest.approx(detonation.speed, rel=1e-12)
    assert rows[1].reflected is not None and rows[2].sigma > rows[1].sigma


def test_a_match_beyond_the_fitted_data_warns_and_reports_no_negative_temperature():
    """Cu at 100 km/s on Al 2024: both states lie far beyond the Us-up data (up_max 3 and
    4 km/s); each row warns with its principal-Hugoniot particle velocity, and where the
    extrapolated temperature model gives no positive temperature the row says unknown."""
    with pytest.warns(FitExtrapolationWarning) as caught:
        rows = match("Cu", "100 km/s", ["Al2024"])
    lines = [str(w.message) for w in caught]
    assert len(lines) == 2
    flyer, target = rows
    assert f"up = {100e3 - flyer.u:.4g} m/s" in lines[0] and "Cu" in lines[0]
    assert f"up = {target.u:.4g} m/s" in lines[1] and "Al2024" in lines[1]
    assert all(row.temperature is None or row.temperature > 0.0 for row in rows)
    assert target.temperature is None


def test_a_match_within_the_fitted_data_does_not_warn():
    with warnings.catch_warnings():
        warnings.simplefilter("error", FitExtrapolationWarning)
        rows = match("Cu", "500 m/s", ["Al2024"])
    assert all(row.temperature > 290.0 for row in rows)
