"""Speed and accuracy benchmarks of the front-tracking engine.

    python benchmarks/run.py            # writes benchmarks/README.md (several minutes)
    python benchmarks/run.py --quick    # smaller scenes, for a smoke test
    python benchmarks/run.py --tight    # also the spall experiment at tenfold tolerances

(a) ring-up: a 0.1 mm PMMA layer between thick copper anvils, hundreds of
    reverberations; (b) symmetric plate impact (Al 2024) with spall; the characteristic
    core: the common spall experiment (Al 2024 1 mm onto 2 mm at 300 m/s) at default
    and tenfold tighter tolerances, a symmetric impact's free-surface record against
    rays per fan with fitted exponents, a four-layer Cu/Al stack; (c) a spall scene (Cu
    on Cu) at 8 ... 32 rays per fan: error against the finest run and time for each.
    Times are wall-clock seconds of ``run(scene)`` on this machine (stated in the
    output).
"""

from __future__ import annotations

import argparse
import os
import platform
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from fronttrack.runner import run  # noqa: E402
from fronttrack.scene import Accuracy, Layer, Probe, Scene  # noqa: E402
from materials.library import get  # noqa: E402


def timed(scene: Scene):
    start = time.perf_counter()
    solution = run(scene)
    return solution, time.perf_counter() - start


def ring_up(quick: bool, negligible: float | None, entropy_contacts: bool) -> dict:
    """0.1 mm PMMA between Cu anvils thick enough that nothing returns from their far
    faces; ``negligible`` (Pa, None: the default) is the smallest wave kept."""
    cu, pmma = get("Cu"), get("PMMA")
    t_end = 2e-6 if quick else 8e-6
    anvil = 1.2 * 4.8e3 * t_end
    scene = Scene(layers=(Layer(cu, anvil, 500.0), Layer(pmma, 0.1e-3), Layer(cu, anvil)),
                  t_end=t_end, probes=(Probe("sample", anvil + 0.05e-3),),
                  accuracy=Accuracy(rays_per_fan=16, negligible_stress=negligible,
                                    entropy_contacts=entropy_contacts),
                  title="ring-up")
    solution, seconds = timed(scene)
    history = solution.history(anvil + 0.05e-3)
    steps = int(np.count_nonzero(np.diff(history.sigma)))
    anvil_stress = solution.state_at(anvil * 0.999, t_end).sigma
    kept = "default accuracy" if negligible is None else f"every echo above {negligible:g} Pa"
    if not entropy_contacts:
        kept += ", entropy contacts neglected"
    return {"name": f"(a) ring-up: 0.1 mm PMMA between Cu anvils, Cu at 500 m/s, {kept}",
            "events": solution.stats["events"], "seconds": seconds,
            "detail": f"{steps} stress steps in the PMMA, final {history.sigma[-1] / 1e9:.6f} "
                      f"GPa (anvil {anvil_stress / 1e9:.6f} GPa)"}


def symmetric_spall(quick: bool, spacing: float, t_end: float) -> dict:
    """Al 2024 2 mm on 6 mm at 300 m/s, spall threshold 1.2 GPa; ``spacing`` (m) is the
    smallest distance between spall planes (0: the threshold's fracture cascade)."""
    al = get("Al2024")
    scene = Scene(layers=(Layer(al, 2e-3, 300.0), Layer(al, 6e-3, bond="unbonded")),
                  t_end=0.5 * t_end if quick else t_end, probes=(Probe("rear", "right"),),
                  accuracy=Accuracy(rays_per_fan=16, spall_spacing=spacing),
                  title="symmetric Al impact")
    solution, seconds = timed(scene)
    spall = solution.spalls[0] if solution.spalls else None
    where = (f"first spall at X = {spall.x * 1e3:.4f} mm, t = {spall.t * 1e6:.4f} us; "
             f"{len(solution.spalls)} fracture planes" if spall else "no spall")
    rule = (f"spall_spacing {spacing * 1e3:g} mm" if spacing
            else "every fracture the threshold asks for")
    return {"name": f"(b) symmetric impact, Al 2024 2 mm on 6 mm at 300 m/s, 16 rays per "
                    f"fan, to {scene.t_end * 1e6:g} us, {rule}",
            "events": solution.stats["events"], "seconds": seconds, "detail": where}


