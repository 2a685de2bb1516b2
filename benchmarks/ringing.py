"""Ringing layers: events, time and balance of scenes whose thin layer rings.

    PYTHONPATH=. python benchmarks/ringing.py            # this tree
    PYTHONPATH=<other tree> python benchmarks/ringing.py # the same scenes, another tree

Scenes: (c) 10 µm PMMA between tungsten anvils, piston at 100 m/s on the left, wall on
the right (``benchmarks/run_length.py``, a ring-up of Mie-Grueneisen solids); (e) a 10
µm linear elastic layer (1200 kg/m3, 2500 m/s) between two 4 mm linear elastic anvils
(19 000 kg/m3, 4000 m/s), the left one at 100 m/s, free ends (``tests/test_ringing.py``:
a ring-up with a closed-form series); (f) the same layer at 100 m/s onto an 8 mm anvil
at rest, its other face free (a ring-down).  Default accuracy.  Prints one Markdown
table: events, wall-clock and CPU seconds, layers whose ringing was ended at its limit
(``fronttrack.ringing``) and the run's balance.  ``fronttrack`` is imported from the
path (set ``PYTHONPATH``), so one script measures a tree before and after a change.
"""

from __future__ import annotations

import time

import fronttrack as ft


def elastic(name: str, rho0: float, c: float):
    modulus = rho0 * c * c / 3.0
    return ft.material(name, model="linear-elastic", rho0=f"{rho0} kg/m3",
                       **{"lambda": f"{modulus} Pa"}, mu=f"{modulus} Pa")


LAYER = elastic("layer", 1200.0, 2500.0)
HEAVY = elastic("heavy anvil", 19000.0, 4000.0)


def ring_up(t_end: str) -> ft.Scene:
    return ft.Scene(layers=(ft.Layer("W", "4 mm", velocity="100 m/s"),
                            ft.Layer("PMMA", "10 um"), ft.Layer("W", "4 mm")),
                    left=ft.Boundary("velocity", "100 m/s"), right=ft.Boundary("wall"),
                    t_end=t_end)


def sandwich(t_end: str) -> ft.Scene:
    return ft.Scene(layers=(ft.Layer(HEAVY, "4 mm", velocity="100 m/s"),
                            ft.Layer(LAYER, "10 um"), ft.Layer(HEAVY, "4 mm")), t_end=t_end)


def ring_down(t_end: str) -> ft.Scene:
    return ft.Scene(layers=(ft.Layer(LAYER, "10 um", velocity="100 m/s"),
                            ft.Layer(HEAVY, "8 mm")), t_end=t_end)


CASES = [("(c) PMMA between W anvils", ring_up, ("0.5 us", "1.5 us")),
         ("(e) linear elastic layer between anvils", sandwich, ("0.5 us", "1 us", "1.5 us")),
         ("(f) linear elastic layer on a free face, ring-down", ring_down, ("1.8 us",))]


def main() -> None:
    print("| scene | t_end | events | wall s | CPU s | rings ended | energy | momentum |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|")
    for title, build, lengths in CASES:
        for t_end in lengths:
            wall, cpu = time.perf_counter(), time.process_time()
            solution = ft.run(build(t_end))
            wall, cpu = time.perf_counter() - wall, time.process_time() - cpu
            report = solution.accuracy_report
            balance = report["balance"]
            print(f"| {title} | {t_end} | {solution.stats['events']} | {wall:.2f} | "
                  f"{cpu:.2f} | {len(report.get('ringing_replaced', []))} | "
                  f"{balance['energy_error']:+.1e} | {balance['momentum_error']:.1e} |",
                  flush=True)


if __name__ == "__main__":
    main()
