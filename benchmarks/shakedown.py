"""Whether the first layer of a strength stack has shaken down: its ringing, taken in
closed form, stays elastic.

    PYTHONPATH=. python benchmarks/shakedown.py 7 30000 100000 170000

Runs ``tests/random_scenes.strength_stack_scene(SEED)`` to each event count and looks at
the stretch from the stack's left end to the first site that is not a contact (a wall,
a free face or a gap on the left; a gap, a free face or an interface on the right).
Between a wall (``u = 0``) and a free face or open gap (``sigma = 0``) a linear elastic
layer of length ``L`` is half of a free slab of length ``2 L`` mirrored about the wall
(``sigma(-X) = sigma(X)``, ``u(-X) = -u(X)``): ``characteristics.free_slab`` rings it in
closed form, period ``4 L / C0``, with no ring-down (stress reflection ``+1`` at the
wall, ``-1`` at the free face).  The layer may be replaced by that closed form only
once it has shaken down: the closed form's stress in every cell, over a period, stays
within the cell's own elastic range (``ElasticPlastic.yield_stresses``, which knows its
plastic strain).  Printed per event count: the time reached, the faces, the fronts
inside, the pattern's range ``W`` (Pa: the stresses reach ``[-W, W]``) and the cells
whose closed-form stress leaves their elastic range (sampled at 4 000 times a period),
with the largest excursion beyond it (MPa).
"""

from __future__ import annotations

import argparse
import dataclasses
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))

from random_scenes import strength_stack_scene  # noqa: E402

from characteristics.free_slab import FreeSlab  # noqa: E402
from fronttrack.engine import Engine, EventLimitError  # noqa: E402
from fronttrack.kinds import FrontKind  # noqa: E402

SAMPLES = 4000
"""Times per period at which the closed form's stress is compared with the elastic ranges."""


def run_to(seed: int, events: int):
    """``(engine, t)``: strength stack ``seed`` stopped after ``events`` events at ``t`` (s)."""
    scene = strength_stack_scene(seed)
    scene = dataclasses.replace(scene, accuracy=dataclasses.replace(
        scene.accuracy, max_events=events))
    engine, last = Engine(scene), [0.0]
    process = engine._process

    def noted(group, t, x, timer):
        last[0] = t
        return process(group, t, x, timer)

    engine._process = noted
    try:
        engine.run()
    except EventLimitError:
        pass
    return engine, last[0]


def first_layer(engine) -> list:
    """The stack's left end, the fronts up to the first site that is not a contact, and
    that site."""
    bounds = [engine.head]
    while bounds[-1].next.kind in (FrontKind.SHOCK, FrontKind.RAY, FrontKind.CONTACT):
        bounds.append(bounds[-1].next)
    return [*bounds, bounds[-1].next]


def mirrored_slab(edges, sigma, u, t: float, material) -> FreeSlab:
    """The free slab of the layer's cells mirrored about its left face (a wall)."""
    c = material.sound_speed(material.v0, 0.0)
    mirror = np.concatenate([2.0 * edges[0] - edges[::-1], edges[1:]])
    return FreeSlab.from_cells(mirror, np.concatenate([sigma[::-1], sigma]),
                               np.concatenate([-u[::-1], u]), t, c, material.rho0 * c)


def report(seed: int, events: int) -> str:
    """One line on the first layer of ``seed`` after ``events`` events."""
    engine, t = run_to(seed, events)
    bounds = first_layer(engine)
    regions = [f.region_right for f in bounds[:-1]]
    material = regions[0].material
    edges = np.array([f.position(t) for f in bounds])
    sigma = np.array([r.state.sigma for r in regions])
    u = np.array([r.state.u for r in regions])
    faces = f"{bounds[0].kind.value} | {bounds[-1].kind.value}"
    if bounds[0].kind != FrontKind.BOUNDARY or engine.scene.left.kind != "wall":
        return f"{events} events, t = {t * 1e9:.1f} ns: faces {faces}, not a wall"
    slab = mirrored_slab(edges, sigma, u, t, material)
    middles = 0.5 * (edges[:-1] + edges[1:])
    stress = np.array([slab.state(middles, s)[0]
                       for s in t + np.linspace(0.0, slab.period, SAMPLES + 1)])
    low, high = np.array([material.yield_stresses(r.state, check=False) for r in regions]).T
    beyond = np.maximum(stress.max(axis=0) - high, low - stress.min(axis=0))
    out = beyond > 0.0
    contacts = sum(f.kind == FrontKind.CONTACT for f in bounds)
    return (f"{events} events, t = {t * 1e9:.1f} ns: faces {faces}, {len(bounds) - 2} fronts "
            f"({contacts} contacts), period {slab.period * 1e9:.1f} ns, W "
            f"{np.ptp(slab.values) / 1e6:.0f} MPa; {int(out.sum())} of {out.size} cells "
            f"({np.diff(edges)[out].sum() * 1e6:.2f} um) leave their elastic range, by up "
            f"to {max(beyond.max(), 0.0) / 1e6:.0f} MPa")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("seed", type=int)
    parser.add_argument("events", type=int, nargs="+")
    args = parser.parse_args()
    for events in args.events:
        print(report(args.seed, events), flush=True)


if __name__ == "__main__":
    main()
