"""An explosive-driven copper plate, and the Gurney velocity it rings up towards.

A 10 mm charge of the book's TNT (gamma-law products, Γ = 2.6, q = 4.9 MJ/kg) initiated
at its free rear face drives a 2 mm copper plate: an open-faced sandwich.  The copper is
linear elastic with copper's density and bulk sound speed (Gurney's plate is rigid; with
copper's Mie–Grüneisen lattices the run takes over ten minutes on the project's machine).
The detonation shocks the plate; its free surface jumps at each arrival of the
reverberating wave, while the plate's mean velocity (its momentum over its mass) rises in
steps towards Gurney's value for the geometry (``fronttrack.gurney``),

    V = sqrt(2E) [((1 + 2M/C)^3 + 1) / (6 (1 + M/C)) + M/C]^(-1/2),

with E = q: the products expand without limit, so all their heat of detonation ends as
kinetic energy.
"""

from __future__ import annotations

import math

import common
import numpy as np

from fronttrack.gurney import gurney_energy, gurney_velocity, plate_velocity

NAME = common.script_name(__file__)


def main() -> None:
    solution = common.solve(NAME)
    charge, plate = solution.scene.layers
    ratio = plate.material.rho0 * plate.thickness / (charge.material.rho0 * charge.thickness)
    energy = gurney_energy(charge.material)
    gurney = gurney_velocity("open-faced", ratio, energy)
    t_end = solution.scene.t_end
    figure, ax_xt, ax_record = common.xt_record_figure(
        solution, "TNT (10 mm, gamma-law products) driving a 2 mm copper plate (linear "
                  "elastic): ring-up towards the Gurney velocity", numbers=False)
    edges, velocity = common.surface_velocity(solution)
    common.plot_record(ax_record, edges, velocity, label="free-surface velocity")
    times = np.linspace(0.0, t_end, 121)[1:]
    mean = [plate_velocity(solution, 1, t) for t in times]
    ax_record.plot(times * common.US, mean, color="#444444", lw=1.2,
                   label="plate mean velocity (momentum / mass)")
    ax_record.axhline(gurney, color=common.RED, lw=1.0, ls="--",
                      label=f"Gurney, open-faced sandwich: {gurney:.0f} m/s")
    ax_record.set_xlim(0.0, t_end * common.US)
    ax_record.set_ylim(0.0, 1.25 * max(float(np.max(velocity)), gurney))  # room for the legend
    ax_record.set_xlabel("time t (µs)")
    ax_record.set_ylabel("velocity (m/s)")
    ax_record.set_title("copper plate", fontsize=10)
    ax_record.legend(fontsize=8, loc="upper left")
    final = mean[-1]
    balance = solution.accuracy_report["balance"]
    common.note(ax_record, f"M/C = {ratio:.3f}, sqrt(2E) = sqrt(2q) = "
                f"{math.sqrt(2.0 * energy):.0f} m/s\n"
                f"plate at {t_end * common.US:.0f} µs: {final:.0f} m/s "
                f"({100.0 * (final / gurney - 1.0):+.1f} % of Gurney)\n"
                f"balance: momentum {100.0 * balance['momentum_error']:.2f} %, energy "
                f"{100.0 * balance['energy_error']:+.2f} % (promised "
                f"{100.0 * balance['promised']:.1f} %)", xy=(0.98, 0.03), ha="right",
                va="bottom")
    common.caption(figure, (
        "The free surface jumps at each arrival of the reverberating wave and falls back in "
        "steps as the release reflected at the products returns: the linear elastic plate "
        "rings about its mean velocity without loss. The mean (momentum over mass) rises in "
        f"steps towards Gurney's {gurney:.0f} m/s for M/C = {ratio:.2f} while the products "
        "expand to vacuum through the charge's free face. Step 5 GPa, waves below 0.1 GPa "
        "dropped."), y=0.015)
    common.save(figure, NAME, f"TNT driving 2 mm Cu: the plate reaches {final:.0f} m/s at "
                f"{t_end * common.US:.0f} µs, Gurney {gurney:.0f} m/s (open-faced sandwich).")


if __name__ == "__main__":
    main()
