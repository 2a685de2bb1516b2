"""Explosive-driven plates against Gurney's model; the balance of detonation scenes; bad
explosive input.

Gurney's formulas (``fronttrack.gurney``; Gurney 1943, Kennedy 1970, Cooper 1996 ch. 27)
are checked against their own assumptions solved numerically, then the engine's plates
against them.  The charge is the gamma = 3 gas of the book's TNT energy (rho0 = 1600
kg/m^3, q = 4.9 MJ/kg, D = sqrt(16 q) = 8854 m/s), whose products expand without limit in
all three geometries, so the Gurney energy is E = q (``gurney_energy``) and the Gurney
velocity sqrt(2q) = 3130 m/s.  The plate is linear elastic with copper's density and bulk
sound speed (8930 kg/m^3, 3940 m/s): Gurney's plate is rigid, and a plate of one wave
speed rings without turning momentum into anything else.  Its velocity is its momentum
over its mass (``plate_velocity``): the free surface rings up in steps, the mean rises
smoothly.

Runs use a characteristic step of 5 GPa (p_CJ = 31.4 GPa) and drop waves below 0.1 GPa
(a ringing elastic plate otherwise fills with ever weaker shocks); their balance is held
to what those settings promise.  The plates are compared at a time when their velocity
still rises by less than 3 % over the last fifth of the run, against Gurney within 5 %:
the few per cent the model claims, plus the last few per cent of the approach.
Measured: tamped 2848 m/s at 16 us (Gurney 2827, +0.7 %), open-faced 1849 m/s at 6 us
(Gurney 1843, +0.3 %; a longer run reaches 1889 m/s at 10 us, +2.5 %), symmetric 2117
m/s at 10 us (Gurney 2150, -1.5 %).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.optimize import brentq

import fronttrack as ft
from fronttrack.cli import main
from fronttrack.gurney import gurney_energy, gurney_velocity, plate_velocity
from materials import LinearElastic, MieGruneisen
from materials.explosive import BURNT, gamma_law_explosive

RHO0, Q = 1600.0, 4.9e6
PLATE = LinearElastic("Cu (elastic)", 8930.0, 3940.0)
CHARGE = gamma_law_explosive("gamma3", RHO0, 3.0, Q,
                             MieGruneisen("unreacted", RHO0, 2390.0, 2.05, 1.0))
ACCURACY = ft.Accuracy(characteristic_step="5 GPa", negligible_stress="0.1 GPa")
GURNEY_TOLERANCE = 0.05
STILL_RISING = 0.03


# --- the formulas against their assumptions ---------------------------------------------
def _gurney_by_balance(geometry: str, r: float, energy: float) -> float:
    """Plate velocity from Gurney's assumptions solved numerically: products of uniform
    density with a velocity linear between the faces, momentum (no wall) and energy."""
    def kinetic(v_plate):
        if geometry == "tamped":
            ends = (0.0, v_plate)
        else:
            # open-faced: momentum M V + C (V + u_free)/2 = 0 fixes the free face's u
            ends = (-v_plate * (2.0 * r + 1.0), v_plate)
        u = np.linspace(*ends, 20001)
        gas = np.trapezoid(u * u, dx=1.0 / 20000) / 2.0  # per unit charge mass
        return r * v_plate**2 / 2.0 + gas - energy

    if geometry == "symmetric":  # each half is a tamped charge C/2 with its plate M
        return _gurney_by_balance("tamped", 2.0 * r, energy)
    return brentq(kinetic, 1.0, 1e5, xtol=1e-12)


@pytest.mark.parametrize("geometry", ["open-faced", "tamped", "symmetric"])
@pytest.mark.parametrize("ratio", [0.5, 1.0, 2.0])
def test_gurney_formulas_solve_their_balance(geometry, ratio):
    """The closed forms against the momentum and energy balance they come from, to the
    trapezoid rule's error on 20 000 intervals (~1e-9)."""
    assert gurney_velocity(geometry, ratio, Q) == pytest.approx(
        _gurney_by_balance(geometry, ratio, Q), rel=1e-8)


