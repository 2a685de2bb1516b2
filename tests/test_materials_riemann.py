"""The Riemann solver: jump conditions, impedance matching, shock tubes, interfaces.

``solve_contact(left_material, left, right_material, right)`` returns left-going
waves into ``left``, right-going waves into ``right`` and the two states at the
contact; ``solve_boundary`` reflects one state from a prescribed stress or
velocity.  Hypothesis drives the solver over random materials, initial stresses
and velocities; each returned shock is checked against the three jump
conditions of PHYSICS.md and each fan against the isentrope.
"""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.optimize import brentq

from materials import (
    LEFT,
    RIGHT,
    Fan,
    IdealGas,
    LinearElastic,
    NoSolutionError,
    Shock,
    State,
    solve_boundary,
    solve_contact,
)

SOLID_NAMES = ["Al6061", "Cu", "PMMA", "W", "quartz", "steel"]
PROPERTY = settings(max_examples=80, deadline=None)

# Initial stresses: -0.5 GPa (tension, inside every solid's range: PMMA's release
# isentrope ends at -0.92 GPa) to 15 GPa (PMMA shocked above ~17 GPa cannot be
# released to zero stress inside its EOS range; see test_materials_errors).
# Magnitudes below 1e-3 Pa (zero kept) are excluded: a state's recorded stress and its
# EOS stress differ by rounding, ~1e-5 Pa, and a stress smaller than that cannot be
# released reliably (see the report on HydrodynamicWaveCurve._volume).
initial_stress = st.floats(-0.5e9, 15e9).filter(lambda x: x == 0.0 or abs(x) >= 1e-3)
velocity = st.floats(10.0, 5000.0)
offset_velocity = st.floats(-1000.0, 1000.0)


def prestressed(m, sigma, u):
    """State of ``m`` at stress ``sigma`` reached from rest by one wave, moving at ``u``."""
    return m.wave_curve(m.reference_state(), RIGHT).state_at(sigma).moving(u)


# --- checks ---------------------------------------------------------------------------------
def finite(state) -> bool:
    return all(math.isfinite(x) for x in (state.sigma, state.u, state.v, state.e))


def rounding_level(m, a, b) -> bool:
    """True if the stress jump a -> b is below what two stored states can resolve:
    a few ulp of the stresses, or the stress change of one ulp of volume, Z^2 ulp(v)."""
    noise = 8 * math.ulp(max(abs(a.sigma), abs(b.sigma)))
    noise += (m.rho0 * m.sound_speed(a.v, a.e)) ** 2 * 4 * math.ulp(a.v)
    return abs(b.sigma - a.sigma) <= noise


def check_shock(shock: Shock, m, direction: int, jump):
    """Mass, momentum and energy jumps to 1e-12 of the jump magnitudes (conftest)."""
    a, b, U = shock.ahead, shock.behind, shock.speed
    assert shock.direction == direction and direction * U > 0.0
    if rounding_level(m, a, b):
        # Nearly matched problems leave waves of rounding-level amplitude (1e-16 of the
        # stress, or below one ulp of volume); their jumps are noise, but the wave must
        # still travel at the acoustic speed of the state it runs into.
        assert abs(U) == pytest.approx(m.sound_speed(a.v, a.e), rel=1e-9)
        return
    jump(shock, m)
    if isinstance(m, LinearElastic):
        assert U == direction * m.C  # every elastic wave runs at exactly C
    else:
        # a shock is compressive and supersonic ahead, subsonic behind (Lax)
        assert b.sigma >= a.sigma
        assert abs(U) >= m.sound_speed(a.v, a.e) * (1 - 1e-12)


