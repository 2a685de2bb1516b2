"""State-space diagrams: stress–particle velocity (σ–u) and stress–density (σ–ρ).

Each numbered region of the X–t diagram (``fronttrack.numbering``) is a point,
labelled with the same number; states that coincide on the page (the two sides
of a contact always share σ and u) share one label, written as a list with
ranges ("2, 5–7").  The waves joining numbered states are drawn along their wave
curves (``plotting.wave_paths``): Hugoniots of shocks solid, isentropes of fans
dashed, coloured by material.  These are the paths a reader follows: the
principal Hugoniots out of the initial states and the release isentropes of the
numbered states.  ``all_paths=True`` adds, faint, the paths of every other wave
(inside fans and lattices, or between regions too small to number).  The axes
span the numbered states only: nothing is extended beyond the states shown.  In
the σ–u plane a right-going wave through a state rises, a left-going one falls;
an impedance match is the crossing of the two.

Stress in GPa (compression positive), velocity in m/s, density in kg/m³.
"""

from __future__ import annotations

import math

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.collections import LineCollection
from matplotlib.lines import Line2D

from ..numbering import region_numbers
from .placed import Placed
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

MERGE_DISTANCE = 6.0
"""States closer than this on the page (pt) share one label."""
PER_LINE = 5
"""Items of a shared label per line (longer lists wrap)."""
MARGIN = 0.08
"""Room around the numbered states, as a fraction of their span."""
DASHED = (0, (4, 2))
FAINT = {"alpha": 0.25, "lw": 0.5}
STRONG = {"alpha": 0.95, "lw": 1.3}


def plot_sigma_u(solution, ax=None, numbers=None, all_paths=False, paths=None) -> Placed:
    """σ–u diagram of ``solution``; return what was placed (``Placed``).

    Parameters
    ----------
    solution : Solution
        The front-tracking solution.
    ax : matplotlib.axes.Axes, optional
        Where to draw (a new figure if ``None``).
    numbers : dict, optional
        ``{region_id: number}`` of the states to show (``Placed.numbers`` of the
        X–t diagram beside it); ``None`` takes the standard numbers
        (``numbering.region_numbers``, those of ``solution.json``).
    all_paths : bool
        Also draw, faint, the waves that do not join two numbered states.
    paths : list of WavePath, optional
        The wave paths, if already computed (``plotting.wave_paths``).

    Returns
    -------
    Placed
        ``labels`` ``{region_id: (u m/s, σ GPa)}`` of every numbered state shown.
    """
    numbers = region_numbers(solution) if numbers is None else dict(numbers)
    return _state_diagram(solution, ax, numbers, lambda s: s.u, lambda p: p.u, U_LABEL,
                          title_of(solution, "σ–u diagram"), None, all_paths, paths)


def plot_sigma_rho(solution, ax=None, numbers=None, all_paths=False, paths=None) -> list:
    """σ–ρ diagrams (stress vs density, kg/m³) of ``solution``; return a ``Placed`` per panel.

    The materials of a stack differ in density far more than each is
    compressed, so each material gets its own panel (shared stress axis) when
    ``ax`` is a list of one axes per material; ``ax`` may also be one axes (all
    materials on it) or ``None`` (a new figure with a panel per material).
    ``numbers``, ``all_paths`` and ``paths`` as for ``plot_sigma_u``; ``labels``
    of each panel are ``{region_id: (ρ kg/m³, σ GPa)}``.
    """
    names = list(material_colors(solution.scene))
    if ax is None:
        figure, axes = plt.subplots(1, len(names), figsize=sigma_rho_figsize(solution),
                                    sharey=True, squeeze=False, layout="constrained")
        axes = list(axes[0])
    else:
        axes = list(ax) if isinstance(ax, list | tuple | np.ndarray) else [ax]
    numbers = region_numbers(solution) if numbers is None else dict(numbers)
    groups = [names] if len(axes) == 1 else [[name] for name in names]
    if paths is None:
        paths = wave_paths(solution, None if all_paths else set(numbers))
    placed = []
    for panel, materials in zip(axes, groups, strict=True):
        title = (title_of(solution, "σ–ρ diagram") if len(axes) == 1
                 else f"σ–ρ diagram: {', '.join(materials)}")
        placed.append(_state_diagram(solution, panel, numbers, lambda s: 1.0 / s.v,
                                     lambda p: p.rho, RHO_LABEL, title, set(materials),
                                     all_paths, paths))
    for panel in axes[1:]:
        panel.set_ylabel("")
    if len(axes) > 1:
        axes[0].figure.suptitle(title_of(solution, "σ–ρ diagrams"), fontsize=10)
    return placed


def sigma_rho_figsize(solution) -> tuple[float, float]:
    """Figure size (in) of the σ–ρ diagrams: a panel per material, never narrower than 6.4."""
    count = len(material_colors(solution.scene))
    return (max(6.4, 3.6 * count + 1.2), 5.0)


