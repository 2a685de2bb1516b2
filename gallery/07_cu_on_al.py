"""A Cu flyer on an Al 2024 target at 1 km/s: impedance match, release, spall, VISAR record.

A 1 mm copper flyer strikes a 5 mm Al 2024 target.  Cu has 2.4 times the shock
impedance of Al, so the contact keeps most of the flyer's velocity.  The
release fans from the flyer's back face and from the target's free rear face
meet near the rear of the target and spall it (instantaneous threshold 1.2 GPa;
every fracture the threshold reaches is kept, giving a zone of spall planes).
"""

from __future__ import annotations

import common

NAME = common.script_name(__file__)


def main() -> None:
    solution = common.solve(NAME)
    g = common.GPA
    target = solution.state_at(1.5e-3, 0.15e-6)    # behind the shock in the Al
    figure, ax_xt, ax_su, ax_rec = common.xt_su_record_figure(
        solution, "Cu flyer (1 mm) on Al 2024 (5 mm) at 1 km/s", bottom=0.185)
    edges, velocity = common.surface_velocity(solution, "right")
    common.plot_record(ax_rec, edges, velocity, label="rear free surface (engine)")
    arrival = edges[1]
    plateau = velocity[1]
    ax_rec.axhline(2.0 * target.u, color="#777777", lw=0.8, ls=":",
                   label=f"2 u_p = {2 * target.u:.0f} m/s")
    ax_rec.set_xlim(0.0, solution.scene.t_end * common.US)
    ax_rec.set_ylim(-50.0, 1.35 * plateau)
    ax_rec.set_xlabel("time t (µs)")
    ax_rec.set_ylabel("velocity (m/s)")
    ax_rec.set_title("rear free-surface velocity (what a VISAR/PDV records)", fontsize=10)
    ax_rec.legend(fontsize=7.5, loc="upper left")
    low = min(velocity[1:])
    common.note(ax_rec, f"arrival {arrival:.3f} µs, plateau {plateau:.0f} m/s\n"
                f"pullback to {low:.0f} m/s, Δu = {plateau - low:.0f} m/s", xy=(0.98, 0.04),
                ha="right", va="bottom")
    common.note(ax_su, f"impact: Cu and Al at {target.sigma * g:.2f} GPa,\n"
                f"  both at {target.u:.0f} m/s (Cu slowed from 1000 m/s)", xy=(0.02, 0.97))
    bottom, top = ax_su.get_ylim()
    ax_su.set_ylim(bottom, 1.3 * top)
    spalls = solution.spalls
    first = spalls[0]
    zone = [s for s in spalls if abs(s.x - first.x) < 0.6e-3]
    later = [s for s in spalls if abs(s.x - first.x) >= 0.6e-3]
    span = max(s.x for s in zone) - min(s.x for s in zone)
    second = (f" At {min(s.t for s in later) * common.US:.2f} µs a second zone of "
              f"{len(later)} planes opens near X = {later[0].x * common.MM:.1f} mm, inside the "
              f"plate left behind the first spall zone."
              if later else "")
    text = (f"The impact state is where the Cu Hugoniot from 1000 m/s (falling to the right) "
            f"crosses the Al Hugoniot from rest: {target.sigma * g:.2f} GPa, u = "
            f"{target.u:.0f} m/s. The shock reaches the rear face at {arrival:.3f} µs, which "
            f"jumps to {plateau:.0f} m/s (2 u_p = {2 * target.u:.0f} m/s). The release from "
            f"the flyer's back face (it crosses the interface into the Al) meets the release "
            f"from the free surface; the tension reaches the 1.2 GPa spall strength at "
            f"X = {first.x * common.MM:.2f} mm, t = {first.t * common.US:.2f} µs. The "
            f"instantaneous threshold then fractures {len(zone)} planes within "
            f"{span * common.MM:.2f} mm (a damage zone; spall_spacing 0), and the free "
            f"surface falls by only {plateau - low:.0f} m/s before the spall signal turns it "
            f"back up.{second}")
    common.caption(figure, text)
    common.save(figure, NAME, f"Cu on Al 2024 at 1 km/s: impact state {target.sigma * g:.2f} "
                f"GPa at {target.u:.0f} m/s; free surface {plateau:.0f} m/s; spall at "
                f"X = {first.x * common.MM:.2f} mm, t = {first.t * common.US:.2f} µs, a zone of "
                f"{len(zone)} planes within {span * common.MM:.2f} mm (no spall_spacing); "
                f"pullback {plateau - low:.0f} m/s.")


if __name__ == "__main__":
    main()
