"""Which decisions lose (or make) a campaign scene's energy: the balance attributed front
by front and to the decision that made each front.

    PYTHONPATH=. python benchmarks/balance_attribution.py 349 [--momentum] [--windows 8]
    PYTHONPATH=. python benchmarks/balance_attribution.py --scene SCENE.toml [--momentum]
    PYTHONPATH=. python benchmarks/balance_attribution.py --al 18 [--rays 16]

``--al T_US`` attributes the symmetric Al 2024 impact of ``benchmarks/run_length.py``
(``symmetric_al``) run to ``T_US`` microseconds instead of a campaign seed, at default
accuracy or at ``--rays`` characteristics per fan.  ``--windows N`` also splits the
residual over N equal windows of simulated time (what the fronts made while the run was
in each, and the changes at its events), to tell a loss that grows with the run's
length from one made once.

Between two events every front is straight and every region constant, so the total
energy per unit area changes at

    dE/dt = sum over fronts of  rho0 U (E_l - E_r) - (sigma_l u_l - sigma_r u_r)

(``fronttrack.dropped.creation_rate`` of the states beside each front; ``U`` zero for a
site), which is zero for an exact jump.  The rate of every front is summed over the
time it lived until the next event, and the total is compared before and after each
event (coalescing a strip changes it at once).  A lattice (``fronttrack.zones``) solves
ahead of the queue: the fronts it splices start at their own later times, so the total
counts each front's region energy at its own start (the rate of the front times the
time between the event and its start), and the change over the event is the energy the
lattice made.  Each front is tagged with the decisions of the event that made it:
``drop`` (a weak family dropped, ``fronttrack.dropped``), ``neglect`` (an entropy
contact not tracked, ``fronttrack.neglect``), ``coalesce`` (``fronttrack.coalesce``),
``lattice`` (``fronttrack.zones``), ``fragment`` (a free fragment ringing in closed
form, ``fronttrack.fragment``), ``ring-down`` (``fronttrack.ringing``), ``exact``
(none).  A front keeps its tag while it lives (a site lives through many events).  The
sum matches the run's energy residual to rounding.

``--momentum`` attributes the momentum residual the same way: per unit area it changes at

    dP/dt = sum over fronts of  rho0 U (u_l - u_r) - (sigma_l - sigma_r)

(stress positive in compression; zero for an exact jump), the boundaries adding the
``sigma`` of the first cell less that of the last; it is given against the momentum
content ``sum m |u|`` (``momentum_scale`` of ``Solution.conservation``).
"""

from __future__ import annotations

import argparse
import collections
import sys
import time
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "tests"))

from random_scenes import campaign_scene  # noqa: E402
from run_length import symmetric_al  # noqa: E402

import fronttrack as ft  # noqa: E402
from fronttrack import coalesce, dropped, fragment, outgoing, ringing, zones  # noqa: E402
from fronttrack import engine as engine_module  # noqa: E402
from fronttrack.runner import run  # noqa: E402
from fronttrack.scene_file import load_scene  # noqa: E402


@dataclass(frozen=True)
class Quantity:
    """A conserved quantity: its ``density`` per unit mass of a state (J/kg or m/s), the
    ``rate`` (W/m^2 or Pa) a front of Lagrangian speed ``U`` makes between its left and
    right states (``rate(rho0, U, left, right)``), the ``flux`` a boundary feeds into the
    cell beside it (``sigma u`` or ``sigma``) and the keys of its residual, boundary
    integral and scale in ``Solution.conservation()``."""

    name: str
    density: Callable
    rate: Callable
    flux: Callable
    error: str
    boundary: str
    scale: str


ENERGY = Quantity(
    "energy", lambda s: s.e + 0.5 * s.u * s.u,
    lambda rho0, speed, left, right: dropped.creation_rate(rho0, speed, right, left, +1),
    lambda s: s.sigma * s.u, "energy_error", "work", "energy_scale")
MOMENTUM = Quantity(
    "momentum", lambda s: s.u,
    lambda rho0, speed, left, right: (rho0 * speed * (left.u - right.u)
                                      - (left.sigma - right.sigma)),
    lambda s: s.sigma, "momentum_error", "impulse", "momentum_scale")