def check_fan(fan: Fan, m, direction: int):
    """A centred fan: release along the isentrope of its head, characteristic speeds."""
    a, b = fan.ahead, fan.behind
    assert fan.direction == direction and b.sigma < a.sigma
    sigma_s, e_s = m.isentrope(a, b.v)
    # On the isentrope: 1e-12 of the stresses, plus the stress resolution of a stored
    # volume, (rho0 C_L)^2 ulp(v) ~ 1e-5 Pa (matters only for a fan of a few Pa).
    floor = (m.rho0 * m.sound_speed(b.v, b.e)) ** 2 * 4 * math.ulp(b.v)
    assert abs(sigma_s - b.sigma) <= 1e-12 * max(abs(a.sigma), abs(b.sigma)) + floor
    # Energy: 1e-12 relative, plus the reference's own rounding: ``isentrope`` subtracts
    # two values of the tabulated F(v) = int A E dv (~1e5 J/kg at 10 % strain), ~2e-11 J/kg
    # of noise, which the weak-wave energy of the curve (a 1 Pa fan) no longer shares.
    assert abs(e_s - b.e) <= 1e-12 * max(abs(a.e), abs(b.e), 1.0) + 1e-10
    # Riemann invariant of the crossing family: u - u_a = -d J (J = int rho0 C_L dv)
    j = m.riemann_integral(a, b.v)
    # J is integrated over [v_a, v_b] of the stored volumes, so it is good only to
    # rho0 C_L ulp(v), and its closed forms (gas: 2 (c_a - c_b)/(gamma - 1)) subtract
    # sound speeds, losing a few ulps of C_L; a weak fan's velocity jump (taken from the
    # exact stress jump) is limited by neither
    c_b = m.sound_speed(b.v, b.e)
    reference_rounding = 4 * m.rho0 * c_b * math.ulp(b.v) + 16 * math.ulp(c_b)
    assert (b.u - a.u) == pytest.approx(-direction * j, rel=1e-12,
                                        abs=1e-12 * abs(a.u) + reference_rounding)
    assert fan.head_speed == direction * m.sound_speed(a.v, a.e)
    assert fan.tail_speed == direction * m.sound_speed(b.v, b.e)


def check_waves(waves, m, direction: int, jump):
    for w in waves:
        assert finite(w.ahead) and finite(w.behind)
        if isinstance(w, Shock):
            check_shock(w, m, direction, jump)
        else:
            check_fan(w, m, direction)


def check_solution(sol, m_left, left, m_right, right, jump):
    assert not sol.separated
    ls, rs = sol.left_star, sol.right_star
    assert finite(ls) and finite(rs)
    check_waves(sol.left_waves, m_left, LEFT, jump)
    check_waves(sol.right_waves, m_right, RIGHT, jump)
    # Each chain of waves starts at the given state and ends at the contact state.
    for waves, start, star in ((sol.left_waves, left, ls), (sol.right_waves, right, rs)):
        if waves:
            assert waves[0].ahead == start and waves[-1].behind == star
        else:
            assert star == start
    # Contact: equal stress and particle velocity (impedance matching).
    scale_sigma = max(abs(left.sigma), abs(right.sigma), abs(ls.sigma), 1.0)
    assert abs(ls.sigma - rs.sigma) <= 1e-12 * scale_sigma
    # velocity scale: the velocities, and the stresses over the impedances
    scale_u = max(abs(left.u), abs(right.u), abs(left.u - right.u), abs(ls.u),
                  scale_sigma / (m_left.rho0 * m_left.sound_speed(left.v, left.e)),
                  scale_sigma / (m_right.rho0 * m_right.sound_speed(right.v, right.e)))
    assert abs(ls.u - rs.u) <= 1e-12 * scale_u
    # Fronts in X order: signed speeds never decrease from left to right.
    speeds = []
    for w in sol.fronts_in_order():
        speeds += [w.speed] if isinstance(w, Shock) else [w.head_speed, w.tail_speed]
        if isinstance(w, Fan) and w.direction == RIGHT:
            speeds[-2:] = speeds[-2:][::-1]  # a right-going fan's tail is to the left
    assert all(s1 <= s2 for s1, s2 in zip(speeds, speeds[1:], strict=False))
    assert all(s < 0 for w in sol.left_waves for s in _speeds(w))
    assert all(s > 0 for w in sol.right_waves for s in _speeds(w))


def _speeds(w):
    return (w.speed,) if isinstance(w, Shock) else (w.head_speed, w.tail_speed)


# --- property tests ---------------------------------------------------------------------------
@PROPERTY
@given(left=st.sampled_from(SOLID_NAMES), right=st.sampled_from(SOLID_NAMES),
       sigma_l=initial_stress, sigma_r=initial_stress, closing=velocity, u0=offset_velocity)
