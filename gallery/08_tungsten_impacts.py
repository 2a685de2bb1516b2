"""A tungsten impactor on Cu and on Al 2024 at 1, 2.5 and 10 km/s.

1 km/s is a single-stage gas gun, 2.5 km/s a powder gun, 10 km/s a two-stage
light-gas gun.  Figure 1: the six impedance matches in the σ–u plane (the W
Hugoniot from the impact velocity, falling to the right, crosses the target's
Hugoniot from rest), with the part of each linear Us–up fit beyond its fitted
range (``up_max`` in the library) dashed, and a table.  The 10 km/s cases are
also run through the engine for a short time to check that every state stays
inside the equations of state.  Figure 2: the X–t and σ–u diagrams of W on Cu
at 2.5 km/s (scene file 08_tungsten_impacts.toml).
"""

from __future__ import annotations

import common
import numpy as np
from matplotlib.figure import Figure

from fronttrack.impedance_match import impedance_match
from fronttrack.scene import Accuracy, Layer, Scene
from materials import NoSolutionError, StateOutOfRangeError, get

NAME = common.script_name(__file__)
VELOCITIES = (1000.0, 2500.0, 10000.0)
GUNS = {1000.0: "gas gun", 2500.0: "powder gun", 10000.0: "two-stage light-gas gun"}
TARGETS = ("Cu", "Al2024")
COLORS = {"W": "#555555", "Cu": "#c0392b", "Al2024": "#1f4e9c"}


def hugoniot(material, jump):
    """Principal-Hugoniot stress (Pa) for a particle-velocity jump ``jump`` (m/s)."""
    return material.rho0 * (material.c0 + material.s * jump) * jump


def draw_curve(ax, material, u, jump, **style):
    """A Hugoniot in the σ–u plane: solid inside the fitted range, dashed beyond it.

    ``u`` are the velocities of the points and ``jump`` the particle-velocity jump
    across the shock at each (the fit's variable); both arrays run in the same order.
    """
    sigma = hugoniot(material, jump) * common.GPA
    inside = jump <= (material.up_max or np.inf)
    ax.plot(u[inside], sigma[inside], ls="-", **style)
    if not inside.all():
        style.pop("label", None)
        outside = ~inside
        edge = np.nonzero(outside)[0]
        keep = np.zeros_like(outside)
        keep[max(edge[0] - 1, 0):edge[-1] + 1] = True   # join the solid part
        ax.plot(u[keep], sigma[keep], ls=(0, (4, 2)), **style)


def check_engine(flyer, target, velocity) -> tuple[bool, str]:
    """Run the impact until both shocks have reflected from the free faces.

    Returns ``(ok, report)``: whether the engine could follow it, and one line
    (events and largest compression, or the equation-of-state error).
    """
    scene = Scene(layers=(Layer(flyer, 1e-3, velocity, name="impactor"),
                          Layer(target, 2e-3, 0.0, bond="unbonded", name="target")),
                  t_end=0.3e-6, accuracy=Accuracy(rays_per_fan=8)).validate()
    try:
        solution = common.run(scene)
    except (StateOutOfRangeError, NoSolutionError) as error:
        message = str(error).split(" is outside")[0]
        return False, (f"{target.name}: the release of the shocked target to the free "
                       f"surface leaves its EOS ({message} is out of range)")
    densest = min(solution.regions, key=lambda r: r.state.v / r.material.v0)
    eps = 1.0 - densest.state.v / densest.material.v0
    return True, (f"{target.name}: the engine follows impact and release "
                  f"({solution.stats['events']} "
                  f"events; largest compression ε = {eps:.3f} in {densest.material.name}, "
                  f"EOS limit {densest.material.COMPRESSION_LIMIT / densest.material.s:.3f})")


def release_limit(flyer, target, low=2500.0, high=10000.0, steps=7) -> float:
    """Largest impact velocity (m/s, to ~60 m/s) the engine can follow through release."""
    for _ in range(steps):
        middle = 0.5 * (low + high)
        if check_engine(flyer, target, middle)[0]:
            low = middle
        else:
            high = middle
    return low


