"""Explosives: the CJ point, overdriven detonations, the products' wave curves.

Reference values: /work/shared/reference/README.md (Davison ch. 13, TNT of the book's
example, gamma-law products, pR neglected); JWL parameters of the library from Dobratz
and Crawford (1985), whose tabulated D_CJ and p_CJ the computed CJ point must reproduce.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import quad

from materials import LEFT, RIGHT, MaterialError, Shock, library, solve_boundary, solve_contact
from materials.explosive import BURNT, DetonationCurve, Explosive, gamma_law_explosive
from materials.mie_gruneisen import MieGruneisen
from materials.products import Products
from materials.state import State

JWL_NAMES = ["TNT", "CompB", "PETN", "PBX9501", "NM", "LX14"]


def book_tnt() -> Explosive:
    unreacted = MieGruneisen("TNT unreacted", 1600.0, 2390.0, 2.05, 1.0)
    return gamma_law_explosive("TNT-book", 1600.0, 2.6, 4.9e6, unreacted)


def test_book_tnt_cj_state_closed_form():
    """D = sqrt(2 (G^2 - 1) q), p = rho0 D^2/(G + 1), u = D/(G + 1), rho = rho0 (G+1)/G."""
    gamma, q, rho0 = 2.6, 4.9e6, 1600.0
    cj = book_tnt().cj_state(book_tnt().reference_state())
    d = math.sqrt(2.0 * (gamma**2 - 1.0) * q)
    assert cj.speed == pytest.approx(d, rel=1e-12)
    assert cj.state.sigma == pytest.approx(rho0 * d * d / (gamma + 1.0), rel=1e-12)
    assert cj.state.u == pytest.approx(d / (gamma + 1.0), rel=1e-12)
    assert cj.state.rho == pytest.approx(rho0 * (gamma + 1.0) / gamma, rel=1e-12)
    # the reference README's rounded numbers
    assert cj.speed == pytest.approx(7513.0, abs=0.5)
    assert cj.state.sigma / 1e9 == pytest.approx(25.09, abs=0.005)
    # sonic: the products' Lagrangian sound speed at CJ equals D
    products = book_tnt().products
    assert products.sound_speed(cj.state.v, cj.state.e) == pytest.approx(d, rel=1e-12)


def test_library_book_tnt_is_the_same():
    m = library.get("TNT-book")
    assert m.cj_state(m.reference_state()).speed == pytest.approx(
        math.sqrt(2.0 * (2.6**2 - 1.0) * 4.9e6), rel=1e-12)


@pytest.mark.parametrize("name", JWL_NAMES)
def test_library_cj_point_matches_tabulated(name):
    """The CJ tangent of the JWL Hugoniot reproduces the handbook's D_CJ and p_CJ (the JWL
    fits were made to them): 0.3 % in D (nitromethane's fit is the loosest), 0.05 % in p."""
    m = library.get(name)
    cj = m.cj_state(m.reference_state())
    assert cj.speed == pytest.approx(m.D_cj, rel=3e-3)
    assert cj.state.sigma == pytest.approx(m.p_cj, rel=5e-4)
    assert cj.state.plastic_strain == BURNT


@pytest.mark.parametrize("name", ["TNT-book", "TNT", "PBX9501", "NM"])
@pytest.mark.parametrize("sigma_a", [0.0, 2e9])
def test_cj_speed_is_the_minimum_over_rayleigh_lines(name, sigma_a):
    """Scan the detonation Hugoniot: no Rayleigh line through it is slower than D_CJ, and
    the slowest found on a fine grid is within the grid's second-order error of it."""
    m = library.get(name)
    ahead = m.reference_state()
    if sigma_a:
        ahead = m.unreacted.wave_curve(ahead, RIGHT).state_at(sigma_a)
    cj = m.cj_state(ahead)
    lo = m.products.hugoniot_volume_limit(ahead)
    v = np.linspace(lo, ahead.v, 20001)[1:-1]
    sigma = np.array([m.products.hugoniot(ahead, x)[0] for x in v])
    d2 = (sigma - ahead.sigma) / (m.rho0**2 * (ahead.v - v))
    assert d2.min() >= cj.speed**2 * (1.0 - 1e-13)
    assert d2.min() == pytest.approx(cj.speed**2, rel=1e-6)
    assert v[np.argmin(d2)] == pytest.approx(cj.state.v, abs=2.0 * (v[1] - v[0]))
    # the tangency: the Hugoniot's slope equals the Rayleigh line's
    slope = m.products.hugoniot(ahead, cj.state.v)[2]
    assert -slope == pytest.approx(m.rho0**2 * cj.speed**2, rel=1e-9)


@pytest.mark.parametrize("name", ["TNT-book", "PBX9501"])
@pytest.mark.parametrize("factor", [1.0, 1.2, 2.0])
def test_overdriven_detonation_jump_conditions(name, factor, jump_conditions):
    m = library.get(name)
    ahead = m.reference_state(u=50.0)
    cj = m.cj_state(ahead)
    for direction in (RIGHT, LEFT):
        curve = DetonationCurve(m, ahead, direction)
        (front,) = curve.waves(factor * cj.state.sigma)
        assert isinstance(front, Shock)
        jump_conditions(front, m)
        assert abs(front.speed) >= cj.speed * (1.0 - 1e-12)
        assert (abs(front.speed) > cj.speed) == (factor > 1.0)
        assert front.behind.plastic_strain == BURNT
        # on the strong branch: denser than CJ
        assert front.behind.v <= cj.state.v * (1.0 + 1e-12)


def test_cj_detonation_and_taylor_wave(jump_conditions):
    """Below p_CJ: the CJ detonation (jump conditions) then a fan on the products'
    isentrope through CJ, whose head moves with the detonation."""
    m = library.get("PBX9501")
    curve = DetonationCurve(m, m.reference_state(), RIGHT)
    front, fan = curve.waves(10e9)
    jump_conditions(front, m)
    assert front.speed == pytest.approx(m.cj_state(m.reference_state()).speed, rel=1e-12)
    assert fan.head_speed == pytest.approx(front.speed, rel=1e-9)
    k = m.products.isentrope_constant(fan.ahead)
    assert m.products.isentrope_constant(fan.behind) == pytest.approx(k, rel=1e-12)


def test_taylor_wave_with_hugoniot_release_is_one_rarefaction_shock(jump_conditions):
    """``release = "hugoniot"``: below p_CJ the Taylor wave is one rarefaction shock on
    the products' Hugoniot through CJ, slower than the detonation (its chord lies under
    the Rayleigh line's tangency).  It crashed before (the fan's head speed was set on a
    shock), on a random command-line scene."""
    m = library.get("PBX9501")
    curve = DetonationCurve(m, m.reference_state(), RIGHT, "hugoniot")
    front, rarefaction = curve.waves(10e9)
    jump_conditions(front, m)
    jump_conditions(rarefaction, m.products)
    assert rarefaction.ahead == front.behind
    assert rarefaction.behind.sigma == pytest.approx(10e9, rel=1e-12)
    assert 0.0 < rarefaction.speed < front.speed


@pytest.mark.parametrize("name", ["TNT-book", "PBX9501"])
def test_detonation_curve_monotone_and_smooth_at_cj(name):
    m = library.get(name)
    curve = DetonationCurve(m, m.reference_state(), RIGHT)
    p_cj = curve.cj.state.sigma
    sigmas = np.linspace(0.02 * p_cj, 3.0 * p_cj, 400)
    g = np.array([curve.velocity_change(s)[0] for s in sigmas])
    assert np.all(np.diff(g) > 0.0)
    # the Rayleigh line is tangent at CJ: dg/dsigma continuous there, and equal to
    # 1/(rho0 D) (the products' acoustic impedance at CJ is rho0 C_L = rho0 D)
    below = curve.velocity_change(p_cj * (1.0 - 1e-9))[1]
    above = curve.velocity_change(p_cj * (1.0 + 1e-9))[1]
    assert below == pytest.approx(above, rel=1e-5)
    assert below == pytest.approx(1.0 / (m.rho0 * curve.cj.speed), rel=1e-5)
    for s in (0.3 * p_cj, 2.0 * p_cj):
        h = 1e-6 * s
        fd = (curve.velocity_change(s + h)[0] - curve.velocity_change(s - h)[0]) / (2 * h)
        assert curve.velocity_change(s)[1] == pytest.approx(fd, rel=1e-6)


# --- the products' equation of state and wave curves ------------------------------------------
@pytest.fixture(params=["TNT-book", "TNT", "PBX9501"])
def explosive(request):
    return library.get(request.param)


def products_state(m, sigma):
    """A products state on the Taylor wave of the CJ detonation at ``sigma``."""
    return DetonationCurve(m, m.reference_state(), RIGHT).state_at(sigma)


@pytest.mark.parametrize("sigma", [5e9, 20e9])
def test_products_isentrope_is_an_isentrope(explosive, sigma):
    """de/dv = -sigma and C_L^2 = -v0^2 dsigma/dv along it (central differences, h^2)."""
    p = explosive.products
    a = products_state(explosive, sigma)
    for v in (0.7 * a.v, a.v, 3.0 * a.v):
        h = 1e-5 * v
        (s_m, e_m), (s_0, _), (s_p, e_p) = (p.isentrope(a, v - h), p.isentrope(a, v),
                                            p.isentrope(a, v + h))
        assert (e_p - e_m) / (2 * h) == pytest.approx(-s_0, rel=1e-7)
        e_0 = p.isentrope(a, v)[1]
        c2 = -p.v0**2 * (s_p - s_m) / (2 * h)
        assert p.sound_speed(v, e_0) ** 2 == pytest.approx(c2, rel=1e-7)
    assert p.isentrope(a, math.inf) == (0.0, -p.q)


@pytest.mark.parametrize("sigma", [5e9, 20e9])
def test_products_riemann_integral_against_quadrature(explosive, sigma):
    p = explosive.products
    a = products_state(explosive, sigma)

    def integrand(v):
        return p.rho0 * p.sound_speed(v, p.isentrope(a, v)[1])

    for v in (0.8 * a.v, 2.0 * a.v, 30.0 * a.v):
        exact = quad(integrand, a.v, v, epsabs=0.0, epsrel=1e-13, limit=200)[0]
        assert p.riemann_integral(a, v) == pytest.approx(exact, rel=1e-11)
    # to vacuum: beyond V = 1e4 V_a the exponential terms are below rounding and the rest is
    # the K term's integral, S (2/omega) V^(-omega/2) with S^2 = v0 (1 + omega) omega rho0 K
    v_far = 1e4 * a.v
    far = quad(integrand, a.v, v_far, epsabs=0.0, epsrel=1e-13, limit=400)[0]
    k = p.isentrope_constant(a)
    scale = math.sqrt(p.v0 * (1.0 + p.omega) * p.omega * p.rho0 * k)
    tail = scale * 2.0 / p.omega * (v_far * p.rho0) ** (-0.5 * p.omega)
    assert p.riemann_integral(a, math.inf) == pytest.approx(far + tail, rel=1e-11)


@pytest.mark.parametrize("sigma_b", [0.5e9, 10e9, 40e9])
def test_products_shocks_satisfy_jump_conditions(explosive, sigma_b, jump_conditions):
    a = products_state(explosive, 3e9)
    for direction in (RIGHT, LEFT):
        curve = explosive.wave_curve(a, direction)
        waves = curve.waves(sigma_b)
        assert all(w.behind.plastic_strain == BURNT for w in waves)
        if sigma_b > a.sigma:
            (shock,) = waves
            jump_conditions(shock, explosive.products)


def test_products_hugoniot_and_isentrope_agree_to_third_order(explosive):
    """sigma_H(v) - sigma_s(v) = O(dv^3): halving dv divides it by about 8."""
    p = explosive.products
    a = products_state(explosive, 10e9)
    gaps = []
    for k in range(3):
        v = a.v * (1.0 - 0.02 / 2**k)
        gaps.append(p.hugoniot(a, v)[0] - p.isentrope(a, v)[0])
    assert all(g > 0.0 for g in gaps)
    for big, small in zip(gaps, gaps[1:], strict=False):
        assert big / small == pytest.approx(8.0, rel=0.06)


def test_products_wave_curve_monotone(explosive):
    a = products_state(explosive, 10e9)
    curve = explosive.wave_curve(a, RIGHT)
    sigmas = np.linspace(0.05e9, 60e9, 300)
    g = np.array([curve.velocity_change(s)[0] for s in sigmas])
    assert np.all(np.diff(g) > 0.0)
    for s in (1e9, 30e9):
        h = 1e-6 * s
        fd = (curve.velocity_change(s + h)[0] - curve.velocity_change(s - h)[0]) / (2 * h)
        assert curve.velocity_change(s)[1] == pytest.approx(fd, rel=1e-6)


def test_gamma_law_products_riemann_invariant_closed_form():
    """Gamma law: J = 2 (c_a - c)/(Gamma - 1), c the Eulerian sound speed."""
    m = book_tnt()
    p = m.products
    a = products_state(m, 20e9)
    for v in (0.9 * a.v, 5.0 * a.v):
        e = p.isentrope(a, v)[1]
        c_a = a.v / p.v0 * p.sound_speed(a.v, a.e)
        c = v / p.v0 * p.sound_speed(v, e)
        assert p.riemann_integral(a, v) == pytest.approx(2.0 * (c_a - c) / 1.6, rel=1e-12)


# --- initiation and the metastable unreacted explosive ------------------------------------
def test_unreacted_explosive_at_rest_next_to_a_solid_sends_nothing(copper):
    m = library.get("PBX9501")
    sol = solve_contact(copper, copper.reference_state(), m, m.reference_state())
    assert sol.left_waves == () and sol.right_waves == ()


def test_impact_detonates_the_explosive(copper):
    """A copper flyer at 4 km/s on PBX 9501: an overdriven detonation (its pressure is above
    p_CJ) satisfying the jump conditions; at 300 m/s a CJ detonation and its Taylor wave."""
    m = library.get("PBX9501")
    p_cj = m.cj_state(m.reference_state()).state.sigma
    fast = solve_contact(copper, copper.reference_state(u=4000.0), m, m.reference_state())
    assert fast.bonded_sigma > p_cj and len(fast.right_waves) == 1
    assert fast.right_star.plastic_strain == BURNT
    slow = solve_contact(copper, copper.reference_state(u=300.0), m, m.reference_state())
    assert slow.bonded_sigma < p_cj and len(slow.right_waves) == 2
    assert slow.left_star.u == pytest.approx(slow.right_star.u, abs=1e-9)


@pytest.mark.parametrize("face", ["free", "wall"])
def test_initiation_at_a_face(face):
    """Ignited at a free face the products expand to vacuum (at the escape velocity
    u_CJ - 2 c_CJ/(Gamma - 1)); at a wall the Taylor wave ends at rest."""
    m = book_tnt()
    kw = {"stress": 0.0} if face == "free" else {"velocity": 0.0}
    sol = solve_boundary(m.ignited, m.reference_state(), "left", **kw)
    cj = m.cj_state(m.reference_state())
    front = sol.right_waves[0]
    assert front.speed == pytest.approx(cj.speed, rel=1e-12)
    star = sol.right_star
    if face == "free":
        c_cj = cj.speed - cj.state.u
        assert star.u == pytest.approx(cj.state.u - 2.0 * c_cj / 1.6, rel=1e-12)
        assert star.e == -m.products.q
    else:
        assert star.u == 0.0
        assert 0.0 < star.sigma < cj.state.sigma


# --- bad input ----------------------------------------------------------------------------------
def test_products_without_heat_have_no_cj_point():
    with pytest.raises(MaterialError, match="q must be"):
        Products("x", 1600.0, 0.0, 1.6)
    spec = dict(library.entry("TNT"), E0=-1.0)
    spec.pop("aliases")
    with pytest.raises(MaterialError, match="E0"):
        library.material_from_spec("bad", spec)


def test_no_cj_point_is_an_error():
    """A JWL with R1 < omega has a negative A term at V = 1: the detonation Hugoniot passes
    below the unreacted state, and no Rayleigh line from it is tangent to the Hugoniot."""
    unreacted = MieGruneisen("u", 1600.0, 2390.0, 2.05, 1.0)
    products = Products("p", 1600.0, 1e3, 0.3, A=10e9, B=0.0, R1=0.1, R2=1.0)
    with pytest.raises(MaterialError, match="no Chapman-Jouguet point"):
        Explosive("bad", unreacted, products)


def test_prestressed_explosive_is_refused():
    with pytest.raises(MaterialError, match="starts unstressed"):
        library.get("TNT").initial_state(stress=1e9)


def test_state_flag():
    state = State(1.0, 0.0, 1.0, 0.0)
    assert library.get("TNT").phase(state) is library.get("TNT").unreacted


# --- the ZND profile ------------------------------------------------------------------------------
def test_znd_profile_from_spike_to_cj():
    """Spike: the unreacted Hugoniot Us = c0 + s up at Us = D (up = (D - c0)/s, sigma = rho0
    D up); end: the CJ point; every state on the Rayleigh line; the pressure falls and the
    reaction completes at D 2/k behind the front."""
    from materials.znd import znd_profile

    m = library.get("PBX9501")
    k = 1e8
    profile = znd_profile(m, k, points=101)
    d = profile.speed
    un = m.unreacted
    assert profile.sigma[0] == pytest.approx(m.rho0 * d * (d - un.c0) / un.s, rel=1e-12)
    cj = m.cj_state(m.reference_state())
    assert profile.sigma[-1] == pytest.approx(cj.state.sigma, rel=1e-12)
    rayleigh = m.rho0**2 * d**2 * (m.v0 - profile.v)
    assert np.allclose(profile.sigma, rayleigh, rtol=1e-12, atol=0.0)
    assert np.all(np.diff(profile.sigma) < 0.0)
    assert np.all(np.diff(profile.reacted) > 0.0)
    assert profile.distance[-1] == pytest.approx(2.0 * d / k, rel=1e-12)
    with pytest.raises(MaterialError, match="rate"):
        znd_profile(m, 0.0)


def test_cold_gamma_law_products_are_shocked_to_their_limiting_compression():
    """Gamma-law products released to zero stress keep e = -q at a finite volume (a cold
    gas).  Their Hugoniot from there is the snowplow: every stress at
    v_lim = v_a (gamma - 1)/(gamma + 1), with u_b - u_a = sqrt(sigma (v_a - v_lim)).
    The states of a random scene (fuzz seed 420: products behind a wall meeting the
    hot products of the detonation, separating at 3 182 m/s) were refused as "needs a
    stress above 0.0007 GPa", the Hugoniot's stress at the representable limit.  The
    contact velocities agree to the solver's rounding (they were 0.01 m/s apart while
    the root's tolerance scaled with the snowplow's 1 PPa bracket over a zero guess)."""
    tnt = book_tnt()
    cold = State(sigma=0.0, u=-2363.1270311547805, v=0.0011335282127277878, e=-4.9e6,
                 plastic_strain=BURNT)
    hot = State(sigma=21521190438.583096, u=818.9430896478634, v=0.0004785367604452429,
                e=1536675.4708779287, plastic_strain=BURNT)
    sol = solve_contact(tnt, cold, tnt, hot, tensile_strength=25.088e6, release="hugoniot")
    star = sol.left_star
    assert not sol.separated and star.sigma == pytest.approx(sol.right_star.sigma, rel=1e-12)
    assert star.u == pytest.approx(sol.right_star.u, rel=1e-12)
    v_lim = cold.v * (2.6 - 1.0) / (2.6 + 1.0)
    assert star.v == pytest.approx(v_lim, rel=1e-9)
    # Jump conditions of the left-facing snowplow shock: momentum and energy.
    assert cold.u - star.u == pytest.approx(math.sqrt(star.sigma * (cold.v - v_lim)), rel=1e-9)
    assert star.e - cold.e == pytest.approx(0.5 * star.sigma * (cold.v - v_lim), rel=1e-9)
    assert 0.0 < star.sigma < hot.sigma
