"""Shock-only scenes against closed forms, to 1e-12 relative.

Linear elastic solids carry every wave as a jump at exactly ``C``, and a
Mie–Grüneisen solid released along its Hugoniot ("hugoniot" release) has only
shocks, so these scenes have no discretisation at all: every state is an
impedance-match value and every arrival time a sum of transit times.
"""

from __future__ import annotations

import pytest
from engine_helpers import (
    assert_contacts_continuous,
    assert_no_nan,
    assert_shock_jumps,
)

from fronttrack.runner import run
from fronttrack.scene import Accuracy, Boundary, Layer, Probe, Scene
from materials import LinearElastic, MieGruneisen

EXACT = Accuracy(release="hugoniot", negligible_stress=0.0)


def elastic(name, rho0, c, strength=float("inf")):
    return LinearElastic(name, rho0, c, spall_strength=strength)


def test_elastic_impact_first_states_and_arrival_times():
    """Flyer A at V on target B: sigma1 = Z_A Z_B V / (Z_A + Z_B), u1 = Z_A V / (Z_A + Z_B)."""
    a, b = elastic("A", 2700.0, 6000.0), elastic("B", 8900.0, 4700.0)
    d_a, d_b, v = 1e-3, 4e-3, 500.0
    scene = Scene(layers=(Layer(a, d_a, v), Layer(b, d_b, bond="unbonded")),
                  t_end=1.5 * d_a / a.C, probes=(Probe("rear", "right"), Probe("back", "left")),
                  accuracy=EXACT)
    sol = run(scene)
    za, zb = a.impedance, b.impedance
    sigma1, u1 = za * zb * v / (za + zb), za * v / (za + zb)
    shocked = sol.state_at(d_a, 0.5 * d_a / a.C)
    assert shocked.sigma == pytest.approx(sigma1, rel=1e-12)
    assert shocked.u == pytest.approx(u1, rel=1e-12)
    # the flyer's back face: still at V until the shock arrives at d_a / C_A, then 2 u1 - V
    back = sol.history("left")
    assert back.t[1] == pytest.approx(d_a / a.C, rel=1e-12)
    assert back.u[0] == v
    assert back.u[1] == pytest.approx(2.0 * u1 - v, rel=1e-12)
    assert back.sigma[1] == 0.0
    assert_shock_jumps(sol)


def test_identical_elastic_plates_exchange_momentum():
    """Equal elastic plates: the flyer stops and the target leaves at V at t = 2 d / C."""
    m = elastic("M", 7870.0, 5900.0)
    d, v = 2e-3, 300.0
    scene = Scene(layers=(Layer(m, d, v), Layer(m, d, bond="unbonded")), t_end=5 * d / m.C,
                  probes=(Probe("rear", "right"),), accuracy=EXACT)
    sol = run(scene)
    late = 4.5 * d / m.C
    assert sol.state_at(0.5 * d, late).u == pytest.approx(0.0, abs=1e-12 * v)
    assert sol.state_at(1.5 * d, late).u == pytest.approx(v, rel=1e-12)
    assert sol.state_at(1.5 * d, late).sigma == pytest.approx(0.0, abs=1e-12 * m.impedance * v)
    rear = sol.history("right")
    assert rear.t[1] == pytest.approx(d / m.C, rel=1e-12)
    assert rear.u[1] == pytest.approx(v, rel=1e-12)
    assert any(e.kind == "gap-open" for e in sol.events)
    c = sol.conservation()
    assert c["momentum_relative_error"] < 1e-12
    assert c["energy_relative_error"] < 1e-12


