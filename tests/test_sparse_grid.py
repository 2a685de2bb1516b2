"""A lattice whose grid of states is too large to tabulate at once reads it row by row.

A release fan ringing in an Al 2024 layer bonded to Cu on both sides reflects at each
join with a coefficient of a few tenths, and every round of reflections adds as many
invariant values as arrive: in the Cu/Al/Cu/Al stack below a fan of 123 rays needed
grids of 500 x 500 states and more.  Such grids were refused (``GridTooLarge``), so the
fan's rays crossed one Riemann solve at a time: 12 036 events to 0.6 us (2 351 of them
in 10 ns).  ``characteristics.grid._SparseStates`` evaluates the rows a lattice reads,
by the same vectorised call to the isentrope table as a dense grid.
"""

import numpy as np
import pytest
from test_grid_join import NEGLIGIBLE, _zone

import fronttrack as ft
from characteristics import grid as moc_grid
from fronttrack.scene import Accuracy, Layer, Scene
from materials import get


def test_a_sparse_grid_reads_the_states_of_the_dense_one(monkeypatch):
    zone = _zone(NEGLIGIBLE)
    dense = moc_grid.Grid(zone)
    monkeypatch.setattr(moc_grid, "MAX_GRID_STATES", 0)
    sparse = moc_grid.Grid(zone)
    assert isinstance(sparse.rows["sigma"], moc_grid._SparseRows)
    np.testing.assert_array_equal(sparse.p, dense.p)
    np.testing.assert_array_equal(sparse.m, dense.m)
    for name in ("sigma", "u", "c"):
        for i in range(dense.p.size):
            assert list(sparse.rows[name][i]) == dense.rows[name][i]
    rows, cols = np.meshgrid(np.arange(dense.p.size), np.arange(dense.m.size), indexing="ij")
    for name in ("sigma", "u", "v", "e"):
        np.testing.assert_array_equal(getattr(sparse, name)[rows.ravel(), cols.ravel()],
                                      getattr(dense, name)[rows, cols].ravel())
    assert sparse.maps == dense.maps


def test_a_sparse_grid_refuses_a_range_past_its_table_as_a_dense_one_does(monkeypatch):
    zone = _zone(NEGLIGIBLE)
    far_out = zone.jm.copy()
    far_out[-1] += 1e5  # a J- beyond any state of the isentrope
    monkeypatch.setattr(zone, "jm", far_out)
    with pytest.raises(ft.StateOutOfRangeError):
        moc_grid.Grid(zone)
    monkeypatch.setattr(moc_grid, "MAX_GRID_STATES", 0)
    with pytest.raises(ft.StateOutOfRangeError):
        moc_grid.Grid(zone)


def test_a_fan_ringing_between_two_joins_is_one_lattice_not_a_riemann_solve_per_crossing():
    cu, al = get("Cu"), get("Al2024")
    scene = Scene(layers=(Layer(cu, 1e-3, 1000.0), Layer(al, 1e-3), Layer(cu, 1e-3),
                          Layer(al, 1e-3)), t_end=0.6e-6, accuracy=Accuracy())
    solution = ft.run(scene)
    # 459 events (12 036 when such grids were refused)
    assert solution.stats["events"] < 1_000
    balance = solution.accuracy_report["balance"]
    # the lattice is exact on its isentrope; what is lost is the neglected waves' (-1.9e-4)
    assert balance["momentum_error"] < 1e-5
    assert -balance["promised"] < balance["energy_error"] < 0.0
