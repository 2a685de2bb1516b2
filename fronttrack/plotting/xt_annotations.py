"""Annotations of an X–t diagram: layer names, spall points, the line-style key.

Each drawing function returns the page area (shapely, in points) its texts
cover, so that region numbers can keep clear of them.
"""

from __future__ import annotations

import numpy as np
from matplotlib.lines import Line2D
from matplotlib.patches import Patch
from shapely.geometry import box
from shapely.ops import unary_union

from .labels import PageScale
from .xt_style import CONTACT, EDGE_RAY, GAP, INTERFACE, RAY, RELEASE_SHOCK, SHOCK, SPALL, VOID

SPALL_CLUSTER = 40.0
"""Spall points closer than this on the page (pt, Manhattan) share one annotation."""


def draw_layer_names(ax, view):
    """Write ``name (material)`` at the bottom of each layer; return the area it covers (pt)."""
    covered = []
    scale = PageScale.of_axes(ax)
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
                covered.append(scale.text_box(xm, 0.0, -0.5 * text_width, 0, text_width, 14))
                break
    return unary_union(covered) if covered else None


def _layer_texts(layer) -> list[str]:
    material = layer.material.name
    if layer.name and layer.name != material:
        return [f"{layer.name} ({material})", material]
    return [material]


SPALL_OFFSETS = ((7, -3), (-7, -3), (7, 9), (-7, 9), (7, -15), (-7, -15), (0, 14), (0, -20))
"""Offsets (pt) of a spall annotation from its point, in order of preference."""

SAMPLES = 12
"""Points per line segment tested against an annotation's box."""


def _line_points(view, scale: PageScale):
    """Page points (pt) along the lines an annotation should not cover: the waves (fan
    rays count a third) and the sites.  Returns the points and their weights."""
    waves = view.waves
    xs = [waves.x, np.array([s.x for s in view.site_segments]).reshape(-1, 2)]
    ts = [waves.t, np.array([s.t for s in view.site_segments]).reshape(-1, 2)]
    weights = [np.where(waves.kind == "ray", 1.0 / 3.0, 1.0), np.ones(len(view.site_segments))]
    x, t, weight = np.concatenate(xs), np.concatenate(ts), np.concatenate(weights)
    f = np.linspace(0.0, 1.0, SAMPLES)
    px = ((x[:, :1] + f * (x[:, 1:] - x[:, :1])) - scale.x0) * scale.sx
    py = ((t[:, :1] + f * (t[:, 1:] - t[:, :1])) - scale.y0) * scale.sy
    return px.ravel(), py.ravel(), np.repeat(weight, SAMPLES)


def draw_spalls(ax, view) -> list:
    """Star every spall point; annotate clusters of nearby ones once ("spall 2–4").

    Each annotation takes, among ``SPALL_OFFSETS``, the place inside the axes that
    covers the fewest fronts (shocks, head and tail rays and sites; fan rays count a
    third).  Returns the page boxes of the annotations.
    """
    covered = []
    for x, t in view.spalls:
        ax.plot([x], [t], ls="none", **SPALL)
    scale = PageScale.of_axes(ax)
    page = scale.to_page(view.spalls)
    width_pt, height_pt = scale.size
    lines = _line_points(view, scale) if view.spalls else None
    for first, last in _clusters(page, SPALL_CLUSTER):
        x, t = view.spalls[first]
        if len(view.spalls) == 1:
            text = "spall"
        else:
            text = f"spall {first + 1}" if first == last else f"spall {first + 1}–{last + 1}"
        width, height = 4.5 * len(text) + 4, 11.0
        best = None
        for dx, dy in SPALL_OFFSETS:
            left = page[first][0] + (dx if dx > 0 else dx - width if dx < 0 else -width / 2)
            bottom = page[first][1] + dy - 3
            if left < 0 or bottom < 0 or left + width > width_pt or bottom + height > height_pt:
                continue
            px, py, weight = lines
            inside = (px > left) & (px < left + width) & (py > bottom) & (py < bottom + height)
            cost = float(weight[inside].sum())
            if best is None or cost < best[0]:
                best = (cost, dx, dy, left, bottom)
        if best is None:
            best = (0.0, 7, -3, page[first][0] + 7, page[first][1] - 6)
        _, dx, dy, left, bottom = best
        ax.annotate(text, (x, t), xytext=(dx, dy), textcoords="offset points", fontsize=7,
                    color="#8b0000", zorder=7,
                    ha="left" if dx > 0 else "right" if dx < 0 else "center", va="bottom",
                    bbox={"boxstyle": "round,pad=0.1", "fc": "white", "ec": "none",
                          "alpha": 0.85})
        covered.append(box(left - 2, bottom - 2, left + width + 2, bottom + height + 2))
    return covered


def _clusters(points, distance) -> list[tuple[int, int]]:
    """Runs ``(first, last)`` of consecutive points each within ``distance`` of the previous."""
    runs = []
    for k, (px, py) in enumerate(points):
        if runs:
            qx, qy = points[runs[-1][1]]
            if abs(px - qx) + abs(py - qy) < distance:
                runs[-1] = (runs[-1][0], k)
                continue
        runs.append((k, k))
    return runs


def draw_key(ax, view) -> int:
    """The line-style key above the diagram; returns its number of rows."""
    kinds = view.waves.kinds()
    handles = []
    if "shock" in kinds:
        handles.append(Line2D([], [], label="shock", **SHOCK))
    if "release" in kinds:
        handles.append(Line2D([], [], label="release shock", **RELEASE_SHOCK))
    if kinds & {"ray", "edge"}:
        handles.append(Line2D([], [], label="fan rays", **RAY))
    if "edge" in kinds:
        handles.append(Line2D([], [], label="fan head/tail", **EDGE_RAY))
    site_kinds = {s.kind for s in view.site_segments}
    if "interface" in site_kinds:
        handles.append(Line2D([], [], label="interface", **INTERFACE))
    if "contact" in site_kinds:
        handles.append(Line2D([], [], label="entropy contact", **CONTACT))
    if "gap" in site_kinds and view.eulerian:
        handles.append(Patch(label="gap (void)", **VOID))
    elif "gap" in site_kinds:
        handles.append(Line2D([], [], label="gap (opened)", **GAP))
    if view.spalls:
        handles.append(Line2D([], [], ls="none", label="spall", **SPALL))
    columns = len(handles) if len(handles) <= 5 else (len(handles) + 1) // 2
    ax.legend(handles=handles, loc="lower center", bbox_to_anchor=(0.5, 1.0), ncol=columns,
              fontsize=7, frameon=False, handlelength=2.2, columnspacing=1.2,
              borderaxespad=0.2)
    return 1 if len(handles) <= 5 else 2