@pytest.mark.parametrize("name, rho0, c0, s, gamma0, velocity", [
    ("Cu", 8930.0, 3940.0, 1.489, 1.99, 1000.0),
    ("Al", 2703.0, 5350.0, 1.34, 2.0, 2500.0),
    ("W", 19224.0, 4029.0, 1.237, 1.54, 400.0),
    # very weak: 1 mm/s (22 kPa, volume jump 1.3e-7, below the chord's resolution) and
    # 1 nm/s; very strong: 6 km/s in Cu (330 GPa, compression 1.5)
    ("Cu", 8930.0, 3940.0, 1.489, 1.99, 1e-3),
    ("Cu", 8930.0, 3940.0, 1.489, 1.99, 1e-9),
    ("Cu", 8930.0, 3940.0, 1.489, 1.99, 6000.0),
])
def test_symmetric_impact_hugoniot_release(name, rho0, c0, s, gamma0, velocity):
    """u = V/2 and sigma = rho0 (c0 + s V/2) V/2 behind both shocks; the rear free surface
    then moves at exactly V; momentum and energy balance to 1e-12."""
    m = MieGruneisen(name, rho0, c0, s, gamma0)
    d = 1e-3
    scene = Scene(layers=(Layer(m, d, velocity), Layer(m, 3 * d, bond="unbonded")),
                  t_end=1.1 * 3 * d / (c0 + s * velocity / 2), probes=(Probe("rear", "right"),),
                  accuracy=EXACT)
    sol = run(scene)
    up = velocity / 2.0
    us = c0 + s * up
    shocked = sol.state_at(d + 1e-6 * d, 1e-3 * d / us)
    assert shocked.u == pytest.approx(up, rel=1e-12)
    assert shocked.sigma == pytest.approx(rho0 * us * up, rel=1e-12)
    rear = sol.history("right")
    assert rear.t[1] == pytest.approx(3 * d / us, rel=1e-12)
    assert rear.u[1] == pytest.approx(velocity, rel=1e-12)
    c = sol.conservation()
    assert c["momentum_relative_error"] < 1e-12 and c["energy_relative_error"] < 1e-12
    assert_shock_jumps(sol)
    assert_no_nan(sol)


def test_shock_only_conservation_to_1e12():
    """Multi-layer Hugoniot-release scene with walls and free ends: mass, momentum, energy."""
    cu = MieGruneisen("Cu", 8930.0, 3940.0, 1.489, 1.99)
    al = MieGruneisen("Al", 2703.0, 5350.0, 1.34, 2.0)
    pmma = MieGruneisen("PMMA", 1186.0, 2598.0, 1.516, 0.97)
    scene = Scene(layers=(Layer(al, 1e-3, 800.0), Layer(cu, 2e-3), Layer(pmma, 0.5e-3),
                          Layer(al, 2e-3)),
                  t_end=0.9e-6, left=Boundary("free"), right=Boundary("wall"), accuracy=EXACT)
    sol = run(scene)
    assert sol.stats["events"] > 10
    for t in (0.3e-6, 0.6e-6, 0.9e-6):
        c = sol.conservation(t)
        assert c["mass"] == pytest.approx(sum(l_.material.rho0 * l_.thickness
                                             for l_ in scene.layers), rel=1e-15)
        assert c["momentum_relative_error"] < 1e-12
        assert c["energy_relative_error"] < 1e-12
    assert_shock_jumps(sol)
    assert_contacts_continuous(sol)
    assert_no_nan(sol)


def test_wall_reflection_doubles_elastic_stress():
    """A layer moving at V onto a rigid wall: sigma = Z V, then u = 0 behind the reflection."""
    m = elastic("M", 2649.0, 5749.0)
    d, v = 5e-3, 100.0
    scene = Scene(layers=(Layer(m, d, v),), t_end=1.5 * d / m.C, right=Boundary("wall"),
                  accuracy=EXACT)
    sol = run(scene)
    s = sol.state_at(0.9 * d, 0.5 * d / m.C)
    assert s.u == 0.0
    assert s.sigma == pytest.approx(m.impedance * v, rel=1e-12)
    back = sol.state_at(0.1 * d, 1.2 * d / m.C)
    assert back.sigma == pytest.approx(0.0, abs=1e-12 * m.impedance * v)
    assert back.u == pytest.approx(-v, rel=1e-12)
