"""Characteristic lattices: a region of one isentrope solved in bulk.

A *zone* is a run of characteristics (rays) of both families inside one material on
one isentrope.  Between rays the engine keeps constant cells, each carrying its
invariants ``(J+, J-)``; each ray carries its own invariant (``J+`` for a right-going
ray ``C+``, ``J-`` for a left-going ``C-``).  A zone may contain *sites* that do not
move: a contact across which the isentrope continues (rays pass through it), and an
open gap (each face a free surface).  Each end of a zone is either a boundary that
reflects (a free surface, a wall, a prescribed stress or velocity, the face of a gap)
or a front the zone does not own (a shock, a contact to another isentrope...).

Inside a zone every interaction is a node of the method of characteristics:

- a ``C+`` ray ``a`` meets a ``C-`` ray ``b``: the cell between them becomes
  ``(J+ of the cell left of a, J- of the cell right of b)``; ``a`` goes on at
  ``C_L(J+_a, J-_right)``, ``b`` at ``-C_L(J+_left, J-_b)``: the characteristic speed of
  the state each carries on its new segment (the midpoint of that segment in the
  lattice, so node positions are second order in the ray spacing);
- a ray reaches a reflecting boundary or a gap face: the cell at the boundary takes the
  arriving invariant and the one the boundary condition gives (``sigma = sigma_b``:
  ``J- = J+ - 2 phi(sigma_b)``; ``u = u_b``: ``J- = 2 u_b - J+``), and a ray of the other
  family leaves with the reflected invariant of the arriving one;
- a ray reaches a contact it passes: it goes on; the cell it leaves behind on the
  far side has the invariants of the one on the near side.

States depend on the invariants alone, so every state the zone can reach is a point of
the grid ``(J+ values) x (J- values)`` (the reflections close the two sets); the grid
is evaluated on the isentrope once, in one vectorised call.  The geometry is then swept
in parallel: every adjacent pair ``(C+, C-)`` crosses at once (crossings of disjoint
pairs commute), every ray at a boundary, a face or a contact is handled, and the sweep
repeats.  A lattice of ``N x M`` nodes needs about ``N + M`` sweeps.

The zone stops (is *cut*) at the first time anything it does not model would happen,
found in a first pass and enforced in a second: the horizon given by the caller (the
next event of the fronts bounding it, the end time); a ray reaching a bounding front;
two rays of one family converging (a compression steepening into a shock); a contact
reaching the tension it carries (it opens); a gap closing; a state outside the table;
tension reaching the material's strength (the first fracture point, located on the
continuous field by ``characteristics.fracture``).  Everything before the cut is final;
the rays and cells alive at the cut go back to the engine's queue.
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

CROSSING, RIGHT_REFLECTION, LEFT_REFLECTION, PASSAGE = 0, 1, 2, 3
"""Kinds of node."""

PASS, GAP = "pass", "gap"
"""Kinds of site inside a zone."""


@dataclass(frozen=True)
class Reflector:
    """A reflecting end of a zone at position ``x`` (m): it holds ``"stress"`` or
    ``"velocity"`` at ``value`` (Pa or m/s).  The face of a gap is a free surface with
    ``gap``: ``(u_other, width, time)``, the velocity (m/s) of the face across the gap
    and the gap's Eulerian width (m) at ``time`` (s), so that the zone sees it close."""

    x: float
    holds: str
    value: float
    gap: tuple | None = None


@dataclass(frozen=True)
class Bound:
    """A front bounding a zone that the zone does not own: its current path
    ``X = x0 + speed (t - t0)``."""

    x0: float
    t0: float
    speed: float


@dataclass(frozen=True)
class Site:
    """A site inside a zone: ``kind`` ``PASS`` (a contact rays go through; it opens under a
    tension of ``strength`` Pa) or ``GAP`` (an open gap of Eulerian ``width`` m at
    ``time`` s, whose faces reflect)."""

    kind: str
    x: float
    strength: float = math.inf
    width: float = 0.0
    time: float = 0.0