def test_impact_of_prestressed_solids(solids, jump_conditions, left, right, sigma_l, sigma_r,
                                      closing, u0):
    """Random solids in random pre-stressed states collide at 10 m/s .. 5 km/s."""
    m_l, m_r = solids[left], solids[right]
    a_l = prestressed(m_l, sigma_l, u0 + closing)
    a_r = prestressed(m_r, sigma_r, u0)
    sol = solve_contact(m_l, a_l, m_r, a_r)
    check_solution(sol, m_l, a_l, m_r, a_r, jump_conditions)


@PROPERTY
@given(left=st.sampled_from(SOLID_NAMES), right=st.sampled_from(SOLID_NAMES),
       sigma_l=initial_stress, sigma_r=initial_stress, opening=st.floats(10.0, 300.0),
       u0=offset_velocity, strength=st.floats(0.5e9, 5e9))
def test_pull_apart_with_finite_strength(solids, jump_conditions, left, right, sigma_l, sigma_r,
                                         opening, u0, strength):
    """Solids moving apart: releases (fans, or elastic rarefaction shocks), and a contact
    that carries the tension or opens if it exceeds the bond strength."""
    m_l, m_r = solids[left], solids[right]
    a_l = prestressed(m_l, sigma_l, u0 - opening)
    a_r = prestressed(m_r, sigma_r, u0)
    # the deepest tension both release curves reach inside their equations of state
    floor = max(m_l.wave_curve(a_l, LEFT).sigma_min(), m_r.wave_curve(a_r, RIGHT).sigma_min())
    if floor > -strength:
        # the materials' range ends before the bond breaks: a named error, or a solution
        # whose contact tension stays inside the range
        # the materials' range ends before the bond breaks: the contact cavitates at
        # the end of the range, or its tension stays inside it
        sol = solve_contact(m_l, a_l, m_r, a_r, tensile_strength=strength)
        if sol.separated:
            assert sol.bonded_sigma >= floor * (1.0 + 1e-9)
            return
    else:
        sol = solve_contact(m_l, a_l, m_r, a_r, tensile_strength=strength)
    if sol.separated:
        assert sol.bonded_sigma < -strength
        assert sol.left_star.sigma == 0.0 and sol.right_star.sigma == 0.0
        assert sol.right_star.u > sol.left_star.u  # the gap opens
        check_waves(sol.left_waves, m_l, LEFT, jump_conditions)
        check_waves(sol.right_waves, m_r, RIGHT, jump_conditions)
    else:
        assert sol.left_star.sigma >= -strength
        check_solution(sol, m_l, a_l, m_r, a_r, jump_conditions)


@PROPERTY
@given(name=st.sampled_from(SOLID_NAMES), sigma0=initial_stress, u0=st.floats(-5000.0, 5000.0),
       side=st.sampled_from(["left", "right"]))
def test_boundaries(solids, jump_conditions, name, sigma0, u0, side):
    """Free surface: sigma = 0 exactly; rigid wall: u = 0 (to rounding of u0)."""
    m = solids[name]
    a = prestressed(m, sigma0, u0)
    direction = LEFT if side == "right" else RIGHT

    free = solve_boundary(m, a, side, stress=0.0)
    star = free.left_star if side == "right" else free.right_star
    assert star.sigma == 0.0 and finite(star)
    check_waves(free.left_waves or free.right_waves, m, direction, jump_conditions)

    curve = m.wave_curve(a, direction)
    needed = -direction * u0  # g(sigma) that brings the boundary to rest
    if not (curve.velocity_change(curve.sigma_min())[0] <= needed
            <= curve.velocity_change(curve.sigma_max())[0]):
        # moving away from the wall faster than the EOS can pull, or into it faster than
        # it can push (a linear elastic solid stops at v = 0): a documented error
        with pytest.raises(NoSolutionError, match=f"{m.name}: a boundary velocity of 0 m/s"):
            solve_boundary(m, a, side, velocity=0.0)
        return
    wall = solve_boundary(m, a, side, velocity=0.0)
    star = wall.left_star if side == "right" else wall.right_star
    assert finite(star)
    # |u| <= 1e-12 |u0|: the root of g(sigma) = |u0| to rounding.
    assert abs(star.u) <= 1e-12 * max(abs(u0), 1.0)
    check_waves(wall.left_waves or wall.right_waves, m, direction, jump_conditions)
    assert (wall.left_star if side == "right" else wall.right_star) is not None
    assert (wall.right_star if side == "right" else wall.left_star) is None


