"""Characteristic lattices: a region of one isentrope solved in bulk.

A *zone* is a run of characteristics (rays) of both families inside one material on
one isentrope, bounded at each end either by a boundary that reflects them (a free
surface, a wall, a gap face, a prescribed stress or velocity) or by a front the zone
does not own (a shock, a contact, a ray on another isentrope).  Between rays the
engine keeps constant cells, each carrying its invariants ``(J+, J-)``; each ray
carries its own invariant (``J+`` for a right-going ray ``C+``, ``J-`` for ``C-``).

Inside a zone every interaction is a node of the method of characteristics:

- a ``C+`` ray ``a`` meets a ``C-`` ray ``b``: the cell between them becomes
  ``(J+ of the cell left of a, J- of the cell right of b)``; ``a`` goes on at
  ``C_L(J+_a, J-_right)``, ``b`` at ``-C_L(J+_left, J-_b)``: the characteristic speed of
  the state each carries on its new segment (the midpoint of that segment in the
  lattice, so node positions are second order in the ray spacing);
- a ray reaches a reflecting boundary: the cell at the boundary takes the arriving
  invariant and the one the boundary condition gives (``sigma = sigma_b``:
  ``J-`` = ``J+ - 2 phi(sigma_b)``; ``u = u_b``: ``J- = 2 u_b - J+``), and a ray of the
  other family leaves with the reflected invariant of the arriving one.

States depend on the invariants alone, so every state the zone can reach is a point
of the grid ``(J+ values) x (J- values)`` (the reflections close the two sets); the
grid is evaluated on the isentrope once, in one vectorised call.  The geometry is
then swept in parallel: every adjacent pair ``(C+, C-)`` crosses at once (crossings
of disjoint pairs commute), every ray at a reflecting end reflects, and the sweep
repeats.  A sweep is a handful of numpy operations; a lattice of ``N x M`` nodes
needs about ``N + M`` sweeps.

The zone stops (is *cut*) at the first time anything it does not model would
happen, found in a first pass and enforced in a second: the horizon given by the
caller (the next event of the fronts bounding it, the end time); a ray of the zone
reaching a bounding front; two rays of one family converging (a compression wave
steepening into a shock); tension reaching the material's strength (the first
fracture point, located on the continuous field, see ``first_fracture``); a state
outside the table.  Everything before the cut is final; the rays and cells alive
at the cut go back to the engine's queue.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from materials import StateOutOfRangeError

from .fracture import FractureZone, fracture_zone
from .isentrope import Isentrope

REFLECTION_ROUNDS = 4
"""Reflections of reflections tabulated in the grid of invariants (a ray ringing between
two reflecting ends needs more; the zone is cut where the grid runs out)."""

CROSSING, RIGHT_REFLECTION, LEFT_REFLECTION = 0, 1, 2
"""Kinds of node."""


@dataclass(frozen=True)
class Reflector:
    """A reflecting end of a zone at position ``x`` (m): it holds ``"stress"`` or
    ``"velocity"`` at ``value`` (Pa or m/s)."""

    x: float
    holds: str
    value: float


@dataclass(frozen=True)
class Bound:
    """A front bounding a zone that the zone does not own: its current path
    ``X = x0 + speed (t - t0)``."""

    x0: float
    t0: float
    speed: float

    def position(self, t):
        return self.x0 + self.speed * (t - self.t0)


@dataclass
class Zone:
    """The input of a lattice: rays left to right and the cells around them.

    Arrays per ray: ``family`` (+1 for ``C+``, -1 for ``C-``), ``own`` (its invariant,
    m/s), ``x0``, ``t0``, ``speed`` (its current segment).  Arrays per cell (one more
    than rays; cell ``k`` is left of ray ``k``): ``jp``, ``jm``.  ``left``/``right``: a
    ``Reflector`` or a ``Bound`` at each end.  ``t_now`` (s): no node before it;
    ``horizon`` (s): no node at or after it.  ``strength`` (Pa): the tension the
    material carries, except inside the ``carried`` intervals ``(x_lo, x_hi)`` (m) of
    earlier fracture zones.  ``tag``: a label per ray, carried through crossings and
    reflections to the segments it makes (``Lattice.seg_tag``).
    """

    table: Isentrope
    family: np.ndarray
    own: np.ndarray
    x0: np.ndarray
    t0: np.ndarray
    speed: np.ndarray
    jp: np.ndarray
    jm: np.ndarray
    left: Reflector | Bound
    right: Reflector | Bound
    t_now: float
    horizon: float
    strength: float = math.inf
    tag: np.ndarray | None = None
    carried: tuple = ()


@dataclass
class Lattice:
    """The solved zone up to its cut.

    Segments are numbered with the input rays' current segments first (``0 ... K-1``);
    cells with the input cells first (``0 ... K``).  Per segment: ``seg_x0``, ``seg_t0``,
    ``seg_speed``, ``seg_t1`` (NaN while alive), ``seg_family``, ``seg_own``, ``seg_left``,
    ``seg_right`` (cell indices), ``seg_start`` (node index, -1 for an input).  Per cell:
    its state (``cell_sigma``, ``cell_u``, ``cell_v``, ``cell_e``), invariants, and
    ``cell_t0``/``cell_t1`` (NaN: alive).  ``chain_*``: points on the left (side 0) or right
    (side 1) boundary of a cell, in the order they were made.  ``live_segments`` and
    ``live_cells``: the zone at the cut, left to right.  ``node_*``: the nodes, with the
    state each carries (``node_sigma``) and its kind.  ``cut`` (s) and ``reason`` say
    where and why the zone stopped; ``fracture`` is the first point where tension
    reaches the strength and the zone the threshold fractures, if that is the reason;
    ``tension_at`` (s) the first node or cell in tension beyond the strength and
    ``tension_sample`` its ``(x, t, sigma)``.
    """

    nodes: int = 0
    node_x: np.ndarray = field(default_factory=lambda: np.empty(0))
    node_t: np.ndarray = field(default_factory=lambda: np.empty(0))
    node_kind: np.ndarray = field(default_factory=lambda: np.empty(0, dtype=int))
    node_sigma: np.ndarray = field(default_factory=lambda: np.empty(0))
    seg_x0: np.ndarray = None
    seg_t0: np.ndarray = None
    seg_speed: np.ndarray = None
    seg_t1: np.ndarray = None
    seg_family: np.ndarray = None
    seg_own: np.ndarray = None
    seg_left: np.ndarray = None
    seg_right: np.ndarray = None
    seg_start: np.ndarray = None
    seg_tag: np.ndarray = None
    cell_sigma: np.ndarray = None
    cell_u: np.ndarray = None
    cell_v: np.ndarray = None
    cell_e: np.ndarray = None
    cell_jp: np.ndarray = None
    cell_jm: np.ndarray = None
    cell_t0: np.ndarray = None
    cell_t1: np.ndarray = None
    chain_cell: np.ndarray = None
    chain_side: np.ndarray = None
    chain_node: np.ndarray = None
    live_segments: np.ndarray = None
    live_cells: np.ndarray = None
    end_changes: dict = field(default_factory=lambda: {"left": [], "right": []})
    cut: float = math.inf
    reason: str = ""
    fracture: FractureZone | None = None
    tension_at: float = math.inf
    tension_sample: tuple | None = None


class _Grid:
    """States on the grid of invariant values ``P x M`` (``J+`` values by ``J-`` values)."""

    def __init__(self, zone: Zone):
        table = zone.table
        plus = [zone.jp, zone.own[zone.family > 0]]
        minus = [zone.jm, zone.own[zone.family < 0]]
        p_values = np.unique(np.concatenate(plus))
        m_values = np.unique(np.concatenate(minus))
        right, left = zone.right, zone.left
        for _ in range(REFLECTION_ROUNDS):
            grown = False
            if isinstance(right, Reflector):
                m_new = np.setdiff1d(_reflect(table, right, p_values, -1), m_values)
                if m_new.size:
                    m_values, grown = np.union1d(m_values, m_new), True
            if isinstance(left, Reflector):
                p_new = np.setdiff1d(_reflect(table, left, m_values, +1), p_values)
                if p_new.size:
                    p_values, grown = np.union1d(p_values, p_new), True
            if not grown:
                break
        self.p, self.m = p_values, m_values
        phi = 0.5 * (p_values[:, None] - m_values[None, :])
        sigma, v, e, c = table.arrays_at_phi(phi.ravel())
        shape = phi.shape
        self.sigma, self.v, self.e, self.c = (a.reshape(shape) for a in (sigma, v, e, c))
        self.u = 0.5 * (p_values[:, None] + m_values[None, :])
        # reflection maps between indices (-1 where the reflected value is not tabulated)
        self.right_map = (_index_map(_reflect(table, right, p_values, -1), m_values)
                          if isinstance(right, Reflector) else None)
        self.left_map = (_index_map(_reflect(table, left, m_values, +1), p_values)
                         if isinstance(left, Reflector) else None)

    def p_index(self, values):
        return np.searchsorted(self.p, values)

    def m_index(self, values):
        return np.searchsorted(self.m, values)


def _reflect(table: Isentrope, end: Reflector, values: np.ndarray, to: int) -> np.ndarray:
    """Invariants reflected by ``end`` from ``values``: ``to = -1`` maps ``J+`` to ``J-`` (a
    right end), ``to = +1`` maps ``J-`` to ``J+`` (a left end)."""
    if end.holds == "velocity":
        return 2.0 * end.value - values
    phi_b = table.phi_at_stress(end.value)
    return values - 2.0 * phi_b if to < 0 else values + 2.0 * phi_b


def _index_map(values: np.ndarray, table_values: np.ndarray) -> np.ndarray:
    index = np.searchsorted(table_values, values)
    index = np.clip(index, 0, len(table_values) - 1)
    return np.where(table_values[index] == values, index, -1)


def _meet(x0a, t0a, sa, x0b, t0b, sb):
    """Time at which two lines ``X = x0 + s (t - t0)`` meet (inf if they do not approach)."""
    closing = sa - sb
    with np.errstate(divide="ignore", invalid="ignore"):
        t = (x0b - x0a + sa * t0a - sb * t0b) / closing
    return np.where(closing > 0.0, np.maximum(t, np.maximum(t0a, t0b)), np.inf)


def solve(zone: Zone) -> Lattice:
    """Solve ``zone`` up to its cut (see the module docstring).

    The first pass runs to the first exception other than tension, so that the whole
    unrelieved tension field is known; if it reaches the strength, the first fracture
    and the zone the threshold fractures are found on it (``characteristics.fracture``)
    and a second pass stops at the first fracture.
    """
    try:
        grid = _Grid(zone)
    except StateOutOfRangeError:
        return _empty(zone, zone.t_now, "state outside the table")
    first = _sweep(zone, grid, zone.horizon)
    cut, reason, found = first.cut, first.reason, None
    if first.tension_at < cut:
        found = _fracture_zone(zone, first)
        if found is not None and found.t < cut:
            cut, reason = max(found.t, zone.t_now), "tension"
    if first.nodes and np.max(first.node_t) >= cut:
        result = _sweep(zone, grid, cut)
    else:
        result = first
    result.cut, result.reason = cut, reason
    result.fracture = found if reason == "tension" else None
    return result


def _fracture_zone(zone: Zone, lattice: Lattice):
    """The first fracture and its zone on the first pass's field, outside earlier zones."""
    strength = zone.strength
    try:
        speed = zone.table.speed_at_stress(-strength)
    except StateOutOfRangeError:
        speed = float(np.max(np.abs(zone.speed))) if zone.speed.size else 1.0
    found = fracture_zone(lattice, strength, speed, zone.carried)
    if found is None and lattice.tension_sample is not None:
        x, t, _ = lattice.tension_sample
        found = FractureZone(x=x, t=t, x_lo=x, t_lo=t, x_hi=x, t_hi=t)
    return found


