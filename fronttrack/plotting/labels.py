"""Where to write each region's number on an X–t diagram.

A number goes at the pole of inaccessibility of its region (shapely's
``polylabel``): the interior point farthest from the region's boundary.  The
search runs in printer's points, i.e. after scaling X and t by the size the
axes will have on paper, so that "far from the boundary" means far on the page
whatever the aspect ratio of mm to µs.  A number is written only if the circle
of that radius holds the whole text (its estimated half-diagonal plus a margin):
the number then lies inside its region and crosses no front.

Skipped, by design:

- fan-interior regions (given by the caller, see ``plotting.fans``): the
  wedges between the rays of a discretised fan and the cells of fan–fan
  interaction;
- regions too small on the page to hold their number legibly (this includes
  the slivers left between nearly coincident fronts);
- the parts of a region covered by ``obstacles`` (other annotations, in points).

Every region is labelled at most once, at a point inside its own polygon.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable

from shapely import make_valid
from shapely.geometry import MultiPolygon, Point, Polygon, box
from shapely.ops import polylabel

CHAR_WIDTH = 0.62
"""Width of a digit as a fraction of the font size (DejaVu Sans digits are 0.636 em)."""

MARGIN = 1.5
"""Clearance (pt) kept between a number and the nearest front."""


def label_radius(text: str, fontsize: float) -> float:
    """Radius (pt) of the circle that holds ``text`` written at ``fontsize`` (pt), plus margin."""
    half_width = 0.5 * CHAR_WIDTH * fontsize * len(text)
    half_height = 0.5 * 0.75 * fontsize
    return (half_width**2 + half_height**2) ** 0.5 + MARGIN


class PageScale:
    """Affine map from data units (e.g. mm, µs) to points on the page.

    ``xlim`` and ``ylim`` are the axes' data limits and ``size`` the axes'
    width and height in points.
    """

    def __init__(self, xlim, ylim, size):
        self.x0, self.y0 = xlim[0], ylim[0]
        self.sx = size[0] / (xlim[1] - xlim[0])
        self.sy = size[1] / (ylim[1] - ylim[0])

    def to_page(self, points):
        return [((x - self.x0) * self.sx, (y - self.y0) * self.sy) for x, y in points]

    def to_data(self, x: float, y: float) -> tuple[float, float]:
        return self.x0 + x / self.sx, self.y0 + y / self.sy

    @classmethod
    def of_axes(cls, ax) -> PageScale:
        """The scale of an axes as laid out now (its position in the figure, its limits)."""
        position = ax.get_position()
        width, height = ax.figure.get_size_inches()
        return cls(ax.get_xlim(), ax.get_ylim(), (position.width * width * 72.0,
                                                  position.height * height * 72.0))

    def text_box(self, x, y, dx: float, dy: float, width: float, height: float):
        """Page box (pt) of a ``width`` x ``height`` text offset by ``dx, dy`` from a point."""
        px, py = self.to_page([(x, y)])[0]
        return box(px + dx, py + dy, px + dx + width, py + dy + height)


def _largest_part(geometry):
    """The largest polygon of a (possibly multi-part) geometry, or ``None``."""
    if isinstance(geometry, Polygon):
        return geometry if not geometry.is_empty else None
    parts = [g for g in getattr(geometry, "geoms", []) if isinstance(g, Polygon | MultiPolygon)]
    parts = [p for g in parts for p in (g.geoms if isinstance(g, MultiPolygon) else [g])]
    return max(parts, key=lambda p: p.area) if parts else None


def place_labels(regions: Iterable, polygon_of: Callable, scale: PageScale,
                 fontsize: float, obstacles=None, skip=frozenset()) -> dict[int, tuple]:
    """Label positions in data units, by region id, for the regions that can hold one.

    ``polygon_of(region)`` returns the region's vertices in data units (mm, µs),
    ``obstacles`` an optional shapely geometry (in points) to keep clear, and
    ``skip`` the ids of regions never to label (fan interiors).
    """
    placed: dict[int, tuple[float, float]] = {}
    for region in regions:
        if region.id in skip:
            continue
        radius = label_radius(str(region.id), fontsize)
        vertices = scale.to_page(polygon_of(region))
        if len(vertices) < 3:
            continue
        xs = [p[0] for p in vertices]
        ys = [p[1] for p in vertices]
        if max(xs) - min(xs) < 2 * radius or max(ys) - min(ys) < 2 * radius:
            continue
        shape = Polygon(vertices)
        if not shape.is_valid:
            shape = make_valid(shape)
        if obstacles is not None:
            shape = shape.difference(obstacles)
        shape = _largest_part(shape)
        if shape is None or shape.area < (2 * radius) ** 2:
            continue
        pole = polylabel(shape, tolerance=0.25)
        if not shape.contains(pole) or shape.exterior.distance(pole) < radius:
            continue
        if any(Point(pole).distance(hole) < radius for hole in shape.interiors):
            continue
        placed[region.id] = scale.to_data(pole.x, pole.y)
    return placed