@PROPERTY
@given(name=st.sampled_from(SOLID_NAMES + ["gas"]), impact=velocity, u0=offset_velocity)
def test_symmetric_impact_gives_half_velocity(solids, gas, jump_conditions, name, impact, u0):
    """Same material, same state, closing at V: the contact moves at the mean velocity."""
    if name == "gas":
        m, a = gas, gas.state_from_pressure(1.2, 1e5)
    else:
        m, a = solids[name], solids[name].reference_state()
    sol = solve_contact(m, a.moving(u0 + impact), m, a.moving(u0))
    mean = u0 + 0.5 * impact
    # The two curves are mirror images: the root is exact to rounding, 1e-13 of the scale.
    scale = max(abs(u0), impact)
    assert abs(sol.left_star.u - mean) <= 1e-13 * scale
    assert abs(sol.right_star.u - mean) <= 1e-13 * scale
    check_solution(sol, m, a.moving(u0 + impact), m, a.moving(u0), jump_conditions)


# --- ideal gas: Toro's shock tubes ------------------------------------------------------------
TORO = {
    # test: ((rho, u, p) left, (rho, u, p) right, (p*, u*, rho*L, rho*R)); Toro (2009),
    # Riemann Solvers and Numerical Methods for Fluid Dynamics, Table 4.3.
    1: ((1.0, 0.0, 1.0), (0.125, 0.0, 0.1), (0.30313, 0.92745, 0.42632, 0.26557)),
    2: ((1.0, -2.0, 0.4), (1.0, 2.0, 0.4), (0.00189, 0.00000, 0.02185, 0.02185)),
    3: ((1.0, 0.0, 1000.0), (1.0, 0.0, 0.01), (460.894, 19.5975, 0.57506, 5.99924)),
    4: ((1.0, 0.0, 0.01), (1.0, 0.0, 100.0), (46.0950, -6.19633, 5.99242, 0.57511)),
    5: ((5.99924, 19.5975, 460.894), (5.99242, -6.19633, 46.0950),
        (1691.64, 8.68975, 14.2823, 31.0426)),
}


def exact_gas_star(left, right, g=1.4):
    """Toro's exact Riemann solver (ch. 4, Eulerian form), solved with brentq to 1e-15."""
    (rl, ul, pl), (rr, ur, pr) = left, right

    def f(p, rho, pk):
        if p > pk:
            a_k, b_k = 2 / ((g + 1) * rho), (g - 1) / (g + 1) * pk
            return (p - pk) * math.sqrt(a_k / (p + b_k))
        c = math.sqrt(g * pk / rho)
        return 2 * c / (g - 1) * ((p / pk) ** ((g - 1) / (2 * g)) - 1)

    def rho_star(p, rho, pk):
        if p > pk:
            q, k = p / pk, (g - 1) / (g + 1)
            return rho * (q + k) / (k * q + 1)
        return rho * (p / pk) ** (1 / g)

    p = brentq(lambda x: f(x, rl, pl) + f(x, rr, pr) + ur - ul, 0.0, 1e6,
               xtol=1e-300, rtol=1e-15, maxiter=500)
    u = 0.5 * (ul + ur) + 0.5 * (f(p, rr, pr) - f(p, rl, pl))
    return p, u, rho_star(p, rl, pl), rho_star(p, rr, pr)


def solve_tube(left, right, g=1.4):
    """Lagrangian shock tube: each side's reference density is its initial density."""
    gl, gr = IdealGas("left gas", g, rho0=left[0]), IdealGas("right gas", g, rho0=right[0])
    sl = gl.state_from_pressure(left[0], left[2], left[1])
    sr = gr.state_from_pressure(right[0], right[2], right[1])
    return solve_contact(gl, sl, gr, sr), (gl, sl, gr, sr)


