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
the grid ``(J+ values) x (J- values)`` (the reflections close the two sets;
``characteristics.grid``), evaluated on the isentrope once, in one vectorised call.
The nodes are then solved in time order from a local queue: each is a few lookups in
the grid and two line intersections.

The zone stops (is *cut*) at the first time anything it does not model would happen:
the horizon given by the caller (the next event of the fronts bounding it, the end
time); a ray reaching a bounding front; two rays of one family converging (a
compression steepening into a shock); a contact reaching the tension it carries (it
opens); a gap closing; a state outside the grid; tension reaching the material's
strength (a first pass runs past it so that the whole unrelieved field is known, and
the first fracture point with its zone is located on that continuous field by
``characteristics.fracture``; a second pass stops there).  Everything before the cut
is final; the rays and cells alive at the cut go back to the engine's queue.
"""

from __future__ import annotations

import heapq
import math
from dataclasses import dataclass, field

import numpy as np

from materials import StateOutOfRangeError

from .fracture import FractureZone, fracture_zone
from .grid import Grid, GridTooLarge
from .isentrope import Isentrope
from .ray_energy import volume_at_energy

CROSSING, RIGHT_REFLECTION, LEFT_REFLECTION, PASSAGE = 0, 1, 2, 3
"""Kinds of node."""

PASS, GAP = "pass", "gap"
"""Kinds of site inside a zone."""


@dataclass(frozen=True)
class Reflector:
    """A reflecting end of a zone at position ``x`` (m): it holds ``"stress"`` or
    ``"velocity"`` at ``value`` (Pa or m/s).  The face of a gap is a free surface with
    ``gap``: ``(u_other, width, time)``, the velocity (m/s) of the face across the gap
    and the gap's Eulerian width (m) at ``time`` (s), so that the zone sees it close.
    A contact to another isentrope (``holds = "join"``, ``join`` its far side) reflects
    what arrives by the contact node of the method of characteristics (equal stress and
    velocity on both sides, each side's invariants on its own isentrope) and sends the
    transmitted characteristics into the far side (``Lattice.emitted``)."""

    x: float
    holds: str
    value: float
    gap: tuple | None = None
    join: Join | None = None


@dataclass(frozen=True)
class Join:
    """The far side of a contact that ends a zone on another isentrope: its ``table``,
    the invariant its cell at the contact keeps while nothing arrives from that side
    (``J-`` beyond a right end, ``J+`` beyond a left end), the tension the contact
    carries (``strength``, Pa), the contact's stress now (``stress``, Pa, where the
    contact node's iteration starts) and the front that bounds the far cell (``bound``:
    rays sent through the contact must not reach it inside the zone)."""

    table: Isentrope
    invariant: float
    strength: float
    stress: float
    bound: Bound | None = None


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
    ``max_nodes``: the zone stops (``"node budget"``) before its node count passes it.
    ``negligible`` (Pa): a contact node's reflection weaker than half of it is dropped
    (``characteristics.grid``).  ``e`` (J/kg, per cell): the specific internal energies
    the input cells carry (``None``: those of the isentrope); a cell behind a ray may lie
    off the isentrope by the energy the ray's jump conditions took
    (``characteristics.ray_energy``), which it keeps while the lattice does not replace it.
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
    max_nodes: int = 10**9
    negligible: float = 0.0
    e: np.ndarray | None = None


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
    ``emitted``: per join end, the rays sent into the far side (arrays ``t``, ``x``,
    ``own``, ``speed``) and the far cells behind them (``jp``, ``jm`` and the state).
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
    emitted: dict = field(default_factory=dict)
    cut: float = math.inf
    reason: str = ""
    fracture: FractureZone | None = None
    tension_at: float = math.inf
    tension_sample: tuple | None = None


# --- solving -----------------------------------------------------------------------------
def solve(zone: Zone) -> Lattice:
    """Solve ``zone`` up to its cut (see the module docstring).

    The first pass runs to the first exception other than tension, so that the whole
    unrelieved tension field is known; if it reaches the strength, the first fracture
    and the zone the threshold fractures are found on it (``characteristics.fracture``)
    and a second pass stops at the first fracture.
    """
    try:
        grid = Grid(zone)
    except StateOutOfRangeError:
        return _March(zone, None).unchanged("state outside the table")
    except GridTooLarge:
        return _March(zone, None).unchanged("grid too large")
    first = _March(zone, grid).run(zone.horizon)
    if first.tension_at < first.cut:
        found = _fracture_zone(zone, first)
        if found is not None and found.t < first.cut:
            cut = max(found.t, zone.t_now)
            result = _March(zone, grid).run(cut) if first.nodes else first
            result.cut, result.reason, result.fracture = cut, "tension", found
            return result
    return first


def _fracture_zone(zone: Zone, lattice: Lattice):
    """The first fracture and its zone on the first pass's field, outside earlier zones."""
    strength = zone.strength
    try:
        speed = zone.table.speed_at_stress(-strength)
    except StateOutOfRangeError:
        speed = float(np.max(np.abs(zone.speed))) if zone.speed.size else 1.0
    faces = [end.x for end in (zone.left, zone.right)
             if isinstance(end, Reflector) and end.holds == "velocity"]
    return fracture_zone(lattice, strength, speed, zone.carried, faces)


