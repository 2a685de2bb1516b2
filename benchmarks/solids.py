"""Benchmarks of the hull wave curve and the viscoplastic characteristic grid.

    python benchmarks/solids.py            # prints a Markdown table (about a minute)

- Hull wave curve (``materials.hull`` on ``materials.saturating_plastic``): building a
  curve's two hulls from a new ahead state, and one ``velocity_change`` on it (the
  Riemann solver's unit of work), cold and from the material's hull cache.
- The engine on gallery 34's scene (Voce plate impact, 4 rays per fan, 0.45 us).
- ``characteristics.viscoplastic_grid``: a 4 mm steel layer to 1 us at 50, 100, 200 and
  400 cells (levels, seconds, precursor error at 2 mm against the scipy reference of
  tests/test_viscoplastic.py).

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


def main() -> None:
    print(f"load average {os.getloadavg()[0]:.2f} on {os.cpu_count()} cores\n")
    print("| hull wave curve | seconds |\n|---|---:|")
    for label, seconds in hull_timings():
        print(f"| {label} | {seconds:.4f} |")
    print("\n| cells | levels | seconds | precursor error at 2 mm |\n|---:|---:|---:|---:|")
    for cells, levels, seconds, error in grid_timings():
        print(f"| {cells} | {levels} | {seconds:.2f} | {error:.2e} |")


if __name__ == "__main__":
    main()
