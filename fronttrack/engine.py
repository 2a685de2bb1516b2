"""The front-tracking event queue.

The scene's initial data is piecewise constant, so every layer boundary is a
Riemann problem at ``t = 0``.  The engine keeps the live fronts ordered in X (a
doubly linked list: only neighbours can meet first), computes when each pair of
neighbours meets, and keeps those meeting times in a heap with lazy invalidation
(an entry is stale once either front has died or the two are no longer
neighbours).  It pops the earliest event and gathers every front through the same
point at that time (symmetric scenes make several meet on purpose).  Then:

- rays of one isentrope meeting each other or a reflecting boundary are handed to
  the method of characteristics (``fronttrack.zones``): the whole zone of rays around
  them is solved in bulk as one lattice, up to the first thing it does not model;
- anything else is one Riemann problem between the state left of the group and the
  state right of it (``fronttrack.interactions``), whose outgoing waves replace the
  group (shocks as jumps, simple waves as families of characteristics).

Invariants kept by every step: the list is ordered in X at the current time; each
front's ``region_right`` is the region between it and its successor; a region's
state is constant; every queue entry is either valid or detectably stale.
"""

from __future__ import annotations

import dataclasses
import heapq
import itertools
import math
import time

from characteristics.isentrope import IsentropeTables
from materials import State, WavediagramError
from materials.release_crossing import ReleasePaths

from . import (
    archive,
    cluster,
    coalesce,
    dropped,
    fragment,
    initiation,
    interactions,
    mismatch,
    neglect,
    outgoing,
    ringing,
    spall,
    zones,
)
from .counters import Counters
from .event_log import EventLog
from .fronts import UNKNOWN, Front, Region, inside_fan
from .kinds import FrontKind, Release
from .resolution import Resolution, initial_state, resolve
from .scene import Scene
from .solution import Solution

ENTROPY_JUMP_TOLERANCE = 1e-12
"""Entropy contacts whose relative volume jump is below this are rounding, never tracked.
Larger ones are tracked unless they would reflect less than the negligible stress."""

FRACTURE, FORMATION, SITE, PAIR = 0, 1, 2, 2
"""Queue priorities at equal times: a fracture or a shock formation happens before the
waves meeting at that instant are solved."""


class EventLimitError(WavediagramError, RuntimeError):
    """The scene needed more events than ``accuracy.max_events`` allows."""


