"""Regions filled by stress on one linear colour scale centred at zero, with a colour bar.

Red is compression, blue tension (stress positive in compression).  The scale is
linear and symmetric, ``-m … +m`` GPa with ``m`` the largest stress magnitude of
the solution, so equal colour steps are equal stress steps on both sides of zero
and a tension of a few per cent of the peak compression looks as weak as it is.
The colour bar shows only the range the solution reaches (its lowest stress to
its highest), with equally spaced ticks; when nothing is in tension beyond the
negligible stress it starts at zero.  The colours are blended with white so that
lines and numbers stay readable on them.
"""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.collections import PolyCollection
from matplotlib.colors import ListedColormap, Normalize
from matplotlib.ticker import FormatStrFormatter, MaxNLocator

from .style import GPA, STRESS_CMAP

SHADE_STRENGTH = 0.5
"""Fraction of the colormap colour in a region's fill (the rest is white)."""

COLORBAR_LABEL = "stress σ (GPa), compression > 0; linear scale, white = 0"


def stress_range(solution) -> tuple[float, float]:
    """Lowest and highest stress (GPa) the colour bar shows.

    The lowest is zero when no region is in tension beyond the negligible stress.
    """
    sigma = np.array([r.state.sigma for r in solution.regions]) * GPA
    negligible = solution.accuracy_report.get("negligible_stress", 0.0) * GPA
    low = float(sigma.min()) if sigma.min() < -negligible else 0.0
    return low, max(float(sigma.max()), low + 1e-12, 0.0)


def stress_norm(solution) -> Normalize:
    """One linear colour scale (GPa), symmetric about zero: ``-m … +m``."""
    low, high = stress_range(solution)
    top = max(abs(low), abs(high), 1e-12)
    return Normalize(vmin=-top, vmax=top)


def stress_ticks(low: float, high: float) -> list[float]:
    """Equally spaced colour-bar ticks (GPa) from ``low`` to ``high``, zero among them."""
    return [float(v) for v in MaxNLocator(7, steps=(1, 2, 2.5, 5, 10)).tick_values(low, high)
            if low - 1e-9 * (high - low) <= v <= high + 1e-9 * (high - low)]


def light_cmap(name: str = STRESS_CMAP, strength: float = SHADE_STRENGTH) -> ListedColormap:
    """A colormap blended with white so that lines and numbers stay readable on it."""
    colors = plt.get_cmap(name)(np.linspace(0.08, 0.92, 256))
    colors[:, :3] = strength * colors[:, :3] + (1.0 - strength)
    return ListedColormap(colors, name=f"{name}_light")


def _polygon_arrays(polygons: list) -> list[np.ndarray]:
    """The polygons grouped into arrays of equal vertex counts (matplotlib's fast path)."""
    by_count: dict[int, list] = {}
    for index, polygon in enumerate(polygons):
        by_count.setdefault(len(polygon), []).append(index)
    return [(np.array(indices), np.array([polygons[i] for i in indices], dtype=float))
            for indices in by_count.values()]


def shade_regions(ax, solution, polygons: dict):
    """Fill each region's polygon (``polygons[id]``, data units) by its stress.

    Adds the colour bar and returns it (``matplotlib.colorbar.Colorbar``).
    """
    norm = stress_norm(solution)
    cmap = light_cmap()
    shown = [r for r in solution.regions if r.id in polygons]
    sigma = np.array([r.state.sigma for r in shown]) * GPA
    collection = None
    for indices, vertices in _polygon_arrays([polygons[r.id] for r in shown]):
        collection = PolyCollection(vertices, cmap=cmap, norm=norm, edgecolors="face",
                                    linewidths=0.2, zorder=0)
        collection.set_array(sigma[indices])
        ax.add_collection(collection, autolim=False)
    bar = ax.figure.colorbar(collection, ax=ax, pad=0.02, fraction=0.05)
    bar.set_label(COLORBAR_LABEL, fontsize=8)
    low, high = stress_range(solution)
    bar.ax.set_ylim(low, high)
    bar.set_ticks(stress_ticks(low, high))
    bar.ax.yaxis.set_major_formatter(FormatStrFormatter("%g"))
    return bar
