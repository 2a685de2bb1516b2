"""Three spall criteria on one plate impact: threshold, incubation time, Tuler–Butcher.

A 1 mm Al 2024 flyer strikes a 3 mm Al 2024 target at 300 m/s (the impact of
gallery 13).  The target is solved three times: (a) with the instantaneous
threshold (the library's spall strength, 1.2 GPa), (b) with an incubation-time
criterion (the tension must stay beyond 1.0 GPa for 10 ns) and (c) with the
Tuler–Butcher cumulative-damage criterion (Int. J. Fract. Mech. 4, 431, 1968):
a point fails when the integral of (T − 1.0 GPa)² dt reaches 0.002 GPa²·µs.
The constants of (b) and (c) are illustrative, not fitted to Al 2024 data.

Top: the three X–t diagrams.  Bottom: the rear free-surface velocity records
overlaid with the pullback of each and the spall strength it implies
(``fronttrack.pullback``, ½ ρ0 c0 Δu) beside the tension at the fracture; the
tension and damage histories the criteria integrate at their fracture planes (in
the target that cannot spall: the same solution up to the fracture); and a zoom
on the meeting of the release fans with the three fracture points.
"""

from __future__ import annotations

from typing import NamedTuple

import common
import numpy as np
from matplotlib.figure import Figure

from fronttrack.damage import damage_rate
from fronttrack.plotting import plot_xt
from fronttrack.pullback import spall_estimates

NAME = common.script_name(__file__)
MM, US, GPA = common.MM, common.US, common.GPA
CASES = (("threshold", "(a) instantaneous threshold", common.BLUE, "o"),
         ("incubation", "(b) incubation time", "#d9730d", "s"),
         ("tuler_butcher", "(c) Tuler–Butcher", "#2e8b57", "D"))


def damage_history(history, t_end: float, criterion):
    """``(t s, K/K_c)``: the damage fraction of a criterion along a step history."""
    times, fractions, total = [0.0], [0.0], 0.0
    ends = [*history.t[1:], t_end]
    for start, end, state in zip(history.t, ends, history.states, strict=True):
        total += damage_rate(-state.sigma, criterion) * (end - start)
        times.append(end)
        fractions.append(total / criterion.damage)
    return np.array(times), np.array(fractions)


def describe(solution) -> str:
    """The criterion of a solution, with its constants (GPa, ns, GPa²·µs)."""
    criterion = solution.scene.spall_criterion
    if criterion is None:
        strength = solution.scene.layers[-1].material.spall_strength
        return f"T ≥ {strength * GPA:.1f} GPa"
    if criterion.exponent == 0.0:
        return (f"T > {criterion.threshold * GPA:.1f} GPa held for "
                f"{criterion.damage * 1e9:.0f} ns")
    k = criterion.damage * GPA**criterion.exponent * US
    power = "²" if criterion.exponent == 2.0 else f"^{criterion.exponent:g}"
    return (f"∫(T − {criterion.threshold * GPA:.1f} GPa){power} dt = "
            f"{k:g} GPa{power}·µs")


class Runs(NamedTuple):
    """The three spall criteria's solutions, the target that cannot spall, the pullback
    estimates of each and its first fracture."""

    solutions: list
    intact: object
    estimates: list
    firsts: list

    @property
    def material(self):
        return self.solutions[0].scene.layers[-1].material

    @property
    def threshold(self) -> float:
        """Threshold (GPa) of the time-dependent criteria (b) and (c)."""
        return self.solutions[1].scene.spall_criterion.threshold * GPA


def solve_all() -> Runs:
    """Run the scene with each criterion, and without spall."""
    solutions = [common.solve(f"{NAME}_{key}") for key, *_ in CASES]
    intact = common.solve(f"{NAME}_nospall")
    return Runs(solutions, intact, [spall_estimates(s) for s in solutions],
                [min(s.spalls, key=lambda p: p.t) for s in solutions])


