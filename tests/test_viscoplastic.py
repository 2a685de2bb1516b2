"""Elastic–viscoplastic layer on its characteristic grid (``materials.viscoplastic``,
``characteristics.viscoplastic_grid``).

References: the precursor decay law ``d sigma_p / dX = -(mu / C0) phi(S_p)`` integrated
here with scipy's ``solve_ivp`` (DOP853, rtol 1e-12); the rate-independent limit from
the elastic–plastic wave curve of ``materials.elastic_plastic`` (a different model
class and code path) with scipy's ``brentq``; the elastic limit in closed form.
Davison's steel (PHYSICS.md): lambda = 123.1 GPa, mu = 79.29 GPa, rho0 = 7870, Y = 1 GPa.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

from characteristics.viscoplastic_grid import run_layer
from materials import RIGHT, ElasticPlastic, MaterialError
from materials.viscoplastic import Viscoplastic

RHO, LAM, MU, Y = 7870.0, 123.1e9, 79.29e9, 1.0e9
U0, THICK = 300.0, 4.0e-3


def steel(tau, n=1.0) -> Viscoplastic:
    return Viscoplastic("steel", RHO, LAM, MU, Y, tau, n)


def precursor_reference(mat: Viscoplastic, x: float) -> float:
    """The decay law from sigma_p(0) = Z u0, integrated by scipy."""
    m, c0, s_y = mat.modulus, mat.C0, 2.0 * Y / 3.0

    def rhs(_, s):
        over = max(4.0 * MU * s[0] / (3.0 * m) / s_y - 1.0, 0.0)
        return [-(MU / c0) * s_y / (2.0 * MU * mat.relaxation_time) * over**mat.rate_exponent]

    return solve_ivp(rhs, (0.0, x), [mat.impedance * U0], method="DOP853", rtol=1e-12,
                     atol=1e-3).y[0, -1]


@pytest.mark.parametrize("n", [1.0, 2.0])
def test_precursor_decay_is_second_order_against_the_ode(n):
    """Amplitude at X = 2 mm: the error falls by 4 per halving of the grid spacing."""
    mat = steel(50e-9, n)
    x = 2.0e-3
    reference = precursor_reference(mat, x)
    errors = []
    for cells in (50, 100, 200):
        run = run_layer(mat, THICK, U0, 0.4e-6, cells)
        k = int(np.argmin(np.abs(run.precursor_x - x)))
        assert run.precursor_x[k] == pytest.approx(x, rel=1e-12)
        errors.append(run.precursor_sigma[k] - reference)
    ratios = [errors[0] / errors[1], errors[1] / errors[2]]
    assert ratios == pytest.approx([4.0, 4.0], rel=0.03)
    assert abs(errors[-1]) < 2e-4 * reference
    # it decays toward the HEL and stays above it
    assert mat.hel < reference < mat.impedance * U0


def elastic_plastic_state(u0: float) -> float:
    """Stress behind the elastic–plastic split wave driven at u0 (wave curve + brentq)."""
    ep = ElasticPlastic("steel", RHO, LAM, MU, Y)
    curve = ep.wave_curve(ep.reference_state(), RIGHT)
    return brentq(lambda s: curve.velocity_change(s)[0] - u0, 0.0, 50e9, xtol=1e-6,
                  rtol=1e-15)


def test_zero_relaxation_time_is_the_elastic_plastic_solution():
    mat = steel(0.0)
    run = run_layer(mat, THICK, U0, 0.6e-6, 200)
    # the precursor drops to the HEL at its first step and stays there
    assert np.all(np.abs(run.precursor_sigma[1:] - mat.hel) <= 1e-12 * mat.hel)
    # behind the plastic wave: the elastic-plastic state (before any reflection returns)
    t, sigma = run.history(1.0e-3, "sigma")
    _, u = run.history(1.0e-3, "u")
    late = (t > 0.45e-6) & (t < 0.55e-6)
    target = elastic_plastic_state(U0)
    assert np.all(np.abs(sigma[late] - target) <= 1e-9 * target)
    assert np.all(np.abs(u[late] - U0) <= 1e-9 * U0)


def test_short_relaxation_time_approaches_the_elastic_plastic_solution():
    """tau = 1 ns: the precursor's overstress decays as exp(-2 mu t / (3 M tau)), ~e^-60
    at 2 mm, so it carries the HEL there to the grid's rounding."""
    mat = steel(1e-9)
    run = run_layer(mat, THICK, U0, 0.6e-6, 200)
    k = int(np.argmin(np.abs(run.precursor_x - 2.0e-3)))
    assert run.precursor_sigma[k] == pytest.approx(mat.hel, rel=1e-9)


@pytest.mark.parametrize("tau", [math.inf, 1.0])
def test_long_relaxation_time_is_elastic(tau):
    """tau = inf: nothing relaxes, the grid is exact; tau = 1 s: within t/tau ~ 1e-6."""
    mat = steel(tau)
    run = run_layer(mat, THICK, U0, 1.0e-6, 100)
    tol = 1e-12 if math.isinf(tau) else 1e-5
    assert run.precursor_sigma == pytest.approx(mat.impedance * U0, rel=tol)
    t, u = run.free_surface_velocity()
    arrived = (t > THICK / mat.C0 + 1e-9) & (t < 3.0 * THICK / mat.C0 - 1e-9)
    assert arrived.sum() > 10
    assert u[arrived] == pytest.approx(2.0 * U0, rel=tol)
    assert np.all(u[t < THICK / mat.C0 - 1e-9] == 0.0)


def test_bad_input_names_the_field():
    with pytest.raises(MaterialError, match="relaxation_time"):
        steel(-1e-9)
    with pytest.raises(MaterialError, match="rate_exponent"):
        steel(1e-9, 0.5)
    with pytest.raises(MaterialError, match="cells"):
        run_layer(steel(1e-9), THICK, U0, 1e-6, 7)