def match_figure():
    w = get("W")
    rows = {}
    for target in TARGETS:
        for velocity in VELOCITIES:
            row = impedance_match(w, velocity, [get(target)])[1]
            rows[target, velocity] = row
    figure = Figure(figsize=(13.0, 9.0))
    grid = figure.add_gridspec(2, 2, height_ratios=(1.0, 0.4), left=0.06, right=0.985,
                               bottom=0.11, top=0.92, wspace=0.2, hspace=0.25)
    ax_low = figure.add_subplot(grid[0, 0])
    ax_high = figure.add_subplot(grid[0, 1])
    ax_table = figure.add_subplot(grid[1, :])
    for ax, velocities, title in (
            (ax_low, VELOCITIES[:2], "(a) 1 km/s (gas gun) and 2.5 km/s (powder gun)"),
            (ax_high, VELOCITIES, "(b) all six, up to 10 km/s (two-stage light-gas gun)")):
        top_u = 1.08 * max(velocities)
        u = np.linspace(0.0, top_u, 400)
        for target in TARGETS:
            draw_curve(ax, get(target), u, u, color=COLORS[target], lw=1.6,
                       label=f"{target} Hugoniot from rest")
        for k, velocity in enumerate(velocities):
            uw = np.linspace(velocity, 0.0, 400)
            draw_curve(ax, w, uw, velocity - uw, color=COLORS["W"], lw=1.3,
                       label="W Hugoniot from the impact velocity" if k == 0 else None)
            for target in TARGETS:
                row = rows[target, velocity]
                beyond = get(target).beyond_fit(row.u) or w.beyond_fit(velocity - row.u)
                ax.plot([row.u], [row.sigma * common.GPA], "o", ms=6,
                        mfc="white" if beyond else COLORS[target], mec=COLORS[target],
                        mew=1.4, zorder=5)
                if ax is ax_high and velocity < 5000.0:
                    continue  # labelled in (a)
                ax.annotate(f"{row.sigma * common.GPA:.0f} GPa", (row.u, row.sigma * common.GPA),
                            xytext=(6, -10 if target == "Al2024" else 4),
                            textcoords="offset points", fontsize=8, color=COLORS[target])
        ax.set_xlim(0.0, top_u)
        ax.set_ylim(0.0, 1.5 * max(rows[t, v].sigma for t in TARGETS for v in velocities)
                    * common.GPA)
        ax.set_xlabel("particle velocity u (m/s)")
        ax.set_ylabel("stress σ (GPa, compression > 0)")
        ax.set_title(title, fontsize=10)
        ax.grid(True, lw=0.3, alpha=0.5)
    ax_high.plot([], [], ls=(0, (4, 2)), color="black", label="beyond the fitted u_p range")
    ax_high.plot([], [], "o", mfc="white", mec="black", ls="none",
                 label="match outside a fit (extrapolated)")
    ax_high.legend(fontsize=8, loc="upper left")

    # the table of the six cases
    ax_table.axis("off")
    header = ["impact", "target", "σ (GPa)", "u (m/s)", "Us (km/s)", "ρ (g/cm³)",
              "T (K)*", "u_p in target / fit", "Δu in W / fit"]
    cells = []
    for velocity in VELOCITIES:
        for target in TARGETS:
            row = rows[target, velocity]
            material = get(target)
            cells.append([f"{velocity / 1e3:g} km/s ({GUNS[velocity]})", target,
                          f"{row.sigma * common.GPA:.1f}", f"{row.u:.0f}",
                          f"{row.shock_speed / 1e3:.2f}", f"{row.rho / 1e3:.2f}",
                          f"{row.temperature:.0f}",
                          f"{row.u / 1e3:.2f} / {material.up_max / 1e3:.1f} km/s"
                          + (" beyond" if material.beyond_fit(row.u) else ""),
                          f"{(velocity - row.u) / 1e3:.2f} / {w.up_max / 1e3:.1f} km/s"
                          + (" beyond" if w.beyond_fit(velocity - row.u) else "")])
    widths = [0.2, 0.07, 0.07, 0.07, 0.08, 0.08, 0.07, 0.18, 0.18]
    table = ax_table.table(cellText=cells, colLabels=header, loc="center", cellLoc="center",
                           colWidths=widths)
    table.auto_set_font_size(False)
    table.set_fontsize(8)
    table.scale(1.0, 1.25)
    for (r, _), cell in table.get_celld().items():
        cell.set_edgecolor("#bbbbbb")
        if r == 0:
            cell.set_facecolor("#eeeeee")
        elif "beyond" in cell.get_text().get_text():
            cell.set_facecolor("#fde2e2")

    checks = [check_engine(w, get(target), 10000.0)[1] for target in TARGETS]
    limits = {target: release_limit(w, get(target)) for target in TARGETS}
    figure.suptitle("Tungsten impactor on Cu and on Al 2024: impedance matches at 1, 2.5 and "
                    "10 km/s", fontsize=12)
    cu10, al10 = rows["Cu", 10000.0], rows["Al2024", 10000.0]
    text = (f"At 1 and 2.5 km/s every state lies inside the fitted ranges. At 10 km/s the "
            f"matches ({cu10.sigma * common.GPA:.0f} GPa in Cu at u = {cu10.u / 1e3:.1f} km/s, "
            f"{al10.sigma * common.GPA:.0f} GPa in Al at {al10.u / 1e3:.1f} km/s) are "
            f"extrapolations of the linear Us–up fits (red cells), and the targets are far "
            f"above melting (*T from a constant cv: indicative only). The equations of state "
            f"hold these shocked states but not their release to zero stress: run in the "
            f"engine (1 mm W on a 2 mm target, free faces), an impact can be followed through "
            f"release only up to "
            + " and ".join(f"{v / 1e3:.1f} km/s on {k}" for k, v in limits.items())
            + ". The X–t diagram (08_tungsten_impacts_xt) is therefore the 2.5 km/s case; at "
            "10 km/s use a high-pressure fit with a release model, or a tabular EOS.")
    print(f"[check] {'; '.join(checks)}")
    common.caption(figure, text, width=175)
    common.save(figure, NAME, "W on Cu / Al 2024 at 1, 2.5, 10 km/s: "
                + ", ".join(f"{t} {v / 1e3:g} km/s {rows[t, v].sigma * common.GPA:.1f} GPa"
                            for v in VELOCITIES for t in TARGETS)
                + "; the 10 km/s states are beyond the library's fits (extrapolated).")
    return rows