class Engine:
    """Evolves one scene; ``run()`` returns a ``Solution``."""

    def __init__(self, scene: Scene, progress=None, fractures=(), deadline=None):
        """``fractures``: ``(x, t)`` points (m, s) at which the material is made to
        fracture (the failures a cumulative-damage criterion found, ``fronttrack.damage``).
        ``deadline``: a ``time.perf_counter()`` value after which the run stops at the
        time it has reached (``stop_early``)."""
        self.scene = scene.validate()
        self.deadline = deadline
        self.stopped = None
        self.acc = scene.accuracy
        self.fractures = tuple(fractures)
        self.progress = progress
        self.counters = Counters()
        self.tables = None  # made once the resolution (its tolerance) is known
        self._ids = itertools.count()
        self._region_ids = itertools.count()
        self._wave_ids = itertools.count()
        self._seq = itertools.count()
        self._heap: list = []
        self.fronts: list[Front] = []  # objects not yet compacted (fronttrack.archive)
        self.regions: list[Region] = []
        self.front_table = archive.FrontTable()
        self.region_table = archive.RegionTable()
        self.compact_at = archive.COMPACT_BATCH
        self.patches: list = []
        self.events = EventLog()
        self.spalls: list = []
        self.fracture_zones: list = []
        self.planned_fractures: list[float] = []
        self.torn_faces: set[int] = set()  # ids of held boundary faces torn off (spall)
        self.min_stress: tuple[float, float, float] | None = None
        self.t_end = scene.t_end
        self.initial_states = [initial_state(layer, f"layer[{k}]")
                               for k, layer in enumerate(scene.layers)]
        self.resolution: Resolution = resolve(scene, self.initial_states)
        self.tables = IsentropeTables(self.resolution.negligible)
        self.release_paths = ReleasePaths()  # plastic release paths met (interactions)
        self.signal_speed = signal_speed(scene, self.resolution.stress_scale)
        self.head: Front | None = None
        self.coalesce_budget: tuple[float, float] | None = None  # fronttrack.coalesce
        self.mismatches = mismatch.new_ledger()
        self.keep_weak_waves = False  # set while a site's mismatch is solved again
        self.neglect_budget = neglect.NeglectBudget()
        self.drop_ledger = dropped.Ledger()
        self.cluster_watch = cluster.ClusterWatch(self.resolution, self.signal_speed)
        self.free_rings = fragment.Rings()  # free fragments ringing in closed form

    # --- ids and objects ------------------------------------------------------------
    def next_front_id(self) -> int:
        return next(self._ids)

    def next_region_id(self) -> int:
        return next(self._region_ids)

    def next_wave_id(self) -> int:
        return next(self._wave_ids)

    def new_front(self, kind: FrontKind, x0: float, t0: float, **kw) -> Front:
        front = Front(id=next(self._ids), kind=kind, x0=x0, t0=t0, **kw)
        self.fronts.append(front)
        return front

    def new_region(self, state: State, material, layer: int, t: float, left_point,
                   right_point, table=UNKNOWN, in_fan: bool = False) -> Region:
        region = Region(id=next(self._region_ids), state=state, material=material, layer=layer,
                        t_start=t, left_points=[left_point], right_points=[right_point],
                        in_fan=in_fan, table=table)
        self.regions.append(region)
        self.note_stress(state.sigma, 0.5 * (left_point[0] + right_point[0]), t)
        return region

    def note_stress(self, sigma: float, x: float, t: float) -> None:
        """Keep the lowest stress (largest tension) and where and when it first appears:
        a later one within the rounding of a computed stress (1e-12 relative) of it, as
        the echoes of a held tension are, is the same tension, not a new maximum."""
        low = self.min_stress
        if low is None or sigma < low[0] - 1e-12 * abs(low[0]):
            self.min_stress = (sigma, x, t)

    def table_of(self, region: Region):
        """The isentrope table of a region's state (looked up once), or ``None``."""
        if region.table is UNKNOWN:
            region.table = (self.tables.table(region.material, region.state)
                            if self.resolution.release == Release.ISENTROPE else None)
        return region.table

    def invariants_of(self, region: Region) -> tuple[float, float]:
        """``(J+, J-)`` of a region on its table (computed once)."""
        if region.invariants is None:
            region.invariants = self.table_of(region).invariants(region.state)
        return region.invariants

    # --- set-up -----------------------------------------------------------------------
    def _build(self) -> None:
        scene, states = self.scene, self.initial_states
        left = self.new_front(FrontKind.BOUNDARY, 0.0, 0.0, side="left")
        fronts = [left]
        x = 0.0
        for i, layer in enumerate(scene.layers):
            x_next = x + layer.thickness
            region = self.new_region(states[i], layer.material, i, 0.0, (x, 0.0),
                                     (x_next, 0.0))
            fronts[-1].region_right = region
            if i + 1 < len(scene.layers):
                nxt = scene.layers[i + 1]
                strength = 0.0 if nxt.bond == "unbonded" else min(
                    layer.material.spall_strength, nxt.material.spall_strength)
                fronts.append(self.new_front(FrontKind.INTERFACE, x_next, 0.0, bond=nxt.bond,
                                             strength=strength))
            x = x_next
        fronts.append(self.new_front(FrontKind.BOUNDARY, x, 0.0, side="right"))
        for a, b in itertools.pairwise(fronts):
            a.next, b.prev = b, a
        self.head = left
        for front in fronts:
            self.push_site(front, 0.0)
        initiation.schedule(self, fronts)
        criterion = scene.spall_criterion
        for x, t in self.fractures:
            spall.schedule_point(self, x, t, criterion.threshold)
        for boundary, spec in ((left, scene.left), (fronts[-1], scene.right)):
            boundary.boundary_steps = interactions.boundary_steps(self, spec, boundary)

    # --- queue ------------------------------------------------------------------------
    def push_site(self, front: Front, t: float) -> None:
        if t <= self.t_end:
            heapq.heappush(self._heap, (t, SITE, next(self._seq), "site", front,
                                        front.gap_version))

    def push_pair(self, a: Front, b: Front, now: float) -> None:
        closing = a.speed - b.speed
        if closing <= 0.0:
            return
        gap = b.position(now) - a.position(now)
        t = now + max(gap, 0.0) / closing
        if t <= self.t_end:
            heapq.heappush(self._heap, (t, PAIR, next(self._seq), "pair", a, b))

    def push_fracture(self, plan) -> None:
        """Queue a ``spall.FracturePlan``: it is made before anything else at its time."""
        if plan.t <= self.t_end:
            heapq.heappush(self._heap, (plan.t, FRACTURE, next(self._seq), "fracture", plan,
                                        None))

    def push_mismatch(self, entry) -> None:
        """Queue the deadline of a site's stress mismatch (``fronttrack.mismatch``)."""
        heapq.heappush(self._heap, (entry.deadline, SITE, next(self._seq), "mismatch", entry,
                                    None))

    def push_gap_closure(self, gap: Front) -> None:
        if fragment.touches(self, gap):  # a face rings: its closure in closed form
            gap.gap_version += 1
            self.push_site(gap, fragment.closure_time(self, gap))
            return
        left, right = gap.prev.region_right.state.u, gap.region_right.state.u
        gap.gap_version += 1
        if left > right:
            self.push_site(gap, gap.gap_time + gap.gap_width / (left - right))

    def causal_horizon(self, left: tuple[float, float], right: tuple[float, float],
                       members: set[int], now: float, limit: float) -> float:
        """The first time an event pending outside ``members`` could reach a region that
        spans, from ``now``, from the line ``left`` to the line ``right`` (each
        ``(X at now, speed)``, m and m/s): no signal outruns ``signal_speed``, so an event
        at ``(x_e, t_e)`` left of the region reaches it when
        ``x_e + C (t - t_e) = X_left + s_left (t - now)``.  A region of the method of
        characteristics may be solved ahead of the queue up to this time."""
        c = self.signal_speed
        best = limit
        for entry in self._heap:
            t_e = entry[0]
            if t_e >= best:
                continue
            kind = entry[3]
            if kind == "pair":
                a, b = entry[4], entry[5]
                if not (a.alive and b.alive and a.next is b) or (
                        id(a) in members and id(b) in members):
                    continue
                x_e = a.position(t_e)
            elif kind == "site":
                front = entry[4]
                if not front.alive or entry[5] != front.gap_version or id(front) in members:
                    continue
                x_e = front.x0
            elif kind == "mismatch":
                if not mismatch.is_due(self, entry[4]) or id(entry[4].site) in members:
                    continue
                x_e = entry[4].site.position(t_e)
            else:
                x_e = entry[4].x
            (x_l, s_l), (x_r, s_r) = left, right
            at_left, at_right = x_l + s_l * (t_e - now), x_r + s_r * (t_e - now)
            # an edge running away at the signal speed is never reached
            if x_e < at_left:
                reach = t_e + (at_left - x_e) / (c - s_l) if c > s_l else math.inf
            elif x_e > at_right:
                reach = t_e + (x_e - at_right) / (c + s_r) if c > -s_r else math.inf
            else:
                reach = t_e
            best = min(best, reach)
        return best

    def next_event_time(self, front: Front) -> float:
        """The earliest time ``front`` would meet its left neighbour, or its own timer
        (a boundary step, a gap closing): the front is unchanged until then."""
        t = math.inf
        before = front.prev
        if before is not None:
            closing = before.speed - front.speed
            if closing > 0.0:
                now = max(before.t0, front.t0)
                t = now + max(front.position(now) - before.position(now), 0.0) / closing
        return min(t, self.timer_of(front))

    def next_event_time_right(self, front: Front) -> float:
        """The earliest time ``front`` would meet its right neighbour, or its own timer."""
        t = math.inf
        after = front.next
        if after is not None:
            closing = front.speed - after.speed
            if closing > 0.0:
                now = max(after.t0, front.t0)
                t = now + max(after.position(now) - front.position(now), 0.0) / closing
        return min(t, self.timer_of(front))

    def timer_of(self, front: Front) -> float:
        """A site's own next event: a boundary step or a gap closing (inf if none)."""
        if front.kind == FrontKind.BOUNDARY:
            later = [s for s, _ in front.boundary_steps if s > front.t0]
            return min((s for s in later), default=math.inf)
        if front.kind == FrontKind.GAP:
            left, right = front.prev.region_right.state.u, front.region_right.state.u
            if left > right:
                return front.gap_time + front.gap_width / (left - right)
        return math.inf

    # --- main loop ----------------------------------------------------------------------
    def run(self) -> Solution:
        start = time.perf_counter()
        self._build()
        counters = self.counters
        while self._heap:
            entry = heapq.heappop(self._heap)
            t, kind = entry[0], entry[3]
            if kind == "fracture":
                interactions.fracture(self, entry[4])
                continue
            if kind == "mismatch":
                if not mismatch.is_due(self, entry[4]) or mismatch.deferred(self, entry[4]):
                    continue
                front = entry[4].site
                x, seed = front.position(t), [front]
            elif kind == "pair":
                a, b = entry[4], entry[5]
                if not (a.alive and b.alive and a.next is b):
                    continue
                x = self._meeting_point(a, b, t)
                seed = [a, b]
            else:
                front, version = entry[4], entry[5]
                if not front.alive or version != front.gap_version:
                    continue
                x = front.x0
                seed = [front]
            counters.events += 1
            if counters.events > self.acc.max_events:
                raise EventLimitError(
                    f"accuracy.max_events: the scene needed more than {self.acc.max_events} "
                    f"events before t = {t * 1e6:.6g} us (t_end = {self.t_end * 1e6:.6g} us); "
                    f"(a lattice's {zones.NODES_PER_EVENT} nodes count as one event); "
                    f"raise max_events, shorten t_end or loosen the accuracy")
            if self.deadline is not None and time.perf_counter() > self.deadline:
                limit = self.acc.max_seconds
                self.stop_early(t, "time limit reached" if limit is None
                                else f"time limit of {limit:g} s reached")
                break
            self.keep_weak_waves = kind == "mismatch"
            if self.keep_weak_waves:
                mismatch.count_resolved(self)
            self._process(seed, t, x, timer=kind == "site")
            self.keep_weak_waves = False
            if len(self.fronts) >= self.compact_at:
                archive.compact(self)
            if self.progress is not None and counters.events % 1000 == 0:
                self.progress(counters.events, t)
        self._finish()
        return Solution.from_engine(self, time.perf_counter() - start)

    def stop_early(self, t: float, reason: str) -> None:
        """End the solution at time ``t`` (s), before ``t_end``, and record why: the
        scene of the solution then ends at ``t`` and ``stats["stopped"]`` says so."""
        t = max(t, 1e-12 * self.t_end)  # a scene lasts some time, even one stopped at once
        self.stopped = {"reason": reason, "t": t, "t_end": self.t_end}
        self.t_end = t
        self.scene = dataclasses.replace(self.scene, t_end=t)

    def _meeting_point(self, a: Front, b: Front, t: float) -> float:
        if a.speed == 0.0:
            return a.x0
        if b.speed == 0.0:
            return b.x0
        return 0.5 * (a.position(t) + b.position(t))

    def _gather(self, seed: list[Front], t: float, x: float) -> list[Front]:
        """All consecutive fronts through ``(x, t)``, at most one site among them."""
        group = list(seed)
        sites = sum(f.is_site for f in group)
        x_tol = self.resolution.x_tol
        while True:
            p = group[0].prev
            if p is None or abs(p.position(t) - x) > x_tol or (p.is_site and sites):
                break
            group.insert(0, p)
            sites += p.is_site
        while True:
            n = group[-1].next
            if n is None or abs(n.position(t) - x) > x_tol or (n.is_site and sites):
                break
            group.append(n)
            sites += n.is_site
        return group

    def _process(self, seed: list[Front], t: float, x: float, timer: bool) -> None:
        group = self._gather(seed, t, x)
        piled = None if timer else cluster.gather(self, group, t, x)
        if piled is not None:
            group, x = piled
        elif not timer and (fragment.try_replace(self, group, t) or ringing.try_end(self, group, t)
                            or zones.try_zone(self, group, t)):
            return
        if timer:
            fragment.end_at_face(self, group, t)  # a ring's gap closes: its waves come back
        site = cluster.principal_site([f for f in group if f.is_site])
        before = group[0].prev
        region_left = before.region_right if before is not None else None
        region_right = group[-1].region_right
        incoming = [f for f in group if not f.is_site]
        if site is not None and site.kind == FrontKind.GAP:
            fragment.advance_gap(self, site, t)  # the faces moved with the states beside them
        self.counters.riemann_solves += 1
        kind, solution, new_site = interactions.solve(self, site, region_left, region_right, t,
                                                      x, incoming, timer)
        if site is None and new_site is None and not incoming:
            return
        self.replace(group, site, new_site, solution, region_left, region_right, t, x,
                     incoming, kind)

    # --- rebuilding the front list --------------------------------------------------------
    def replace(self, group, site, new_site, sol, region_left, region_right, t, x, incoming,
                kind) -> None:
        """Replace ``group`` by the waves of the Riemann solution ``sol`` and the site."""
        if sol.release_floor is not None:
            self.counters.note_release_floor(*sol.release_floor)
        material_left = region_left.material if region_left is not None else None
        material_right = region_right.material if region_right is not None else None
        drop = [dropped.drops(self, sol, d, region_left, region_right, site or new_site, t)
                for d in (-1, 1)]
        merged = None
        if (site or new_site) is None and any(drop) and all(
                d or not waves for d, waves in zip(drop, (sol.left_waves, sol.right_waves),
                                                   strict=True)):
            merged = self._merged_state(group, region_left, region_right, t, x)
            if not dropped.merge_allowed(self, group[0].prev, group[-1].next, region_left,
                                         region_right, merged, t):
                drop, merged = [False, False], None
        left_specs = outgoing.wave_fronts(self, sol.left_waves, material_left, t, x, incoming,
                                          -1, site or new_site, drop[0])
        right_specs = outgoing.wave_fronts(self, sol.right_waves, material_right, t, x,
                                           incoming, +1, site or new_site, drop[1])
        mismatch.note_event(self, site or new_site, group, t,
                            sol.left_waves if left_specs is None else (),
                            sol.right_waves if right_specs is None else (), merged)
        # the star behind a family whose rays took energy from the states behind them
        # is its last wave's behind state (outgoing._conserving)
        left_star = _star(sol.left_star, left_specs, region_left)
        right_star = _star(sol.right_star, right_specs, region_right)
        middle = site if site is not None else new_site
        if middle is None and left_star is not None and right_star is not None:
            middle = self._entropy_contact(left_star, right_star, material_left, t, x, group,
                                           (_trailing(left_specs), _trailing(right_specs)))
            if middle is None:
                left_star = right_star = self._neglected_contact_state(
                    left_star, right_star, material_left)
        left_specs = left_specs or []
        right_specs = right_specs or []
        dropped.attach(self, {} if middle is not None else {
            -1: right_specs[-1].front if right_specs else None,
            +1: left_specs[-1].front if left_specs else None})
        # Fronts left to right, each with the state (and its table) on its right.
        items, right_of, tables = [], [], []
        for k, spec in enumerate(left_specs):
            items.append(spec.front)
            last = k == len(left_specs) - 1
            right_of.append(left_star if last else spec.behind)
            tables.append(_star_table(spec, right_specs if middle is None else ())
                          if last else spec.table)
        if middle is not None:
            items.append(middle)
            right_of.append(right_star)
            tables.append(_star_table(right_specs[-1], ()) if right_specs else UNKNOWN)
        for spec in reversed(right_specs):
            items.append(spec.front)
            right_of.append(spec.ahead)
            tables.append(spec.table)
        self.splice(group, items, right_of[:-1], tables[:-1], region_left, region_right, t,
                    x, middle)
        if middle is not None and middle.kind == FrontKind.GAP:
            self.push_gap_closure(middle)
        coalesce.coalesce_around(self, items, t)
        self.events.log(t, x, kind, [f.id for f in incoming],
                        [f.id for f in items if not f.is_site],
                        middle.id if middle is not None else None)

    def _entropy_contact(self, left: State, right: State, material, t: float,
                         x: float, group, carriers=(None, None)) -> Front | None:
        """A contact for the entropy jump between two star states, if it matters.

        A contact that would reflect less than the negligible stress from the scene's
        largest wave (``Material.contact_reflection``), and whose bound on the energy
        the neglect moves fits the budget (``_neglectable``), is not tracked (every later
        crossing would be an event for nothing): the two states are merged and the
        largest relative volume jump so neglected is reported.  Jumps below
        ``ENTROPY_JUMP_TOLERANCE`` are rounding.  So is, when the scene sets
        ``accuracy.contact_resolution``, a contact born closer than that to the
        neighbouring contact; those are counted, and so is the largest energy jump above
        the negligible stress neglected outside the budget (``accuracy.entropy_contacts
        = false``, or a contact that close: ``neglected_contact_energy``, J/kg).
        ``carriers``: the trailing waves of the left and right families leaving the
        event (``None`` where a family is empty or dropped).
        """
        counters, res = self.counters, self.resolution
        jump = abs(left.v - right.v) / max(left.v, right.v)
        # where the stress does not depend on the energy (a two-phase solid's path) two
        # states of one stress have one volume: their entropy jump is in the energy alone
        heat = material.rho0 * abs(left.e - right.e)
        keep = self.acc.entropy_contacts and max(jump, heat / res.stress_scale) > \
            ENTROPY_JUMP_TOLERANCE
        budgeted = keep and res.negligible > 0.0 and math.isfinite(left.v + right.v)
        if budgeted:
            keep = (material.contact_reflection(left, right, res.stress_scale) > res.negligible
                    or not self._neglectable(left, right, material, t, x, group, carriers,
                                             heat))
        if keep and _contact_within(group, x, self.acc.contact_resolution):
            keep, budgeted = False, False
            counters.unresolved_contacts += 1
        if keep:
            return self.new_front(FrontKind.CONTACT, x, t, bond="bonded")
        counters.neglected_entropy = max(counters.neglected_entropy, float(jump))
        if jump > ENTROPY_JUMP_TOLERANCE:
            counters.neglected_contacts += 1
        if not budgeted and heat > res.negligible:
            counters.neglected_contact_energy = max(counters.neglected_contact_energy,
                                                    abs(left.e - right.e))
        return None

    def _neglectable(self, left: State, right: State, material, t: float, x: float, group,
                     carriers, heat: float) -> bool:
        """Whether the energy that neglecting a contact between the star states ``left``
        and ``right`` (energy jump ``heat`` = ``rho0 |e_L - e_R|``, Pa) may make or lose
        fits the budget (``fronttrack.neglect``).

        A contact whose energy jump ``rho0 |e_L - e_R|`` or yield offset is above the
        negligible stress carries history (thermal or plastic) the run forgets: it is
        held, with every such contact neglected before it, to one budget for their sum.
        A thermal one costs what the wave on its hotter side (``carriers``) loses
        sweeping the colder state until its next event, where it is solved again from
        the states it meets (``neglect.hold``): the symmetric Al 2024 impact at 16 rays
        per fan made such a contact (264 kPa, the negligible stress 246 kPa) in its
        spalled fragment once a ring period from 4.5 us; kept, its weak reflections
        filled the fragment and the run to 18 us stopped at the event limit."""
        res = self.resolution
        cost = neglect.neglect_cost(self, material, group, x, left, right, t)
        plastic = material.yield_offset(left, right) > res.negligible
        if not neglect.affordable(self, cost, t, history=plastic or heat > res.negligible):
            return False
        if heat > res.negligible and not plastic:
            neglect.hold(self, carriers[0] if left.e > right.e else carriers[1], heat, t, cost)
        return True

    def _neglected_contact_state(self, left: State, right: State, material) -> State:
        """The one state that replaces two star states whose entropy contact is not tracked.

        The two waves leaving the event will not sweep for the same time (the weaker is
        soon replaced, the stronger may run across the layer), so any mean of the two
        would make the longer-running wave create energy for as long as it runs (campaign
        seed 349: a mean weighted by the sweep rates created 0.3 % of the energy per
        microsecond behind an 86 GPa shock).  The state of lower specific internal energy
        is taken for both sides: the wave on the other side runs into a state below its
        jump conditions and can only lose energy.
        """
        return left if left.e <= right.e else right

    def splice(self, group, items, between, tables, region_left, region_right, t, x,
               middle) -> None:
        """Kill ``group`` (except a continuing site), link ``items`` and make their regions.

        ``between[k]`` is the state right of ``items[k]`` (for all but the last item) and
        ``tables[k]`` its isentrope table where the outgoing wave knows it.
        """
        before, after = group[0].prev, group[-1].next
        point = (x, t)
        for front in group:
            if front is middle:
                continue
            dropped.settle(self, front, t)
            neglect.settle(self, front, t)
            front.alive = False
            front.t1, front.x1 = t, x
            front.right_region_id = front.region_right.id if front.region_right else None
        for front in group[:-1]:
            region = front.region_right
            if region is not None and region.t_end is None:
                region.left_points.append(point)
                region.right_points.append(point)
                region.t_end = t
        if not items:
            self._merge(group, region_left, region_right, t, x)
            return
        if region_left is not None:
            region_left.right_points.append(point)
        if region_right is not None:
            region_right.left_points.append(point)
        chain = ([before] if before is not None else []) + items + (
            [after] if after is not None else [])
        for a, b in itertools.pairwise(chain):
            a.next, b.prev = b, a
        if before is None:
            self.head = items[0]
        layer_left = region_left.layer if region_left is not None else region_right.layer
        layer_right = region_right.layer if region_right is not None else layer_left
        continuing = middle.region_right if middle is not None else None
        on_right = False
        for k, front in enumerate(items):
            on_right = on_right or front is middle
            front.left_region = (items[k - 1].region_right.id if k > 0 else
                                 (region_left.id if region_left is not None else None))
            if k + 1 < len(items):
                material = region_right.material if on_right else region_left.material
                layer = layer_right if on_right else layer_left
                front.region_right = self.new_region(
                    between[k], material, layer, t, point, point, table=tables[k],
                    in_fan=inside_fan(front, items[k + 1]))
            else:
                front.region_right = region_right
        if continuing is not None and middle.region_right is not continuing:
            middle.earlier_regions.append((t, continuing.id))
        for a, b in itertools.pairwise(chain):
            self.push_pair(a, b, t)

    @staticmethod
    def _merged_state(group, region_left, region_right, t, x) -> State:
        """The state of the region that ``region_left`` and ``region_right``, beside the
        event of ``group`` at ``(x, t)`` (m, s) in one material, become when no front
        leaves it: weighted by the mass each holds now, so that it holds both."""
        return _merged(region_left.state, region_right.state,
                       x - group[0].prev.position(t), group[-1].next.position(t) - x)

    def _merge(self, group, region_left, region_right, t, x) -> None:
        """No front leaves the event: the two neighbouring regions become one."""
        before, after = group[0].prev, group[-1].next
        x_left = before.position(t)
        x_right = after.position(t)
        region_left.right_points.append((x, t))
        region_left.left_points.append((x_left, t))
        region_right.right_points.append((x_right, t))
        region_right.left_points.append((x, t))
        region_left.t_end = region_right.t_end = t
        state = self._merged_state(group, region_left, region_right, t, x)
        merged = self.new_region(state, region_left.material, region_left.layer, t,
                                 (x_left, t), (x_right, t), in_fan=inside_fan(before, after))
        before.next, after.prev = after, before
        before.earlier_regions.append((t, region_left.id))
        before.region_right = merged
        self.push_pair(before, after, t)

    def _finish(self) -> None:
        t = self.t_end
        front = self.head
        while front is not None:
            if front.alive:
                front.t1, front.x1 = t, front.position(t)
                front.right_region_id = front.region_right.id if front.region_right else None
            region = front.region_right
            if region is not None and region.t_end is None:
                region.left_points.append((front.position(t), t))
                region.right_points.append((front.next.position(t), t))
                region.t_end = t
            front = front.next


