"""The plastic wave of a viscoplastic solid becomes a steady wave (Davison §10.3.2).

An elastic steel flyer at 560 m/s strikes elastic–viscoplastic steel (overstress law,
τ = 2 ns) whose relaxed path, the Us–up Hugoniot pressure (s = 1.49) plus 2Y/3, is
convex.  The precursor decays to the HEL within a few tenths of a millimetre; the
plastic wave behind it steepens against its own spreading and runs unchanged at the speed
D the jump conditions give between the HEL state A and the final state B, every state
inside it on the Rayleigh line from A to B.  Left: stress profiles of the grid at four
times against the steady profile integrated from ``d xi/d eps = -D (M - ρ0 D²) / (2 μ φ)``
(``materials.steady_wave``), each placed at the grid's mid-stress point.  Right: the
states of the last profile in the σ–ε plane, on the Rayleigh line above the convex relaxed
path.  The scene file runs through ``ft.run`` / ``wavediagram run`` like any other; the
viscoplastic layer sends it to the characteristic grid (second order), not the engine.
"""

from __future__ import annotations

import common
import numpy as np
from matplotlib.figure import Figure
from scipy.optimize import brentq

from fronttrack.runner import run
from materials.steady_wave import steady_wave

NAME = common.script_name(__file__)
MM, US, GPA = common.MM, common.US, common.GPA
TIMES = (0.15e-6, 0.3e-6, 0.45e-6, 0.6e-6)
COLORS = ("#9ecae1", "#4292c6", "#2171b5", "#08306b")


def final_wave(scene):
    """The steady wave whose final state B the elastic flyer holds: on the flyer's line
    sigma = Z_f (V - u) and on the relaxed path (brentq on the contact velocity)."""
    flyer, target = scene.layers
    mat, z_f = target.material, flyer.material.impedance
    hel_u = mat.hel / mat.impedance

    def mismatch(u):
        return steady_wave(mat, u).behind[0] - z_f * (flyer.velocity - u)

    return steady_wave(mat, brentq(mismatch, 1.01 * hel_u, flyer.velocity, xtol=1e-10))


def crossing(run_, level, target):
    sigma = run_.sigma[level]
    nodes = np.nonzero(np.isfinite(sigma))[0]
    x, s = nodes * run_.dx, sigma[nodes]
    k = np.nonzero((s[:-1] >= target) & (s[1:] < target))[0][-1]
    return x[k] + (s[k] - target) / (s[k] - s[k + 1]) * (x[k + 1] - x[k])


