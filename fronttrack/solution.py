"""The solution of a scene: fronts, regions, events, and the queries on them.

The engine's solution is a tiling of the X–t plane by cells of constant state
separated by straight fronts.  Shocks and contacts are exact jumps; rays are the
characteristics of simple waves and lattices, and the cells between them carry the
state of their middle.  Every query a user makes reads the solution continuously
(``characteristics.reconstruct``): a history at a Lagrangian station, a profile at
an instant and ``state_at`` interpolate the Riemann invariants between rays (exact
at each ray, second order between them) and jump only at shocks and contacts.

The conservation balance

    d/dt int rho0 u dX           = sigma(left) - sigma(right),
    d/dt int rho0 (e + u^2/2) dX = (sigma u)(left) - (sigma u)(right),

(stress positive in compression) is computed on the cells the engine advanced and
the boundary histories they give, exactly: its residual measures the engine itself.
Units are SI throughout.
"""

from __future__ import annotations

import dataclasses
import json
import math
from collections.abc import Iterator
from dataclasses import dataclass, field
from typing import TextIO

import numpy as np

from characteristics.reconstruct import Cell, Crossing, knots
from materials import State

from . import dropped, ring_records, spall
from .archive import FrontTable, RegionTable, compact
from .errors import SceneError
from .event_log import EventRecord
from .fronts import UNKNOWN, FrontRecord, RegionRecord
from .kinds import FrontKind
from .numbering import region_numbers
from .units import to_si
from .windows import window_record

POSITION_ROUNDING = 1e-12
"""Fronts closer than this fraction of the stack length are at one point (rounding)."""


@dataclass(frozen=True)
class SpallRecord:
    """A fracture: position ``x`` (m), time ``t`` (s), the tension reached (Pa, positive)
    and the strength that failed (Pa); ``layer`` and, when the threshold fractured a
    zone around it, that zone's ``(x_lo, x_hi)`` (m)."""

    x: float
    t: float
    tension: float
    strength: float
    layer: int = 0
    zone: tuple | None = None


class StateSeries:
    """Arrays of the fields of a sequence of states (``self.states``)."""

    states: tuple | list

    @property
    def sigma(self) -> np.ndarray:
        """Stress (Pa, compression positive) of each state."""
        return np.array([s.sigma for s in self.states])

    @property
    def u(self) -> np.ndarray:
        """Particle velocity (m/s) of each state."""
        return np.array([s.u for s in self.states])

    @property
    def rho(self) -> np.ndarray:
        """Density (kg/m³); zero for a gas expanded into vacuum (infinite volume)."""
        return np.array([1.0 / s.v for s in self.states])


@dataclass(frozen=True)
class History(StateSeries):
    """A record along one coordinate (time at a station, or X at an instant).

    Piece ``k`` starts at ``t[k]`` with ``states[k]`` and runs linearly to ``ends[k]`` just
    before ``t[k + 1]`` (the last piece to the record's end ``stop``).  A piece with
    ``ends[k] == states[k]`` is constant; a shock is a jump between ``ends[k - 1]`` and
    ``states[k]``; inside a simple wave the pieces join continuously.  (The name ``t``
    is kept for the coordinate of a profile too.)
    """

    t: np.ndarray
    states: list
    ends: list
    stop: float

    @property
    def sigma_end(self) -> np.ndarray:
        return np.array([s.sigma for s in self.ends])

    @property
    def u_end(self) -> np.ndarray:
        return np.array([s.u for s in self.ends])

    def samples(self, quantity: str = "sigma") -> tuple[np.ndarray, np.ndarray]:
        """Points to draw the record: each piece's start and end (jumps are vertical)."""
        starts = np.array([getattr(s, quantity) for s in self.states])
        ends = np.array([getattr(s, quantity) for s in self.ends])
        coord = np.empty(2 * len(self.t))
        coord[0::2] = self.t
        coord[1::2] = np.append(self.t[1:], self.stop)
        values = np.empty(2 * len(self.t))
        values[0::2], values[1::2] = starts, ends
        return coord, values

    def at(self, where, quantity: str = "sigma") -> np.ndarray:
        """The record's value at the coordinates ``where`` (right limit at a jump)."""
        where = np.atleast_1d(np.asarray(where, dtype=float))
        k = np.clip(np.searchsorted(self.t, where, side="right") - 1, 0, len(self.t) - 1)
        a = np.array([getattr(s, quantity) for s in self.states])
        b = np.array([getattr(s, quantity) for s in self.ends])
        right = np.append(self.t[1:], self.stop)
        width = right - self.t
        f = np.where(width[k] > 0.0, (where - self.t[k]) / np.where(width[k] > 0, width[k], 1),
                     0.0)
        return a[k] + np.clip(f, 0.0, 1.0) * (b[k] - a[k])

    def l1_distance(self, other: History, quantity: str = "sigma") -> float:
        """Exact integral of ``|self - other|`` over the common span of two records (both
        are linear between the union of their break points)."""
        stop = min(self.stop, other.stop)
        edges = np.union1d(np.append(self.t, stop), np.append(other.t, stop))
        edges = edges[edges <= stop]
        lo, hi = edges[:-1], edges[1:]
        inside = 1e-9 * (hi - lo)
        d0 = self.at(lo + inside, quantity) - other.at(lo + inside, quantity)
        d1 = self.at(hi - inside, quantity) - other.at(hi - inside, quantity)
        width = hi - lo
        same_sign = d0 * d1 >= 0.0
        with np.errstate(divide="ignore", invalid="ignore"):
            crossing = np.where(same_sign, 0.0, np.abs(d0) / (np.abs(d0) + np.abs(d1)))
        area = np.where(same_sign, 0.5 * np.abs(d0 + d1) * width,
                        0.5 * width * (np.abs(d0) * crossing + np.abs(d1) * (1.0 - crossing)))
        return float(np.sum(area))

    def integral(self, values: np.ndarray, t_end: float, ends: np.ndarray | None = None
                 ) -> float:
        """Exact integral from 0 to ``t_end`` of a quantity linear on each piece (its
        values at the starts, and at the ends if they differ)."""
        ends = values if ends is None else ends
        edges = np.append(self.t, self.stop)
        total = 0.0
        for k in range(len(self.t)):
            a, b = edges[k], min(edges[k + 1], t_end)
            if b <= a:
                continue
            width = edges[k + 1] - a
            f = (b - a) / width if width > 0 else 1.0
            mid_end = values[k] + f * (ends[k] - values[k])
            total += 0.5 * (values[k] + mid_end) * (b - a)
        return total