def test_gurney_bad_input():
    with pytest.raises(ft.SceneError, match="geometry must be one of"):
        gurney_velocity("cylinder", 1.0, Q)
    with pytest.raises(ft.SceneError, match=r"mass_ratio M/C must be > 0"):
        gurney_velocity("tamped", -1.0, Q)


# --- explosive-driven plates --------------------------------------------------------------
def _run(layers, left, t_end):
    scene = ft.Scene(layers, left=ft.Boundary(left), t_end=t_end, accuracy=ACCURACY)
    return ft.run(scene)


@pytest.fixture(scope="module")
def tamped():
    """10 mm of charge against a wall, a 1.6 mm plate (M/C = 0.893)."""
    return _run([ft.Layer(CHARGE, "10 mm", initiate="left"), ft.Layer(PLATE, "1.6 mm")],
                "wall", "16 us")


@pytest.fixture(scope="module")
def open_faced():
    """The same charge and plate with the charge's rear face free."""
    return _run([ft.Layer(CHARGE, "10 mm", initiate="left"), ft.Layer(PLATE, "1.6 mm")],
                "free", "6 us")


@pytest.fixture(scope="module")
def symmetric():
    """A plate on each face of 2 x 5 mm of charge initiated at its mid-plane (M/C =
    0.893 for the whole charge): each half is the tamped charge of half the mass."""
    return _run([ft.Layer(PLATE, "1.6 mm"), ft.Layer(CHARGE, "5 mm", initiate="right"),
                 ft.Layer(CHARGE, "5 mm"), ft.Layer(PLATE, "1.6 mm")], "free", "10 us")


def _check_plate(solution, layer, geometry, ratio):
    t_end = solution.scene.t_end
    final = plate_velocity(solution, layer, t_end)
    earlier = plate_velocity(solution, layer, 0.8 * t_end)
    gurney = gurney_velocity(geometry, ratio, gurney_energy(CHARGE))
    assert 0.0 <= (final - earlier) / final < STILL_RISING
    assert abs(final / gurney - 1.0) < GURNEY_TOLERANCE
    return final, gurney


def _check_balance(solution):
    balance = solution.accuracy_report["balance"]
    assert balance["momentum_error"] <= balance["promised"]
    assert abs(balance["energy_error"]) <= balance["promised"]
    # mass is exact: the cells at t_end hold the stack's mass
    mass = sum(layer.material.rho0 * layer.thickness for layer in solution.scene.layers)
    assert solution.conservation()["mass"] == pytest.approx(mass, rel=1e-12)


def test_tamped_plate_against_gurney(tamped):
    ratio = 8930.0 * 1.6 / (RHO0 * 10.0)
    final, gurney = _check_plate(tamped, 1, "tamped", ratio)
    assert gurney == pytest.approx(2826.9, abs=0.1)
    _check_balance(tamped)


def test_open_faced_plate_against_gurney(open_faced):
    ratio = 8930.0 * 1.6 / (RHO0 * 10.0)
    _check_plate(open_faced, 1, "open-faced", ratio)
    _check_balance(open_faced)
    # the products leave through the free face: the charge's momentum is negative
    assert open_faced.state_at(0.0, open_faced.scene.t_end).u < 0.0


def test_symmetric_sandwich_against_gurney(symmetric):
    ratio = 8930.0 * 1.6 / (RHO0 * 10.0)
    right, _ = _check_plate(symmetric, 3, "symmetric", ratio)
    # initiated at the mid-plane the sandwich is symmetric: the plates mirror each other
    left = plate_velocity(symmetric, 0, symmetric.scene.t_end)
    assert left == pytest.approx(-right, rel=1e-9)
    _check_balance(symmetric)