def _empty(zone: Zone, cut: float, reason: str) -> Lattice:
    """The zone unchanged: nothing could be solved (no grid)."""
    k = len(zone.family)
    out = Lattice()
    out.seg_x0, out.seg_t0, out.seg_speed = zone.x0.copy(), zone.t0.copy(), zone.speed.copy()
    out.seg_t1 = np.full(k, np.nan)
    out.seg_family, out.seg_own = zone.family.copy(), zone.own.copy()
    out.seg_left, out.seg_right = np.arange(k), np.arange(1, k + 1)
    out.seg_start = np.full(k, -1)
    out.seg_tag = _tags(zone)
    out.live_segments, out.live_cells = np.arange(k), np.arange(k + 1)
    out.cut, out.reason = cut, reason
    return out


class _Records:
    """What a sweep makes, gathered as arrays per sweep and joined once at the end."""

    def __init__(self, zone: Zone, grid: _Grid, pi, mi):
        k = len(zone.family)
        self.segments = k
        self.cells = k + 1
        self.nodes = 0
        self.seg = {"x0": [zone.x0.astype(float)], "t0": [zone.t0.astype(float)],
                    "speed": [zone.speed.astype(float)], "family": [zone.family.astype(int)],
                    "own": [zone.own.astype(float)], "left": [np.arange(k)],
                    "right": [np.arange(1, k + 1)], "start": [np.full(k, -1)],
                    "tag": [_tags(zone)]}
        self.seg_end = ([], [])
        self.end_changes = {"left": [], "right": []}
        self.cell = {"p": [pi.copy()], "m": [mi.copy()], "t0": [np.full(k + 1, np.nan)]}
        self.cell_end = ([], [])
        self.chain = ([], [], [])
        self.node = {"x": [], "t": [], "kind": [], "sigma": []}

    def add_nodes(self, x, t, kind, sigma) -> np.ndarray:
        ids = self.nodes + np.arange(len(x))
        self.nodes += len(x)
        for name, values in (("x", x), ("t", t), ("kind", kind), ("sigma", sigma)):
            self.node[name].append(values)
        return ids

    def add_segments(self, **fields) -> np.ndarray:
        count = len(fields["x0"])
        ids = self.segments + np.arange(count)
        self.segments += count
        for name, values in fields.items():
            self.seg[name].append(values)
        return ids

    def add_cells(self, p, m, t0) -> np.ndarray:
        ids = self.cells + np.arange(len(p))
        self.cells += len(p)
        self.cell["p"].append(p)
        self.cell["m"].append(m)
        self.cell["t0"].append(t0)
        return ids

    def end_segments(self, ids, t) -> None:
        self.seg_end[0].append(ids)
        self.seg_end[1].append(t)

    def end_cells(self, ids, t) -> None:
        self.cell_end[0].append(ids)
        self.cell_end[1].append(t)

    def add_chain(self, cells, sides, nodes) -> None:
        self.chain[0].append(cells)
        self.chain[1].append(sides)
        self.chain[2].append(nodes)

    def lattice(self, grid: _Grid, seg, cell) -> Lattice:
        out = Lattice()
        out.nodes = self.nodes
        if self.nodes:
            out.node_x, out.node_t, out.node_kind, out.node_sigma = (
                np.concatenate(self.node[name]) for name in ("x", "t", "kind", "sigma"))
        for name, parts in self.seg.items():
            setattr(out, f"seg_{name}", np.concatenate(parts))
        out.seg_t1 = _ends(self.segments, self.seg_end)
        p_all, m_all = np.concatenate(self.cell["p"]), np.concatenate(self.cell["m"])
        out.cell_sigma, out.cell_u = grid.sigma[p_all, m_all], grid.u[p_all, m_all]
        out.cell_v, out.cell_e = grid.v[p_all, m_all], grid.e[p_all, m_all]
        out.cell_jp, out.cell_jm = grid.p[p_all], grid.m[m_all]
        out.cell_t0 = np.concatenate(self.cell["t0"])
        out.cell_t1 = _ends(self.cells, self.cell_end)
        if self.chain[0]:
            out.chain_cell, out.chain_side, out.chain_node = (
                np.concatenate(part).astype(int) for part in self.chain)
        else:
            out.chain_cell = out.chain_side = out.chain_node = np.empty(0, dtype=int)
        out.live_segments, out.live_cells = seg.copy(), cell.copy()
        out.end_changes = self.end_changes
        return out


