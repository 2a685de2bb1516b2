"""Continuous records from characteristics: the state between rays.

Along a line of the X–t plane (a station's history, or a profile at one instant) the
solution is a sequence of cells separated by the fronts that cross the line.  A shock
or a contact is a jump.  A ray is a characteristic: across a ``C+`` ray only ``J+``
changes, across a ``C-`` ray only ``J-``, and the ray carries its own exact value.
Between the rays of a run of cells on one isentrope each invariant is interpolated
linearly between the crossings of its own family, and the state is evaluated from the two
invariants on the isentrope: exact at each ray, second order in the ray spacing
between them, continuous everywhere but at shocks and contacts (beyond the first and
last ray of its family an invariant keeps the ray's value; the run's two end knots
are the end cells' own states).  Cells of a wave
without an isentrope table (a solid's elastic release) are joined by straight lines
through the mean states at the rays.

The result is a list of knots: ``(coordinate, state)``, linear in between, a jump
where two knots share a coordinate.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from materials import State


@dataclass(frozen=True)
class Cell:
    """A cell met along the line: its ``state``, its isentrope ``table`` (or ``None``) and
    its invariants ``(J+, J-)`` on that table (or ``None``)."""

    state: State
    table: object = None
    invariants: tuple | None = None


@dataclass(frozen=True)
class Crossing:
    """A front crossing the line between two cells: ``ray`` (a characteristic with its
    own ``invariant`` of ``family`` +1 for ``J+`` or -1 for ``J-``) or not (a jump)."""

    ray: bool
    family: int = 0
    invariant: float = float("nan")


def knots(coords: list[float], crossings: list[list[Crossing]], cells: list[Cell]
          ) -> tuple[list[float], list[State]]:
    """Knots of the continuous record along a line.

    ``coords[k]`` is where the fronts ``crossings[k]`` (one or several through the same
    point) cross the line, between ``cells[k]`` and ``cells[k + 1]``.
    """
    out_x: list[float] = []
    out_s: list[State] = []
    n = len(coords)
    start = 0  # first cell of the current run
    for k in range(n + 1):
        ends_run = k == n or not _smooth(crossings[k], cells[k], cells[k + 1])
        if not ends_run:
            continue
        x_run, s_run = _run(coords, crossings, cells, start, k)
        out_x += x_run
        out_s += s_run
        start = k + 1
    return out_x, out_s


def _smooth(group: list[Crossing], before: Cell, after: Cell) -> bool:
    """Whether the record is continuous across this point: only rays, one wave on either
    side (both with a table, the same one, or both without)."""
    return all(c.ray for c in group) and before.table is after.table


def _run(coords, crossings, cells, first: int, last: int) -> tuple[list, list[State]]:
    """Knots of the run of cells ``first ... last`` (the crossings between them are rays):
    from its start (``coords[first - 1]``, or the cell's own state if the line starts in
    it) to its end (``coords[last]``)."""
    lo = coords[first - 1] if first > 0 else None
    hi = coords[last] if last < len(coords) else None
    inner = range(first, last)  # crossings inside the run
    if first == last:
        state = cells[first].state
        xs = [x for x in (lo, hi) if x is not None]
        return xs, [state] * len(xs)
    table = cells[first].table
    if table is not None and all(cells[i].invariants is not None
                                 for i in range(first, last + 1)) and _resolved(
                                     table, cells, first, last):
        return _run_on_table(coords, crossings, cells, first, last, lo, hi, table)
    # no table: straight lines through the mean states at the rays
    xs, states = [], []
    if lo is not None:
        xs.append(lo)
        states.append(cells[first].state)
    for k in inner:
        xs.append(coords[k])
        states.append(_mean(cells[k].state, cells[k + 1].state))
    if hi is not None:
        xs.append(hi)
        states.append(cells[last].state)
    return xs, states


def _resolved(table, cells, first: int, last: int) -> bool:
    """Whether the run's waves are strong enough to be read from the table."""
    jp = [cells[i].invariants[0] for i in range(first, last + 1)]
    jm = [cells[i].invariants[1] for i in range(first, last + 1)]
    return table.resolves(max(max(jp) - min(jp), max(jm) - min(jm)))


def _run_on_table(coords, crossings, cells, first, last, lo, hi, table):
    knot_x = [x for x in (lo, *(coords[k] for k in range(first, last)), hi) if x is not None]
    plus = _invariant(coords, crossings, cells, first, last, +1)
    minus = _invariant(coords, crossings, cells, first, last, -1)
    at = np.array(knot_x)
    jp, jm = plus(at), minus(at)
    # the two invariants are interpolated apart, so their half difference may step past
    # the cells' own range (and past the table's end where a release stopped at the end
    # of its equation of state: Cu released from 286 GPa); it is held within that range
    own = [0.5 * (cells[i].invariants[0] - cells[i].invariants[1])
           for i in range(first, last + 1)]
    phi = np.clip(0.5 * (jp - jm), min(own), max(own))
    sigma, v, e, _ = table.arrays_at_phi(phi)
    u = 0.5 * (jp + jm)
    states = [State(sigma=float(a), u=float(b), v=float(c), e=float(d))
              for a, b, c, d in zip(sigma, u, v, e, strict=True)]
    # the run's ends are its cells' own states (exact), not re-evaluated ones
    if lo is not None:
        states[0] = cells[first].state
    if hi is not None:
        states[-1] = cells[last].state
    return knot_x, states


def _invariant(coords, crossings, cells, first, last, family):
    """The invariant of ``family`` along the run as a function of the coordinate: linear
    between the crossings of that family's rays, the cells' values beyond them."""
    index = 0 if family > 0 else 1
    xs, values = [], []
    for k in range(first, last):
        for c in crossings[k]:
            if c.ray and c.family == family:
                xs.append(coords[k])
                values.append(c.invariant)
                break
    if not xs:
        constant = cells[first].invariants[index]
        return lambda at: np.full(np.shape(at), constant)
    xs_arr, values_arr = np.array(xs), np.array(values)
    return lambda at: np.interp(at, xs_arr, values_arr)


def _mean(a: State, b: State) -> State:
    return State(sigma=0.5 * (a.sigma + b.sigma), u=0.5 * (a.u + b.u), v=0.5 * (a.v + b.v),
                 e=0.5 * (a.e + b.e))
