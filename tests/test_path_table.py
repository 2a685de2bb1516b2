"""Chebyshev path tables (``materials.path_table``) against closed forms and quadrature.

A table replaces, on each panel of a continuous wave path, the stress and the sound
speed by their Chebyshev interpolants and the path integral ``J = int rho0 C dv`` by the
interpolant's exact integral.  For paths analytic well beyond each panel (the
finite-plastic release paths) that is exact to rounding: these tests hold it to 1e-13
(stress) and 1e-12 (``J``, against adaptive quadrature of the closed-form speed) over
random states, panels and volumes.
"""

from __future__ import annotations

import math
import random

import numpy as np
import pytest
from scipy.integrate import quad

from materials import LEFT, RIGHT, FinitePlastic, State
from materials.path_table import PathTable, panel_integral, panel_nodes

RHO = 2703.0
V0 = 1.0 / RHO


def _exponential(k: float, amplitude: float):
    """``sigma = A exp(-k (v - v0))``: ``C = v0 sqrt(A k) exp(-k (v - v0)/2)``, and
    ``J = rho0 int C dv = sqrt(A k) (2/k) (exp(-k (v_s - v0)/2) - exp(-k (v - v0)/2))``."""
    def sample(p0, p1):
        v = panel_nodes(p0, p1)
        sigma = amplitude * np.exp(-k * (v - V0))
        return sigma, V0 * np.sqrt(amplitude * k * np.exp(-k * (v - V0)))

    def exact(v_s, v):
        sigma = amplitude * math.exp(-k * (v - V0))
        j = math.sqrt(amplitude * k) * (2.0 / k) * (
            math.exp(-k * (v_s - V0) / 2.0) - math.exp(-k * (v - V0) / 2.0))
        return sigma, -amplitude * k * math.exp(-k * (v - V0)), j

    return sample, exact


@pytest.mark.parametrize("seed", range(4))
def test_table_of_a_closed_form_path_over_several_panels(seed):
    rng = random.Random(seed)
    k = rng.uniform(2.0, 8.0) / V0            # stress e-folds over 0.12-0.5 v0
    sample, exact = _exponential(k, rng.uniform(1e9, 5e10))
    start = V0 * rng.uniform(0.8, 1.1)
    direction = rng.choice([-1.0, 1.0])
    end = start + direction * 0.3 * V0
    table = PathTable(sample, start, end, 0.05 * V0, RHO)
    volumes = [start + direction * rng.uniform(0.0, 0.3) * V0 for _ in range(40)]
    for v in [start, end, *volumes]:
        sigma, slope, j = exact(start, v)
        got_sigma, got_slope = table.stress(v)
        assert got_sigma == pytest.approx(sigma, rel=1e-13)
        assert got_slope == pytest.approx(slope, rel=1e-12)
        assert table.integral(v) == pytest.approx(j, rel=1e-12, abs=1e-13 * abs(
            exact(start, end)[2]))
    assert len(table._panels) == 6               # 0.3 v0 in panels of 0.05 v0


def test_panel_integral_is_spectral_integration():
    # int_{p0}^{w} cos(k v) dv = (sin(k w) - sin(k p0)) / k on a panel k (p1 - p0) = 1.5
    p0, p1, k = 0.3, 0.8, 3.0
    w = panel_nodes(p0, p1)
    exact = (np.sin(k * w) - math.sin(k * p0)) / k
    assert panel_integral(np.cos(k * w), p0, p1) == pytest.approx(exact, rel=1e-14, abs=1e-15)
    assert w.min() > p0 and w.max() < p1


def test_within_admits_built_panels_only():
    sample, _ = _exponential(4.0 / V0, 1e10)
    table = PathTable(sample, V0, 1.5 * V0, 0.05 * V0, RHO)
    assert table.within(1.01 * V0) and not table.within(1.06 * V0)
    assert not table.within(0.99 * V0) and not table.within(1.6 * V0)
    table.stress(1.01 * V0)                       # builds the first panel
    assert table.within(1.049 * V0) and not table.within(1.051 * V0)
    table.integral(1.12 * V0)                     # the integral extends the table
    assert table.within(1.149 * V0) and len(table._panels) == 3


# --- finite-plastic release paths ----------------------------------------------------------
AL = FinitePlastic("Al6061", RHO, 5350.0, 1.34, 2.0, 26.0e9, 0.29e9)
HARD = FinitePlastic("Al-hardening", RHO, 5350.0, 1.34, 2.0, 26.0e9, 0.29e9, hardening=1e9)


def _random_release(rng):
    """A release curve from a random state: shocked from rest (1-25 GPa), then possibly
    released part way along an isentropic path, facing left or right."""
    material = rng.choice([AL, HARD])
    state = material.wave_curve(material.reference_state(), RIGHT).state_at(
        rng.uniform(1e9, 25e9))
    if rng.random() < 0.5:
        state = material.wave_curve(state, LEFT).state_at(state.sigma * rng.uniform(0.0, 0.9))
    return material, material.wave_curve(state, rng.choice([LEFT, RIGHT]))


def _quadrature(curve, v_from, v_to):
    """``int rho0 C dv`` of the closed-form characteristic speed along the fan path."""
    rho0 = curve.material.rho0
    value, _ = quad(lambda v: rho0 * curve.point_at_volume(v, shock=False).speed,
                    v_from, v_to, epsabs=0.0, epsrel=2e-14, limit=200)
    return value