SIGNAL_MARGIN = 1.25
"""The fastest signal of a scene is taken as this factor times the largest sound speed
behind a shock of twice its stress scale (a bound, used to order lattices with the
queue: ``Engine.causal_horizon``)."""


def signal_speed(scene: Scene, stress_scale: float) -> float:
    """A speed (m/s) no wave of the scene exceeds (``SIGNAL_MARGIN`` of the largest sound
    speed, in any layer, behind a shock to twice the stress scale)."""
    fastest = 0.0
    for layer in scene.layers:
        material = layer.material
        reference = material.reference_state()
        curve = material.wave_curve(reference, 1, "hugoniot")
        top = min(2.0 * stress_scale, curve.sigma_max())
        try:
            state = curve.state_at(top)
            fastest = max(fastest, material.sound_speed(state.v, state.e),
                          material.sound_speed(reference.v, reference.e))
        except ValueError:
            fastest = max(fastest, material.sound_speed(reference.v, reference.e))
        fastest = max(fastest, getattr(material, "C0", 0.0))
    return SIGNAL_MARGIN * fastest


def _contact_within(group, x: float, distance: float) -> bool:
    """True if the nearest site on either side of ``group`` is an entropy contact closer
    than ``distance`` (m) to ``x``."""
    if distance <= 0.0:
        return False
    for front, step in ((group[0].prev, "prev"), (group[-1].next, "next")):
        while front is not None and not front.is_site:
            front = getattr(front, step)
        if front is not None and front.kind == FrontKind.CONTACT \
                and abs(front.x0 - x) < distance:
            return True
    return False


