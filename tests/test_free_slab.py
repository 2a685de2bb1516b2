"""The closed-form ringing of a slab free on both faces (characteristics.free_slab).

Exact checks of the d'Alembert solution: it holds the cells it was built from, the
faces stay at zero stress, the pattern repeats with period 2L/C, momentum and the
acoustic energy are constants, and the faces' displacement is the integral of their
velocity.  All to rounding (1e-9 of the quantity's scale).
"""

import numpy as np
import pytest

from characteristics.free_slab import FreeSlab

C, Z = 5328.0, 2785.0 * 5328.0


@pytest.fixture
def slab():
    # a 2 mm slab, four cells: a compression pulse and a velocity step
    edges = [1.0e-3, 1.4e-3, 1.9e-3, 2.2e-3, 3.0e-3]
    sigma = [0.0, 40e6, -15e6, 0.0]
    u = [10.0, 22.0, 3.0, 1.0]
    return FreeSlab.from_cells(edges, sigma, u, 2.0e-7, C, Z), edges, sigma, u


def test_holds_its_cells_at_t0(slab):
    s, edges, sigma, u = slab
    mids = 0.5 * (np.array(edges[:-1]) + np.array(edges[1:]))
    got_sigma, got_u = s.state(mids, s.t0)
    assert np.allclose(got_sigma, sigma, rtol=0, atol=1e-9 * 40e6)
    assert np.allclose(got_u, u, rtol=0, atol=1e-9 * 22.0)


def test_faces_free_and_period(slab):
    s = slab[0]
    times = s.t0 + np.linspace(0.0, 3.0 * s.period, 71) + 1.234e-10
    for x in (s.x_lo, s.x_hi):
        assert np.all(s.state(np.full(times.size, x), times)[0] == 0.0)
    x = np.linspace(s.x_lo, s.x_hi, 57)[1:-1] + 1e-9
    for t in times[:5]:
        a, b = s.state(x, t), s.state(x, t + s.period)
        assert np.allclose(a[0], b[0], atol=1e-6) and np.allclose(a[1], b[1], atol=1e-9)


def test_momentum_and_acoustic_energy_constant(slab):
    s, edges, sigma, u = slab
    widths = np.diff(edges)
    momentum = np.dot(widths, u)
    energy = np.dot(widths, (np.array(sigma) ** 2 / Z + Z * (np.array(u) - s.u0) ** 2)
                    / (2.0 * C))
    assert s.acoustic_energy() == pytest.approx(energy, rel=1e-12)
    x = np.linspace(s.x_lo, s.x_hi, 200_001)
    dx = x[1] - x[0]
    for t in s.t0 + np.array([0.13, 0.5, 0.77, 2.31]) * s.period:
        sig, vel = s.state(x[:-1] + 0.5 * dx, t)
        # cells are piecewise constant: the midpoint sum errs by a cell edge per jump
        assert np.sum(vel) * dx == pytest.approx(momentum, rel=1e-4)
        assert np.sum(sig ** 2 / Z + Z * (vel - s.u0) ** 2) * dx / (2.0 * C) == \
            pytest.approx(energy, rel=1e-3)
    assert s.u0 * s.length == pytest.approx(momentum, rel=1e-12)


def test_face_pieces_integrate_the_face_velocity(slab):
    s = slab[0]
    t0, t1 = s.t0 + 0.1 * s.period, s.t0 + 2.7 * s.period
    for side in ("left", "right"):
        starts, velocities = s.face_pieces(side, t0, t1)
        ends = np.append(starts[1:], t1)
        assert np.all(ends > starts)
        fine = np.linspace(t0, t1, 400_001)
        dt = fine[1] - fine[0]
        brute = np.sum(s.face_velocity(side, fine[:-1] + 0.5 * dt)) * dt
        assert np.dot(velocities, ends - starts) == pytest.approx(brute, rel=1e-5)
        # each piece is constant: the velocity just after a start is the piece's
        assert np.allclose(s.face_velocity(side, starts + 1e-13), velocities)


def test_passages_are_the_jumps_of_the_record(slab):
    s = slab[0]
    x = 2.05e-3
    times = s.passages(x, s.t0, s.t0 + 2.0 * s.period)
    assert times.size > 0
    for tc in times:
        before, after = s.state(x, tc - 1e-12), s.state(x, tc + 1e-12)
        assert before[0] != after[0] or before[1] != after[1]
    mids = 0.5 * (times[:-1] + times[1:])
    # nothing changes between passages
    for a, b, m in zip(times[:-1], times[1:], mids, strict=True):
        probe = np.linspace(a, b, 7)[1:-1]
        sig, vel = s.state(np.full(probe.size, x), probe)
        assert np.ptp(sig) == 0.0 and np.ptp(vel) == 0.0, m


def test_waves_at_rebuild_the_cells(slab):
    s = slab[0]
    t = s.t0 + 0.37 * s.period
    x, direction, jump = s.jumps_at(t)
    edges = np.concatenate([[s.x_lo], x, [s.x_hi]])
    mids = 0.5 * (edges[:-1] + edges[1:])
    sig, vel = s.state(mids, t)
    # each wave's stress jump, behind minus ahead, and its velocity jump dsigma = +-Z du
    for k, (d, j) in enumerate(zip(direction, jump, strict=True)):
        behind, ahead = (k, k + 1) if d > 0 else (k + 1, k)
        assert sig[behind] - sig[ahead] == pytest.approx(j, abs=1e-6)
        assert sig[behind] - sig[ahead] == pytest.approx(d * Z * (vel[behind] - vel[ahead]),
                                                        abs=1e-6)
