"""The ZND reaction zone of a CJ detonation (Davison §13.2).

The engine's detonations have an infinitely thin reaction zone.  Its steady structure
(``materials.znd``): the lead shock compresses the unreacted PBX 9501 to the von Neumann
spike on its own Hugoniot, and the reaction then brings the state down the Rayleigh
line to the CJ point, at a rate ``dλ/dt = k (1 − λ)^½`` (a stated law, complete after
``2/k``; here k = 1e8 1/s).
"""

from __future__ import annotations

import common
import numpy as np
from matplotlib.figure import Figure

from materials import library
from materials.znd import znd_profile

NAME = common.script_name(__file__)
RATE = 1e8
"""Rate constant k (1/s) of the stated reaction law."""


def main() -> None:
    explosive = library.get("PBX9501")
    profile = znd_profile(explosive, RATE)
    rest = explosive.reference_state()
    cj = explosive.cj_state(rest)
    g, mm = common.GPA, common.MM
    figure = Figure(figsize=(13.0, 5.6))
    grid = figure.add_gridspec(1, 2, left=0.06, right=0.985, bottom=0.2, top=0.86, wspace=0.25)
    ax_p, ax_v = figure.add_subplot(grid[0, 0]), figure.add_subplot(grid[0, 1])
    ax_p.plot(profile.distance * mm, profile.sigma * g, color=common.BLUE, lw=1.6,
              label="pressure")
    ax_p.set_xlabel("Lagrangian distance behind the front D t (mm)")
    ax_p.set_ylabel("pressure σ (GPa)")
    ax_p.grid(True, lw=0.3, alpha=0.5)
    twin = ax_p.twinx()
    twin.plot(profile.distance * mm, profile.reacted, color="#555555", lw=1.0, ls="--",
              label="reacted fraction λ")
    twin.set_ylabel("reacted fraction λ")
    twin.set_ylim(0.0, 1.05)
    ax_p.set_title("ZND profile: spike, reaction zone, CJ point", fontsize=10)
    ax_p.legend(fontsize=8, loc="center left")
    twin.legend(fontsize=8, loc="center right")
    # the sigma-v plane
    v = np.linspace(0.55, 1.0, 300) * explosive.v0
    unreacted = [explosive.unreacted.hugoniot(rest, x)[0] for x in v]
    products = [explosive.products.hugoniot(rest, x)[0] for x in v]
    ax_v.plot(v / explosive.v0, np.array(unreacted) * g, color="#444444", lw=1.0,
              label="unreacted Hugoniot")
    ax_v.plot(v / explosive.v0, np.array(products) * g, color=common.RED, lw=1.0,
              label="products (detonation) Hugoniot")
    line = explosive.rho0**2 * cj.speed**2 * (explosive.v0 - v)
    ax_v.plot(v / explosive.v0, line * g, color="#888888", lw=0.9, ls="--",
              label=f"Rayleigh line, D = {cj.speed:.0f} m/s")
    ax_v.plot(profile.v / explosive.v0, profile.sigma * g, color=common.BLUE, lw=2.2,
              label="reaction path")
    common.mark(ax_v, profile.v[0] / explosive.v0, profile.sigma[0] * g,
                f"von Neumann spike {profile.sigma[0] * g:.1f} GPa", offset=(12, 4))
    common.mark(ax_v, cj.state.v / explosive.v0, cj.state.sigma * g,
                f"CJ {cj.state.sigma * g:.1f} GPa", offset=(14, -14), va="top")
    ax_v.set_xlim(0.55, 1.0)
    ax_v.set_ylim(0.0, 70.0)
    ax_v.set_xlabel("relative volume v/v0")
    ax_v.set_ylabel("pressure σ (GPa)")
    ax_v.grid(True, lw=0.3, alpha=0.5)
    ax_v.legend(fontsize=8, loc="upper right")
    ax_v.set_title("the reaction path on the Rayleigh line", fontsize=10)
    figure.suptitle("ZND structure of the PBX 9501 detonation (the engine keeps it "
                    "infinitely thin)", fontsize=12, y=0.985)
    common.caption(figure, (
        f"The lead shock takes the unreacted explosive to the von Neumann spike "
        f"({profile.sigma[0] * g:.1f} GPa) on the unreacted Hugoniot; the reaction "
        f"(dλ/dt = k (1 − λ)^½, k = {RATE:.0e} 1/s) releases its heat while the state moves "
        f"down the Rayleigh line to the CJ point ({cj.state.sigma * g:.1f} GPa), reached "
        f"{profile.distance[-1] * mm:.2f} mm behind the front. The unreacted Hugoniot is "
        f"an approximate Us–up fit (explosives.toml)."))
    common.save(figure, NAME, f"ZND profile of PBX 9501: spike {profile.sigma[0] * g:.1f} "
                f"GPa down the Rayleigh line to CJ {cj.state.sigma * g:.1f} GPa.")


if __name__ == "__main__":
    main()
