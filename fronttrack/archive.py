"""Finished fronts and regions, kept as columns of numbers.

A long run makes about two fronts and one region per event.  As the engine's objects
(``fronttrack.fronts.Front``, with its links and lists, and ``Region``, with its lists of
``(X, t)`` vertex tuples and its ``State``) they cost about 1.4 kB per event, and a run of
10^5 events would hold hundreds of megabytes.  Once a front has died and a region has
ended nothing in the engine changes them again, and the diagram, the records and the
outputs need only their numbers: ``compact`` moves them into a ``FrontTable`` and a
``RegionTable`` (float64, int32 and int8 columns: a front in 92 B, a region in 105 B and
16 B per vertex of its polygon) and the engine drops the objects.  The engine compacts
whenever it holds ``COMPACT_BATCH`` front objects more than twice the ones it kept last
time, and once more at the end: a ``Solution`` reads only the tables.

Rows are kept in the order of the ids (the order in which the engine made the objects),
so records come out in the order they always had.
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from itertools import chain
from operator import attrgetter

import numpy as np

from materials import State

from .fronts import FrontRecord, RegionRecord, polygon_of
from .kinds import FrontKind

COMPACT_BATCH = 4096
"""The engine compacts when it holds this many front objects more than twice the number
it kept after its last compaction (the live ones): each object is copied once, which
costs about a tenth of the time the engine took to make it (``benchmarks/MEMORY.md``),
and the objects waiting to be copied stay a few megabytes."""

ID = np.int32
"""Ids and counts: an id numbers an object the engine made, far below 2^31 in any run
that fits in memory (a live ``Front`` alone takes about 500 B)."""

_FRONT_FLOATS = ("x0", "t0", "x1", "t1", "speed", "jump", "invariant")
_FRONT_INTS = {"id": ID, "direction": np.int8, "wave": ID, "fan": ID, "ray_index": ID,
               "ray_count": ID, "left_region": ID, "right_region_id": ID, "lineage": ID}
_FRONT_CODES = ("kind", "bond", "side")
_STATE_FIELDS = ("sigma", "u", "v", "e", "plastic_strain")
_REGION_FLOATS = ("t_start", "t_end", *_STATE_FIELDS)
_REGION_INTS = {"id": ID, "layer": ID}
_REGION_CODES = ("material", "table")
_UNKNOWN_INVARIANTS = (math.nan, math.nan)


class _Codes:
    """Distinct values numbered in order of first sight: equal values share a code, or,
    with ``by_identity``, only the same object does (materials, isentrope tables)."""

    def __init__(self, by_identity: bool = False):
        self.values: list = []
        self._index: dict = {}
        self._by_identity = by_identity

    def code(self, value) -> int:
        """The code of ``value`` (a new one if it is new)."""
        return int(self.codes([value])[0])

    def codes(self, values: list) -> np.ndarray:
        """The code of each of ``values`` (new ones numbered as they come)."""
        index = self._index
        keys = list(map(id, values)) if self._by_identity else values
        found = list(map(index.get, keys))
        for k in [k for k, code in enumerate(found) if code is None]:
            found[k] = index.get(keys[k])
            if found[k] is None:
                found[k] = index[keys[k]] = len(self.values)
                self.values.append(values[k])
        return np.fromiter(found, ID, len(found))


def _column(objects: list, name: str, dtype) -> np.ndarray:
    """The attribute ``name`` of each object as a column of ``dtype``; ``None`` as NaN in
    a float column, as -1 in an integer one (ids are >= 0)."""
    try:
        return np.fromiter(map(attrgetter(name), objects), dtype, len(objects))
    except TypeError:  # a None among them
        missing = math.nan if np.dtype(dtype).kind == "f" else -1
        return np.array([missing if value is None else value
                         for value in map(attrgetter(name), objects)], dtype)


def _floats(objects: list, names: tuple) -> dict[str, np.ndarray]:
    """The attributes ``names`` of each object as float64 columns (``None`` as NaN)."""
    return {name: _column(objects, name, float) for name in names}


def _ints(objects: list, dtypes: dict) -> dict[str, np.ndarray]:
    """The attributes named in ``dtypes`` of each object as integer columns of those
    types (``None`` as -1)."""
    return {name: _column(objects, name, dtype) for name, dtype in dtypes.items()}


ROWS_PER_CHUNK = 4096
"""Rows turned into Python numbers at a time when records are read one by one."""


def _chunked_rows(columns: dict[str, np.ndarray], names: tuple) -> Iterator[tuple]:
    """The rows of ``columns`` as tuples of Python numbers (in the order of ``names``),
    converted ``ROWS_PER_CHUNK`` at a time."""
    for start in range(0, len(columns["id"]), ROWS_PER_CHUNK):
        stop = start + ROWS_PER_CHUNK
        yield from zip(*(columns[name][start:stop].tolist() for name in names), strict=True)


def _optional(value: float) -> float | None:
    return None if math.isnan(value) else float(value)


def _optional_int(value: int) -> int | None:
    return None if value < 0 else int(value)


class _Columns:
    """Columns filled in blocks, merged (and ordered by ``id``) when read; ``empty``: the
    columns of no rows."""

    def __init__(self, empty: dict[str, np.ndarray]):
        self._blocks: list[dict[str, np.ndarray]] = []
        self._empty = empty

    def _append(self, block: dict[str, np.ndarray]) -> None:
        self._blocks.append(block)

    @property
    def columns(self) -> dict[str, np.ndarray]:
        if len(self._blocks) != 1:
            self._blocks = [self._merged(self._blocks)]
        return self._blocks[0]

    def _merged(self, blocks: list[dict[str, np.ndarray]]) -> dict[str, np.ndarray]:
        if not blocks:
            return dict(self._empty)
        order = np.argsort(np.concatenate([b["id"] for b in blocks]), kind="stable")
        merged = {}
        for name in list(blocks[0]):  # one column at a time: little more than the blocks
            merged[name] = np.concatenate([b.pop(name) for b in blocks])[order]
        return merged

    def __len__(self) -> int:
        return sum(len(b["id"]) for b in self._blocks)


class FrontTable(_Columns):
    """Finished fronts: one row each, the fields of a ``FrontRecord`` (SI units).

    Floats ``x0``, ``t0``, ``x1``, ``t1``, ``speed``, ``jump``, ``invariant`` (``None`` as
    NaN); integers ``id``, ``direction``, ``wave``, ``fan``, ``ray_index``, ``ray_count``,
    ``left_region``, ``right_region_id``, ``lineage`` (``None`` as -1); ``kind``,
    ``bond`` and ``side`` as codes into ``codes[name].values``.  The few fronts with a
    ``history`` or ``earlier_regions`` keep them in dictionaries by front id.
    """

    def __init__(self):
        super().__init__({name: np.empty(0) for name in _FRONT_FLOATS}
                         | {name: np.empty(0, dtype) for name, dtype in _FRONT_INTS.items()}
                         | {name: np.empty(0, np.int8) for name in _FRONT_CODES})
        # kinds are enum members (hashed in Python): told apart by identity
        self.codes = {name: _Codes(by_identity=name == "kind") for name in _FRONT_CODES}
        self.history: dict[int, tuple] = {}
        self._earlier: list[tuple[np.ndarray, np.ndarray, np.ndarray]] = []

    def add(self, fronts: list) -> None:
        """Copy ``fronts`` (``Front`` objects that will not change again) into rows."""
        if not fronts:
            return
        block = _floats(fronts, _FRONT_FLOATS) | _ints(fronts, _FRONT_INTS)
        for name, codes in self.codes.items():
            block[name] = codes.codes(list(map(attrgetter(name), fronts))).astype(np.int8)
        earlier = [(f.id, t, region) for f in fronts if f.earlier_regions
                   for t, region in f.earlier_regions]
        if earlier:
            owner, times, regions = zip(*earlier, strict=True)
            self._earlier.append((np.array(owner, ID), np.array(times),
                                  np.array(regions, ID)))
        self.history.update((f.id, tuple(f.history)) for f in fronts if f.history)
        self._append(block)

    def earlier_regions(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Every front's ``earlier_regions`` as three arrays: the front's id, the time
        (s) until which the region was on its right and that region's id; in order of
        the front ids, each front's in time order."""
        if len(self._earlier) != 1:
            parts = self._earlier or [(np.empty(0, ID), np.empty(0), np.empty(0, ID))]
            owner = np.concatenate([p[0] for p in parts])
            order = np.argsort(owner, kind="stable")
            self._earlier = [(owner[order], np.concatenate([p[1] for p in parts])[order],
                              np.concatenate([p[2] for p in parts])[order])]
        return self._earlier[0]

    def count(self, kind: FrontKind) -> int:
        """How many fronts of ``kind`` the table holds."""
        values = self.codes["kind"].values
        if kind not in values:
            return 0
        return int(np.count_nonzero(self.columns["kind"] == values.index(kind)))

    def records(self) -> Iterator[FrontRecord]:
        """The rows as frozen records, in id order."""
        c = self.columns
        kinds, bonds, sides = (self.codes[name].values for name in _FRONT_CODES)
        owner, times, regions = self.earlier_regions()
        bounds = np.searchsorted(owner, c["id"]).tolist() + [len(owner)]
        times, regions = times.tolist(), regions.tolist()
        names = (*_FRONT_FLOATS, *_FRONT_INTS, *_FRONT_CODES)
        for row, (x0, t0, x1, t1, speed, jump, invariant, front_id, direction, wave, fan,
                  ray_index, ray_count, left, right, lineage, kind, bond, side) in enumerate(
                _chunked_rows(c, names)):
            lo, hi = bounds[row], bounds[row + 1]
            yield FrontRecord(
                id=front_id, kind=kinds[kind], x0=x0, t0=t0, x1=_optional(x1),
                t1=_optional(t1), speed=speed, direction=direction, jump=jump,
                wave=_optional_int(wave), fan=_optional_int(fan), ray_index=ray_index,
                ray_count=ray_count, invariant=invariant, bond=bonds[bond], side=sides[side],
                left_region=_optional_int(left), right_region_id=_optional_int(right),
                history=self.history.get(front_id, ()),
                earlier_regions=tuple(zip(times[lo:hi], regions[lo:hi], strict=True)),
                lineage=lineage)

    def site_history(self, kind: FrontKind, side: str) -> tuple:
        """The ``(t, kind)`` history of the first front of ``kind`` on ``side``."""
        c = self.columns
        kinds, sides = self.codes["kind"].values, self.codes["side"].values
        for row in range(len(c["id"])):
            if kinds[c["kind"][row]] == kind and sides[c["side"][row]] == side:
                return self.history.get(int(c["id"][row]), ())
        raise KeyError(f"no {kind} front on side {side!r}")

    def segments(self) -> dict[str, np.ndarray]:
        """One straight segment per front and per region on its right (its
        ``earlier_regions`` split it): ``x0``, ``t0``, ``t1``, ``speed``, ``right`` (region id,
        -1 for none), ``ray``, ``family``, ``invariant``, ``lineage``.  Fronts that never
        lasted (``t1 < t0``) have none."""
        c = self.columns
        valid = ~(c["t1"] < c["t0"]) & ~np.isnan(c["t1"])
        owner, times, regions = self.earlier_regions()
        rows = np.searchsorted(c["id"], owner)  # the row of each earlier region's front
        lasted = valid[rows]
        rows, times, regions = rows[lasted], times[lasted], regions[lasted]
        counts = valid.astype(np.int64) + np.bincount(rows, minlength=len(valid))
        row = np.repeat(np.arange(len(counts)), counts)
        start, end = c["t0"][row], c["t1"][row]
        right = c["right_region_id"][row]
        # the k-th earlier region of a front ends its k-th segment and starts the next
        first = np.cumsum(counts) - counts
        seg = first[rows] + np.arange(len(rows)) - np.searchsorted(rows, rows)
        end[seg], right[seg], start[seg + 1] = times, regions, times
        speed = c["speed"][row]
        x0 = np.where(speed == 0.0, c["x0"][row], c["x0"][row] + speed * (start - c["t0"][row]))
        return {"x0": x0, "t0": start, "t1": end, "speed": speed, "right": right,
                "ray": c["kind"][row] == self._code_of_ray(), "family": c["direction"][row],
                "invariant": c["invariant"][row], "lineage": c["lineage"][row]}

    def _code_of_ray(self) -> int:
        values = self.codes["kind"].values
        return values.index(FrontKind.RAY) if FrontKind.RAY in values else -1