def _history(coords, states, stop: float, start: float = 0.0) -> History:
    """Pieces from reconstruction knots (equal consecutive coordinates make a jump)."""
    t, starts, ends = [], [], []
    for k in range(len(coords) - 1):
        a, b = coords[k], coords[k + 1]
        if b <= a:
            continue
        s0, s1 = states[k], states[k + 1]
        if t and s0 == s1 == starts[-1] == ends[-1]:
            continue  # a constant piece continuing the previous one
        t.append(a)
        starts.append(s0)
        ends.append(s1)
    if not t:
        t, starts, ends = [start], [states[-1]], [states[-1]]
    t[0] = start
    return History(t=np.array(t), states=starts, ends=ends, stop=stop)


@dataclass
class Solution:
    """The front-tracking solution of one scene.

    The fronts and regions the engine made are held as columns (``front_table``,
    ``region_table``: ``fronttrack.archive``), the interiors of lattices as ``patches``;
    records are made from them when asked for.
    """

    scene: object
    front_table: FrontTable
    region_table: RegionTable
    patches: list
    events: list
    spalls: list
    stats: dict
    accuracy_report: dict
    min_stress: tuple | None
    initial_states: list
    counters: object = None
    fracture_zones: list = field(default_factory=list)
    tables: object = None
    rings: tuple = ()
    _cache: dict = field(default_factory=dict, repr=False)

    @classmethod
    def from_engine(cls, engine, elapsed: float) -> Solution:
        counters = engine.counters
        compact(engine, final=True)
        fronts, regions = engine.front_table, engine.region_table
        rays = fronts.count(FrontKind.RAY) + sum(len(p.seg_id) for p in engine.patches)
        stats = {
            "events": len(engine.events),
            "lattices": counters.lattices,
            "lattice_nodes": counters.nodes,
            "riemann_solves": counters.riemann_solves,
            "isentrope_tables": engine.tables.built,
            "fronts": len(fronts) + sum(len(p.seg_id) for p in engine.patches),
            "regions": len(regions) + sum(len(p.cell_id) for p in engine.patches),
            "rays": rays,
            "shocks": fronts.count(FrontKind.SHOCK),
            "contacts": fronts.count(FrontKind.CONTACT),
            "solve_time": elapsed,
        }
        if engine.stopped is not None:
            stats["stopped"] = engine.stopped
        acc = engine.acc
        report = engine.resolution.report() | {
            "entropy_contacts": acc.entropy_contacts,
            "dropped_waves": counters.dropped_waves,
            "dropped_stress_total": counters.dropped_stress,
            "neglected_entropy_volume_jump": counters.neglected_entropy,
            "neglected_entropy_contacts": counters.neglected_contacts,
            "neglected_contact_energy": counters.neglected_contact_energy,
            "neglected_contact_cost": counters.neglect_cost,
            "neglected_history_cost": counters.history_cost,
            "dropped_wave_cost": dropped.cost(engine),
            "cavitations": counters.cavitations,
            "release_floors": {name: {"stress": stress, "faces": count}
                               for name, (stress, count) in counters.release_floors.items()},
            "contact_resolution": acc.contact_resolution,
            "contacts_below_resolution": counters.unresolved_contacts,
            "coalesced_fronts": counters.coalesced,
            "coalesced_momentum": counters.coalesced_momentum,
            "coalesced_energy": counters.coalesced_energy,
            "ringing_replaced": counters.ringing,
            "fragments_ringing": counters.fragments,
            "gathered_fronts": counters.gathered,
            "gathered_momentum": counters.gathered_momentum,
            "gathered_energy": counters.gathered_energy,
            "spall_spacing": spall.spacing(engine),
            "fracture_zones": [{"layer": z.layer, "x_lo": z.x_lo, "x_hi": z.x_hi, "t": z.t}
                               for z in engine.fracture_zones],
            "suppressed_spalls": counters.suppressed_spalls,
            "largest_suppressed_tension": counters.suppressed_tension,
        } | engine.mismatches.report()
        return cls(scene=engine.scene, front_table=fronts, region_table=regions,
                   patches=engine.patches,
                   events=engine.events, spalls=engine.spalls, stats=stats,
                   accuracy_report=report, min_stress=engine.min_stress,
                   initial_states=engine.initial_states, counters=counters,
                   fracture_zones=engine.fracture_zones, tables=engine.tables,
                   rings=ring_records.records(engine))

    # --- records ------------------------------------------------------------------------
    @property
    def fronts(self) -> list[FrontRecord]:
        """Every front as a frozen record (segments inside lattices included)."""
        if "fronts" not in self._cache:
            self._cache["fronts"] = list(self.front_records())
        return self._cache["fronts"]

    @property
    def regions(self) -> list[RegionRecord]:
        """Every region as a frozen record (cells inside lattices included)."""
        if "regions" not in self._cache:
            self._cache["regions"] = list(self.region_records())
        return self._cache["regions"]

    def front_records(self) -> Iterator[FrontRecord]:
        """The front records one by one, made as they are read and not kept (``fronts``
        keeps them; from its list when it has been read)."""
        if "fronts" in self._cache:
            yield from self._cache["fronts"]
            return
        yield from self.front_table.records()
        for patch in self.patches:
            yield from patch.front_records()

    def region_records(self) -> Iterator[RegionRecord]:
        """The region records one by one, made as they are read and not kept (``regions``
        keeps them; from its list when it has been read)."""
        if "regions" in self._cache:
            yield from self._cache["regions"]
            return
        yield from self.region_table.records()
        for patch in self.patches:
            yield from patch.region_records()

    # --- geometry -----------------------------------------------------------------------
    def _segments(self) -> dict:
        """Front segments as arrays: one per front and per region on its right."""
        if "segments" not in self._cache:
            parts = [self.front_table.segments()]
            for patch in self.patches:
                parts.append({"x0": patch.seg_x0, "t0": patch.seg_t0, "t1": patch.seg_t1,
                              "speed": patch.seg_speed, "right": patch.seg_right,
                              "ray": np.ones(len(patch.seg_id), bool),
                              "family": patch.seg_direction, "invariant": patch.seg_invariant,
                              "lineage": np.full(len(patch.seg_id), patch.lineage)})
            arrays = {name: np.concatenate([part[name] for part in parts])
                      for name in parts[0]}
            for name, dtype in (("right", int), ("ray", bool), ("lineage", int)):
                arrays[name] = arrays[name].astype(dtype, copy=False)
            self._cache["segments"] = arrays
        return self._cache["segments"]

    def _cells(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Where the cells inside lattices live: their ids in increasing order, and for
        each its patch (index in ``patches``) and its index in that patch."""
        if "cells" not in self._cache:
            ids = np.concatenate([p.cell_id for p in self.patches] or [np.empty(0, int)])
            patch = np.repeat(np.arange(len(self.patches)),
                              [len(p.cell_id) for p in self.patches])
            index = np.concatenate([np.arange(len(p.cell_id)) for p in self.patches]
                                   or [np.empty(0, int)])
            order = np.argsort(ids, kind="stable")
            self._cache["cells"] = ids[order], patch[order], index[order]
        return self._cache["cells"]

    def _find(self, region_id: int) -> int | tuple:
        """Where region ``region_id`` lives: its row of ``region_table``, or a lattice
        patch and an index in it."""
        row = self.region_table.row(region_id)
        if row >= 0:
            return row
        ids, patch, index = self._cells()
        k = int(np.searchsorted(ids, region_id))
        if k == len(ids) or ids[k] != region_id:
            raise KeyError(region_id)
        return self.patches[patch[k]], int(index[k])

    def _region_state(self, region_id: int) -> State:
        found = self._find(region_id)
        return self.region_table.state(found) if not isinstance(found, tuple) else \
            found[0].state(found[1])

    def _region_cell(self, region_id: int) -> Cell:
        """A region as the reconstruction sees it: its state, table and invariants."""
        found = self._find(region_id)
        if isinstance(found, tuple):
            patch, i = found
            table = patch.table
            state = patch.state(i)
            return Cell(state, table, table.invariants(state) if table is not None else None)
        regions = self.region_table
        state, table = regions.state(found), regions.table(found)
        if table is UNKNOWN:
            table = (self.tables.table(regions.material(found), state)
                     if self.tables is not None and self.accuracy_report.get(
                         "release", "isentrope") == "isentrope" else None)
            regions.set_table(found, table)
        if table is None:
            return Cell(state)
        invariants = regions.invariants(found)
        if invariants is None:
            invariants = table.invariants(state)
            regions.set_invariants(found, invariants)
        return Cell(state, table, invariants)

    def region_record(self, region_id: int) -> RegionRecord:
        """The frozen record of region ``region_id``."""
        found = self._find(region_id)
        if isinstance(found, tuple):
            patch, i = found
            return RegionRecord(id=region_id, state=patch.state(i), material=patch.material,
                                layer=int(patch.layers[i]), t_start=float(patch.cell_t0[i]),
                                t_end=float(patch.cell_t1[i]), in_fan=True,
                                vertices=tuple(patch.polygon(i)), birth=patch.birth(i))
        return self.region_table.record(found)

    def _end_time(self) -> float:
        """When the run ended (s): ``t_end``, or where a time limit stopped it."""
        return self.stats.get("stopped", {}).get("t", self.scene.t_end)

    def _spatial_order(self, index: np.ndarray, pos: np.ndarray, t: float) -> np.ndarray:
        """Order (left to right at time ``t``) of the front segments ``index``.

        Fronts at one point meet at an event there.  Those born at it are ordered as an
        instant later (fastest rightmost); those about to arrive, when ``t`` is within
        rounding of the event but before it, as an instant earlier (slowest rightmost).
        Last key: the latest-born.  Positions within ``POSITION_ROUNDING`` of the stack
        length of each other are one point: two rays extrapolated to the node where they
        cross land a rounding apart, in either order, and read by position alone the
        cell between them (of zero width) would stand for its neighbour.
        """
        a = self._segments()
        speed, t0, t1 = a["speed"][index], a["t0"][index], a["t1"][index]
        # a front still alive when the run ends (t1 at its end) is not arriving anywhere:
        # a detonation shock and the head of its Taylor fan, born together, part by
        # rounding (1e-15 of their speed) and stay a rounding apart to t_end
        arriving = ((t1 - t) < (t - t0)) & (t1 < self._end_time())
        return np.lexsort((t0, np.where(arriving, -speed, speed),
                           _points(pos[index], POSITION_ROUNDING * self.scene.length)))

    def _time_buckets(self) -> tuple[np.ndarray, np.ndarray, float]:
        """The front segments by time slice: ``(index, start, width)``, where the segments
        overlapping slice ``k`` (``[k width, (k+1) width)``, s) are
        ``index[start[k]:start[k+1]]``, in increasing order.  About 64 segments per slice,
        so finding the segments live at one instant costs the few slices' segments, not
        all of them (records at a station look up one instant per crossing: without the
        slices that was quadratic in the length of the run)."""
        if "buckets" not in self._cache:
            a = self._segments()
            n, t_end = len(a["t0"]), self.scene.t_end
            slices = max(1, min(n // 64, 1 << 16))
            width = t_end / slices
            if not (np.all(np.isfinite(a["t0"])) and np.all(np.isfinite(a["t1"]))):
                slices, width = 1, math.inf  # one slice holding every segment
            first = np.clip(np.floor(a["t0"] / width), 0, slices - 1).astype(np.int64)
            last = np.clip(np.floor(np.minimum(a["t1"], t_end) / width), 0,
                           slices - 1).astype(np.int64)
            counts = np.maximum(last - first + 1, 0)
            starts = np.cumsum(counts) - counts
            offsets = np.arange(counts.sum()) - np.repeat(starts, counts)
            bucket = np.repeat(first, counts) + offsets
            order = np.argsort(bucket, kind="stable")
            index = np.repeat(np.arange(n), counts)[order]
            start = np.searchsorted(bucket[order], np.arange(slices + 1))
            self._cache["buckets"] = (index, start, width)
        return self._cache["buckets"]

    def _live_at(self, t: float) -> tuple[np.ndarray, np.ndarray]:
        """The segments live at time ``t`` (s), in increasing order, and their positions
        (m) then: ``pos`` is indexed like the segments, set only at the live ones."""
        a = self._segments()
        index, start, width = self._time_buckets()
        k = min(max(int(t / width), 0), len(start) - 2) if math.isfinite(width) else 0
        near = index[start[k]:start[k + 1]]
        t0, t1 = a["t0"][near], a["t1"][near]
        live = near[(t0 <= t) & ((t1 > t) | (t1 >= self.scene.t_end))]
        pos = np.empty(len(a["t0"]))
        speed, x0 = a["speed"][live], a["x0"][live]
        pos[live] = np.where(speed == 0.0, x0, x0 + speed * (t - a["t0"][live]))
        return live, pos

    def _region_id_at(self, x: float, t: float) -> int:
        a = self._segments()
        t = min(max(t, 0.0), self.scene.t_end)
        live, pos = self._live_at(t)
        right = a["right"][live] >= 0
        candidates = live[(pos[live] <= x) & right]
        if candidates.size == 0:
            candidates = live[right]
            best = candidates[np.argmin(pos[candidates])]
        else:
            best = candidates[self._spatial_order(candidates, pos, t)[-1]]
        return int(a["right"][best])

    def region_at(self, x: float, t: float) -> RegionRecord:
        """The cell containing Lagrangian position ``x`` (m) at time ``t`` (s).

        On a front the cell to its right is returned (to its left at the right end).
        """
        return self.region_record(self._region_id_at(x, t))

    def state_at(self, x: float, t: float) -> State:
        """State (stress Pa, velocity m/s, volume, energy) at ``(x, t)``, read continuously
        inside simple waves and lattices (``characteristics.reconstruct``).  ``x`` is
        anything ``station`` takes, ``t`` (s, or a string with a unit) lies in
        ``[0, t_end]``; otherwise ``SceneError``."""
        x, t = self.station(x), self._instant(t)
        ring = next((r for r in self.rings if r.covers(x, t)), None)
        if ring is not None:  # a free fragment ringing in closed form
            return ring.state(x, t)
        profile = self._profile_near(x, t)
        if profile is None:
            return self._region_state(self._region_id_at(x, t))
        return _state_in(profile, x)

    def cell_state_at(self, x: float, t: float) -> State:
        """The state of the cell the engine kept at ``(x, t)`` (no reconstruction)."""
        return self._region_state(self._region_id_at(x, t))

    def _crossings(self, x: float) -> tuple[np.ndarray, np.ndarray]:
        """Times (s) at which moving segments pass the station ``x`` (m), and which."""
        a = self._segments()
        moving = a["speed"] != 0.0
        with np.errstate(divide="ignore", invalid="ignore"):
            tc = a["t0"] + (x - a["x0"]) / np.where(moving, a["speed"], 1.0)
        ok = moving & (tc >= a["t0"] - 1e-18) & (tc <= a["t1"] + 1e-18)
        ok &= tc < self.scene.t_end
        index = np.nonzero(ok)[0]
        order = np.argsort(tc[index], kind="stable")
        return tc[index][order], index[order]

    def crossing_times(self, x: float) -> np.ndarray:
        """Times (s) at which a moving front passes the station ``x`` (m)."""
        return np.unique(self._crossings(x)[0])

    def arrivals(self, at) -> tuple[np.ndarray, np.ndarray]:
        """The waves that pass the station ``at`` (as ``history``): their times (s), in
        order, and lineages (``Front.lineage``: the wave each descends from)."""
        times, index = self._crossings(self.station(at))
        return times, self._segments()["lineage"][index]

    def station(self, at) -> float:
        """Lagrangian position (m) of ``at`` in the scene (``station``)."""
        return station(self.scene, at)

    def _instant(self, t) -> float:
        """``t`` (s, or a string with a unit) checked to lie in ``[0, t_end]`` (with a
        rounding allowance of 1e-12 of ``t_end``); raises ``SceneError`` naming ``t``."""
        t_end = self.scene.t_end
        value = to_si(t, "time", "t")
        if not -1e-12 * t_end <= value <= (1.0 + 1e-12) * t_end:
            raise SceneError(f"t: {value * 1e6:.6g} us is outside the run "
                             f"(0 to {t_end * 1e6:.6g} us)")
        return min(max(value, 0.0), t_end)

    def history(self, at) -> History:
        """The record at a station: ``at`` is ``"left"``, ``"right"``, a probe name or X (m).

        Continuous inside simple waves and lattices, a jump at each shock (see
        ``History``).
        """
        x = self.station(at)
        t_end = self.scene.t_end
        times, index = self._crossings(x)
        groups, cells = self._groups_along(times, index, lambda t: self._region_id_at(x, t),
                                           t_end, 1e-12 * t_end)
        coords, states = knots([g[0] for g in groups], [g[1] for g in groups], cells)
        coords = [0.0, *coords, t_end]
        states = [cells[0].state, *states, cells[-1].state]
        coords, states = ring_records.splice(
            self.rings, x, coords, states,
            lambda t: self._region_state(self._region_id_at(x, t * (1.0 - 1e-12))))
        end = self.scene.left if x == 0.0 else self.scene.right if x == self.scene.length \
            else None
        if end is not None:
            apart = self._piston_gaps("left" if x == 0.0 else "right")
            states = [_held(end, t, s, apart) for t, s in zip(coords, states, strict=True)]
        return _history(coords, states, t_end)

    def _piston_gaps(self, side: str) -> list[tuple[float, float]]:
        """The ``(t_open, t_close)`` intervals (s) during which a piston boundary was apart
        from its face (``fronttrack.interactions._piston``), or a stress boundary had torn
        the material off it (``_traction``: from the tear on)."""
        intervals, opened = [], None
        for t, kind in self.front_table.site_history(FrontKind.BOUNDARY, side):
            if kind == FrontKind.GAP:
                opened = t
            elif opened is not None:
                intervals.append((opened, t))
                opened = None
        if opened is not None:
            intervals.append((opened, math.inf))
        return intervals

    def cell_history(self, at) -> History:
        """The record of the cells the engine kept at a station: constant pieces."""
        x = self.station(at)
        t_end = self.scene.t_end
        resolution = 1e-12 * t_end
        times = []
        for t in self.crossing_times(x):
            if t > resolution and (not times or t - times[-1] > resolution):
                times.append(float(t))
        edges = [0.0, *times, t_end]
        starts, states = [], []
        for t0, t1 in zip(edges[:-1], edges[1:], strict=True):
            if t1 <= t0:
                continue
            state = self.cell_state_at(x, 0.5 * (t0 + t1))
            if states and state == states[-1]:
                continue
            starts.append(t0)
            states.append(state)
        return History(t=np.array(starts), states=states, ends=list(states), stop=t_end)

    def _groups_along(self, coords, index, region_id_at, stop, resolution):
        """Crossings grouped by coordinate, and the cells between the groups."""
        a = self._segments()
        groups = []
        for c, i in zip(coords.tolist(), index.tolist(), strict=True):
            if c <= resolution:
                continue
            crossing = Crossing(bool(a["ray"][i]) and not math.isnan(a["invariant"][i]),
                                int(a["family"][i]), float(a["invariant"][i]))
            if groups and c - groups[-1][0] <= resolution:
                groups[-1][1].append(crossing)
            else:
                groups.append((c, [crossing]))
        edges = [0.0, *(g[0] for g in groups), stop]
        cells = [self._region_cell(region_id_at(0.5 * (lo + hi)))
                 for lo, hi in zip(edges[:-1], edges[1:], strict=True)]
        return groups, cells

    def probe_histories(self) -> dict:
        """Histories at every probe of the scene, by probe name."""
        return {p.name: self.history(p.at) for p in self.scene.probes}

    def cells_at(self, t: float) -> list[tuple[float, float, RegionRecord]]:
        """``(x_left, x_right, region)`` intervals of the cells the engine kept at time
        ``t`` (s): the piecewise-constant solution behind ``profile``."""
        return [(x0, x1, self.region_record(rid)) for x0, x1, rid in self._cell_ids_at(t)]

    def _cell_ids_at(self, t: float) -> list[tuple[float, float, int]]:
        """``(x_left, x_right, region_id)`` intervals of the cells at time ``t`` (s)."""
        a = self._segments()
        t = min(max(t, 0.0), self.scene.t_end)
        index, pos = self._live_at(t)
        order = index[self._spatial_order(index, pos, t)]
        intervals = []
        for i, j in zip(order[:-1], order[1:], strict=True):
            if a["right"][i] >= 0 and pos[j] > pos[i]:
                intervals.append((float(pos[i]), float(pos[j]), int(a["right"][i])))
        return intervals

    def profile(self, t: float) -> History:
        """The profile at time ``t`` (s) along Lagrangian X (the ``History`` coordinate is X,
        m): continuous inside simple waves and lattices, a jump at shocks and contacts."""
        t = self._instant(t)
        key = ("profile", t)
        if key not in self._cache:
            self._cache[key] = self._build_profile(t)
        return self._cache[key]

    def _build_profile(self, t: float) -> History:
        a = self._segments()
        cells = self._cell_ids_at(t)
        length = self.scene.length
        live, pos = self._live_at(t)
        region_ids = [rid for _, _, rid in cells]
        coords = [x_lo for x_lo, _, _ in cells[1:]]
        groups = []
        for c in coords:
            near = live[np.abs(pos[live] - c) <= POSITION_ROUNDING * length]
            groups.append([Crossing(bool(a["ray"][i]) and not math.isnan(a["invariant"][i]),
                                    int(a["family"][i]), float(a["invariant"][i]))
                           for i in near] or [Crossing(False)])
        members = [self._region_cell(rid) for rid in region_ids]
        xs, states = knots(coords, groups, members)
        xs = [0.0, *xs, length]
        states = [members[0].state, *states, members[-1].state]
        return _history(xs, states, length)

    def _profile_near(self, x: float, t: float) -> History | None:
        return self.profile(t)

    # --- derived quantities ---------------------------------------------------------------
    def eulerian_position(self, at, t: float) -> float:
        """Eulerian position (m) at time ``t`` (s) of the material point at station ``at``.

        ``x(X, t) = x(X, 0) + int_0^t u dt``, with ``x(X, 0) = int_0^X v/v0 dX`` so that a
        pre-stressed layer starts compressed.
        """
        x = self.station(at)
        hist = self.history(at)
        return self.initial_eulerian(x) + hist.integral(hist.u, t, hist.u_end)

    def initial_eulerian(self, x: float) -> float:
        """Eulerian position (m) at ``t = 0`` of the Lagrangian point ``x`` (m)."""
        total = 0.0
        for x0, x1, rid in self._cell_ids_at(0.0):
            if x0 >= x:
                break
            total += (min(x1, x) - x0) * self._region_state(rid).v / self._material_of(rid).v0
        return total

    def max_tension(self) -> dict | None:
        """Largest tension reached in any cell: ``{"sigma", "x", "t"}`` (Pa, m, s).

        ``None`` when no cell is in tension beyond the negligible stress (a
        rounding-level tension of a few ulps is not a tension).
        """
        negligible = self.accuracy_report.get("negligible_stress", 0.0)
        if self.min_stress is None or self.min_stress[0] >= -negligible:
            return None
        sigma, x, t = self.min_stress
        return {"sigma": sigma, "x": x, "t": t}

    def conservation(self, t: float | None = None) -> dict:
        """Momentum and energy balance at time ``t`` (default ``t_end``), per unit area.

        Computed on the cells the engine advanced (see the module docstring).  Returns
        the totals at 0 and ``t``, the boundary impulse and work, and the residuals
        ``momentum_error`` and ``energy_error`` (absolute) with their relative sizes:
        momentum against the largest of the momentum content ``sum m |u|`` at 0 and
        ``t`` and the impulse (``momentum_scale``), energy against the largest of the
        energy content ``sum m (|e| + u^2/2)`` at 0 and ``t`` and the work
        (``energy_scale``).
        """
        t = self.scene.t_end if t is None else t

        def totals(pieces):
            p = e = content = energy_content = 0.0
            for mass, s in pieces:
                p += mass * s.u
                content += mass * abs(s.u)
                e += mass * (s.e + 0.5 * s.u * s.u)
                energy_content += mass * (abs(s.e) + 0.5 * s.u * s.u)
            return p, e, content, energy_content

        p0, e0, content0, energy0 = totals((layer.material.rho0 * layer.thickness, state)
                        for layer, state in zip(self.scene.layers, self.initial_states,
                                                strict=True))
        cells = [(self._material_of(rid).rho0 * (x1 - x0), self._region_state(rid))
                 for x0, x1, rid in self._cell_ids_at(t)]
        p1, e1, content1, energy1 = totals(cells)
        left, right = self.cell_history("left"), self.cell_history("right")
        impulse = left.integral(left.sigma, t) - right.integral(right.sigma, t)
        work = (left.integral(left.sigma * left.u, t)
                - right.integral(right.sigma * right.u, t))
        # momentum is measured against its content (sum of mass |u|): plates moving
        # towards each other can carry almost no net momentum
        kinetic_scale = max(content0, content1, abs(impulse), 1e-300)
        # energy against its content (sum of mass (|e| + u^2/2)): an explosive's total
        # energy stays zero while the heat of detonation turns into motion and heat
        energy_scale = max(energy0, energy1, abs(work), 1e-300)
        return {
            "t": t,
            "momentum": (p0, p1), "impulse": impulse,
            "momentum_error": p1 - p0 - impulse,
            "momentum_relative_error": abs(p1 - p0 - impulse) / kinetic_scale,
            "momentum_scale": kinetic_scale,
            "energy": (e0, e1), "work": work,
            "energy_error": e1 - e0 - work,
            "energy_relative_error": abs(e1 - e0 - work) / energy_scale,
            "energy_scale": energy_scale,
            "mass": sum(m for m, _ in cells),
        }

    def _material_of(self, region_id: int):
        found = self._find(region_id)
        return self.region_table.material(found) if not isinstance(found, tuple) else \
            found[0].material

    # --- export -------------------------------------------------------------------------
    def to_dict(self, probes: bool = True, polygons: bool = True) -> dict:
        """A JSON-ready document of the solution (SI units); ``polygons=False`` leaves
        out the regions' X–t polygons (most of a large run's document)."""
        return {key: list(value) if isinstance(value, Iterator) else value
                for key, value in self._document(probes, polygons)}

    def write_json(self, stream: TextIO, probes: bool = True, progress=None,
                   polygons: bool = True) -> None:
        """Write ``to_dict(probes, polygons)`` as compact JSON to the text ``stream``, one
        record at a time (the whole document is never held in memory).

        ``progress``, if given, is called as ``progress(done, total)`` with the records
        (regions, fronts and events) written so far, every ``JSON_PROGRESS_STEP``.
        """
        total = self.stats["regions"] + self.stats["fronts"] + len(self.events)
        done = 0
        stream.write("{")
        for index, (key, value) in enumerate(self._document(probes, polygons)):
            stream.write(("," if index else "") + json.dumps(key) + ":")
            if not isinstance(value, Iterator):
                stream.write(json.dumps(value, separators=(",", ":"), default=_json_number))
                continue
            stream.write("[")
            for count, item in enumerate(value):
                stream.write(("," if count else "") + json.dumps(item, separators=(",", ":"),
                                                                 default=_json_number))
                done += 1
                if progress is not None and done % JSON_PROGRESS_STEP == 0:
                    progress(done, total)
            stream.write("]")
        stream.write("}")
        if progress is not None:
            progress(total, total)

    def _document(self, probes: bool, polygons: bool = True
                  ) -> Iterator[tuple[str, object]]:
        """The keys of the JSON document with their values, in order; the long lists
        (regions, fronts, events) as iterators of their entries.  Regions carry the
        reader-facing ``number`` of the figures beside their internal ``id``."""
        numbers = region_numbers(self)
        yield "title", self.scene.title
        yield "t_end", self.scene.t_end
        yield "regions", (_region_entry(r, numbers.get(r.id), polygons)
                          for r in self.region_records())
        yield "fronts", map(_front_entry, self.front_records())
        yield "events", map(_event_entry, self.events)
        yield "spall", [{"x": s.x, "t": s.t, "tension": s.tension, "strength": s.strength,
                         "layer": s.layer, "zone": list(s.zone) if s.zone else None}
                        for s in self.spalls]
        yield "max_tension", self.max_tension()
        yield "stats", self.stats
        yield "accuracy", self.accuracy_report
        if probes:
            yield "probes", {
                name: {"at": _probe_at(p), "t": h.t.tolist(), "sigma": h.sigma.tolist(),
                       "u": h.u.tolist(), "sigma_end": h.sigma_end.tolist(),
                       "u_end": h.u_end.tolist()} | _window_fields(self, p)
                for (name, h), p in zip(self.probe_histories().items(), self.scene.probes,
                                        strict=True)
            }


JSON_PROGRESS_STEP = 10_000
"""Records of the JSON document written between two progress reports."""


def _region_entry(r: RegionRecord, number: int | None, polygon: bool = True) -> dict:
    """A region's JSON entry: its figure ``number`` (``None`` if not numbered), state (SI),
    temperature (K) and, with ``polygon``, its X–t polygon."""
    s = r.state
    temperature = r.material.temperature(s.v, s.e) if math.isfinite(s.v) else None
    return {
        "number": number, "id": r.id, "layer": r.layer, "material": r.material.name,
        "sigma": s.sigma, "u": s.u, "v": _finite_or_none(s.v),
        "rho": 1.0 / s.v if s.v > 0 else None, "e": s.e,
        "plastic_strain": s.plastic_strain,
        "temperature": temperature, "t_start": r.t_start, "t_end": r.t_end,
        "in_fan": r.in_fan,
    } | ({"polygon": [list(p) for p in r.polygon()]} if polygon else {})


def _front_entry(f: FrontRecord) -> dict:
    """A front's JSON entry: kind, path in X–t and neighbouring regions."""
    return {
        "id": f.id, "kind": str(f.kind), "x0": f.x0, "t0": f.t0, "x1": f.x1, "t1": f.t1,
        "speed": f.speed, "direction": f.direction, "jump": f.jump, "wave": f.wave,
        "fan": f.fan, "ray_index": f.ray_index, "ray_count": f.ray_count,
        "invariant": _finite_or_none(f.invariant),
        "bond": f.bond or None, "left_region": f.left_region,
        "right_region": f.right_region_id,
        "kind_history": [[t, str(k)] for t, k in f.history],
        "earlier_right_regions": [list(p) for p in f.earlier_regions],
    }


