"""The reverse-yield (plastic release) path of a finite-plastic solid as an isentrope table.

``characteristics.isentrope.PlasticPathIsentrope``: on the branch ``S = -2Y/3`` of a
perfectly plastic ``FinitePlastic`` solid the stress is a function of the volume alone,
so a lattice of characteristics can solve rays crossing rays there instead of one
Riemann problem per crossing; a node that would compress a cell (an elastic reload,
off the path) cuts the zone (``characteristics.lattice``).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from characteristics import lattice as moc
from characteristics.isentrope import PlasticPathIsentrope, isentrope_for
from materials import RIGHT, FinitePlastic, solve_contact

# the denser solid of the class-B reproducer (benchmarks/RUN_LENGTH.md, (d, classes))
SOLID = FinitePlastic("B", 18123.0, 3000.0, 1.3, 2.0, 80e9, 1.22e9)


def _knee():
    """The reverse-yield state of ``SOLID`` released from 10 GPa on its Hugoniot, and the
    release wave curve from that shocked state."""
    shocked = SOLID.wave_curve(SOLID.reference_state(), RIGHT).state_at(10e9)
    curve = SOLID.wave_curve(shocked, RIGHT)
    return curve.state_at(curve.yield_low), curve


def test_the_path_table_is_the_plastic_release_of_the_wave_curve():
    knee, curve = _knee()
    table = isentrope_for(SOLID, knee)
    assert isinstance(table, PlasticPathIsentrope)
    j_minus = table.invariants(knee)[1]
    for sigma in (4.0e9, 2.0e9, 0.0, -1.0e9):
        exact = curve.state_at(sigma)
        read = table.state_at_stress(sigma, j_minus, RIGHT)
        # both are exact to rounding (closed forms, and Chebyshev series converged to
        # rounding): 1e-9 leaves room for the rounding summed over a few panels
        assert read.u == pytest.approx(exact.u, abs=1e-9 * SOLID.C_bulk)
        assert read.v == pytest.approx(exact.v, rel=1e-12)
        assert read.e == pytest.approx(exact.e, rel=1e-9, abs=1e-9 * abs(knee.e))
        assert read.plastic_strain == pytest.approx(exact.plastic_strain, rel=1e-12)
        assert SOLID.deviator(read) == pytest.approx(-2.0 * SOLID.yield_strength / 3.0,
                                                     rel=1e-9)
        assert table.speed_at_stress(sigma) == pytest.approx(
            curve.characteristic_speed(sigma), rel=1e-12)


def test_elastic_states_have_no_path_table():
    shocked = SOLID.wave_curve(SOLID.reference_state(), RIGHT).state_at(10e9)
    assert isentrope_for(SOLID, shocked) is None  # on the forward yield surface
    assert isentrope_for(SOLID, SOLID.reference_state()) is None
    hardening = FinitePlastic("H", 18123.0, 3000.0, 1.3, 2.0, 80e9, 1.22e9, hardening=1e9)
    knee = _knee()[0]
    assert isentrope_for(hardening, knee) is None  # no single path per state


def _fans(table, knee, step: float, n: int, right=None, far=1e-3):
    """Two centred release fans of ``n`` rays on the path, a right-going one from
    X = -1 mm and a left-going one from X = +1 mm at t = 0, meeting at X = 0; each ray
    carries ``step`` (m/s) of its invariant.  Ends: bounds at ``-far`` and ``+far``
    (m), or ``right``."""
    jp0, jm0 = table.invariants(knee)
    jp = [jp0 - (n - k) * step for k in range(n)] + [jp0] * (n + 1)
    jm = [jm0] * (n + 1) + [jm0 + (k + 1) * step for k in range(n)]
    own = [0.5 * (jp[k] + jp[k + 1]) for k in range(n)] + \
        [0.5 * (jm[n + k] + jm[n + k + 1]) for k in range(n)]
    speed = [table.speed(own[k], jm0) for k in range(n)] + \
        [-table.speed(jp0, own[n + k]) for k in range(n)]
    return moc.Zone(
        table=table, family=np.array([1] * n + [-1] * n, dtype=np.int8), own=np.array(own),
        x0=np.array([-1e-3] * n + [1e-3] * n), t0=np.zeros(2 * n), speed=np.array(speed),
        jp=np.array(jp), jm=np.array(jm), left=moc.Bound(-far, 0.0, 0.0),
        right=right if right is not None else moc.Bound(far, 0.0, 0.0), t_now=0.0,
        horizon=1e-6)


def test_crossing_fans_on_the_path_agree_with_riemann_solves():
    knee, _ = _knee()
    table = isentrope_for(SOLID, knee)
    zone = _fans(table, knee, step=20.0, n=4, far=3e-3)
    lattice = moc.solve(zone)
    assert lattice.nodes == 16 and np.all(lattice.node_kind == moc.CROSSING)
    jp0, jm0 = table.invariants(knee)
    for j in range(len(zone.jp), len(lattice.cell_jp)):
        # the cell behind ray i of the right-going fan and ray k of the left-going one is
        # the star state of the Riemann problem between the states they left behind
        left = table.state(lattice.cell_jp[j], jm0)
        right = table.state(jp0, lattice.cell_jm[j])
        star = solve_contact(SOLID, left, SOLID, right).left_star
        assert star is not None and not math.isnan(star.sigma)
        assert lattice.cell_sigma[j] < min(left.sigma, right.sigma)  # both waves release
        # the solver converges the contact stress to 1e-12 of its scale (5.3 GPa here)
        # and the table reads states to rounding (measured: 2e-4 Pa, 3e-12 m/s)
        assert lattice.cell_sigma[j] == pytest.approx(star.sigma, abs=1e-2)
        assert lattice.cell_u[j] == pytest.approx(star.u, abs=1e-9)
        assert lattice.cell_v[j] == pytest.approx(star.v, rel=1e-9)
        assert table.plastic_strain(lattice.cell_v[j]) == pytest.approx(
            star.plastic_strain, rel=1e-9)


def _onto(table, knee, end: moc.Reflector):
    """A right-going release fan of 4 rays from X = 0 running into the reflecting
    ``end`` at X = 0.1 mm, through cells on the path at stress 0."""
    at_zero = table.state_at_stress(0.0, table.invariants(knee)[1], RIGHT)
    jp0, jm0 = table.invariants(at_zero)
    step, n = 20.0, 4
    jp = [jp0 - (n - k) * step for k in range(n)] + [jp0]
    own = [0.5 * (jp[k] + jp[k + 1]) for k in range(n)]
    return moc.Zone(
        table=table, family=np.ones(n, dtype=np.int8), own=np.array(own), x0=np.zeros(n),
        t0=np.zeros(n), speed=np.array([table.speed(j, jm0) for j in own]), jp=np.array(jp),
        jm=np.full(n + 1, jm0), left=moc.Bound(-1e-3, 0.0, 0.0), right=end, t_now=0.0,
        horizon=1e-6)


def test_a_release_reflected_as_a_compression_cuts_the_zone():
    knee, _ = _knee()
    table = isentrope_for(SOLID, knee)
    # at a free surface the tension the fan brings reflects as a compression back to
    # zero stress: that material reloads elastically, off the path
    free = moc.solve(_onto(table, knee, moc.Reflector(1e-4, "stress", 0.0)))
    assert free.nodes == 0 and free.reason == "reloads"
    first = 1e-4 / free.seg_speed[3]  # the head ray (fastest, rightmost) arrives
    assert free.cut == pytest.approx(first, rel=1e-12)
    # at a wall the release reflects as a release: the lattice goes on
    wall = moc.solve(_onto(table, knee, moc.Reflector(1e-4, "velocity", 0.0)))
    assert wall.nodes > 4 and wall.reason != "reloads"
    assert np.all(np.diff(wall.node_sigma[wall.node_kind == moc.RIGHT_REFLECTION]) < 0.0)


def test_a_zone_with_a_compression_ray_on_the_path_is_left_to_the_riemann_solver():
    knee, _ = _knee()
    table = isentrope_for(SOLID, knee)
    zone = _fans(table, knee, step=-20.0, n=4)  # the fans' steps reversed: compressions
    lattice = moc.solve(zone)
    assert lattice.nodes == 0 and lattice.reason == "compression on a release path"