class RegionTable(_Columns):
    """Finished regions: one row each (SI units).

    Floats ``t_start``, ``t_end`` (``None`` as NaN), the state ``sigma``, ``u``, ``v``,
    ``e``, ``plastic_strain`` and its Riemann invariants ``jp``, ``jm`` once known (NaN
    before); integers ``id``, ``layer``, ``in_fan``; ``material`` and ``table`` (its
    isentrope, ``fronts.UNKNOWN`` until looked up) as codes into ``codes[name].values``.
    The boundary chains are points ``chain_x``, ``chain_t`` (m, s): a row's left chain
    is the ``n_left`` points from ``chain_start``, its right chain the ``n_right`` after
    them.  A state of a model with more fields than ``State`` (``HardenedState``) is
    kept whole in ``special_states`` by region id.
    """

    def __init__(self):
        super().__init__({name: np.empty(0) for name in (*_REGION_FLOATS, "jp", "jm")}
                         | {name: np.empty(0, dtype) for name, dtype in _REGION_INTS.items()}
                         | {name: np.empty(0, ID) for name in (*_REGION_CODES, "n_left",
                                                               "n_right")}
                         | {"in_fan": np.empty(0, bool), "chain_start": np.empty(0, np.int64)})
        self.codes = {"material": _Codes(by_identity=True), "table": _Codes(by_identity=True)}
        self.special_states: dict[int, State] = {}
        self._chains: list[tuple[np.ndarray, np.ndarray]] = []
        self._points = 0
        self._row_of: np.ndarray | None = None

    def add(self, regions: list) -> None:
        """Copy ``regions`` (``Region`` objects that will not change again) into rows."""
        if not regions:
            return
        n = len(regions)
        states = list(map(attrgetter("state"), regions))
        block = _floats(regions, ("t_start", "t_end")) | _floats(states, _STATE_FIELDS)
        block |= _ints(regions, _REGION_INTS)
        block["in_fan"] = _column(regions, "in_fan", bool)
        for name, codes in self.codes.items():
            block[name] = codes.codes(list(map(attrgetter(name), regions)))
        invariants = np.array([r.invariants or _UNKNOWN_INVARIANTS for r in regions],
                              dtype=float).reshape(n, 2)
        block["jp"], block["jm"] = invariants[:, 0].copy(), invariants[:, 1].copy()
        lefts = list(map(attrgetter("left_points"), regions))
        rights = list(map(attrgetter("right_points"), regions))
        block["n_left"] = np.fromiter(map(len, lefts), ID, n)
        block["n_right"] = np.fromiter(map(len, rights), ID, n)
        sizes = block["n_left"].astype(np.int64) + block["n_right"]
        block["chain_start"] = self._points + np.cumsum(sizes) - sizes
        chains = chain.from_iterable(zip(lefts, rights, strict=True))  # left, right, ...
        points = np.fromiter(chain.from_iterable(chain.from_iterable(chains)), float,
                             2 * int(sizes.sum())).reshape(-1, 2)
        self._chains.append((points[:, 0].copy(), points[:, 1].copy()))
        self._points += len(points)
        self.special_states.update((r.id, r.state) for r in regions
                                   if type(r.state) is not State)
        self._append(block)
        self._row_of = None

    def _chain(self) -> tuple[np.ndarray, np.ndarray]:
        if len(self._chains) != 1:
            self._chains = [(np.concatenate([x for x, _ in self._chains] or [np.empty(0)]),
                             np.concatenate([t for _, t in self._chains] or [np.empty(0)]))]
        return self._chains[0]

    def row(self, region_id: int) -> int:
        """The row of region ``region_id``, or -1 if the table does not hold it."""
        if self._row_of is None:
            ids = self.columns["id"]
            self._row_of = np.full(int(ids.max()) + 1 if len(ids) else 0, -1, np.int64)
            self._row_of[ids] = np.arange(len(ids))
        return int(self._row_of[region_id]) if 0 <= region_id < len(self._row_of) else -1

    def state(self, row: int) -> State:
        c = self.columns
        special = self.special_states.get(int(c["id"][row]))
        if special is not None:
            return special
        return State(*(float(c[name][row]) for name in _STATE_FIELDS))

    def material(self, row: int):
        return self.codes["material"].values[self.columns["material"][row]]

    def table(self, row: int):
        """The row's isentrope table (``fronts.UNKNOWN`` if never looked up)."""
        return self.codes["table"].values[self.columns["table"][row]]

    def set_table(self, row: int, table) -> None:
        self.columns["table"][row] = self.codes["table"].code(table)

    def invariants(self, row: int) -> tuple[float, float] | None:
        c = self.columns
        jp = float(c["jp"][row])
        return None if math.isnan(jp) else (jp, float(c["jm"][row]))

    def set_invariants(self, row: int, invariants: tuple[float, float]) -> None:
        self.columns["jp"][row], self.columns["jm"][row] = invariants

    def chains(self, row: int) -> tuple[list, list]:
        """The left and right boundary chains of a row as ``(X, t)`` tuples (m, s)."""
        c = self.columns
        x, t = self._chain()
        start, n_left, n_right = (int(c[name][row]) for name in ("chain_start", "n_left",
                                                                   "n_right"))
        points = list(zip(x[start:start + n_left + n_right].tolist(),
                          t[start:start + n_left + n_right].tolist(), strict=True))
        return points[:n_left], points[n_left:]

    def record(self, row: int) -> RegionRecord:
        """The frozen record of a row."""
        c = self.columns
        left, right = self.chains(row)
        return RegionRecord(id=int(c["id"][row]), state=self.state(row),
                            material=self.material(row), layer=int(c["layer"][row]),
                            t_start=float(c["t_start"][row]),
                            t_end=_optional(c["t_end"][row]), in_fan=bool(c["in_fan"][row]),
                            vertices=tuple(polygon_of(left, right)),
                            birth=left[0] if left else None)

    def records(self) -> Iterator[RegionRecord]:
        """The rows as frozen records, in id order."""
        return (self.record(row) for row in range(len(self.columns["id"])))

    def densest(self) -> list[tuple[object, float]]:
        """``(material, smallest finite specific volume)`` for each material (m^3/kg)."""
        c = self.columns
        found = []
        for code, material in enumerate(self.codes["material"].values):
            v = c["v"][(c["material"] == code) & np.isfinite(c["v"])]
            if v.size:
                found.append((material, float(v.min())))
        return found


def compact(engine, final: bool = False) -> None:
    """Move the dead fronts and the ended regions of ``engine`` into its tables (all of
    them, with ``final``, once the run is over) and keep only the others as objects.

    Nothing but stale queue entries (which test ``alive`` first) refers to a dead front
    after the event that killed it, so its links are cut."""
    fronts, regions = engine.fronts, engine.regions
    done = [f for f in fronts if final or (not f.alive and f.t1 is not None)]
    ended = [r for r in regions if final or r.t_end is not None]
    engine.front_table.add(done)
    engine.region_table.add(ended)
    for front in done:  # unlinked, a dead front is freed at once, not by a later full
        front.prev = front.next = front.region_right = None  # collection of its cycles
    engine.fronts = [] if final else [f for f in fronts if f.alive or f.t1 is None]
    engine.regions = [] if final else [r for r in regions if r.t_end is None]
    engine.compact_at = 2 * len(engine.fronts) + COMPACT_BATCH
