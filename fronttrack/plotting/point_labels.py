"""Offsets for the numbers written next to points (the states of a σ–u diagram).

Greedy and local: each text tries a few positions around its point (upper
right first, as in hand-drawn diagrams) and takes the first whose box, on the
page, stays inside the axes and overlaps neither an earlier text nor a marker;
if none is free it keeps the first that stays inside.  Everything is in
printer's points.
"""

from __future__ import annotations

CANDIDATES = ((4, 3), (-4, 3), (4, -3), (-4, -3), (6, 0), (-6, 0), (0, 7), (0, -7),
              (9, 9), (-9, 9), (9, -9), (-9, -9), (0, 14), (0, -14))
"""Offsets (pt) of the text's anchor corner from its point, in order of preference."""

MARKER_RADIUS = 3.0
"""Half-size (pt) of a state marker, kept clear of the texts."""


def _box(x, y, dx, dy, width, height):
    left = x + dx if dx >= 0 else x + dx - width
    if dx == 0:
        left = x - 0.5 * width
    bottom = y + dy if dy >= 0 else y + dy - height
    if dy == 0:
        bottom = y - 0.5 * height
    return left, bottom, left + width, bottom + height


def _overlaps(a, b) -> bool:
    return a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]


def _inside(box, bounds) -> bool:
    return bounds is None or (box[0] >= bounds[0] and box[1] >= bounds[1]
                              and box[2] <= bounds[2] and box[3] <= bounds[3])


def place_point_labels(points, texts, fontsize: float, markers=None,
                       bounds=None) -> list[tuple[float, float, str, str]]:
    """For each point (pt) and text: ``(dx, dy, ha, va)`` for ``annotate``'s offset.

    ``markers`` are the page positions (pt) of every marker to keep clear
    (default: the labelled points themselves); ``bounds`` ``(x0, y0, x1, y1)``
    (pt), if given, is the box the texts must stay in (the axes).
    """
    markers = [(x - MARKER_RADIUS, y - MARKER_RADIUS, x + MARKER_RADIUS, y + MARKER_RADIUS)
               for x, y in (points if markers is None else markers)]
    taken: list[tuple] = []
    result = []
    for (x, y), text in zip(points, texts, strict=True):
        width, height = 0.6 * fontsize * len(text) + 2.0, 0.8 * fontsize + 2.0
        choice = next((c for c in CANDIDATES
                       if _inside(_box(x, y, *c, width, height), bounds)), CANDIDATES[0])
        for dx, dy in CANDIDATES:
            box = _box(x, y, dx, dy, width, height)
            if _inside(box, bounds) and not any(_overlaps(box, o) for o in taken + markers):
                choice = (dx, dy)
                break
        taken.append(_box(x, y, *choice, width, height))
        dx, dy = choice
        ha = "left" if dx > 0 else "right" if dx < 0 else "center"
        va = "bottom" if dy > 0 else "top" if dy < 0 else "center"
        result.append((dx, dy, ha, va))
    return result
