"""Free fragments that rang in closed form, on an X–t diagram.

While a free fragment rings in closed form (``fronttrack.fragment``) the run tracks no
wave inside it: its waves bounce between its two free faces with period ``2L/C``.  The
diagram draws that stretch of X–t honestly, as a hatched band labelled with what it
is (the closed form's records are read by ``Solution.history`` and ``state_at``).
"""

from __future__ import annotations

from matplotlib.patches import Rectangle

from .style import MM, US

RING_STYLE = {"fill": False, "hatch": "////", "edgecolor": "#555555", "linewidth": 0.6,
              "zorder": 4}
"""The band's look: hatched, unfilled (the stress shading of its mean state shows
through)."""


def draw_rings(ax, solution) -> list:
    """Hatch each fragment that rang in closed form over its X range (mm) and its time
    (µs), labelled "ringing, period ... ns"; returns the patches."""
    patches = []
    for ring in solution.rings:
        slab = ring.slab
        x0, t0 = slab.x_lo * MM, slab.t0 * US
        width, height = (slab.x_hi - slab.x_lo) * MM, (ring.t_end - slab.t0) * US
        patch = Rectangle((x0, t0), width, height, **RING_STYLE)
        ax.add_patch(patch)
        ax.text(x0 + 0.5 * width, t0 + 0.25 * height,  # below the region number
                f"ringing\n(closed form,\nperiod {slab.period * 1e9:.3g} ns)", fontsize=6,
                ha="center", va="center", rotation=90 if width < 0.1 * height else 0,
                zorder=7, bbox={"boxstyle": "round,pad=0.1", "fc": "white", "ec": "none",
                                "alpha": 0.85})
        patches.append(patch)
    return patches
