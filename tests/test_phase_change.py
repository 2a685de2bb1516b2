"""Polymorphic phase change (``materials.phase_change``): iron's alpha -> epsilon.

Reference values are computed here from the two branches' Us–up fits alone (scipy
quadrature and root finding), independently of the model's closed forms.
"""

from __future__ import annotations

import math
import random

import numpy as np
import pytest
from engine_helpers import assert_no_nan, assert_shock_jumps, assert_wave_jumps
from scipy.integrate import quad
from scipy.optimize import brentq

from fronttrack.runner import run
from fronttrack.scene import Accuracy, Boundary, Layer, Probe, Scene
from materials import LEFT, RIGHT, Fan, MaterialError, Shock, get, material_from_spec
from materials.finite_plastic import concave_hull_waves
from materials.phase_change import PhaseChangeSolid

RHO, C1, S1, C2, S2 = 7850.0, 4630.0, 1.57, 3574.0, 1.92
SIGMA_T, DEPS = 13.0e9, 0.02817


def iron(**kwargs) -> PhaseChangeSolid:
    return PhaseChangeSolid("Fe", RHO, C1, S1, C2, S2, SIGMA_T, DEPS, **kwargs)


def branch(c, s):
    """Stress and slope of ``sigma = rho c^2 eps / (1 - s eps)^2``."""
    def stress(eps):
        return RHO * c * c * eps / (1.0 - s * eps) ** 2

    def slope(eps, h=1e-7):
        return (stress(eps + h) - stress(eps - h)) / (2.0 * h)
    return stress, slope


ALPHA, ALPHA_SLOPE = branch(C1, S1)
EPSILON, EPSILON_SLOPE = branch(C2, S2)
EPS_A = brentq(lambda e: ALPHA(e) - SIGMA_T, 0.0, 0.3, xtol=1e-16, rtol=1e-15)
EPS_B = EPS_A + DEPS


@pytest.mark.parametrize("sigma", [13.2e9, 20.0e9, 30.0e9])
def test_p1_is_the_transition_stress_and_p2_follows(sigma):
    fe = iron()
    waves = fe.wave_curve(fe.reference_state(), RIGHT).waves(sigma)
    p1, p2 = waves
    assert p1.behind.sigma == SIGMA_T
    assert p1.speed == pytest.approx(math.sqrt(SIGMA_T / EPS_A / RHO), rel=1e-12)
    assert p2.behind.sigma == sigma
    eps_b = 1.0 - p2.behind.v * RHO
    expected = EPSILON(eps_b) if eps_b > EPS_B else SIGMA_T + (
        EPSILON(EPS_B) - SIGMA_T) * (eps_b - EPS_A) / DEPS
    assert expected == pytest.approx(sigma, rel=1e-12)
    assert 0.0 < p2.speed < p1.speed
    for shock in waves:
        assert_wave_jumps(shock, RHO)


def test_strong_load_is_one_overdriven_shock():
    fe = iron()
    (shock,) = fe.wave_curve(fe.reference_state(), RIGHT).waves(60e9)
    assert_wave_jumps(shock, RHO)
    assert shock.speed > math.sqrt(SIGMA_T / EPS_A / RHO)


def release_velocity(sigma_top: float) -> float:
    """Velocity gained by releasing the epsilon state of ``sigma_top`` to zero, computed
    from the branches: a fan down the epsilon branch to ``B``, then the rarefaction shock
    from ``B`` to rest (its chord below the alpha branch's initial slope)."""
    eps_top = brentq(lambda e: EPSILON(e) - sigma_top, EPS_B, 0.4, xtol=1e-16, rtol=1e-15)
    fan = quad(lambda e: math.sqrt(EPSILON_SLOPE(e) / RHO), EPS_B, eps_top,
               epsabs=0.0, epsrel=1e-12)[0]
    assert EPSILON(EPS_B) / EPS_B < ALPHA_SLOPE(0.0)
    return fan + math.sqrt(EPSILON(EPS_B) * EPS_B / RHO)


def test_release_through_the_mixed_region_is_a_rarefaction_shock():
    fe = iron()
    top = fe.wave_curve(fe.reference_state(), RIGHT).state_at(25e9)
    waves = fe.wave_curve(top, LEFT).waves(0.0)
    fan, shock = waves
    assert isinstance(fan, Fan) and isinstance(shock, Shock)
    assert fan.behind.sigma == pytest.approx(EPSILON(EPS_B), rel=1e-12)
    assert shock.behind.sigma == 0.0 and shock.ahead.sigma > SIGMA_T
    assert abs(shock.speed) < abs(fan.tail_speed) < abs(fan.head_speed)
    assert_wave_jumps(shock, RHO)
    assert shock.behind.u - top.u == pytest.approx(release_velocity(25e9), rel=1e-10)
    assert fe.dissipated_energy(shock.behind) > fe.dissipated_energy(top)


