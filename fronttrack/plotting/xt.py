"""The X–t (wave) diagram: position horizontal in mm, time vertical in µs.

Conventions, as in Davison's and Forbes's figures:

- shocks: heavy solid lines (compressive black, rarefaction shocks of a
  Hugoniot release or of a linear elastic solid dark blue), thinner for weak
  shocks (``shock_width``);
- fans: thin rays, the head and tail ray of each fan a little heavier;
- material interfaces: dashed verticals; entropy contacts left by interactions
  inside a material: light dotted verticals;
- gaps (an unbonded interface that opened, or a spall plane): a double line,
  starting when the site opened (its ``history`` says when);
- boundaries: a free surface is a plain line, a rigid wall a heavy line hatched
  on the outside, a prescribed velocity or stress a heavy line marked u(t), σ(t);
- spall: a red star at the fracture point, annotated;
- regions: optionally shaded by stress on a diverging colormap centred at zero
  (red compression, blue tension, colorbar in GPa), and numbered by region id
  (see ``plotting.labels`` for where numbers go and which regions are skipped:
  fan interiors and regions too small on the page to hold their number).

``eulerian=True`` draws the same solution at Eulerian positions ``x(X, t)``,
exactly (``plotting.eulerian``).  The numbers placed are returned by
``placed_labels(ax)`` as ``{region_id: (x_mm, t_us)}``.
"""

from __future__ import annotations

import matplotlib.pyplot as plt
from shapely.ops import unary_union

from .fans import fan_interior
from .labels import PageScale, place_labels
from .stress_shading import shade_regions
from .style import LABEL_FONTSIZE, T_LABEL, X_EULER_LABEL, X_LABEL, title_of
from .xt_annotations import draw_key, draw_layer_names, draw_spalls
from .xt_geometry import eulerian_view, lagrangian_view
from .xt_lines import draw_sites, draw_waves

XT_FIGSIZE = (7.0, 5.4)
"""Size (in) of a stand-alone X–t figure; region numbers are chosen to fit it."""

LABELS_ATTR = "region_labels"
"""Attribute of a diagram's axes holding its placed numbers ``{region_id: (x, y)}``."""
PAD_ATTR = "xt_title_pad"
"""Attribute of an X–t axes holding the title pad used above its key."""
TITLE_PAD = {1: 22, 2: 34}
"""Space (pt) between the axes and the title, by rows of the key in between."""


def title_pad(ax) -> float:
    """Title pad (pt) ``plot_xt`` used on ``ax`` to make room for its key (6 if none)."""
    return getattr(ax, PAD_ATTR, 6.0)


def placed_labels(ax) -> dict[int, tuple[float, float]]:
    """The region numbers placed on an axes by ``plot_xt`` or ``plot_sigma_u``."""
    return dict(getattr(ax, LABELS_ATTR, {}))


def plot_xt(solution, ax=None, shade=True, numbers=True, eulerian=False):
    """Draw the X–t diagram of ``solution`` on ``ax`` (a new figure if ``None``); return ``ax``.

    ``shade`` fills regions by stress with a colorbar (GPa); ``eulerian`` draws
    at Eulerian positions x(X, t) (mm) instead of Lagrangian X (mm).

    ``numbers`` writes each region's id once, at the point of its polygon
    farthest from its boundary on the page.  Skipped: regions inside a fan
    (between two rays of one fan, and the cells where fans cross;
    ``plotting.fans.fan_interior``), regions whose widest inscribed circle on
    the page cannot hold the number's text (slivers, small triangles at
    interactions), and the parts of regions under the layer names, spall and
    boundary annotations.  The placed numbers, ``{region_id: (x_mm, t_us)}``,
    are returned by ``placed_labels(ax)``; each lies inside its own region.
    """
    if ax is None:
        _, ax = plt.subplots(figsize=XT_FIGSIZE)
    view = eulerian_view(solution) if eulerian else lagrangian_view(solution)
    x_lo, x_hi = view.x_range()
    pad = 0.03 * (x_hi - x_lo)
    walls = _wall_sides(solution)
    ax.set_xlim(x_lo - pad * ("left" in walls), x_hi + pad * ("right" in walls))
    ax.set_ylim(0.0, view.t_end)
    ax.set_xlabel(X_EULER_LABEL if eulerian else X_LABEL)
    ax.set_ylabel(T_LABEL)
    what = "Eulerian x–t diagram" if eulerian else "X–t diagram"
    ax.set_title(title_of(solution, what), fontsize=10)
    if shade:
        shade_regions(ax, solution, view.polygons)
    draw_waves(ax, solution, view)
    obstacles = [*draw_sites(ax, view), draw_layer_names(ax, view), *draw_spalls(ax, view)]
    rows = draw_key(ax, view)
    ax.set_title(ax.get_title(), fontsize=10, pad=TITLE_PAD[rows])
    setattr(ax, PAD_ATTR, TITLE_PAD[rows])
    labels = {}
    if numbers:
        labels = _draw_numbers(ax, solution, view, [o for o in obstacles if o is not None])
    setattr(ax, LABELS_ATTR, labels)
    return ax


def _wall_sides(solution) -> set[str]:
    scene = solution.scene
    return {side for side, spec in (("left", scene.left), ("right", scene.right))
            if spec.kind == "wall"}


def _draw_numbers(ax, solution, view, obstacles) -> dict[int, tuple[float, float]]:
    obstacle = unary_union(obstacles) if obstacles else None
    regions = [r for r in solution.regions if r.id in view.polygons]
    labels = place_labels(regions, lambda r: view.polygons[r.id], PageScale.of_axes(ax),
                          LABEL_FONTSIZE, obstacle, skip=fan_interior(solution))
    for region_id, (x, t) in labels.items():
        ax.text(x, t, str(region_id), ha="center", va="center", fontsize=LABEL_FONTSIZE,
                zorder=8)
    return labels
