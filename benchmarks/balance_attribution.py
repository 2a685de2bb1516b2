"""Which decisions lose (or make) a campaign scene's energy: the balance attributed front
by front and to the decision that made each front.

    PYTHONPATH=. python benchmarks/balance_attribution.py 349

Between two events every front is straight and every region constant, so the total
energy per unit area changes at

    dE/dt = sum over fronts of  rho0 U (E_l - E_r) - (sigma_l u_l - sigma_r u_r)

(``fronttrack.dropped.creation_rate`` of the states beside each front; ``U`` zero for a
site), which is zero for an exact jump.  The rate of every front is summed over the
time until the next event, and the live total is compared before and after each event
(coalescing a strip changes it at once).  Each front is tagged with the decisions of
the event that made it: ``drop`` (a weak family dropped, ``fronttrack.dropped``),
``neglect`` (an entropy contact not tracked, ``fronttrack.neglect``), ``coalesce``
(``fronttrack.coalesce``), ``exact`` (none).  A front keeps its tag while it lives (a
site lives through many events).  The sum matches the run's energy residual to
rounding when no lattice or ring-down replaces fronts without an event record.
"""

from __future__ import annotations

import argparse
import collections
import sys
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "tests"))

from random_scenes import campaign_scene  # noqa: E402

from fronttrack import coalesce, dropped  # noqa: E402
from fronttrack import engine as engine_module  # noqa: E402
from fronttrack.runner import run  # noqa: E402


def _live_energy(engine, t: float) -> float:
    """Total energy (J/m^2) of the live regions at time ``t`` (s)."""
    total, front = 0.0, engine.head
    while front is not None and front.next is not None:
        region, width = front.region_right, front.next.position(t) - front.position(t)
        if region is not None and width > 0.0:
            state = region.state
            total += region.material.rho0 * width * (state.e + 0.5 * state.u * state.u)
        front = front.next
    return total


def _rates(engine) -> list:
    """``(front, dE/dt W/m^2)`` of every front whose jump is not exact."""
    found, front = [], engine.head
    while front is not None:
        left = front.prev.region_right if front.prev is not None else None
        right = front.region_right if front.next is not None else None
        if left is not None and right is not None:
            # a site does not move: the rho0 U term vanishes across an interface too
            rate = dropped.creation_rate(left.material.rho0,
                                         0.0 if front.is_site else front.speed,
                                         right.state, left.state, +1)
            if rate != 0.0:
                found.append((front, rate))
        front = front.next
    return found


class Attribution:
    """Patches the engine to attribute energy to fronts and decisions while a run goes."""

    def __init__(self):
        self.by_tag, self.jumps = collections.Counter(), collections.Counter()
        self.by_front, self.info, self.tags = collections.Counter(), {}, {}
        self.decisions, self.rates, self.last_t, self.newest = [], [], 0.0, 0

    def install(self) -> None:
        process, drops = engine_module.Engine._process, dropped.drops
        contact, merge = engine_module.Engine._entropy_contact, coalesce._replace
        me = self

        def patched_process(engine, seed, t, x, timer=False):
            for front, rate in me.rates:
                tag = me.tags.get(front.id, "initial")
                me.by_tag[tag] += rate * (t - me.last_t)
                me.by_front[front.id] += rate * (t - me.last_t)
                me.info[front.id] = (front.kind.value, tag, front.t0, front.x0)
            me.last_t, me.decisions = t, []
            before = _live_energy(engine, t)
            process(engine, seed, t, x, timer=timer)
            tag = "+".join(sorted(set(me.decisions))) or "exact"
            me.jumps[tag] += _live_energy(engine, t) - before
            front, newest = engine.head, me.newest
            while front is not None:
                if front.id > newest:
                    me.tags.setdefault(front.id, tag)
                    me.newest = max(me.newest, front.id)
                front = front.next
            me.rates = _rates(engine)

        def patched_drops(*args):
            dropped_now = drops(*args)
            if dropped_now:
                me.decisions.append("drop")
            return dropped_now

        def patched_contact(engine, left, right, material, t, x, group):
            kept = contact(engine, left, right, material, t, x, group)
            if kept is None and left.e != right.e:
                me.decisions.append("neglect")
            return kept

        def patched_merge(*args):
            me.decisions.append("coalesce")
            return merge(*args)

        engine_module.Engine._process = patched_process
        engine_module.dropped.drops = patched_drops
        engine_module.Engine._entropy_contact = patched_contact
        coalesce._replace = patched_merge


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("seed", type=int)
    parser.add_argument("--fronts", type=int, default=8, help="largest fronts to list")
    args = parser.parse_args()
    attribution = Attribution()
    attribution.install()
    start = time.process_time()
    solution = run(campaign_scene(args.seed, max_events=200_000))
    cpu = time.process_time() - start
    balance, scale = (solution.accuracy_report["balance"],
                      solution.conservation()["energy_scale"])

    def percent(counter):
        return {k: round(100.0 * v / scale, 3) for k, v in counter.most_common()
                if abs(v) > 1e-6 * scale}

    print(f"seed {args.seed}: {solution.stats['events']} events, {cpu:.1f} s CPU; momentum "
          f"{balance['momentum_error']:.3g}, energy {balance['energy_error']:.3g}, promise "
          f"{balance['promised']:.3g}")
    print("  fronts by the decision that made them (% of the energy content):",
          percent(attribution.by_tag))
    print("  changes at events:", percent(attribution.jumps))
    total = sum(attribution.by_tag.values()) + sum(attribution.jumps.values())
    print(f"  attributed in all: {100.0 * total / scale:.4f} %")
    for front_id, energy in sorted(attribution.by_front.items(),
                                   key=lambda item: item[1])[:args.fronts]:
        kind, tag, t0, x0 = attribution.info[front_id]
        print(f"    {kind} {front_id} ({tag}) from {t0 * 1e6:.4f} us, {x0 * 1e3:.4f} mm: "
              f"{100.0 * energy / scale:.4f} %")


if __name__ == "__main__":
    main()
