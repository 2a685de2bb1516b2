"""A campaign of random scenes: every outcome is a solution or a named error, never a crash.

    python benchmarks/campaign.py --scenes 1000 --time-limit 5 --workers 2

Each scene (``tests/random_scenes.py``, seeds 0..N-1) runs in its own process with a
limit on the CPU time of that process (``RLIMIT_CPU``), so that an outcome does not depend on
what else the machine runs; a wall-clock limit of ten times as much catches a process that
waits instead of computing.  Outcomes: ``solved`` (balance within what the settings promise),
``solved, beyond promise`` (the run said so in a warning), ``energy created`` (beyond the
promise: a defect), ``named error`` by class (a ``WavediagramError``), ``time limit``,
``crash`` (any other exception: a defect).  Writes ``benchmarks/campaign.json`` with
every scene's outcome and prints the table.
"""

from __future__ import annotations

import argparse
import collections
import json
import multiprocessing
import signal
import sys
import time
import traceback
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "tests"))


def _one(seed: int, queue, cpu_limit: float) -> None:
    import resource

    from random_scenes import campaign_scene

    seconds = max(1, round(cpu_limit))
    resource.setrlimit(resource.RLIMIT_CPU, (seconds, seconds + 1))

    from fronttrack.runner import run
    from materials.errors import WavediagramError

    start = time.process_time()
    try:
        solution = run(campaign_scene(seed))
    except WavediagramError as error:
        queue.put({"outcome": f"named error: {type(error).__name__}",
                   "message": str(error)[:300]})
        return
    except Exception as error:  # noqa: BLE001 - a crash is what this campaign looks for
        queue.put({"outcome": "crash", "message": f"{type(error).__name__}: {error}"[:300],
                   "traceback": traceback.format_exc()[-2000:]})
        return
    report = solution.accuracy_report
    balance = report["balance"]
    if balance["energy_error"] is None or balance["momentum_error"] is None:
        outcome = "solved, balance not measurable (warned)"
    elif balance["energy_error"] > balance["promised"]:
        outcome = "energy created beyond promise"
    elif max(balance["momentum_error"], -balance["energy_error"]) > balance["promised"]:
        outcome = "solved, beyond promise (warned)" if report["warnings"] else \
            "beyond promise, not warned"
    else:
        outcome = "solved"
    queue.put({"outcome": outcome, "balance": balance, "warnings": report["warnings"],
               "events": solution.stats["events"],
               "cpu_seconds": time.process_time() - start})


def run_scene(seed: int, limit: float, wall_factor: float = 10.0) -> dict:
    """Run scene ``seed`` in a child process stopped after ``limit`` seconds of its CPU time.

    The child is killed by ``SIGXCPU`` at the limit (reported as ``time limit``), or after
    ``wall_factor`` times the limit of wall-clock time if it is still alive then (on a
    loaded machine a process gets a fraction of a core: raise it there, or the wall
    clock, not the CPU limit, decides).
    """
    queue = multiprocessing.Queue()
    process = multiprocessing.Process(target=_one, args=(seed, queue, limit))
    process.start()
    process.join(wall_factor * limit)
    if process.is_alive():
        process.kill()
        process.join()
        return {"seed": seed, "outcome": "time limit"}
    if process.exitcode in (-signal.SIGXCPU, -signal.SIGKILL) and queue.empty():
        return {"seed": seed, "outcome": "time limit"}
    if queue.empty():
        return {"seed": seed, "outcome": "crash", "message": f"exit code {process.exitcode}"}
    return {"seed": seed} | queue.get()


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scenes", type=int, default=1000)
    parser.add_argument("--first", type=int, default=0)
    parser.add_argument("--time-limit", type=float, default=5.0,
                        help="CPU seconds allowed to each scene (whole seconds)")
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--wall-factor", type=float, default=10.0,
                        help="wall-clock seconds allowed per CPU second before a scene is "
                             "stopped (raise it on a loaded machine)")
    parser.add_argument("--out", type=Path, default=HERE / "campaign.json")
    parser.add_argument("--log", type=Path, default=None,
                        help="append each outcome as one JSON line when it is known (a "
                             "campaign stopped early keeps what it ran)")
    args = parser.parse_args()
    seeds = range(args.first, args.first + args.scenes)
    from concurrent.futures import ThreadPoolExecutor

    def one(seed):
        result = run_scene(seed, args.time_limit, args.wall_factor)
        if args.log is not None:
            with args.log.open("a") as log:
                log.write(json.dumps(result) + "\n")
        return result

    with ThreadPoolExecutor(args.workers) as pool:
        results = list(pool.map(one, seeds))
    table = collections.Counter(r["outcome"] for r in results)
    args.out.write_text(json.dumps({"time_limit_s": args.time_limit, "table": table,
                                    "scenes": results}, indent=1))
    width = max(len(k) for k in table)
    for outcome, count in table.most_common():
        print(f"{outcome:<{width}}  {count:5d}")
    print(f"{'total':<{width}}  {len(results):5d}")


if __name__ == "__main__":
    main()
