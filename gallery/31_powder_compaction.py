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
surface velocity of the powder.
"""

from __future__ import annotations

import common

from materials import solve_contact

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


if __name__ == "__main__":
    main()