def draw_xt_panels(figure, top, runs: Runs) -> None:
    """The three X–t diagrams, each with its first fracture marked."""
    solutions, firsts = runs.solutions, runs.firsts
    for k, ((_key, label, color, marker), sol, first) in enumerate(
            zip(CASES, solutions, firsts, strict=True)):
        ax = figure.add_subplot(top[0, k])
        placed = plot_xt(sol, ax=ax, numbers=False)
        ax.set_title(f"{label}: {describe(sol)}", fontsize=9.5, pad=placed.title_pad,
                     color=color)
        for text in list(ax.texts):   # the engine's "spall n" labels crowd: markers + note
            if text.get_text().startswith("spall"):
                text.remove()
        if k < len(CASES) - 1:   # one colorbar label, on the last panel
            placed.colorbar.set_label("")
        ax.plot([first.x * MM], [first.t * US], marker=marker, ms=7, mfc="none", mec=color,
                mew=1.6, zorder=23, ls="none")
        more = len(sol.spalls) - 1
        common.note(ax, f"first fracture X = {first.x * MM:.3f} mm\n"
                    f"t = {first.t * US:.4f} µs, T = {first.tension * GPA:.2f} GPa"
                    + (f"\n+{more} later plane{'s' if more > 1 else ''}" if more else ""),
                    xy=(0.03, 0.97))



def draw_records(ax_v, runs: Runs) -> None:
    """The rear free-surface records, zoomed on the pullback of each criterion."""
    intact, solutions, estimates, firsts = runs.intact, runs.solutions, runs.estimates, runs.firsts
    material = runs.material
    edges, velocity = common.surface_velocity(intact)
    common.plot_record(ax_v, edges, velocity, color="#888888", lw=1.1, ls="--",
                       label="target that cannot spall")
    lines = []
    t_right = 0.99
    for (_key, label, color, marker), sol, est, first in zip(CASES, solutions, estimates,
                                                             firsts, strict=True):
        edges, velocity = common.surface_velocity(sol)
        common.plot_record(ax_v, edges, velocity, color=color, lw=1.6, label=label)
        rec = est.record
        ax_v.plot([rec.t_min * US], [rec.u_min], marker=marker, ms=6, mfc="white",
                  mec=color, mew=1.4, zorder=12, ls="none")
        ax_v.plot([rec.t_min * US, t_right], [rec.u_min, rec.u_min], color=color, lw=0.8,
                  ls=":")
        ax_v.text(t_right - 0.001, rec.u_min + 3, f"{label[:3]} Δu = {rec.delta_u:.1f} m/s",
                  color=color, fontsize=7.5, ha="right", va="bottom")
        lines.append(f"{label[:3]} Δu = {rec.delta_u:5.1f} m/s → ½ρ0c0Δu = "
                     f"{est.acoustic_longitudinal * GPA:.2f} GPa\n"
                     f"    tension at the fracture {first.tension * GPA:.2f} GPa")
    rec0 = estimates[0].record
    ax_v.set_xlim(0.86, t_right)
    ax_v.set_ylim(-15.0, 470.0)
    ax_v.set_xlabel("time t (µs)")
    ax_v.set_ylabel("rear free-surface velocity (m/s)")
    ax_v.set_title("rear free-surface velocity: the pullback per criterion", fontsize=10)
    ax_v.legend(fontsize=7.5, loc="lower left")
    common.note(ax_v, f"plateau {rec0.u_max:.1f} m/s from t = {rec0.t_peak * US:.3f} µs\n"
                f"ρ0 = {material.rho0:.0f} kg/m³, c0 = {estimates[0].c0:.0f} m/s\n"
                + "\n".join(lines), xy=(0.02, 0.98), fontsize=7.5)



