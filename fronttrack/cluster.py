"""Events that pile up: a cluster of fronts far below the resolution solved as one event.

Waves that converge on one point do not meet there at once in a front-tracking run:
a train of shocks running into a free face, each catching the release its predecessor
sent back, or the rays of a fan crossing a comb of entropy contacts left by that
release, meet one pair at a time, at times and places that shrink geometrically (a
Zeno cluster).  Random stacks of solids with strength spent thousands of events
within picoseconds and nanometres of a free face that way (seed 8 of
``tests/random_scenes.py::strength_stack_scene``: 2 250 events within 32 ps and
2 nm), each event exact, none visible in any record.

**When.**  An event piles up when at least ``PILE`` of the last ``WINDOW`` events lay
within the cluster length ``delta`` of it in X and within ``2 delta / C`` before it in
time (``C``: the scene's signal speed, ``Engine.signal_speed``, so ``2 delta / C`` is
less than the time any wave takes to cross the cluster and come back).  The cluster
length is ``CLUSTER_FRACTION`` of the resolution length ``l`` of the records
(``Resolution.coalesce_length``); no record resolves it.

**What.**  The group of fronts meeting at the event is widened to every consecutive
front within ``delta`` of the event point: waves of any kind, any number of entropy
contacts, and at most one other site (an interface or a boundary; a gap ends the
cluster).  The group is then one Riemann problem between the state left of it and the
state right of it, solved at the site if there is one; the entropy contacts inside are
replaced by the one contact, if any, that Riemann solution leaves.  This changes the
data only inside the strip: by at most ``delta`` times the largest jump there, in L1
over X.  Solutions of a hyperbolic system of conservation laws depend Lipschitz-
continuously in L1 on their data (for data of small total variation; Bressan,
*Hyperbolic Systems of Conservation Laws*, Oxford 2000, ch. 8), so every later state
changes by no more than a fixed multiple of that.  Solved pair by pair instead, each
event drops its echoes below the negligible stress, and a cluster of thousands of
events adds thousands of those errors: in ``tests/test_pile_up.py`` the gathered face
velocity converges (633.42, 633.35, 633.37 m/s at 1, 1/10, 1/100 of the default
negligible stress) where the pair-by-pair run ends 10 m/s off, at 623.1 m/s.

**Conservation.**  Mass is exact (Lagrangian X).  Before the event the strip
``[x_first, x_last]`` held the states between the gathered fronts; after it the outer
left state reaches the event point ``x*`` and the outer right state starts there.
Inside one material ``x*`` is the point that keeps the strip's energy
``sum rho0 (e + u^2/2) dX`` (clamped to the strip); at a site it is the site.  The
momentum (absolute) and energy (signed) the strip gains are counted
(``Counters.gathered_momentum``, kg/(m^2 s); ``gathered_energy``, J/m^2) and reported
in ``accuracy``; all gathering of a run together may move at most ``BUDGET`` of the
balance the accuracy settings promise, in momentum and in energy of either sign
(measured as ``fronttrack.coalesce.budget`` measures it).  Beyond that budget, or with
``accuracy.coalesce_length = "0 m"``, every event is solved as it comes.
"""

from __future__ import annotations

import collections
import math

from . import coalesce
from .coalesce import specific_energy
from .fronts import Front
from .kinds import FrontKind

CLUSTER_FRACTION = 1e-2
"""The cluster length, as a fraction of the resolution length of the records."""

WINDOW = 64
"""How many recent events the pile-up test looks back over."""

PILE = 48
"""An event piles up when this many of the last ``WINDOW`` events lie within the
cluster length and twice its crossing time of it: three quarters of the run's recent
activity in one spot (a Zeno cluster runs thousands of events there; the 16 rays of
one fan crossing a contact are not yet a pile-up)."""

BUDGET = 0.1
"""Fraction of the promised balance all gathering of a run may move (coalescing may
move ``fronttrack.coalesce.BUDGET``; the two together stay within the promise)."""


class ClusterWatch:
    """The recent events of a run, to tell when events pile up (module docstring)."""

    def __init__(self, resolution, signal_speed: float):
        self.length = CLUSTER_FRACTION * resolution.coalesce_length
        self.duration = 2.0 * self.length / signal_speed if signal_speed > 0.0 else 0.0
        self.recent: collections.deque = collections.deque(maxlen=WINDOW)

    def piling(self, t: float, x: float) -> bool:
        """Note the event at ``(x, t)`` (m, s); whether it piles up on the recent ones."""
        near = 0
        if self.length > 0.0:
            for t_i, x_i in reversed(self.recent):  # events come in time order
                if t - t_i > self.duration:
                    break
                near += abs(x - x_i) <= self.length
        self.recent.append((t, x))
        return near >= PILE


