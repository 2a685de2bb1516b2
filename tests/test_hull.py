"""The hull construction as a wave curve (``materials.hull``) on the saturating-hardening
solid (``materials.saturating_plastic``).

Reference values are computed here independently: the loading path from the model's
equations with scipy's ``brentq`` (not the module's Newton iterations), the tangent
chord with ``brentq`` on the tangency condition, fan integrals with ``quad``.
"""

from __future__ import annotations

import math
import random
import tomllib

import pytest
from engine_helpers import assert_no_nan, assert_shock_jumps, assert_wave_jumps
from scipy.integrate import quad
from scipy.optimize import brentq

from fronttrack.runner import run
from fronttrack.scene import Accuracy, Layer, Scene
from fronttrack.scene_file import scene_from_dict
from materials import LEFT, RIGHT, Fan, MaterialError, Shock, material_from_spec
from materials.saturating_plastic import SaturatingPlastic

# Illustrative numbers (aluminium-like pressure; a strong, fast-saturating hardening
# that makes the plastic branch concave beyond the HEL): not a fit to a metal.
RHO, C0, S, G = 2700.0, 5350.0, 1.34, 26.0e9
Y0, YS, ES = 0.3e9, 0.8e9, 0.002
K = RHO * C0 * C0


def solid(**kwargs) -> SaturatingPlastic:
    return SaturatingPlastic("Al-Voce", RHO, C0, S, G, Y0, YS, ES, **kwargs)


def path_stress(eps: float) -> float:
    """Monotone loading from the virgin state, from the equations (scipy root)."""
    p = K * eps / (1.0 - S * eps) ** 2
    if 4.0 * G * eps / 3.0 <= 2.0 * Y0 / 3.0:
        return p + 4.0 * G * eps / 3.0

    def flow(bar):
        return YS - (YS - Y0) * math.exp(-bar / ES)

    bar = brentq(lambda b: 4.0 * G * eps / 3.0 - 2.0 * G * b - 2.0 * flow(b) / 3.0,
                 0.0, eps, xtol=1e-18, rtol=1e-15)
    return p + 2.0 * flow(bar) / 3.0


def path_slope(eps: float, h: float = 1e-7) -> float:
    return (path_stress(eps + h) - path_stress(eps - h)) / (2.0 * h)


def path_strain(sigma: float) -> float:
    return brentq(lambda e: path_stress(e) - sigma, 0.0, 0.5, xtol=1e-18, rtol=1e-15)


def test_shock_fan_shock_with_the_tangent_chord():
    """3 GPa from rest: precursor to the HEL, a plastic fan on the concave stretch, and a
    plastic shock whose chord to the final state touches the path where the fan ends."""
    mat = solid()
    sigma = 3.0e9
    precursor, fan, shock = mat.wave_curve(mat.reference_state(), RIGHT).waves(sigma)
    assert isinstance(precursor, Shock) and isinstance(fan, Fan) and isinstance(shock, Shock)
    eps_hel = Y0 / (2.0 * G)
    assert precursor.behind.sigma == pytest.approx(path_stress(eps_hel), rel=1e-13)
    assert_wave_jumps(precursor, RHO)
    assert_wave_jumps(shock, RHO)
    eps_b = path_strain(sigma)

    def tangency(e):
        return path_slope(e) * (eps_b - e) - (sigma - path_stress(e))

    eps_t = brentq(tangency, 1.01 * eps_hel, 0.99 * eps_b, xtol=1e-16)
    assert 1.0 - shock.ahead.v * RHO == pytest.approx(eps_t, rel=1e-7)   # central differences
    chord = math.sqrt((sigma - path_stress(eps_t)) / (eps_b - eps_t) / RHO)
    assert shock.speed == pytest.approx(chord, rel=1e-7)
    assert abs(fan.tail_speed) == pytest.approx(shock.speed, rel=1e-9)   # tangent: equal
    # the fan's velocity jump against an independent quadrature of sqrt(sigma'/rho0)
    du = quad(lambda e: math.sqrt(path_slope(e) / RHO), eps_hel, eps_t, epsabs=0,
              epsrel=1e-11, limit=200)[0]
    assert fan.behind.u - fan.ahead.u == pytest.approx(du, rel=1e-6)