def test_partial_release_bridges_the_corner_with_a_tangent_chord():
    """Release to a stress above zero: the chord ends on the target or where it touches the
    alpha branch; either way it lies below the path and the jump conditions hold."""
    fe = iron()
    top = fe.wave_curve(fe.reference_state(), RIGHT).state_at(13.3e9)
    for target in (12.0e9, 8.0e9, 2.0e9):
        waves = fe.wave_curve(top, LEFT).waves(target)
        shocks = [w for w in waves if isinstance(w, Shock)]
        assert shocks and shocks[0].ahead.sigma == top.sigma
        for shock in shocks:
            assert_wave_jumps(shock, RHO)


@pytest.mark.parametrize("seed", range(8))
def test_wave_curve_properties(seed):
    """Random states on the path, both directions: g increasing, jumps exact, speeds
    decreasing from the leading wave, dissipation never negative."""
    rng = random.Random(seed)
    fe = iron()
    start = fe.wave_curve(fe.reference_state(), RIGHT).state_at(rng.uniform(0.0, 40e9))
    curve = fe.wave_curve(start, rng.choice([LEFT, RIGHT]))
    stresses = sorted(rng.uniform(-5e9, 45e9) for _ in range(10))
    g = [curve.velocity_change(s)[0] for s in stresses]
    assert all(b > a for a, b in zip(g[:-1], g[1:], strict=True))
    for sigma in stresses:
        waves = curve.waves(sigma)
        speeds = []
        for wave in waves:
            if isinstance(wave, Shock):
                assert_wave_jumps(wave, RHO, tol=1e-11)
                speeds.append(abs(wave.speed))
            else:
                speeds += [abs(wave.head_speed), abs(wave.tail_speed)]
        assert all(b <= a * (1 + 1e-12) for a, b in zip(speeds[:-1], speeds[1:], strict=True))
        behind = curve.state_at(sigma)
        assert fe.dissipated_energy(behind) >= fe.dissipated_energy(start) - 1e-9 * abs(
            behind.e - start.e) - 1e-6


def test_bad_input_names_the_field():
    with pytest.raises(MaterialError, match="transition_stress"):
        iron_spec = {"model": "phase-change", "rho0": RHO, "c1": C1, "s1": S1, "c2": C2,
                     "s2": S2, "transition_stress": 500e9, "transition_strain": DEPS}
        material_from_spec("Fe", iron_spec)
    with pytest.raises(MaterialError, match="transition_strain"):
        PhaseChangeSolid("Fe", RHO, C1, S1, C2, S2, SIGMA_T, -0.01)
    assert isinstance(get("Fe_alpha_epsilon"), PhaseChangeSolid)


FLYER, TARGET, GAUGE = 0.5e-3, 2.0e-3, 1.0e-3
"""The symmetric impact's flyer and target thicknesses, and the gauge's depth in the
target (m): deep enough that P2 has separated from P1, shallow enough that P2 passes it
before the flyer's release and long before anything comes back from the free surface."""


def symmetric_impact(rays: int, t_end: float = 0.6e-6):
    """Iron on iron at 1 km/s, both faces free, a gauge ``GAUGE`` into the target."""
    fe = iron()
    scene = Scene(layers=(Layer(fe, FLYER, 1000.0), Layer(fe, TARGET, 0.0, bond="unbonded")),
                  left=Boundary("free"), right=Boundary("free"), t_end=t_end,
                  probes=(Probe("gauge", FLYER + GAUGE),),
                  accuracy=Accuracy(rays_per_fan=rays, negligible_stress=1e4, max_events=4000))
    solution = run(scene)
    assert_no_nan(solution)
    return solution


def speeds(eps2: float) -> dict:
    """Wave speeds of the symmetric impact (m/s) from the branches: the P1 chord ``0 -> A``,
    the P2 chord ``A -> eps2``, the alpha characteristic at ``A`` and the epsilon one at
    the impact state."""
    sigma2 = EPSILON(eps2)
    return {"U1": math.sqrt(SIGMA_T / EPS_A / RHO),
            "U2": math.sqrt((sigma2 - SIGMA_T) / (eps2 - EPS_A) / RHO),
            "C_A": math.sqrt(ALPHA_SLOPE(EPS_A) / RHO),
            "C_2": math.sqrt(EPSILON_SLOPE(eps2) / RHO)}


