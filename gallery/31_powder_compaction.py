"""A powder layer under impact: the elastic precursor and the compaction wave (p–α).

A 1 mm copper flyer at 500 m/s strikes 2 mm of pressed copper powder (6.4 g/cm³,
distension α0 = 1.395; the p–α model of ``materials.porous`` with Boade's
exponential crush curve).  The impact sends into the powder an elastic precursor
to the crush stress (0.14 GPa) at the matrix's speed and, far behind it, the
compaction shock that squeezes the pores out.  The σ–u diagram shows the powder's
composite wave curve: the short steep precursor chord, then the shallow
compaction branch.  At the free surface the precursor reflects first: the
surface steps up by 2 σ_e / (ρ0 C) at each of its echoes between the surface and
the oncoming compaction shock, before the compaction shock itself arrives.

Top: X–t and σ–u diagrams with the same region numbers.  Bottom right: the free-
surface velocity of the powder.  A second figure shows the porous Hugoniots of the
strong-shock model (Davison §11.2): copper compacted fully in one shock from several
distensions; above α0 = 1 + 2/Γ0 the compressed density falls as the stress rises
(the anomalous Hugoniot).
"""

from __future__ import annotations

import common
import numpy as np
from matplotlib.figure import Figure

from materials import RIGHT, PorousSolid, StateOutOfRangeError, get, solve_contact

NAME = common.script_name(__file__)
MM, US, GPA = common.MM, common.US, common.GPA


def main() -> None:
    solution = common.solve(NAME)
    flyer, powder = (layer.material for layer in solution.scene.layers)
    velocity = solution.scene.layers[0].velocity
    impact = solve_contact(flyer, flyer.reference_state(velocity), powder,
                           powder.reference_state())
    precursor, compaction = impact.right_waves
    star = impact.right_star
    alpha = powder.distension(star)
    rear = solution.history("right")
    thickness = solution.scene.layers[1].thickness
    arrival = thickness / compaction.speed

    figure, ax_xt, ax_su, ax_record = common.xt_su_record_figure(
        solution, "Cu at 500 m/s on pressed Cu powder: elastic precursor and compaction wave")
    common.note(ax_su, f"precursor: {precursor.behind.sigma * GPA:.3f} GPa at "
                f"{precursor.speed:.0f} m/s\ncompaction shock: {star.sigma * GPA:.2f} GPa at "
                f"{compaction.speed:.0f} m/s\ndistension {powder.alpha0:.3f} → {alpha:.3f}, "
                f"u = {star.u:.1f} m/s", xy=(0.02, 0.97))
    edges, values = common.surface_velocity(solution, "right")
    common.plot_record(ax_record, edges, values, label="powder free surface")
    ax_record.axvline(arrival * US, color=common.RED, lw=0.8, ls="--")
    ax_record.set_xlabel("t (µs)")
    ax_record.set_ylabel("free-surface velocity (m/s)")
    ax_record.set_title("Free surface of the powder", fontsize=10)
    first_step = float(rear.u[1])
    common.note(ax_record, f"each precursor echo: +{first_step:.1f} m/s\n"
                f"dashed: the compaction shock would reach the surface at "
                f"{arrival * US:.2f} µs\nif nothing slowed it", xy=(0.02, 0.97))
    text = (f"Pressed copper powder (ρ00 = {powder.rho0:.0f} kg/m³, α0 = {powder.alpha0:.3f}) "
            f"struck by copper at {velocity:.0f} m/s. The elastic precursor runs at the matrix "
            f"speed ({precursor.speed:.0f} m/s) to the crush stress "
            f"{precursor.behind.sigma * GPA:.2f} GPa; the compaction shock follows at only "
            f"{compaction.speed:.0f} m/s to {star.sigma * GPA:.2f} GPa and distension "
            f"{alpha:.3f} (the powder is {100 * (1 - alpha / powder.alpha0):.1f} % denser "
            f"behind it, for good: release keeps α). The precursor rings between the free "
            f"surface and the compaction shock, stepping the surface up by {first_step:.1f} "
            f"m/s at each echo. The model's precursor runs at the matrix's bulk speed; "
            f"Boade measured ~1.9 km/s (the reversible elastic α(p) is not modelled).")
    common.caption(figure, text)
    common.save(figure, NAME, f"Cu at {velocity:.0f} m/s on Cu powder (α0 = "
                f"{powder.alpha0:.3f}): precursor {precursor.behind.sigma * GPA:.2f} GPa at "
                f"{precursor.speed:.0f} m/s, compaction shock {star.sigma * GPA:.2f} GPa at "
                f"{compaction.speed:.0f} m/s to α = {alpha:.3f}; the free surface rings up by "
                f"{first_step:.1f} m/s per precursor echo.")


def hugoniot_figure() -> None:
    """Porous Hugoniots of copper (full compaction in one shock) for several ``alpha0``."""
    copper = get("Cu")
    figure = Figure(figsize=(9.0, 6.2))
    ax = figure.add_axes((0.1, 0.26, 0.86, 0.64))
    limit = 1.0 + 2.0 / copper.gamma0
    anomalous = []
    for alpha0, color in ((1.0, "#222222"), (1.4, "#1f4e9c"), (1.8, "#2e8b57"),
                          (2.0, "#c08000"), (2.1, common.RED)):
        body = PorousSolid(f"Cu alpha0 {alpha0}", copper, alpha0)
        curve = body.wave_curve(body.reference_state(), RIGHT)
        stresses, densities = [], []
        for sigma in np.geomspace(0.2e9, 120e9, 160):
            try:
                state = curve.state_at(float(sigma))
            except StateOutOfRangeError:
                break
            stresses.append(sigma * GPA)
            densities.append(state.rho / copper.rho0)
        ax.plot(densities, stresses, color=color, lw=1.6, label=f"α0 = {alpha0:g}")
        if alpha0 > limit:
            anomalous.append((alpha0, densities[0], densities[-1], stresses[-1]))
    ax.axvline(1.0, color="#888888", lw=0.8, ls=":")
    ax.set_xlabel("ρ / ρ_s0 behind the shock")
    ax.set_ylabel("σ (GPa)")
    ax.legend(loc="center right", fontsize=9)
    ax.set_title("Strong shocks in porous copper: the porous Hugoniot (Davison §11.2)",
                 fontsize=11)
    alpha0, first, last, top = anomalous[-1]
    text = (f"Copper (Γ0 = {copper.gamma0:g}) compacted fully in one shock from distension α0: "
            f"σ = A(v) / (1 − ρ_s0 Γ0 (v00 − v)/2) from the Mie–Grüneisen matrix and the "
            f"Rankine–Hugoniot energy. The shock heating grows with α0; above α0 = "
            f"{limit:.2f} (= 1 + 2/Γ0) the compressed density falls as the stress rises: "
            f"for α0 = {alpha0:g} from {first:.3f} ρ_s0 to {last:.3f} ρ_s0 at {top:.0f} GPa "
            f"(the curves stop at the matrix's fitted range).")
    common.caption(figure, text, width=120)
    common.save(figure, f"{NAME}_hugoniots", f"Porous Hugoniots of copper: for α0 = "
                f"{alpha0:g} > 1 + 2/Γ0 = {limit:.2f} the density behind the shock falls "
                f"from {first:.3f} to {last:.3f} ρ_s0 as σ rises to {top:.0f} GPa.")


if __name__ == "__main__":
    main()
    hugoniot_figure()
