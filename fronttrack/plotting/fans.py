"""Fans as the figures see them: groups of rays, fan interiors, head and tail rays.

A centred simple wave is discretised into ``ray_count`` rays issuing from one
point (``ray_index`` 0 is the head, the leading characteristic; the last index
is the tail).  A ray that crosses another wave continues as a new segment that
keeps its ``fan``, ``ray_index`` and ``ray_count``; a ray reflected from a
boundary or interface starts a new one-ray "fan".

``fan_interior`` lists the regions inside a fan (``Region.in_fan``, set by the
engine with ``fronttrack.fronts.inside_fan``: between two rays of one fan, or
two one-ray fans of one direction).
"""

from __future__ import annotations

from collections import defaultdict


def is_edge_ray(front) -> bool:
    """The head or tail ray of a fan of several rays (drawn heavier)."""
    return front.ray_count > 1 and front.ray_index in (0, front.ray_count - 1)


def fan_interior(solution) -> set[int]:
    """Ids of the regions inside a fan (see the module docstring)."""
    return {region.id for region in solution.regions if region.in_fan}


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
