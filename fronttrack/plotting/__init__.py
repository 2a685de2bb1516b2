"""Figures of a front-tracking solution: X–t and σ–u diagrams, records, attenuation.

Every figure uses the units of the field (mm, µs, GPa, m/s, kg/m³) and the
project's sign convention (stress positive in compression).  Region numbers
are the region ids of the solution and are the same on the X–t and σ–u
diagrams of one figure set.
"""

from .xt import placed_labels, plot_xt

__all__ = ["placed_labels", "plot_xt"]
