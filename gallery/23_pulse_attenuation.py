"""Attenuation of a short stress pulse in an elastic–plastic solid, down to the HEL.

A 1 µs square stress pulse is applied to the left face of a 130 mm bar of
Davison's steel (ideal elastic–plastic, small strain; HEL 1.776 GPa).  The pulse
runs in as an elastic precursor (the HEL, at C0) and a plastic shock (at CB).  Its
end sends an elastic release (at C0, a drop of 2 HEL) and a plastic release (at
CB).  The elastic release overtakes the plastic shock and weakens it; the precursor,
at the same speed C0, is never caught, so far enough from the face the largest
stress is the HEL (Davison ch. 10).

The scene asked for, 4.5 GPa, is shown with two stronger pulses (8 and 12 GPa)
that need several overtakings.  A square pulse cannot be written as a stress
history (times must increase strictly): it ends with a 1 ps ramp, which the
engine carries as two steps 1 ps apart.
"""

from __future__ import annotations

import common
import numpy as np
from matplotlib.figure import Figure

from fronttrack.plotting import peak_stress, plot_xt

NAME = common.script_name(__file__)
MM, US, GPA = common.MM, common.US, common.GPA
VARIANTS = ((NAME, 4.5, common.RED), (f"{NAME}_8GPa", 8.0, "#d35400"),
            (f"{NAME}_12GPa", 12.0, "#6c3483"))
STATIONS = 26001
"""Stations for the peak-stress curve: 0.005 mm apart over the 130 mm bar."""


def hel_distance(x, top, hel):
    """First station (m) from which the peak stays at the HEL (to 1e-9)."""
    above = np.nonzero(top > hel * (1.0 + 1e-9))[0]
    return float(x[above[-1] + 1])


def main() -> None:
    runs = [(common.solve(name), amplitude, color) for name, amplitude, color in VARIANTS]
    steel = runs[0][0].scene.layers[0].material
    hel, c0, cb = steel.hel, steel.C0, steel.CB
    tau = 1e-6
    x_catch = c0 * cb * tau / (c0 - cb)
    drop = 4.0 * hel * steel.bulk_impedance / (steel.impedance + steel.bulk_impedance)
    t_end = runs[0][0].scene.t_end
    reach = c0 * t_end            # the precursor's position at t_end

    figure = Figure(figsize=(13.0, 11.8))
    grid = figure.add_gridspec(2, 2, height_ratios=(1.15, 1.0), left=0.06, right=0.94,
                               bottom=0.13, top=0.9, wspace=0.33, hspace=0.32)
    for k, (solution, amplitude, _) in enumerate((runs[0], runs[2])):
        ax = figure.add_subplot(grid[0, k])
        placed = plot_xt(solution, ax=ax)
        ax.set_title(f"{amplitude:g} GPa, 1 µs pulse: X–t diagram", fontsize=10,
                     pad=placed.title_pad)
        ax.axvline(x_catch * MM, color="#555555", lw=0.8, ls=(0, (2, 2)), zorder=7)
    ax_p = figure.add_subplot(grid[1, :])

    results = []
    for solution, amplitude, color in runs:
        x, top, _ = peak_stress(solution, STATIONS)
        keep = x <= reach
        distance = hel_distance(x[keep], top[keep], hel)
        results.append((amplitude, distance, solution.stats["events"]))
        ax_p.plot(x[keep] * MM, top[keep] * GPA, color=color, lw=1.6,
                  label=f"{amplitude:g} GPa pulse: at the HEL from X = {distance * MM:.2f} mm "
                        f"({solution.stats['events']} events)")
    ax_p.axhline(hel * GPA, color="black", lw=1.0, ls="--", zorder=1)
    ax_p.text(reach * MM - 1.0, hel * GPA + 0.12, f"HEL = {hel * GPA:.3f} GPa", ha="right",
              va="bottom", fontsize=9)
    for n in range(1, 5):
        ax_p.axvline(n * x_catch * MM, color="#999999", lw=0.7, ls=":", zorder=0)
        ax_p.text(n * x_catch * MM + 0.5, 12.3, f"{n} X_c", fontsize=8, color="#555555")
    ax_p.annotate(f"X_c = C0 CB τ / (C0 − CB) = {x_catch * MM:.2f} mm: the elastic release\n"
                  f"overtakes the plastic shock; each overtaking removes\n"
                  f"4 HEL ZB/(Z0 + ZB) = {drop * GPA:.3f} GPa of its plastic part",
                  (x_catch * MM, 3.4), xytext=(50.0, 7.0), textcoords="data",
                  fontsize=8.5, va="bottom", bbox={"boxstyle": "round,pad=0.3", "fc": "white",
                                                   "ec": "#888888", "lw": 0.6},
                  arrowprops={"arrowstyle": "->", "lw": 0.7})
    ax_p.set_xlim(0.0, reach * MM)
    ax_p.set_ylim(0.0, 13.2)
    ax_p.set_xlabel("Lagrangian position X (mm)")
    ax_p.set_ylabel("peak stress σ_max (GPa, compression > 0)")
    ax_p.set_title("attenuation: the largest stress each station ever sees (exact, "
                   f"{STATIONS} stations)", fontsize=10)
    ax_p.legend(fontsize=8.5, loc="upper right", bbox_to_anchor=(1.0, 0.93))
    ax_p.grid(True, lw=0.3, alpha=0.5)

    figure.suptitle("A 1 µs stress pulse in Davison's steel decays to the HEL "
                    "(ideal elastic–plastic, applied stress on the left face)", fontsize=12,
                    y=0.985)
    first = results[0]
    text = (f"The 4.5 GPa pulse's plastic part ({4.5 - hel * GPA:.2f} GPa above the HEL) is "
            f"smaller than the {drop * GPA:.3f} GPa one overtaking removes, so at "
            f"X_c = {x_catch * MM:.2f} mm the plastic shock disappears at once and the peak "
            f"drops to the HEL ({first[1] * MM:.2f} mm on the station grid). Stronger pulses "
            f"lose {drop * GPA:.3f} GPa per overtaking: the tail's plastic release (at CB) "
            f"never catches the shock, but where it crosses a plane at which the shock was "
            f"weakened it meets material compressed less, turns partly elastic, and a new "
            f"elastic release overtakes the shock one X_c further on (smaller steps are "
            f"waves reflected between the two). 8 GPa reaches the HEL at "
            f"{results[1][1] * MM:.2f} mm, 12 GPa at {results[2][1] * MM:.2f} mm. Curves "
            f"stop at the precursor's reach at t = {t_end * US:.0f} µs. Waves weaker than "
            f"10 MPa are dropped.")
    common.caption(figure, text, width=180)
    common.save(figure, NAME,
                f"1 µs pulses in steel decay to the HEL ({hel * GPA:.3f} GPa): 4.5 GPa at "
                f"X = {first[1] * MM:.2f} mm (X_c = {x_catch * MM:.2f} mm), 8 GPa at "
                f"{results[1][1] * MM:.2f} mm, 12 GPa at {results[2][1] * MM:.2f} mm.")
    for amplitude, distance, events in results:
        print(f"{amplitude:g} GPa: peak at the HEL from X = {distance * MM:.3f} mm "
              f"({events} events)")
    print(f"X_c = {x_catch * MM:.4f} mm, drop per overtaking {drop * GPA:.4f} GPa")


if __name__ == "__main__":
    main()
