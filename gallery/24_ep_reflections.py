"""Reflection of an elastic–plastic wave from a free surface and from a rigid wall.

A sustained stress is applied at t = 0 to the left face of a 6 mm plate of
Davison's steel (ideal elastic–plastic, small strain: HEL 1.776 GPa, 2 HEL
3.553 GPa) and the wave reflects from the right end, free or an immovable wall.
Three levels: 1.2 GPa (below the HEL: a single elastic wave), 2.8 GPa (between
the HEL and 2 HEL: precursor and plastic shock, elastic release) and 8 GPa (well
above 2 HEL: the release from it reverse-yields).  Each column shows the X–t
diagram over the σ–u diagram with the same region numbers; one figure per end.

Closed forms (incident state σ1, u1; Z0 = ρ0 C0, ZB = ρ0 CB):

- free surface: u_fs = u1 + σ1/Z0 if σ1 <= 2 HEL (elastic release), else
  u1 + 2 HEL/Z0 + (σ1 - 2 HEL)/ZB; never the acoustic 2 u1 once the wave is plastic;
- wall: a plastically loaded state reloads plastically at once, σ_w = σ1 + ZB u1;
  an elastic one first elastically up to the HEL, σ_w = HEL + ZB (u1 - (HEL - σ1)/Z0).
"""

from __future__ import annotations

import common
from matplotlib.figure import Figure

from fronttrack.plotting import plot_sigma_u, plot_xt

NAME = common.script_name(__file__)
MM, US, GPA = common.MM, common.US, common.GPA
LEVELS = (("low", "below the HEL"), ("mid", "between HEL and 2 HEL"),
          ("high", "well above 2 HEL"))


def incident(steel, sigma):
    """Particle velocity (m/s) behind the incident wave of stress ``sigma`` (Pa)."""
    if sigma <= steel.hel:
        return sigma / steel.impedance
    return steel.hel / steel.impedance + (sigma - steel.hel) / steel.bulk_impedance


def free_surface_velocity(steel, sigma):
    u1 = incident(steel, sigma)
    if sigma <= 2.0 * steel.hel:
        return u1 + sigma / steel.impedance
    return (u1 + 2.0 * steel.hel / steel.impedance
            + (sigma - 2.0 * steel.hel) / steel.bulk_impedance)


def wall_stress(steel, sigma):
    u1 = incident(steel, sigma)
    if sigma >= steel.hel:
        return sigma + steel.bulk_impedance * u1
    return steel.hel + steel.bulk_impedance * (u1 - (steel.hel - sigma) / steel.impedance)


