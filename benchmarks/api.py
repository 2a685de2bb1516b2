"""Benchmarks of the Python API: impedance matches per second, sweep speed-up, Dask overhead.

    python benchmarks/api.py            # prints a Markdown table (about a minute)

- ``ft.match``: Cu onto Al 2024 then PMMA at velocities from 200 to 2000 m/s, on one
  core, with materials given by name (the user's call) and as objects.
- Sweep speed-up: the common spall experiment (Al 2024 1 mm onto 2 mm at 300 m/s,
  4 rays per fan, to 1.2 us) at 8 velocities, serially and in 2 processes.
- Dask overhead per task: 40 shock-only points (Cu onto Al 2024, release on the
  Hugoniot) on a ``LocalCluster`` of 2 single-threaded workers against the serial
  time: ``(2 t_dask - t_serial) / points``.

Not run by the tests.  Times are wall-clock seconds on this machine, which other
processes may share: the script states the machine and the load average.
"""

from __future__ import annotations

import os
import platform
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

import fronttrack as ft  # noqa: E402


def match_rate(by_name: bool, count: int = 3000) -> tuple[float, float]:
    """Impedance matches per second through ``ft.match``: per second of wall-clock time
    and per second of this process's CPU time (what one core gives it, whatever else
    the machine runs)."""
    flyer, stack = ("Cu", ["Al2024", "PMMA"]) if by_name else (
        ft.material("Cu"), [ft.material("Al2024"), ft.material("PMMA")])
    velocities = np.linspace(200.0, 2000.0, count)
    start, cpu = time.perf_counter(), time.process_time()
    for velocity in velocities:
        ft.match(flyer, float(velocity), stack)
    return count / (time.perf_counter() - start), count / (time.process_time() - cpu)


def timed_sweep(scene, velocities, backend, **options) -> float:
    start = time.perf_counter()
    table = ft.sweep(scene, {"layer.0.velocity": velocities}, ["spall_x", "events"],
                     backend=backend, **options)
    assert all(row["error"] is None for row in table.rows)
    return time.perf_counter() - start


def main() -> None:
    print(f"Machine: {platform.machine()}, {os.cpu_count()} cores, Python "
          f"{platform.python_version()}; load average before: {os.getloadavg()[0]:.2f}\n")
    print("| measure | value |\n|---|---|")
    for by_name, what in ((True, "materials by name"), (False, "material objects")):
        wall, cpu = match_rate(by_name)
        print(f"| ft.match, {what} (matches per wall / CPU second, one core) | "
              f"{wall:.0f} / {cpu:.0f} |")

    spall = ft.Scene([ft.Layer("Al2024", "1 mm", velocity="300 m/s"),
                      ft.Layer("Al2024", "2 mm")], t_end="1.2 us",
                     accuracy=ft.Accuracy(rays_per_fan=4))
    velocities = [f"{v} m/s" for v in np.linspace(250.0, 320.0, 8)]
    serial = timed_sweep(spall, velocities, "serial")
    parallel = timed_sweep(spall, velocities, "processes", workers=2)
    print(f"| spall sweep, 8 points: serial (s) | {serial:.2f} |")
    print(f"| spall sweep, 8 points: 2 processes (s) | {parallel:.2f} |")
    print(f"| process speed-up on 2 cores | {serial / parallel:.2f} |")

    shocks = ft.Scene([ft.Layer("Cu", "1 mm", velocity="500 m/s"), ft.Layer("Al2024", "2 mm")],
                      t_end="0.6 us", accuracy=ft.Accuracy(release="hugoniot"))
    quick = [f"{v} m/s" for v in np.linspace(200.0, 1200.0, 40)]
    serial = timed_sweep(shocks, quick, "serial")
    try:
        from dask.distributed import Client, LocalCluster
    except ImportError:
        print("| Dask overhead per task | dask.distributed not installed |")
        return
    with LocalCluster(n_workers=2, threads_per_worker=1, dashboard_address=None) as cluster, \
            Client(cluster) as client:
        timed_sweep(shocks, quick[:4], "dask", client=client)  # workers import the code
        dask = timed_sweep(shocks, quick, "dask", client=client)
    print(f"| shock-only sweep, 40 points: serial (s) | {serial:.3f} |")
    print(f"| same on Dask, 2 workers (s) | {dask:.3f} |")
    print(f"| Dask overhead per task (ms) | {(2 * dask - serial) / len(quick) * 1e3:.1f} |")
    print(f"\nLoad average after: {os.getloadavg()[0]:.2f}")


if __name__ == "__main__":
    main()
