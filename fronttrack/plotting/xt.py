"""The X–t (wave) diagram: position horizontal in mm, time vertical in µs.

Conventions, as in Davison's and Forbes's figures:

- shocks: heavy solid lines (compressive black, rarefaction shocks of a
  Hugoniot release or of a linear elastic solid dark blue);
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
import numpy as np
from matplotlib import patheffects
from matplotlib.collections import LineCollection, PolyCollection
from matplotlib.colors import ListedColormap, TwoSlopeNorm
from matplotlib.lines import Line2D
from shapely.geometry import box
from shapely.ops import unary_union

from .labels import PageScale, place_labels
from .style import GPA, LABEL_FONTSIZE, STRESS_CMAP, T_LABEL, X_EULER_LABEL, X_LABEL, title_of
from .xt_geometry import lagrangian_view, eulerian_view

LABELS_ATTR = "region_labels"
"""Attribute of a diagram's axes holding its placed numbers ``{region_id: (x, y)}``."""

SHOCK = {"color": "black", "lw": 1.7}
RELEASE_SHOCK = {"color": "#23408e", "lw": 1.3}
RAY = {"color": "#3a3a3a", "lw": 0.4}
EDGE_RAY = {"color": "#1a1a1a", "lw": 0.85}
INTERFACE = {"color": "#4d4d4d", "lw": 1.0, "ls": (0, (5, 3))}
CONTACT = {"color": "#9a9a9a", "lw": 0.8, "ls": (0, (1, 2))}
GAP = {"color": "white", "lw": 1.6,
       "path_effects": [patheffects.Stroke(linewidth=3.4, foreground="black"),
                        patheffects.Normal()]}
"""A gap in the Lagrangian view: a double line (white core on a black stroke)."""
GAP_FACE = {"color": "black", "lw": 0.8}
SPALL = {"marker": "*", "color": "#d62728", "markersize": 11, "markeredgecolor": "#6b0000",
         "markeredgewidth": 0.6, "zorder": 6}
SHADE_STRENGTH = 0.5
"""Fraction of the colormap colour in a region's fill (the rest is white)."""


def placed_labels(ax) -> dict[int, tuple[float, float]]:
    """The region numbers placed on an axes by ``plot_xt`` or ``plot_sigma_u``."""
    return dict(getattr(ax, LABELS_ATTR, {}))


def stress_norm(solution) -> TwoSlopeNorm:
    """Colour scale (GPa) centred at zero, each half spanning its own extreme."""
    sigma = np.array([r.state.sigma for r in solution.regions]) * GPA
    top = max(float(sigma.max()), 1e-12)
    bottom = min(float(sigma.min()), -0.05 * top)
    return TwoSlopeNorm(vmin=bottom, vcenter=0.0, vmax=max(top, 0.05 * -bottom))


def light_cmap(name: str = STRESS_CMAP, strength: float = SHADE_STRENGTH) -> ListedColormap:
    """A colormap blended with white so that lines and numbers stay readable on it."""
    colors = plt.get_cmap(name)(np.linspace(0.0, 1.0, 256))
    colors[:, :3] = strength * colors[:, :3] + (1.0 - strength)
    return ListedColormap(colors, name=f"{name}_light")


def plot_xt(solution, ax=None, shade=True, numbers=True, eulerian=False):
    """Draw the X–t diagram of ``solution`` on ``ax`` (a new figure if ``None``); return ``ax``.

    ``shade`` fills regions by stress with a colorbar (GPa); ``numbers`` writes
    region ids (fan interiors and regions too small to hold a number are
    skipped); ``eulerian`` draws at Eulerian positions x(X, t).  The placed
    numbers are available from ``placed_labels(ax)``.
    """
    if ax is None:
        _, ax = plt.subplots(figsize=(7.0, 5.4))
    view = eulerian_view(solution) if eulerian else lagrangian_view(solution)
    x_lo, x_hi = view.x_range()
    pad = 0.03 * (x_hi - x_lo) if _has_wall(view) else 0.0
    ax.set_xlim(x_lo - pad, x_hi + pad)
    ax.set_ylim(0.0, view.t_end)
    ax.set_xlabel(X_EULER_LABEL if eulerian else X_LABEL)
    ax.set_ylabel(T_LABEL)
    what = "Eulerian x–t diagram" if eulerian else "X–t diagram"
    ax.set_title(title_of(solution, what), fontsize=10)
    if shade:
        _shade(ax, solution, view)
    _draw_waves(ax, view)
    _draw_sites(ax, view)
    obstacles = [_draw_layer_names(ax, view), *_draw_spalls(ax, view)]
    _legend(ax, view, solution)
    labels = {}
    if numbers:
        labels = _draw_numbers(ax, solution, view, [o for o in obstacles if o is not None])
    setattr(ax, LABELS_ATTR, labels)
    return ax