def spall_scene(rays: int, t_end: float) -> Scene:
    cu = get("Cu")
    return Scene(layers=(Layer(cu, 1e-3, 400.0), Layer(cu, 3e-3, bond="unbonded")),
                 t_end=t_end, probes=(Probe("rear", "right"),),
                 accuracy=Accuracy(rays_per_fan=rays, max_events=2_000_000))


def history_l1(solution, reference, x: float, quantity: str = "sigma") -> float:
    """Integral over the run of |q - q_ref| dt at station ``x`` (the records are
    continuous, piecewise linear: the integral is exact)."""
    return solution.history(x).l1_distance(reference.history(x), quantity)


STATION = 2.5e-3
"""Lagrangian station (m) inside the target, between the impact plane and the spall plane,
where the stress history is compared."""


def convergence(quick: bool) -> list[dict]:
    counts = (8, 16) if quick else (8, 16, 32)
    t_end = 0.94e-6  # just after the first fracture (t ~ 0.9379 us)
    runs = {n: timed(spall_scene(n, t_end)) for n in counts}
    finest, _ = runs[counts[-1]]
    rows = []
    for n in counts:
        solution, seconds = runs[n]
        first, ref = solution.spalls[0], finest.spalls[0]
        rows.append({
            "rays": n, "events": solution.stats["events"], "seconds": seconds,
            "spall_t_error": abs(first.t - ref.t), "spall_x_error": abs(first.x - ref.x),
            "stress_l1": history_l1(solution, finest, STATION),
            "tension_error": abs(solution.max_tension()["sigma"] - finest.max_tension()["sigma"]),
            "energy_balance": solution.conservation()["energy_relative_error"],
        })
    return rows


def _exponent(rows: list[dict], key: str) -> float:
    """Slope of log ``row[key]`` against log rays per fan (least squares)."""
    rays = [r["rays"] for r in rows]
    values = [max(r[key], 1e-300) for r in rows]
    return float(np.polyfit(np.log(rays), np.log(values), 1)[0])


def spall_experiment(tolerance_scale: float = 1.0) -> dict:
    """The most common spall experiment: Al 2024 1 mm onto 2 mm at 300 m/s, unbonded,
    free surfaces, to 2 us, default accuracy (``tolerance_scale`` tightens the record
    tolerances)."""
    al = get("Al2024")
    accuracy = Accuracy()
    if tolerance_scale != 1.0:
        base = run(Scene(layers=(Layer(al, 1e-3, 300.0), Layer(al, 2e-3, bond="unbonded")),
                         t_end=1e-9)).accuracy_report
        accuracy = Accuracy(stress_tolerance=base["stress_tolerance"] * tolerance_scale,
                            velocity_tolerance=base["velocity_tolerance"] * tolerance_scale)
    scene = Scene(layers=(Layer(al, 1e-3, 300.0), Layer(al, 2e-3, bond="unbonded")),
                  t_end=2e-6, accuracy=accuracy)
    solution, seconds = timed(scene)
    first = min(solution.spalls, key=lambda s: s.t)
    balance = solution.conservation()
    return {"scale": tolerance_scale, "seconds": seconds, "events": solution.stats["events"],
            "lattices": solution.counters.lattices, "nodes": solution.counters.nodes,
            "x": first.x, "t": first.t, "planes": len(solution.spalls),
            "zones": solution.accuracy_report["fracture_zones"],
            "energy": balance["energy_error"] / balance["energy"][0]}


