"""Units and visual conventions shared by every figure.

The engine works in SI (m, s, Pa, m/s, kg/m³).  Figures use the units of the
field: position in mm, time in µs, stress in GPa (positive in compression, as
everywhere in the project), particle velocity in m/s, density in kg/m³.  The
factors below convert SI values to those units; the labels name them.
"""

from __future__ import annotations

MM = 1e3
"""Metres to millimetres."""
US = 1e6
"""Seconds to microseconds."""
GPA = 1e-9
"""Pascals to gigapascals."""

X_LABEL = "Lagrangian position X (mm)"
X_EULER_LABEL = "Eulerian position x (mm)"
T_LABEL = "time t (µs)"
SIGMA_LABEL = "stress σ (GPa, compression > 0)"
U_LABEL = "particle velocity u (m/s)"
RHO_LABEL = "density ρ (kg/m³)"

MATERIAL_COLORS = ("#1f4e9c", "#c0392b", "#2e8b57", "#8e44ad", "#d35400", "#16a085",
                   "#7f6000", "#555555")
"""Colours given to the scene's materials in order of first appearance in the stack."""

STRESS_CMAP = "RdBu_r"
"""Diverging colormap for stress: red for compression, blue for tension, white at zero."""

LABEL_FONTSIZE = 8.0
"""Font size (pt) of region numbers on every diagram."""


def material_colors(scene) -> dict[str, str]:
    """A colour per material name, in the order the materials appear in the stack."""
    colors: dict[str, str] = {}
    for layer in scene.layers:
        name = layer.material.name
        if name not in colors:
            colors[name] = MATERIAL_COLORS[len(colors) % len(MATERIAL_COLORS)]
    return colors


def title_of(solution, what: str) -> str:
    """Figure title: the scene's title (if any) followed by what the figure shows."""
    title = getattr(solution.scene, "title", "") or ""
    return f"{title}: {what}" if title else what
