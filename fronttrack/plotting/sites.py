"""What a site (interface, contact, gap, boundary) was at each instant of its life.

Sites are fixed in the Lagrangian coordinate ``X``.  A site's ``kind`` is its
kind at the end of the run; ``history`` lists the changes ``(t, kind)``.  The
only changes are an interface (or closed spall plane) opening into a gap and a
gap closing into an unbonded interface, so the kind before the first change is
the other one of the pair.
"""

from __future__ import annotations

_OTHER = {"gap": "interface", "interface": "gap"}


def kind_segments(front) -> list[tuple[float, float, str]]:
    """``(t_start, t_end, kind)`` pieces (s) of a site's life, in time order.

    Example: an interface that opened at 1.9 µs gives
    ``[(0, 1.9e-6, "interface"), (1.9e-6, t_end, "gap")]``.
    """
    t_end = front.t1 if front.t1 is not None else front.t0
    changes = [(t, kind) for t, kind in front.history if isinstance(kind, str)]
    if not changes:
        return [(front.t0, t_end, front.kind)]
    kind = _OTHER.get(changes[0][1], front.kind)
    pieces, start = [], front.t0
    for t, new_kind in changes:
        if t > start:
            pieces.append((start, t, kind))
        start, kind = t, new_kind
    if t_end > start:
        pieces.append((start, t_end, kind))
    return pieces


def kind_at(front, t: float) -> str:
    """The site's kind at time ``t`` (s); the later piece wins at a change."""
    kind = front.kind
    for start, _, piece_kind in kind_segments(front):
        if start <= t:
            kind = piece_kind
    return kind


def boundary_kind(solution, front) -> str:
    """``free``, ``wall``, ``velocity`` or ``stress``: the condition at a boundary front."""
    spec = solution.scene.left if front.side == "left" else solution.scene.right
    return spec.kind


def sites(solution) -> list:
    """Every site front of the solution (boundaries included)."""
    return [f for f in solution.fronts if f.kind in ("interface", "contact", "gap", "boundary")]
