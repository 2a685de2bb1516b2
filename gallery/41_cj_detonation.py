"""A CJ detonation and its Taylor wave (Davison §13.1), with the σ–u diagram of the CJ point.

The gamma-law TNT of the book (ρ0 = 1600 kg/m³, Γ = 2.6, q = 4.9 MJ/kg) is initiated at
a rigid wall.  The X–t diagram shows the detonation at D_CJ and the centred simple wave
of the products behind it, ending at rest at the wall; at the far free face the
products expand to vacuum.  In the σ–u plane the detonation Hugoniot of the products
(through the unreacted state), the Rayleigh line tangent to it at the CJ point and the
Taylor wave's isentrope from CJ down to the wall state; the last panel is the pressure
profile at one time, the peaked pulse a plate in contact would receive.
"""

from __future__ import annotations

import common
import numpy as np

from materials import RIGHT
from materials.explosive import DetonationCurve

NAME = common.script_name(__file__)


def main() -> None:
    solution = common.solve(NAME)
    explosive = solution.scene.layers[0].material
    rest = explosive.reference_state()
    cj = explosive.cj_state(rest)
    d, p_cj, u_cj = cj.speed, cj.state.sigma, cj.state.u
    g, mm, us = common.GPA, common.MM, common.US
    figure, ax_xt, ax_su, ax_profile = common.xt_su_record_figure(
        solution, "CJ detonation of TNT (gamma law, Davison's example) initiated at a rigid "
                  "wall")
    # --- the sigma-u diagram: Hugoniot, Rayleigh line, CJ point, Taylor wave ---------------
    products = explosive.products
    v = np.linspace(products.hugoniot_volume_limit(rest) * 1.02, rest.v * 0.999, 400)
    sigma_h = np.array([products.hugoniot(rest, x)[0] for x in v])
    u_h = np.sqrt(sigma_h * (rest.v - v))
    strong = v <= cj.state.v
    ax_su.plot(u_h[strong], sigma_h[strong] * g, color=common.RED, lw=1.2,
               label="detonation Hugoniot (strong branch)")
    ax_su.plot(u_h[~strong], sigma_h[~strong] * g, color=common.RED, lw=1.0, ls=":",
               label="weak branch (not reached)")
    u_line = np.linspace(0.0, 1.6 * u_cj, 10)
    ax_su.plot(u_line, explosive.rho0 * d * u_line * g, color="#444444", lw=1.0, ls="--",
               label=f"Rayleigh line, slope ρ0 D_CJ (D = {d:.0f} m/s)")
    curve = DetonationCurve(explosive, rest, RIGHT)
    sigma_t = np.linspace(0.02 * p_cj, p_cj, 200)
    u_t = [curve.state_at(s).u for s in sigma_t]
    ax_su.plot(u_t, sigma_t * g, color=common.BLUE, lw=1.3, label="Taylor wave (isentrope)")
    common.mark(ax_su, u_cj, p_cj * g, f"CJ: {p_cj * g:.2f} GPa, {u_cj:.0f} m/s",
                offset=(-150, 8))
    ax_su.set_xlim(-500.0, 1.7 * u_cj)
    ax_su.set_ylim(-1.0, 1.8 * p_cj * g)
    ax_su.legend(fontsize=7.5, loc="upper left")
    # --- the pressure profile at one time ------------------------------------------------
    t = 1.0e-6
    x = np.linspace(0.0, solution.scene.length, 600)
    p = [solution.state_at(xi, t).sigma for xi in x]
    ax_profile.plot(x * mm, np.array(p) * g, color=common.BLUE, lw=1.5)
    ax_profile.axvline(d * t * mm, color=common.RED, lw=0.8, ls="--")
    ax_profile.set_xlabel("Lagrangian position X (mm)")
    ax_profile.set_ylabel("pressure σ (GPa)")
    ax_profile.set_title(f"pressure profile at t = {t * us:.1f} µs", fontsize=10)
    ax_profile.grid(True, lw=0.3, alpha=0.5)
    wall = solution.state_at(0.0, t).sigma
    common.note(ax_profile, f"peak p_CJ = {p_cj * g:.2f} GPa at the front X = D t\n"
                f"wall: {wall * g:.2f} GPa, products at rest", xy=(0.02, 0.97))
    common.caption(figure, (
        f"The detonation runs at D_CJ = {d:.0f} m/s = sqrt(2 (Γ² − 1) q); its CJ state "
        f"({p_cj * g:.2f} GPa, {u_cj:.0f} m/s) is where the Rayleigh line through the "
        f"unreacted state is tangent to the products' Hugoniot, and the products leave it "
        f"at the sound speed. Behind it the Taylor wave (a centred fan on the products' "
        f"isentrope through CJ) brings the products to rest at the wall at "
        f"{wall * g:.2f} GPa. At the free face the products expand to vacuum. The reaction "
        f"zone is infinitely thin."))
    common.save(figure, NAME, f"CJ detonation of the book's TNT from a wall: D = {d:.0f} m/s, "
                f"p_CJ = {p_cj * g:.2f} GPa, Taylor wave to rest; Rayleigh line tangent to "
                f"the products' Hugoniot.")


if __name__ == "__main__":
    main()
