"""The explosive-loading spall experiment (Davison §12.1.2).

A layer of Composition B in contact with an aluminium 6061 plate is initiated at its
free face.  The plate receives a pulse that rises at once to a peak far above its spall
strength and falls gradually behind it: the Taylor wave of the products.  When the
pulse reflects from the plate's free rear face, the reflected release meets the
decaying tail of the incoming pulse and the net tension reaches the spall strength a
short distance inside the rear face: a thin layer spalls off.
"""

from __future__ import annotations

import common
import numpy as np

NAME = common.script_name(__file__)


def main() -> None:
    solution = common.solve(NAME)
    charge, plate = solution.scene.layers
    g, mm, us = common.GPA, common.MM, common.US
    figure, ax_xt, ax_record = common.xt_record_figure(
        solution, "Explosive loading of aluminium 6061 (Comp B, 3 mm, on 6 mm): peaked "
                  "pulse and spall", numbers=False)
    station = charge.thickness + 0.25 * plate.thickness
    history = solution.history(station)
    t = np.linspace(0.0, solution.scene.t_end, 800)
    sigma = [common.value_at(history, ti) for ti in t]
    ax_record.plot(t * us, np.array(sigma) * g, color=common.BLUE, lw=1.5,
                   label=f"stress at X = {station * mm:.0f} mm (in the plate)")
    strength = plate.material.spall_strength
    ax_record.axhline(-strength * g, color=common.RED, lw=0.9, ls="--",
                      label=f"spall strength {strength * g:.1f} GPa (tension)")
    ax_record.set_xlabel("time t (µs)")
    ax_record.set_ylabel("stress σ (GPa, compression > 0)")
    ax_record.set_title("the pulse in the plate, a quarter of the way in", fontsize=10)
    ax_record.set_xlim(0.0, solution.scene.t_end * us)
    ax_record.grid(True, lw=0.3, alpha=0.5)
    ax_record.legend(fontsize=8, loc="center right")
    peak = max(sigma)
    spalls = solution.spalls
    in_plate = [s for s in spalls if s.x > charge.thickness]
    where = (f"the first spall plane opens at X = {in_plate[0].x * mm:.2f} mm "
             f"({(solution.scene.length - in_plate[0].x) * mm:.2f} mm from the rear face), "
             f"t = {in_plate[0].t * us:.2f} µs, and more follow as the pulse's tail keeps "
             f"meeting its reflection (scabbing)" if in_plate else "no spall plane opens")
    common.note(ax_record, f"peak {peak * g:.1f} GPa = {peak / strength:.0f} × the spall "
                f"strength\n{len(in_plate)} spall planes in the plate, "
                f"{len(spalls) - len(in_plate)} where\nthe products cavitate near their "
                f"free face", xy=(0.3, 0.97))
    common.caption(figure, (
        f"The CJ detonation of Comp B reaches the aluminium and drives a shock of "
        f"{peak * g:.1f} GPa into it; the Taylor wave behind the detonation makes the pulse "
        f"decay at once behind its front (blue record, a quarter of the way into the "
        f"plate). The pulse reflects from the free rear face as a release; where it meets "
        f"the falling tail of the incoming pulse the tension reaches the spall strength: "
        f"{where}. Characteristic step 3 GPa; the reaction zone is infinitely thin."),
        y=0.02)
    common.save(figure, NAME, f"Comp B on aluminium 6061: a {peak * g:.1f} GPa peaked, "
                f"decaying pulse and spall near the rear face.")


if __name__ == "__main__":
    main()
