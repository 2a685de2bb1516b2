"""The grid of states a lattice can reach, evaluated once.

In a zone of one isentrope every state is fixed by its two Riemann invariants, and the
values they take are those of the cells and rays the zone starts with, closed under
the reflections its ends and gaps make: a free surface or a prescribed stress maps
``J+`` to ``J- = J+ - 2 phi(sigma_b)``, a wall or a prescribed velocity to
``J- = 2 u_b - J+``, and a contact to another isentrope (a join) by the contact node
of the method of characteristics (equal stress and velocity on both sides, each side
on its own isentrope).  The states on the grid ``(J+ values) x (J- values)`` come from
one vectorised call to the isentrope table; the lattice then reads them by index.

A contact node reflects part of what arrives: a weak contact (an entropy jump left
behind a decaying shock, impedances equal within 1e-6) reflects a ray of step ``dJ`` as a
new invariant ``R dJ`` from one the grid holds, whose own reflections are new again,
so the set of values never closes and the grid outgrows ``MAX_GRID_STATES`` (the
symmetric Al 2024 impact at 16 rays: 1 636 grids of 467 x 443 built and thrown away to
2.25 us).  A value a contact node reflects within ``Zone.negligible / (rho0 C_L)`` of
one the grid holds is therefore taken as that value: the wave so dropped carries a
stress below half the negligible stress (a simple wave of stress ``d sigma`` moves its
invariant by ``2 d sigma / (rho0 C_L)``), the amplitude the engine's Riemann solves
drop too.

A zone between two joins (a fan ringing in a layer bonded to other materials on both
sides: a Cu/Al/Cu/Al stack) reflects at each end with a coefficient of a few tenths,
and each round adds as many values as arrive: 123 rays between two Cu plates made
500 x 500 grids and more, and each event tried one and gave up, so the fan's crossings
went to the Riemann solver one by one (2 351 in 10 ns).  A lattice visits a few states
of each row, so a grid beyond ``MAX_GRID_STATES`` is evaluated where it is read
(``_SparseStates``): a row at a time, by the same call to the isentrope table.
"""

from __future__ import annotations

import math
import weakref

import numpy as np

from materials import StateOutOfRangeError

from .isentrope import Isentrope

REFLECTION_ROUNDS = 4
"""Reflections of reflections tabulated in the grid (a ray ringing between two
reflecting ends needs more; the lattice stops where the grid runs out)."""


MAX_GRID_STATES = 200_000
"""Largest grid a lattice tabulates at once; a larger one is evaluated state by state
where the lattice reads it (``_SparseStates``)."""

MAX_GRID_VALUES = 20_000
"""Most invariant values (``J+`` and ``J-`` together) a grid holds; a zone that would
need more (many rays with many reflections of reflections) is left to the queue's
Riemann solves."""


class GridTooLarge(Exception):
    """The zone's grid would hold more than ``MAX_GRID_VALUES`` invariant values."""


