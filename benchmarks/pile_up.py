"""Random stacks of solids with strength against a CPU-time cap: which finish, how far the rest get.

    python benchmarks/pile_up.py --seeds 30 --cpu-limit 10 [--out stacks.json]

Each seed of ``tests/random_scenes.py::strength_stack_scene`` runs in its own process,
with the run's time limit (``accuracy.max_seconds``) counted in CPU seconds of that
process instead of wall-clock seconds, so an outcome does not depend on what else the
machine runs.  A run that reaches the limit stops with its partial solution
(``Engine.stop_early``).  Prints one row per seed (outcome, events, simulated time
reached over ``t_end``, CPU seconds, fronts gathered at pile-ups and coalesced) and the
number that finished; with ``--out`` writes the rows as JSON, with each scene's layers
(model and thickness in um) and the three commonest kinds of event (the kinds of the
fronts each event gathers, counted by wrapping ``Engine._gather``).  The runs use the
packages of the tree this script lies in (a copy of the script in another checkout
measures that checkout).
"""

from __future__ import annotations

import argparse
import json
import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent

CHILD = """
import collections, dataclasses, json, sys, time
sys.path.insert(0, {tests!r})
time.perf_counter = time.process_time  # the run's limit in CPU seconds of this process
from random_scenes import strength_stack_scene
import fronttrack as ft
from fronttrack.engine import Engine
kinds = collections.Counter()  # what the events meet: the kinds of the fronts gathered
gather = Engine._gather
def counted(self, seed, t, x):
    group = gather(self, seed, t, x)
    kinds["-".join(sorted(f.kind.value for f in group))] += 1
    return group
Engine._gather = counted
scene = strength_stack_scene({seed})
scene = dataclasses.replace(scene, accuracy=dataclasses.replace(
    scene.accuracy, max_seconds={limit}, max_events=10**7))
start = time.process_time()
row = {{"seed": {seed}}}
try:
    solution = ft.run(scene)
    stopped = solution.stats.get("stopped")
    report = solution.accuracy_report
    row.update(outcome="time cap" if stopped else "finished",
               events=solution.stats["events"],
               reached=(stopped["t"] / stopped["t_end"]) if stopped else 1.0,
               gathered=report.get("gathered_fronts", 0),
               coalesced=report.get("coalesced_fronts", 0),
               energy=report["balance"]["energy_error"],
               momentum=report["balance"]["momentum_error"],
               promised=report["balance"]["promised"])
except ft.WavediagramError as error:
    row.update(outcome=type(error).__name__)
row["cpu"] = time.process_time() - start
row["kinds"] = kinds.most_common(3)
row["layers"] = " ".join(f"{{type(l.material).__name__}} {{l.thickness * 1e6:.0f}}"
                         for l in scene.layers)
print(json.dumps(row))
"""


def run_seed(seed: int, limit: float) -> dict:
    """One seed in a fresh interpreter started in this tree (whose packages it runs)."""
    code = CHILD.format(tests=str(HERE.parent / "tests"), seed=seed, limit=limit)
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          timeout=30 * limit + 120, cwd=HERE.parent)
    if done.returncode != 0:
        return {"seed": seed, "outcome": "crash", "message": done.stderr[-300:]}
    return json.loads(done.stdout.strip().splitlines()[-1])


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seeds", type=int, default=30)
    parser.add_argument("--cpu-limit", type=float, default=10.0)
    parser.add_argument("--out", type=Path, default=None)
    args = parser.parse_args()
    rows = []
    print("| seed | outcome | events | t reached / t_end | CPU s | gathered | coalesced |")
    print("|---:|---|---:|---:|---:|---:|---:|")
    for seed in range(args.seeds):
        row = run_seed(seed, args.cpu_limit)
        rows.append(row)
        print(f"| {seed} | {row['outcome']} | {row.get('events', '')} | "
              f"{row.get('reached', 0.0):.3f} | {row.get('cpu', 0.0):.1f} | "
              f"{row.get('gathered', '')} | {row.get('coalesced', '')} |", flush=True)
    finished = sum(row["outcome"] == "finished" for row in rows)
    print(f"\nfinished within {args.cpu_limit:g} CPU s: {finished} of {len(rows)}")
    if args.out is not None:
        args.out.write_text(json.dumps(rows, indent=1))


if __name__ == "__main__":
    main()