@pytest.mark.parametrize("test", sorted(TORO))
def test_toro_shock_tubes(test, jump_conditions):
    left, right, published = TORO[test]
    sol, (gl, sl, gr, sr) = solve_tube(left, right)
    got = (sol.left_star.sigma, sol.left_star.u, sol.left_star.rho, sol.right_star.rho)
    # 1) The exact solution of the same data (independent Eulerian formulas): 1e-11.
    for x, y in zip(got, exact_gas_star(left, right), strict=True):
        assert x == pytest.approx(y, rel=1e-11, abs=1e-12)
    # 2) Toro's published digits: within one unit of the last printed digit.
    #    Test 5 alone needs 5e-6 relative: its data are themselves rounded outputs of
    #    tests 3 and 4, and the exact solution of the printed data (engine and the
    #    independent solver agree to 1e-15) is p* = 1691.6470, u* = 8.689774,
    #    rho*L = 14.28235, i.e. the table is off by ~3e-6 relative there (Toro's
    #    iteration stops at a pressure change of 1e-6).
    for x, y in zip(got, published, strict=True):
        digits = _last_digit(y)
        if test == 5:
            assert x == pytest.approx(y, rel=5e-6)
        else:
            assert abs(x - y) <= digits
    assert sol.left_star.u == pytest.approx(sol.right_star.u, rel=1e-12, abs=1e-14)
    check_solution(sol, gl, sl, gr, sr, jump_conditions)


def _last_digit(y: float) -> float:
    """One unit of the last digit Toro prints (5 decimals, 6 significant figures)."""
    if abs(y) < 1.0:
        return 1e-5
    return 10.0 ** (math.floor(math.log10(abs(y))) - 5)


def test_toro_test2_is_symmetric():
    # The 123 problem: two rarefactions, u* = 0 by symmetry, p* = 0.00189.
    sol, _ = solve_tube(*TORO[2][:2])
    assert abs(sol.left_star.u) < 1e-15 and abs(sol.right_star.u) < 1e-15
    assert sol.left_star.sigma == pytest.approx(0.00189, abs=1e-5)
    assert isinstance(sol.left_waves[0], Fan) and isinstance(sol.right_waves[0], Fan)


@PROPERTY
@given(rl=st.floats(0.1, 10.0), rr=st.floats(0.1, 10.0), pl=st.floats(0.01, 1000.0),
       pr=st.floats(0.01, 1000.0), ul=st.floats(-5.0, 5.0), ur=st.floats(-5.0, 5.0))
def test_random_shock_tubes_match_exact_solver(jump_conditions, rl, rr, pl, pr, ul, ur):
    left, right = (rl, ul, pl), (rr, ur, pr)
    cl, cr = math.sqrt(1.4 * pl / rl), math.sqrt(1.4 * pr / rr)
    sol, (gl, sl, gr, sr) = solve_tube(left, right)
    if ur - ul >= 2 * (cl + cr) / 0.4:  # Toro's pressure-positivity condition fails
        assert sol.separated and sol.left_star.sigma == sol.right_star.sigma == 0.0
        assert sol.right_star.u - sol.left_star.u == pytest.approx(
            ur - ul - 2 * (cl + cr) / 0.4, rel=1e-10, abs=1e-12)
        return
    p, u, rho_l, rho_r = exact_gas_star(left, right)
    # Both exact, different formulations (Lagrangian wave curves vs Toro's f_K):
    # 1e-10 allows the conditioning of weak-pressure (near-vacuum) cases.
    assert sol.left_star.sigma == pytest.approx(p, rel=1e-10)
    assert sol.left_star.u == pytest.approx(u, rel=1e-10, abs=1e-10 * (abs(ul) + abs(ur) + cl))
    assert sol.left_star.rho == pytest.approx(rho_l, rel=1e-10)
    assert sol.right_star.rho == pytest.approx(rho_r, rel=1e-10)
    check_solution(sol, gl, sl, gr, sr, jump_conditions)