def symmetric_scene(rays: int | None, t_end: float) -> Scene:
    al = get("Al2024")
    return Scene(layers=(Layer(al, 2e-3, 500.0), Layer(al, 4e-3, bond="unbonded")),
                 t_end=t_end, accuracy=Accuracy(rays_per_fan=rays, max_events=2_000_000))


def symmetric_free_surface(quick: bool) -> tuple[dict, list[dict]]:
    """Al 2024 2 -> 4 mm at 500 m/s: to 1.2 us at default accuracy (time), and to 2.4 us
    the free-surface velocity record against the finest run, per rays per fan."""
    short, seconds = timed(symmetric_scene(None, 1.2e-6))
    default = {"seconds": seconds, "events": short.stats["events"]}
    counts = (4, 8) if quick else (4, 8, 16)
    runs = {n: timed(symmetric_scene(n, 2.4e-6)) for n in counts}
    finest = runs[counts[-1]][0]
    rows = [{"rays": n, "events": sol.stats["events"], "seconds": sec,
             "lattices": sol.counters.lattices, "nodes": sol.counters.nodes,
             "u_l1": history_l1(sol, finest, 6e-3, "u")} for n, (sol, sec) in runs.items()]
    return default, rows


STACK_EVENTS = 1_000
"""Event budget of the four-layer stack (it does not finish within it today)."""


def four_layer_stack() -> dict:
    """Cu/Al/Cu/Al, 1 mm each, the first Cu at 1 km/s, bonded, free ends, to 2 us."""
    cu, al = get("Cu"), get("Al2024")
    scene = Scene(layers=(Layer(cu, 1e-3, 1000.0), Layer(al, 1e-3), Layer(cu, 1e-3),
                          Layer(al, 1e-3)), t_end=2e-6,
                  accuracy=Accuracy(max_events=STACK_EVENTS))
    start = time.perf_counter()
    try:
        solution = run(scene)
    except Exception as error:  # the benchmark reports the limit it met
        return {"seconds": time.perf_counter() - start, "result": str(error).split(";")[0]}
    return {"seconds": time.perf_counter() - start,
            "result": f"{solution.stats['events']} events, "
                      f"{solution.counters.lattices} lattices, {solution.counters.nodes} nodes"}


def machine() -> str:
    return (f"{platform.processor() or platform.machine()}, {os.cpu_count()} cores, "
            f"Python {platform.python_version()}, {platform.system()} {platform.release()}")


def write_report(cases: list[dict], rows: list[dict], core: dict, path: Path,
                 quick: bool) -> None:
    lines = ["# Benchmarks", "",
             "Generated by `python benchmarks/run.py`" + (" --quick" if quick else "") + ".", "",
             f"Machine: {machine()}.", "",
             "## Events per second", "",
             "| scene | events | time (s) | events/s | result |", "|---|---|---|---|---|"]
    for c in cases:
        lines.append(f"| {c['name']} | {c['events']} | {c['seconds']:.2f} | "
                     f"{c['events'] / c['seconds']:.0f} | {c['detail']} |")
    lines += ["", "The ring-up at 1 Pa neglects entropy contacts: each reverberation sends a "
              "weak shock into the anvils that overtakes the previous ones, and the entropy "
              "jumps those overtakings leave (a few kPa) echo between each other.", ""]
    lines += _core_section(core)
    lines += ["## Speed against error: Cu 1 mm on Cu 3 mm at 400 m/s, to just after spall",
              "", "Errors against the finest run (last row).  `energy balance` is the relative "
              "residual of the energy balance, which needs no reference.", "",
              "| rays per fan | events | time (s) | spall time error (ns) | spall X error (um) | "
              "largest tension error (MPa) | stress history L1 error at X = 2.5 mm (MPa ns) | "
              "energy balance |", "|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(f"| {r['rays']} | {r['events']} | {r['seconds']:.2f} | "
                     f"{r['spall_t_error'] * 1e9:.3g} | {r['spall_x_error'] * 1e6:.3g} | "
                     f"{r['tension_error'] / 1e6:.3g} | {r['stress_l1'] / 1e6 * 1e9:.3g} | "
                     f"{r['energy_balance']:.2e} |")
    coarse = [r for r in rows[:-1]]
    lines += ["", "Fitted exponents over the rows above but the last: events ~ rays^"
              f"{_exponent(coarse, 'events'):.2f}"
              ", stress-record L1 error ~ rays^"
              f"{_exponent(coarse, 'stress_l1'):.2f}"
              ".", ""]
    path.write_text("\n".join(lines))


