"""Pullback analysis of free-surface records (``fronttrack.pullback``).

Exact checks in linear elastic solids, where every wave runs at one speed C and
the acoustic estimate ½ ρ0 C Δu is an identity for the tension the spall plane
carried; then the elastic–plastic plate impact of Davison's steel with a spall
strength, where the three estimates are compared with what the solution knows.
Conventions of PHYSICS.md: stress positive in compression, SI units.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from fronttrack.pullback import (
    NoPullbackError,
    acoustic_spall_strength,
    find_pullback,
    pullback,
    spall_estimates,
    stepanov_spall_strength,
    surface_record,
    wave_speeds,
)
from fronttrack.runner import run
from fronttrack.scene import Accuracy, Boundary, Layer, Probe, Scene
from materials import ElasticPlastic, LinearElastic, MieGruneisen

REL = 1e-12
RHO, C = 2700.0, 6000.0
Z = RHO * C
LAM, MU, RHO_STEEL, Y = 123.1e9, 79.29e9, 7870.0, 1.00e9


def close(a, b, rel=REL):
    return abs(a - b) <= rel * max(abs(a), abs(b))


# --- the record analysis on its own ---------------------------------------------------------------
def test_find_pullback_on_a_step_record():
    t = np.array([0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0])
    u = np.array([0.0, 80.0, 200.0, 150.0, 120.0, 170.0, 160.0])
    record = find_pullback(t, u)
    assert (record.t_peak, record.u_max) == (2.0, 200.0)
    assert (record.t_min, record.u_min) == (4.0, 120.0)
    assert record.t_rebound == 5.0 and record.delta_u == 80.0
    assert record.acoustic(RHO, C) == 0.5 * RHO * C * 80.0
    assert record.stepanov(RHO, C, C) == pytest.approx(record.acoustic(RHO, C), rel=REL)


def test_small_wiggles_are_ignored_below_the_tolerance():
    t = np.arange(8.0)
    u = np.array([0.0, 199.99, 200.0, 199.95, 150.0, 150.01, 149.0, 180.0])
    record = find_pullback(t, u)  # default tolerance 0.2 m/s (1e-3 of 200 m/s)
    assert (record.u_max, record.u_min, record.t_rebound) == (200.0, 149.0, 7.0)
    exact = find_pullback(t, u, tolerance=0.0)
    assert (exact.u_max, exact.u_min, exact.t_rebound) == (200.0, 150.0, 5.0)


def test_records_without_pullback_raise_clear_errors():
    with pytest.raises(NoPullbackError, match="never falls"):
        find_pullback([0.0, 1.0, 2.0], [0.0, 100.0, 150.0])
    with pytest.raises(NoPullbackError, match="no spall signal"):
        find_pullback([0.0, 1.0, 2.0, 3.0], [0.0, 100.0, 50.0, 20.0])
    drop = find_pullback([0.0, 1.0, 2.0, 3.0], [0.0, 100.0, 50.0, 20.0], require_rebound=False)
    assert drop.delta_u == 80.0 and drop.t_rebound is None
    with pytest.raises(NoPullbackError, match="empty"):
        find_pullback([], [])
    with pytest.raises(ValueError, match="one length"):
        find_pullback([0.0, 1.0], [0.0])
    with pytest.raises(ValueError, match="tolerance"):
        find_pullback([0.0, 1.0], [0.0, 1.0], tolerance=-1.0)


def test_formulas_and_wave_speeds():
    steel = ElasticPlastic("steel", RHO_STEEL, LAM, MU, Y)
    c0, cb = wave_speeds(steel)
    assert (c0, cb) == (steel.C0, steel.CB)
    du = 60.0
    low, mid, high = (acoustic_spall_strength(RHO_STEEL, cb, du),
                      stepanov_spall_strength(RHO_STEEL, c0, cb, du),
                      acoustic_spall_strength(RHO_STEEL, c0, du))
    assert low < mid < high
    # Stepanov's estimate inverts du = s/(rho0 CB) + s/(rho0 C0)
    assert close(mid / (RHO_STEEL * cb) + mid / (RHO_STEEL * c0), du)
    assert wave_speeds(LinearElastic("a", RHO, C)) == (C, C)
    copper = MieGruneisen("Cu", 8930.0, 3940.0, 1.489, 1.99)
    assert wave_speeds(copper) == (copper.sound_speed(copper.v0, 0.0),) * 2


# --- linear elastic: the acoustic estimate is exact -----------------------------------------------
def _symmetric_elastic(t_end):
    solid = LinearElastic("elastic", RHO, C)
    return Scene(layers=(Layer(solid, 1e-3, velocity=200.0, name="flyer"),
                         Layer(solid, 2e-3, bond="unbonded", name="target")),
                 t_end=t_end, probes=(Probe("rear", "right"),))


def test_symmetric_elastic_impact_without_spall():
    """1 mm on 2 mm at 200 m/s: the rear face jumps to v, the flyer's release brings it
    to 0 and the tension -Z v/2 (met 1 mm inside the target) equals ½ Z Δu exactly."""
    sol = run(_symmetric_elastic(1.2e-6))
    estimate = spall_estimates(sol)
    record = estimate.record
    assert close(record.u_max, 200.0) and abs(record.u_min) <= 1e-12
    assert close(record.t_peak, 2e-3 / C) and close(record.t_min, 4e-3 / C)
    assert close(record.t_rebound, 6e-3 / C)
    assert close(estimate.acoustic_longitudinal, Z * 200.0 / 2)
    assert close(estimate.acoustic_longitudinal, estimate.max_tension)
    assert estimate.stepanov == estimate.acoustic_bulk == estimate.acoustic_longitudinal
    assert close(estimate.max_tension_x, 2e-3) and close(estimate.max_tension_t, 3e-3 / C)
    assert estimate.spall_strength is None and estimate.carried_tension is None
    assert estimate.relative_errors()["acoustic_longitudinal"] == pytest.approx(0.0, abs=1e-12)


def test_record_that_has_not_risen_yet():
    sol = run(_symmetric_elastic(0.9e-6))
    with pytest.raises(NoPullbackError, match="no spall signal"):
        pullback(sol)
    assert close(pullback(sol, require_rebound=False).delta_u, 200.0)
    with pytest.raises(ValueError, match="side"):
        pullback(sol, side="top")


def test_wall_boundary_is_not_a_free_surface():
    solid = LinearElastic("elastic", RHO, C)
    scene = Scene(layers=(Layer(solid, 1e-3, velocity=100.0),), t_end=0.5e-6,
                  right=Boundary("wall"))
    with pytest.raises(ValueError, match="not a free surface"):
        surface_record(run(scene), "right")


def _triangular_pulse(strength, step):
    """A 4 GPa stress pulse decaying linearly to 0 in 1 us, applied to the left face of a
    10 mm elastic bar (spall strength ``strength``); the ramp is carried as release
    steps of ``step`` Pa (the first and last half a step)."""
    bar = LinearElastic("elastic", RHO, C, spall_strength=strength)
    return Scene(layers=(Layer(bar, 10e-3, name="bar"),), t_end=2.6e-6,
                 left=Boundary("stress", ((0.0, 4e9), (1e-6, 0.0))),
                 accuracy=Accuracy(characteristic_step=step))


@pytest.mark.parametrize(("strength", "step"), [(1.1e9, 0.25e9), (1.15e9, 0.1e9),
                                                (2.3e9, 0.25e9)])
def test_elastic_spall_pullback_is_the_carried_tension(strength, step):
    """The reflected head (a tension jump of 4 GPa - step/2) meets the incident release
    steps one by one: after j of them the tension is j*step, so the bar breaks at the
    first j with j*step >= strength, having carried (j - 1)*step.  The rear face has by
    then lost exactly the j - 1 steps: Δu = 2 (j - 1) step / Z, ½ Z Δu is the carried
    tension exactly and the spall strength to within one step."""
    sol = run(_triangular_pulse(strength, step))
    j = math.ceil(strength / step - 1e-9)
    n = round(4e9 / step)
    estimate = spall_estimates(sol)
    record = estimate.record
    assert close(record.u_max, 2 * (4e9 - step / 2) / Z)
    assert close(record.delta_u, 2 * (j - 1) * step / Z, rel=1e-9)
    assert close(estimate.acoustic_longitudinal, (j - 1) * step, rel=1e-9)
    assert close(estimate.acoustic_longitudinal, estimate.carried_tension, rel=1e-9)
    assert close(estimate.acoustic_longitudinal, estimate.max_tension, rel=1e-9)
    assert strength - step < estimate.acoustic_longitudinal <= strength
    assert estimate.spall_strength == strength
    assert close(estimate.fracture_tension, j * step, rel=1e-9)
    # the spall plane: the reflected head meets the j-th step j * C T/(2 n) from the face
    assert close(estimate.spall_x, 10e-3 - j * C * 1e-6 / (2 * n), rel=1e-9)
    # timing: steps arrive every T/n; the spall signal arrives when the j-th would have
    assert close(record.t_peak, 10e-3 / C)
    assert close(record.t_min, 10e-3 / C + (j - 1) * 1e-6 / n, rel=1e-9)
    assert close(record.t_rebound, 10e-3 / C + j * 1e-6 / n, rel=1e-9)


# --- elastic–plastic plate impact with spall ------------------------------------------------------
def test_elastic_plastic_spall_estimates_against_the_true_tension():
    """Davison's steel, 5 mm on 10 mm at 230 m/s, spall strength 2.5 GPa.

    Exact parts: the precursor step 2 HEL/(rho0 C0) of the rear face and the arrival of
    the spall signal, an elastic recompression at C0 from the first fracture.  The
    estimates all fall short of the true tension: the tension at the spall plane is
    built by slow plastic release waves (CB) which the fast elastic spall signal (C0)
    overtakes before they reach the surface, so the record sees only part of them.
    """
    steel = ElasticPlastic("steel", RHO_STEEL, LAM, MU, Y, spall_strength=2.5e9)
    scene = Scene(layers=(Layer(steel, 5e-3, velocity=230.0, name="flyer"),
                          Layer(steel, 10e-3, bond="unbonded", name="target")),
                  t_end=4e-6, probes=(Probe("rear", "right"),),
                  accuracy=Accuracy(negligible_stress=10e6))
    sol = run(scene)
    t, u = surface_record(sol)
    assert close(u[1], 2 * steel.hel / steel.impedance) and close(t[1], 10e-3 / steel.C0)
    estimate = spall_estimates(sol)
    record = estimate.record
    # the free-surface plateau: elastic release of 2 HEL, then plastic to zero stress
    shocked = sol.state_at(7.5e-3, 1.5e-6)
    plateau = shocked.u + 2 * steel.hel / steel.impedance + (
        shocked.sigma - 2 * steel.hel) / steel.bulk_impedance
    assert record.u_max == pytest.approx(plateau, rel=1e-3)  # ring-up cut at 10 MPa
    assert close(record.t_rebound, estimate.spall_t + (15e-3 - estimate.spall_x) / steel.C0,
                 rel=1e-9)
    assert estimate.spall_strength == 2.5e9
    assert estimate.carried_tension <= estimate.spall_strength < estimate.fracture_tension
    assert estimate.max_tension <= estimate.spall_strength
    assert (estimate.acoustic_bulk < estimate.stepanov < estimate.acoustic_longitudinal
            < estimate.carried_tension)
    errors = estimate.relative_errors()
    assert all(-0.6 < e < -0.4 for e in errors.values())
    print(f"\npullback {record.delta_u:.3f} m/s (u_max {record.u_max:.3f}, u_min "
          f"{record.u_min:.3f}); true: strength 2.5 GPa, carried "
          f"{estimate.carried_tension / 1e9:.4f} GPa, max tension "
          f"{estimate.max_tension / 1e9:.4f} GPa")
    for name, value in estimate.estimates().items():
        print(f"  {name:22s} {value / 1e9:.4f} GPa ({errors[name]:+.1%} of the strength)")
