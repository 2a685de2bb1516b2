"""Figures of a front-tracking solution: X–t and σ–u diagrams, records, attenuation.

Every figure uses the units of the field (mm, µs, GPa, m/s, kg/m³) and the
project's sign convention (stress positive in compression).  Region numbers
are the region ids of the solution and are the same on the X–t and σ–u
diagrams of one figure set; ``placed_labels(ax)`` returns those placed on an
axes as ``{region_id: (x, y)}`` in the axes' data units.
"""

from .figures import save_standard_figures, xt_and_sigma_u
from .records import (
    plot_free_surface_velocity,
    plot_histories,
    plot_peak_stress,
    plot_profiles,
)
from .su import plot_sigma_u, plot_sigma_v
from .xt import placed_labels, plot_xt

__all__ = [
    "placed_labels", "plot_free_surface_velocity", "plot_histories", "plot_peak_stress",
    "plot_profiles", "plot_sigma_u", "plot_sigma_v", "plot_xt", "save_standard_figures",
    "xt_and_sigma_u",
]
