"""Exact Eulerian positions from the Lagrangian solution.

Inside a region of constant state the motion is affine:

    x(X, t) = a + (v / v0) X + u t,

because ``dx/dX = v/v0`` (the stretch) and ``dx/dt = u`` are both constant there.
So every region maps to its Eulerian image by an affine map of its polygon,
and every front, which borders fixed regions, has a piecewise-linear Eulerian
path.  A wave front (shock or ray) borders the same two regions all its life,
so its Eulerian path is one straight segment.

The offsets ``a`` follow from continuity.  At ``t = 0``, ``x(X, 0)`` is the
integral of ``v/v0`` over the stack (a pre-stressed layer starts compressed).
A later region is born at an event point ``P`` (or, after a merge, on a
segment whose left end is a vertex of the merged-in region); ``x(P)`` is the
same in every region touching ``P`` (the particle there has one position),
except across an open gap, whose two faces have different positions.  A
region born on a site line therefore takes ``x(P)`` from an older region on
the same side of that site.  Units: m, s (the callers scale to mm, µs).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class AffineMotion:
    """``x = a + b X + u t`` (m) inside one region: ``b = v/v0``, ``u`` its velocity (m/s)."""

    a: float
    b: float
    u: float

    def __call__(self, x, t):
        """Eulerian position (m) of ``X`` (m) at ``t`` (s): floats or numpy arrays."""
        return self.a + self.b * x + self.u * t


def _centroid_x(polygon) -> float:
    return sum(p[0] for p in polygon) / len(polygon)


def _bottom_width(polygon) -> float:
    """Width (m) of a polygon's edge on ``t = 0``: positive only for the initial layers."""
    bottom = [p[0] for p in polygon if p[1] == 0.0]
    return max(bottom) - min(bottom) if bottom else 0.0


def region_motions(solution) -> dict[int, AffineMotion]:
    """The affine motion of every region, by region id.

    Regions whose volume is infinite (a gas expanded into vacuum) have no
    finite Eulerian position and are left out.
    """
    site_x = {f.x0 for f in solution.fronts if f.kind in ("interface", "contact", "gap",
                                                          "boundary")}
    motions: dict[int, AffineMotion] = {}
    owners: dict[tuple[float, float], list] = {}
    polygons = {r.id: r.polygon() for r in solution.regions}
    centres = {i: _centroid_x(p) for i, p in polygons.items()}
    initial = sorted((r for r in solution.regions if _bottom_width(polygons[r.id]) > 0.0),
                     key=lambda r: min(p[0] for p in polygons[r.id]))
    x_start, x_euler = 0.0, 0.0
    for region in initial:
        stretch = region.state.v / region.material.v0
        width = _bottom_width(polygons[region.id])
        if math.isfinite(stretch):
            motions[region.id] = AffineMotion(x_euler - stretch * x_start, stretch,
                                              region.state.u)
        x_start, x_euler = x_start + width, x_euler + stretch * width
    for region in sorted(solution.regions, key=lambda r: r.id):
        polygon = polygons[region.id]
        if region.id not in motions:
            motion = _born_motion(region, owners, motions, site_x, centres)
            if motion is not None:
                motions[region.id] = motion
        for point in polygon:
            owners.setdefault(point, []).append(region)
    return motions


def _born_motion(region, owners, motions, site_x, centres) -> AffineMotion | None:
    """Motion of a region born after ``t = 0``, from an older region at its birth point."""
    stretch = region.state.v / region.material.v0
    if not math.isfinite(stretch) or region.birth is None:
        return None
    point = region.birth
    side = centres[region.id] - point[0]
    candidates = [r for r in owners.get(point, []) if r.id in motions]
    if point[0] in site_x:
        same = [r for r in candidates if (centres[r.id] - point[0]) * side > 0.0]
        candidates = same or candidates
    if not candidates:
        return None
    x_at_point = float(motions[candidates[0].id](*point))
    a = x_at_point - stretch * point[0] - region.state.u * point[1]
    return AffineMotion(a, stretch, region.state.u)


def front_path(front, motions: dict[int, AffineMotion]) -> tuple[tuple, tuple] | None:
    """Eulerian ``((x0, x1), (t0, t1))`` end points (m, s) of a wave front's straight path."""
    region = front.left_region if front.left_region in motions else front.right_region_id
    if region not in motions or front.t1 is None:
        return None
    motion = motions[region]
    return ((motion(front.x0, front.t0), motion(front.x1, front.t1)), (front.t0, front.t1))


def site_edges(solution, motions) -> list[tuple[float, str, np.ndarray, np.ndarray]]:
    """Eulerian images of every polygon edge lying on a site line.

    Returns ``(X_site, side, x, t)`` with ``side`` ``"left"`` or ``"right"`` of the
    site (the region's side), ``x`` and ``t`` the two end points (m, s).  The two
    faces of an open gap are the left- and right-side edges of its line.
    """
    site_x = {f.x0 for f in solution.fronts if f.kind in ("interface", "contact", "gap",
                                                          "boundary")}
    edges = []
    for region in solution.regions:
        if region.id not in motions:
            continue
        polygon = region.polygon()
        centre = _centroid_x(polygon)
        for p, q in zip(polygon, polygon[1:] + polygon[:1], strict=True):
            if p[0] == q[0] and p[0] in site_x and p[1] != q[1]:
                t = np.array(sorted((p[1], q[1])))
                x = motions[region.id](np.array([p[0], p[0]]), t)
                side = "left" if centre < p[0] else "right"
                edges.append((p[0], side, x, t))
    return edges


def eulerian_polygon(region, motion: AffineMotion) -> list[tuple[float, float]]:
    """The region's polygon mapped to Eulerian ``(x, t)`` (m, s)."""
    return [(motion(x, t), t) for x, t in region.vertices]