def _event_entry(e: EventRecord) -> dict:
    """An event's JSON entry: time, place, kind and the fronts in and out."""
    return {"t": e.t, "x": e.x, "kind": str(e.kind), "incoming": e.incoming,
            "outgoing": e.outgoing, "site": e.site, "nodes": e.nodes}


def _held(boundary, t: float, state: State, apart=()) -> State:
    """A state at an end of the stack with the quantity its boundary prescribes held
    exactly (the reconstruction between two rays reaching a free surface gives its zero
    stress only to rounding).  While a piston is ``apart`` from its face (``(t_open,
    t_close)`` intervals, s), the face is free; a face a stress tore off its load
    (``fronttrack.interactions._traction``) takes compression only."""
    separated = any(a <= t < b for a, b in apart)
    if boundary.kind in ("free", "stress"):
        value = boundary.value_at(t)
        value = max(value, 0.0) if separated else value
        return state if state.sigma == value else dataclasses.replace(state, sigma=value)
    if separated:
        return state if state.sigma == 0.0 else dataclasses.replace(state, sigma=0.0)
    value = boundary.value_at(t)
    return state if state.u == value else dataclasses.replace(state, u=value)


def _state_in(record: History, x: float) -> State:
    """The state of a record at coordinate ``x`` (interpolated inside its piece)."""
    k = int(np.clip(np.searchsorted(record.t, x, side="right") - 1, 0, len(record.t) - 1))
    a, b = record.states[k], record.ends[k]
    if a == b:
        return a
    right = record.t[k + 1] if k + 1 < len(record.t) else record.stop
    f = (x - record.t[k]) / (right - record.t[k]) if right > record.t[k] else 0.0
    f = min(max(f, 0.0), 1.0)
    return State(sigma=a.sigma + f * (b.sigma - a.sigma), u=a.u + f * (b.u - a.u),
                 v=a.v + f * (b.v - a.v), e=a.e + f * (b.e - a.e),
                 plastic_strain=a.plastic_strain)