def _core_section(core: dict) -> list[str]:
    """The characteristic core's scenes: the spall experiment, the symmetric impact's
    free-surface record against rays, the four-layer stack."""
    lines = ["## The characteristic core", "",
             "Al 2024 1 mm onto 2 mm at 300 m/s, unbonded, free surfaces, to 2 us (the "
             "common spall experiment), at default accuracy (and, with `--tight`, with the "
             "record tolerances tightened tenfold):", "",
             "| tolerances | time (s) | events | lattices | nodes | first fracture X (mm) | "
             "first fracture t (us) | planes | energy balance |",
             "|---|---|---|---|---|---|---|---|---|"]
    for r in core["spall"]:
        lines.append(f"| x{r['scale']:g} | {r['seconds']:.2f} | {r['events']} | "
                     f"{r['lattices']} | {r['nodes']} | {r['x'] * 1e3:.5f} | "
                     f"{r['t'] * 1e6:.5f} | {r['planes']} | {r['energy']:+.2e} |")
    default, rows = core["symmetric"]
    lines += ["", "Symmetric Al 2024 2 mm onto 4 mm at 500 m/s: to 1.2 us at default accuracy "
              f"{default['seconds'] * 1e3:.0f} ms ({default['events']} events).  To 2.4 us, the "
              "free-surface velocity record against the finest run (last row):", "",
              "| rays per fan | time (s) | events | lattices | nodes | "
              "free-surface velocity L1 (m/s ns) |", "|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(f"| {r['rays']} | {r['seconds']:.3f} | {r['events']} | {r['lattices']} | "
                     f"{r['nodes']} | {r['u_l1'] * 1e9:.3g} |")
    coarse = rows[:-1]
    lines += ["", "Fitted exponents over the rows above but the last: events ~ rays^"
              f"{_exponent(coarse, 'events'):.2f}"
              ", lattice nodes ~ rays^"
              f"{_exponent(coarse, 'nodes'):.2f}"
              ", record L1 error ~ rays^"
              f"{_exponent(coarse, 'u_l1'):.2f}.",
              "", f"Cu/Al/Cu/Al, 1 mm each, Cu at 1 km/s, to 2 us: {core['stack']['result']} "
              f"({core['stack']['seconds']:.2f} s).", ""]
    return lines


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--tight", action="store_true",
                        help="also run the spall experiment at tenfold tighter tolerances "
                             "(more than five minutes)")
    parser.add_argument("--output", type=Path, default=Path(__file__).parent / "README.md")
    args = parser.parse_args()
    cases = [ring_up(args.quick, None, True), ring_up(args.quick, 1.0, False),
             symmetric_spall(args.quick, 0.5e-3, 3e-6),
             symmetric_spall(args.quick, 0.0, 1.5e-6)]
    for c in cases:
        print(f"{c['name']}: {c['events']} events in {c['seconds']:.2f} s; {c['detail']}")
    spall_runs = [spall_experiment(1.0)] + ([spall_experiment(0.1)] if args.tight else [])
    core = {"spall": spall_runs,
            "symmetric": symmetric_free_surface(args.quick), "stack": four_layer_stack()}
    print(core)
    rows = convergence(args.quick)
    for r in rows:
        print(r)
    write_report(cases, rows, core, args.output, args.quick)
    print(f"wrote {args.output}")


if __name__ == "__main__":
    main()
