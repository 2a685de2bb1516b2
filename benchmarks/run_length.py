"""Cost against simulated time: events and seconds as a scene runs longer.

    python benchmarks/run_length.py            # writes benchmarks/RUN_LENGTH.md
    python benchmarks/run_length.py --quick    # fewer lengths, for a smoke test
    python benchmarks/run_length.py --stacks   # only (d), replaced in RUN_LENGTH.md
    python benchmarks/run_length.py --case b   # only (b), printed (nothing written)

For scenes whose wave content does not grow, events and solve time should grow
linearly with the simulated time ``T``; the fitted exponent ``d ln(events)/d ln(T)``
(least squares over the lengths that finished) says how far each scene is from that;
CPU seconds (the process's) beside the wall clock tell a slow run from a loaded machine.
Scenes: (a) a symmetric Al 2024 impact (2 mm onto 4 mm at 500 m/s, library spall
strength) at 16 characteristics per fan and at default accuracy, run to 2, 4, 8 and 16
times the transit time of the stack at c0; (b) Davison's steel (5 mm onto 10 mm at 230 m/s, small
strain ideal elastic–plastic, default accuracy) to 2-20 µs, whose split waves
multiply once the plates separate (3.54 µs) unless coalesced (its exponent is fitted
from 6 µs, when the separated plates ring); (c) a 10 µm PMMA layer between tungsten
anvils (piston at 100 m/s on the left, wall on the right), a ring-up; (d) random
stacks of solids with strength (``tests/random_scenes.py::strength_stack_scene``,
fixed seeds): how many finish within 10 s of CPU time each.  Each run is capped at ``--max-seconds``
(wall clock); a run stopped by the cap or by the event limit is listed and left out of
the fit.  Under each table, the events per µs of simulated time between successive
lengths: constant once a scene's wave content stops growing.  Times are wall-clock
seconds on this machine (stated in the output).
"""

from __future__ import annotations

import argparse
import itertools
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

STEEL = ft.material("Davison steel", model="elastic-plastic", rho0="7870 kg/m3",
                    **{"lambda": "123.1 GPa"}, mu="79.29 GPa", yield_strength="1 GPa")


def symmetric_al(t_end: float, accuracy: ft.Accuracy) -> ft.Scene:
    return ft.Scene(layers=(ft.Layer("Al2024", "2 mm", velocity="500 m/s"),
                            ft.Layer("Al2024", "4 mm", bond="unbonded")),
                    t_end=t_end, accuracy=accuracy, title="symmetric Al 2024")


def steel(t_end: float, accuracy: ft.Accuracy) -> ft.Scene:
    return ft.Scene(layers=(ft.Layer(STEEL, "5 mm", velocity="230 m/s"),
                            ft.Layer(STEEL, "10 mm", bond="unbonded")),
                    t_end=t_end, accuracy=accuracy, title="Davison steel")


def ring_up(t_end: float, accuracy: ft.Accuracy) -> ft.Scene:
    return ft.Scene(layers=(ft.Layer("W", "4 mm", velocity="100 m/s"),
                            ft.Layer("PMMA", "10 um"), ft.Layer("W", "4 mm")),
                    left=ft.Boundary("velocity", "100 m/s"), right=ft.Boundary("wall"),
                    t_end=t_end, accuracy=accuracy, title="10 um PMMA between W anvils")


def measure(build, lengths, accuracy, max_seconds: float) -> list[dict]:
    rows = []
    for t_end in lengths:
        acc = ft.Accuracy(**{**accuracy, "max_seconds": max_seconds})
        start, cpu = time.perf_counter(), time.process_time()
        try:
            solution = ft.run(build(t_end, acc))
        except ft.WavediagramError as error:
            rows.append({"t_end": t_end, "outcome": type(error).__name__,
                         "seconds": time.perf_counter() - start,
                         "cpu": time.process_time() - cpu})
            continue
        seconds, cpu = time.perf_counter() - start, time.process_time() - cpu
        stopped = solution.stats.get("stopped")
        balance = solution.accuracy_report["balance"]
        rows.append({"t_end": t_end, "events": solution.stats["events"], "seconds": seconds,
                     "cpu": cpu,
                     "outcome": "time cap" if stopped else "finished",
                     "energy": balance["energy_error"], "momentum": balance["momentum_error"]})
    return rows


def exponent(rows: list[dict], key: str, fit_from: float = 0.0) -> float:
    done = [r for r in rows if r["outcome"] == "finished" and r.get(key, 0) > 0
            and r["t_end"] >= fit_from * (1 - 1e-9)]
    if len(done) < 2:
        return math.nan
    x = np.log([r["t_end"] for r in done])
    y = np.log([r[key] for r in done])
    return float(np.polyfit(x, y, 1)[0])


def table(title: str, rows: list[dict], fit_from: float = 0.0) -> list[str]:
    lines = [f"### {title}", "",
             "| t_end (µs) | outcome | events | seconds | CPU seconds | energy balance "
             "| momentum balance |",
             "|---:|---|---:|---:|---:|---:|---:|"]
    for r in rows:
        events = r.get("events", "")
        energy = f"{r['energy']:+.1e}" if r.get("energy") is not None else ""
        momentum = f"{r['momentum']:.1e}" if r.get("momentum") is not None else ""
        lines.append(f"| {r['t_end'] * 1e6:.3g} | {r['outcome']} | {events} | "
                     f"{r['seconds']:.2f} | {r['cpu']:.2f} | {energy} | {momentum} |")
    since = f" from {fit_from * 1e6:.3g} µs" if fit_from > 0.0 else ""
    lines += ["", f"Fitted exponent over the finished runs{since}: "
              f"events ~ T^{exponent(rows, 'events', fit_from):.2f}, "
              f"time ~ T^{exponent(rows, 'seconds', fit_from):.2f}.", "", rates(rows), ""]
    return lines


