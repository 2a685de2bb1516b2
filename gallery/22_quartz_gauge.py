"""An X-cut quartz gauge behind a steel target: the elastic precursor and the plastic step.

A 3 mm steel flyer strikes a 6 mm steel target at 230 m/s (Davison's ideal
elastic–plastic steel); a 6 mm X-cut quartz disc (linear elastic, rho0 2649 kg/m³,
C0 5749 m/s) is bonded to the target's rear face.  A shorted quartz gauge reads
the stress at its impact face for one transit time of the quartz.  The record
shows the two-wave structure of the steel: the elastic precursor (the HEL,
transmitted at the quartz's lower impedance), a ring-up to the HEL while the
plastic shock approaches, then the plastic step.  The levels are checked against
the impedance match drawn in the σ–u plane.
"""

from __future__ import annotations

import common
import numpy as np
from matplotlib.figure import Figure

from fronttrack.plotting import plot_xt

NAME = common.script_name(__file__)
MM, US, GPA = common.MM, common.US, common.GPA
GAUGE_X = 9e-3


def levels(steel, quartz, velocity):
    """Impedance-match states (σ Pa, u m/s) of the symmetric impact and of the gauge."""
    z0, zb, zq = steel.impedance, steel.bulk_impedance, quartz.impedance
    hel = steel.hel
    u_hel = hel / z0
    u_a = velocity / 2.0                                  # symmetric impact
    sigma_a = hel + zb * (u_a - u_hel)
    precursor = 2.0 * zq * hel / (zq + z0)                # HEL state released onto quartz
    plastic = zq * (sigma_a + z0 * u_a) / (zq + z0)       # shocked state released onto quartz
    assert sigma_a - plastic < 2.0 * hel                  # the release is elastic
    return {"P": (hel, u_hel), "A": (sigma_a, u_a), "G1": (precursor, precursor / zq),
            "G2": (plastic, plastic / zq), "H": (hel, hel / zq)}


def draw_impedance_match(ax, steel, quartz, velocity, states, record):
    """σ–u construction: steel Hugoniots, elastic releases, the quartz line, the record."""
    z0, zb = steel.impedance, steel.bulk_impedance
    hel, u_hel = states["P"]
    sigma_a, u_a = states["A"]
    u = np.linspace(0.0, 240.0, 400)
    target = np.where(u <= u_hel, z0 * u, hel + zb * (u - u_hel))
    flyer = np.where(velocity - u <= u_hel, z0 * (velocity - u), hel + zb * (velocity - u - u_hel))
    ax.plot(u, target * GPA, color=common.BLUE, lw=1.4, label="steel target (right-going)")
    ax.plot(u, flyer * GPA, color=common.BLUE, lw=1.4, ls=(0, (5, 2)),
            label=f"steel flyer (left-going, from {velocity:.0f} m/s)")
    ax.plot(u, quartz.impedance * u * GPA, color="#c0392b", lw=1.4,
            label="quartz σ = Zq u (right-going)")
    for (s0, u0), key in (((hel, u_hel), "G1"), ((sigma_a, u_a), "G2")):
        end = states[key][1]
        uu = np.linspace(u0, end, 20)
        ax.plot(uu, (s0 - z0 * (uu - u0)) * GPA, color="#555555", lw=1.0, ls=":")
    ax.plot(record[1], record[0] * GPA, color="#c0392b", marker=".", ms=4, lw=0, zorder=5,
            label="gauge record (engine)")
    marks = {"P": ("precursor state (HEL)", (12, 24), "left"),
             "A": ("shocked steel", (10, 6), "left"),
             "G1": ("gauge: precursor", (8, -12), "left"),
             "G2": ("gauge: plastic step", (8, 10), "left"),
             "H": ("ring-up limit (HEL)", (8, -10), "left")}
    for key, (text, offset, ha) in marks.items():
        s, v = states[key]
        ax.plot([v], [s * GPA], "o", ms=6, mfc="white", mec="black", mew=1.2, zorder=6)
        ax.annotate(f"{text}\n{s * GPA:.3f} GPa, {v:.1f} m/s", (v, s * GPA), xytext=offset,
                    textcoords="offset points", fontsize=7.5, ha=ha, va="center")
    ax.axhline(hel * GPA, color="#999999", lw=0.6, ls="--", zorder=0)
    ax.text(236, hel * GPA + 0.05, "HEL", fontsize=7.5, ha="right", va="bottom",
            color="#555555")
    ax.set_xlim(0.0, 240.0)
    ax.set_ylim(0.0, 5.4)
    ax.set_xlabel("particle velocity u (m/s)")
    ax.set_ylabel("stress σ (GPa, compression > 0)")
    ax.set_title("impedance match in the σ–u plane (dotted: elastic releases)", fontsize=10)
    ax.legend(fontsize=7.5, loc="upper left")
    ax.grid(True, lw=0.3, alpha=0.5)