def test_nearly_cold_gas_impact(gas):
    """Two nearly cold gas layers colliding at V: strong shocks, rho*/rho0 -> (g+1)/(g-1).

    Exactly cold (p = 0) the Hugoniot is degenerate (p = 0 at every volume but the
    limiting one): the snowplow, each side swept to rho0 (g+1)/(g-1) by a shock with
    p = rho0 (g+1)/2 (dU)^2 and e = (dU)^2/2 (the jump conditions with v_b = v_lim).
    """
    sol = solve_contact(gas, gas.reference_state(u=100.0), gas, gas.reference_state())
    assert sol.right_star.u == pytest.approx(50.0, rel=1e-12)
    assert sol.right_star.sigma == pytest.approx(gas.rho0 * 1.2 * 50.0**2, rel=1e-11)
    assert sol.right_star.e == pytest.approx(0.5 * 50.0**2, rel=1e-11)
    assert sol.right_star.rho == pytest.approx(gas.rho0 * 6.0, rel=1e-11)
    cold = gas.state_from_pressure(gas.rho0, 1e-9 * gas.rho0 * 50.0**2)
    sol = solve_contact(gas, cold.moving(100.0), gas, cold)
    assert sol.right_star.u == pytest.approx(50.0, rel=1e-12)
    assert sol.right_star.rho == pytest.approx(gas.rho0 * 6.0, rel=1e-6)


# --- linear elastic interfaces ------------------------------------------------------------------
@pytest.mark.parametrize("amplitude", [1e8, 2e9, -5e8])
@pytest.mark.parametrize("order", ["quartz->steel", "steel->quartz"])
def test_elastic_interface_reflection_and_transmission(quartz, steel, jump_conditions, amplitude,
                                                       order):
    """A right-going wave sigma_i in Z1 meets Z2: reflected R sigma_i, transmitted T sigma_i."""
    m1, m2 = (quartz, steel) if order == "quartz->steel" else (steel, quartz)
    incident = m1.wave_curve(m1.reference_state(), RIGHT).state_at(amplitude)
    sol = solve_contact(m1, incident, m2, m2.reference_state())
    z1, z2 = m1.impedance, m2.impedance
    r, t = (z2 - z1) / (z2 + z1), 2 * z2 / (z1 + z2)
    transmitted = sol.right_star.sigma
    reflected = sol.left_star.sigma - amplitude
    # Linear algebra in double precision: 1e-12 (brief).
    assert transmitted == pytest.approx(t * amplitude, rel=1e-12)
    assert reflected == pytest.approx(r * amplitude, rel=1e-12)
    assert sol.left_star.u == pytest.approx(amplitude * (1 - r) / z1, rel=1e-12)
    (back,), (forward,) = sol.left_waves, sol.right_waves
    assert isinstance(back, Shock) and isinstance(forward, Shock)
    assert back.speed == -m1.C and forward.speed == m2.C  # exactly C
    check_solution(sol, m1, incident, m2, m2.reference_state(), jump_conditions)


def test_elastic_matched_impedance_transmits_everything(quartz):
    twin = LinearElastic("quartz twin", quartz.rho0, quartz.C)
    incident = quartz.wave_curve(quartz.reference_state(), RIGHT).state_at(1e9)
    sol = solve_contact(quartz, incident, twin, twin.reference_state())
    assert sol.right_star.sigma == pytest.approx(1e9, rel=1e-14)
    assert sol.left_star.sigma == pytest.approx(1e9, rel=1e-14)  # no reflected jump


def test_davison_steel_impact_on_quartz_gauge(quartz, steel):
    # Acoustic impact: sigma = V Z1 Z2 / (Z1 + Z2), exactly for linear solids.
    v_impact = 200.0
    sol = solve_contact(steel, steel.reference_state(u=v_impact), quartz, quartz.reference_state())
    z1, z2 = steel.impedance, quartz.impedance
    assert sol.left_star.sigma == pytest.approx(v_impact * z1 * z2 / (z1 + z2), rel=1e-12)
    assert sol.left_star.u == pytest.approx(v_impact * z1 / (z1 + z2), rel=1e-12)


