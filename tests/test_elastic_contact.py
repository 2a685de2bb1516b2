"""The elastic Riemann problem of one elastic–plastic solid (``materials.elastic_contact``).

Davison's steel (Davison, *Fundamentals of Shock Wave Propagation in Solids*, ch. 7:
rho0 = 7870 kg/m^3, lambda = 123.1 GPa, mu = 79.29 GPa, Y = 1 GPa).  The closed form is
checked against the general solver of ``materials.riemann``, reached with a second,
equal material object (the closed form applies only to one material), and against the
acoustic jump conditions written out by hand.
"""

from __future__ import annotations

import dataclasses
import math

import pytest

from materials import ElasticPlastic, solve_contact
from materials.elastic_contact import elastic_contact
from materials.state import LEFT, RIGHT


def steel() -> ElasticPlastic:
    return ElasticPlastic("Davison steel", 7870.0, 123.1e9, 79.29e9, 1e9, spall_strength=2e9)


STEEL, TWIN = steel(), steel()


def state(sigma_peak: float, sigma: float, u: float):
    """A state loaded along the right-going wave curve to ``sigma_peak`` (Pa; beyond the
    HEL it yields), then unloaded elastically to ``sigma``, moving at ``u`` (m/s)."""
    loaded = STEEL.wave_curve(STEEL.reference_state(), RIGHT).state_at(sigma_peak)
    unloaded = STEEL.wave_curve(loaded, LEFT).state_at(sigma) if sigma != sigma_peak else loaded
    return dataclasses.replace(unloaded, u=u)


# (left, right): elastic on both sides, including states on the yield surface unloading
# and states with different plastic strains (a plastic-strain contact)
ELASTIC_PAIRS = [
    (state(0.0, 0.0, 10.0), state(0.0, 0.0, 0.0)),
    (state(3e9, 3e9, 50.0), state(3e9, 3e9, 80.0)),
    (state(3e9, 2.2e9, 61.0), state(2.5e9, 2.3e9, 60.0)),
    (state(4e9, 1.0e9, 120.0), state(1.2e9, 0.4e9, 118.5)),
    (state(2.5e9, 0.3e9, -5.0), state(2.5e9, 0.3e9, -5.0)),
]


@pytest.mark.parametrize("left, right", ELASTIC_PAIRS)
def test_elastic_contact_agrees_with_the_general_solver(left, right):
    assert elastic_contact(STEEL, left, right, -math.inf) is not None
    fast = solve_contact(STEEL, left, STEEL, right, 2e9)
    general = solve_contact(STEEL, left, TWIN, right, 2e9)
    # one linear piece each side: the general solver's root is exact up to rounding
    scale = abs(left.sigma) + abs(right.sigma) + 1e6
    assert fast.bonded_sigma == pytest.approx(general.bonded_sigma, abs=1e-12 * scale)
    for a, b in ((fast.left_star, general.left_star), (fast.right_star, general.right_star)):
        assert a.sigma == pytest.approx(b.sigma, abs=1e-12 * scale)
        assert a.u == pytest.approx(b.u, abs=1e-9)
        assert a.v == pytest.approx(b.v, rel=1e-14)
        assert a.e == pytest.approx(b.e, abs=1e-9 * (abs(b.e) + 1.0))
        assert a.plastic_strain == b.plastic_strain
    # the general solver may send a wave of rounding strength where nothing moves
    for fast_waves, general_waves in ((fast.left_waves, general.left_waves),
                                      (fast.right_waves, general.right_waves)):
        real = [w.speed for w in general_waves
                if abs(w.behind.sigma - w.ahead.sigma) > 1e-12 * scale]
        assert [w.speed for w in fast_waves] == real
    assert not fast.separated


def test_symmetric_impact_below_the_hel_by_hand():
    # 10 m/s onto a plate at rest: sigma* = Z0 u / 2 with Z0 = sqrt(rho0 (lambda + 2 mu))
    impedance = math.sqrt(7870.0 * (123.1e9 + 2 * 79.29e9))
    left, right = state(0.0, 0.0, 10.0), state(0.0, 0.0, 0.0)
    left_waves, right_waves, left_star, right_star, sigma = elastic_contact(
        STEEL, left, right, -math.inf)
    assert sigma == pytest.approx(0.5 * impedance * 10.0, rel=1e-14)
    assert left_star.u == pytest.approx(5.0, rel=1e-14)
    assert right_star.u == pytest.approx(5.0, rel=1e-14)
    # each wave: elastic speed and the momentum jump sigma_b - sigma_a = d Z0 (u_b - u_a)
    # (compression positive: a right-going compression speeds the material up)
    (left_wave,), (right_wave,) = left_waves, right_waves
    assert right_wave.speed == pytest.approx(impedance / 7870.0, rel=1e-14)
    assert left_wave.speed == -right_wave.speed
    for wave, d in ((left_wave, -1), (right_wave, 1)):
        a, b = wave.ahead, wave.behind
        assert b.sigma - a.sigma == pytest.approx(d * impedance * (b.u - a.u), rel=1e-12)
        # energy: the Rankine–Hugoniot trapezoid, the elastic strain energy v0 sigma^2/(2M)
        assert b.e - a.e == pytest.approx(0.5 * (a.sigma + b.sigma) * (a.v - b.v), rel=1e-12)
        assert b.e == pytest.approx(sigma**2 / (2 * impedance**2), rel=1e-9)


def test_a_side_that_yields_goes_to_the_general_solver():
    # 300 m/s onto steel at rest: about 7 GPa, far beyond the HEL (about 1.8 GPa)
    left, right = state(0.0, 0.0, 300.0), state(0.0, 0.0, 0.0)
    assert elastic_contact(STEEL, left, right, -math.inf) is None
    solution = solve_contact(STEEL, left, STEEL, right, 2e9)
    assert len(solution.right_waves) == 2  # elastic precursor and plastic shock


def test_a_tension_beyond_the_floor_goes_to_the_general_solver():
    # releases meeting at 2 x 20 m/s apart pull Z0 x 20 m/s = 0.94 GPa, beyond 0.5 GPa
    left, right = state(0.0, 0.0, -20.0), state(0.0, 0.0, 20.0)
    assert elastic_contact(STEEL, left, right, -0.5e9) is None
    assert elastic_contact(STEEL, left, right, -2e9) is not None
    assert solve_contact(STEEL, left, STEEL, right, 0.5e9).separated
    assert not solve_contact(STEEL, left, STEEL, right, 2e9).separated