def _tags(zone: Zone) -> np.ndarray:
    return (np.arange(len(zone.family)) if zone.tag is None
            else np.asarray(zone.tag, dtype=int))


def _ends(count: int, ends) -> np.ndarray:
    t1 = np.full(count, np.nan)
    if ends[0]:
        t1[np.concatenate(ends[0])] = np.concatenate(ends[1])
    return t1


_CROSSING_SIDES = np.array([0, 1, 1, 0, 0, 1])
"""Chain sides at a crossing: the middle cell closes (both sides), the cell left of the
pair gains a vertex on its right, the cell right of it on its left, the new cell opens."""


def _sweep(zone: Zone, grid: _Grid, cut: float) -> Lattice:
    """Process every node before ``cut``; record the earliest exception."""
    k = len(zone.family)
    fam = zone.family.astype(np.int8).copy()
    own_idx = np.where(fam > 0, grid.p_index(zone.own), grid.m_index(zone.own))
    x0, t0 = zone.x0.astype(float).copy(), zone.t0.astype(float).copy()
    sp = zone.speed.astype(float).copy()
    seg = np.arange(k)
    tag = _tags(zone).copy()
    pi, mi = grid.p_index(zone.jp), grid.m_index(zone.jm)
    cell = np.arange(k + 1)
    rec = _Records(zone, grid, pi, mi)
    exceptions = [(cut, "horizon", None)]
    tension_hit = [math.inf, None]
    ever_left, ever_right = ({0}, {k - 1}) if k else (set(), set())
    tension = zone.strength
    limit = cut
    while k:
        # --- crossings of adjacent (C+, C-) pairs
        pairs = np.nonzero((fam[:-1] > 0) & (fam[1:] < 0))[0]
        if pairs.size:
            t_cross = _meet(x0[pairs], t0[pairs], sp[pairs], x0[pairs + 1], t0[pairs + 1],
                            sp[pairs + 1])
            ok = t_cross < limit
            pairs, t_cross = pairs[ok], t_cross[ok]
        right_hit = _reflection_time(zone.right, fam[-1] > 0, x0[-1], t0[-1], sp[-1], limit)
        left_hit = _reflection_time(zone.left, fam[0] < 0, x0[0], t0[0], sp[0], limit)
        if not pairs.size and right_hit is None and left_hit is None:
            break
        if pairs.size:
            a, b = pairs, pairs + 1
            xn = x0[a] + sp[a] * (t_cross - t0[a])
            new_p, new_m = pi[a], mi[b + 1]  # the left cell's J+, the right cell's J-
            oa, ob = own_idx[a].copy(), own_idx[b].copy()
            speed_a, speed_b = grid.c[oa, new_m], -grid.c[new_p, ob]
            ids = rec.add_nodes(xn, t_cross, np.full(pairs.size, CROSSING), grid.sigma[oa, ob])
            middle = cell[b]
            rec.end_cells(middle, t_cross)
            new_cells = rec.add_cells(new_p, new_m, t_cross)
            rec.add_chain(np.concatenate([middle, middle, cell[a], cell[b + 1], new_cells,
                                          new_cells]),
                          np.repeat(_CROSSING_SIDES, pairs.size), np.tile(ids, 6))
            rec.end_segments(np.concatenate([seg[a], seg[b]]), np.concatenate([t_cross,
                                                                                 t_cross]))
            both = np.concatenate([xn, xn])
            seg_ids = rec.add_segments(
                x0=both, t0=np.concatenate([t_cross, t_cross]),
                speed=np.concatenate([speed_b, speed_a]),
                family=np.concatenate([fam[b], fam[a]]).astype(int),
                own=np.concatenate([grid.m[ob], grid.p[oa]]),
                left=np.concatenate([cell[a], new_cells]),
                right=np.concatenate([new_cells, cell[b + 1]]),
                start=np.concatenate([ids, ids]), tag=np.concatenate([tag[b], tag[a]]))
            tag[a], tag[b] = tag[b].copy(), tag[a].copy()
            fam[a], fam[b] = -1, 1
            own_idx[a], own_idx[b] = ob, oa
            x0[a] = x0[b] = xn
            t0[a] = t0[b] = t_cross
            sp[a], sp[b] = speed_b, speed_a
            seg[a], seg[b] = seg_ids[:pairs.size], seg_ids[pairs.size:]
            cell[b] = new_cells
            pi[b], mi[b] = new_p, new_m
            _note_tension(tension_hit, grid.sigma[new_p, new_m], t_cross, xn, tension,
                          zone.carried)
            _note_tension(tension_hit, grid.sigma[oa, ob], t_cross, xn, tension, zone.carried)
        for end, hit in (("right", right_hit), ("left", left_hit)):
            if hit is not None:
                _reflect_end(end, hit, zone, grid, rec, exceptions, fam, own_idx, x0, t0, sp,
                             seg, cell, pi, mi, tension, tag, tension_hit)
        # --- same-family rays converging (a compression steepening into a shock)
        same = np.nonzero(fam[:-1] == fam[1:])[0]
        if same.size:
            t_meet = _meet(x0[same], t0[same], sp[same], x0[same + 1], t0[same + 1],
                           sp[same + 1])
            first = float(np.min(t_meet))
            if first < limit:
                exceptions.append((first, "overtake", None))
        ever_left.add(int(seg[0]))
        ever_right.add(int(seg[-1]))
        limit = min(limit, min(e[0] for e in exceptions))
    out = rec.lattice(grid, seg, cell)
    # the bounding fronts: the first time a ray of the zone would reach one
    _note_bounds(exceptions, zone, out, ever_left, ever_right)
    when, why, _ = min(exceptions, key=lambda item: item[0])
    out.cut, out.reason = when, why
    out.tension_at, out.tension_sample = tension_hit
    return out


