"""Benchmarks of the hull wave curve and the viscoplastic characteristic grid.

    python benchmarks/solids.py            # prints a Markdown table (about a minute)

- Hull wave curve (``materials.hull`` on ``materials.saturating_plastic``): building a
  curve's two hulls from a new ahead state, and one ``velocity_change`` on it (the
  Riemann solver's unit of work), cold and from the material's hull cache.
- The engine on gallery 34's scene (Voce plate impact, 4 rays per fan, 0.45 us).
- ``characteristics.viscoplastic_grid``: a 4 mm steel layer to 1 us at 50, 100, 200 and
  400 cells (levels, seconds, precursor error at 2 mm against the scipy reference of
  tests/test_viscoplastic.py).
- The steady plastic wave (``materials.steady_wave``): steel with a convex equilibrium
  pressure (s = 1.49, tau = 2 ns), piston at 300 m/s, 4 mm to 0.6 us at 400, 800 and
  1600 cells: seconds, the 10-90 % width and the mid-point speed against the ODE's and
  the jump conditions' (the rest of the width gap is the wave still settling).
- Gallery 35's scene through ``fronttrack.run`` (dispatched to the grid).

Not run by the tests.  Wall-clock seconds on this machine, which other processes may
share: the script states the load average.
"""

from __future__ import annotations

import os
import sys
import time
from pathlib import Path

import numpy as np
from scipy.integrate import solve_ivp

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

from characteristics.viscoplastic_grid import run_layer  # noqa: E402
from fronttrack.runner import run  # noqa: E402
from fronttrack.scene_file import load_scene  # noqa: E402
from materials import RIGHT  # noqa: E402
from materials.saturating_plastic import SaturatingPlastic  # noqa: E402
from materials.steady_wave import steady_wave  # noqa: E402
from materials.viscoplastic import Viscoplastic  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent


def hull_timings() -> list[tuple[str, float]]:
    mat = SaturatingPlastic("Al-Voce", 2700.0, 5350.0, 1.34, 26.0e9, 0.3e9, 0.8e9, 0.002)
    start = mat.wave_curve(mat.reference_state(), RIGHT).state_at(5.0e9)
    rows = []
    t = time.perf_counter()
    curve = mat.wave_curve(start.moving(1.0), RIGHT)
    curve.sigma_limits()
    rows.append(("build both hulls (new ahead state)", time.perf_counter() - t))
    t = time.perf_counter()
    curve.velocity_change(7.0e9)
    rows.append(("velocity_change, first target", time.perf_counter() - t))
    t = time.perf_counter()
    for sigma in np.linspace(5.5e9, 9.0e9, 50):
        mat.wave_curve(start.moving(1.0), RIGHT).velocity_change(float(sigma))
    rows.append(("velocity_change, cached hull (mean of 50)", (time.perf_counter() - t) / 50))
    t = time.perf_counter()
    solution = run(load_scene(ROOT / "gallery" / "scenes" / "34_saturating_hardening.toml"))
    rows.append((f"engine, gallery 34 scene ({solution.stats['events']} events)",
                 time.perf_counter() - t))
    return rows


def grid_timings() -> list[tuple[int, int, float, float]]:
    mat = Viscoplastic("steel", 7870.0, 123.1e9, 79.29e9, 1.0e9, 50e-9)
    m, mu, c0, s_y = mat.modulus, mat.mu, mat.C0, 2.0e9 / 3.0

    def rhs(_, s):
        over = max(4.0 * mu * s[0] / (3.0 * m) / s_y - 1.0, 0.0)
        return [-(mu / c0) * s_y / (2.0 * mu * mat.relaxation_time) * over]

    reference = solve_ivp(rhs, (0.0, 2e-3), [mat.impedance * 300.0], method="DOP853",
                          rtol=1e-12, atol=1e-3).y[0, -1]
    rows = []
    for cells in (50, 100, 200, 400):
        t = time.perf_counter()
        layer = run_layer(mat, 4e-3, 300.0, 1.0e-6, cells)
        seconds = time.perf_counter() - t
        k = int(np.argmin(np.abs(layer.precursor_x - 2e-3)))
        rows.append((cells, layer.sigma.shape[0], seconds,
                     abs(layer.precursor_sigma[k] - reference) / reference))
    return rows


def steady_timings() -> list[tuple[int, float, float, float]]:
    mat = Viscoplastic("steel", 7870.0, 123.1e9, 79.29e9, 1.0e9, 2e-9, 1.0, 1.49)
    wave = steady_wave(mat, 300.0)
    (sigma_a, _, _), (sigma_b, _, _) = wave.ahead, wave.behind

    def crossing(layer, level, fraction):
        sigma = layer.sigma[level]
        nodes = np.nonzero(np.isfinite(sigma))[0]
        x, s = nodes * layer.dx, sigma[nodes]
        target = sigma_a + fraction * (sigma_b - sigma_a)
        k = np.nonzero((s[:-1] >= target) & (s[1:] < target))[0][-1]
        return x[k] + (s[k] - target) / (s[k] - s[k + 1]) * (x[k + 1] - x[k])

    rows = []
    for cells in (400, 800, 1600):
        t = time.perf_counter()
        layer = run_layer(mat, 4e-3, 300.0, 0.6e-6, cells)
        seconds = time.perf_counter() - t
        last = layer.sigma.shape[0] - 1
        last -= last % 2
        earlier = last - 2 * (last // 8)
        width = crossing(layer, last, 0.1) - crossing(layer, last, 0.9)
        speed = ((crossing(layer, last, 0.5) - crossing(layer, earlier, 0.5))
                 / ((last - earlier) * layer.dt))
        rows.append((cells, seconds, width / wave.width() - 1.0, speed / wave.speed - 1.0))
    return rows


def scene_timing() -> tuple[int, float]:
    t = time.perf_counter()
    solution = run(load_scene(ROOT / "gallery" / "scenes" / "35_viscoplastic_steady_wave.toml"))
    return solution.stats["cells"], time.perf_counter() - t


def main() -> None:
    print(f"load average {os.getloadavg()[0]:.2f} on {os.cpu_count()} cores\n")
    print("| hull wave curve | seconds |\n|---|---:|")
    for label, seconds in hull_timings():
        print(f"| {label} | {seconds:.4f} |")
    print("\n| cells | levels | seconds | precursor error at 2 mm |\n|---:|---:|---:|---:|")
    for cells, levels, seconds, error in grid_timings():
        print(f"| {cells} | {levels} | {seconds:.2f} | {error:.2e} |")
    print("\n| steady wave: cells | seconds | width / ODE - 1 | speed / D - 1 |\n"
          "|---:|---:|---:|---:|")
    for cells, seconds, width, speed in steady_timings():
        print(f"| {cells} | {seconds:.2f} | {width:+.2e} | {speed:+.2e} |")
    cells, seconds = scene_timing()
    print(f"\ngallery 35 scene through fronttrack.run: {cells} cells, {seconds:.1f} s")


if __name__ == "__main__":
    main()
