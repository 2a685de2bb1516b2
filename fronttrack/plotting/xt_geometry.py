"""The drawable geometry of an X–t diagram, in mm and µs.

Two views of one solution:

- Lagrangian (``X``, t): every front is a straight segment, sites are vertical;
- Eulerian (``x``, t): each region is the affine image of its Lagrangian
  polygon (``plotting.eulerian``), wave fronts are straight segments, sites
  are piecewise-linear particle paths, and an open gap shows its two faces with
  the void between them.

A view lists region polygons, wave segments (as arrays: a lattice holds a hundred
thousand rays), site segments (with the site's
kind at that time), gap voids, spall points and the layer spans at ``t = 0``;
``plotting.xt`` draws them.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from . import eulerian, sites
from .fans import is_edge_ray
from .style import MM, US

WAVE_KINDS = ("shock", "release", "ray", "edge")
"""Kinds of drawn wave segment: compressive shock, rarefaction shock, fan ray, and
the head or tail ray of a fan (``plotting.fans.is_edge_ray``)."""


@dataclass(frozen=True)
class WaveSegments:
    """Straight wave segments of a view: end points ``x``, ``t`` (n × 2, mm and µs),
    ``kind`` (one of ``WAVE_KINDS``) and the stress ``jump`` (Pa) of each."""

    x: np.ndarray
    t: np.ndarray
    kind: np.ndarray
    jump: np.ndarray

    @classmethod
    def of(cls, fronts, ends) -> WaveSegments:
        """Segments of the wave ``fronts`` whose ``ends(front)`` (``((x0, x1), (t0, t1))``
        in mm and µs) is not ``None``."""
        xs, ts, kinds, jumps = [], [], [], []
        for front in fronts:
            if front.kind not in ("shock", "ray") or front.t1 is None:
                continue
            end = ends(front)
            if end is None:
                continue
            xs.append(end[0])
            ts.append(end[1])
            if front.kind == "shock":
                kinds.append("shock" if front.jump >= 0.0 else "release")
            else:
                kinds.append("edge" if is_edge_ray(front) else "ray")
            jumps.append(front.jump)
        return cls(np.array(xs, dtype=float).reshape(-1, 2),
                   np.array(ts, dtype=float).reshape(-1, 2), np.array(kinds, dtype=str),
                   np.array(jumps, dtype=float))

    def kinds(self) -> set[str]:
        """The kinds present."""
        return set(self.kind.tolist())


@dataclass(frozen=True)
class SiteSegment:
    """A piece of a site line: ``kind`` (interface/contact/gap/boundary), end points (mm, µs).

    ``bond`` is the interface's bond, ``condition`` a boundary's kind (free, wall,
    velocity, stress), ``face`` the side of an open gap in the Eulerian view
    (``None`` for the Lagrangian line, drawn as a double line).
    """

    kind: str
    x: tuple[float, float]
    t: tuple[float, float]
    bond: str = ""
    condition: str = ""
    face: str | None = None


@dataclass
class XtView:
    """Geometry of one X–t view (mm, µs)."""

    eulerian: bool
    polygons: dict[int, list[tuple[float, float]]]
    waves: WaveSegments
    site_segments: list[SiteSegment]
    voids: list[tuple[np.ndarray, np.ndarray, np.ndarray]] = field(default_factory=list)
    spalls: list[tuple[float, float]] = field(default_factory=list)
    layers: list[tuple[float, float, object]] = field(default_factory=list)
    t_end: float = 0.0

    def x_range(self) -> tuple[float, float]:
        xs = [x for poly in self.polygons.values() for x, _ in poly]
        return min(xs), max(xs)


def _layer_spans(scene, positions) -> list[tuple[float, float, object]]:
    spans, x = [], 0.0
    for layer in scene.layers:
        spans.append((positions(x), positions(x + layer.thickness), layer))
        x += layer.thickness
    return spans


def lagrangian_view(solution) -> XtView:
    """The Lagrangian X–t geometry (mm, µs)."""
    polygons = {r.id: [(x * MM, t * US) for x, t in r.vertices] for r in solution.regions}
    waves = WaveSegments.of(solution.fronts, lambda f: ((f.x0 * MM, f.x1 * MM),
                                                         (f.t0 * US, f.t1 * US)))
    segments = []
    for front in sites.sites(solution):
        condition = sites.boundary_kind(solution, front) if front.kind == "boundary" else ""
        for t0, t1, kind in sites.kind_segments(front):
            segments.append(SiteSegment(kind, (front.x0 * MM, front.x0 * MM), (t0 * US, t1 * US),
                                        bond=front.bond, condition=condition))
    return XtView(eulerian=False, polygons=polygons, waves=waves, site_segments=segments,
                  spalls=[(s.x * MM, s.t * US) for s in solution.spalls],
                  layers=_layer_spans(solution.scene, lambda x: x * MM),
                  t_end=solution.scene.t_end * US)


def eulerian_view(solution) -> XtView:
    """The Eulerian x–t geometry (mm, µs), exact for the piecewise-constant solution."""
    motions = eulerian.region_motions(solution)
    polygons = {}
    for region in solution.regions:
        if region.id in motions:
            polygons[region.id] = [(x * MM, t * US) for x, t in
                                   eulerian.eulerian_polygon(region, motions[region.id])]

    def ends(front):
        path = eulerian.front_path(front, motions)
        return None if path is None else ((path[0][0] * MM, path[0][1] * MM),
                                          (path[1][0] * US, path[1][1] * US))

    waves = WaveSegments.of(solution.fronts, ends)
    segments, faces = _eulerian_sites(solution, motions)
    spalls = [(float(motions[rid](s.x, s.t)) * MM, s.t * US)
              for s, rid in zip(solution.spalls, _regions_at_points(
                  solution, motions, [(s.x, s.t) for s in solution.spalls]), strict=True)
              if rid is not None]
    def initial_position(x):
        return solution.initial_eulerian(x) * MM

    return XtView(eulerian=True, polygons=polygons, waves=waves, site_segments=segments,
                  voids=_voids(faces), spalls=spalls,
                  layers=_layer_spans(solution.scene, initial_position),
                  t_end=solution.scene.t_end * US)


def _regions_at_points(solution, motions, points) -> list[int | None]:
    """For each point (m, s), a region with a motion that has it as a vertex (``None`` if
    none): the spall points are event points, so vertices of the regions around them."""
    wanted = set(points)
    found: dict[tuple[float, float], int] = {}
    for region in solution.regions:
        if region.id in motions:
            for vertex in region.vertices:
                if vertex in wanted and vertex not in found:
                    found[vertex] = region.id
    return [found.get(point) for point in points]


def _eulerian_sites(solution, motions):
    """Site segments of the Eulerian view, and the gap faces by site position."""
    by_x = {f.x0: f for f in sites.sites(solution)}
    segments, faces = [], {}
    for x_site, side, x, t in eulerian.site_edges(solution, motions):
        front = by_x[x_site]
        kind = sites.kind_at(front, 0.5 * (t[0] + t[1]))
        condition = sites.boundary_kind(solution, front) if front.kind == "boundary" else ""
        xs, ts = (x[0] * MM, x[1] * MM), (t[0] * US, t[1] * US)
        if kind == "gap":
            segments.append(SiteSegment(kind, xs, ts, bond=front.bond, face=side))
            faces.setdefault(x_site, {"left": [], "right": []})[side].append((ts, xs))
        elif side == ("right" if x_site == 0.0 else "left"):
            segments.append(SiteSegment(kind, xs, ts, bond=front.bond, condition=condition))
    return segments, faces


def _voids(faces) -> list[tuple[np.ndarray, np.ndarray, np.ndarray]]:
    """``(t, x_left_face, x_right_face)`` polylines (µs, mm) of every open gap."""
    voids = []
    for both in faces.values():
        if not both["left"] or not both["right"]:
            continue
        paths = {}
        for side, pieces in both.items():
            t = np.array([p for ts, _ in pieces for p in ts])
            x = np.array([p for _, xs in pieces for p in xs])
            order = np.argsort(t, kind="stable")
            paths[side] = (t[order], x[order])
        t_lo = max(paths["left"][0][0], paths["right"][0][0])
        t_hi = min(paths["left"][0][-1], paths["right"][0][-1])
        times = np.unique(np.concatenate([paths["left"][0], paths["right"][0]]))
        times = times[(times >= t_lo) & (times <= t_hi)]
        if times.size < 2:
            continue
        voids.append((times, np.interp(times, *paths["left"]), np.interp(times, *paths["right"])))
    return voids
