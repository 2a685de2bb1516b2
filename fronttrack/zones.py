"""Zones of one isentrope, handed to the method of characteristics.

When rays meet each other, a reflecting boundary, a gap face or a contact that the
isentrope continues across, inside cells that all lie on one isentrope, the engine
does not solve one Riemann problem per node: it gathers the maximal run of such rays
and sites around the event (the *zone*), solves it in bulk as a characteristic
lattice (``characteristics.lattice``) up to the first time anything it does not
model would happen, and splices the result back:

- input rays that met something end at their first node; rays and cells alive at
  the cut become fronts and regions of the queue again; the sites keep their place
  and record the cells they bordered;
- segments and cells that began and ended inside the lattice are stored as one
  ``LatticePatch`` (arrays), not as objects;
- a lattice stopped by tension reaching the strength schedules the fracture at the
  first point of the continuous field where it does (``fronttrack.spall``).

The zone's ends: a free surface, a wall or a prescribed boundary reflects (its next
step bounds the zone in time), and so does a gap face whose far side lies on another
isentrope; any other front (a shock, a contact to another isentrope, a ray of another
isentrope) bounds it, and the zone stops when one of its rays would reach it or when
that front's own next event comes.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from characteristics import lattice as moc
from materials import State

from . import fragment, interactions, spall
from .fronts import MIXED, Front, Region
from .kinds import BoundaryKind, EventKind, FrontKind
from .patch import LatticePatch
from .solution import EventRecord

MIN_ZONE_RAYS = 6
"""Rays a zone needs before it is solved as a lattice: building a lattice's grid of
states costs about as much as ten Riemann solves (measured on random stacks), so a
few rays meeting go through the queue, one solve per meeting."""


NODES_PER_EVENT = 50
"""Nodes of a lattice that count as one event against ``accuracy.max_events`` (a node
costs about a fiftieth of a Riemann solve): a zone whose rays ring in a thin layer
cannot run without bound."""


@dataclass
class _Run:
    """The slots of a zone (rays and sites, left to right), the cells around them and the
    fronts at its ends."""

    slots: list[Front]
    cells: list[Region]
    left_end: Front
    right_end: Front
    table: object


def try_zone(engine, group: list[Front], t: float) -> bool:
    """Solve the event of ``group`` at ``t`` as part of a lattice; False if it is not one."""
    if not engine.resolution.makes_fans:
        return False  # no isentrope tables: no ray carries an invariant (``_eligible``)
    table = _eligible(engine, group)
    if table is None:
        return False
    run = _collect(engine, group, table)
    if sum(1 for f in run.slots if f.kind == FrontKind.RAY) < MIN_ZONE_RAYS:
        return False  # a few rays: one Riemann solve each costs less than a lattice
    if not all(table.covers(c.state.sigma) for c in run.cells):
        return False  # a cell past the end of the isentrope (the end of the range)
    zone = _zone(engine, run, t)
    if not table.resolves(max(np.ptp(zone.jp), np.ptp(zone.jm))):
        return False  # waves too weak for the table's rounding: the Riemann solver's
    lattice = moc.solve(zone)
    if lattice.nodes == 0:
        if lattice.fracture is None:
            return False
        spall.schedule(engine, lattice, _layer_at(run, lattice.fracture.x), t)
        _requeue(engine, run, t)
        return True
    _splice(engine, run, lattice, t)
    if lattice.fracture is not None:
        spall.schedule(engine, lattice, _layer_at(run, lattice.fracture.x), t)
    return True


def _eligible(engine, group: list[Front]):
    """The common isentrope of an event of rays meeting each other or a site the method
    of characteristics handles; ``None`` otherwise."""
    rays = [f for f in group if f.kind == FrontKind.RAY]
    sites = [f for f in group if f.is_site]
    if not rays or len(rays) + len(sites) != len(group) or len(sites) > 1:
        return None
    if any(math.isnan(f.invariant) for f in rays):
        return None
    if sites and not _handles(engine, sites[0], group):
        return None
    cells = {id(c): c for c in _ray_cells(rays)}
    table = engine.table_of(next(iter(cells.values())))
    if table is None or not all(_on(engine, c, table) for c in cells.values()):
        return None
    return table


def _on(engine, region: Region | None, table) -> bool:
    """Whether ``region`` lies on ``table``'s isentrope: its own table, or within the
    tolerance of the run's tables (Pa, a stress gap at equal volume: a nearby isentrope
    it would share a table with) plus the gap at which it lies off its own table.  A
    cell behind expansion rays keeps their table below it by the energy their jumps took
    (``characteristics.ray_energy``); the lattice reads its invariants from its stress
    and velocity, which the shift keeps, and keeps its energy (``Zone.e``), so that
    offset is no reason to leave it out of a zone.  The table must reach the region's
    stress (``covers``): a hot state may lie near an isentrope that ends above it."""
    if region is None or region.material is not table.material:
        return False
    own = engine.table_of(region)
    if own is table:
        return True
    if own is None:
        return False
    offset = own.stress_gap(region.state)
    return (table.matches(region.state, engine.tables.tolerance + offset)
            and table.covers(region.state.sigma))


def _ray_cells(rays: list[Front]) -> list[Region]:
    """The cells on both sides of each ray."""
    cells = []
    for ray in rays:
        cells.append(ray.region_right)
        if ray.prev is not None:
            cells.append(ray.prev.region_right)
    return cells


def _handles(engine, site: Front, group: list[Front]) -> bool:
    """A site at which the lattice takes the rays: a boundary of the stack (rays arriving
    at it), a gap, a contact that the isentrope crosses (``_passes``), or a contact to
    another isentrope table (a join: the rays arrive from one side)."""
    if site.kind == FrontKind.BOUNDARY:
        return (site is group[-1]) if site.side == "right" else (site is group[0])
    if site.kind == FrontKind.GAP or _passes(engine, site):
        return True
    if site.kind not in (FrontKind.INTERFACE, FrontKind.CONTACT):
        return False
    side = "right" if site is group[-1] else "left" if site is group[0] else None
    if side is None:
        return False
    far = site.region_right if side == "right" else site.prev.region_right
    return far is not None and engine.table_of(far) is not None


def _passes(engine, site: Front) -> bool:
    """An interface or contact whose two sides lie on one isentrope (rays cross it)."""
    if site.kind not in (FrontKind.INTERFACE, FrontKind.CONTACT) or site.prev is None:
        return False
    left, right = site.prev.region_right, site.region_right
    table = engine.table_of(left) if left is not None else None
    return table is not None and _on(engine, right, table)


def _collect(engine, group: list[Front], table) -> _Run:
    """The maximal run of rays and sites on ``table`` around the group."""
    slots = [f for f in group if f.kind == FrontKind.RAY or _inside(engine, f, table)]
    left = slots[0].prev
    while left is not None and _joins(engine, left, table, "left"):
        slots.insert(0, left)
        left = left.prev
    right = slots[-1].next
    while right is not None and _joins(engine, right, table, "right"):
        slots.append(right)
        right = right.next
    cells = [slots[0].prev.region_right] + [f.region_right for f in slots]
    return _Run(slots=slots, cells=cells, left_end=slots[0].prev, right_end=slots[-1].next,
                table=table)


def _inside(engine, front: Front, table) -> bool:
    """A site that can sit inside a zone on ``table``: a contact the isentrope crosses,
    or a gap with both faces on it."""
    if front.kind == FrontKind.GAP:
        return (front.prev is not None and front.region_right is not None
                and _on(engine, front.prev.region_right, table)
                and _on(engine, front.region_right, table))
    return _passes(engine, front) and _on(engine, front.region_right, table)


def _joins(engine, front: Front, table, side: str) -> bool:
    """Whether ``front``, next to a run on ``table``, belongs to it."""
    if front.kind == FrontKind.RAY:
        if math.isnan(front.invariant):
            return False
        far = front.prev.region_right if side == "left" else front.region_right
        return _on(engine, far, table)
    return _inside(engine, front, table)


def _zone(engine, run: _Run, t: float) -> moc.Zone:
    """The lattice input for a run at time ``t``."""
    invariants = [engine.invariants_of(c) if c.table is run.table
                  else run.table.invariants(c.state) for c in run.cells]
    material = run.cells[0].material
    strength = (material.spall_strength if engine.scene.spall_criterion is None
                else math.inf)
    left, left_horizon = _end(engine, run.left_end, "left", t, run.table)
    right, right_horizon = _end(engine, run.right_end, "right", t, run.table)
    horizon = min(engine.t_end, left_horizon, right_horizon, spall.next_scheduled(engine, t))
    members = {id(f) for f in run.slots} | {id(run.left_end), id(run.right_end)}
    horizon = engine.causal_horizon(_reach(run.left_end, left, t), _reach(run.right_end, right, t),
                                    members, t, horizon)
    sites, carried = [], []
    for front in run.slots:
        if front.kind == FrontKind.RAY:
            continue
        if front.kind == FrontKind.GAP:
            sites.append(moc.Site(moc.GAP, front.x0, width=front.gap_width,
                                  time=front.gap_time))
        else:
            sites.append(moc.Site(moc.PASS, front.x0, strength=interactions.contact_strength(
                engine, front, material)))
    layers = {run.cells[0].layer} | {c.layer for c in run.cells}
    for layer in layers:
        carried += spall.carried_intervals(engine, layer)
    rays = [f for f in run.slots]
    return moc.Zone(
        table=run.table,
        family=np.array([f.direction if f.kind == FrontKind.RAY else 0 for f in rays],
                        dtype=np.int8),
        own=np.array([_own_invariant(engine, run, i, invariants) for i in range(len(rays))]),
        x0=np.array([f.x0 for f in rays]), t0=np.array([f.t0 for f in rays]),
        speed=np.array([f.speed for f in rays]),
        jp=np.array([j[0] for j in invariants]), jm=np.array([j[1] for j in invariants]),
        left=left, right=right, t_now=t, horizon=horizon, strength=strength,
        carried=tuple(carried), sites=tuple(sites),
        max_nodes=NODES_PER_EVENT * max(engine.acc.max_events - engine.counters.events, 1),
        negligible=engine.resolution.negligible,
        e=np.array([c.state.e for c in run.cells]))


def _own_invariant(engine, run: _Run, i: int, invariants: list) -> float:
    """The invariant of the ray in slot ``i`` on the run's table (NaN for a site).

    Each table measures ``phi`` from its own labelling state, so a ray born on a nearby
    isentrope's table carries its invariant in that table's gauge: it is shifted by
    the offset between the two gauges at the cell beside it that has another table
    (the isentropes agree within the tolerance, so the offset is constant to it).  A
    ray's state lies between those of the cells beside it; an invariant that does not
    (a ray whose own table is neither cell's) is replaced by the cells' mean, which is
    its state to second order in the ray's step.
    """
    ray = run.slots[i]
    if ray.kind != FrontKind.RAY:
        return math.nan
    family = 0 if ray.direction > 0 else 1
    own = ray.invariant
    for cell, here in ((run.cells[i], invariants[i]), (run.cells[i + 1], invariants[i + 1])):
        if cell.table is not run.table and cell.table is not None:
            own += here[family] - engine.invariants_of(cell)[family]
            break
    left, right = invariants[i][family], invariants[i + 1][family]
    slack = 1e-9 * (abs(left) + abs(right) + abs(left - right))
    if not min(left, right) - slack <= own <= max(left, right) + slack:
        return 0.5 * (left + right)
    return own


def _reach(front: Front, end, t: float) -> tuple[float, float]:
    """How far a zone reaches on one side: the end's line ``(X at t, speed)``, or for a join
    the line of the front bounding the far cell, into which the zone sends rays."""
    if isinstance(end, moc.Reflector) and end.join is not None and end.join.bound is not None:
        bound = end.join.bound
        return bound.x0 + bound.speed * (t - bound.t0), bound.speed
    return front.position(t), front.speed


def _meeting(outer: Front | None, front: Front, side: str, t: float) -> float:
    """When ``outer`` (beyond ``front`` on ``side``) would meet ``front`` (inf if never)."""
    if outer is None:
        return math.inf
    a, b = (outer, front) if side == "left" else (front, outer)
    closing = a.speed - b.speed
    if closing <= 0.0:
        return math.inf
    return t + max(b.position(t) - a.position(t), 0.0) / closing


def _join(engine, front: Front, side: str, table, t: float) -> moc.Join | None:
    """The far side of a contact ending a zone on ``side``, when it lies on another
    isentrope table (rays then pass the contact by the contact node)."""
    if front.kind not in (FrontKind.INTERFACE, FrontKind.CONTACT):
        return None
    far = front.prev.region_right if side == "left" else front.region_right
    outer = front.prev if side == "left" else front.next
    if far is None or outer is None:
        return None
    far_table = engine.table_of(far)
    if far_table is None or _on(engine, far, table):
        return None
    jp, jm = engine.invariants_of(far)
    return moc.Join(table=far_table, invariant=jp if side == "left" else jm,
                    strength=interactions.contact_strength(engine, front, far.material),
                    stress=far.state.sigma,
                    bound=moc.Bound(outer.x0, outer.t0, outer.speed))


def _end(engine, front: Front, side: str, t: float, table):
    """The zone's end at ``front``: a ``Reflector`` or a ``Bound``, and the time until which
    the end stays as it is."""
    if front.kind == FrontKind.BOUNDARY:
        spec = engine.scene.left if front.side == "left" else engine.scene.right
        if interactions.pushes_only(engine, front, spec):
            # a piston may separate from its face: each reflection there is an event that
            # checks for it (``interactions._piston``)
            return moc.Bound(front.x0, front.t0, 0.0), math.inf
        value = interactions.boundary_value(front, spec, t)
        holds = "stress" if spec.kind in (BoundaryKind.FREE, BoundaryKind.STRESS) else "velocity"
        return moc.Reflector(front.x0, holds, value), interactions.next_step_time(front, t)
    outer = front.prev if side == "left" else front.next
    horizon = _meeting(outer, front, side, t)
    join = _join(engine, front, side, table, t)
    if join is not None:
        # the far cell keeps its invariant until a wave reaches the contact from there,
        # and the front beyond it keeps its path until its own next meeting
        beyond = outer.prev if side == "left" else outer.next
        horizon = min(horizon, _meeting(beyond, outer, side, t))
        return moc.Reflector(front.x0, "join", 0.0, join=join), horizon
    if front.kind == FrontKind.GAP:
        # the face across the gap keeps its velocity until a wave reaches it
        u_far, steady = fragment.far_face(engine, front, side, t)  # a ring's: closed form
        horizon = min(horizon, steady)
        gap = (u_far, front.gap_width, front.gap_time)
        return moc.Reflector(front.x0, "stress", 0.0, gap=gap), horizon
    return moc.Bound(front.x0, front.t0, front.speed), horizon


def _layer_at(run: _Run, x: float) -> int:
    """The layer of the run's cell around ``x`` (m)."""
    sites = [f.x0 for f in run.slots if f.is_site]
    count = sum(1 for s in sites if s < x)
    return _layers(run)[count]


def _layers(run: _Run) -> list[int]:
    """The layer of the cells with ``j`` sites of the run to their left, by ``j``."""
    layers = [run.cells[0].layer]
    for k, front in enumerate(run.slots):
        if front.is_site:
            layers.append(run.cells[k + 1].layer)
    return layers


def _requeue(engine, run: _Run, t: float) -> None:
    """Put the run's pairs back in the queue (nothing of it was solved)."""
    chain = [run.left_end, *run.slots, run.right_end]
    for a, b in zip(chain[:-1], chain[1:], strict=True):
        engine.push_pair(a, b, t)


def _splice(engine, run: _Run, lat: moc.Lattice, t: float) -> None:
    """Write the solved lattice back into the engine (see the module docstring)."""
    k = len(run.slots)
    n_seg, n_cell = len(lat.seg_x0), len(lat.cell_sigma)
    live_seg, live_cell = lat.live_segments, lat.live_cells
    is_live_cell = np.zeros(n_cell, bool)
    is_live_cell[live_cell] = True
    is_live_seg = np.zeros(n_seg, bool)
    is_live_seg[live_seg] = True
    material = run.cells[0].material
    layer_of = np.array(_layers(run))[lat.cell_sites]
    # --- cells: ids, objects for inputs and live ones
    cell_ids = np.empty(n_cell, dtype=int)
    cell_ids[:k + 1] = [c.id for c in run.cells]
    for j in range(k + 1, n_cell):
        cell_ids[j] = engine.next_region_id()
    order = np.lexsort((lat.node_t[lat.chain_node], lat.chain_side, lat.chain_cell))
    chain_side = lat.chain_side[order]
    chain_x = lat.node_x[lat.chain_node[order]]
    chain_t = lat.node_t[lat.chain_node[order]]
    bounds = np.searchsorted(lat.chain_cell[order], np.arange(n_cell + 1))
    regions: dict[int, Region] = {j: run.cells[j] for j in range(k + 1)}
    for j in range(k + 1):
        _extend_chains(run.cells[j], chain_side, chain_x, chain_t, bounds[j], bounds[j + 1])
        if not math.isnan(lat.cell_t1[j]):
            run.cells[j].t_end = float(lat.cell_t1[j])
    for j in np.nonzero(is_live_cell[k + 1:])[0] + k + 1:
        j = int(j)
        region = Region(id=int(cell_ids[j]), state=_state(lat, j), material=material,
                        layer=int(layer_of[j]), t_start=float(lat.cell_t0[j]),
                        left_points=[], right_points=[], in_fan=True, table=run.table,
                        invariants=(float(lat.cell_jp[j]), float(lat.cell_jm[j])))
        _extend_chains(region, chain_side, chain_x, chain_t, bounds[j], bounds[j + 1])
        engine.regions.append(region)
        regions[j] = region
    # --- segments: close the inputs that ended, make fronts of the new live ones
    fans = _fan_ids(engine, run, lat)
    origin = _lineage(run)
    for i, front in enumerate(run.slots):
        if front.kind == FrontKind.RAY and not math.isnan(lat.seg_t1[i]):
            front.alive = False
            front.t1 = float(lat.seg_t1[i])
            front.x1 = front.position(front.t1)
            front.right_region_id = front.region_right.id
    live_fronts = []
    for s in live_seg.tolist():
        if s < k:
            live_fronts.append(run.slots[s])
            continue
        source = run.slots[int(lat.seg_tag[s])]
        left_cell, right_cell = int(lat.seg_left[s]), int(lat.seg_right[s])
        front = engine.new_front(
            FrontKind.RAY, float(lat.seg_x0[s]), float(lat.seg_t0[s]),
            speed=float(lat.seg_speed[s]), direction=int(lat.seg_family[s]),
            jump=_jump(lat, left_cell, right_cell, int(lat.seg_family[s])),
            fan=int(fans[s]), ray_index=source.ray_index, ray_count=source.ray_count,
            invariant=float(lat.seg_own[s]), lineage=origin)
        front.left_region = int(cell_ids[left_cell])
        live_fronts.append(front)
    # --- the regions right of each front, and the sites' earlier ones
    chain = [run.left_end, *live_fronts, run.right_end]
    sites = [f for f in run.slots if f.is_site]
    for index, site in enumerate(sites):
        _record_changes(site, lat.site_changes[index], cell_ids)
    for site in (run.left_end, *sites, run.right_end):
        site.solved_until = max(site.solved_until, lat.cut)
    _record_changes(run.left_end, lat.site_changes["left"], cell_ids)
    for position, front in enumerate(chain[:-1]):
        front.region_right = regions[int(live_cell[position])]
    for a, b in zip(chain[:-1], chain[1:], strict=True):
        a.next, b.prev = b, a
    _update_gaps(engine, run, lat, sites)
    for a, b in zip(chain[:-1], chain[1:], strict=True):
        # from when both exist: a front leaving the lattice before its cut may meet a
        # site at the lattice's edge before the cut (taking the cut, a ray passed a
        # contact unseen and was pulled back to it 63 ns later)
        engine.push_pair(a, b, max(t, a.t0, b.t0))
    for end, emitted in lat.emitted.items():
        _send_through(engine, run.left_end if end == "left" else run.right_end, end, emitted,
                      lat.cut, origin)
    # --- the interior as one patch
    patch = _patch(engine, run, lat, cell_ids, layer_of, is_live_cell, is_live_seg, fans,
                   chain_x, chain_t, chain_side, bounds, origin)
    if patch is not None:
        engine.patches.append(patch)
    _note_tension(engine, lat, k)
    engine.counters.lattices += 1
    engine.counters.nodes += lat.nodes
    engine.counters.events += lat.nodes // NODES_PER_EVENT  # the event budget pays for nodes
    engine.events.append(EventRecord(
        t=t, x=float(lat.node_x[0]), kind=EventKind.LATTICE,
        incoming=[f.id for i, f in enumerate(run.slots)
                  if f.kind == FrontKind.RAY and not math.isnan(lat.seg_t1[i])],
        outgoing=[f.id for f in live_fronts if f not in run.slots], site=None,
        nodes=lat.nodes))


def _lineage(run: _Run) -> int:
    """The lineage of every ray a lattice makes (``fronttrack.outgoing.lineage``): that of
    its input rays if they share one and nothing in it reflects from an edge (a boundary
    or a gap), else ``MIXED`` (a lattice does not follow each characteristic's origin)."""
    rays = {f.lineage for f in run.slots if f.kind == FrontKind.RAY}
    edges = any(f is not None and f.kind in (FrontKind.BOUNDARY, FrontKind.GAP)
                for f in (*run.slots, run.left_end, run.right_end))
    return rays.pop() if len(rays) == 1 and not edges else MIXED


def _send_through(engine, join: Front, end: str, emitted: dict, cut: float,
                  origin: int) -> None:
    """The rays a lattice sent through the contact ``join`` at its ``end``, made fronts of
    the far side with the cells between them (see ``characteristics.lattice.Join``)."""
    times = emitted["t"]
    n = times.size
    right = end == "right"
    far_cell = join.region_right if right else join.prev.region_right
    outer = join.next if right else join.prev
    x = join.x0
    fan = engine.next_wave_id()
    rays, cells = [], []
    for k in range(n):
        t_k = float(times[k])
        state = State(sigma=float(emitted["sigma"][k]), u=float(emitted["u"][k]),
                      v=float(emitted["v"][k]), e=float(emitted["e"][k]))
        later = (x, float(times[k + 1])) if k + 1 < n else None
        region = Region(id=engine.next_region_id(), state=state, material=far_cell.material,
                        layer=far_cell.layer, t_start=t_k, left_points=[(x, t_k)],
                        right_points=[(x, t_k)], in_fan=n > 1, table=far_cell.table,
                        invariants=(float(emitted["jp"][k]), float(emitted["jm"][k])))
        if later is not None:
            (region.left_points if right else region.right_points).append(later)
        engine.regions.append(region)
        engine.note_stress(state.sigma, x, t_k)
        cells.append(region)
        ahead = far_cell if k == 0 else cells[k - 1]
        behind_state = state
        rays.append(engine.new_front(
            FrontKind.RAY, x, t_k, speed=float(emitted["speed"][k]),
            direction=1 if right else -1, fan=fan, ray_index=k, ray_count=n, lineage=origin,
            jump=behind_state.sigma - ahead.state.sigma, invariant=float(emitted["own"][k])))
    # the far cell now ends at the first ray, not at the contact
    (far_cell.left_points if right else far_cell.right_points).append((x, float(times[0])))
    if right:
        join.earlier_regions.append((float(times[0]), far_cell.id))
        for k in range(1, n):
            join.earlier_regions.append((float(times[k]), cells[k - 1].id))
        chain = [join, *reversed(rays), outer]
        for k, ray in enumerate(rays):
            ray.left_region = cells[k].id
            ray.region_right = far_cell if k == 0 else cells[k - 1]
        join.region_right = cells[-1]
    else:
        chain = [outer, *rays, join]
        for k, ray in enumerate(rays):
            ray.left_region = far_cell.id if k == 0 else cells[k - 1].id
            ray.region_right = cells[k]
    for a, b in zip(chain[:-1], chain[1:], strict=True):
        a.next, b.prev = b, a
        engine.push_pair(a, b, cut)


def _record_changes(front: Front, changes: list, cell_ids: np.ndarray) -> None:
    """A site's region on its right changed at these ``(t, cell)``: keep the earlier ones
    (the last one becomes its ``region_right``)."""
    previous = front.region_right.id
    for when, cell in changes:
        front.earlier_regions.append((when, previous))
        previous = int(cell_ids[cell])


def _update_gaps(engine, run: _Run, lat: moc.Lattice, sites: list[Front]) -> None:
    """Gaps the lattice followed: their widths at the cut, and their closing re-queued."""
    for key, (width, time) in lat.gaps.items():
        gap = (sites[key] if isinstance(key, int)
               else run.left_end if key == "left" else run.right_end)
        gap.gap_width, gap.gap_time = width, time
        engine.push_gap_closure(gap)


def _state(lat, j: int) -> State:
    return State(sigma=float(lat.cell_sigma[j]), u=float(lat.cell_u[j]),
                 v=float(lat.cell_v[j]), e=float(lat.cell_e[j]))


def _jump(lat, left: int, right: int, family: int) -> float:
    """Stress behind the ray minus ahead (behind is on the left of a right-going ray)."""
    ahead, behind = (right, left) if family > 0 else (left, right)
    return float(lat.cell_sigma[behind] - lat.cell_sigma[ahead])


def _extend_chains(region: Region, side, xs, ts, start: int, end: int) -> None:
    for i in range(start, end):
        point = (float(xs[i]), float(ts[i]))
        (region.right_points if side[i] else region.left_points).append(point)


def _fan_ids(engine, run: _Run, lat) -> np.ndarray:
    """A fan id per segment: its source ray's, or a new one per direction for rays the
    lattice reflected."""
    source_fan = np.array([f.fan if f.fan is not None else -1 for f in run.slots])
    source_dir = np.array([f.direction for f in run.slots])
    fans = source_fan[lat.seg_tag]
    reflected = (lat.seg_family != source_dir[lat.seg_tag]) & (lat.seg_family != 0)
    new_ids = {}
    for s in np.nonzero(reflected)[0]:
        key = int(lat.seg_family[s])
        if key not in new_ids:
            new_ids[key] = engine.next_wave_id()
        fans[s] = new_ids[key]
    return fans


def _patch(engine, run, lat, cell_ids, layer_of, is_live_cell, is_live_seg, fans, chain_x,
           chain_t, chain_side, bounds, origin) -> LatticePatch | None:
    """The segments and cells that began and ended inside the lattice."""
    k = len(run.slots)
    segs = np.nonzero(~is_live_seg)[0]
    segs = segs[(segs >= k)]
    cells = np.nonzero(~is_live_cell)[0]
    cells = cells[cells > k]
    if not segs.size and not cells.size:
        return None
    seg_ids = np.array([engine.next_front_id() for _ in range(segs.size)], dtype=int)
    behind = np.where(lat.seg_family[segs] > 0, lat.seg_left[segs], lat.seg_right[segs])
    ahead = np.where(lat.seg_family[segs] > 0, lat.seg_right[segs], lat.seg_left[segs])
    source = lat.seg_tag[segs]
    starts, splits, xs, ts = [0], [], [], []
    for j in cells.tolist():
        a, b = bounds[j], bounds[j + 1]
        side = chain_side[a:b]
        left = np.nonzero(side == 0)[0] + a
        right = np.nonzero(side == 1)[0] + a
        xs += [chain_x[left], chain_x[right]]
        ts += [chain_t[left], chain_t[right]]
        splits.append(starts[-1] + left.size)
        starts.append(starts[-1] + left.size + right.size)
    return LatticePatch(
        material=run.cells[0].material, layers=layer_of[cells], table=run.table,
        seg_id=seg_ids, seg_x0=lat.seg_x0[segs], seg_t0=lat.seg_t0[segs],
        seg_t1=lat.seg_t1[segs], seg_speed=lat.seg_speed[segs],
        seg_direction=lat.seg_family[segs], seg_invariant=lat.seg_own[segs],
        seg_fan=fans[segs],
        seg_ray_index=np.array([run.slots[s].ray_index for s in source.tolist()], dtype=int),
        seg_ray_count=np.array([run.slots[s].ray_count for s in source.tolist()], dtype=int),
        seg_left=cell_ids[lat.seg_left[segs]], seg_right=cell_ids[lat.seg_right[segs]],
        seg_jump=lat.cell_sigma[behind] - lat.cell_sigma[ahead],
        cell_id=cell_ids[cells], cell_sigma=lat.cell_sigma[cells], cell_u=lat.cell_u[cells],
        cell_v=lat.cell_v[cells], cell_e=lat.cell_e[cells], cell_t0=lat.cell_t0[cells],
        cell_t1=lat.cell_t1[cells],
        chain_x=np.concatenate(xs) if xs else np.empty(0),
        chain_t=np.concatenate(ts) if ts else np.empty(0),
        chain_start=np.array(starts), chain_split=np.array(splits), lineage=origin)


def _note_tension(engine, lat, k: int) -> None:
    """The largest tension among the lattice's new cells, where it first appeared."""
    if len(lat.cell_sigma) <= k + 1:
        return
    j = int(np.argmin(lat.cell_sigma[k + 1:])) + k + 1
    born = lat.chain_cell == j
    x = float(np.mean(lat.node_x[lat.chain_node[born]])) if np.any(born) else 0.0
    engine.note_stress(float(lat.cell_sigma[j]), x, float(lat.cell_t0[j]))
