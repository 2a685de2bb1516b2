"""States a run reached beyond the data its equations of state were fitted to.

A Mie–Grüneisen entry of the library records ``up_max``, the top of the particle
velocity range of its ``Us = c0 + s up`` fit.  Beyond it the fit is extrapolated: the
run goes on (a hydrocode would too), and says so in one line per material, with the
largest principal-Hugoniot particle velocity its states correspond to.
"""

from __future__ import annotations

import math


def hugoniot_particle_velocity(material, v: float) -> float:
    """Particle velocity (m/s) of the principal-Hugoniot state at volume ``v`` (m^3/kg):
    ``up = sqrt(sigma_H (v0 - v))`` from the Rayleigh line through the reference state."""
    reference = material.reference_state()
    if not v < reference.v:
        return 0.0
    sigma = material.hugoniot(reference, v)[0]
    return math.sqrt(max(sigma - reference.sigma, 0.0) * (reference.v - v))


def fit_warnings(solution) -> list[str]:
    """One line for each material whose states went beyond its fitted range."""
    # the engine's regions and the lattices' cell volumes, read without building a
    # record per cell (a large run holds ~1e5 of them)
    pieces = solution.region_table.densest()
    pieces += [(p.material, float(p.cell_v.min())) for p in solution.patches if len(p.cell_v)]
    densest = {}
    for material, v in pieces:
        if getattr(material, "up_max", None) is None or not math.isfinite(v):
            continue
        key = id(material)
        if key not in densest or v < densest[key][1]:
            densest[key] = (material, v)
    return extrapolations(densest.values())


class FitExtrapolationWarning(UserWarning):
    """A state beyond the particle-velocity range an equation of state was fitted to."""


def extrapolations(pieces) -> list[str]:
    """One line for each ``(material, v)`` whose volume ``v`` (m^3/kg) lies beyond the
    principal-Hugoniot state at the top of the material's fitted data (``up_max``)."""
    found = []
    for material, v in pieces:
        if getattr(material, "up_max", None) is None or not math.isfinite(v):
            continue
        up = hugoniot_particle_velocity(material, v)
        if material.beyond_fit(up):
            found.append(f"{material.name}: compressed to the volume of the principal-"
                         f"Hugoniot state of up = {up:.4g} m/s, beyond the top of its fitted data "
                         f"(up_max = {material.up_max:.4g} m/s): the Us-up fit is "
                         "extrapolated there")
    return found