# --- the balance of a charge's own Taylor wave (regression) ------------------------------
@pytest.mark.parametrize("face", ["free", "wall"])
def test_taylor_wave_balance_within_the_promise(face):
    """10 mm of JWL TNT initiated at a free face or at a wall.  Its fans used to be cut at
    equal steps of stress alone: towards vacuum the last step carries most of the velocity,
    and the balance was off by 10-12 % in energy (created) and 5.6 % in momentum.  Cut at
    equal steps of stress and velocity the residual is second order in the step."""
    residuals = {}
    for step in ("2 GPa", "1 GPa"):
        scene = ft.Scene([ft.Layer("TNT", "10 mm", initiate="left")], left=ft.Boundary(face),
                         t_end="2 us", accuracy=ft.Accuracy(characteristic_step=step))
        solution = ft.run(scene)
        balance = solution.accuracy_report["balance"]
        assert balance["momentum_error"] <= balance["promised"]
        assert abs(balance["energy_error"]) <= balance["promised"]
        residuals[step] = abs(balance["energy_error"])
    # second order: halving the step divides the residual by about 4 (measured 2.2-3.4)
    assert residuals["1 GPa"] < 0.5 * residuals["2 GPa"]


# --- bad input and a detonation into a gap --------------------------------------------------
NO_CJ = ('[materials.BadJWL]\nmodel = "explosive-jwl"\nrho0 = "1630 kg/m3"\nc0 = "2.39 km/s"\n'
         's = 2.05\ngamma0 = 1.0\nA = "371.2 GPa"\nB = "3.231 GPa"\nR1 = 0.2\nR2 = 0.95\n'
         'omega = 0.3\nE0 = "7 GPa"\n')


def test_explosive_without_cj_point(tmp_path, capsys):
    with pytest.raises(ft.SceneError, match=r"no Chapman-Jouguet point: R1 = 0.2 .* R1 must "
                                            r"be > omega = 0.3"):
        ft.material("BadJWL", model="explosive-jwl", rho0="1630 kg/m3", c0="2.39 km/s",
                    s=2.05, gamma0=1.0, A="371.2 GPa", B="3.231 GPa", R1=0.2, R2=0.95,
                    omega=0.3, E0="7 GPa")
    scene = tmp_path / "bad.toml"
    scene.write_text('t_end = "1 us"\n' + NO_CJ + '[[layer]]\nmaterial = "BadJWL"\n'
                     'thickness = "1 mm"\ninitiate = "left"\n')
    assert main(["run", str(scene), "--quiet", "--no-figures"]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1
    assert "R1 must be > omega" in err


def test_initiation_after_t_end_through_the_cli(tmp_path, capsys):
    scene = tmp_path / "late.toml"
    scene.write_text('t_end = "1 us"\n[[layer]]\nmaterial = "TNT"\nthickness = "1 mm"\n'
                     'initiate = "right 2 us"\n')
    assert main(["run", str(scene), "--quiet", "--no-figures"]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1
    assert "layer[0].initiate" in err and "after t_end" in err


def test_detonation_into_a_gap():
    """A plate moving away from an unbonded charge opens a gap at once; the detonation
    reaches the gap's face, the products expand into the gap at their escape speed (D for
    gamma = 3: u_CJ + 2 c_CJ/(gamma - 1) = D/4 + 3D/4) and close it on the plate, which
    they then drive.  Well defined, so it runs (it is no error)."""
    d = math.sqrt(16.0 * Q)
    scene = ft.Scene([ft.Layer(CHARGE, "3 mm", initiate="left"),
                      ft.Layer(PLATE, "1 mm", velocity="200 m/s", bond="unbonded")],
                     left=ft.Boundary("wall"), t_end="0.6 us", accuracy=ACCURACY)
    solution = ft.run(scene)
    kinds = [e.kind for e in solution.events]
    assert "gap-open" in kinds and "gap-close" in kinds
    closing = next(e for e in solution.events if e.kind == "gap-close")
    arrival = 3e-3 / d
    gap = 200.0 * arrival
    # the products' vacuum front crosses the gap at ~D (less the plate's 200 m/s)
    assert closing.t == pytest.approx(arrival + gap / (d - 200.0), rel=0.05)
    assert solution.state_at(2.9e-3, 0.6e-6).plastic_strain == BURNT
    assert plate_velocity(solution, 1, 0.6e-6) > 400.0
    _check_balance(solution)