def rates(rows: list[dict]) -> str:
    """Events per µs of simulated time between successive finished lengths."""
    done = [r for r in rows if r["outcome"] == "finished"]
    parts = [f"{a['t_end'] * 1e6:.3g}-{b['t_end'] * 1e6:.3g}: "
             f"{(b['events'] - a['events']) / ((b['t_end'] - a['t_end']) * 1e6):.0f}"
             for a, b in itertools.pairwise(done)]
    return "Events per µs between successive lengths: " + ("; ".join(parts) or "–") + "."


def strength_stacks(seeds: range, cpu_limit: float) -> list[str]:
    """(d): each random stack in its own process, capped at ``cpu_limit`` CPU seconds of
    that process (``benchmarks/pile_up.py``: the outcome does not depend on the load);
    one row per seed (its layers, how far it got, its commonest kinds of event) and the
    outcomes counted."""
    from pile_up import run_seed

    load = os.getloadavg()[0]
    rows = [run_seed(seed, cpu_limit) for seed in seeds]
    lines = [f"### (d) random stacks of solids with strength, seeds {seeds.start}-"
             f"{seeds.stop - 1}, cap {cpu_limit:g} CPU s", "",
             f"Each seed in its own process (`benchmarks/pile_up.py`); load average "
             f"{load:.1f} at the start, {os.getloadavg()[0]:.1f} at the end.", "",
             "| seed | layers (model, um) | outcome | events | t reached / t_end | CPU s "
             "| commonest events |", "|---:|---|---|---:|---:|---:|---|"]
    lines += [f"| {r['seed']} | {r.get('layers', '')} | {r['outcome']} | "
              f"{r.get('events', '')} | {r.get('reached', 0.0):.3f} | {r.get('cpu', 0.0):.1f} | "
              + ", ".join(f"{kind} {count}" for kind, count in r.get("kinds", ())) + " |"
              for r in rows]
    outcomes: dict[str, int] = {}
    for r in rows:
        outcomes[r["outcome"]] = outcomes.get(r["outcome"], 0) + 1
    lines += ["", "| outcome | scenes |", "|---|---:|"]
    lines += [f"| {name} | {count} |" for name, count in sorted(outcomes.items())]
    cpu = [r.get("cpu", 0.0) for r in rows]
    lines += ["", f"Median {np.median(cpu):.2f} CPU s, longest {max(cpu):.2f} CPU s.", ""]
    return lines


def replace_section(text: str, section: list[str]) -> str:
    """``text`` with the section whose heading is ``section[0]``'s up to its first comma
    (up to the next ``###`` heading) replaced by ``section``, or ``section`` appended if
    there is none."""
    head = section[0].split(",")[0]
    start = text.find(head)
    if start < 0:
        return text + "\n" + "\n".join(section)
    end = text.find("\n### ", start + len(head))
    end = len(text) if end < 0 else end + 1
    return text[:start] + "\n".join(section) + "\n" + text[end:]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--max-seconds", type=float, default=120.0)
    parser.add_argument("--stacks", action="store_true")
    parser.add_argument("--case", choices=("a", "a'", "b", "c"),
                        help="run only this section and print it")
    args = parser.parse_args()
    if args.stacks:
        stacks = strength_stacks(range(30), 10.0)
        out = ROOT / "benchmarks" / "RUN_LENGTH.md"
        out.write_text(replace_section(out.read_text(), stacks))
        print("\n".join(stacks))
        return
    transit = 6e-3 / 5328.0
    factors = (2, 4) if args.quick else (2, 4, 8, 16)
    cases = [
        ("(a) symmetric Al 2024, 2 mm onto 4 mm at 500 m/s, 16 rays per fan", symmetric_al,
         [f * transit for f in factors], {"rays_per_fan": 16}, 0.0),
        ("(a') the same at default accuracy", symmetric_al,
         [f * transit for f in factors], {}, 0.0),
        ("(b) Davison steel, 5 mm onto 10 mm at 230 m/s, default accuracy", steel,
         [t * 1e-6 for t in ((2, 3, 4) if args.quick else (2, 3, 4, 5, 6, 8, 10, 12, 16, 20))],
         {}, 6e-6),
        ("(c) 10 µm PMMA between W anvils, piston 100 m/s, default accuracy", ring_up,
         [t * 1e-6 for t in ((0.25, 0.5) if args.quick else (0.25, 0.5, 1.0, 1.5))], {},
         0.0),
    ]
    lines = ["# Cost against simulated time", "",
             f"`python benchmarks/run_length.py`; {platform.machine()}, {os.cpu_count()} cores, "
             f"Python {platform.python_version()}, {time.strftime('%Y-%m-%d')}; "
             f"each run capped at {args.max_seconds:g} s of wall clock.", ""]
    if args.case is not None:
        title, build, lengths, accuracy, fit_from = next(
            case for case in cases if case[0].startswith(f"({args.case})"))
        rows = measure(build, lengths, accuracy, args.max_seconds)
        print("\n".join(lines + table(title, rows, fit_from)), flush=True)
        return
    for title, build, lengths, accuracy, fit_from in cases:
        rows = measure(build, lengths, accuracy, args.max_seconds)
        lines += table(title, rows, fit_from)
        print("\n".join(table(title, rows, fit_from)), flush=True)
    stacks = strength_stacks(range(10 if args.quick else 30), 10.0)
    print("\n".join(stacks), flush=True)
    lines += stacks
    out = ROOT / "benchmarks" / ("RUN_LENGTH_quick.md" if args.quick else "RUN_LENGTH.md")
    out.write_text("\n".join(lines))
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
