"""Iron's α → ε transition: P1, P2 and the rarefaction shock of the reverse transformation.

A 0.5 mm iron flyer strikes 2 mm of iron at 1 km/s (``materials.phase_change``: the
α branch up to the 13 GPa transition stress, a straight mixed-phase line, the ε
branch; no strength).  The upper concave hull of the loading path splits the impact
shock into P1, which stops exactly at the transition stress, and the slower P2
behind it.  Release from the ε phase follows the lower convex hull: a fan down the ε
branch to the end of the mixed line, then a *rarefaction shock* across the mixed
region, the reverse transformation (Barker & Hollenbach 1974 saw it on release).
The target's free surface records the three arrivals: P1, P2, and the release.
The iron has no spall strength here, so that the release reaches the surface.

Left: X–t diagram (release shocks in blue).  Right: σ–u diagram and the free-
surface velocity of the target.
"""

from __future__ import annotations

import common

from materials import LEFT, Fan, solve_contact

NAME = common.script_name(__file__)
MM, US, GPA = common.MM, common.US, common.GPA


def main() -> None:
    solution = common.solve(NAME)
    flyer_layer, target_layer = solution.scene.layers
    iron = target_layer.material
    impact = solve_contact(iron, iron.reference_state(flyer_layer.velocity), iron,
                           iron.reference_state())
    p1, p2 = impact.right_waves
    star = impact.right_star
    fan, rarefaction = iron.wave_curve(star, LEFT).waves(0.0)
    assert isinstance(fan, Fan)
    rear = solution.history("right")
    t1 = target_layer.thickness / p1.speed

    figure, ax_xt, ax_su, ax_record = common.xt_su_record_figure(
        solution, "Iron on iron at 1 km/s: P1, P2 and the rarefaction shock of the reverse "
        "transformation")
    common.note(ax_su, f"P1: {p1.behind.sigma * GPA:.2f} GPa at {p1.speed:.0f} m/s "
                f"(u = {p1.behind.u:.0f} m/s)\nP2: {star.sigma * GPA:.2f} GPa at "
                f"{p2.speed:.0f} m/s\nrelease: fan {abs(fan.head_speed):.0f} → "
                f"{abs(fan.tail_speed):.0f} m/s to {fan.behind.sigma * GPA:.2f} GPa,\n"
                f"then a rarefaction shock at {abs(rarefaction.speed):.0f} m/s to 0",
                xy=(0.98, 0.03), ha="right", va="bottom")
    edges, values = common.surface_velocity(solution, "right")
    common.plot_record(ax_record, edges, values, label="target free surface")
    ax_record.set_xlabel("t (µs)")
    ax_record.set_ylabel("free-surface velocity (m/s)")
    ax_record.set_title("Free surface of the target", fontsize=10)
    peak = float(max(rear.u))
    u_fs1 = float(rear.u[1])
    t2 = float(rear.t[2])
    common.note(ax_record, f"P1 at {t1 * US:.3f} µs: {u_fs1:.0f} m/s\n"
                f"P2 at {t2 * US:.3f} µs: up to {peak:.0f} m/s\n"
                f"then the flyer's release", xy=(0.02, 0.97))
    text = (f"Iron (α → ε at {iron.transition_stress * GPA:.0f} GPa, transformation strain "
            f"{iron.transition_strain:.4f}) at 1 km/s on iron. The impact splits into P1 "
            f"({p1.behind.sigma * GPA:.1f} GPa, {p1.speed:.0f} m/s) and P2 "
            f"({star.sigma * GPA:.2f} GPa, {p2.speed:.0f} m/s). From the ε state the release "
            f"is a fan to {fan.behind.sigma * GPA:.2f} GPa (the end of the mixed line) and a "
            f"rarefaction shock at {abs(rarefaction.speed):.0f} m/s to zero: the chord below "
            f"the path's concave corner. The free surface jumps to {u_fs1:.0f} m/s at "
            f"{t1 * US:.3f} µs (P1 and its α-branch release), to {peak:.0f} m/s after P2, "
            f"and falls when the flyer's release arrives, which the reflected waves have "
            f"broken into steps. No hysteresis, no strength, no spall in this model.")
    common.caption(figure, text)
    common.save(figure, NAME, f"Iron at 1 km/s: P1 {p1.behind.sigma * GPA:.1f} GPa at "
                f"{p1.speed:.0f} m/s, P2 {star.sigma * GPA:.2f} GPa at {p2.speed:.0f} m/s; "
                f"release: fan then a rarefaction shock at {abs(rarefaction.speed):.0f} m/s "
                f"from {fan.behind.sigma * GPA:.2f} GPa to 0; free surface {u_fs1:.0f} → "
                f"{peak:.0f} m/s.")


if __name__ == "__main__":
    main()