def test_symmetric_impact_three_arrivals():
    """Iron on iron at 1 km/s (0.5 mm flyer, 2 mm target): the three arrivals P1, P2 and
    the flyer's release, in that order, at the times and states the branches give.

    Where each quantity is clean.  P1 and P2 run through undisturbed material to a gauge
    1 mm into the target, so the gauge's two plateaus are the two chords' end states
    (``sigma_t``, ``u1``) and (``sigma2``, 500 m/s) and their arrival times are depth over
    the chord speeds: all shock-only, exact to rounding (1e-9).  The free surface is
    exact only for P1: its velocity jumps at ``L / U1`` to ``u1`` plus the alpha-branch
    Riemann integral from ``A`` to 0 (the reflection is a centred alpha fan).  P2 then
    has to cross that fan (splitting a recompression shock off at every alpha state it
    meets), so its free-surface rise is not ``500`` plus a centred release of ``sigma2``;
    no signal of it can reach the free surface before the alpha characteristic at ``A``
    from the point where P2 meets the fan's head (checked), and the release arrives after
    the P2 rise (checked).

    The release.  The flyer's rear face reflects P1 as a right-going alpha fan; its head
    (``C_A`` through state ``A``) meets the left-going P2 and continues as the epsilon
    characteristic ``C_2`` of the impact state, which reaches the gauge at ``t_head``
    (straight lines, exact).  The engine replaces the fan by ``rays_per_fan`` rays, the
    first carrying its first slice, so its first release arrival comes after ``t_head``
    by an error of first order in the ray spacing: halving the spacing (4 -> 8 rays)
    halves it (ratio 2 within 5 %, the second-order remainder).  Behind the epsilon fan
    the state is the corner ``B`` exactly, and the next arrival is the rarefaction shock
    of the reverse transformation: one jump from ``B`` across the mixed region onto the
    alpha branch, momentum and mass satisfied with the alpha branch's own strain (1e-9).
    That needs ``negligible_stress`` of 10 kPa: at the default (1e-3 of the stress scale,
    18 MPa) the engine drops a 4.3 MPa wave right behind the rarefaction shock, which
    moves the recorded jump by 0.24 m/s (0.06 %), within the engine's promise but not
    a check of the shock.
    """
    eps2 = solve_symmetric_strain()
    sigma2 = EPSILON(eps2)
    w = speeds(eps2)
    u1 = math.sqrt(SIGMA_T * EPS_A / RHO)
    solution = symmetric_impact(rays=4)

    gauge = solution.history("gauge")
    t, states = list(gauge.t), gauge.states
    assert t[1] == pytest.approx(GAUGE / w["U1"], rel=1e-9)
    assert states[1].sigma == pytest.approx(SIGMA_T, rel=1e-9)
    assert states[1].u == pytest.approx(u1, rel=1e-9)
    assert t[2] == pytest.approx(GAUGE / w["U2"], rel=1e-9)
    assert states[2].sigma == pytest.approx(sigma2, rel=1e-9)
    assert states[2].u == pytest.approx(500.0, rel=1e-9)

    t_rear = FLYER / w["U1"]                       # P1 reaches the flyer's free face
    t_meet = (FLYER + w["C_A"] * t_rear) / (w["C_A"] + w["U2"])
    x_meet = FLYER - w["U2"] * t_meet              # the fan's head meets P2 (flyer X)
    t_head = t_meet + (FLYER + GAUGE - x_meet) / w["C_2"]
    assert t[2] < t_head < t[3]
    finer = symmetric_impact(rays=8, t_end=t[3]).history("gauge")
    error4, error8 = t[3] - t_head, float(finer.t[3]) - t_head
    assert 0.0 < error8 < error4
    assert error4 / error8 == pytest.approx(2.0, rel=0.05)
    corner = next(k for k in range(3, len(states)) if states[k].sigma < SIGMA_T) - 1
    released = [s.sigma for s in states[2:corner + 2]]     # the release only unloads
    assert all(b < a for a, b in zip(released[:-1], released[1:], strict=True))
    b, p = states[corner], states[corner + 1]
    assert b.sigma == pytest.approx(EPSILON(EPS_B), rel=1e-9)
    assert 1.0 - b.v * RHO == pytest.approx(EPS_B, rel=1e-9)
    eps_p = brentq(lambda e: ALPHA(e) - p.sigma, -0.05, EPS_A, xtol=1e-16, rtol=1e-15)
    assert 1.0 - p.v * RHO == pytest.approx(eps_p, rel=1e-9, abs=1e-12)
    assert b.u - p.u == pytest.approx(
        math.sqrt((b.sigma - p.sigma) * (EPS_B - eps_p) / RHO), rel=1e-9)

    surface = solution.history("right")
    t, u = list(surface.t), list(surface.u)
    u_fs1 = u1 + quad(lambda e: math.sqrt(ALPHA_SLOPE(e) / RHO), 0.0, EPS_A,
                      epsabs=0.0, epsrel=1e-12)[0]
    t1 = TARGET / w["U1"]
    assert t[1] == pytest.approx(t1, rel=1e-9)
    assert u[1] == pytest.approx(u_fs1, rel=1e-9)
    t_fan = (TARGET + w["C_A"] * t1) / (w["C_A"] + w["U2"])   # P2 meets the fan's head
    t_signal = t_fan + (TARGET - w["U2"] * t_fan) / w["C_A"]
    assert t[2] >= t_signal and u[2] > u[1]
    peak = max(range(len(u)), key=u.__getitem__)
    assert peak >= 2 and peak + 1 < len(u) and u[peak + 1] < u[peak]


