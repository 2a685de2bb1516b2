"""Reflection from a free surface, and the error of "free-surface velocity = 2 u_p".

(1) The scene of 04_rigid_wall with a free rear surface: the shock reflects as
a release fan and the surface jumps to the velocity at the foot of the release
isentrope.  (2) The same symmetric impact run by the engine for several
materials and impact velocities: the free-surface velocity from the solution
against twice the particle velocity behind the shock.
"""

from __future__ import annotations

import common
import numpy as np
from matplotlib.figure import Figure
from scipy.optimize import brentq

from fronttrack.scene import Accuracy, Layer, Scene
from materials import StateOutOfRangeError, get

NAME = common.script_name(__file__)
MATERIALS = ("PMMA", "Al2024", "Cu", "W")
COLORS = {"PMMA": "#2e8b57", "Al2024": "#1f4e9c", "Cu": "#c0392b", "W": "#555555"}


def free_surface_velocity(material, impact_velocity: float) -> tuple[float, float, float]:
    """Engine run of a symmetric impact; returns ``(u_p, sigma, u_fs)`` (SI).

    A 3 mm flyer strikes a 1 mm target; the run stops after the shock has
    reflected from the target's free surface and before the flyer's release
    arrives there, so the surface shows its first plateau.
    """
    up = 0.5 * impact_velocity
    shock_speed = material.c0 + material.s * up
    t_end = 1.5 * 1e-3 / shock_speed
    scene = Scene(layers=(Layer(material, 3e-3, impact_velocity, name="flyer"),
                          Layer(material, 1e-3, 0.0, bond="unbonded", name="target")),
                  t_end=t_end, accuracy=Accuracy(rays_per_fan=8)).validate()
    solution = common.run(scene)
    rear = solution.history("right")
    sigma = material.rho0 * shock_speed * up          # principal Hugoniot: exact
    return up, sigma, float(rear.u[-1])


def release_isentrope(material, state, n: int = 80):
    """Points ``(u, sigma)`` of the release isentrope from ``state`` down to sigma = 0."""
    def stress(v):
        return material.isentrope(state, v)[0]

    v_top = material.volume_range()[1] * 0.999
    v_zero = brentq(stress, state.v, v_top)
    volumes = np.linspace(state.v, v_zero, n)
    u = [state.u + material.riemann_integral(state, v) for v in volumes]
    sigma = [stress(v) for v in volumes]
    return np.array(u), np.array(sigma)


def scene_figure() -> None:
    solution = common.solve(NAME)
    first = solution.state_at(4.0e-3, 0.25e-6)
    rear = solution.history("right")
    u_fs = float(rear.u[1])
    g = common.GPA
    error = (u_fs - 2.0 * first.u) / (2.0 * first.u) * 100.0
    figure, ax_xt, ax_su = common.xt_su_figure(
        solution, "Reflection from a free surface: a release fan, and the surface at "
        "almost 2 u_p")
    ax_su.plot([2.0 * first.u], [0.0], marker="|", color="#8b0000", ms=16, mew=1.6)
    common.note(ax_su, f"behind the shock: {first.sigma * g:.2f} GPa, u_p = {first.u:.1f} m/s\n"
                f"free surface (engine): u_fs = {u_fs:.1f} m/s\n"
                f"2 u_p = {2 * first.u:.1f} m/s (red tick): u_fs is "
                f"{common.signed(error, 2)} % off", xy=(0.02, 0.97))
    ax_su.set_ylim(ax_su.get_ylim()[0], 1.45 * first.sigma * g)
    text = (f"The same impact as 04_rigid_wall with a free rear face. The shock "
            f"({first.sigma * g:.2f} GPa, u_p = {first.u:.1f} m/s) reflects at "
            f"{rear.t[1] * common.US:.2f} µs as a centred release fan; the surface jumps to "
            f"the foot of the release isentrope of the shocked state (dashed), "
            f"u_fs = {u_fs:.1f} m/s, {error:.2f} % above 2 u_p = {2 * first.u:.0f} m/s. "
            f"The run stops before this fan meets the one from the flyer's back face (they "
            f"would pull the plates into tension, see 01 and 13).")
    common.caption(figure, text)
    common.save(figure, NAME, f"Al 2024 at 1 km/s, free rear surface: u_p = {first.u:.1f} m/s, "
                f"the free surface reaches u_fs = {u_fs:.1f} m/s "
                f"({common.signed(error, 2)} % from 2 u_p).")


