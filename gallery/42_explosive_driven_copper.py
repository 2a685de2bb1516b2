"""An explosive-driven copper plate, and the Gurney velocity it rings up towards.

A 10 mm PBX 9501 charge initiated at its free rear face drives a 2 mm copper plate (an
open-faced sandwich).  The detonation shocks the plate; its free surface jumps, then
each reverberation in the plate (a release from the free surface, a reshock from the
products still pushing behind it) raises the free-surface velocity in a step towards
the Gurney velocity of the geometry,

    V = sqrt(2E) [((1 + 2M/C)^3 + 1) / (6 (1 + M/C)) + M/C]^(-1/2),

with M and C the plate's and the charge's masses per unit area and E the energy per
unit mass of explosive turned into motion (here the products' heat of detonation q of
the JWL model, which all turns into motion as the products expand without limit).
"""

from __future__ import annotations

import math

import common

NAME = common.script_name(__file__)


def gurney_open_faced(ratio: float, energy: float) -> float:
    """Gurney velocity (m/s) of an open-faced sandwich of mass ratio ``M/C``."""
    return math.sqrt(2.0 * energy) / math.sqrt(((1.0 + 2.0 * ratio) ** 3 + 1.0)
                                               / (6.0 * (1.0 + ratio)) + ratio)


def main() -> None:
    solution = common.solve(NAME)
    charge, plate = solution.scene.layers
    ratio = plate.material.rho0 * plate.thickness / (charge.material.rho0 * charge.thickness)
    q = charge.material.products.q
    gurney = gurney_open_faced(ratio, q)
    figure, ax_xt, ax_record = common.xt_record_figure(
        solution, "PBX 9501 (10 mm) driving a 2 mm copper plate: ring-up towards the Gurney "
                  "velocity", numbers=False)
    edges, velocity = common.surface_velocity(solution)
    common.plot_record(ax_record, edges, velocity, label="free-surface velocity (engine)")
    ax_record.axhline(gurney, color=common.RED, lw=1.0, ls="--",
                      label=f"Gurney, open-faced sandwich: {gurney:.0f} m/s")
    ax_record.set_xlim(0.0, solution.scene.t_end * common.US)
    ax_record.set_ylim(0.0, 1.25 * gurney)
    ax_record.set_xlabel("time t (µs)")
    ax_record.set_ylabel("free-surface velocity (m/s)")
    ax_record.set_title("copper free-surface velocity", fontsize=10)
    ax_record.legend(fontsize=8, loc="lower right")
    final = float(velocity[-1])
    balance = solution.accuracy_report["balance"]
    common.note(ax_record, f"M/C = {ratio:.3f}, sqrt(2q) = {math.sqrt(2 * q):.0f} m/s\n"
                f"at t = {solution.scene.t_end * common.US:.0f} µs: {final:.0f} m/s "
                f"({100 * (final / gurney - 1):+.1f} % of Gurney)\n"
                f"energy balance {100 * balance['energy_error']:+.2f} % of the content",
                xy=(0.02, 0.97))
    common.caption(figure, (
        f"The CJ detonation (8.80 km/s) reaches the copper and shocks it; the free surface "
        f"jumps and then rings up in steps, one per round trip in the plate, while the "
        f"products behind it expand to vacuum through the charge's free face. At the end "
        f"of the run the plate moves at {final:.0f} m/s against the Gurney estimate "
        f"{gurney:.0f} m/s for M/C = {ratio:.2f} (Gurney's linear-velocity model claims a "
        f"few per cent). Characteristic step 5 GPa; the products have no lattice, every "
        f"crossing of their rays is a Riemann problem."), y=0.02)
    common.save(figure, NAME, f"PBX 9501 driving 2 mm Cu: free surface rings up to "
                f"{final:.0f} m/s, Gurney {gurney:.0f} m/s (open-faced sandwich).")


if __name__ == "__main__":
    main()
