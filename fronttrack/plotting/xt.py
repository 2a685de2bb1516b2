"""The X–t (wave) diagram: position horizontal in mm, time vertical in µs.

Conventions, as in Davison's and Forbes's figures:

- shocks: heavy solid lines (compressive black, rarefaction shocks of a
  Hugoniot release or of a linear elastic solid dark blue), thinner for weak
  shocks (``shock_width``);
- fans: light, translucent blue-grey rays; the head and tail ray of each fan
  dashed and darker, so that a dense fan reads as a band, never as a shock;
- material interfaces: dashed verticals; entropy contacts left by interactions
  inside a material: light dotted verticals;
- gaps (an unbonded interface that opened, or a spall plane): a double line,
  starting when the site opened (its ``history`` says when);
- boundaries: a free surface is a plain line, a rigid wall a heavy line hatched
  on the outside, a prescribed velocity or stress a heavy line marked u(t), σ(t);
- spall: a red star at the fracture point, annotated;
- regions: optionally shaded by stress on one linear colour scale centred at zero
  (red compression, blue tension, colour bar in GPa; ``plotting.stress_shading``),
  and numbered 1, 2, 3 … in reading order (``fronttrack.numbering``: fan
  interiors and regions too small on the page to hold their number are not
  numbered).

``eulerian=True`` draws the same solution at Eulerian positions ``x(X, t)``,
exactly (``plotting.eulerian``).
"""

from __future__ import annotations

import matplotlib.pyplot as plt
from shapely.ops import unary_union

from ..numbering import region_numbers, xt_limits
from .labels import PageScale, place_labels
from .placed import Placed
from .rings import draw_rings
from .stress_shading import shade_regions
from .style import LABEL_FONTSIZE, MM, T_LABEL, X_EULER_LABEL, X_LABEL, title_of
from .xt_annotations import draw_key, draw_layer_names, draw_spalls
from .xt_geometry import eulerian_view, lagrangian_view
from .xt_lines import draw_sites, draw_waves

XT_FIGSIZE = (7.0, 5.4)
"""Size (in) of a stand-alone X–t figure; its axes are ``numbering.STANDARD_PAGE``."""

TITLE_PAD = {0: 6, 1: 22, 2: 34}
"""Space (pt) between the axes and the title, by rows of the key in between."""


def plot_xt(solution, ax=None, shade=True, numbers=True, eulerian=False, view=None) -> Placed:
    """Draw the X–t diagram of ``solution``; return what was placed (``Placed``).

    Parameters
    ----------
    solution : Solution
        The front-tracking solution.
    ax : matplotlib.axes.Axes, optional
        Where to draw (a new figure of ``XT_FIGSIZE`` if ``None``).
    shade : bool
        Fill regions by stress (GPa) with a colour bar.
    numbers : bool or dict
        ``True`` numbers the regions that fit on this axes
        (``numbering.region_numbers`` at the axes' size on the page); a dict
        ``{region_id: number}`` (e.g. the standard numbers of ``solution.json``)
        writes those; ``False`` writes none.
    eulerian : bool
        Draw at Eulerian positions x(X, t) (mm) instead of Lagrangian X (mm).
    view : XtView, optional
        The geometry, if already computed (``plotting.xt_geometry``).

    Returns
    -------
    Placed
        The axes, ``numbers`` ``{region_id: number}`` and ``labels``
        ``{region_id: (x mm, t µs)}`` (each inside its region), the texts placed,
        the title pad that clears the key, and the colour bar.
    """
    if ax is None:
        _, ax = plt.subplots(figsize=XT_FIGSIZE)
    if view is None:
        view = eulerian_view(solution) if eulerian else lagrangian_view(solution)
    (x_lo, x_hi), _ = xt_limits(solution.scene)
    if eulerian:  # the stack moves: its extent, with the same room outside any wall
        left, right = view.x_range()
        x_lo, x_hi = left - (0.0 - x_lo), right + (x_hi - solution.scene.length * MM)
    ax.set_xlim(x_lo, x_hi)
    ax.set_ylim(0.0, view.t_end)
    ax.set_xlabel(X_EULER_LABEL if eulerian else X_LABEL)
    ax.set_ylabel(T_LABEL)
    bar = shade_regions(ax, solution, view.polygons) if shade else None
    draw_waves(ax, solution, view)
    if not eulerian:  # a fragment that rang in closed form: a hatched band
        draw_rings(ax, solution)
    obstacles = [*draw_sites(ax, view), draw_layer_names(ax, view), *draw_spalls(ax, view)]
    rows = draw_key(ax, view)
    what = "Eulerian x–t diagram" if eulerian else "X–t diagram"
    ax.set_title(title_of(solution, what), fontsize=10, pad=TITLE_PAD[rows])
    if numbers is True:
        scale = PageScale.of_axes(ax)
        numbers = region_numbers(solution, page=scale.size)
    numbers = dict(numbers or {})
    labels, texts = _draw_numbers(ax, solution, view, numbers,
                                  [o for o in obstacles if o is not None])
    return Placed(ax=ax, numbers=numbers, labels=labels, texts=tuple(texts),
                  title_pad=TITLE_PAD[rows], colorbar=bar)


def _draw_numbers(ax, solution, view, numbers, obstacles):
    if not numbers:
        return {}, []
    obstacle = unary_union(obstacles) if obstacles else None
    regions = [r for r in solution.regions if r.id in numbers and r.id in view.polygons]
    labels = place_labels(regions, lambda r: view.polygons[r.id], PageScale.of_axes(ax),
                          numbers, LABEL_FONTSIZE, obstacle)
    texts = [ax.text(x, t, str(numbers[region_id]), ha="center", va="center",
                     fontsize=LABEL_FONTSIZE, zorder=8)
             for region_id, (x, t) in labels.items()]
    return labels, texts
