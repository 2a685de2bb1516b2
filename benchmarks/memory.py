"""Memory of long runs: bytes per event during and after the solve, and while writing JSON.

    python benchmarks/memory.py             # writes benchmarks/MEMORY.md
    python benchmarks/memory.py --quick     # shorter runs, printed only

Each scene is solved once under ``tracemalloc`` (one frame: the counts are the same
with more, the run is slower) after a short warm-up run, so the library, the materials
and the code are loaded before the baseline is taken.  Reported, divided by the
solution's events:

- *peak*: the largest memory traced during ``ft.run`` (solve, balance, warnings) above
  the baseline;
- *retained*: what the ``Solution`` holds once ``ft.run`` has returned and the garbage
  collector has run (the columns of ``fronttrack.archive``, the event log, the lattice
  patches, the isentrope tables and the query caches the balance filled);
- *JSON peak*: the largest memory above *retained* while ``write_json`` streams the full
  document (with polygons) to ``os.devnull``.

The solve time is measured in a separate run without ``tracemalloc`` (which slows Python
about threefold), and the machine's load average is stated: the machine is shared.
Scenes: Davison's steel (5 mm onto 10 mm at 230 m/s, ``benchmarks/run_length.py``) to
6, 10 and 20 µs, and the built-in ``wavediagram demo`` scene (Cu on Al 2024, 8 rays per
fan, lattices).
"""

from __future__ import annotations

import argparse
import gc
import os
import platform
import sys
import time
import tracemalloc
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "benchmarks"))

from run_length import steel  # noqa: E402

import fronttrack as ft  # noqa: E402

NOTES = "\n## Notes"
"""MEMORY.md keeps what follows this heading (written by hand) when it is rewritten."""


def demo() -> ft.Scene:
    return ft.load_scene(ROOT / "fronttrack" / "scenes" / "demo.toml")


def measure(build) -> dict:
    """Peak and retained bytes of ``ft.run(build())`` and the peak of its JSON, traced."""
    gc.collect()
    tracemalloc.start(1)
    try:
        base = tracemalloc.get_traced_memory()[0]
        solution = ft.run(build())
        gc.collect()
        retained, peak = tracemalloc.get_traced_memory()
        tracemalloc.reset_peak()
        with open(os.devnull, "w") as sink:
            solution.write_json(sink)
        json_peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    return {"events": solution.stats["events"], "fronts": solution.stats["fronts"],
            "regions": solution.stats["regions"], "peak": peak - base,
            "retained": retained - base, "json_peak": json_peak - retained}


def seconds(build) -> float:
    """Wall-clock seconds of ``ft.run(build())``, untraced."""
    gc.collect()
    start = time.perf_counter()
    ft.run(build())
    return time.perf_counter() - start


def row(name: str, build) -> str:
    found = measure(build)
    events = found["events"]
    line = (f"| {name} | {events} | {found['fronts']} | {found['regions']} | "
            f"{found['peak'] / events:.0f} | {found['retained'] / events:.0f} | "
            f"{found['retained'] / 1e6:.2f} | {found['json_peak'] / 1e6:.2f} | "
            f"{seconds(build):.2f} |")
    print(line, flush=True)
    return line


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true")
    args = parser.parse_args()
    ft.run(steel(1e-6, ft.Accuracy()))  # warm-up: library, materials, code
    lengths = (2e-6, 6e-6) if args.quick else (6e-6, 10e-6, 20e-6)
    cases = [(f"Davison steel to {t * 1e6:g} µs", lambda t=t: steel(t, ft.Accuracy()))
             for t in lengths]
    cases.append(("`wavediagram demo` (Cu on Al 2024, 3 µs)", demo))
    load_before = os.getloadavg()
    header = ["| scene | events | fronts | regions | peak (B/event) | retained (B/event) | "
              "retained (MB) | JSON peak (MB) | solve (s) |",
              "|---|---:|---:|---:|---:|---:|---:|---:|---:|"]
    print("\n".join(header), flush=True)
    rows = [row(name, build) for name, build in cases]
    load_after = os.getloadavg()
    lines = ["# Memory of long runs", "",
             f"`python benchmarks/memory.py`; {platform.machine()}, {os.cpu_count()} cores, "
             f"Python {platform.python_version()}, "
             f"{time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}; "
             f"load average {load_before[0]:.1f} before and {load_after[0]:.1f} after "
             "(a shared machine: other jobs ran beside these).", "",
             "Bytes traced by `tracemalloc` above a baseline taken after a warm-up run, "
             "divided by the solution's events (see the script's docstring).", "",
             *header, *rows, ""]
    if not args.quick:
        out = ROOT / "benchmarks" / "MEMORY.md"
        old = out.read_text() if out.exists() else ""
        notes = old[old.index(NOTES):] if NOTES in old else ""
        out.write_text("\n".join(lines) + notes)
        print(f"wrote {out}")


if __name__ == "__main__":
    main()
