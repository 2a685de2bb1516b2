"""Regions filled by stress: a diverging colormap centred at zero, with a colorbar in GPa.

Red is compression, blue tension (stress positive in compression).  Each half
of the scale spans its own extreme (``TwoSlopeNorm``), so a tension of a few
per cent of the peak compression still shows; when nothing is in tension the
colorbar shows its compressive half only.  The colours are blended with white
so that lines and numbers stay readable on them.
"""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.collections import PolyCollection
from matplotlib.colors import ListedColormap, TwoSlopeNorm
from matplotlib.ticker import FormatStrFormatter, MaxNLocator

from .style import GPA, STRESS_CMAP

SHADE_STRENGTH = 0.5
"""Fraction of the colormap colour in a region's fill (the rest is white)."""


def stress_norm(solution) -> TwoSlopeNorm:
    """Colour scale (GPa) centred at zero, each half spanning its own extreme."""
    sigma = np.array([r.state.sigma for r in solution.regions]) * GPA
    top = max(float(sigma.max()), 1e-12)
    bottom = min(float(sigma.min()), -0.05 * top)
    return TwoSlopeNorm(vmin=bottom, vcenter=0.0, vmax=max(top, 0.05 * -bottom))


def stress_ticks(norm) -> list[float]:
    """Colorbar ticks (GPa): a few on each side of zero, inside the colour range."""
    ticks = {0.0}
    for low, high, count in ((norm.vmin, 0.0, 3), (0.0, norm.vmax, 6)):
        values = MaxNLocator(count).tick_values(low, high)
        ticks.update(float(v) for v in values if low <= v <= high)
    return sorted(ticks)


def light_cmap(name: str = STRESS_CMAP, strength: float = SHADE_STRENGTH) -> ListedColormap:
    """A colormap blended with white so that lines and numbers stay readable on it."""
    colors = plt.get_cmap(name)(np.linspace(0.08, 0.92, 256))
    colors[:, :3] = strength * colors[:, :3] + (1.0 - strength)
    return ListedColormap(colors, name=f"{name}_light")


def shade_regions(ax, solution, polygons: dict) -> None:
    """Fill each region's polygon (``polygons[id]``, data units) by its stress; add a colorbar."""
    norm = stress_norm(solution)
    ids = [r.id for r in solution.regions if r.id in polygons]
    sigma = {r.id: r.state.sigma * GPA for r in solution.regions}
    collection = PolyCollection([polygons[i] for i in ids], cmap=light_cmap(), norm=norm,
                                edgecolors="face", linewidths=0.2, zorder=0)
    collection.set_array(np.array([sigma[i] for i in ids]))
    ax.add_collection(collection)
    bar = ax.figure.colorbar(collection, ax=ax, pad=0.02, fraction=0.05)
    bar.set_label("stress σ (GPa), compression > 0")
    bar.set_ticks(stress_ticks(norm))
    bar.ax.yaxis.set_major_formatter(FormatStrFormatter("%g"))
    negligible = solution.accuracy_report.get("negligible_stress", 0.0) * GPA
    if min(sigma.values()) >= -negligible:
        # no tension beyond the negligible stress (rounding): the compressive half only
        bar.ax.set_ylim(0.0, norm.vmax)