@dataclass
class Zone:
    """The input of a lattice: slots (rays and sites) left to right and the cells
    between them.

    Arrays per slot: ``family`` (+1 for ``C+``, -1 for ``C-``, 0 for a site), ``own`` (a
    ray's invariant, m/s), ``x0``, ``t0``, ``speed`` (its current segment; a site's
    position and speed 0).  ``sites``: the ``Site`` of each site slot, in order.  Arrays
    per cell (one more than slots; cell ``k`` is left of slot ``k``): ``jp``, ``jm``.
    ``left``/``right``: a ``Reflector`` or a ``Bound`` at each end.  ``t_now`` (s): no
    node before it; ``horizon`` (s): no node at or after it.  ``strength`` (Pa): the
    tension the material carries, except inside the ``carried`` intervals
    ``(x_lo, x_hi)`` (m) of earlier fracture zones.  ``tag``: a label per slot, carried
    through crossings and reflections to the segments it makes (``Lattice.seg_tag``).
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
    sites: tuple = ()


@dataclass
class Lattice:
    """The solved zone up to its cut.

    Segments are numbered with the input slots' current segments first (``0 ... K-1``;
    a site's "segment" never ends); cells with the input cells first (``0 ... K``).  Per
    segment: ``seg_x0``, ``seg_t0``, ``seg_speed``, ``seg_t1`` (NaN while alive),
    ``seg_family``, ``seg_own``, ``seg_left``, ``seg_right`` (cell indices),
    ``seg_start`` (node index, -1 for an input), ``seg_tag``.  Per cell: its state
    (``cell_sigma``, ``cell_u``, ``cell_v``, ``cell_e``), invariants, and
    ``cell_t0``/``cell_t1`` (NaN: alive), ``cell_sites`` (how many sites lie left of it:
    which layer it is in).  ``chain_*``: points on the left (side 0) or right
    (side 1) boundary of a cell.  ``live_segments``/``live_cells``: the zone at the cut,
    left to right.  ``site_changes``: per site (in order, then ``"left"``/``"right"`` for
    the ends), the ``(t, cell)`` changes of the cell on its right (left end: the cell
    at it).  ``gaps``: per gap site and gap end, ``(width, time)`` at the cut.
    ``node_*``: the nodes, with the stress each carries and its kind.  ``cut`` (s) and
    ``reason`` say where and why the zone stopped; ``fracture`` is the first point where
    tension reaches the strength with the zone the threshold fractures, if that is the
    reason; ``tension_at`` (s) and ``tension_sample`` ``(x, t, sigma)``: the first node or
    cell in tension beyond the strength.
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
    cell_sites: np.ndarray = None
    chain_cell: np.ndarray = None
    chain_side: np.ndarray = None
    chain_node: np.ndarray = None
    live_segments: np.ndarray = None
    live_cells: np.ndarray = None
    site_changes: dict = field(default_factory=dict)
    gaps: dict = field(default_factory=dict)
    cut: float = math.inf
    reason: str = ""
    fracture: FractureZone | None = None
    tension_at: float = math.inf
    tension_sample: tuple | None = None


# --- the grid of states ------------------------------------------------------------------
class _Grid:
    """States on the grid of invariant values ``P x M`` (``J+`` values by ``J-`` values),
    closed under the reflections the zone can make."""

    def __init__(self, zone: Zone):
        table = zone.table
        self.to_minus = []  # conditions mapping J+ to J- (a right end, a gap's left face)
        self.to_plus = []  # conditions mapping J- to J+ (a left end, a gap's right face)
        if isinstance(zone.right, Reflector):
            self.to_minus.append((zone.right.holds, zone.right.value))
        if isinstance(zone.left, Reflector):
            self.to_plus.append((zone.left.holds, zone.left.value))
        if any(site.kind == GAP for site in zone.sites):
            self.to_minus.append(("stress", 0.0))
            self.to_plus.append(("stress", 0.0))
        p_values = np.unique(np.concatenate([zone.jp, zone.own[zone.family > 0]]))
        m_values = np.unique(np.concatenate([zone.jm, zone.own[zone.family < 0]]))
        for _ in range(REFLECTION_ROUNDS):
            grown = False
            for condition in self.to_minus:
                new = np.setdiff1d(_reflect(table, condition, p_values, -1), m_values)
                if new.size:
                    m_values, grown = np.union1d(m_values, new), True
            for condition in self.to_plus:
                new = np.setdiff1d(_reflect(table, condition, m_values, +1), p_values)
                if new.size:
                    p_values, grown = np.union1d(p_values, new), True
            if not grown:
                break
        self.p, self.m = p_values, m_values
        phi = 0.5 * (p_values[:, None] - m_values[None, :])
        sigma, v, e, c = table.arrays_at_phi(phi.ravel())
        self.sigma, self.v, self.e, self.c = (a.reshape(phi.shape) for a in (sigma, v, e, c))
        self.u = 0.5 * (p_values[:, None] + m_values[None, :])
        self.maps = {}
        for condition in self.to_minus:
            self.maps[(-1, condition)] = _index_map(_reflect(table, condition, p_values, -1),
                                                    m_values)
        for condition in self.to_plus:
            self.maps[(+1, condition)] = _index_map(_reflect(table, condition, m_values, +1),
                                                    p_values)

    def p_index(self, values):
        return np.searchsorted(self.p, values)

    def m_index(self, values):
        return np.searchsorted(self.m, values)


