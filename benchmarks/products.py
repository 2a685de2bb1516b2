"""Detonation products: the tabulated isentrope against the quadrature it replaced.

    python benchmarks/products.py            # prints a Markdown table (PRODUCTS.md)

(a) The Riemann-invariant integral ``J = int rho0 C_L dv`` of JWL products along the
isentrope through the CJ state, from ``v_CJ`` to 2000 volumes between ``0.5 v_CJ`` and
``50 v_CJ``: the Chebyshev table (``materials.products_isentrope``, built once per
isentrope) against the Gauss–Legendre quadrature in ``y = V^(-omega/2)`` the products used
before (16 points on panels of 0.02 in ``y``, reproduced here as the reference), time per
call and the largest difference relative to ``J``.  (b) Runs that spend their time on
products: 10 mm of JWL TNT initiated at a wall, 2 us, characteristic step 1 GPa; and the
open-faced gamma = 3 charge of ``tests/test_gurney.py``.  Wall-clock seconds on this
machine; the load average is printed with them.
"""

from __future__ import annotations

import math
import os
import platform
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "tests"))

import fronttrack as ft  # noqa: E402
from materials import library  # noqa: E402
from materials.quadrature import unit_rule  # noqa: E402

PANEL, POINTS = 0.02, 16


def quadrature(products, through, v) -> float:
    """The reference: ``int rho0 C_L dv`` by Gauss–Legendre in ``y`` (the former method)."""
    k = products.isentrope_constant(through)
    y0, y1 = products.y(through.v), products.y(v)
    count = max(1, math.ceil(abs(y1 - y0) / PANEL))
    nodes, weights = unit_rule(POINTS)
    edges = np.linspace(y0, y1, count + 1)
    y = edges[:-1, None] + (edges[1:] - edges[:-1])[:, None] * nodes
    big_v = y ** (-2.0 / products.omega)
    c2 = products.v0 * (products.A * products.R1 * np.exp(-products.R1 * big_v)
                        + products.B * products.R2 * np.exp(-products.R2 * big_v))
    integrand = -2.0 / products.omega * np.sqrt(
        c2 * big_v ** (2.0 + products.omega)
        + products.v0 * (1.0 + products.omega) * products.omega * products.rho0 * k)
    return float(np.sum((edges[1:] - edges[:-1]) * (integrand @ weights)))


def integrals(name: str) -> tuple[float, float, float]:
    """(table us/call, quadrature us/call, largest relative difference) for ``name``."""
    explosive = library.get(name)
    products = explosive.products
    cj = explosive.cj_state(explosive.reference_state()).state
    volumes = (np.linspace(0.5, 50.0, 2000) * cj.v).tolist()
    start = time.perf_counter()
    table = [products.riemann_integral(cj, v) for v in volumes]
    t_table = (time.perf_counter() - start) / len(volumes)
    start = time.perf_counter()
    reference = [quadrature(products, cj, v) for v in volumes]
    t_quad = (time.perf_counter() - start) / len(volumes)
    scale = max(abs(r) for r in reference)
    worst = max(abs(a - b) for a, b in zip(table, reference, strict=True)) / scale
    return 1e6 * t_table, 1e6 * t_quad, worst


def runs() -> list[tuple[str, float, int, dict]]:
    from test_gurney import ACCURACY, CHARGE, PLATE

    scenes = {
        "TNT (JWL) 10 mm at a wall, 2 us, step 1 GPa": ft.Scene(
            [ft.Layer("TNT", "10 mm", initiate="left")], left=ft.Boundary("wall"),
            t_end="2 us", accuracy=ft.Accuracy(characteristic_step="1 GPa")),
        "gamma = 3 charge, open-faced 1.6 mm plate, 6 us": ft.Scene(
            [ft.Layer(CHARGE, "10 mm", initiate="left"), ft.Layer(PLATE, "1.6 mm")],
            left=ft.Boundary("free"), t_end="6 us", accuracy=ACCURACY),
    }
    out = []
    for name, scene in scenes.items():
        start = time.perf_counter()
        solution = ft.run(scene)
        out.append((name, time.perf_counter() - start, len(solution.events),
                    solution.accuracy_report["balance"]))
    return out


def main() -> None:
    print(f"Machine: {platform.processor() or platform.machine()}, {os.cpu_count()} cores, "
          f"load average {os.getloadavg()[0]:.2f} at the start\n")
    print("| explosive | table (us/call) | quadrature (us/call) | speed-up | max rel. diff |")
    print("|---|---:|---:|---:|---:|")
    for name in ("TNT", "PBX9501", "NM"):
        t_table, t_quad, worst = integrals(name)
        print(f"| {name} | {t_table:.1f} | {t_quad:.1f} | {t_quad / t_table:.0f}x | "
              f"{worst:.1e} |")
    print("\n| run | seconds | events | momentum balance | energy balance | promised |")
    print("|---|---:|---:|---:|---:|---:|")
    for name, seconds, events, balance in runs():
        print(f"| {name} | {seconds:.1f} | {events} | {balance['momentum_error']:.2g} | "
              f"{balance['energy_error']:.2g} | {balance['promised']:.2g} |")
    print(f"\nload average {os.getloadavg()[0]:.2f} at the end")


if __name__ == "__main__":
    main()
