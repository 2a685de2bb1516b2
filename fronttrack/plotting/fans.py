"""Fans as the figures see them: groups of rays, fan interiors, head and tail rays.

A centred simple wave is discretised into ``ray_count`` rays issuing from one
point (``ray_index`` 0 is the head, the leading characteristic; the last index
is the tail).  A ray that crosses another wave continues as a new segment that
keeps its ``fan``, ``ray_index`` and ``ray_count``; a ray reflected from a
boundary or interface starts a new one-ray "fan".

``fan_interior`` decides which regions are inside a fan.  (``Region.in_fan`` is
not used: the engine also sets it for the constant state just ahead of a
fan's head or behind its tail, e.g. the whole free-surface state behind a
reflected fan.)  A region is inside a fan when a ray bounds it on the left and a
ray of the same direction bounds it on the right, and the two rays belong to
the same fan, or both are one-ray fans (the train of rays reflected from a
surface, one by one, by an incident fan).
"""

from __future__ import annotations

from collections import defaultdict


def is_edge_ray(front) -> bool:
    """The head or tail ray of a fan of several rays (drawn heavier)."""
    return front.ray_count > 1 and front.ray_index in (0, front.ray_count - 1)


def fan_interior(solution) -> set[int]:
    """Ids of the regions inside a fan (see the module docstring)."""
    on_left: dict[int, list] = defaultdict(list)  # rays bounding a region on its left
    on_right: dict[int, list] = defaultdict(list)
    for front in solution.fronts:
        if front.kind != "ray":
            continue
        if front.right_region_id is not None:
            on_left[front.right_region_id].append(front)
        if front.left_region is not None:
            on_right[front.left_region].append(front)
    interior = set()
    for region_id, left_rays in on_left.items():
        for a in left_rays:
            if any(_same_fan(a, b) for b in on_right.get(region_id, ())):
                interior.add(region_id)
                break
    return interior


def _same_fan(a, b) -> bool:
    if a.direction != b.direction:
        return False
    return a.fan == b.fan or (a.ray_count == 1 and b.ray_count == 1)


def fan_groups(solution) -> list[list]:
    """Rays grouped by fan and origin point, each group ordered head first.

    One group is one centred fan (or one continued segment of it) drawn as a
    single curve from the state ahead of its head to the state behind its tail.
    """
    groups: dict[tuple, list] = defaultdict(list)
    for front in solution.fronts:
        if front.kind == "ray" and front.t1 is not None:
            groups[(front.fan, front.direction, front.x0, front.t0)].append(front)
    return [sorted(rays, key=lambda f: -abs(f.speed)) for rays in groups.values()]