def _state_diagram(solution, ax, numbers, x_of_state, x_of_path, xlabel, title,
                   materials, all_paths, paths) -> Placed:
    """Draw the wave paths and numbered states of ``materials`` (all if ``None``) on ``ax``."""
    if ax is None:
        _, ax = plt.subplots(figsize=(6.4, 5.0), layout="constrained")
    colors = material_colors(solution.scene)
    if materials is not None:
        colors = {name: c for name, c in colors.items() if name in materials}
    if paths is None:
        paths = wave_paths(solution, None if all_paths else set(numbers))
    paths = [p for p in paths if p.material.name in colors]
    shown = sorted((r for r in solution.regions
                    if r.id in numbers and r.material.name in colors),
                   key=lambda r: numbers[r.id])
    _draw_paths(ax, paths, numbers, colors, x_of_path, all_paths)
    points = [(float(x_of_state(r.state)), r.state.sigma * GPA) for r in shown]
    _set_limits(ax, points)
    ax.axhline(0.0, color="#999999", lw=0.6, zorder=1)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(SIGMA_LABEL)
    ax.set_title(title, fontsize=10)
    ax.grid(True, lw=0.3, alpha=0.5)
    _legend(ax, solution, paths, colors, bool(shown))
    texts = _draw_states(ax, shown, points, numbers, colors)
    labels = {region.id: point for region, point in zip(shown, points, strict=True)}
    return Placed(ax=ax, numbers={r.id: numbers[r.id] for r in shown}, labels=labels,
                  texts=tuple(texts))


def _draw_paths(ax, paths, numbers, colors, x_of_path, all_paths) -> None:
    """Paths joining two numbered states strong; the others (``all_paths``) faint."""
    groups: dict[tuple, list] = {}
    for path in paths:
        strong = path.ahead in numbers and path.behind in numbers
        if strong or all_paths:
            key = (path.material.name, path.kind, strong)
            groups.setdefault(key, []).append(
                np.column_stack([x_of_path(path), path.sigma * GPA]))
    for (name, kind, strong), segments in groups.items():
        style = STRONG if strong else FAINT
        ax.add_collection(LineCollection(
            segments, colors=colors[name], linewidths=style["lw"], alpha=style["alpha"],
            linestyles="solid" if kind == "shock" else DASHED, zorder=3 if strong else 2),
            autolim=False)


def _set_limits(ax, points) -> None:
    """Axes limits spanning the numbered states, with a margin (and always σ = 0)."""
    if not points:
        return
    xs = np.array([p[0] for p in points])
    ys = np.array([p[1] for p in points] + [0.0])
    for setter, values in ((ax.set_xlim, xs), (ax.set_ylim, ys)):
        lo, hi = float(values.min()), float(values.max())
        span = hi - lo if hi > lo else max(abs(hi), 1.0)
        setter(lo - MARGIN * span, hi + MARGIN * span)


def number_list(numbers: list[int]) -> str:
    """Numbers as a sorted list with ranges, wrapped every ``PER_LINE`` items: "1, 3–5"."""
    items, run = [], []
    for n in sorted(numbers):
        if run and n == run[-1] + 1:
            run.append(n)
            continue
        if run:
            items.append(_run_text(run))
        run = [n]
    items.append(_run_text(run))
    lines = [", ".join(items[k:k + PER_LINE]) for k in range(0, len(items), PER_LINE)]
    return ",\n".join(lines)


def _run_text(run: list[int]) -> str:
    if len(run) == 1:
        return str(run[0])
    return f"{run[0]}, {run[1]}" if len(run) == 2 else f"{run[0]}–{run[-1]}"


def _draw_states(ax, shown, points, numbers, colors) -> list:
    """Mark each numbered state; write the numbers, one label per group of coincident states.

    States closer than ``MERGE_DISTANCE`` on the page (always the two sides of a
    contact, which share σ and u) share one label, e.g. "2, 3".  Returns the texts.
    """
    if not shown:
        return []
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
    texts = [number_list([numbers[shown[k].id] for k in group]) for group in groups]
    anchors = [tuple(page[group[0]]) for group in groups]
    scale = 72.0 / ax.figure.dpi
    box = ax.bbox
    offsets = place_point_labels(anchors, texts, LABEL_FONTSIZE,
                                 markers=[tuple(p) for p in page],
                                 bounds=(box.x0 * scale, box.y0 * scale, box.x1 * scale,
                                         box.y1 * scale))
    return [ax.annotate(text, points[group[0]], xytext=(dx, dy), textcoords="offset points",
                        ha=ha, va=va, fontsize=LABEL_FONTSIZE, zorder=6,
                        bbox={"boxstyle": "round,pad=0.1", "fc": "white", "ec": "none",
                              "alpha": 0.7})
            for group, text, (dx, dy, ha, va) in zip(groups, texts, offsets, strict=True)]


def _legend(ax, solution, paths, colors, states: bool) -> None:
    handles = [Line2D([], [], color=c, lw=2.0, label=name) for name, c in colors.items()]
    kinds = {p.kind for p in paths}
    if "shock" in kinds:
        handles.append(Line2D([], [], color="black", lw=1.2, label="Hugoniot (shock)"))
    if "fan" in kinds:
        handles.append(Line2D([], [], color="black", lw=1.2, ls=DASHED,
                              label="isentrope (fan)"))
    if states:
        handles.append(Line2D([], [], ls="none", marker="o", ms=4.5, mfc="white",
                              mec="black", label="state of numbered region"))
    release = solution.accuracy_report.get("release", "")
    ax.legend(handles=handles, fontsize=7.5, loc="best", framealpha=0.9,
              title=f"release: {release}" if release else None, title_fontsize=7.5)
