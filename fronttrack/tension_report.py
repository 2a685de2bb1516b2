"""Materials that carried tension with nothing to stop it: no spall strength.

A solid without ``spall_strength`` never fractures (``math.inf``), so it takes any
tension the waves bring, however unphysical (release waves meeting in a LiF
window can pull it to several GPa).  The run summary names such materials when
the tension they carried exceeds ``TYPICAL_STRENGTH``, the dynamic tensile
strength of the weakest common solids (polymers spall at about 0.1–0.2 GPa,
metals at 1–6 GPa; Antoun et al., *Spall Fracture*, 2003): beyond it a real
sample would probably have failed.  Units: Pa, m, s.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

TYPICAL_STRENGTH = 0.1e9
"""Tension (Pa) beyond which a solid without a spall strength is reported."""


@dataclass(frozen=True)
class UnlimitedTension:
    """The largest tension ``sigma`` (Pa, negative) carried by ``material``, at ``x``, ``t``."""

    material: str
    sigma: float
    x: float
    t: float

    def message(self) -> str:
        """One line for the run summary."""
        return (f"{self.material} carried {-self.sigma / 1e9:.3g} GPa of tension (at X = "
                f"{self.x * 1e3:.4g} mm, t = {self.t * 1e6:.4g} us) and has no spall strength: "
                f"it cannot fracture in this run (typical solids spall at 0.1-6 GPa; give it "
                f"spall_strength to allow it)")


def unlimited_tension(solution, threshold: float = TYPICAL_STRENGTH) -> list[UnlimitedTension]:
    """Materials without a spall strength whose largest tension exceeds ``threshold`` (Pa).

    Returns one record per such material, in the order of the stack, at the
    region of its lowest stress (the point of the region's polygon that comes
    first in time).
    """
    lowest: dict[str, object] = {}
    for region in solution.regions:
        material = region.material
        if math.isfinite(getattr(material, "spall_strength", math.inf)):
            continue
        name = material.name
        if region.state.sigma < -threshold and (
                name not in lowest or region.state.sigma < lowest[name].state.sigma):
            lowest[name] = region
    order = list(dict.fromkeys(layer.material.name for layer in solution.scene.layers))
    found = []
    for name in order:
        if name in lowest:
            region = lowest[name]
            x, t = min(region.vertices, key=lambda p: (p[1], p[0]))
            found.append(UnlimitedTension(name, region.state.sigma, x, t))
    return found