@pytest.mark.parametrize("seed", range(12))
def test_release_fans_agree_with_quadrature_of_the_closed_form_path(seed):
    rng = random.Random(1000 + seed)
    material, curve = _random_release(rng)
    a = curve.ahead
    for _ in range(6):
        sigma = a.sigma - rng.uniform(0.0, 1.0) ** 2 * (a.sigma + 2e9)
        state = curve.state_at(sigma)
        g = curve.velocity_change(sigma)[0]
        v_knee = curve._v_low
        if state.v <= v_knee:
            expected = -_quadrature(curve, a.v, state.v)
        else:
            expected = -(_quadrature(curve, a.v, v_knee) + _quadrature(curve, v_knee, state.v))
        assert g == pytest.approx(expected, rel=1e-12, abs=1e-12)
        # the state is the closed-form path's at the volume the table's root gave
        point = curve.point_at_volume(state.v, shock=False)
        assert state.sigma == pytest.approx(point.sigma, rel=1e-13, abs=1e-13 * abs(a.sigma))
        assert state.e == point.e and state.plastic_strain == point.plastic_strain
        # and the table's stress and slope are the closed form's to rounding
        branch = "plastic-down" if state.v > v_knee else "elastic"
        table = curve._table(branch, expanding=True)
        for v in np.linspace(table.start, state.v, 5)[1:].tolist():
            p = curve.point_at_volume(v, shock=False)
            t_sigma, t_slope = table.stress(v)
            assert t_sigma == pytest.approx(p.sigma, rel=1e-13, abs=1e-13 * abs(a.sigma))
            assert t_slope == pytest.approx(p.slope, rel=1e-12)
    # the slope of g is 1/(rho0 C) at the state behind, as the closed form says
    sigma = 0.5 * a.sigma - 1e8
    speed = curve.characteristic_speed(sigma)
    assert curve.velocity_change(sigma)[1] == pytest.approx(1.0 / (material.rho0 * speed),
                                                            rel=1e-12)


# --- panels and curve bases shared between tables and curves of one path ----------------
def test_tables_of_one_path_share_panels_but_each_reaches_only_as_asked():
    sample, _ = _exponential(4.0 / V0, 1e10)
    calls = []

    def counted(p0, p1):
        calls.append(p0)
        return sample(p0, p1)

    store: list = []
    first = PathTable(counted, V0, 1.5 * V0, 0.05 * V0, RHO, store=store)
    first.integral(1.12 * V0)                      # three panels sampled
    assert len(calls) == 3 and len(store) == 3
    second = PathTable(counted, V0, 1.5 * V0, 0.05 * V0, RHO, store=store)
    alone = PathTable(sample, V0, 1.5 * V0, 0.05 * V0, RHO)
    # the second table has asked nothing yet: it reaches its first panel only, as
    # a table of its own would (the closed form answers beyond, in a root search)
    assert second.within(1.049 * V0) and not second.within(1.051 * V0)
    for v in (1.01 * V0, 1.07 * V0, 1.12 * V0, 1.22 * V0):
        assert second.stress(v) == alone.stress(v)
        assert second.integral(v) == alone.integral(v)
    assert len(calls) == 5                          # only the two beyond the first's reach
    assert second.within(1.249 * V0) and not second.within(1.251 * V0)


def _without_curves(waves) -> list:
    """Waves as their states and speeds (a fan also names the curve it came from)."""
    return [(type(w), w.ahead, w.behind, getattr(w, "speed", None),
             getattr(w, "head_speed", None), getattr(w, "tail_speed", None)) for w in waves]


def test_curves_of_one_ahead_state_share_their_basis_and_answer_as_alone():
    """Two curves from one state of one material share what the state fixes (knees, path
    panels), and answer bit for bit as a curve of an unshared copy of the material."""
    def solid():
        return FinitePlastic("Al6061", RHO, 5350.0, 1.34, 2.0, 26.0e9, 0.29e9)

    shared, alone = solid(), solid()
    shocked = shared.wave_curve(shared.reference_state(), RIGHT).state_at(12e9)
    ahead = shared.wave_curve(shocked, LEFT).state_at(4e9)
    stresses = [3.9e9, 2e9, 1e8, -5e8, 4.5e9, 9e9]
    first = shared.wave_curve(ahead, LEFT)
    for sigma in stresses[::-1]:
        first.velocity_change(sigma)
    second = shared.wave_curve(ahead, RIGHT)
    assert second._knee_down is first._knee_down and second._panel_stores is first._panel_stores
    built = sum(len(store) for store in first._panel_stores.values())
    reference = alone.wave_curve(ahead, RIGHT)
    for sigma in stresses:
        assert second.velocity_change(sigma) == reference.velocity_change(sigma)
        assert second.state_at(sigma) == reference.state_at(sigma)
        assert _without_curves(second.waves(sigma)) == _without_curves(reference.waves(sigma))
    assert sum(len(store) for store in first._panel_stores.values()) == built
    # a zero of either sign is its own key: the knees keep the sign of their stress
    rest = shared.reference_state()
    assert rest.sigma == 0.0
    negative = State(-0.0, rest.u, rest.v, rest.e, rest.plastic_strain)
    assert shared.wave_curve(negative, RIGHT)._start is not \
        shared.wave_curve(rest, RIGHT)._start