def rule_figure() -> None:
    figure = Figure(figsize=(13.0, 6.2))
    grid = figure.add_gridspec(1, 2, left=0.06, right=0.985, bottom=0.22, top=0.88,
                               wspace=0.22, width_ratios=(1.0, 1.15))
    ax_su = figure.add_subplot(grid[0, 0])
    ax_err = figure.add_subplot(grid[0, 1])

    # (a) the construction for Cu at u_p = 2 km/s
    cu = get("Cu")
    up = 2000.0
    shocked = cu.wave_curve(cu.reference_state(), 1).state_at(
        cu.rho0 * (cu.c0 + cu.s * up) * up)
    u_i, s_i = release_isentrope(cu, shocked)
    u_end = u_i[-1]
    u = np.linspace(0.0, 2.0 * up, 400)
    hug = cu.rho0 * (cu.c0 + cu.s * u) * u * common.GPA
    mirror = cu.rho0 * (cu.c0 + cu.s * (2 * up - u)) * (2 * up - u) * common.GPA
    keep = u >= up
    inset = ax_su.inset_axes([0.6, 0.55, 0.37, 0.38])
    for ax in (ax_su, inset):
        ax.plot(u[u <= 1.15 * up], hug[u <= 1.15 * up], color="#c0392b", lw=1.6,
                label="principal Hugoniot")
        ax.plot(u[keep], mirror[keep], color="#444444", lw=1.3, ls=":",
                label="mirrored Hugoniot: ends at 2 u_p")
        ax.plot(u_i, s_i * common.GPA, color="#c0392b", lw=1.4, ls=(0, (4, 2)),
                label="release isentrope: ends at u_fs")
        ax.plot([u_end], [0.0], "o", color="#c0392b", ms=5, zorder=5)
        ax.plot([2 * up], [0.0], "x", color="#222222", ms=7, mew=1.4, zorder=5)
        ax.axhline(0.0, color="#999999", lw=0.6)
        ax.grid(True, lw=0.3, alpha=0.5)
    ax_su.plot([shocked.u], [shocked.sigma * common.GPA], "o", mfc="white", mec="#c0392b",
               zorder=5)
    ax_su.annotate(f"shocked state\n{shocked.sigma * common.GPA:.1f} GPa, "
                   f"u_p = {up:.0f} m/s", (shocked.u, shocked.sigma * common.GPA),
                   xytext=(-12, 4), textcoords="offset points", ha="right", fontsize=8)
    inset.set_xlim(3800.0, 4260.0)
    inset.set_ylim(-5.0, 12.0)
    inset.tick_params(labelsize=7)
    inset.set_title("near σ = 0 (zoom)", fontsize=8)
    inset.annotate(f"u_fs = {u_end:.0f}", (u_end, 0.0), xytext=(3, -6),
                   textcoords="offset points", ha="left", va="top", fontsize=8,
                   color="#c0392b")
    inset.annotate(f"2 u_p = {2 * up:.0f}", (2 * up, 0.0), xytext=(-3, -6),
                   textcoords="offset points", ha="right", va="top", fontsize=8)
    ax_su.indicate_inset_zoom(inset, edgecolor="#777777")
    ax_su.set_xlabel("particle velocity u (m/s)")
    ax_su.set_ylabel("stress σ (GPa, compression > 0)")
    ax_su.set_title(f"(a) Cu shocked to u_p = {up / 1e3:.0f} km/s and released to σ = 0",
                    fontsize=10)
    ax_su.legend(fontsize=8, loc="upper left")
    ax_su.set_xlim(0.0, 4400.0)
    ax_su.set_ylim(-3.0, 1.3 * shocked.sigma * common.GPA)

    # (b) the engine's free-surface velocity against 2 u_p
    results, limits = {}, {}
    for name in MATERIALS:
        material = get(name)
        top = material.up_max or 3000.0
        ups = np.linspace(0.1, 1.0, 8) * top
        rows = []
        for value in ups:
            try:
                rows.append(free_surface_velocity(material, 2.0 * value))
            except StateOutOfRangeError as error:  # the release leaves the EOS range
                limits[name] = (rows[-1][0] if rows else 0.0, value, str(error))
                break
        results[name] = rows
        x = np.array([r[0] for r in rows]) / 1e3
        err = np.array([(r[2] - 2 * r[0]) / (2 * r[0]) * 100.0 for r in rows])
        ax_err.plot(x, err, marker="o", ms=4, color=COLORS[name], lw=1.4,
                    label=f"{name} (fit to u_p = {top / 1e3:.1f} km/s)")
    ax_err.axhline(0.0, color="#999999", lw=0.6)
    ax_err.set_xlabel("particle velocity behind the shock u_p (km/s)")
    ax_err.set_ylabel("(u_fs − 2 u_p) / 2 u_p (%)")
    ax_err.set_title("(b) free-surface velocity from the engine against 2 u_p "
                     "(symmetric impacts)", fontsize=10)
    ax_err.legend(fontsize=8, loc="upper left")
    ax_err.grid(True, lw=0.3, alpha=0.5)
    figure.suptitle("The free-surface velocity is not exactly twice the particle velocity",
                    fontsize=12)

    def at(name, fraction):
        rows = results[name]
        up_, sigma_, ufs_ = rows[fraction]
        return up_, sigma_, ufs_, (ufs_ - 2 * up_) / (2 * up_) * 100.0

    lines = []
    for name in MATERIALS:
        up_, sigma_, ufs_, err_ = at(name, -1)
        lines.append(f"{name} {common.signed(err_, 1)} % at u_p = {up_ / 1e3:.1f} km/s "
                     f"({sigma_ * common.GPA:.0f} GPa)")
    stops = "".join(f" {name} ends at u_p = {last / 1e3:.1f} km/s: from u_p = "
                    f"{value / 1e3:.1f} km/s its release to σ = 0 leaves the range of its "
                    f"equation of state." for name, (last, value, _) in limits.items())
    text = (f"(a) Release follows the isentrope of the shocked state, which lies above the "
            f"mirrored Hugoniot (dotted): Cu shocked to {shocked.sigma * common.GPA:.0f} GPa "
            f"releases to u_fs = {u_end:.0f} m/s, not {2 * up:.0f} m/s "
            f"({(u_end - 2 * up) / (2 * up) * 100:.1f} %). (b) The error grows about as "
            f"u_p²: " + "; ".join(lines) + ". Below 1 km/s it stays under ~1 %, which is "
            "why the 2 u_p rule is the usual shortcut for gas-gun records." + stops)
    common.caption(figure, text)
    common.save(figure, f"{NAME}_rule", "Free-surface velocity vs 2 u_p from engine runs of "
                "symmetric impacts: " + "; ".join(lines) + ".")


def main() -> None:
    scene_figure()
    rule_figure()


if __name__ == "__main__":
    main()