def solve_symmetric_strain() -> float:
    """Compression of the symmetric 1 km/s impact state (on the epsilon branch): the P1
    and P2 chords of the branches bring the target to 500 m/s."""
    u1 = math.sqrt(SIGMA_T * EPS_A / RHO)

    def mismatch(eps):
        return u1 + math.sqrt((EPSILON(eps) - SIGMA_T) * (eps - EPS_A) / RHO) - 500.0

    return brentq(mismatch, EPS_B, 0.3, xtol=1e-16, rtol=1e-15)


def test_hull_agrees_with_the_sampled_construction():
    """The exact hull against ``concave_hull_waves`` on 40 001 samples of the path: the
    P1 and P2 speeds on loading to 20 GPa; on release from 25 GPa to zero (the lower
    hull, as the upper hull of ``-sigma`` against ``-eps``) a fan then one chord."""
    fe = iron()
    eps_top = brentq(lambda e: EPSILON(e) - 20e9, EPS_B, 0.4, xtol=1e-16, rtol=1e-15)
    eps = np.union1d(np.linspace(0.0, eps_top, 40001), [EPS_A, EPS_B])
    sigma = np.array([fe.path_stress(x) for x in eps])
    kinds = concave_hull_waves(eps, sigma, RHO)
    p1, p2 = fe.wave_curve(fe.reference_state(), RIGHT).waves(20e9)
    assert [k["kind"] for k in kinds] == ["shock", "shock"]
    assert kinds[0]["speeds"][0] == pytest.approx(p1.speed, rel=1e-12)
    assert kinds[1]["speeds"][0] == pytest.approx(p2.speed, rel=1e-12)
    top = fe.wave_curve(fe.reference_state(), RIGHT).state_at(25e9)
    eps_top = 1.0 - top.v * RHO
    eps = np.union1d(np.linspace(0.0, eps_top, 40001), [EPS_A, EPS_B])
    sigma = np.array([fe.path_stress(x) for x in eps])
    pieces = concave_hull_waves(-eps[::-1], -sigma[::-1], RHO)
    fan, shock = fe.wave_curve(top, LEFT).waves(0.0)
    assert [p["kind"] for p in pieces] == ["fan", "shock"]
    assert pieces[0]["speeds"][0] == pytest.approx(abs(fan.head_speed), rel=1e-3)
    assert pieces[1]["speeds"][0] == pytest.approx(abs(shock.speed), rel=1e-9)


def test_energy_balance_keeps_the_energy_jumps_at_contacts():
    """All shocks (``release = "hugoniot"``): momentum to rounding and energy to the
    negligible stress.  Two states of one stress have one volume here, so an entropy
    contact is an energy jump alone; merging it put shocks off their Hugoniots (1.6 %
    of the energy lost in this scene before the engine kept such contacts).  The
    contacts still neglected (energy jumps below the negligible stress) keep the state
    of lower energy, so the balance is a loss (7.6e-4 here; 2e-4 with the sweep-weighted
    mean that created energy elsewhere, campaign seed 349) within the promise."""
    fe = iron()
    scene = Scene(layers=(Layer(fe, 0.5e-3, 1000.0), Layer(fe, 2.0e-3, 0.0, bond="unbonded")),
                  left=Boundary("free"), right=Boundary("free"), t_end=0.75e-6,
                  accuracy=Accuracy(release="hugoniot", max_events=2000))
    solution = run(scene)
    assert assert_shock_jumps(solution) > 0
    balance = solution.conservation()
    assert balance["momentum_relative_error"] < 1e-9
    report = solution.accuracy_report["balance"]
    assert -report["promised"] < report["energy_error"] <= 0.0