def _reflection_time(end, arriving: bool, x0: float, t0: float, speed: float,
                     limit: float) -> float | None:
    """When the ray at an end reaches it, if the end reflects and that is before ``limit``."""
    if not (arriving and isinstance(end, Reflector)):
        return None
    t = max(t0 + (end.x - x0) / speed, t0)
    return t if t < limit else None


def _reflect_end(end, hit, zone, grid, rec, exceptions, fam, own_idx, x0, t0, sp, seg, cell,
                 pi, mi, tension, tag, tension_hit) -> None:
    """The ray at ``end`` reflects at time ``hit``: a node on the boundary, a new cell at it
    and a ray of the other family leaving."""
    k = len(fam)
    if end == "right":
        r, at, came_from = k - 1, k, k - 1
        new_p = int(pi[came_from])
        new_m = int(grid.right_map[new_p])
        refl = int(grid.right_map[own_idx[r]])
        p_node, m_node = int(own_idx[r]), refl
        new_family, side = -1, 1
        speed_new = -grid.c[new_p, refl] if min(new_m, refl) >= 0 else 0.0
        own_value = grid.m[refl]
        x_end = zone.right.x
    else:
        r, at, came_from = 0, 0, 1
        new_m = int(mi[came_from])
        new_p = int(grid.left_map[new_m])
        refl = int(grid.left_map[own_idx[r]])
        p_node, m_node = refl, int(own_idx[r])
        new_family, side = 1, 0
        speed_new = grid.c[refl, new_m] if min(new_p, refl) >= 0 else 0.0
        own_value = grid.p[refl]
        x_end = zone.left.x
    if min(new_p, new_m, refl) < 0:
        exceptions.append((hit, "reflections beyond the tabulated grid", None))
        return
    (node,) = rec.add_nodes(np.array([x_end]), np.array([hit]),
                            np.array([RIGHT_REFLECTION if end == "right" else LEFT_REFLECTION]),
                            np.array([grid.sigma[p_node, m_node]]))
    boundary_cell, other = int(cell[at]), int(cell[came_from])
    rec.end_cells(np.array([boundary_cell]), np.array([hit]))
    (new_cell,) = rec.add_cells(np.array([new_p]), np.array([new_m]), np.array([hit]))
    rec.add_chain(np.array([boundary_cell, boundary_cell, other, new_cell, new_cell]),
                  np.array([0, 1, side, 0, 1]), np.full(5, node))
    rec.end_segments(np.array([seg[r]]), np.array([hit]))
    fam[r], own_idx[r] = new_family, refl
    x0[r], t0[r], sp[r] = x_end, hit, speed_new
    cell[at] = new_cell
    pi[at], mi[at] = new_p, new_m
    (seg[r],) = rec.add_segments(
        x0=np.array([x_end]), t0=np.array([hit]), speed=np.array([speed_new]),
        family=np.array([new_family]), own=np.array([own_value]),
        left=np.array([cell[r]]), right=np.array([cell[r + 1]]), start=np.array([node]),
        tag=np.array([tag[r]]))
    rec.end_changes[end].append((hit, int(new_cell)))
    _note_tension(tension_hit, grid.sigma[[new_p], [new_m]], np.array([hit]), np.array([x_end]),
                  tension, zone.carried)


