"""Fronts and regions: the geometric objects of an X–t diagram.

Between events every front is a straight line in the Lagrangian X–t plane and every
region a constant state.  The engine keeps the live fronts in a doubly linked list
ordered by X (only neighbours can meet first); each front knows the region to its
right.  A front's neighbouring regions never change during its life, so a finished
front records the ids of the two regions it separates.

A ray is one characteristic of a simple wave (``characteristics.simple_waves``): it
carries its own Riemann invariant (``invariant``: ``J+`` for a right-going ray,
``J-`` for a left-going one); the regions beside it are cells of the wave, each
constant at the state of its middle, and ``Region.table`` is the isentrope they lie
on (``characteristics.isentrope``).  Contacts, gaps and boundaries are vertical in X–t.

The engine's ``Front`` and ``Region`` are mutable and linked; once finished they are
copied into columns (``fronttrack.archive``), from which a ``Solution`` hands out
``FrontRecord`` and ``RegionRecord``, frozen and without links.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from materials import State

from .kinds import SITE_KINDS, FrontKind

_SITES = frozenset(SITE_KINDS)

UNKNOWN = object()
"""A region's isentrope not looked up yet."""

MIXED = -1
"""The lineage of a wave that descends from waves of several lineages (see ``Front``)."""


@dataclass(eq=False, slots=True)
class Region:
    """A region of constant state, with the chains of points bounding it.

    ``left_points`` and ``right_points`` are ``(X, t)`` vertices (m, s) of its left and
    right boundaries from bottom to top; the polygon is the right chain followed by the
    reversed left chain.  ``in_fan``: a cell inside a simple wave or a lattice.
    ``table``: its isentrope (``UNKNOWN`` until looked up, ``None`` if it has none);
    ``invariants``: its ``(J+, J-)`` on that table, once known.
    """

    id: int
    state: State
    material: object
    layer: int
    t_start: float
    left_points: list
    right_points: list
    t_end: float | None = None
    in_fan: bool = False
    table: object = UNKNOWN
    invariants: tuple | None = None


def polygon_of(left_points, right_points) -> list[tuple[float, float]]:
    """The polygon of a region from its left and right chains (repeated points removed)."""
    points = [*right_points, *reversed(left_points)]
    cleaned = []
    for p in points:
        if not cleaned or p != cleaned[-1]:
            cleaned.append(p)
    if len(cleaned) > 1 and cleaned[0] == cleaned[-1]:
        cleaned.pop()
    return cleaned


@dataclass(eq=False, slots=True)
class Front:
    """A live or finished front (engine side, linked to its neighbours).

    Position ``X(t) = x0 + speed (t - t0)`` (m, s, m/s) for ``t0 <= t <= t1``.  ``wave``
    links successive segments of one physical shock; ``fan``/``ray_index``/``ray_count``
    place a ray in its simple wave and ``invariant`` is its own Riemann invariant (m/s,
    NaN for a ray without an isentrope table).  For sites: ``bond``, ``strength``
    (tension it carries, Pa), ``side`` of a boundary, and the gap's ``gap_width``
    (Eulerian, m) at ``gap_time``; a piston boundary that separated from its face keeps
    its ``piston_velocity`` (m/s, ``None`` while in contact) and the gap the same way.
    ``history`` records ``(t, kind)`` changes of a site's
    kind (a stress boundary whose tension tore the material off its face: ``GAP`` from
    then on); ``boundary_steps`` the ``(t, value)`` steps of a prescribed history;
    ``earlier_regions`` records ``(t, region_id)``: the region on the right until ``t``.
    ``solved_until`` (s): a site that ends or lies inside a lattice, the time up to which
    that lattice solved the cells beside it, ahead of the queue (``fronttrack.zones``).
    ``lineage`` names the wave a wave descends from (``fronttrack.outgoing.lineage``):
    a wave born at an impact or at an edge of the material (a boundary, a gap's face)
    starts a lineage, the waves an event sends out inherit the lineage of the waves that
    met there, and ``MIXED`` when those differ.
    """

    id: int
    kind: FrontKind
    x0: float
    t0: float
    speed: float = 0.0
    direction: int = 0
    jump: float = 0.0
    wave: int | None = None
    fan: int | None = None
    ray_index: int = 0
    ray_count: int = 0
    invariant: float = math.nan
    bond: str = ""
    strength: float = 0.0
    side: str = ""
    t1: float | None = None
    x1: float | None = None
    left_region: int | None = None
    right_region_id: int | None = None
    prev: Front | None = field(default=None, repr=False)
    next: Front | None = field(default=None, repr=False)
    region_right: Region | None = field(default=None, repr=False)
    alive: bool = True
    gap_width: float = 0.0
    gap_time: float = 0.0
    gap_version: int = 0
    piston_velocity: float | None = None
    history: list = field(default_factory=list)
    boundary_steps: list = field(default_factory=list)
    earlier_regions: list = field(default_factory=list)
    lineage: int = MIXED
    solved_until: float = 0.0

    @property
    def is_site(self) -> bool:
        return self.kind in _SITES  # FrontKind.is_site, asked at every event

    def position(self, t: float) -> float:
        """Lagrangian position (m) at time ``t`` (s)."""
        if self.speed == 0.0:
            return self.x0
        return self.x0 + self.speed * (t - self.t0)


