"""Where to write each region's number on an X–t diagram.

Which regions are numbered, and their numbers, is decided once for a solution
(``fronttrack.numbering``); this module finds where each number goes.  A number
goes at the pole of inaccessibility of its region (shapely's ``polylabel``): the
interior point farthest from the region's boundary.  The search runs in printer's
points, i.e. after scaling X and t by the size the axes have on paper, so that
"far from the boundary" means far on the page whatever the aspect ratio of mm to
µs.  The parts of a region under other annotations (``obstacles``: layer names,
spall and boundary marks) are avoided when the rest still holds the number;
otherwise the number goes at the pole of the whole region if that holds it, and
at the pole of the part left free by the annotations if nothing does.

Every numbered region is labelled exactly once, at a point inside its own polygon.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable

from shapely import make_valid
from shapely.geometry import MultiPolygon, Polygon, box
from shapely.ops import polylabel

from ..numbering import label_radius


class PageScale:
    """Affine map from data units (e.g. mm, µs) to points on the page.

    ``xlim`` and ``ylim`` are the axes' data limits and ``size`` the axes'
    width and height in points.
    """

    def __init__(self, xlim, ylim, size):
        self.size = (float(size[0]), float(size[1]))
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


def _pole(shape, radius: float):
    """The pole of ``shape`` if a circle of ``radius`` about it fits inside, else ``None``."""
    shape = _largest_part(shape)
    if shape is None:
        return None
    pole = polylabel(shape, tolerance=0.25)
    if not shape.contains(pole) or shape.boundary.distance(pole) < radius:
        return None
    return pole


def place_labels(regions: Iterable, polygon_of: Callable, scale: PageScale,
                 numbers: dict[int, int], fontsize: float, obstacles=None) -> dict[int, tuple]:
    """Label positions in data units, by region id, for every numbered region shown.

    ``polygon_of(region)`` returns the region's vertices in data units (mm, µs),
    ``numbers`` the region numbers (``fronttrack.numbering.region_numbers``) and
    ``obstacles`` an optional shapely geometry (in points) to keep clear.
    """
    placed: dict[int, tuple[float, float]] = {}
    for region in regions:
        if region.id not in numbers:
            continue
        vertices = scale.to_page(polygon_of(region))
        if len(vertices) < 3:
            continue
        radius = label_radius(str(numbers[region.id]), fontsize)
        shape = Polygon(vertices)
        if not shape.is_valid:
            shape = make_valid(shape)
        free = _largest_part(shape.difference(obstacles)) if obstacles is not None else None
        pole = (_pole(free, radius) if free is not None else None) or _pole(shape, radius)
        if pole is None:  # too tight for full clearance: still keep off the annotations
            pole = polylabel(free if free is not None else _largest_part(shape),
                             tolerance=0.25)
        placed[region.id] = scale.to_data(pole.x, pole.y)
    return placed