def gather(engine, group: list[Front], t: float, x: float):
    """Widen ``group`` to the cluster around ``(x, t)`` if events pile up there.

    Returns ``(group, x)``, the widened group and the point (m) its Riemann problem is
    solved at, with the strip's change of momentum and energy counted; ``None`` if the
    event does not pile up, the cluster adds no front, or the change would exceed the
    budget (then the event is solved as it comes).
    """
    watch = engine.cluster_watch
    if not watch.piling(t, x) or any(f.kind == FrontKind.GAP for f in group):
        return None
    delta = watch.length
    anchor = [f for f in group if f.is_site and f.kind != FrontKind.CONTACT]
    if len(anchor) > 1:
        return None
    widened = list(group)
    for step in ("prev", "next"):
        front = getattr(widened[0 if step == "prev" else -1], step)
        while front is not None and abs(front.position(t) - x) <= delta \
                and front.kind != FrontKind.GAP:
            if front.is_site and front.kind != FrontKind.CONTACT:
                if anchor:
                    break
                anchor.append(front)
            if step == "prev":
                widened.insert(0, front)
            else:
                widened.append(front)
            front = getattr(front, step)
    if len(widened) == len(group):
        return None
    point = anchor[0].x0 if anchor else None
    change = _strip_change(widened, t, point)
    if change is None:
        return None
    point, momentum, energy = change
    counters = engine.counters
    if not (_within(engine.coalesce_budget, counters, momentum, energy)
            or _within(coalesce.budget(engine, t), counters, momentum, energy)):
        return None
    counters.gathered += len(widened) - len(group)
    counters.gathered_momentum += momentum
    counters.gathered_energy += energy
    return widened, point


def principal_site(sites: list[Front]) -> Front | None:
    """The site a group's Riemann problem is solved at: its interface or boundary if it
    has one, its only site otherwise; ``None`` for several entropy contacts of one
    material (they are replaced by the contact the solution leaves, if any)."""
    for front in sites:
        if front.kind != FrontKind.CONTACT:
            return front
    return sites[0] if len(sites) == 1 else None


def _within(budget, counters, momentum: float, energy: float) -> bool:
    """Whether gathering ``momentum`` and ``energy`` more stays within ``BUDGET`` of the
    promise, given the coalescing ``budget`` (``None``: not measured yet)."""
    if budget is None:
        return False
    share = BUDGET / coalesce.BUDGET
    return (counters.gathered_momentum + momentum <= share * budget[0]
            and abs(counters.gathered_energy + energy) <= share * budget[1])


def _strip_change(group: list[Front], t: float, point: float | None):
    """``(x*, momentum, energy)``: the point the strip of ``group`` is solved at and the
    absolute momentum (kg/(m^2 s)) and signed energy (J/m^2) the strip gains when its
    outer states meet there (module docstring); ``None`` if a state is not finite."""
    before, after = group[0].prev, group[-1]
    left = before.region_right if before is not None else None
    right = after.region_right
    x_first, x_last = group[0].position(t), after.position(t)
    momentum = energy = 0.0
    for front in group[:-1]:
        region = front.region_right
        width = front.next.position(t) - front.position(t)
        momentum += region.material.rho0 * width * region.state.u
        energy += region.material.rho0 * width * specific_energy(region.state)
    if point is None:  # one material: the point that keeps the strip's energy
        rho0 = (left or right).material.rho0
        e_left = specific_energy(left.state) if left is not None else 0.0
        e_right = specific_energy(right.state) if right is not None else 0.0
        width = x_last - x_first
        if e_left == e_right or width <= 0.0:
            point = 0.5 * (x_first + x_last)
        else:
            share = (energy / rho0 - width * e_right) / (width * (e_left - e_right))
            point = x_first + min(max(share, 0.0), 1.0) * width
    new_momentum = new_energy = 0.0
    for region, width in ((left, point - x_first), (right, x_last - point)):
        if region is not None:
            mass = region.material.rho0 * width
            new_momentum += mass * region.state.u
            new_energy += mass * specific_energy(region.state)
    gained = (abs(new_momentum - momentum), new_energy - energy)
    if not all(map(math.isfinite, gained)):
        return None
    return (point, *gained)