class Grid:
    """States on the grid of invariant values ``P x M`` (``J+`` values by ``J-`` values),
    closed under the reflections the zone can make.

    A reflection is keyed by ``(to, condition)``: ``to = -1`` maps ``J+`` values to ``J-``
    (a right end, a gap's left face), ``+1`` maps ``J-`` to ``J+``; ``condition`` is
    ``(holds, value)`` for a boundary or ``("join", end)`` for a contact to another
    isentrope, whose transmitted waves are kept in ``emitted``.
    """

    def __init__(self, zone):
        self.table = zone.table
        self.joins = {}
        self.to_minus, self.to_plus = [], []
        for end, conditions in (("right", self.to_minus), ("left", self.to_plus)):
            bc = getattr(zone, end)
            if getattr(bc, "holds", None) is not None:
                if bc.join is not None:
                    self.joins[end] = bc.join
                    conditions.append(("join", end))
                else:
                    conditions.append((bc.holds, bc.value))
        if any(site.kind == "gap" for site in zone.sites):
            self.to_minus.append(("stress", 0.0))
            self.to_plus.append(("stress", 0.0))
        self.snap = _snap_width(zone, self.joins)
        p_values = np.unique(np.concatenate([zone.jp, zone.own[zone.family > 0]]))
        m_values = np.unique(np.concatenate([zone.jm, zone.own[zone.family < 0]]))
        for _ in range(REFLECTION_ROUNDS):
            grown = False
            for condition in self.to_minus:
                new = self._reflect(condition, p_values, -1, m_values)[0]
                new = np.setdiff1d(new[np.isfinite(new)], m_values)
                if new.size:
                    m_values, grown = np.union1d(m_values, new), True
            for condition in self.to_plus:
                new = self._reflect(condition, m_values, +1, p_values)[0]
                new = np.setdiff1d(new[np.isfinite(new)], p_values)
                if new.size:
                    p_values, grown = np.union1d(p_values, new), True
            # the sets only grow: a grid too large now stays too large
            if p_values.size + m_values.size > MAX_GRID_VALUES:
                raise GridTooLarge(f"{p_values.size} x {m_values.size} states")
            if not grown:
                break
        self.p, self.m = p_values, m_values
        if p_values.size * m_values.size <= MAX_GRID_STATES:
            phi = 0.5 * (p_values[:, None] - m_values[None, :])
            sigma, v, e, c = self.table.arrays_at_phi(phi.ravel())
            self.sigma, self.v, self.e = (a.reshape(phi.shape) for a in (sigma, v, e))
            self.u = 0.5 * (p_values[:, None] + m_values[None, :])
            self.rows = {"sigma": self.sigma.tolist(), "u": self.u.tolist(),
                         "c": c.reshape(phi.shape).tolist()}
        else:
            states = _SparseStates(self.table, p_values, m_values)
            self.sigma, self.v, self.e, self.u = (states.column(k) for k in range(4))
            self.rows = {"sigma": states.rows(0), "u": states.rows(3), "c": states.rows(4)}
        self.p_list, self.m_list = p_values.tolist(), m_values.tolist()
        self.maps, self.emitted = {}, {}
        for to, conditions, source, target in ((-1, self.to_minus, p_values, m_values),
                                               (+1, self.to_plus, m_values, p_values)):
            for condition in conditions:
                reflected, far = self._reflect(condition, source, to, target)
                self.maps[(to, condition)] = _index_map(reflected, target).tolist()
                if far is not None:
                    self.emitted[(to, condition)] = tuple(a.tolist() for a in far)

    def _reflect(self, condition, values: np.ndarray, to: int, held: np.ndarray):
        """Invariants reflected from ``values`` (see the class docstring), and for a join
        ``(contact stress, far invariant, far speed)`` per value (NaN where the contact
        leaves the tables).  A join's reflected invariant within ``snap`` (m/s) of one
        of the ``held`` values (sorted) is that value (see the module docstring)."""
        holds, value = condition
        if holds == "velocity":
            return 2.0 * value - values, None
        if holds == "stress":
            phi_b = self.table.phi_at_stress(value)
            return (values - 2.0 * phi_b if to < 0 else values + 2.0 * phi_b), None
        join = self.joins[value]
        sigma, phi_own, phi_far, c_far = _contact_node(self.table, join, values, to)
        if to < 0:  # arriving J+ from the left; the far cell keeps J-
            reflected, far = values - 2.0 * phi_own, (sigma, values - phi_own + phi_far, c_far)
        else:
            reflected, far = values + 2.0 * phi_own, (sigma, values + phi_own - phi_far, c_far)
        return _snapped(reflected, held, self.snap), far

    def p_index(self, values):
        return np.searchsorted(self.p, values)

    def m_index(self, values):
        return np.searchsorted(self.m, values)


class _SparseStates:
    """The states of a grid ``P x M`` evaluated a row at a time where they are read, and
    kept: row ``i`` holds ``(sigma, v, e, u, C_L)`` lists over ``j``, at ``phi = (P_i -
    M_j) / 2`` and ``u = (P_i + M_j) / 2`` (Pa, m^3/kg, J/kg, m/s, m/s), from the
    isentrope table's vectorised call, as a dense grid evaluates them.  Its
    stress-function range is checked up front (the corners ``P_max - M_min`` and
    ``P_min - M_max``), so that a grid reaching past the table is refused as a dense one
    is (``StateOutOfRangeError``)."""

    def __init__(self, table: Isentrope, p: np.ndarray, m: np.ndarray):
        self.table, self.p, self.m = table, p, m
        table.arrays_at_phi(0.5 * np.array([p[-1] - m[0], p[0] - m[-1]]))
        self.known: dict = {}

    def row(self, i: int) -> tuple:
        """Row ``i``: the lists ``(sigma, v, e, u, C_L)`` over the ``J-`` values."""
        found = self.known.get(i)
        if found is None:
            p = self.p[i]
            sigma, v, e, c = self.table.arrays_at_phi(0.5 * (p - self.m))
            found = self.known[i] = tuple(a.tolist() for a in (sigma, v, e, 0.5 * (p + self.m),
                                                                c))
        return found

    def rows(self, k: int) -> _SparseRows:
        """Quantity ``k`` of the states, read as ``rows[i][j]``."""
        return _SparseRows(self, k)

    def column(self, k: int) -> _SparseColumn:
        """Quantity ``k`` of the states, read as ``column[P, M]`` (index arrays)."""
        return _SparseColumn(self, k)


class _SparseRows:
    """``rows[i][j]``: quantity ``k`` of state ``(i, j)`` of a ``_SparseStates``."""

    def __init__(self, states: _SparseStates, k: int):
        self.states, self.k = states, k

    def __getitem__(self, i: int) -> list:
        return self.states.row(i)[self.k]


class _SparseColumn:
    """``column[P, M]``: quantity ``k`` of the states ``(P[n], M[n])`` as an array."""

    def __init__(self, states: _SparseStates, k: int):
        self.states, self.k = states, k

    def __getitem__(self, index: tuple) -> np.ndarray:
        row, k = self.states.row, self.k
        return np.array([row(int(i))[k][int(j)] for i, j in zip(*index, strict=True)],
                        dtype=float)


