"""Why campaign scenes reach their CPU limit: what each one spends its time on.

    python benchmarks/time_limit_causes.py --every 20 --cpu-seconds 5 [--profile DIR]

Takes every N-th seed that reached the time limit in ``benchmarks/campaign.json`` and
runs each scene (``tests/random_scenes.py``) in its own process for a budget of CPU
time (``ITIMER_PROF``: the process's own CPU time, whatever the load; the import is
not counted).  For each it prints one JSON line: the layers (model, thickness, share of
the thickest), rays per fan, release path, the fraction of ``t_end`` reached, events and
events per CPU second, the live fronts by kind at the stop, and for the later half of
the events the layer they happened in, the kinds of the fronts that met and the span of
time and position they covered (a span of zero time is a stopped clock).  Then a table
of the layer that took most of the later events (thin: at most 50 um or 2 % of the
thickest), by model.  With ``--profile`` each run's cProfile statistics are written
there.  The findings are in ``benchmarks/CAMPAIGN.md``.
"""

from __future__ import annotations

import argparse
import collections
import json
import multiprocessing
import signal
import sys
import time
from pathlib import Path
from queue import Empty

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "tests"))

THIN_LENGTH = 50e-6
"""A layer at most this thick (m) ..."""
THIN_SHARE = 0.02
"""... or at most this fraction of the thickest layer is thin."""


class _Budget(Exception):
    """The CPU budget is spent."""


def _spent(*_):
    raise _Budget


def diagnose(seed: int, cpu_seconds: float, profile_dir: Path | None = None) -> dict:
    """Run scene ``seed`` for ``cpu_seconds`` of CPU time and describe where it went."""
    import cProfile

    from random_scenes import campaign_scene

    from fronttrack import engine as engine_module
    from fronttrack.runner import run

    scene = campaign_scene(seed)
    log, seen = [], {}
    process = engine_module.Engine._process

    def counted(self, group, t, x, timer=False):
        seen["engine"] = self
        region = group[0].region_right or (group[0].prev.region_right if group[0].prev
                                           else None)
        log.append((t, x, "+".join(sorted(f.kind.value for f in group)),
                    region.layer if region is not None else None))
        return process(self, group, t, x, timer=timer)

    engine_module.Engine._process = counted
    profiler = cProfile.Profile() if profile_dir is not None else None
    signal.signal(signal.SIGPROF, _spent)
    start = time.process_time()
    outcome = "solved"
    if profiler is not None:
        profiler.enable()
    signal.setitimer(signal.ITIMER_PROF, cpu_seconds)
    try:
        run(scene)
    except _Budget:
        outcome = "time limit"
    except Exception as error:  # noqa: BLE001 - a named error is an outcome here
        outcome = f"{type(error).__name__}: {str(error)[:120]}"
    finally:
        signal.setitimer(signal.ITIMER_PROF, 0.0)
        if profiler is not None:
            profiler.disable()
            profiler.dump_stats(profile_dir / f"seed_{seed}.pstat")
    cpu = time.process_time() - start
    thickest = max(layer.thickness for layer in scene.layers)
    live = collections.Counter()
    front = seen["engine"].head if "engine" in seen else None
    while front is not None:
        live[front.kind.value] += 1
        front = front.next
    late = log[len(log) // 2:]
    return {
        "seed": seed, "outcome": outcome, "cpu_seconds": round(cpu, 2), "events": len(log),
        "events_per_cpu_second": round(len(log) / cpu) if cpu > 0 else None,
        "rays_per_fan": scene.accuracy.rays_per_fan, "release": scene.accuracy.release,
        "ends": [scene.left.kind, scene.right.kind],
        "reached": max((e[0] for e in log), default=0.0) / scene.t_end,
        "layers": [{"model": type(layer.material).__name__, "name": layer.material.name,
                    "thickness_um": layer.thickness * 1e6,
                    "share": layer.thickness / thickest} for layer in scene.layers],
        "live": dict(live),
        "late_layers": dict(collections.Counter(e[3] for e in late).most_common()),
        "late_kinds": collections.Counter(e[2] for e in late).most_common(4),
        "late_time_span": ((late[-1][0] - late[0][0]) / scene.t_end) if late else None,
        "late_x_span_mm": (max(e[1] for e in late) - min(e[1] for e in late)) * 1e3
        if late else None,
    }


def _child(seed, cpu_seconds, profile_dir, queue):
    queue.put(diagnose(seed, cpu_seconds, profile_dir))


def _cause(record: dict) -> str:
    """The layer that took most of the later events: thin or not, and its model."""
    late = record["late_layers"]
    if not late:
        return "no events"
    top = max(late, key=late.get)
    if top is None:
        return "no layer"
    layer = record["layers"][int(top)]
    thin = layer["thickness_um"] * 1e-6 <= THIN_LENGTH or layer["share"] <= THIN_SHARE
    return f"{'thin' if thin else 'thick'} {layer['model']}"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--every", type=int, default=20)
    parser.add_argument("--cpu-seconds", type=float, default=5.0)
    parser.add_argument("--profile", type=Path, default=None)
    args = parser.parse_args()
    campaign = json.loads((HERE / "campaign.json").read_text())
    limited = [r["seed"] for r in campaign["scenes"] if r["outcome"] == "time limit"]
    records = []
    for seed in limited[::args.every]:
        queue = multiprocessing.Queue()
        child = multiprocessing.Process(target=_child,
                                        args=(seed, args.cpu_seconds, args.profile, queue))
        child.start()
        try:  # read before joining: a child exits only once its record is read
            record = queue.get(timeout=20 * args.cpu_seconds)
        except Empty:
            record = {"seed": seed, "outcome": "lost (crashed or waited)"}
        child.join(1.0)
        if child.is_alive():
            child.kill()
            child.join()
        records.append(record)
        print(json.dumps(record), flush=True)
    table = collections.Counter(_cause(r) for r in records if "late_layers" in r)
    for cause, count in table.most_common():
        print(f"{cause:<28} {count:4d}")


if __name__ == "__main__":
    main()