# --- separation -----------------------------------------------------------------------------
def test_unbonded_interface_opens_under_tension(copper, aluminium):
    sol = solve_contact(copper, copper.reference_state(u=-60.0), aluminium,
                        aluminium.reference_state(u=40.0), tensile_strength=0.0)
    assert sol.separated
    assert sol.left_star.sigma == 0.0 and sol.right_star.sigma == 0.0
    assert sol.right_star.u > sol.left_star.u
    assert sol.left_star.u == -60.0 and sol.right_star.u == 40.0  # unstressed: nothing moves
    assert sol.left_waves == () and sol.right_waves == ()
    # bonded_sigma is the tension the bond would have needed: the infinite-strength root
    bonded = solve_contact(copper, copper.reference_state(u=-60.0), aluminium,
                           aluminium.reference_state(u=40.0))
    assert sol.bonded_sigma == pytest.approx(bonded.left_star.sigma, rel=1e-9)
    # acoustic estimate -V Z1 Z2 / (Z1 + Z2) to ~1 % (isentropes soften in tension)
    z1, z2 = copper.rho0 * copper.c0, aluminium.rho0 * aluminium.c0
    assert bonded.left_star.sigma == pytest.approx(-100.0 * z1 * z2 / (z1 + z2), rel=0.02)


def test_unbonded_compressed_plates_release_then_open(copper, aluminium, jump_conditions):
    # Pre-stressed plates moving apart: each releases to sigma = 0 by a fan, then a gap.
    a_l = prestressed(copper, 5e9, -300.0)
    a_r = prestressed(aluminium, 5e9, 300.0)
    sol = solve_contact(copper, a_l, aluminium, a_r, tensile_strength=0.0)
    assert sol.separated and sol.bonded_sigma < 0.0
    assert sol.left_star.sigma == sol.right_star.sigma == 0.0
    assert sol.right_star.u > sol.left_star.u
    check_waves(sol.left_waves, copper, LEFT, jump_conditions)
    check_waves(sol.right_waves, aluminium, RIGHT, jump_conditions)
    assert isinstance(sol.left_waves[0], Fan) and isinstance(sol.right_waves[0], Fan)


def test_unbonded_interface_in_compression_stays_closed(copper, aluminium):
    sol = solve_contact(copper, copper.reference_state(u=100.0), aluminium,
                        aluminium.reference_state(), tensile_strength=0.0)
    assert not sol.separated and sol.left_star.sigma > 0.0


@pytest.mark.parametrize("factor, opens", [(0.98, True), (1.02, False)])
def test_bond_fails_only_beyond_its_strength(copper, aluminium, factor, opens):
    left, right = copper.reference_state(u=-100.0), aluminium.reference_state(u=100.0)
    bonded = solve_contact(copper, left, aluminium, right).left_star.sigma
    assert bonded < 0.0
    strength = -bonded * factor
    sol = solve_contact(copper, left, aluminium, right, tensile_strength=strength)
    assert sol.separated is opens
    if opens:
        assert sol.bonded_sigma < -strength
        assert sol.left_star.sigma == sol.right_star.sigma == 0.0
    else:
        assert sol.left_star.sigma == pytest.approx(bonded, rel=1e-12)


def test_gas_contact_with_hugoniot_release_pulled_apart_stays_on_its_curves():
    """Campaign seed 141: two states of one gas (gamma 1.2) moving apart at 1 272 m/s,
    Hugoniot release, a contact holding 33 MPa of tension.  A gas carries no tension, so
    below zero stress its curve is the vacuum (``v = inf``) and ``phi`` jumps to -inf;
    the root lies just above the right gas's stress (phi(16 MPa) < 0 < phi(30 MPa)).  When the
    Hugoniot's zero-stress end became finite, negative stresses were taken on the
    ideal-gas Hugoniot beyond it, and the solver returned an infinite stress, after which
    the engine looped for ever."""
    gas = IdealGas("M3", 1.2, rho0=42.20705669825478)
    left = State(sigma=162388596.96560857, u=1828.4307221226054, v=0.002629842380058222,
                 e=2135282.071691759)
    right = State(sigma=16425109.44185581, u=3100.642008576111, v=0.013840227157909874,
                  e=1136636.22884408)
    sol = solve_contact(gas, left, gas, right, 33218445.9755857, "hugoniot")
    assert not sol.separated
    assert 16e6 < sol.bonded_sigma < 30e6
    # one velocity on both sides of the contact, to the rounding of the root search
    assert sol.left_star.u == pytest.approx(sol.right_star.u, abs=1e-9 * right.u)
    # the left gas is released to it, the right one (at 16.4 MPa) slightly compressed
    assert sol.left_star.v > left.v and sol.right_star.v < right.v
    for star, ahead in ((sol.left_star, left), (sol.right_star, right)):
        assert math.isfinite(star.v)
        # the Rayleigh line of the release jump: (u - u_a)^2 = (sigma_a - sigma)(v - v_a)
        assert (star.u - ahead.u) ** 2 == pytest.approx(
            (ahead.sigma - star.sigma) * (star.v - ahead.v), rel=1e-10)