CONTACT_NEWTON_STEPS = 12
"""Newton steps of the contact node (the stress function is smooth and monotone)."""

CONTACT_STRESS_ROUNDING = 1e-12
"""The contact node's stress is converged to this fraction of the modulus ``rho0 C_L^2``
(the tables' own rounding: a tighter test never passes and spends every step)."""


_NODES: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()
"""Contact nodes solved in a run, per own isentrope table: ``{(id of the far table, far
invariant, to): {arriving invariant: (sigma, phi_own, phi_far, C_far)}}``.  A contact
stays while the fans on one side cross it, and each event rebuilds the zone's grid
from mostly the same invariants (94 % of the nodes of the 16-ray Al 2024 impact to
2.25 us had been solved before); a node depends on its three invariants alone, and the
tables live as long as the run."""


def _contact_node(table: Isentrope, join, values: np.ndarray, to: int):
    """Stress at a contact between this zone's isentrope and the join's, where ``values``
    (this side's arriving invariants) meet the far side's kept invariant:
    ``phi_own(sigma) + phi_far(sigma) = J+_arriving - J-_far`` (a right end) or
    ``J+_far - J-_arriving`` (a left end).  Returns ``(sigma, phi_own, phi_far, C_far)``
    per value, NaN where the stress leaves either table.  Nodes solved before in the
    run are looked up (``_NODES``)."""
    known = _NODES.setdefault(table, {}).setdefault(
        (id(join.table), join.invariant, to), {})
    listed = values.tolist()
    missing = [v for v in dict.fromkeys(listed) if v not in known and math.isfinite(v)]
    if missing:
        solved = np.column_stack(_solve_contact_node(table, join, np.array(missing), to))
        if np.all(np.isfinite(solved)):
            known.update(zip(missing, solved.tolist(), strict=True))
        else:  # the stress leaves a table: as before, none of this batch is kept
            return _solve_contact_node(table, join, values, to)
    nan = (math.nan,) * 4
    return tuple(np.array([known.get(v, nan) for v in listed]).reshape(-1, 4).T)


def _solve_contact_node(table: Isentrope, join, values: np.ndarray, to: int):
    """``_contact_node`` solved by Newton's method on the stress for every value."""
    rhs = values - join.invariant if to < 0 else join.invariant - values
    rho_own, rho_far = table.material.rho0, join.table.material.rho0
    sigma = np.full(values.shape, float(join.stress))
    nan = np.full(values.shape, np.nan)
    for _ in range(CONTACT_NEWTON_STEPS):
        try:
            phi_own, c_own = table.arrays_at_stress(sigma)
            phi_far, c_far = join.table.arrays_at_stress(sigma)
        except StateOutOfRangeError:
            return nan, nan, nan, nan
        with np.errstate(divide="ignore"):
            # a side at zero sound speed (a gas at zero pressure) is infinitely
            # compliant: the slope is infinite and that node's stress stays put
            slope = 1.0 / (rho_own * c_own) + 1.0 / (rho_far * c_far)
        step = (phi_own + phi_far - rhs) / slope
        sigma = sigma - step
        if np.all(np.abs(step) <= CONTACT_STRESS_ROUNDING * rho_own * c_own * c_own):
            break
    try:
        phi_own, _ = table.arrays_at_stress(sigma)
        phi_far, c_far = join.table.arrays_at_stress(sigma)
    except StateOutOfRangeError:
        return nan, nan, nan, nan
    return sigma, phi_own, phi_far, c_far


def _snap_width(zone, joins: dict) -> float:
    """Invariant distance (m/s) within which a contact node's reflection is taken as
    a value the grid holds: ``Zone.negligible / (rho0 C_L)`` at each join's stress
    (the smaller over the joins; zero without a join, and zero where a join's sound
    speed vanishes, as in a gas at zero pressure: no invariant distance there is within
    a stress tolerance, so nothing is snapped)."""
    if not joins or zone.negligible <= 0.0:
        return 0.0
    rho0 = zone.table.material.rho0
    try:
        speeds = [zone.table.speed_at_stress(join.stress) for join in joins.values()]
    except StateOutOfRangeError:
        return 0.0
    slowest = min(speeds)
    return zone.negligible / (rho0 * slowest) if slowest > 0.0 else 0.0


def _snapped(values: np.ndarray, held: np.ndarray, width: float) -> np.ndarray:
    """``values`` with each one within ``width`` of a ``held`` value (sorted) replaced
    by the nearest such value."""
    if width <= 0.0 or held.size == 0:
        return values
    index = np.searchsorted(held, values)
    above = np.minimum(index, held.size - 1)
    below = np.maximum(index - 1, 0)
    nearest = np.where(np.abs(held[above] - values) < np.abs(held[below] - values),
                       held[above], held[below])
    return np.where(np.abs(nearest - values) <= width, nearest, values)


def _index_map(values: np.ndarray, table_values: np.ndarray) -> np.ndarray:
    index = np.clip(np.searchsorted(table_values, values), 0, len(table_values) - 1)
    return np.where((table_values[index] == values) & np.isfinite(values), index, -1)
