"""Fronts and regions: the geometric objects of an X–t diagram.

Between events every front is a straight line in the Lagrangian X–t plane and
every region a constant state.  The engine keeps the live fronts in a doubly
linked list ordered by X (only neighbours can meet first); each front knows
the region to its right.  A front's neighbouring regions never change during
its life, so a finished front records the ids of the two regions it separates.

Front kinds:

- ``shock``: a jump satisfying the Rankine–Hugoniot conditions (also the
  rarefaction shocks of Hugoniot release and of linear elastic solids);
- ``ray``: one characteristic of a discretised fan (``fan`` groups them);
- ``interface``: the contact between two layers (``bond``: bonded/unbonded);
- ``contact``: an entropy jump left inside a material by an interaction;
- ``gap``: an interface or spall plane that has opened (two free surfaces);
- ``boundary``: the left or right end of the stack.

Contacts, gaps and boundaries are vertical in X–t (they do not move in X).
"""

from __future__ import annotations

from dataclasses import dataclass, field

from materials import State

WAVE_KINDS = ("shock", "ray")
SITE_KINDS = ("interface", "contact", "gap", "boundary")


@dataclass(eq=False)
class Region:
    """A region of constant state, with the chains of points bounding it.

    ``left_points`` and ``right_points`` are ``(X, t)`` vertices (m, s) of its
    left and right boundaries from bottom to top; the polygon is the left chain
    followed by the reversed right chain.
    """

    id: int
    state: State
    material: object
    layer: int
    t_start: float
    left_points: list = field(default_factory=list)
    right_points: list = field(default_factory=list)
    t_end: float | None = None
    in_fan: bool = False

    def polygon(self) -> list[tuple[float, float]]:
        """Closed boundary as ``(X, t)`` vertices (m, s), counter-clockwise."""
        points = [*self.right_points, *reversed(self.left_points)]
        cleaned = []
        for p in points:
            if not cleaned or p != cleaned[-1]:
                cleaned.append(p)
        if len(cleaned) > 1 and cleaned[0] == cleaned[-1]:
            cleaned.pop()
        return cleaned


@dataclass(eq=False)
class Front:
    """A live or finished front.

    Position ``X(t) = x0 + speed (t - t0)`` (m, s, m/s) for ``t0 <= t <= t1``.
    ``wave`` links successive segments of one physical wave (a shock weakened
    by a fan is a chain of segments with one ``wave`` id); ``fan``/``ray_index``
    place a ray in its fan.  For sites: ``bond`` (``"bonded"``/``"unbonded"``),
    ``strength`` (tension it carries, Pa), ``side`` of a boundary, and the
    gap's ``gap_width`` (Eulerian, m) at ``gap_time``.  ``history`` records
    ``(t, kind)`` changes of a site's kind (an interface that opens into a gap);
    ``boundary_steps`` the ``(t, value)`` steps of a boundary's prescribed history;
    ``earlier_regions`` records ``(t, region_id)``: the region on the right
    until ``t``, when two neighbouring regions merged into a new one.
    """

    id: int
    kind: str
    x0: float
    t0: float
    speed: float = 0.0
    wave: int | None = None
    fan: int | None = None
    ray_index: int = 0
    ray_count: int = 0
    direction: int = 0
    jump: float = 0.0
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
    history: list = field(default_factory=list)
    boundary_steps: list = field(default_factory=list)
    earlier_regions: list = field(default_factory=list)

    @property
    def is_site(self) -> bool:
        return self.kind in SITE_KINDS

    def position(self, t: float) -> float:
        """Lagrangian position (m) at time ``t`` (s)."""
        if self.speed == 0.0:
            return self.x0
        return self.x0 + self.speed * (t - self.t0)


def inside_fan(left: Front, right: Front) -> bool:
    """True when the region between ``left`` and ``right`` lies inside a fan.

    It does when both are rays of one direction and of one fan, or both are
    one-ray fans (the train of single rays that a fan sends off a surface, one
    reflection at a time).  The constant states ahead of a fan's head and
    behind its tail are not inside it.
    """
    if left.kind != "ray" or right.kind != "ray" or left.direction != right.direction:
        return False
    return left.fan == right.fan or (left.ray_count == 1 and right.ray_count == 1)