def _has_wall(view) -> bool:
    return any(s.kind == "boundary" and s.condition == "wall" for s in view.site_segments)


def _shade(ax, solution, view) -> None:
    norm = stress_norm(solution)
    cmap = light_cmap()
    ids = [r.id for r in solution.regions if r.id in view.polygons]
    sigma = {r.id: r.state.sigma * GPA for r in solution.regions}
    collection = PolyCollection([view.polygons[i] for i in ids], cmap=cmap, norm=norm,
                                edgecolors="face", linewidths=0.2, zorder=0)
    collection.set_array(np.array([sigma[i] for i in ids]))
    ax.add_collection(collection)
    bar = ax.figure.colorbar(collection, ax=ax, pad=0.02, fraction=0.05)
    bar.set_label("stress σ (GPa): compression > 0, tension < 0")
    ticks = sorted({*np.round(np.linspace(norm.vmin, 0.0, 3), 2),
                    *np.round(np.linspace(0.0, norm.vmax, 5), 1)})
    bar.set_ticks(ticks)


def _draw_waves(ax, view) -> None:
    groups = {"shock": [], "release": [], "ray": [], "edge": []}
    for front, xs, ts in view.waves:
        segment = list(zip(xs, ts, strict=True))
        if front.kind == "shock":
            groups["shock" if front.jump >= 0.0 else "release"].append(segment)
        elif front.ray_index in (0, max(front.ray_count - 1, 0)):
            groups["edge"].append(segment)
        else:
            groups["ray"].append(segment)
    styles = {"shock": SHOCK, "release": RELEASE_SHOCK, "ray": RAY, "edge": EDGE_RAY}
    for name, segments in groups.items():
        if segments:
            style = styles[name]
            ax.add_collection(LineCollection(segments, colors=style["color"],
                                             linewidths=style["lw"], zorder=3,
                                             capstyle="round"))


def _draw_sites(ax, view) -> None:
    for seg in view.site_segments:
        xs, ts = seg.x, seg.t
        if seg.kind == "gap":
            ax.plot(xs, ts, zorder=4, solid_capstyle="butt",
                    **(GAP if seg.face is None else GAP_FACE))
        elif seg.kind == "interface":
            ax.plot(xs, ts, zorder=2, **INTERFACE)
        elif seg.kind == "contact":
            ax.plot(xs, ts, zorder=2, **CONTACT)
        elif seg.kind == "boundary":
            _draw_boundary(ax, seg)
    for t, x_left, x_right in view.voids:
        ax.fill_betweenx(t, x_left, x_right, facecolor="white", edgecolor="#777777",
                         hatch="////", linewidth=0.0, zorder=1)


def _draw_boundary(ax, seg) -> None:
    xs, ts = seg.x, seg.t
    if seg.condition == "free":
        ax.plot(xs, ts, color="black", lw=1.2, zorder=4, solid_capstyle="butt")
        return
    ax.plot(xs, ts, color="black", lw=2.4, zorder=4, solid_capstyle="butt")
    if seg.condition == "wall":
        x_lo, x_hi = ax.get_xlim()
        width = 0.025 * (x_hi - x_lo)
        outward = -width if xs[0] <= 0.5 * (x_lo + x_hi) else width
        ax.fill_betweenx(ts, xs[0], xs[0] + outward, facecolor="none", edgecolor="black",
                         hatch="////", linewidth=0.0, zorder=1)
    else:
        mark = "u(t)" if seg.condition == "velocity" else "σ(t)"
        ax.annotate(mark, (xs[1], ts[1]), xytext=(3, -10), textcoords="offset points",
                    fontsize=7)