def _merged(a: State, b: State, weight_a: float = 1.0, weight_b: float = 1.0) -> State:
    """One state standing for two that differ negligibly: the weighted mean of each
    numeric field (equal weights when both are zero); ``a``'s type is kept, so a
    model's extra state fields survive."""
    total = weight_a + weight_b
    wa, wb = (weight_a / total, weight_b / total) if total > 0.0 else (0.5, 0.5)
    shared = {f.name for f in dataclasses.fields(b)}
    means = {f.name: wa * getattr(a, f.name) + wb * getattr(b, f.name)
             for f in dataclasses.fields(a) if f.name in shared}
    return dataclasses.replace(a, **means)


def _star(solved: State, specs, region) -> State | None:
    """The state behind a family of waves leaving an event: ``region``'s where the
    family was dropped (``specs`` None), the state behind its last wave where its rays'
    jumps shifted it (``outgoing._conserving``), else the solved star."""
    if specs is None:
        return region.state if region is not None else None
    return specs[-1].behind if specs and specs[-1].shifted else solved


def _trailing(specs) -> Front | None:
    """The trailing front of a family's ``specs`` (leading first), ``None`` if none."""
    return specs[-1].front if specs else None


def _star_table(spec, beside) -> object:
    """The isentrope table of the star region behind ``spec`` (the last wave of a family),
    ``UNKNOWN`` (looked up from its state) unless its rays shifted it off their table by
    the energy their jumps took (``outgoing._conserving``): a look-up from the state could
    then land on a neighbouring isentrope, so it keeps its rays' table, unless it also
    lies behind the last wave of the other family (``beside``: no contact between) on
    another table."""
    if not spec.shifted or spec.table is UNKNOWN or spec.front.kind != FrontKind.RAY:
        return UNKNOWN
    if beside and beside[-1].table is not spec.table:
        return UNKNOWN
    return spec.table