def test_weak_plastic_load_is_precursor_and_fan_strong_load_one_shock():
    mat = solid()
    curve = mat.wave_curve(mat.reference_state(), RIGHT)
    kinds = [type(w).__name__ for w in curve.waves(1.0e9)]
    assert kinds == ["Shock", "Fan"]
    (single,) = curve.waves(20.0e9)   # faster than the elastic precursor: overdriven
    assert single.speed > mat.C_elastic
    assert_wave_jumps(single, RHO)


@pytest.mark.parametrize("seed", range(4))
def test_wave_curve_properties(seed):
    """Monotone curve, ordered waves, jump conditions, dissipation never negative."""
    rng = random.Random(seed)
    mat = solid()
    start = mat.wave_curve(mat.reference_state(), RIGHT).state_at(rng.uniform(1.0e9, 6.0e9))
    for direction in (RIGHT, LEFT):
        curve = mat.wave_curve(start, direction)
        targets = sorted(rng.uniform(-1.0e9, 12.0e9) for _ in range(6))
        g = [curve.velocity_change(t)[0] for t in targets]
        assert all(b > a for a, b in zip(g[:-1], g[1:], strict=True))
        for t in targets:
            waves = curve.waves(t)
            speeds = [abs(w.speed) if isinstance(w, Shock) else abs(w.head_speed)
                      for w in waves]
            assert all(b <= a * (1 + 1e-12) for a, b in zip(speeds[:-1], speeds[1:], strict=True))
            for w in waves:
                if isinstance(w, Shock):
                    assert_wave_jumps(w, RHO)
                gain = mat.dissipated_energy(w.behind) - mat.dissipated_energy(w.ahead)
                assert gain >= -1e-9 * abs(w.behind.e - w.ahead.e) - 1e-9
            # plastic strain never unwinds: eps_bar only grows
            assert waves[-1].behind.equivalent_plastic_strain >= (
                getattr(start, "equivalent_plastic_strain", 0.0) - 1e-15)


def test_bad_input_names_the_field():
    with pytest.raises(MaterialError, match="saturation_strength"):
        SaturatingPlastic("x", RHO, C0, S, G, Y0, 0.5 * Y0, ES)
    with pytest.raises(MaterialError, match="saturation_strain"):
        SaturatingPlastic("x", RHO, C0, S, G, Y0, YS, -1.0)
    with pytest.raises(MaterialError, match="saturation_strain"):
        material_from_spec("x", {"model": "saturating-plastic", "rho0": RHO, "c0": C0,
                                 "s": S, "shear_modulus": G, "yield_strength": Y0,
                                 "saturation_strength": YS})


def test_engine_runs_the_split_wave_exactly():
    """Plate impact at 300 m/s through the engine: the split waves satisfy the jump
    conditions to 1e-12 and the free-surface-bound precursor carries the HEL."""
    mat = solid()
    scene = Scene(layers=(Layer(mat, 1.0e-3, 300.0), Layer(mat, 4.0e-3, 0.0, bond="unbonded")),
                  t_end=0.25e-6, accuracy=Accuracy(rays_per_fan=4))
    solution = run(scene)
    assert_no_nan(solution)
    assert assert_shock_jumps(solution) >= 2
    hel = path_stress(Y0 / (2.0 * G))
    sigmas = {round(r.state.sigma / hel, 9) for r in solution.regions}
    assert 1.0 in sigmas


SCENE_TOML = """
title = "Voce-hardening aluminium-like plate impact"
t_end = "0.2 us"

[materials.voce]
model = "saturating-plastic"
rho0 = "2700 kg/m3"
c0 = "5350 m/s"
s = 1.34
shear_modulus = "26 GPa"
yield_strength = "0.3 GPa"
saturation_strength = "0.8 GPa"
saturation_strain = 0.002

[accuracy]
rays_per_fan = 3

[[layer]]
material = "voce"
thickness = "1 mm"
velocity = "400 m/s"

[[layer]]
material = "voce"
thickness = "3 mm"
bond = "unbonded"
"""


def test_scene_file_with_the_material_runs():
    scene = scene_from_dict(tomllib.loads(SCENE_TOML))
    assert isinstance(scene.layers[0].material, SaturatingPlastic)
    solution = run(scene)
    assert_no_nan(solution)
    assert assert_shock_jumps(solution) >= 2
    kinds = {f.kind for f in solution.fronts}
    assert "shock" in kinds and len(kinds) >= 2
