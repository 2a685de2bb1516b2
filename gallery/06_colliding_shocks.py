"""Colliding shocks: an Al 2024 plate struck from both sides by Cu flyers at ±1 km/s.

The two shocks meet in the middle of the plate.  By symmetry the collision plane
does not move, so each shock reflects from the other as from a rigid wall: two
reshocks run back out, and the stress behind them is a little more than twice
that of one shock.  The lower right panel is the stress history at the
collision plane (one jump to the final stress) and 1 mm inside the plate (two
steps).
"""

from __future__ import annotations

import common

NAME = common.script_name(__file__)


def main() -> None:
    solution = common.solve(NAME)
    g = common.GPA
    single = solution.state_at(2.0e-3, 0.2e-6)     # behind one shock, before the collision
    centre = solution.history(3.0e-3)
    quarter = solution.history(2.0e-3)
    collided = max(centre.sigma)
    t_collide = centre.t[1] * common.US
    figure, ax_xt, ax_su, ax_rec = common.xt_su_record_figure(
        solution, "Colliding shocks: two Cu flyers strike an Al 2024 plate at ±1 km/s")
    t_end = solution.scene.t_end
    for history, label, color in ((centre, "collision plane, X = 3 mm", common.RED),
                                  (quarter, "X = 2 mm (1 mm inside the plate)", common.BLUE)):
        edges, values = common.steps(history, history.sigma * g, t_end)
        common.plot_record(ax_rec, edges, values, label=label, color=color)
    ax_rec.axhline(2.0 * single.sigma * g, color="#777777", lw=0.8, ls=":",
                   label=f"2 × one shock = {2 * single.sigma * g:.1f} GPa")
    ax_rec.set_xlim(0.0, t_end * common.US)
    ax_rec.set_ylim(-1.0, 1.3 * collided * g)
    ax_rec.set_xlabel("time t (µs)")
    ax_rec.set_ylabel("stress σ (GPa)")
    ax_rec.set_title("stress histories in the Al plate", fontsize=10)
    ax_rec.legend(fontsize=7.5, loc="upper left")
    common.note(ax_su, f"one shock in Al: {single.sigma * g:.2f} GPa, "
                f"{single.u:.0f} m/s\nafter the collision: {collided * g:.2f} GPa, u = 0\n"
                f"= {collided / single.sigma:.2f} × one shock", xy=(0.02, 0.97))
    bottom, top = ax_su.get_ylim()
    ax_su.set_ylim(bottom, 1.35 * collided * g)
    text = (f"Each Cu flyer drives a {single.sigma * g:.2f} GPa shock (u = ±{abs(single.u):.0f} "
            f"m/s) into the aluminium. The shocks collide at the mid-plane at "
            f"{t_collide:.3f} µs; by symmetry the velocity there is zero, so each reflects as "
            f"from a rigid wall (compare 04): the stress jumps to {collided * g:.2f} GPa, "
            f"{collided / single.sigma:.2f} times one shock, because the reshocks run on "
            f"Hugoniots centred on the shocked states. The reshocks then cross the Al|Cu "
            f"faces, where part of them is reflected, while the release fans from the flyers' "
            f"back faces arrive.")
    common.caption(figure, text)
    common.save(figure, NAME, f"Two Cu flyers at ±1 km/s on an Al 2024 plate: each shock is "
                f"{single.sigma * g:.2f} GPa; their collision at the mid-plane raises the "
                f"stress to {collided * g:.2f} GPa ({collided / single.sigma:.2f} × one shock) "
                f"at u = 0.")


if __name__ == "__main__":
    main()
