"""Figures of a front-tracking solution: X–t and σ–u diagrams, records, attenuation.

Every figure uses the units of the field (mm, µs, GPa, m/s, kg/m³) and the
project's sign convention (stress positive in compression).  Regions are
numbered 1, 2, 3 … in reading order (``fronttrack.numbering``), the same
numbers on the X–t, σ–u and σ–ρ diagrams of one figure set and in
``solution.json``.  The diagram functions return a ``Placed`` record of what
they drew (numbers, label positions, texts, title pad, colour bar).
"""

from ..numbering import region_numbers
from .attenuation import peak_stress, peak_stress_steps
from .figures import FIGURE_NAMES, save_standard_figures, xt_and_sigma_u
from .placed import Placed
from .records import (
    plot_free_surface_velocity,
    plot_histories,
    plot_peak_stress,
    plot_profiles,
    pullback,
)
from .stress_shading import light_cmap, stress_norm
from .su import number_list, plot_sigma_rho, plot_sigma_u
from .xt import XT_FIGSIZE, plot_xt

__all__ = [
    "FIGURE_NAMES", "XT_FIGSIZE", "Placed", "light_cmap", "number_list", "peak_stress",
    "peak_stress_steps", "plot_free_surface_velocity", "plot_histories", "plot_peak_stress",
    "plot_profiles", "plot_sigma_rho", "plot_sigma_u", "plot_xt", "pullback",
    "region_numbers", "save_standard_figures", "stress_norm", "xt_and_sigma_u",
]