def _json_number(value):
    """A numpy scalar (a counter incremented by a numpy comparison, a float64 position)
    as the Python number JSON writes; anything else is a bug, raised as JSON would."""
    if isinstance(value, np.generic):
        return value.item()
    raise TypeError(f"Object of type {type(value).__name__} is not JSON serializable")


def _finite_or_none(value: float):
    return value if math.isfinite(value) else None


def _points(positions: np.ndarray, tolerance: float) -> np.ndarray:
    """The rank of each of ``positions`` (m) among the points they make, positions
    closer than ``tolerance`` (m) to the next one in order counting as one point."""
    order = np.argsort(positions, kind="stable")
    ranks = np.empty(len(positions), dtype=np.int64)
    ranks[order] = np.cumsum(np.diff(positions[order], prepend=-np.inf) > tolerance)
    return ranks


def station(scene, at) -> float:
    """Lagrangian position (m) of a probe location in ``scene``: ``"left"``, ``"right"``,
    the name of one of its probes, or X (metres, or a string with a unit: ``"2 mm"``).

    Raises ``SceneError`` for a name that is neither a probe nor a length, and for an
    X outside the stack (beyond a rounding allowance of 1e-12 of its length).
    """
    if at == "left":
        return 0.0
    if at == "right":
        return scene.length
    probe = next((p for p in scene.probes if isinstance(at, str) and p.name == at), None)
    if probe is not None:
        return station(scene, probe.at)
    length = scene.length
    try:
        x = to_si(at, "length", "at")
    except SceneError:
        names = ", ".join(repr(p.name) for p in scene.probes) or "none"
        raise SceneError(f"at: expected 'left', 'right', a probe name (probes: {names}) "
                         f"or X such as 1e-3 or \"1 mm\", got {at!r}") from None
    if not -1e-12 * length <= x <= (1.0 + 1e-12) * length:
        raise SceneError(f"at: X = {x * 1e3:.6g} mm is outside the stack "
                         f"(0 to {length * 1e3:.6g} mm)")
    return min(max(x, 0.0), length)


def _window_fields(solution: Solution, probe) -> dict:
    """The interferometer record of a probe behind an optical window (``{}`` without one):
    samples ``t`` (s) of the true ``u`` and apparent ``u_apparent`` velocity (m/s)."""
    if probe.window is None:
        return {}
    record = window_record(solution, probe.name)
    return {"window": {"name": record.window.name, "a": record.window.a,
                       "b": record.window.b, "source": record.window.source,
                       "t": record.t.tolist(), "u": record.u.tolist(),
                       "u_apparent": record.u_apparent.tolist()}}


def _probe_at(probe):
    return probe.at if isinstance(probe.at, str) else float(probe.at)
