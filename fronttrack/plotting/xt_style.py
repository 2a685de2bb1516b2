"""Line styles of the X–t diagram (see ``plotting.xt`` for what each one marks)."""

from __future__ import annotations

from matplotlib import patheffects

SHOCK = {"color": "black", "lw": 1.7}
"""A compressive shock (full width; weaker shocks thinner, see ``shock_width``)."""
RELEASE_SHOCK = {"color": "#23408e", "lw": 1.7}
"""A rarefaction shock: Hugoniot release, or any release in a linear elastic solid."""
SHOCK_MIN_WIDTH = 0.6
RAY = {"color": "#4a6fa5", "lw": 0.4, "alpha": 0.35}
"""A ray of a fan: light, blue-grey and translucent, so that a dense fan (or a
lattice of crossing fans) reads as a shaded band, never as a shock."""
EDGE_RAY = {"color": "#2b4a7a", "lw": 0.8, "alpha": 0.9, "ls": (0, (4, 2))}
"""The head and tail ray of a fan of several rays: dashed, in the fans' colour."""
INTERFACE = {"color": "#4d4d4d", "lw": 1.0, "ls": (0, (5, 3))}
CONTACT = {"color": "#9a9a9a", "lw": 0.8, "ls": (0, (1, 2))}
GAP = {"color": "white", "lw": 1.6,
       "path_effects": [patheffects.Stroke(linewidth=3.4, foreground="black", capstyle="butt"),
                        patheffects.Normal()]}
"""A gap in the Lagrangian view: a double line (white core on a black stroke)."""
GAP_FACE = {"color": "black", "lw": 0.8}
"""A face of an open gap in the Eulerian view (the void between is hatched)."""
VOID = {"facecolor": "white", "edgecolor": "#777777", "hatch": "////"}
SPALL = {"marker": "*", "color": "#d62728", "markersize": 11, "markeredgecolor": "#6b0000",
         "markeredgewidth": 0.6, "zorder": 6}


def shock_width(jump: float, scale: float) -> float:
    """Line width (pt) of a shock: heavy for a strong one, thinner for a weak one.

    Full width for jumps of half the scene's stress scale or more, so
    that trains of weak shocks (a fan transmitted into a linear elastic solid, a
    compression wave made of shocklets) do not read as one heavy band.
    """
    fraction = min(1.0, abs(jump) / (0.5 * scale)) if scale > 0.0 else 1.0
    return SHOCK_MIN_WIDTH + (SHOCK["lw"] - SHOCK_MIN_WIDTH) * fraction