@dataclass(frozen=True, slots=True)
class FrontRecord:
    """A front of a solution: ``X = x0 + speed (t - t0)`` from ``t0`` to ``t1`` (m, s).

    ``kind`` (a ``FrontKind``); for waves ``direction`` (+1 right-going), ``jump`` (the
    stress behind minus ahead, Pa), ``wave`` (segments of one shock share it), ``fan``,
    ``ray_index``, ``ray_count`` and ``invariant`` (a ray's own Riemann invariant, m/s);
    for sites ``bond``, ``side`` and ``history`` (``(t, kind)`` changes of kind);
    ``left_region`` and ``right_region_id`` the regions it separates, and
    ``earlier_regions`` the ``(t, id)`` regions on its right before ``t``; ``lineage`` the
    wave it descends from (see ``Front``).
    """

    id: int
    kind: FrontKind
    x0: float
    t0: float
    x1: float | None
    t1: float | None
    speed: float = 0.0
    direction: int = 0
    jump: float = 0.0
    wave: int | None = None
    fan: int | None = None
    ray_index: int = 0
    ray_count: int = 0
    invariant: float = math.nan
    bond: str = ""
    side: str = ""
    left_region: int | None = None
    right_region_id: int | None = None
    history: tuple = ()
    earlier_regions: tuple = ()
    lineage: int = MIXED

    @property
    def is_site(self) -> bool:
        return self.kind.is_site

    def position(self, t: float) -> float:
        """Lagrangian position (m) at time ``t`` (s)."""
        if self.speed == 0.0:
            return self.x0
        return self.x0 + self.speed * (t - self.t0)


@dataclass(frozen=True, slots=True)
class RegionRecord:
    """A region of a solution: a constant ``state`` of ``material`` in ``layer`` over the
    polygon ``vertices`` (``(X, t)``, m and s) from ``t_start`` to ``t_end``; ``birth``
    is the first vertex of its left boundary (where it began); ``in_fan`` marks a cell
    of a simple wave or a lattice."""

    id: int
    state: State
    material: object
    layer: int
    t_start: float
    t_end: float | None
    in_fan: bool
    vertices: tuple
    birth: tuple | None = None

    def polygon(self) -> list[tuple[float, float]]:
        """Closed boundary as ``(X, t)`` vertices (m, s), counter-clockwise."""
        return list(self.vertices)


def inside_fan(left: Front, right: Front) -> bool:
    """True when the region between ``left`` and ``right`` is a cell of a simple wave:
    both are rays of one direction, of one fan or each a one-ray wave."""
    if left.kind != FrontKind.RAY or right.kind != FrontKind.RAY \
            or left.direction != right.direction:
        return False
    return left.fan == right.fan or (left.ray_count == 1 and right.ray_count == 1)