def _meet(x0a: float, t0a: float, sa: float, x0b: float, t0b: float, sb: float) -> float:
    """When the line of ``a`` (left) reaches the line of ``b`` (inf if they do not approach)."""
    closing = sa - sb
    if not closing > 0.0:
        return math.inf
    t = (x0b - x0a + sa * t0a - sb * t0b) / closing
    return max(t, t0a, t0b)


class _March:
    """One pass over a zone in time order: a local queue of the nodes the rays of the zone
    will make with each other, with its sites and with its ends, each node solved from
    the grid of states when it comes.  The state of a slot (a ray or a site) is its
    current line; a pair of neighbouring slots or a slot at an end has at most one next
    event; a change of a slot (``version``) makes its earlier events stale."""

    def __init__(self, zone: Zone, grid: Grid | None):
        self.zone, self.grid = zone, grid
        k = len(zone.family)
        self.k = k
        self.rho0 = zone.table.material.rho0
        self.fam = [int(f) for f in zone.family]
        self.x0, self.t0, self.sp = zone.x0.tolist(), zone.t0.tolist(), zone.speed.tolist()
        self.seg = list(range(k))
        self.tag = list(range(k)) if zone.tag is None else [int(x) for x in zone.tag]
        self.site = [-1] * k
        for slot, index in zip([i for i, f in enumerate(self.fam) if f == 0],
                               range(len(zone.sites)), strict=True):
            self.site[slot] = index
        self.version = [0] * k
        self.cell = list(range(k + 1))
        # records
        self.seg_x0, self.seg_t0, self.seg_speed = list(self.x0), list(self.t0), list(self.sp)
        self.seg_family = list(self.fam)
        self.seg_own = zone.own.tolist()
        self.seg_left, self.seg_right = list(range(k)), list(range(1, k + 1))
        self.seg_start, self.seg_tag = [-1] * k, list(self.tag)
        self.seg_end: dict[int, float] = {}
        self.cell_end: dict[int, float] = {}
        self.node_x, self.node_t, self.node_kind, self.node_sigma = [], [], [], []
        self.chain_cell, self.chain_side, self.chain_node = [], [], []
        self.cell_t0 = [math.nan] * (k + 1)
        sites_left, count = [], 0
        for q in range(k + 1):
            sites_left.append(count)
            if q < k and self.fam[q] == 0:
                count += 1
        self.cell_sites = sites_left
        self.site_changes = {i: [] for i in range(len(zone.sites))} | {"left": [], "right": []}
        self.emissions = {"left": [], "right": []}
        self.gaps = {i: (s.width, s.time) for i, s in enumerate(zone.sites) if s.kind == GAP}
        for end in ("left", "right"):
            bc = getattr(zone, end)
            if isinstance(bc, Reflector) and bc.gap is not None:
                self.gaps[end] = bc.gap[1:]
        self.gap_version = dict.fromkeys(self.gaps, 0)
        self.tension = [math.inf, None]
        self.stop = (math.inf, "horizon")
        self.queue: list = []
        self.seq = 0
        if grid is not None:
            self.own = [int(i) for i in np.where(
                zone.family > 0, grid.p_index(zone.own),
                np.where(zone.family < 0, grid.m_index(zone.own), -1))]
            self.pi = grid.p_index(zone.jp).tolist()
            self.mi = grid.m_index(zone.jm).tolist()
            self.cell_p, self.cell_m = list(self.pi), list(self.mi)

    # --- the queue --------------------------------------------------------------------
    def _push(self, t: float, kind: str, slot, other=None, single: bool = False) -> None:
        """Queue an event at ``t`` involving ``slot`` and, unless ``single`` (an event of
        one slot at an end of the zone), the slot after it."""
        if t == math.inf:
            return
        self.seq += 1
        stamp = None
        if isinstance(slot, int):
            stamp = (self.version[slot],
                     None if single or slot + 1 >= self.k else self.version[slot + 1])
        heapq.heappush(self.queue, (t, self.seq, kind, slot, other, stamp))

    def _valid(self, slot, stamp) -> bool:
        """Whether the slots an event involves are unchanged since it was queued."""
        if stamp is None:
            return True
        if self.version[slot] != stamp[0]:
            return False
        return stamp[1] is None or self.version[slot + 1] == stamp[1]

    def _schedule_pair(self, j: int) -> None:
        """The next event of slots ``j`` and ``j + 1``."""
        if j < 0 or j + 1 >= self.k:
            return
        fa, fb = self.fam[j], self.fam[j + 1]
        if fa > 0 and fb < 0:
            self._push(self._pair_meet(j), "cross", j)
        elif fa > 0 and fb == 0:
            self._push(self._arrival(j, self.zone.sites[self.site[j + 1]].x), "site", j, j)
        elif fa == 0 and fb < 0:
            self._push(self._arrival(j + 1, self.zone.sites[self.site[j]].x), "site", j, j + 1)
        elif fa == fb and fa != 0:
            self._push(self._pair_meet(j), "stop", j, "overtake")

    def _schedule_end(self, side: str) -> None:
        """The next event of the slot at an end: a reflection, or meeting the bound."""
        if not self.k:
            return
        slot = 0 if side == "left" else self.k - 1
        end = getattr(self.zone, side)
        f = self.fam[slot]
        if f == 0:
            # a site at the end (every ray has passed it): it stands at its X, and the
            # bound must not reach it inside the zone (its rays are all beyond the site)
            if isinstance(end, Bound):
                x, now = self.zone.sites[self.site[slot]].x, self.zone.t_now
                t = (_meet(end.x0, end.t0, end.speed, x, now, 0.0) if side == "left"
                     else _meet(x, now, 0.0, end.x0, end.t0, end.speed))
                self._push(t, "stop", slot, f"{side} bound", single=True)
            return
        if isinstance(end, Reflector):
            if (f < 0) == (side == "left"):
                self._push(self._arrival(slot, end.x), "end", slot, side, single=True)
            return
        if side == "left":
            t = _meet(end.x0, end.t0, end.speed, self.x0[slot], self.t0[slot], self.sp[slot])
        else:
            t = _meet(self.x0[slot], self.t0[slot], self.sp[slot], end.x0, end.t0, end.speed)
        self._push(max(t, self.t0[slot]), "stop", slot, f"{side} bound", single=True)

    def _schedule_around(self, slots) -> None:
        for j in sorted({s + d for s in slots for d in (-1, 0)}):
            self._schedule_pair(j)
        if 0 in slots:
            self._schedule_end("left")
        if self.k - 1 in slots:
            self._schedule_end("right")

    def _pair_meet(self, j: int) -> float:
        return _meet(self.x0[j], self.t0[j], self.sp[j], self.x0[j + 1], self.t0[j + 1],
                     self.sp[j + 1])

    def _arrival(self, slot: int, x: float) -> float:
        """When the characteristic in ``slot`` reaches ``x`` (inf if it stands still
        elsewhere: a characteristic of a state with no sound speed, such as vacuum)."""
        gap, speed = x - self.x0[slot], self.sp[slot]
        if speed == 0.0:
            return self.t0[slot] if gap == 0.0 else math.inf
        return max(self.t0[slot] + gap / speed, self.t0[slot])

    # --- the pass -----------------------------------------------------------------------
    def run(self, cut: float) -> Lattice:
        """Process every event before ``cut`` in time order, up to the first exception."""
        self._open_gaps()
        self._schedule_around(set(range(self.k)))
        while self.queue:
            t, _, kind, slot, other, stamp = heapq.heappop(self.queue)
            if t >= min(cut, self.stop[0]):
                break
            if not self._valid(slot, stamp):
                continue
            if len(self.node_x) >= self.zone.max_nodes:
                self.stop = (t, "node budget")
                break
            if kind == "stop":
                if isinstance(other, tuple):  # a gap closing, unless its faces moved since
                    if self.gap_version[slot[1]] != other[1]:
                        continue
                    other = other[0]
                self.stop = (t, other)
                break
            if kind == "cross":
                self._cross(slot, t)
            elif kind == "site":
                self._at_site(other, t)
            else:
                self._reflect(slot, t, other)
        if self.stop[0] >= cut:
            self.stop = (cut, "horizon")
        return self._lattice()

    # --- records ------------------------------------------------------------------------
    def _node(self, x: float, t: float, kind: int, sigma: float) -> int:
        self.node_x.append(x)
        self.node_t.append(t)
        self.node_kind.append(kind)
        self.node_sigma.append(sigma)
        return len(self.node_x) - 1

    def _new_cell(self, p: int, m: int, t: float, position: int) -> int:
        self.cell_p.append(p)
        self.cell_m.append(m)
        self.cell_t0.append(t)
        count = sum(1 for q in range(position) if self.fam[q] == 0)
        self.cell_sites.append(count)
        return len(self.cell_p) - 1

    def _new_segment(self, slot: int, node: int) -> None:
        """The slot's line from its last change becomes a new segment starting at ``node``."""
        self.seg_end[self.seg[slot]] = self.node_t[node]
        self.seg_x0.append(self.x0[slot])
        self.seg_t0.append(self.t0[slot])
        self.seg_speed.append(self.sp[slot])
        self.seg_family.append(self.fam[slot])
        self.seg_own.append(self._own_value(slot))
        self.seg_left.append(self.cell[slot])
        self.seg_right.append(self.cell[slot + 1])
        self.seg_start.append(node)
        self.seg_tag.append(self.tag[slot])
        self.seg[slot] = len(self.seg_x0) - 1
        self.version[slot] += 1

    def _chain(self, node: int, pairs) -> None:
        for cell, side in pairs:
            self.chain_cell.append(cell)
            self.chain_side.append(side)
            self.chain_node.append(node)

    def _own_value(self, slot: int) -> float:
        f = self.fam[slot]
        if f == 0:
            return math.nan
        return self.grid.p_list[self.own[slot]] if f > 0 else self.grid.m_list[self.own[slot]]

    def _note_tension(self, sigma: float, t: float, x: float) -> None:
        """Keep the first state in tension beyond the strength outside the carried intervals."""
        strength = self.zone.strength
        if sigma > -strength or t >= self.tension[0]:
            return
        if any(lo <= x <= hi for lo, hi in self.zone.carried):
            return
        self.tension = [t, (x, t, sigma)]

    # --- nodes ----------------------------------------------------------------------------
    def _cross(self, j: int, t: float) -> None:
        """The ``C+`` ray in ``j`` meets the ``C-`` ray in ``j + 1``."""
        a, b = j, j + 1
        grid = self.grid
        x = self.x0[a] + self.sp[a] * (t - self.t0[a])
        new_p, new_m = self.pi[a], self.mi[b + 1]  # the left cell's J+, the right cell's J-
        oa, ob = self.own[a], self.own[b]
        c = grid.rows["c"]
        speed_a, speed_b = c[oa][new_m], -c[new_p][ob]  # each ray's own new state
        node = self._node(x, t, CROSSING, grid.rows["sigma"][oa][ob])
        middle = self.cell[b]
        self.cell_end[middle] = t
        new_cell = self._new_cell(new_p, new_m, t, b)
        self._chain(node, ((middle, 0), (middle, 1), (self.cell[a], 1), (self.cell[b + 1], 0),
                           (new_cell, 0), (new_cell, 1)))
        # swap the two rays; each starts a new segment at the node
        for array in (self.fam, self.own, self.tag):
            array[a], array[b] = array[b], array[a]
        self.seg[a], self.seg[b] = self.seg[b], self.seg[a]
        self.cell[b] = new_cell
        self.pi[b], self.mi[b] = new_p, new_m
        self.x0[a] = self.x0[b] = x
        self.t0[a] = self.t0[b] = t
        self.sp[a], self.sp[b] = speed_b, speed_a
        self._new_segment(a, node)
        self._new_segment(b, node)
        self._note_tension(grid.rows["sigma"][new_p][new_m], t, x)
        self._note_tension(grid.rows["sigma"][oa][ob], t, x)
        self._schedule_around({a, b})

    def _at_site(self, ray: int, t: float) -> None:
        """A ray reaches the site next to it: it passes a contact, or reflects from a gap
        face."""
        right_going = self.fam[ray] > 0
        site_slot = ray + 1 if right_going else ray - 1
        site = self.zone.sites[self.site[site_slot]]
        if site.kind == GAP:
            self._reflect(ray, t, "left face" if right_going else "right face")
        else:
            self._pass(ray, site_slot, site, t)

    def _pass(self, ray: int, site_slot: int, site: Site, t: float) -> None:
        """A ray goes through a contact; the cell it leaves behind on the far side has the
        invariants of the near side's cell (the isentrope continues across)."""
        right_going = self.fam[ray] > 0
        lo = min(ray, site_slot)  # the pair occupies slots lo, lo + 1
        near = lo if right_going else lo + 2  # the cell the ray leaves behind
        new_p, new_m = self.pi[near], self.mi[near]
        sigma = self.grid.rows["sigma"][new_p][new_m]
        if sigma <= -site.strength:
            self.stop = (t, "contact opens")
            return
        node = self._node(site.x, t, PASSAGE, sigma)
        middle = self.cell[lo + 1]
        self.cell_end[middle] = t
        for array in (self.fam, self.own, self.tag, self.site, self.seg):
            array[lo], array[lo + 1] = array[lo + 1], array[lo]
        for array in (self.x0, self.t0, self.sp, self.version):
            array[lo], array[lo + 1] = array[lo + 1], array[lo]
        new_cell = self._new_cell(new_p, new_m, t, lo + 1)
        self._chain(node, ((middle, 0), (middle, 1), (self.cell[lo], 1), (self.cell[lo + 2], 0),
                           (new_cell, 0), (new_cell, 1)))
        ray = lo + 1 if right_going else lo
        self.cell[lo + 1] = new_cell
        self.pi[lo + 1], self.mi[lo + 1] = new_p, new_m
        self.x0[ray], self.t0[ray] = site.x, t
        self._new_segment(ray, node)
        site_now = lo if right_going else lo + 1
        self.version[site_now] += 1
        index = self.site[site_now]
        # the site's right cell: the new one (a C+ passed) or the far one (a C- passed)
        self.site_changes[index].append((t, self.cell[site_now + 1]))
        self._schedule_around({lo, lo + 1})

    def _reflect(self, ray: int, t: float, where: str) -> None:
        """The ray in ``ray`` reflects at an end (``"left"``/``"right"``) or a gap face
        (``"left face"``: the face left of a gap, reached by a ``C+``)."""
        grid, zone = self.grid, self.zone
        right_going = self.fam[ray] > 0
        if where in ("left", "right"):
            end = getattr(zone, where)
            condition = ("join", where) if end.join is not None else (end.holds, end.value)
            x = end.x
        else:
            site_slot = ray + 1 if right_going else ray - 1
            condition, x = ("stress", 0.0), zone.sites[self.site[site_slot]].x
        face = ray + 1 if right_going else ray  # the cell at the boundary
        came_from = ray if right_going else ray + 1
        to = -1 if right_going else +1
        table = grid.maps[(to, condition)]
        if right_going:
            new_p = self.pi[came_from]
            new_m, refl = table[new_p], table[self.own[ray]]
            p_node, m_node = self.own[ray], refl
        else:
            new_m = self.mi[came_from]
            new_p, refl = table[new_m], table[self.own[ray]]
            p_node, m_node = refl, self.own[ray]
        if min(new_p, new_m, refl) < 0:
            self.stop = (t, "reflections beyond the tabulated grid")
            return
        if condition[0] == "join" and not self._emit(where, (to, condition), t, x,
                                                     self.own[ray],
                                                     new_p if right_going else new_m):
            return
        sigma, c = grid.rows["sigma"], grid.rows["c"]
        kind = RIGHT_REFLECTION if right_going else LEFT_REFLECTION
        node = self._node(x, t, kind, sigma[p_node][m_node])
        old, other = self.cell[face], self.cell[came_from]
        if (new_p, new_m) == (self.pi[came_from], self.mi[came_from]):
            self._absorb(ray, node, old, other, where)
            return
        self.cell_end[old] = t
        new_cell = self._new_cell(new_p, new_m, t, face)
        self._chain(node, ((old, 0), (old, 1), (other, 1 if right_going else 0),
                           (new_cell, 0), (new_cell, 1)))
        self.cell[face] = new_cell
        self.pi[face], self.mi[face] = new_p, new_m
        # the reflected ray moves at the characteristic speed of its own state
        speed = -c[new_p][refl] if right_going else c[refl][new_m]
        self.fam[ray], self.own[ray] = (-1, refl) if right_going else (1, refl)
        self.x0[ray], self.t0[ray], self.sp[ray] = x, t, speed
        self._new_segment(ray, node)
        self._note_tension(sigma[new_p][new_m], t, x)
        self._face_moved(ray, t, where, new_cell)
        self._schedule_around({ray, face - 1 if not right_going else ray})

    def _absorb(self, ray: int, node: int, old: int, other: int, where: str) -> None:
        """The ray in ``ray`` ends at the contact node ``node`` of the end ``where``
        without a reflection: the contact reflects nothing the grid resolves (the new face
        cell would be the state behind the ray, ``characteristics.grid``), so the cell
        behind it (``other``) reaches the contact and the face cell ``old`` ends.  A
        reflected characteristic with the same state on both sides carries no wave; kept,
        it would ring in the layer for ever, one node or one event at each meeting.  The
        slot is removed; the queued nodes of the shifted slots are made again."""
        t = self.node_t[node]
        self.seg_end[self.seg[ray]] = t
        self.cell_end[old] = t
        self._chain(node, ((old, 0), (old, 1), (other, 1 if where == "right" else 0)))
        for array in (self.fam, self.own, self.tag, self.site, self.seg, self.x0, self.t0,
                      self.sp, self.version):
            del array[ray]
        face = ray + 1 if where == "right" else ray
        for array in (self.cell, self.pi, self.mi):
            del array[face]
        self.k -= 1
        if where == "left":
            self.site_changes["left"].append((t, other))
        self.queue = [entry for entry in self.queue if not isinstance(entry[3], int)]
        heapq.heapify(self.queue)
        self._schedule_around(set(range(self.k)))

    def _emit(self, end: str, key, t: float, x: float, arriving: int, source: int) -> bool:
        """A ray goes through the contact at ``end``: what it sends into the far side (its
        own invariant there and speed, and the far cell behind it).  False if the contact
        does not hold (then the zone stops there)."""
        sigma, far, speed = self.grid.emitted[key]
        join = getattr(self.zone, end).join
        if not min(sigma[arriving], sigma[source]) > -join.strength:
            self.stop = (t, "contact opens")
            return False
        sign = 1.0 if end == "right" else -1.0
        rows = self.emissions[end]
        rows.append((t, x, far[arriving], sign * speed[arriving], far[source]))
        b = join.bound
        if b is not None:  # the ray must not reach the far side's front inside the zone
            s = sign * speed[arriving]
            meet = (_meet(x, t, s, b.x0, b.t0, b.speed) if end == "right"
                    else _meet(b.x0, b.t0, b.speed, x, t, s))
            self._push(meet, "stop", end, "far bound")
        if len(rows) > 1:  # nor the ray it follows
            t0, x0_, _, s0, _ = rows[-2]
            s = sign * speed[arriving]
            meet = (_meet(x, t, s, x0_, t0, s0) if end == "right"
                    else _meet(x0_, t0, s0, x, t, s))
            self._push(meet, "stop", end, "far overtake")
        return True

    def _face_moved(self, ray: int, t: float, where: str, new_cell: int) -> None:
        """Record the new cell at an end or a face; follow a gap's width to its closing."""
        if where == "left":
            self.site_changes["left"].append((t, new_cell))
        if where in ("left face", "right face"):
            # the ray has just reflected: from the left face it now goes left
            site_slot = ray + 1 if self.fam[ray] < 0 else ray - 1
            index = self.site[site_slot]
            if where == "right face":
                self.site_changes[index].append((t, new_cell))
            self._gap_moved(index, t)
        elif getattr(self.zone, where).gap is not None:
            self._gap_moved(where, t)

    def _face_u(self, key, side: str) -> float:
        """Velocity (m/s) of a gap's face now: the cell at it, or the other side's face of
        a gap at an end of the zone."""
        u = self.grid.rows["u"]
        if key in ("left", "right"):
            if side != key:  # the face inside the zone
                q = 0 if key == "left" else self.k
                return u[self.pi[q]][self.mi[q]]
            return getattr(self.zone, key).gap[0]
        slot = self.site.index(key)
        q = slot if side == "left" else slot + 1
        return u[self.pi[q]][self.mi[q]]

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
        self.gap_version[key] += 1
        self._note_closing(key, width, t)

    def _note_closing(self, key, width: float, since: float) -> None:
        u_left, u_right = self.faces[key]
        if u_left > u_right:
            self._push(since + max(width, 0.0) / (u_left - u_right), "stop", ("gap", key),
                       ("gap closes", self.gap_version[key]))

    # --- the result -----------------------------------------------------------------------
    def unchanged(self, reason: str) -> Lattice:
        """The zone as it was: nothing could be solved."""
        self.stop = (self.zone.t_now, reason)
        return self._lattice(states=False)

    def _lattice(self, states: bool = True) -> Lattice:
        out = Lattice()
        out.nodes = len(self.node_x)
        if out.nodes:
            out.node_x = np.array(self.node_x)
            out.node_t = np.array(self.node_t)
            out.node_kind = np.array(self.node_kind, dtype=int)
            out.node_sigma = np.array(self.node_sigma)
        for name in ("x0", "t0", "speed", "own"):
            setattr(out, f"seg_{name}", np.array(getattr(self, f"seg_{name}"), dtype=float))
        for name in ("family", "left", "right", "start", "tag"):
            setattr(out, f"seg_{name}", np.array(getattr(self, f"seg_{name}"), dtype=int))
        out.seg_t1 = np.full(len(self.seg_x0), np.nan)
        if self.seg_end:
            out.seg_t1[list(self.seg_end)] = list(self.seg_end.values())
        if states:
            grid = self.grid
            p_all, m_all = np.array(self.cell_p, dtype=int), np.array(self.cell_m, dtype=int)
            out.cell_sigma, out.cell_u = grid.sigma[p_all, m_all], grid.u[p_all, m_all]
            out.cell_v, out.cell_e = self._volume_energy(p_all, m_all)
            out.cell_jp, out.cell_jm = grid.p[p_all], grid.m[m_all]
        out.cell_t0 = np.array(self.cell_t0, dtype=float)
        out.cell_t1 = np.full(len(self.cell_t0), np.nan)
        if self.cell_end:
            out.cell_t1[list(self.cell_end)] = list(self.cell_end.values())
        out.cell_sites = np.array(self.cell_sites, dtype=int)
        out.chain_cell = np.array(self.chain_cell, dtype=int)
        out.chain_side = np.array(self.chain_side, dtype=int)
        out.chain_node = np.array(self.chain_node, dtype=int)
        out.live_segments = np.array(self.seg, dtype=int)
        out.live_cells = np.array(self.cell, dtype=int)
        out.site_changes, out.gaps = self.site_changes, self.gaps
        out.emitted = self._emitted() if states else {}
        out.cut, out.reason = self.stop
        out.tension_at, out.tension_sample = self.tension
        return out

    def _volume_energy(self, p_all: np.ndarray, m_all: np.ndarray):
        """Specific volumes (m^3/kg) and internal energies (J/kg) of the cells: the
        isentrope's, except for an input cell that carries another energy (``Zone.e``),
        which keeps it, at the volume that keeps its stress."""
        v, e = self.grid.v[p_all, m_all], self.grid.e[p_all, m_all]
        if self.zone.e is None:
            return v, e
        given = self.zone.e
        for k in np.flatnonzero(given != e[:given.size]):
            found = volume_at_energy(self.zone.table.material, float(v[k]), float(e[k]),
                                     float(given[k]))
            if found is not None:  # else the isentrope's state (as before)
                v[k], e[k] = found, given[k]
        return v, e

    def _emitted(self) -> dict:
        """The rays each join sent into its far side, as arrays (each at the characteristic
        speed of its own state), with the far cells behind them."""
        out = {}
        for end, rows in self.emissions.items():
            if not rows:
                continue
            join = getattr(self.zone, end).join
            t, x, own, speed, cell = (np.array(column) for column in zip(*rows, strict=True))
            if end == "right":
                jp, jm = cell, np.full(cell.size, join.invariant)
            else:
                jp, jm = np.full(cell.size, join.invariant), cell
            sigma, v, e, _ = join.table.arrays_at_phi(0.5 * (jp - jm))
            out[end] = {"t": t, "x": x, "own": own, "speed": speed, "jp": jp, "jm": jm,
                        "sigma": sigma, "u": 0.5 * (jp + jm), "v": v, "e": e}
        return out
