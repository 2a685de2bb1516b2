"""Drawing the fronts of an X–t view: waves, interfaces, contacts, gaps, boundaries."""

from __future__ import annotations

import numpy as np
from matplotlib.collections import LineCollection

from .labels import PageScale
from .xt_style import (
    CONTACT,
    EDGE_RAY,
    GAP,
    GAP_FACE,
    INTERFACE,
    RAY,
    RELEASE_SHOCK,
    SHOCK,
    VOID,
    shock_width,
)


def _polyline(x: np.ndarray, t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Segments (n × 2 end points) as one NaN-separated polyline: one path to draw,
    where a collection of a hundred thousand rays costs a path object each."""
    gap = np.full((len(x), 1), np.nan)
    return np.hstack([x, gap]).ravel(), np.hstack([t, gap]).ravel()


def draw_waves(ax, solution, view) -> None:
    """Shocks (width by strength) as line collections; fan rays as light polylines."""
    scale = solution.accuracy_report.get("stress_scale") or max(
        abs(r.state.sigma) for r in solution.regions)
    waves = view.waves
    for kind, style in (("ray", RAY), ("edge", EDGE_RAY)):
        chosen = waves.kind == kind
        if chosen.any():
            ax.plot(*_polyline(waves.x[chosen], waves.t[chosen]), color=style["color"],
                    lw=style["lw"], alpha=style["alpha"], ls=style.get("ls", "solid"),
                    zorder=3, solid_capstyle="round")
    for kind, style in (("shock", SHOCK), ("release", RELEASE_SHOCK)):
        chosen = np.nonzero(waves.kind == kind)[0]
        if chosen.size:
            segments = np.stack([waves.x[chosen], waves.t[chosen]], axis=2)
            widths = [shock_width(jump, scale) for jump in waves.jump[chosen]]
            ax.add_collection(LineCollection(segments, colors=style["color"],
                                             linewidths=widths, zorder=3.5,
                                             capstyle="round"))


def _collection(segments, style: dict, zorder: float) -> LineCollection:
    """One line collection in a ``Line2D``-style dict (color, lw, ls, path_effects)."""
    collection = LineCollection(segments, colors=style["color"], linewidths=style["lw"],
                                linestyles=style.get("ls", "solid"), zorder=zorder,
                                capstyle="butt")
    if "path_effects" in style:
        collection.set_path_effects(style["path_effects"])
    return collection


def draw_sites(ax, view) -> list:
    """Draw interfaces, contacts, gaps and boundaries; return the page boxes of their marks."""
    styles = {"gap": (GAP, 4), "face": (GAP_FACE, 4), "interface": (INTERFACE, 2),
              "contact": (CONTACT, 2)}
    groups: dict[str, list] = {}
    boundaries: dict[tuple, list] = {}
    x_mid = 0.5 * sum(ax.get_xlim())
    for seg in view.site_segments:
        segment = list(zip(seg.x, seg.t, strict=True))
        if seg.kind == "boundary":
            side = "left" if seg.x[0] <= x_mid else "right"
            boundaries.setdefault((side, seg.condition), []).append(segment)
        elif seg.kind == "gap":
            groups.setdefault("gap" if seg.face is None else "face", []).append(segment)
        elif seg.kind in styles:
            groups.setdefault(seg.kind, []).append(segment)
    for name, segments in groups.items():
        style, zorder = styles[name]
        ax.add_collection(_collection(segments, style, zorder))
    for t, x_left, x_right in view.voids:
        ax.fill_betweenx(t, x_left, x_right, linewidth=0.0, zorder=1, **VOID)
    covered = []
    for (side, condition), segments in boundaries.items():
        covered += _draw_boundary(ax, side, condition, segments)
    return covered


def _draw_boundary(ax, side: str, condition: str, segments) -> list:
    """One end of the stack styled by its condition; returns the page box of its mark, if any.

    Free surface: a plain line.  Wall: a heavy line hatched on the outside.
    Prescribed velocity or stress: a heavy line marked "u(t) given" / "σ(t) given".
    """
    free = condition == "free"
    ax.add_collection(_collection(segments, {"color": "black", "lw": 1.2 if free else 2.4}, 4))
    if free:
        return []
    points = sorted({p for segment in segments for p in segment}, key=lambda p: p[1])
    xs, ts = np.array([p[0] for p in points]), np.array([p[1] for p in points])
    if condition == "wall":
        x_lo, x_hi = ax.get_xlim()
        outward = 0.025 * (x_hi - x_lo) * (-1.0 if side == "left" else 1.0)
        ax.fill_betweenx(ts, xs, xs + outward, facecolor="none", edgecolor="black",
                         hatch="////", linewidth=0.0, zorder=1)
        return []
    mark = "u(t) given" if condition == "velocity" else "σ(t) given"
    inward = 4 if side == "left" else -4
    ax.annotate(mark, (xs[-1], ts[-1]), xytext=(inward, -4), textcoords="offset points",
                fontsize=7, ha="left" if inward > 0 else "right", va="top", zorder=7,
                bbox={"boxstyle": "round,pad=0.1", "fc": "white", "ec": "none", "alpha": 0.8})
    width = 4.2 * len(mark) + 4
    return [PageScale.of_axes(ax).text_box(xs[-1], ts[-1], inward if inward > 0 else
                                           inward - width, -16, width, 14)]
