"""Reader-facing region numbers: 1, 2, 3 … in the order a reader meets the regions.

The engine's region ids are internal (they count every region ever made, lattice
cells included, and run into the thousands).  A figure numbers only the regions it
can show legibly on a standard X–t diagram, and numbers them in reading order: by
the time the region begins, then by its position X at that time (the layers at
``t = 0`` are 1, 2, … from left to right, then the regions the impact makes).  The
same numbers appear on the X–t and σ–u diagrams and in ``solution.json``
(``regions[k].number``, beside the internal ``id``).

A region is numbered when it is not inside a fan (``RegionRecord.in_fan``) and a
circle holding its number fits inside its polygon on the standard X–t axes
(``STANDARD_PAGE``, in printer's points: the X–t panel of ``xt.png`` and
``xt_su.png``).  The fit is tested on the page, where "wide enough" means wide
enough to read whatever the aspect ratio of mm to µs: the largest distance from
the boundary over a grid of interior points (``GRID`` × ``GRID``) must reach the
label's radius (``label_radius``).  The figures then place each number at the
exact pole of inaccessibility (``plotting.labels``), which is at least as far
from the boundary.

Pure numpy (no matplotlib, no shapely): the JSON writer uses it without drawing.
"""

from __future__ import annotations

import numpy as np

STANDARD_PAGE = (363.0, 299.0)
"""Width and height (pt) of the X–t axes of the standard figures (``xt.png``)."""

LABEL_FONTSIZE = 8.0
"""Font size (pt) of region numbers on every diagram."""

CHAR_WIDTH = 0.62
"""Width of a digit as a fraction of the font size (DejaVu Sans digits are 0.636 em)."""

MARGIN = 1.5
"""Clearance (pt) kept between a number and the nearest front."""

GRID = 9
"""Interior points per direction tried when testing whether a number fits."""

WALL_PAD = 0.03
"""Room outside a rigid wall for its hatching, as a fraction of the stack length."""


def label_radius(text: str, fontsize: float = LABEL_FONTSIZE) -> float:
    """Radius (pt) of the circle that holds ``text`` written at ``fontsize`` (pt), plus margin."""
    half_width = 0.5 * CHAR_WIDTH * fontsize * len(text)
    half_height = 0.5 * 0.75 * fontsize
    return (half_width**2 + half_height**2) ** 0.5 + MARGIN


def xt_limits(scene) -> tuple[tuple[float, float], tuple[float, float]]:
    """Data limits of a Lagrangian X–t diagram: ``((X_lo, X_hi) mm, (0, t_end) µs)``.

    A rigid wall gets ``WALL_PAD`` of the stack length outside it for its hatching.
    """
    length = scene.length * 1e3
    pad = WALL_PAD * length
    lo = -pad if scene.left.kind == "wall" else 0.0
    hi = length + (pad if scene.right.kind == "wall" else 0.0)
    return (lo, hi), (0.0, scene.t_end * 1e6)


def _clearance(page: np.ndarray) -> float:
    """Largest distance (pt) from the boundary over a grid of points inside a polygon."""
    lo, hi = page.min(axis=0), page.max(axis=0)
    fractions = (np.arange(GRID) + 0.5) / GRID
    gx, gy = np.meshgrid(lo[0] + fractions * (hi[0] - lo[0]), lo[1] + fractions * (hi[1] - lo[1]))
    points = np.column_stack([gx.ravel(), gy.ravel()])
    a, b = page, np.roll(page, -1, axis=0)
    # inside: crossing number of a ray towards +x
    ya, yb = a[:, 1][None, :], b[:, 1][None, :]
    py = points[:, 1:2]
    straddles = (ya > py) != (yb > py)
    with np.errstate(divide="ignore", invalid="ignore"):
        x_cross = a[:, 0][None, :] + (py - ya) * (b[:, 0] - a[:, 0])[None, :] / (yb - ya)
    inside = np.count_nonzero(straddles & (points[:, :1] < x_cross), axis=1) % 2 == 1
    if not inside.any():
        return 0.0
    points = points[inside]
    edge = b - a
    length2 = np.maximum((edge**2).sum(axis=1), 1e-300)
    rel = points[:, None, :] - a[None, :, :]
    f = np.clip((rel * edge[None, :, :]).sum(axis=2) / length2[None, :], 0.0, 1.0)
    nearest = a[None, :, :] + f[:, :, None] * edge[None, :, :]
    distance = np.sqrt(((points[:, None, :] - nearest) ** 2).sum(axis=2)).min(axis=1)
    return float(distance.max())


def _reading_key(vertices: np.ndarray) -> tuple[float, bool, float, float]:
    """Where a reader meets a region: its earliest time; then the regions present over a
    stretch of X at that time (the layers at ``t = 0``) before those born at a point;
    then its leftmost X then; then its centre (the regions born at one point, left to
    right)."""
    t_first = vertices[:, 1].min()
    first = vertices[vertices[:, 1] == t_first, 0]
    return (float(t_first), bool(first.max() == first.min()), float(first.min()),
            float(vertices[:, 0].mean()))


def region_numbers(solution, page: tuple[float, float] = STANDARD_PAGE,
                   fontsize: float = LABEL_FONTSIZE) -> dict[int, int]:
    """Reader-facing numbers ``{region_id: number}`` (1, 2, …) of the regions a figure shows.

    Parameters
    ----------
    solution : Solution
        The front-tracking solution.
    page : (float, float)
        Width and height (pt) of the X–t axes the numbers must fit; the default is
        the standard figures' (so the numbers agree with ``solution.json``).
    fontsize : float
        Font size (pt) of the numbers.

    Returns
    -------
    dict
        Region id to number, numbered in reading order (see the module docstring).
    """
    (x_lo, x_hi), (t_lo, t_hi) = xt_limits(solution.scene)
    scale = np.array([page[0] / (x_hi - x_lo) * 1e3, page[1] / (t_hi - t_lo) * 1e6])
    origin = np.array([x_lo * 1e-3, t_lo * 1e-6])
    # what decides whether a number fits, kept per region instead of its polygon: the
    # narrower extent of the polygon on the page and its clearance (both in pt)
    smallest = label_radius("99", fontsize)
    candidates = []
    for region in solution.region_records():
        if region.in_fan or len(region.vertices) < 3:
            continue
        vertices = np.asarray(region.vertices, dtype=float)
        if not np.all(np.isfinite(vertices)):
            continue
        on_page = (vertices - origin) * scale
        extent = float(np.ptp(on_page, axis=0).min())
        if extent >= 2.0 * smallest:
            candidates.append((region.id, _reading_key(vertices), extent,
                               _clearance(on_page)))
    digits = 2
    while True:
        radius = label_radius("9" * digits, fontsize)
        shown = [(region_id, key) for region_id, key, extent, clearance in candidates
                 if extent >= 2.0 * radius and clearance >= radius]
        if len(str(len(shown))) <= digits:
            break
        digits += 1
    order = sorted(shown, key=lambda item: (*item[1], item[0]))
    return {region_id: number for number, (region_id, _) in enumerate(order, start=1)}
