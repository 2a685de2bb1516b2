"""A contact node's weak reflections close the lattice's grid (``characteristics.grid``).

A release fan in shocked Al 2024 runs onto an entropy contact (37 J/kg hotter beyond
it, the jump a release ray leaves behind a decaying shock in the symmetric Al 2024
impact), with a free surface at the other end.  Each ray the contact reflects carries
about 1e-6 of its step; without a tolerance those reflections are new invariants at
every round, and the grid grows by the zone's size each time.  Within the negligible
stress they are the values the grid holds.
"""

import dataclasses

import numpy as np
import pytest
from scipy.optimize import brentq

from characteristics import grid as moc_grid
from characteristics import lattice as moc
from characteristics.isentrope import isentrope_for
from materials import get

NEGLIGIBLE = 2.46e5
"""Pa: the negligible stress of the symmetric Al 2024 impact (1e-3 x its scale)."""


def _zone(negligible: float) -> moc.Zone:
    al = get("Al2024")
    shocked = al.wave_curve(al.reference_state(), 1, "hugoniot").state_at(5e9)
    # the same stress and velocity, 37 J/kg hotter: a slightly larger volume
    e = shocked.e + 37.0
    v = brentq(lambda v: al.stress(v, e) - shocked.sigma, shocked.v, 1.001 * shocked.v,
               xtol=1e-16, rtol=1e-15)
    hotter = dataclasses.replace(shocked, v=v, e=e)
    own, far = isentrope_for(al, shocked), isentrope_for(al, hotter)
    jp, jm = own.invariants(shocked)
    # eight C- rays of a release fan, 4 m/s apart in J-, running left onto the contact
    k = 8
    jm_cells = jm + 4.0 * np.arange(k + 1)
    return moc.Zone(
        table=own, family=-np.ones(k, dtype=np.int8),
        own=0.5 * (jm_cells[:-1] + jm_cells[1:]),
        x0=np.linspace(1e-3, 2e-3, k), t0=np.zeros(k), speed=-6e3 * np.ones(k),
        jp=np.full(k + 1, jp), jm=jm_cells,
        left=moc.Reflector(0.0, "join", 0.0, join=moc.Join(
            table=far, invariant=far.invariants(hotter)[0], strength=np.inf,
            stress=shocked.sigma)),
        right=moc.Reflector(3e-3, "stress", 0.0), t_now=0.0, horizon=1e-6,
        negligible=negligible)


def test_the_snap_width_is_half_the_negligible_stress_as_an_invariant():
    zone = _zone(NEGLIGIBLE)
    grid = moc_grid.Grid(zone)
    join = zone.left.join
    c = zone.table.speed_at_stress(join.stress)
    assert grid.snap == pytest.approx(NEGLIGIBLE / (zone.table.material.rho0 * c), rel=1e-12)
    # a wave of stress d sigma moves its invariant by 2 d sigma / (rho0 C_L): the width
    # drops waves of at most half the negligible stress
    assert 0.5 * grid.snap * zone.table.material.rho0 * c == pytest.approx(NEGLIGIBLE / 2)


def test_weak_reflections_are_values_the_grid_holds():
    exact = moc_grid.Grid(_zone(0.0))
    snapped = moc_grid.Grid(_zone(NEGLIGIBLE))
    assert exact.snap == 0.0
    # the exact grid grows at every round by new invariants the contact reflects ...
    assert exact.p.size > 10 * snapped.p.size
    # ... each within the width of one the snapped grid holds: nothing resolved is lost
    for values, held in ((exact.p, snapped.p), (exact.m, snapped.m)):
        gap = np.min(np.abs(values[:, None] - held[None, :]), axis=1)
        assert np.max(gap) <= snapped.snap
    # the contact node's reflection of every held J- is a held J+, within the width of
    # the exact reflection, and its transmission is solved exactly
    key = (+1, ("join", "left"))
    reflected, far = exact._reflect(("join", "left"), snapped.m, +1, np.empty(0))
    mapped = np.asarray(snapped.maps[key])
    assert np.all(mapped >= 0)
    dropped = np.abs(snapped.p[mapped] - reflected)
    assert np.max(dropped) <= snapped.snap
    # what was dropped is the weak reflection itself: the fan's J- step from the
    # contact's state times a reflection coefficient of order the 2.3e-6 volume jump
    steps = snapped.m[1:-1] - snapped.m[0]
    assert np.all((1e-7 < dropped[1:-1] / steps) & (dropped[1:-1] / steps < 1e-5))
    np.testing.assert_allclose(snapped.emitted[key][1], far[1], rtol=0, atol=1e-12)


def test_a_ray_the_contact_reflects_nothing_of_ends_there():
    """Every ray of the fan reaches the contact, whose reflection (about 1e-6 of the
    ray's step) is dropped by the snap: the cell behind the ray reaches the contact
    unchanged, so no reflected characteristic leaves (kept, eight rays carrying no
    wave would ring between the contact and the far end, one node at each meeting,
    for ever: the spalled fragment of the symmetric Al 2024 impact at 16 rays)."""
    zone = _zone(NEGLIGIBLE)
    # the far end holds the stress of the cell at it, as a free face holds zero
    far_end = zone.table.arrays_at_phi(np.array([0.5 * (zone.jp[-1] - zone.jm[-1])]))[0]
    zone = dataclasses.replace(zone, right=moc.Reflector(3e-3, "stress", float(far_end[0])))
    lat = moc.solve(zone)
    assert lat.reason == "horizon"
    # one node per arriving ray, and every ray went through into the hotter side
    assert lat.nodes == 8
    assert lat.emitted["left"]["t"].size == 8
    # nothing is left in the zone but the state behind the fan, exactly
    assert lat.live_segments.size == 0
    (cell,) = lat.live_cells
    assert (lat.cell_jp[cell], lat.cell_jm[cell]) == (zone.jp[-1], zone.jm[-1])