def figure_for(end: str) -> list[str]:
    figure = Figure(figsize=(16.0, 11.0))
    grid = figure.add_gridspec(2, 3, height_ratios=(1.1, 1.0), left=0.045, right=0.95,
                               bottom=0.12, top=0.89, wspace=0.42, hspace=0.36)
    lines = []
    for k, (level, what) in enumerate(LEVELS):
        solution = common.solve(f"{NAME}_{level}_{end}")
        scene = solution.scene
        steel = scene.layers[0].material
        sigma = scene.left.history[0][1]
        u1 = incident(steel, sigma)
        ax_xt = figure.add_subplot(grid[0, k])
        ax_su = figure.add_subplot(grid[1, k])
        placed = plot_xt(solution, ax=ax_xt)
        plot_sigma_u(solution, ax=ax_su, numbers=placed.numbers)
        ax_xt.set_title(f"{sigma * GPA:g} GPa, {what}: X–t", fontsize=10,
                        pad=placed.title_pad)
        ax_su.axhline(steel.hel * GPA, color="#999999", lw=0.7, ls="--", zorder=0)
        ax_su.text(0.99, steel.hel * GPA, "HEL", transform=ax_su.get_yaxis_transform(),
                   ha="right", va="bottom", fontsize=7.5, color="#555555")
        if sigma > steel.hel:
            ax_su.axhline(2 * steel.hel * GPA, color="#cccccc", lw=0.7, ls="--", zorder=0)
            ax_su.text(0.99, 2 * steel.hel * GPA, "2 HEL", transform=ax_su.get_yaxis_transform(),
                       ha="right", va="bottom", fontsize=7.5, color="#777777")
        # the σ–u axes span the numbered states: make room for the lines drawn above them
        shown = 2 * steel.hel if sigma > steel.hel else steel.hel
        ax_su.set_ylim(top=max(ax_su.get_ylim()[1], 1.1 * shown * GPA))
        record = solution.history("right")
        final = record.states[-1]
        if end == "free":
            expected = free_surface_velocity(steel, sigma)
            text = (f"free surface at t_end: u = {final.u:.2f} m/s\n"
                    f"closed form {expected:.2f} m/s, acoustic 2 u1 = {2 * u1:.2f} m/s")
            lines.append(f"{sigma * GPA:g} GPa: u_fs {final.u:.2f} m/s (closed form "
                         f"{expected:.2f}, 2 u1 = {2 * u1:.2f})")
        else:
            expected = wall_stress(steel, sigma)
            text = (f"at the wall: σ = {final.sigma * GPA:.3f} GPa\n"
                    f"closed form {expected * GPA:.3f} GPa, acoustic 2 σ1 = "
                    f"{2 * sigma * GPA:.2f} GPa")
            lines.append(f"{sigma * GPA:g} GPa: wall stress {final.sigma * GPA:.4f} GPa "
                         f"(closed form {expected * GPA:.4f}, 2 sigma1 = "
                         f"{2 * sigma * GPA:.2f})")
        ax_su.set_title(f"σ–u, same numbers. {text[0].upper()}{text[1:]}", fontsize=9.5)
    return figure, lines


def main() -> None:
    captions = {
        "free": ("Below the HEL the wave is elastic and the free surface doubles the particle "
                 "velocity. Above it the precursor arrives first and reflects as an elastic "
                 "release to zero stress at the surface. That release meets the plastic shock, "
                 "which sends another precursor to the HEL; at 8 GPa this repeats in ever "
                 "shorter steps of 2 HEL/(ρ0 C0) = 75.5 m/s at the surface until the plastic "
                 "shock arrives. The release from a plastic state is elastic over 2 HEL and "
                 "plastic beyond (slope ρ0 CB < ρ0 C0), so the free-surface velocity stays "
                 "below 2 u1. At 8 GPa it is still approaching its closed form at t_end "
                 "(waves weaker than 10 MPa are dropped)."),
        "wall": ("A state on the yield surface reloads plastically at once, so the wall "
                 "reflects the plastic shock as a plastic shock (slope ρ0 CB) and the wall "
                 "stress σ1 + ρ0 CB u1 is below the acoustic 2 σ1. The precursor reflects "
                 "first, as an elastic reload to the HEL followed by a plastic one to "
                 "HEL + ρ0 CB HEL/(ρ0 C0) = 3.180 GPa at the wall. A wave below the HEL "
                 "(1.2 GPa) reflects with a plastic part too, because doubling would exceed "
                 "the HEL."),
    }
    titles = {"free": "from a free surface", "wall": "from a rigid wall"}
    for end in ("free", "wall"):
        figure, lines = figure_for(end)
        figure.suptitle(f"Reflection of elastic–plastic waves {titles[end]}: Davison's "
                        f"steel, 6 mm plate, sustained stress applied on the left at t = 0",
                        fontsize=12, y=0.985)
        common.caption(figure, captions[end], width=190)
        common.save(figure, f"{NAME}_{end}",
                    f"Elastic–plastic reflection {titles[end]} at 1.2, 2.8 and 8 GPa: "
                    + "; ".join(lines) + ".")
        for line in lines:
            print(f"{end}: {line}")


if __name__ == "__main__":
    main()