def _estimated_box(ax, x, y, dx_pt, dy_pt, width_pt, height_pt):
    """A text box (in page points of the axes) around a data point, for label avoidance."""
    scale = _page_scale(ax)
    px, py = scale.to_page([(x, y)])[0]
    return box(px + dx_pt, py + dy_pt, px + dx_pt + width_pt, py + dy_pt + height_pt)


def _draw_layer_names(ax, view):
    """Write ``name (material)`` at the bottom of each layer; return the area it covers (pt)."""
    covered = []
    scale = _page_scale(ax)
    for x0, x1, layer in view.layers:
        width_pt = (x1 - x0) * scale.sx
        for text in _layer_texts(layer):
            text_width = 0.55 * 7.0 * len(text) + 4
            if text_width < width_pt - 4:
                xm = 0.5 * (x0 + x1)
                ax.annotate(text, (xm, 0.0), xytext=(0, 3), textcoords="offset points",
                            ha="center", va="bottom", fontsize=7, zorder=7,
                            bbox={"boxstyle": "round,pad=0.15", "fc": "white", "ec": "none",
                                  "alpha": 0.85})
                covered.append(_estimated_box(ax, xm, 0.0, -0.5 * text_width, 0,
                                              text_width, 14))
                break
    return unary_union(covered) if covered else None


def _layer_texts(layer) -> list[str]:
    material = layer.material.name
    if layer.name and layer.name != material:
        return [f"{layer.name} ({material})", material]
    return [material]


def _draw_spalls(ax, view) -> list:
    covered = []
    for k, (x, t) in enumerate(view.spalls):
        ax.plot([x], [t], ls="none", **SPALL)
        text = "spall" if len(view.spalls) == 1 else f"spall {k + 1}"
        ax.annotate(text, (x, t), xytext=(6, -3), textcoords="offset points", fontsize=7,
                    color="#8b0000", zorder=7,
                    bbox={"boxstyle": "round,pad=0.1", "fc": "white", "ec": "none",
                          "alpha": 0.7})
        covered.append(_estimated_box(ax, x, t, -7, -8, 14 + 4.5 * len(text), 16))
    return covered


def _legend(ax, view, solution) -> None:
    kinds = {f.kind for f, _, _ in view.waves}
    handles = []
    if any(f.kind == "shock" and f.jump >= 0 for f, _, _ in view.waves):
        handles.append(Line2D([], [], label="shock", **SHOCK))
    if any(f.kind == "shock" and f.jump < 0 for f, _, _ in view.waves):
        handles.append(Line2D([], [], label="release shock", **RELEASE_SHOCK))
    if "ray" in kinds:
        handles.append(Line2D([], [], label="fan rays", **EDGE_RAY))
    site_kinds = {s.kind for s in view.site_segments}
    if "interface" in site_kinds:
        handles.append(Line2D([], [], label="interface", **INTERFACE))
    if "contact" in site_kinds:
        handles.append(Line2D([], [], label="entropy contact", **CONTACT))
    if "gap" in site_kinds:
        handles.append(Line2D([], [], label="gap (opened)", **GAP))
    if view.spalls:
        handles.append(Line2D([], [], ls="none", label="spall", **SPALL))
    ax.legend(handles=handles, loc="lower center", bbox_to_anchor=(0.5, 1.06), ncol=4,
              fontsize=7, frameon=False, handlelength=2.2, columnspacing=1.2)


def _page_scale(ax) -> PageScale:
    fig = ax.figure
    pos = ax.get_position()
    width, height = fig.get_size_inches()
    return PageScale(ax.get_xlim(), ax.get_ylim(), (pos.width * width * 72.0,
                                                   pos.height * height * 72.0))


def _draw_numbers(ax, solution, view, obstacles) -> dict[int, tuple[float, float]]:
    obstacle = unary_union(obstacles) if obstacles else None
    regions = [r for r in solution.regions if r.id in view.polygons]
    labels = place_labels(regions, lambda r: view.polygons[r.id], _page_scale(ax),
                          LABEL_FONTSIZE, obstacle)
    for region_id, (x, t) in labels.items():
        ax.text(x, t, str(region_id), ha="center", va="center", fontsize=LABEL_FONTSIZE,
                zorder=8)
    return labels
