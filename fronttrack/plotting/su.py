"""State-space diagrams: stress–particle velocity (σ–u) and stress–density (σ–ρ).

Each numbered region of the X–t diagram is a point, labelled with the same
number; regions in the same state (the two sides of a contact always share σ
and u) share one point labelled "2, 3".  Every wave is the path of its wave
curve between its ahead and behind states (``plotting.wave_paths``): Hugoniots
of shocks solid, isentropes of fans dashed, coloured by material.  Paths that
join two unnumbered states (inside fans, or regions too small to number) are
drawn faint; an unnumbered state at the end of a strong path is a small dot.
In the σ–u plane a right-going wave through a state rises, a left-going one
falls; an impedance match is the crossing of the two.

Stress in GPa (compression positive), velocity in m/s, density in kg/m³.
"""

from __future__ import annotations

import math

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.collections import LineCollection
from matplotlib.figure import Figure
from matplotlib.lines import Line2D

from .point_labels import place_point_labels
from .style import (
    GPA,
    LABEL_FONTSIZE,
    RHO_LABEL,
    SIGMA_LABEL,
    U_LABEL,
    material_colors,
    title_of,
)
from .wave_paths import wave_paths
from .xt import LABELS_ATTR, XT_FIGSIZE, placed_labels, plot_xt

MERGE_DISTANCE = 5.0
"""States closer than this on the page (pt) share one label."""
DASHED = (0, (4, 2))
FAINT = {"alpha": 0.3, "lw": 0.6}
STRONG = {"alpha": 0.95, "lw": 1.3}


def xt_numbers(solution) -> set[int]:
    """The region ids ``plot_xt`` numbers on a standard-size X–t figure."""
    figure = Figure(figsize=XT_FIGSIZE)
    ax = figure.add_subplot()
    return set(placed_labels(plot_xt(solution, ax=ax)))


def _numbers(solution, numbers) -> set[int]:
    if numbers is None:
        return xt_numbers(solution)
    return {int(n) for n in numbers}


def plot_sigma_u(solution, ax=None, numbers=None):
    """σ–u diagram of ``solution`` on ``ax`` (new figure if ``None``); return ``ax``.

    ``numbers``: the region ids to show as numbered states (a dict from
    ``placed_labels`` or any iterable of ids); ``None`` takes those that
    ``plot_xt`` numbers on a standard figure.  ``placed_labels(ax)`` returns
    ``{region_id: (u m/s, σ GPa)}``.
    """
    return _state_diagram(solution, ax, _numbers(solution, numbers), lambda s: s.u,
                          lambda p: p.u, U_LABEL, "σ–u diagram")


def plot_sigma_v(solution, ax=None, numbers=None) -> list:
    """σ–ρ diagrams (stress vs density, kg/m³) of ``solution``; return the list of axes.

    The materials of a stack differ in density far more than each is
    compressed, so by default each material gets its own panel (shared stress
    axis).  ``ax`` may be one axes (all materials on it) or one per material.
    ``numbers`` as for ``plot_sigma_u``; ``placed_labels(ax)`` of each panel
    returns ``{region_id: (ρ kg/m³, σ GPa)}``.
    """
    names = list(material_colors(solution.scene))
    if ax is None:
        figure, axes = plt.subplots(1, len(names), figsize=(3.4 * len(names) + 1.4, 5.0),
                                    sharey=True, squeeze=False)
        axes = list(axes[0])
        figure.suptitle(title_of(solution, "σ–ρ diagram"), fontsize=10)
    else:
        axes = list(ax) if isinstance(ax, list | tuple | np.ndarray) else [ax]
    numbered = _numbers(solution, numbers)
    groups = [names] if len(axes) == 1 else [[name] for name in names]
    paths = wave_paths(solution)
    for panel, materials in zip(axes, groups, strict=True):
        what = "σ–ρ diagram" if len(axes) == 1 else ", ".join(materials)
        _state_diagram(solution, panel, numbered, lambda s: 1.0 / s.v, lambda p: p.rho,
                       RHO_LABEL, what, materials=set(materials),
                       full_title=len(axes) == 1, paths=paths)
    for panel in axes[1:]:
        panel.set_ylabel("")
    return axes