def xt_figure(rows):
    solution = common.solve(NAME)
    row = rows["Cu", 2500.0]
    g = common.GPA
    figure, ax_xt, ax_su = common.xt_su_figure(
        solution, "W impactor (1 mm) on Cu (4 mm) at 2.5 km/s (powder gun)")
    rear = solution.history("right")
    u_fs = float(rear.u[1])
    common.note(ax_su, f"impact: {row.sigma * g:.1f} GPa, u = {row.u:.0f} m/s\n"
                f"Cu shock {row.shock_speed / 1e3:.2f} km/s (Lagrangian)\n"
                f"free surface: {u_fs:.0f} m/s (2 u_p = {2 * row.u:.0f})",
                xy=(0.02, 0.97))
    bottom, top = ax_su.get_ylim()
    ax_su.set_ylim(bottom, 1.3 * top)
    # the head of the release fan that enters the Cu, and where it would catch the shock
    interface = solution.scene.layers[0].thickness
    heads = [f for f in solution.fronts if f.kind == "ray" and f.direction > 0
             and abs(f.x0 - interface) < 1e-9]
    head = max(heads, key=lambda f: f.speed)
    shock = row.shock_speed
    t_catch = head.speed * head.t0 / (head.speed - shock)
    x_catch = interface + shock * t_catch
    text = (f"W has 2.2 times the impedance of Cu, so the contact keeps {row.u:.0f} m/s of the "
            f"2500 m/s and the copper is shocked to {row.sigma * g:.1f} GPa. The release from "
            f"the impactor's back face enters the Cu at {head.t0 * common.US:.2f} µs; its head "
            f"({head.speed / 1e3:.2f} km/s) is faster than the shock ({shock / 1e3:.2f} km/s) "
            f"and would overtake and attenuate it at X ≈ {x_catch * common.MM:.0f} mm. In this "
            f"4 mm target the shock reaches the free surface intact at "
            f"{rear.t[1] * common.US:.3f} µs, and the surface jumps to {u_fs:.0f} m/s. The run "
            f"stops at 0.75 µs, before the Cu spalls.")
    common.caption(figure, text)
    common.save(figure, f"{NAME}_xt", f"W on Cu at 2.5 km/s: {row.sigma * g:.1f} GPa at "
                f"{row.u:.0f} m/s; the impactor's release follows the shock into the Cu; free "
                f"surface {u_fs:.0f} m/s.")


def main() -> None:
    rows = match_figure()
    xt_figure(rows)


if __name__ == "__main__":
    main()