def _live_total(engine, t: float, rates, quantity: Quantity) -> float:
    """Total ``quantity`` (J/m^2 or kg/(m s)) of the live regions, each front taken at
    ``t`` (s) or, if it starts later (spliced by a lattice), at its own start: the total at ``t`` of
    the fronts extrapolated back, plus each late front's ``rate`` (W/m^2, ``rates``
    maps front ids to them) times the time to its start.  Regions between fronts
    extrapolated past each other count with a negative width: the total is linear in
    the positions."""
    total, front = 0.0, engine.head
    while front is not None and front.next is not None:
        region, width = front.region_right, front.next.position(t) - front.position(t)
        if region is not None:
            total += region.material.rho0 * width * quantity.density(region.state)
        total += rates.get(front.id, 0.0) * max(front.t0 - t, 0.0)
        front = front.next
    return total


def _rates(engine, quantity: Quantity) -> dict:
    """``{front id: (front, rate)}`` of every front whose jump does not conserve
    ``quantity`` (rate in W/m^2 or Pa)."""
    found, front = {}, engine.head
    while front is not None:
        left = front.prev.region_right if front.prev is not None else None
        right = front.region_right if front.next is not None else None
        if left is not None and right is not None:
            # a site does not move: the rho0 U term vanishes across an interface too
            rate = quantity.rate(left.material.rho0, 0.0 if front.is_site else front.speed,
                                 left.state, right.state)
            if rate != 0.0:
                found[front.id] = (front, rate)
        front = front.next
    return found


def _boundary_rate(engine, quantity: Quantity) -> float:
    """Rate (W/m^2 or Pa) at which the boundaries feed ``quantity`` into the live cells
    beside them, the flux of the first cell less that of the last (the run's balance
    takes it from the cells it recorded there: inside a lattice those are the
    lattice's, not the cell at its cut)."""
    first, last = engine.head, engine.head
    while last.next is not None:
        last = last.next
    power = 0.0
    for region, sign in ((first.region_right, 1.0), (last.prev.region_right, -1.0)):
        if region is not None:
            power += sign * quantity.flux(region.state)
    return power


class Attribution:
    """Patches the engine to attribute a quantity's residual (``ENERGY`` by default) to
    fronts and decisions while a run goes."""

    def __init__(self, quantity: Quantity = ENERGY, window: float = 0.0):
        self.quantity, self.window = quantity, window
        self.by_window = collections.defaultdict(collections.Counter)
        self.by_tag, self.jumps = collections.Counter(), collections.Counter()
        self.by_front, self.info, self.tags = collections.Counter(), {}, {}
        self.decisions, self.rates, self.last_t, self.newest = [], {}, 0.0, 0
        self.work, self.power = 0.0, 0.0

    def advance(self, t: float) -> None:
        """Add each front's rate over the time it lived from the last event to ``t`` (s),
        and the boundaries' work on the live cells beside them."""
        self.work += self.power * (t - self.last_t)
        for front, rate in self.rates.values():
            tag = self.tags.get(front.id, "initial")
            energy = rate * max(t - max(self.last_t, front.t0), 0.0)
            self.by_tag[tag] += energy
            self.by_front[front.id] += energy
            self._book(t, tag, energy)
            self.info[front.id] = (front.kind.value, tag, front.t0, front.x0)
        self.last_t, self.decisions = t, []

    def event(self, engine, t: float, process) -> None:
        """Run ``process()``, the event at ``t`` (s), and book the change of the total."""
        self.advance(t)
        before = _live_total(engine, t, {i: r for i, (_, r) in self.rates.items()},
                             self.quantity)
        process()
        rates = _rates(engine, self.quantity)
        tag = "+".join(sorted(set(self.decisions))) or "exact"
        change = _live_total(engine, t, {i: r for i, (_, r) in rates.items()},
                             self.quantity) - before
        self.jumps[tag] += change
        self._book(t, "events", change)
        front, newest = engine.head, self.newest
        while front is not None:
            if front.id > newest:
                self.tags.setdefault(front.id, tag)
                self.newest = max(self.newest, front.id)
            front = front.next
        self.rates = rates
        self.power = _boundary_rate(engine, self.quantity)

    def _book(self, t: float, key: str, amount: float) -> None:
        """Add ``amount`` under ``key`` to the window of simulated time holding ``t`` (s)
        (the interval since the previous event lies in it to within one event)."""
        if self.window > 0.0:
            self.by_window[int(t / self.window)][key] += amount

    def install(self) -> None:
        process, wave_fronts = engine_module.Engine._process, outgoing.wave_fronts
        contact, merge = engine_module.Engine._entropy_contact, coalesce._replace
        me = self

        def patched_process(engine, seed, t, x, timer=False):
            me.event(engine, t, lambda: process(engine, seed, t, x, timer=timer))

        def patched_wave_fronts(*args):
            specs = wave_fronts(*args)
            if specs is None:  # the family was dropped (a merge refused keeps both)
                me.decisions.append("drop")
            return specs

        def patched_contact(engine, left, right, material, t, x, group, *carriers):
            kept = contact(engine, left, right, material, t, x, group, *carriers)
            if kept is None and left.e != right.e:
                me.decisions.append("neglect")
            return kept

        def patched_merge(*args):
            me.decisions.append("coalesce")
            return merge(*args)

        def tagging(function, tag):
            def patched(*args):
                done = function(*args)
                if done:
                    me.decisions.append(tag)
                return done
            return patched

        engine_module.Engine._process = patched_process
        engine_module.outgoing.wave_fronts = patched_wave_fronts
        engine_module.Engine._entropy_contact = patched_contact
        coalesce._replace = patched_merge
        zones.try_zone = tagging(zones.try_zone, "lattice")
        fragment.try_replace = tagging(fragment.try_replace, "fragment")
        ringing.try_end = tagging(ringing.try_end, "ring-down")