def _note_tension(hit: list, sigma, t, x, strength, carried) -> None:
    """Keep in ``hit`` (``[time, (x, t, sigma)]``) the first of the states ``sigma`` (made
    at times ``t``, positions ``x``) in tension beyond ``strength`` outside the
    ``carried`` intervals."""
    if not math.isfinite(strength):
        return
    beyond = sigma <= -strength
    for lo, hi in carried:
        beyond &= (x < lo) | (x > hi)
    beyond = np.nonzero(beyond)[0]
    if beyond.size:
        first = beyond[np.argmin(t[beyond])]
        if t[first] < hit[0]:
            hit[0] = float(t[first])
            hit[1] = (float(x[first]), float(t[first]), float(sigma[first]))


def _note_bounds(exceptions, zone: Zone, out: Lattice, ever_left, ever_right) -> None:
    """The first time a segment that was ever at an open end meets the front there."""
    for end, ids in (("left", ever_left), ("right", ever_right)):
        bound = zone.left if end == "left" else zone.right
        if not isinstance(bound, Bound) or not ids:
            continue
        idx = np.fromiter(ids, int, len(ids))
        x0, t0, s = out.seg_x0[idx], out.seg_t0[idx], out.seg_speed[idx]
        t1 = np.where(np.isnan(out.seg_t1[idx]), np.inf, out.seg_t1[idx])
        if end == "left":
            t = _meet(np.full(idx.size, bound.x0), np.full(idx.size, bound.t0),
                      np.full(idx.size, bound.speed), x0, t0, s)
        else:
            t = _meet(x0, t0, s, np.full(idx.size, bound.x0), np.full(idx.size, bound.t0),
                      np.full(idx.size, bound.speed))
        valid = (t >= t0) & (t <= t1)
        if np.any(valid):
            exceptions.append((float(np.min(t[valid])), f"{end} bound", None))