def test_gas_pulled_from_a_solid_with_hugoniot_release_separates_at_zero_stress():
    """Campaign seed 467: shocked gas (309 MPa) moving off tantalum at 3 631 m/s, Hugoniot
    release, an unbonded contact (4.8 MPa strength).  Along its Hugoniot the gas gains at
    most sqrt(sigma_a (v0 - v_a)) = 2 310 m/s reaching zero stress at v0 = v_a (gamma +
    1) / (gamma - 1): the contact opens, the gas there at zero stress and v0.  Before, the
    solver took the gas below zero stress as vacuum at u = +inf and returned that."""
    gas = IdealGas("M0", 1.4, rho0=1.0)
    tantalum = LinearElastic("Ta", 16650.0, 3400.0)
    left = State(sigma=309042208.6600003, u=-3480.591692956286, v=0.0017270305905210117,
                 e=309042208.6600003 * 0.0017270305905210117 / 0.4)
    right = State(sigma=0.0, u=150.4405550869993, v=1.0 / 16650.0, e=0.0)
    sol = solve_contact(gas, left, tantalum, right, 4832442.780091816, "hugoniot")
    assert sol.separated and sol.bonded_sigma == 0.0
    v0 = left.v * 2.4 / 0.4
    assert sol.left_star.v == pytest.approx(v0, rel=1e-9)
    assert sol.left_star.u == pytest.approx(left.u + math.sqrt(left.sigma * (v0 - left.v)),
                                            rel=1e-9)
    assert sol.right_star.u == pytest.approx(right.u, abs=1e-9)


def test_gas_cannot_pull_vacuum_forms():
    # Toro's pressure-positivity condition violated: two rarefactions to vacuum.
    g = IdealGas("g", 1.4, rho0=1.0)
    a = g.state_from_pressure(1.0, 0.4)
    c = math.sqrt(1.4 * 0.4)
    sol = solve_contact(g, a.moving(-10.0), g, a.moving(10.0))
    assert sol.separated
    assert math.isinf(sol.left_star.v) and math.isinf(sol.right_star.v)
    # escape speeds u -/+ 2c/(gamma - 1): the vacuum front velocities
    assert sol.left_star.u == pytest.approx(-10.0 + 2 * c / 0.4, rel=1e-14)
    assert sol.right_star.u == pytest.approx(10.0 - 2 * c / 0.4, rel=1e-14)


def test_elastic_solid_carries_large_tension(quartz, steel):
    # No spinodal in a linear law: a bonded elastic pair pulls without limit.
    sol = solve_contact(steel, steel.reference_state(u=-1000.0), quartz,
                        quartz.reference_state(u=1000.0))
    z1, z2 = steel.impedance, quartz.impedance
    assert not sol.separated
    assert sol.left_star.sigma == pytest.approx(-2000.0 * z1 * z2 / (z1 + z2), rel=1e-12)


def test_infinite_strength_tension_beyond_eos_cavitates(copper):
    # beyond the most tension the equation of state carries, the contact separates there
    sol = solve_contact(copper, copper.reference_state(u=-1000.0), copper,
                        copper.reference_state(u=1000.0))
    floor = copper.wave_curve(copper.reference_state(u=-1000.0), LEFT).sigma_min()
    assert sol.separated
    assert sol.bonded_sigma == pytest.approx(floor, rel=1e-9)
    assert sol.left_star.sigma == 0.0 and sol.right_star.sigma == 0.0