def _scene(args):
    """The scene the command line names, and how to call it."""
    if args.scene is not None:
        return load_scene(args.scene), args.scene
    if args.al is None:
        return campaign_scene(args.seed, max_events=200_000), f"seed {args.seed}"
    accuracy = ft.Accuracy() if args.rays is None else ft.Accuracy(rays_per_fan=args.rays)
    rays = "default accuracy" if args.rays is None else f"{args.rays} rays"
    return symmetric_al(args.al * 1e-6, accuracy), f"symmetric Al to {args.al:g} us, {rays}"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("seed", type=int, nargs="?", help="a campaign seed")
    parser.add_argument("--scene", help="a scene file (TOML) instead of a campaign seed")
    parser.add_argument("--al", type=float, help="the symmetric Al impact to T_US us")
    parser.add_argument("--rays", type=int, help="characteristics per fan for --al")
    parser.add_argument("--windows", type=int, default=0,
                        help="split the residual over this many windows of time")
    parser.add_argument("--fronts", type=int, default=8, help="largest fronts to list")
    parser.add_argument("--momentum", action="store_true",
                        help="attribute the momentum residual instead of the energy's")
    args = parser.parse_args()
    if sum(x is not None for x in (args.seed, args.scene, args.al)) != 1:
        parser.error("give one of a campaign seed, --scene or --al")
    scene, name = _scene(args)
    quantity = MOMENTUM if args.momentum else ENERGY
    attribution = Attribution(quantity, scene.t_end / args.windows if args.windows else 0.0)
    attribution.install()
    start = time.process_time()
    solution = run(scene)
    cpu = time.process_time() - start
    attribution.advance(solution.scene.t_end)  # the fronts alive at the end
    balance, conservation = solution.accuracy_report["balance"], solution.conservation()
    scale = conservation[quantity.scale]
    # fronts a lattice spliced count from the event, at their cells' states: the work (or
    # impulse) the boundaries gave the lattice's own cells differs, and belongs to it
    attribution.jumps["lattice"] += attribution.work - conservation[quantity.boundary]

    def percent(counter):
        return {k: round(float(100.0 * v / scale), 3) for k, v in counter.most_common()
                if abs(v) > 1e-6 * scale}

    print(f"{name}: {solution.stats['events']} events, {cpu:.1f} s CPU; momentum "
          f"{balance['momentum_error']:.3g}, energy {balance['energy_error']:.3g}, promise "
          f"{balance['promised']:.3g}")
    print(f"  fronts by the decision that made them (% of the {quantity.name} content):",
          percent(attribution.by_tag))
    print("  changes at events:", percent(attribution.jumps))
    total = sum(attribution.by_tag.values()) + sum(attribution.jumps.values())
    print(f"  attributed in all: {100.0 * total / scale:.4f} %")
    for window, counter in sorted(attribution.by_window.items()):
        print(f"  {window * attribution.window * 1e6:.3g}-"
              f"{(window + 1) * attribution.window * 1e6:.3g} us:", percent(counter))
    for front_id, amount in sorted(attribution.by_front.items(),
                                   key=lambda item: -abs(item[1]))[:args.fronts]:
        kind, tag, t0, x0 = attribution.info[front_id]
        print(f"    {kind} {front_id} ({tag}) from {t0 * 1e6:.4f} us, {x0 * 1e3:.4f} mm: "
              f"{100.0 * amount / scale:.4f} %")


if __name__ == "__main__":
    main()