def _state_diagram(solution, ax, numbered, x_of_state, x_of_path, xlabel, what,
                   materials=None, full_title=True, paths=None):
    """Draw the wave paths and numbered states of ``materials`` (all if ``None``) on ``ax``."""
    if ax is None:
        _, ax = plt.subplots(figsize=(6.4, 5.0))
    colors = material_colors(solution.scene)
    if materials is not None:
        colors = {name: c for name, c in colors.items() if name in materials}
    paths = [p for p in (paths or wave_paths(solution)) if p.material.name in colors]
    groups: dict[tuple, list] = {}
    for path in paths:
        strong = path.ahead in numbered or path.behind in numbered
        key = (path.material.name, path.kind, strong)
        groups.setdefault(key, []).append(np.column_stack([x_of_path(path), path.sigma * GPA]))
    for (name, kind, strong), segments in groups.items():
        style = STRONG if strong else FAINT
        ax.add_collection(LineCollection(
            segments, colors=colors[name], linewidths=style["lw"], alpha=style["alpha"],
            linestyles="solid" if kind == "shock" else DASHED, zorder=3 if strong else 2))
    ends = _unnumbered_ends(solution, paths, numbered, x_of_state)
    if ends:
        ax.plot(*zip(*ends, strict=True), ls="none", marker="o", ms=2.2, color="#555555",
                zorder=4)
    ax.autoscale_view()
    ax.axhline(0.0, color="#999999", lw=0.6, zorder=1)
    regions = [r for r in solution.regions if r.material.name in colors]
    labels = _draw_states(ax, regions, numbered, x_of_state, colors)
    setattr(ax, LABELS_ATTR, labels)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(SIGMA_LABEL)
    ax.ticklabel_format(axis="y", style="sci", scilimits=(-2, 4))
    ax.set_title(title_of(solution, what) if full_title else what, fontsize=10)
    _legend(ax, solution, paths, colors)
    ax.grid(True, lw=0.3, alpha=0.5)
    return ax


def _draw_states(ax, regions, numbered, x_of_state, colors) -> dict[int, tuple[float, float]]:
    """Mark each numbered state; write its number; return the positions by region id.

    States closer than ``MERGE_DISTANCE`` on the page (always the two sides of a
    contact, which share σ and u) share one label, e.g. "2, 3".
    """
    shown = sorted((r for r in regions if r.id in numbered), key=lambda r: r.id)
    if not shown:
        return {}
    points = [(float(x_of_state(r.state)), r.state.sigma * GPA) for r in shown]
    ax.update_datalim(points)
    ax.autoscale_view()
    ax.margins(0.08)
    page = ax.transData.transform(np.array(points)) * 72.0 / ax.figure.dpi
    groups: list[list[int]] = []
    for k, (px, py) in enumerate(page):
        for group in groups:
            qx, qy = page[group[0]]
            if math.hypot(px - qx, py - qy) < MERGE_DISTANCE:
                group.append(k)
                break
        else:
            groups.append([k])
    for region, (x, y) in zip(shown, points, strict=True):
        ax.plot([x], [y], "o", ms=4.5, mfc="white", mec=colors.get(region.material.name),
                mew=1.2, zorder=5)
    texts = [", ".join(str(shown[k].id) for k in group) for group in groups]
    anchors = [tuple(page[group[0]]) for group in groups]
    scale = 72.0 / ax.figure.dpi
    box = ax.bbox
    offsets = place_point_labels(anchors, texts, LABEL_FONTSIZE,
                                 markers=[tuple(p) for p in page],
                                 bounds=(box.x0 * scale, box.y0 * scale, box.x1 * scale,
                                         box.y1 * scale))
    for group, text, (dx, dy, ha, va) in zip(groups, texts, offsets, strict=True):
        ax.annotate(text, points[group[0]], xytext=(dx, dy), textcoords="offset points",
                    ha=ha, va=va, fontsize=LABEL_FONTSIZE, zorder=6,
                    bbox={"boxstyle": "round,pad=0.1", "fc": "white", "ec": "none",
                          "alpha": 0.7})
    return {region.id: point for region, point in zip(shown, points, strict=True)}


def _unnumbered_ends(solution, paths, numbered, x_of_state) -> list[tuple[float, float]]:
    """Unnumbered states at the end of a drawn-strong path (a small dot marks them)."""
    regions = {r.id: r for r in solution.regions}
    ends = set()
    for path in paths:
        if path.ahead in numbered or path.behind in numbered:
            for end in (path.ahead, path.behind):
                if end not in numbered:
                    state = regions[end].state
                    ends.add((float(x_of_state(state)), state.sigma * GPA))
    return sorted(ends)


def _legend(ax, solution, paths, colors) -> None:
    handles = [Line2D([], [], color=c, lw=2.0, label=name) for name, c in colors.items()]
    kinds = {p.kind for p in paths}
    if "shock" in kinds:
        handles.append(Line2D([], [], color="black", lw=1.2, label="Hugoniot (shock)"))
    if "fan" in kinds:
        handles.append(Line2D([], [], color="black", lw=1.2, ls=DASHED,
                              label="isentrope (fan)"))
    release = solution.accuracy_report.get("release", "")
    ax.legend(handles=handles, fontsize=7.5, loc="best", framealpha=0.9,
              title=f"release: {release}" if release else None, title_fontsize=7.5)