def main() -> None:
    solution = common.solve(NAME)
    scene = solution.scene
    steel, quartz = scene.layers[1].material, scene.layers[2].material
    velocity = scene.layers[0].velocity
    t_end = scene.t_end
    states = levels(steel, quartz, velocity)
    history = solution.history("gauge")
    sigma, u = history.sigma, history.u

    t_precursor = history.t[1]
    i_plastic = int(np.argmax(sigma))
    t_plastic = history.t[i_plastic]
    t_release = history.t[i_plastic + 1]
    t_window = t_precursor + scene.layers[2].thickness / quartz.C
    ring = [k for k in range(2, i_plastic)]
    # checks against the impedance match
    assert abs(sigma[1] - states["G1"][0]) <= 1e-9 * states["G1"][0]
    assert abs(sigma[i_plastic] - states["G2"][0]) <= 1e-9 * states["G2"][0]

    figure = Figure(figsize=(13.0, 11.4))
    grid = figure.add_gridspec(2, 2, width_ratios=(1.2, 1.0), height_ratios=(1.2, 1.0),
                               left=0.06, right=0.985, bottom=0.125, top=0.905,
                               wspace=0.24, hspace=0.30)
    ax_xt = figure.add_subplot(grid[0, 0])
    ax_su = figure.add_subplot(grid[0, 1])
    ax_g = figure.add_subplot(grid[1, :])

    placed = plot_xt(solution, ax=ax_xt)
    ax_xt.set_title("X–t diagram (Lagrangian), regions shaded by stress", fontsize=10,
                    pad=placed.title_pad)
    ax_xt.axvline(GAUGE_X * MM, color=common.RED, lw=1.0, ls=(0, (2, 2)), zorder=7)
    common.note(ax_xt, "gauge plane\nX = 9 mm", xy=(0.60, 0.40), color=common.RED)
    draw_impedance_match(ax_su, steel, quartz, velocity, states, (sigma, u))

    # the gauge record
    edges, values = common.steps(history, sigma * GPA, t_end)
    ax_g.stairs(values, edges, baseline=None, color="#c0392b", lw=1.7,
                label="stress at the steel–quartz interface (gauge record)")
    ax_g.axvspan(t_window * US, t_end * US, color="#dddddd", alpha=0.6, zorder=0)
    ax_g.text(t_window * US - 0.01, 0.12, f"gauge window ends at {t_window * US:.3f} µs:\n"
              f"one quartz transit, 6 mm / 5749 m/s = {(t_window - t_precursor) * US:.3f} µs",
              fontsize=7.5, va="bottom", ha="right", color="#444444")
    hel = steel.hel * GPA
    for level, text in ((states["G1"][0], "precursor 2 Zq/(Zq + Z0) · HEL"),
                        (steel.hel, "HEL of the steel"),
                        (states["G2"][0], "plastic: shocked steel state released onto quartz")):
        ax_g.axhline(level * GPA, color="#777777", lw=0.7, ls=":", zorder=0)
        ax_g.text(1.31, level * GPA + 0.03, f"{text}: {level * GPA:.3f} GPa", fontsize=8,
                  color="#333333", va="bottom")
    ax_g.annotate(f"precursor arrives\nt = {t_precursor * US:.3f} µs", (t_precursor * US,
                  states["G1"][0] * GPA), xytext=(-20, 40), textcoords="offset points",
                  fontsize=8, ha="right", arrowprops={"arrowstyle": "->", "lw": 0.7})
    ax_g.annotate(f"plastic shock arrives\nt = {t_plastic * US:.4f} µs = 6 mm / CB",
                  (t_plastic * US, states["G2"][0] * GPA), xytext=(-30, -22),
                  textcoords="offset points", fontsize=8, ha="right", va="top",
                  arrowprops={"arrowstyle": "->", "lw": 0.7})
    ax_g.annotate(f"release from the flyer's back\nt = {t_release * US:.3f} µs",
                  (t_release * US, sigma[i_plastic + 1] * GPA), xytext=(-30, -50),
                  textcoords="offset points", fontsize=8, ha="right",
                  arrowprops={"arrowstyle": "->", "lw": 0.7})
    ax_g.set_xlim(0.0, t_end * US)
    ax_g.set_ylim(0.0, 2.9)
    ax_g.set_xlabel("time t (µs)")
    ax_g.set_ylabel("stress σ (GPa, compression > 0)")
    ax_g.set_title("quartz gauge record: stress at X = 9 mm", fontsize=10)
    ax_g.grid(True, lw=0.3, alpha=0.5)
    ax_g.legend(fontsize=8, loc="upper right")
    # zoom on the ring-up
    inset = ax_g.inset_axes((0.06, 0.34, 0.26, 0.52))
    inset.stairs(values, edges, baseline=None, color="#c0392b", lw=1.5)
    inset.set_xlim(1.225, 1.275)
    inset.set_ylim(0.8, 2.55)
    inset.axhline(hel, color="#777777", lw=0.7, ls=":")
    inset.tick_params(labelsize=7)
    inset.set_title("ring-up to the HEL (zoom)", fontsize=7.5)
    inset.set_xlabel("t (µs)", fontsize=7)
    inset.set_ylabel("σ (GPa)", fontsize=7)
    inset.grid(True, lw=0.3, alpha=0.5)

    figure.suptitle("Quartz gauge behind steel: 3 mm steel flyer on 6 mm steel at 230 m/s, "
                    "6 mm X-cut quartz bonded behind", fontsize=12, y=0.985)
    steps_text = ", ".join(f"{s * GPA:.3f}" for s in sigma[ring[:4]])
    text = (f"The steel's elastic precursor (HEL {hel:.3f} GPa) reaches the quartz first and "
            f"is transmitted at 2 Zq/(Zq + Z0) · HEL = {states['G1'][0] * GPA:.3f} GPa "
            f"(Zq = {quartz.impedance * 1e-6:.2f}, Z0 = {steel.impedance * 1e-6:.2f} "
            f"MPa·s/m). The elastic release reflected into the steel meets the plastic shock, "
            f"which sends a new precursor back up to the HEL: the interface rings up in "
            f"ever faster steps ({steps_text}, … GPa) toward the HEL, reached as the plastic "
            f"shock arrives at t = {t_plastic * US:.4f} µs. The plastic step is the "
            f"{states['A'][0] * GPA:.3f} GPa shocked steel state released elastically onto "
            f"the quartz: {states['G2'][0] * GPA:.3f} GPa, equal to the engine's value to "
            f"1e-9. Waves weaker than 10 MPa are dropped "
            f"({solution.stats['events']} events).")
    common.caption(figure, text, width=175)
    common.save(figure, NAME,
                f"Quartz gauge behind steel (3 mm on 6 mm at 230 m/s): precursor "
                f"{states['G1'][0] * GPA:.3f} GPa at {t_precursor * US:.3f} µs, ring-up to the "
                f"HEL {hel:.3f} GPa, plastic step {states['G2'][0] * GPA:.3f} GPa at "
                f"{t_plastic * US:.4f} µs, release at {t_release * US:.3f} µs.")
    print(f"gauge: precursor {sigma[1] * GPA:.4f} GPa at {t_precursor * US:.4f} us; ring-up "
          f"{', '.join(f'{s * GPA:.4f}' for s in sigma[ring])} GPa; plastic "
          f"{sigma[i_plastic] * GPA:.4f} GPa at {t_plastic * US:.4f} us; release from "
          f"{t_release * US:.4f} us")
    print(f"impedance match: P {states['P'][0] * GPA:.4f} GPa; A {states['A'][0] * GPA:.4f} "
          f"GPa at {states['A'][1]:.2f} m/s; G1 {states['G1'][0] * GPA:.4f}; "
          f"G2 {states['G2'][0] * GPA:.4f} GPa")


if __name__ == "__main__":
    main()