def draw_tension_and_damage(ax_s, ax_d, runs: Runs) -> None:
    """Tension and damage histories at the fracture planes, on the intact solution."""
    intact, solutions, firsts = runs.intact, runs.solutions, runs.firsts
    t_end = intact.scene.t_end
    t0 = min(f.t for f in firsts) - 0.03e-6
    for (_key, label, color, marker), sol, first in zip(CASES, solutions, firsts, strict=True):
        history = intact.history(first.x)
        edges, values = common.steps(history, -history.sigma * GPA, t_end)
        ax_s.stairs(values, edges, baseline=None, color=color, lw=1.3,
                    label=f"{label[:3]} X = {first.x * MM:.3f} mm")
        ax_s.plot([first.t * US], [first.tension * GPA], marker=marker, ms=6, mfc="white",
                  mec=color, mew=1.4, zorder=12, ls="none")
        criterion = sol.scene.spall_criterion
        if criterion is not None:
            times, fraction = damage_history(history, t_end, criterion)
            ax_d.plot(times * US, fraction, color=color, lw=1.4)
            reached = float(np.interp(first.t, times, fraction))
            print(f"{label}: damage of the intact solution at the fracture {reached:.12f}")
            ax_d.plot([first.t * US], [1.0], marker=marker, ms=6, mfc="white", mec=color,
                      mew=1.4, zorder=12, ls="none")
    strength = runs.material.spall_strength * GPA
    threshold = runs.threshold
    ax_s.axhline(strength, color=CASES[0][2], lw=0.8, ls=":")
    ax_s.text(t0 * US + 0.002, strength, f"spall strength {strength:.1f} GPa", fontsize=7,
              color=CASES[0][2], va="bottom")
    ax_s.axhline(threshold, color="#555555", lw=0.8, ls=":")
    ax_s.text(t0 * US + 0.002, threshold, f"threshold of (b), (c) {threshold:.1f} GPa",
              fontsize=7, color="#555555", va="top")
    ax_s.set_ylabel("tension T = −σ (GPa)")
    ax_s.set_ylim(-0.1, 2.5)
    ax_s.set_title("tension and damage at the fracture planes (intact target)", fontsize=10)
    ax_s.legend(fontsize=7, loc="lower right")
    ax_s.grid(True, lw=0.3, alpha=0.5)
    ax_s.tick_params(labelbottom=False)
    ax_d.axhline(1.0, color="#555555", lw=0.8, ls=":")
    ax_d.set_ylim(-0.05, 1.6)
    ax_d.set_xlim(t0 * US, t0 * US + 0.06)
    ax_d.set_xlabel("time t (µs)")
    ax_d.set_ylabel("damage K/K_c of (b), (c)")
    ax_d.grid(True, lw=0.3, alpha=0.5)



def draw_zoom(ax_z, runs: Runs) -> None:
    """Zoom on the crossing fans of the intact target, with the three fracture points."""
    intact, firsts = runs.intact, runs.firsts
    placed = plot_xt(intact, ax=ax_z, numbers=False)
    placed.colorbar.set_label("stress σ (GPa)", fontsize=8)
    legend = ax_z.get_legend()
    if legend is not None:
        legend.remove()
    xs = [f.x * MM for f in firsts]
    ts = [f.t * US for f in firsts]
    ax_z.set_xlim(min(xs) - 0.12, max(xs) + 0.12)
    ax_z.set_ylim(min(ts) - 0.025, max(ts) + 0.015)
    for (_key, label, color, marker), x, t in zip(CASES, xs, ts, strict=True):
        ax_z.plot([x], [t], marker=marker, ms=8, mfc=color, mec="white", mew=1.0, zorder=23,
                  ls="none", label=label)
    ax_z.legend(fontsize=7.5, loc="lower left", framealpha=0.95)
    ax_z.set_title("zoom: fracture points in the crossing fans", fontsize=10)



def caption_text(runs: Runs) -> str:
    """The figure's caption: where and when each criterion breaks, and what the pullback says."""
    solutions, estimates, firsts = runs.solutions, runs.estimates, runs.firsts
    strength = runs.material.spall_strength * GPA
    threshold = runs.threshold
    t_end = runs.intact.scene.t_end
    a, b, c = firsts
    ea, eb, ec = estimates
    spacing = solutions[0].scene.accuracy.spall_spacing * MM
    step = solutions[0].accuracy_report["characteristic_step"] * GPA
    text = (f"Fans of characteristics {step:.3g} GPa apart (default accuracy); the tension "
            f"at a "
            f"point rises in ray steps. (a) The threshold breaks the target at X = "
            f"{a.x * MM:.3f} mm, t = {a.t * US:.4f} µs, in the step that takes the tension "
            f"past {strength:.1f} GPa (to {a.tension * GPA:.2f} GPa; it carried "
            f"{ea.carried_tension * GPA:.2f} GPa before). (b) The incubation "
            f"criterion waits "
            f"until the tension has stayed above {threshold:.1f} GPa for "
            f"{solutions[1].scene.spall_criterion.damage * 1e9:.0f} ns: X = {b.x * MM:.3f} mm, "
            f"t = {b.t * US:.4f} µs, T = {b.tension * GPA:.2f} GPa. (c) Tuler–Butcher "
            f"(Int. J. Fract. Mech. 4, 431, 1968; illustrative constants) integrates "
            f"(T − {threshold:.1f} GPa)²: X = {c.x * MM:.3f} mm, t = {c.t * US:.4f} µs, "
            f"T = {c.tension * GPA:.2f} GPa. The later the fracture, the more of the release "
            f"the rear surface sees: pullback Δu = {ea.record.delta_u:.1f}, "
            f"{eb.record.delta_u:.1f}, {ec.record.delta_u:.1f} m/s, so ½ρ0c0Δu = "
            f"{ea.acoustic_longitudinal * GPA:.2f}, {eb.acoustic_longitudinal * GPA:.2f}, "
            f"{ec.acoustic_longitudinal * GPA:.2f} GPa against the tension at the fracture "
            f"{a.tension * GPA:.2f}, {b.tension * GPA:.2f}, {c.tension * GPA:.2f} GPa ("
            + ", ".join(common.signed((e.acoustic_longitudinal / f.tension - 1) * 100, 0)
                        for e, f in zip(estimates, firsts, strict=True))
            + " %: the last ray step before the spall signal is partly lost, as in gallery 13). "
            f"Damage histories are integrated on the intact solution, identical up to the "
            f"fracture: each reaches 1 at its fracture time. The time-dependent criteria "
            f"would break further planes just before the relief from the first one reaches "
            f"them; spall_spacing = {spacing:.1f} mm keeps planes at least that far apart "
            f"({len(solutions[0].spalls)}, {len(solutions[1].spalls)}, "
            f"{len(solutions[2].spalls)} planes by {t_end * US:.2f} µs).")
    return text