def _reflect(table: Isentrope, condition, values: np.ndarray, to: int) -> np.ndarray:
    """Invariants a boundary holding ``condition`` (``(holds, value)``) reflects from
    ``values``: ``to = -1`` maps ``J+`` to ``J-`` (a right end), ``+1`` maps ``J-`` to ``J+``."""
    holds, value = condition
    if holds == "velocity":
        return 2.0 * value - values
    phi_b = table.phi_at_stress(value)
    return values - 2.0 * phi_b if to < 0 else values + 2.0 * phi_b


def _index_map(values: np.ndarray, table_values: np.ndarray) -> np.ndarray:
    index = np.clip(np.searchsorted(table_values, values), 0, len(table_values) - 1)
    return np.where(table_values[index] == values, index, -1)


def _meet(x0a, t0a, sa, x0b, t0b, sb):
    """Time at which two lines ``X = x0 + s (t - t0)`` meet (inf if they do not approach)."""
    closing = sa - sb
    with np.errstate(divide="ignore", invalid="ignore"):
        t = (x0b - x0a + sa * t0a - sb * t0b) / closing
    return np.where(closing > 0.0, np.maximum(t, np.maximum(t0a, t0b)), np.inf)


# --- solving -----------------------------------------------------------------------------
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
        return _Sweeper(zone, None, zone.t_now).unchanged("state outside the table")
    first = _Sweeper(zone, grid, zone.horizon).run()
    cut, reason, found = first.cut, first.reason, None
    if first.tension_at < cut:
        found = _fracture_zone(zone, first)
        if found is not None and found.t < cut:
            cut, reason = max(found.t, zone.t_now), "tension"
    if first.nodes and np.max(first.node_t) >= cut:
        result = _Sweeper(zone, grid, cut).run()
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
    return fracture_zone(lattice, strength, speed, zone.carried)


_CROSSING_SIDES = np.array([0, 1, 1, 0, 0, 1])
"""Chain sides at a crossing or a passage: the cell between the two closes (both sides),
the cell left of the pair gains a vertex on its right, the cell right of it on its
left, the new cell opens."""


