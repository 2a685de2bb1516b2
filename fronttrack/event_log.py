"""The log of a run's events, kept as packed arrays.

A run logs one ``EventRecord`` per interaction (time, place, kind, the ids of the fronts
in and out).  As Python objects (a record, two lists, a float and an int object per
number) an event costs about 400 B; packed into ``array.array`` columns it costs about
70 B (8 B per number), and the records are rebuilt when read.
"""

from __future__ import annotations

from array import array
from collections.abc import Iterator, Sequence
from dataclasses import dataclass

NO_SITE = -1
"""``site`` of an event without a site (front ids are >= 0)."""


@dataclass(frozen=True, slots=True)
class EventRecord:
    """One interaction: time (s), position (m), kind, ids of the fronts in and out;
    ``nodes`` counts the nodes of a lattice (one event)."""

    t: float
    x: float
    kind: str
    incoming: list
    outgoing: list
    site: int | None = None
    nodes: int = 0


class EventLog(Sequence):
    """Events in the order they were logged: ``append`` an ``EventRecord``, read records
    back by index or by iterating (each read builds a new record, equal to the one
    appended)."""

    def __init__(self):
        self._t, self._x = array("d"), array("d")
        self._kind, self._site, self._nodes = array("b"), array("q"), array("q")
        self._kinds: list = []
        self._kind_codes: dict = {}  # kind -> its index in _kinds
        self._ids = array("q")  # incoming then outgoing fronts of each event
        self._starts = array("q", [0])  # event k's ids: _starts[k] to _starts[k + 1]
        self._splits = array("q")  # where its outgoing ids begin

    def append(self, event: EventRecord) -> None:
        self.log(event.t, event.x, event.kind, event.incoming, event.outgoing, event.site,
                 event.nodes)

    def log(self, t: float, x: float, kind: str, incoming, outgoing, site: int | None = None,
            nodes: int = 0) -> None:
        """Append the event of these fields (those of ``EventRecord``) without making the
        record (the engine logs one per event)."""
        code = self._kind_codes.get(kind)
        if code is None:
            code = self._kind_codes[kind] = len(self._kinds)
            self._kinds.append(kind)
        self._t.append(t)
        self._x.append(x)
        self._kind.append(code)
        self._site.append(NO_SITE if site is None else site)
        self._nodes.append(nodes)
        ids = self._ids
        ids.extend(incoming)
        self._splits.append(len(ids))
        ids.extend(outgoing)
        self._starts.append(len(ids))

    def __len__(self) -> int:
        return len(self._t)

    def __getitem__(self, index):
        if isinstance(index, slice):
            return [self[k] for k in range(*index.indices(len(self)))]
        if index < 0:
            index += len(self)
        if not 0 <= index < len(self):
            raise IndexError("event index out of range")
        start, split, end = self._starts[index], self._splits[index], self._starts[index + 1]
        site = self._site[index]
        return EventRecord(t=self._t[index], x=self._x[index],
                           kind=self._kinds[self._kind[index]],
                           incoming=self._ids[start:split].tolist(),
                           outgoing=self._ids[split:end].tolist(),
                           site=None if site == NO_SITE else site, nodes=self._nodes[index])

    def __iter__(self) -> Iterator[EventRecord]:
        return (self[k] for k in range(len(self)))