def main() -> None:
    runs = solve_all()
    solutions, estimates, firsts = runs.solutions, runs.estimates, runs.firsts
    strength = runs.material.spall_strength * GPA
    figure = Figure(figsize=(14.0, 11.6))
    top = figure.add_gridspec(1, 3, left=0.045, right=0.95, top=0.895, bottom=0.565,
                              wspace=0.3)
    low = figure.add_gridspec(2, 3, left=0.055, right=0.95, top=0.475, bottom=0.17,
                              wspace=0.3, hspace=0.12, width_ratios=(1.15, 1.0, 0.95))
    ax_s = figure.add_subplot(low[0, 1])
    draw_xt_panels(figure, top, runs)
    draw_records(figure.add_subplot(low[:, 0]), runs)
    draw_tension_and_damage(ax_s, figure.add_subplot(low[1, 1], sharex=ax_s), runs)
    draw_zoom(figure.add_subplot(low[:, 2]), runs)
    figure.suptitle("Spall criteria on one impact: Al 2024, 1 mm on 3 mm at 300 m/s "
                    "(unbonded, free ends)", fontsize=12, y=0.985)
    common.caption(figure, caption_text(runs), width=185)
    a, b, c = firsts
    ea, eb, ec = estimates
    common.save(figure, NAME,
                f"Al 2024 1 mm on 3 mm at 300 m/s with three spall criteria: first fracture "
                f"(a) threshold {strength:.1f} GPa X = {a.x * MM:.3f} mm, t = {a.t * US:.4f} µs; "
                f"(b) incubation X = {b.x * MM:.3f} mm, t = {b.t * US:.4f} µs; "
                f"(c) Tuler–Butcher X = {c.x * MM:.3f} mm, t = {c.t * US:.4f} µs; pullback "
                f"Δu = {ea.record.delta_u:.1f}/{eb.record.delta_u:.1f}/"
                f"{ec.record.delta_u:.1f} m/s gives ½ρ0c0Δu = "
                f"{ea.acoustic_longitudinal * GPA:.2f}/{eb.acoustic_longitudinal * GPA:.2f}/"
                f"{ec.acoustic_longitudinal * GPA:.2f} GPa against T at fracture "
                f"{a.tension * GPA:.2f}/{b.tension * GPA:.2f}/{c.tension * GPA:.2f} GPa.")
    for (_key, label, *_), sol, est, first in zip(CASES, solutions, estimates, firsts,
                                                 strict=True):
        print(f"{label}: X = {first.x * MM:.4f} mm, t = {first.t * US:.4f} us, "
              f"T = {first.tension * GPA:.4f} GPa, du = {est.record.delta_u:.2f} m/s, "
              f"acoustic = {est.acoustic_longitudinal * GPA:.4f} GPa, "
              f"carried = {est.carried_tension * GPA:.4f} GPa, planes = {len(sol.spalls)}")




if __name__ == "__main__":
    main()