class _Sweeper:
    """One pass over a zone: the state arrays, the records, the exceptions."""

    def __init__(self, zone: Zone, grid: _Grid | None, cut: float):
        self.zone, self.grid, self.cut = zone, grid, cut
        k = len(zone.family)
        self.k = k
        self.fam = zone.family.astype(np.int8).copy()
        self.x0 = zone.x0.astype(float).copy()
        self.t0 = zone.t0.astype(float).copy()
        self.sp = zone.speed.astype(float).copy()
        self.seg = np.arange(k)
        self.tag = (np.arange(k) if zone.tag is None else np.asarray(zone.tag, int)).copy()
        self.cell = np.arange(k + 1)
        self.site_of_slot = np.full(k, -1)
        self.site_of_slot[np.nonzero(self.fam == 0)[0]] = np.arange(len(zone.sites))
        # records, joined at the end
        self.seg_rec = {"x0": [self.x0.copy()], "t0": [self.t0.copy()],
                        "speed": [self.sp.copy()], "family": [self.fam.astype(int)],
                        "own": [zone.own.astype(float)], "left": [np.arange(k)],
                        "right": [np.arange(1, k + 1)], "start": [np.full(k, -1)],
                        "tag": [self.tag.copy()]}
        self.n_seg, self.n_cell, self.n_node = k, k + 1, 0
        self.seg_end, self.cell_end = ([], []), ([], [])
        self.chain = ([], [], [])
        self.node = {"x": [], "t": [], "kind": [], "sigma": []}
        self.site_changes = {i: [] for i in range(len(zone.sites))} | {"left": [], "right": []}
        self.gaps = {i: (s.width, s.time) for i, s in enumerate(zone.sites) if s.kind == GAP}
        for end in ("left", "right"):
            bc = getattr(zone, end)
            if isinstance(bc, Reflector) and bc.gap is not None:
                self.gaps[end] = bc.gap[1:]
        self.exceptions = [(cut, "horizon")]
        self.tension = [math.inf, None]
        self.ever = ({0}, {k - 1}) if k else (set(), set())
        if grid is not None:
            self.own = np.where(self.fam > 0, grid.p_index(zone.own),
                                np.where(self.fam < 0, grid.m_index(zone.own), -1))
            self.pi, self.mi = grid.p_index(zone.jp), grid.m_index(zone.jm)
            self.cell_p, self.cell_m = [self.pi.copy()], [self.mi.copy()]
        self.cell_t0 = [np.full(k + 1, np.nan)]
        self.cell_sites = [np.concatenate([[0], np.cumsum(self.fam == 0)])]

    # --- records ----------------------------------------------------------------------
    def _add_nodes(self, x, t, kind, sigma) -> np.ndarray:
        ids = self.n_node + np.arange(len(x))
        self.n_node += len(x)
        for name, values in (("x", x), ("t", t), ("kind", kind), ("sigma", sigma)):
            self.node[name].append(np.asarray(values, dtype=float if name != "kind" else int))
        return ids

    def _add_segments(self, **fields) -> np.ndarray:
        ids = self.n_seg + np.arange(len(fields["x0"]))
        self.n_seg += len(ids)
        for name, values in fields.items():
            self.seg_rec[name].append(np.asarray(values))
        return ids

    def _add_cells(self, p, m, t, positions) -> np.ndarray:
        """New cells at slot positions ``positions`` (the cell left of slot ``q`` is at
        ``q``), with the count of sites to their left (which layer they are in)."""
        ids = self.n_cell + np.arange(len(p))
        self.n_cell += len(ids)
        sites_left = np.concatenate([[0], np.cumsum(self.fam == 0)])
        self.cell_sites.append(sites_left[np.asarray(positions)])
        self.cell_p.append(np.asarray(p))
        self.cell_m.append(np.asarray(m))
        self.cell_t0.append(np.asarray(t, dtype=float))
        return ids

    def _chain(self, cells, sides, nodes) -> None:
        self.chain[0].append(np.asarray(cells))
        self.chain[1].append(np.asarray(sides))
        self.chain[2].append(np.asarray(nodes))

    def _note_tension(self, sigma, t, x) -> None:
        """Keep the first of the states ``sigma`` (made at times ``t``, positions ``x``) in
        tension beyond the strength outside the carried intervals."""
        strength = self.zone.strength
        if not math.isfinite(strength):
            return
        beyond = np.asarray(sigma) <= -strength
        x = np.asarray(x)
        for lo, hi in self.zone.carried:
            beyond &= (x < lo) | (x > hi)
        beyond = np.nonzero(beyond)[0]
        if beyond.size:
            t = np.asarray(t)
            first = beyond[np.argmin(t[beyond])]
            if t[first] < self.tension[0]:
                self.tension = [float(t[first]), (float(x[first]), float(t[first]),
                                                  float(np.asarray(sigma)[first]))]

    # --- the pass -----------------------------------------------------------------------
    def run(self) -> Lattice:
        self._open_gaps()
        limit = min(self.cut, min(e[0] for e in self.exceptions))
        while self.k:
            if not self._sweep(limit):
                break
            limit = min(limit, min(e[0] for e in self.exceptions))
        return self._lattice()

    def _sweep(self, limit: float) -> bool:
        """One parallel sweep of every event before ``limit``; False if there was none."""
        fam, x0, t0, sp = self.fam, self.x0, self.t0, self.sp
        pairs = np.nonzero((fam[:-1] > 0) & (fam[1:] < 0))[0]
        if pairs.size:
            t_cross = _meet(x0[pairs], t0[pairs], sp[pairs], x0[pairs + 1], t0[pairs + 1],
                            sp[pairs + 1])
            ok = t_cross < limit
            pairs, t_cross = pairs[ok], t_cross[ok]
        site_events = self._site_events(limit)
        end_events = self._end_events(limit)
        if not pairs.size and not site_events and not end_events:
            return False
        if pairs.size:
            self._cross(pairs, t_cross)
        for t, slot, face in site_events:
            if face == "pass":
                self._pass(slot, t)
            else:
                self._reflect(slot, t, face)
        for t, end in end_events:
            self._reflect(self.k - 1 if end == "right" else 0, t, end)
        self._note_overtakes(limit)
        self.ever[0].add(int(self.seg[0]))
        self.ever[1].add(int(self.seg[-1]))
        return True

    def _site_events(self, limit: float) -> list:
        """Rays reaching sites: ``(t, ray slot, "pass" or the face it reflects from)``."""
        fam, sites = self.fam, self.zone.sites
        events, used = [], set()
        for slot in np.nonzero(fam == 0)[0].tolist():
            site = sites[self.site_of_slot[slot]]
            arrivals = []
            if slot > 0 and fam[slot - 1] > 0:
                arrivals.append((self._arrival(slot - 1, site.x), slot - 1, "left face"))
            if slot + 1 < self.k and fam[slot + 1] < 0:
                arrivals.append((self._arrival(slot + 1, site.x), slot + 1, "right face"))
            arrivals = [a for a in arrivals if a[0] < limit and a[1] not in used]
            if site.kind == PASS and arrivals:
                arrivals = [min(arrivals)]  # one passage per site and sweep
            for t, ray, face in arrivals:
                used.add(ray)
                events.append((t, ray, "pass" if site.kind == PASS else face))
        return events

    def _arrival(self, slot: int, x: float) -> float:
        return max(self.t0[slot] + (x - self.x0[slot]) / self.sp[slot], self.t0[slot])

    def _end_events(self, limit: float) -> list:
        events = []
        zone, fam = self.zone, self.fam
        if isinstance(zone.right, Reflector) and fam[-1] > 0:
            t = self._arrival(self.k - 1, zone.right.x)
            if t < limit:
                events.append((t, "right"))
        if isinstance(zone.left, Reflector) and fam[0] < 0 and not (self.k == 1 and events):
            t = self._arrival(0, zone.left.x)
            if t < limit:
                events.append((t, "left"))
        return events

    def _cross(self, pairs: np.ndarray, t_cross: np.ndarray) -> None:
        grid, fam, own = self.grid, self.fam, self.own
        a, b = pairs, pairs + 1
        xn = self.x0[a] + self.sp[a] * (t_cross - self.t0[a])
        new_p, new_m = self.pi[a], self.mi[b + 1]  # the left cell's J+, the right cell's J-
        oa, ob = own[a].copy(), own[b].copy()
        speed_a, speed_b = grid.c[oa, new_m], -grid.c[new_p, ob]
        ids = self._add_nodes(xn, t_cross, np.full(pairs.size, CROSSING), grid.sigma[oa, ob])
        cell = self.cell
        middle = cell[b]
        self.cell_end[0].append(middle)
        self.cell_end[1].append(t_cross)
        new_cells = self._add_cells(new_p, new_m, t_cross, b)
        self._chain(np.concatenate([middle, middle, cell[a], cell[b + 1], new_cells, new_cells]),
                    np.repeat(_CROSSING_SIDES, pairs.size), np.tile(ids, 6))
        self.seg_end[0].append(np.concatenate([self.seg[a], self.seg[b]]))
        self.seg_end[1].append(np.concatenate([t_cross, t_cross]))
        seg_ids = self._add_segments(
            x0=np.concatenate([xn, xn]), t0=np.concatenate([t_cross, t_cross]),
            speed=np.concatenate([speed_b, speed_a]), family=np.concatenate(
                [np.full(pairs.size, -1), np.full(pairs.size, 1)]),
            own=np.concatenate([grid.m[ob], grid.p[oa]]),
            left=np.concatenate([cell[a], new_cells]),
            right=np.concatenate([new_cells, cell[b + 1]]),
            start=np.concatenate([ids, ids]), tag=np.concatenate([self.tag[b], self.tag[a]]))
        self.tag[a], self.tag[b] = self.tag[b].copy(), self.tag[a].copy()
        fam[a], fam[b] = -1, 1
        own[a], own[b] = ob, oa
        self.x0[a] = self.x0[b] = xn
        self.t0[a] = self.t0[b] = t_cross
        self.sp[a], self.sp[b] = speed_b, speed_a
        self.seg[a], self.seg[b] = seg_ids[:pairs.size], seg_ids[pairs.size:]
        cell[b] = new_cells
        self.pi[b], self.mi[b] = new_p, new_m
        self._note_tension(grid.sigma[new_p, new_m], t_cross, xn)
        self._note_tension(grid.sigma[oa, ob], t_cross, xn)

    def _pass(self, ray: int, t: float) -> None:
        """A ray goes through the contact next to it; the cell it leaves behind on the far
        side has the invariants of the near side's cell."""
        grid, right_going = self.grid, self.fam[ray] > 0
        site_slot = ray + 1 if right_going else ray - 1
        site = self.zone.sites[self.site_of_slot[site_slot]]
        lo = min(ray, site_slot)  # the pair occupies slots lo, lo + 1
        near = lo if right_going else lo + 2  # the cell the ray leaves behind
        new_p, new_m = int(self.pi[near]), int(self.mi[near])
        (node,) = self._add_nodes([site.x], [t], [PASSAGE], [grid.sigma[new_p, new_m]])
        cell = self.cell
        middle = int(cell[lo + 1])
        self.cell_end[0].append(np.array([middle]))
        self.cell_end[1].append(np.array([t]))
        self.seg_end[0].append(np.array([self.seg[ray]]))
        self.seg_end[1].append(np.array([t]))
        family, own_value = int(self.fam[ray]), self._own_value(ray)
        speed = self.sp[ray]
        # swap the ray and the site
        for array in (self.fam, self.own, self.tag, self.site_of_slot):
            array[lo], array[lo + 1] = array[lo + 1], array[lo]
        self.x0[lo], self.x0[lo + 1] = self.x0[lo + 1], self.x0[lo]
        self.t0[lo], self.t0[lo + 1] = self.t0[lo + 1], self.t0[lo]
        self.sp[lo], self.sp[lo + 1] = self.sp[lo + 1], self.sp[lo]
        self.seg[lo], self.seg[lo + 1] = self.seg[lo + 1], self.seg[lo]
        (new_cell,) = self._add_cells([new_p], [new_m], [t], [lo + 1])
        self._chain([middle, middle, cell[lo], cell[lo + 2], new_cell, new_cell],
                    _CROSSING_SIDES, np.full(6, node))
        ray = lo + 1 if right_going else lo
        cell[lo + 1] = new_cell
        self.pi[lo + 1], self.mi[lo + 1] = new_p, new_m
        self.x0[ray], self.t0[ray], self.sp[ray] = site.x, t, speed
        (self.seg[ray],) = self._add_segments(
            x0=[site.x], t0=[t], speed=[speed], family=[family], own=[own_value],
            left=[cell[ray]], right=[cell[ray + 1]], start=[node], tag=[self.tag[ray]])
        # the site's right cell: the new one (a C+ passed) or the far one (a C- passed)
        index = int(self.site_of_slot[lo if right_going else lo + 1])
        self.site_changes[index].append((t, int(cell[(lo if right_going else lo + 1) + 1])))
        sigma = grid.sigma[new_p, new_m]
        if sigma <= -site.strength:
            self.exceptions.append((t, "contact opens"))

    def _own_value(self, slot: int) -> float:
        return float(self.grid.p[self.own[slot]] if self.fam[slot] > 0
                     else self.grid.m[self.own[slot]])

    def _reflect(self, ray: int, t: float, where: str) -> None:
        """The ray in ``ray`` reflects at an end (``"left"``/``"right"``) or a gap face
        (``"left face"``: the face left of a gap, reached by a ``C+``)."""
        grid, zone = self.grid, self.zone
        right_going = self.fam[ray] > 0
        if where in ("left", "right"):
            end = getattr(zone, where)
            condition, x = (end.holds, end.value), end.x
        else:
            site_slot = ray + 1 if right_going else ray - 1
            condition, x = ("stress", 0.0), zone.sites[self.site_of_slot[site_slot]].x
        face = ray + 1 if right_going else ray  # the cell at the boundary
        came_from = ray if right_going else ray + 1
        if right_going:
            new_p = int(self.pi[came_from])
            new_m = int(grid.maps[(-1, condition)][new_p])
            refl = int(grid.maps[(-1, condition)][self.own[ray]])
            p_node, m_node = int(self.own[ray]), refl
        else:
            new_m = int(self.mi[came_from])
            new_p = int(grid.maps[(+1, condition)][new_m])
            refl = int(grid.maps[(+1, condition)][self.own[ray]])
            p_node, m_node = refl, int(self.own[ray])
        if min(new_p, new_m, refl) < 0:
            self.exceptions.append((t, "reflections beyond the tabulated grid"))
            return
        kind = RIGHT_REFLECTION if right_going else LEFT_REFLECTION
        (node,) = self._add_nodes([x], [t], [kind], [grid.sigma[p_node, m_node]])
        cell = self.cell
        old, other = int(cell[face]), int(cell[came_from])
        self.cell_end[0].append(np.array([old]))
        self.cell_end[1].append(np.array([t]))
        (new_cell,) = self._add_cells([new_p], [new_m], [t], [face])
        self._chain([old, old, other, new_cell, new_cell],
                    [0, 1, 1 if right_going else 0, 0, 1], np.full(5, node))
        self.seg_end[0].append(np.array([self.seg[ray]]))
        self.seg_end[1].append(np.array([t]))
        self.fam[ray], self.own[ray] = (-1, refl) if right_going else (1, refl)
        speed = -grid.c[new_p, refl] if right_going else grid.c[refl, new_m]
        self.x0[ray], self.t0[ray], self.sp[ray] = x, t, speed
        cell[face] = new_cell
        self.pi[face], self.mi[face] = new_p, new_m
        (self.seg[ray],) = self._add_segments(
            x0=[x], t0=[t], speed=[speed], family=[int(self.fam[ray])],
            own=[self._own_value(ray)], left=[cell[ray]], right=[cell[ray + 1]],
            start=[node], tag=[self.tag[ray]])
        self._note_tension([grid.sigma[new_p, new_m]], [t], [x])
        self._face_moved(ray, t, where, new_cell)

    def _face_moved(self, ray: int, t: float, where: str, new_cell: int) -> None:
        """Record the new cell at an end or a face; follow a gap's width to its closing."""
        if where == "left":
            self.site_changes["left"].append((t, new_cell))
        if where in ("left face", "right face"):
            # the ray has just reflected: from the left face it now goes left
            site_slot = ray + 1 if self.fam[ray] < 0 else ray - 1
            index = int(self.site_of_slot[site_slot])
            if where == "right face":
                self.site_changes[index].append((t, new_cell))
            self._gap_moved(index, t)
        elif getattr(self.zone, where).gap is not None:
            self._gap_moved(where, t)

    def _face_u(self, key, side: str) -> float:
        """Velocity (m/s) of a gap's face now: the cell at it, or the other side's face of
        a gap at an end of the zone."""
        if key in ("left", "right"):
            if side != key:  # the face inside the zone
                cell = 0 if key == "left" else self.k
                return float(self.grid.u[self.pi[cell], self.mi[cell]])
            return getattr(self.zone, key).gap[0]
        slot = int(np.nonzero(self.site_of_slot == key)[0][0])
        cell = slot if side == "left" else slot + 1
        return float(self.grid.u[self.pi[cell], self.mi[cell]])

    def _open_gaps(self) -> None:
        """Each gap's face velocities at the start, and when it closes if they stay."""
        self.faces = {}
        for key, (width, since) in self.gaps.items():
            self.faces[key] = (self._face_u(key, "left"), self._face_u(key, "right"))
            self._note_closing(key, width, since)

    def _gap_moved(self, key, t: float) -> None:
        """A face of a gap changed velocity at ``t``: advance its width, note its closing."""
        width, since = self.gaps[key]
        u_left, u_right = self.faces[key]
        width += (u_right - u_left) * (t - since)
        self.gaps[key] = (width, t)
        self.faces[key] = (self._face_u(key, "left"), self._face_u(key, "right"))
        self._note_closing(key, width, t)

    def _note_closing(self, key, width: float, since: float) -> None:
        u_left, u_right = self.faces[key]
        if u_left > u_right:
            self.exceptions.append((since + max(width, 0.0) / (u_left - u_right),
                                    "gap closes"))

    def _note_overtakes(self, limit: float) -> None:
        """Two adjacent rays of one family converging: a compression steepening."""
        fam = self.fam
        same = np.nonzero((fam[:-1] == fam[1:]) & (fam[:-1] != 0))[0]
        if same.size:
            t_meet = _meet(self.x0[same], self.t0[same], self.sp[same], self.x0[same + 1],
                           self.t0[same + 1], self.sp[same + 1])
            first = float(np.min(t_meet))
            if first < limit:
                self.exceptions.append((first, "overtake"))

    def unchanged(self, reason: str) -> Lattice:
        """The zone as it was: nothing could be solved."""
        out = self._lattice(states=False)
        out.cut, out.reason = self.zone.t_now, reason
        return out

    def _lattice(self, states: bool = True) -> Lattice:
        out = Lattice()
        out.nodes = self.n_node
        if self.n_node:
            out.node_x, out.node_t, out.node_kind, out.node_sigma = (
                np.concatenate(self.node[name]) for name in ("x", "t", "kind", "sigma"))
        for name, parts in self.seg_rec.items():
            setattr(out, f"seg_{name}", np.concatenate(parts))
        out.seg_t1 = _ends(self.n_seg, self.seg_end)
        if states:
            grid = self.grid
            p_all, m_all = np.concatenate(self.cell_p), np.concatenate(self.cell_m)
            out.cell_sigma, out.cell_u = grid.sigma[p_all, m_all], grid.u[p_all, m_all]
            out.cell_v, out.cell_e = grid.v[p_all, m_all], grid.e[p_all, m_all]
            out.cell_jp, out.cell_jm = grid.p[p_all], grid.m[m_all]
        out.cell_t0 = np.concatenate(self.cell_t0)
        out.cell_t1 = _ends(self.n_cell, self.cell_end)
        out.cell_sites = np.concatenate(self.cell_sites).astype(int)
        if self.chain[0]:
            out.chain_cell, out.chain_side, out.chain_node = (
                np.concatenate(part).astype(int) for part in self.chain)
        else:
            out.chain_cell = out.chain_side = out.chain_node = np.empty(0, dtype=int)
        out.live_segments, out.live_cells = self.seg.copy(), self.cell.copy()
        out.site_changes, out.gaps = self.site_changes, self.gaps
        self._note_bounds(out)
        when, why = min(self.exceptions, key=lambda item: item[0])
        out.cut, out.reason = when, why
        out.tension_at, out.tension_sample = self.tension
        return out

    def _note_bounds(self, out: Lattice) -> None:
        """The first time a segment that was ever at an open end meets the front there."""
        for end, ids in (("left", self.ever[0]), ("right", self.ever[1])):
            bound = getattr(self.zone, end)
            if not isinstance(bound, Bound) or not ids:
                continue
            idx = np.fromiter(ids, int, len(ids))
            idx = idx[out.seg_family[idx] != 0]
            if not idx.size:
                continue
            x0, t0, s = out.seg_x0[idx], out.seg_t0[idx], out.seg_speed[idx]
            t1 = np.where(np.isnan(out.seg_t1[idx]), np.inf, out.seg_t1[idx])
            line = (np.full(idx.size, bound.x0), np.full(idx.size, bound.t0),
                    np.full(idx.size, bound.speed))
            t = _meet(*line, x0, t0, s) if end == "left" else _meet(x0, t0, s, *line)
            valid = (t >= t0) & (t <= t1)
            if np.any(valid):
                self.exceptions.append((float(np.min(t[valid])), f"{end} bound"))


def _ends(count: int, ends) -> np.ndarray:
    t1 = np.full(count, np.nan)
    if ends[0]:
        t1[np.concatenate(ends[0])] = np.concatenate(ends[1])
    return t1