def main() -> None:
    scene = common.scene(NAME)
    solution = run(scene)
    grid, origin = solution.run, solution.origin
    mat = grid.material
    print(f"[stats] {NAME}: grid cells={solution.stats['cells']} "
          f"levels={solution.stats['levels']}")
    wave = final_wave(scene)
    (sigma_a, _, eps_a), (sigma_b, u_b, eps_b) = wave.ahead, wave.behind
    fractions = np.linspace(0.02, 0.98, 49)
    xi = wave.position(fractions)
    profile = sigma_a + fractions * (sigma_b - sigma_a)
    figure = Figure(figsize=(13.0, 6.0))
    ax_x, ax_s = figure.subplots(1, 2, gridspec_kw={"width_ratios": [1.3, 1.0]})
    figure.subplots_adjust(left=0.06, right=0.98, top=0.88, bottom=0.22, wspace=0.22)
    widths, speeds, mids = [], [], []
    for t, color in zip(TIMES, COLORS, strict=True):
        level = int(round(t / grid.dt))
        level -= level % 2
        sigma = grid.sigma[level]
        nodes = np.nonzero(np.isfinite(sigma))[0]
        ax_x.plot((origin + nodes * grid.dx) * MM, sigma[nodes] * GPA, color=color, lw=1.3,
                  label=f"grid, t = {level * grid.dt * US:.2f} µs")
        mid = crossing(grid, level, 0.5 * (sigma_a + sigma_b))
        mids.append((level * grid.dt, mid))
        widths.append(crossing(grid, level, sigma_a + 0.1 * (sigma_b - sigma_a))
                      - crossing(grid, level, sigma_a + 0.9 * (sigma_b - sigma_a)))
        ax_x.plot((origin + mid + xi) * MM, profile * GPA, color=common.RED, lw=1.0,
                  ls="--", label="steady-wave ODE" if t == TIMES[-1] else None)
    for (t0, x0), (t1, x1) in zip(mids[:-1], mids[1:], strict=True):
        speeds.append((x1 - x0) / (t1 - t0))
    ax_x.axhline(mat.hel * GPA, color="#777777", lw=0.7, ls=":")
    ax_x.text(origin * MM + 0.05, mat.hel * GPA + 0.2, f"HEL {mat.hel * GPA:.2f} GPa",
              fontsize=8, color="#555555")
    ax_x.set_xlabel("Lagrangian position X (mm)")
    ax_x.set_ylabel("stress σ (GPa, compression > 0)")
    ax_x.set_title("stress profiles in the target: the plastic wave settles", fontsize=10)
    ax_x.legend(fontsize=8, loc="upper right")
    ax_x.grid(True, lw=0.3, alpha=0.5)

    last = mids[-1][0]
    level = int(round(last / grid.dt))
    sigma, plastic = grid.sigma[level], grid.plastic_strain[level]
    known = np.isfinite(sigma)
    eps = mat.strain(sigma[known], plastic[known])
    strains = np.linspace(0.0, 1.1 * eps_b, 200)
    ax_s.plot(strains, (mat.pressure(strains) + 2.0 * mat.yield_strength / 3.0) * GPA,
              color="#555555", lw=1.2, label="relaxed path p(ε) + 2Y/3 (convex)")
    elastic = strains[strains <= 1.3 * eps_a]
    ax_s.plot(elastic, mat.modulus * elastic * GPA, color="#2e8b57", lw=1.0,
              label="elastic line σ = M ε")
    ax_s.plot([eps_a, eps_b], [sigma_a * GPA, sigma_b * GPA], color=common.RED, lw=1.0,
              ls="--", label=f"Rayleigh line A → B, D = {wave.speed:.0f} m/s")
    ax_s.plot(eps, sigma[known] * GPA, ".", color=COLORS[-1], ms=2.5,
              label=f"grid states at t = {last * US:.2f} µs")
    ax_s.plot([eps_a, eps_b], [sigma_a * GPA, sigma_b * GPA], "o", color="black", ms=4)
    ax_s.annotate("A (HEL)", (eps_a, sigma_a * GPA), xytext=(8, -12),
                  textcoords="offset points", fontsize=8)
    ax_s.annotate("B", (eps_b, sigma_b * GPA), xytext=(-14, 4), textcoords="offset points",
                  fontsize=8)
    ax_s.set_xlabel("compression ε = 1 − v/v0")
    ax_s.set_ylabel("stress σ (GPa, compression > 0)")
    ax_s.set_title("σ–ε: the wave's states on the Rayleigh line", fontsize=10)
    ax_s.legend(fontsize=8, loc="upper left")
    ax_s.grid(True, lw=0.3, alpha=0.5)
    figure.suptitle("Steady plastic wave in viscoplastic steel (τ = 2 ns, convex relaxed "
                    "path), elastic flyer at 560 m/s", fontsize=12)
    width = wave.width()
    text = (f"Steady wave from A (HEL {sigma_a * GPA:.3f} GPa) to B ({sigma_b * GPA:.2f} GPa, "
            f"u {u_b:.1f} m/s): D = {wave.speed:.1f} m/s from the jump conditions, 10–90 % "
            f"width {width * 1e6:.1f} µm from the ODE. Grid (dX = "
            f"{grid.dx * 1e6:.1f} µm): width " + ", ".join(
                f"{w * 1e6:.1f}" for w in widths) + " µm at "
            + ", ".join(f"{t * US:.2f}" for t in TIMES) + " µs; mid-point speed "
            + ", ".join(f"{s:.1f}" for s in speeds) + " m/s between them.")
    common.caption(figure, text)
    common.save(figure, NAME, text)


if __name__ == "__main__":
    main()
