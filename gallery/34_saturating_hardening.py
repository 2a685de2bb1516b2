"""Saturating hardening through the engine: precursor, plastic fan and tangent plastic shock.

The solid of ``materials.saturating_plastic``: a Γ0 = 0 Us–up pressure plus a deviator
whose flow stress saturates (Voce, Y = Ys − (Ys − Y0) exp(−ε̄/εs)), so that the plastic
branch of the loading path is concave just beyond the Hugoniot elastic limit.  Its
wave curves are the hull construction of ``materials.hull`` (the upper concave hull of
σ(ε) for loading, the lower convex hull for release), which the engine's one Riemann
solver intersects like any other: the impact splits into the elastic precursor to the
HEL, a plastic fan on the concave stretch and a plastic shock whose chord is tangent to
the path where the fan ends.  The construction itself is gallery 27; here the waves
run, reflect and interact in a plate impact.  Illustrative parameters (those of
tests/test_hull.py), not a fit to a metal.

Left: X–t diagram.  Right: σ–u diagram and the target's free-surface velocity.
"""

from __future__ import annotations

import common
import numpy as np

from materials import LEFT, RIGHT, Fan, Shock, solve_contact

NAME = common.script_name(__file__)
MM, US, GPA = common.MM, common.US, common.GPA


def main() -> None:
    solution = common.solve(NAME)
    flyer_layer, target_layer = solution.scene.layers
    mat = target_layer.material
    impact = solve_contact(mat, mat.reference_state(flyer_layer.velocity), mat,
                           mat.reference_state())
    precursor, fan, shock = impact.right_waves
    assert isinstance(precursor, Shock) and isinstance(fan, Fan) and isinstance(shock, Shock)
    figure, ax_xt, ax_su, ax_record = common.xt_su_record_figure(
        solution, "Saturating hardening at 600 m/s: precursor, plastic fan and the tangent "
        "plastic shock")
    target_curve = mat.wave_curve(mat.reference_state(), RIGHT)
    flyer_curve = mat.wave_curve(mat.reference_state(flyer_layer.velocity), LEFT)
    sigmas = np.linspace(0.0, 1.15 * shock.behind.sigma, 200)
    for curve, sign, base, label in ((target_curve, 1.0, 0.0, "target's hull wave curve"),
                                     (flyer_curve, -1.0, flyer_layer.velocity,
                                      "flyer's hull wave curve")):
        u = [base + sign * curve.velocity_change(float(x))[0] for x in sigmas]
        ax_su.plot(u, sigmas * GPA, color=common.BLUE if sign > 0 else common.RED, lw=1.0,
                   label=label)
    ax_su.plot([precursor.behind.u, fan.behind.u], [precursor.behind.sigma * GPA,
               fan.behind.sigma * GPA], "s", color="black", ms=4,
               label="HEL and the fan's tail")
    ax_su.legend(fontsize=8, loc="upper left")
    edges, values = common.surface_velocity(solution, "right")
    common.plot_record(ax_record, edges, values, label="target free surface")
    # the note goes on the record's empty upper left: on the σ–u panel it would hide the
    # numbered states at σ = 0 near the flyer's velocity (1 and 7)
    common.note(ax_record, f"impact waves in the target:\nprecursor: "
                f"{precursor.behind.sigma * GPA:.3f} GPa at {precursor.speed:.0f} m/s\n"
                f"plastic fan: {fan.head_speed:.0f} → {fan.tail_speed:.0f} m/s to "
                f"{fan.behind.sigma * GPA:.2f} GPa\nplastic shock: {shock.speed:.0f} m/s to "
                f"{shock.behind.sigma * GPA:.2f} GPa")
    ax_record.set_xlabel("t (µs)")
    ax_record.set_ylabel("free-surface velocity (m/s)")
    ax_record.set_title("Free surface of the target", fontsize=10)
    text = (f"{flyer_layer.thickness * MM:g} mm on {target_layer.thickness * MM:g} mm of the "
            f"same Voce-hardening solid (Y0 {mat.yield_strength * GPA:.1f} → Ys "
            f"{mat.saturation_strength * GPA:.1f} GPa over εs {mat.saturation_strain:g}) at "
            f"{flyer_layer.velocity:.0f} m/s. Impact: precursor to the HEL "
            f"{precursor.behind.sigma * GPA:.3f} GPa at {precursor.speed:.0f} m/s, a plastic "
            f"fan {fan.head_speed:.0f} → {fan.tail_speed:.0f} m/s to "
            f"{fan.behind.sigma * GPA:.2f} GPa and a plastic shock at {shock.speed:.0f} m/s "
            f"(equal to the fan's tail speed: the chord is tangent to the path) to "
            f"{shock.behind.sigma * GPA:.2f} GPa. Fans are drawn as "
            f"{solution.scene.accuracy.rays_per_fan} rays.")
    common.caption(figure, text)
    common.save(figure, NAME, f"Voce hardening at {flyer_layer.velocity:.0f} m/s: precursor "
                f"{precursor.behind.sigma * GPA:.3f} GPa at {precursor.speed:.0f} m/s, plastic "
                f"fan {fan.head_speed:.0f} → {fan.tail_speed:.0f} m/s to "
                f"{fan.behind.sigma * GPA:.2f} GPa, tangent plastic shock at "
                f"{shock.speed:.0f} m/s to {shock.behind.sigma * GPA:.2f} GPa.")


if __name__ == "__main__":
    main()
