"""Reflection from a rigid wall: the reshock and the "twice the stress" rule.

An Al 2024 flyer (3 mm) at 1 km/s strikes a 2 mm Al 2024 target backed by an
immovable wall.  The wall stops the material (u = 0), so the shock reflects as a
reshock; the stress behind it is on the Hugoniot centred on the first shocked
state.  The figure compares it with the acoustic rule (twice the first stress)
and with the mirrored-principal-Hugoniot shortcut.
"""

from __future__ import annotations

import common
import numpy as np

NAME = common.script_name(__file__)


def main() -> None:
    solution = common.solve(NAME)
    scene = solution.scene
    al = scene.layers[1].material
    first = solution.state_at(4.0e-3, 0.25e-6)     # behind the impact shock in the target
    wall = solution.history("right")
    reflected = max(wall.sigma)                     # behind the reshock, at the wall

    def principal(u):                               # Al 2024 principal Hugoniot (Pa)
        return al.rho0 * (al.c0 + al.s * u) * u

    mirrored = principal(2.0 * first.u)             # the shortcut: mirror about u1
    g = common.GPA
    figure, ax_xt, ax_su = common.xt_su_figure(
        solution, "Reflection from a rigid wall: the reshock stops the material (u = 0)")
    # the shortcut's curve, for comparison with the exact reshock Hugoniot
    u = np.linspace(0.0, first.u, 60)
    ax_su.plot(u, principal(2.0 * first.u - u) * g, color="#777777", lw=1.0, ls=":",
               zorder=2, label="mirrored principal Hugoniot")
    ax_su.plot([0.0], [mirrored * g], marker="x", color="#555555", ms=6, ls="none")
    ax_su.plot([0.0], [2.0 * first.sigma * g], marker="_", color="#8b0000", ms=14, mew=1.6,
               ls="none")
    handles, labels = ax_su.get_legend_handles_labels()
    legend = ax_su.get_legend()
    if legend is not None:
        extra = legend.legend_handles + handles
        ax_su.legend(handles=extra, fontsize=7.5, loc="upper right", framealpha=0.9,
                     title=legend.get_title().get_text(), title_fontsize=7.5)
    err_mirror = (mirrored - reflected) / reflected * 100.0
    err_double = (2.0 * first.sigma - reflected) / reflected * 100.0
    common.note(ax_su, f"first shock: {first.sigma * g:.2f} GPa, {first.u:.0f} m/s\n"
                f"at the wall (exact reshock): {reflected * g:.2f} GPa\n"
                f"2 × first stress (acoustic): {2 * first.sigma * g:.2f} GPa "
                f"({common.signed(err_double, 1)} %)\n"
                f"mirrored Hugoniot (×): {mirrored * g:.2f} GPa "
                f"({common.signed(err_mirror, 1)} %)", xy=(0.02, 0.97))
    bottom, top = ax_su.get_ylim()
    ax_su.set_ylim(bottom, 1.4 * reflected * g)
    text = (f"The impact shock ({first.sigma * g:.2f} GPa, u = {first.u:.0f} m/s) reaches the "
            f"wall at {wall.t[1] * common.US:.2f} µs and reflects as a second shock that brings "
            f"the aluminium to "
            f"rest. The state at the wall is on the Hugoniot centred on the first shocked "
            f"state (solid blue, rising to the left): {reflected * g:.2f} GPa, "
            f"{reflected / first.sigma:.2f} times the first stress. The acoustic rule (2σ, red "
            f"tick) is {abs(err_double):.1f} % low because the shocked Al is stiffer; the "
            f"mirrored principal Hugoniot (dotted, ×), which ignores the entropy of the first "
            f"shock, is only {abs(err_mirror):.1f} % off at this strength.")
    common.caption(figure, text)
    common.save(figure, NAME, f"Al 2024 at 1 km/s against a rigid wall: first shock "
                f"{first.sigma * g:.2f} GPa; the reshock brings the wall stress to "
                f"{reflected * g:.2f} GPa (2σ rule {2 * first.sigma * g:.2f} GPa, mirrored "
                f"principal Hugoniot {mirrored * g:.2f} GPa).")


if __name__ == "__main__":
    main()
