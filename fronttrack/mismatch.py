"""Stress mismatches that dropped waves leave at sites, and when they are solved again.

A wave weaker than the negligible stress is dropped (``fronttrack.outgoing``).  At a
site (a boundary, an interface between layers, a gap face) the state beside it
then keeps the value it had before the event: across an interface the two sides differ
by the dropped jump ``d_sigma``, and beside a boundary the state differs from the
prescribed value by as much.  The material's equations do not see that difference,
so it acts as a force ``d_sigma`` (Pa) on the stack, and the momentum balance drifts at
that rate until the next wave reaches the site and its Riemann problem is solved again
from the states there.  Usually a wave comes within a transit.  Where none comes, the
mismatch acts for the rest of the run: a 50 µm layer at rest struck by a slow foam
(campaign seed 78) had the 27.7 MPa wave into it dropped; the foam pushed on a layer
that never moved, and 2 % of the momentum was lost over 4 µs.

So a mismatch may act only until its impulse ``|d_sigma| tau`` reaches its share of a
budget: ``BUDGET`` of the balance the accuracy settings promise, times the momentum
content ``sum rho0 |u| dX`` of the stack (the scale the balance is measured on; taken
at the first mismatch, and again whenever the budget runs short: it never shrinks).
Each new mismatch may make ``1 / SHARES`` of what is left of it.  At its deadline
the site's Riemann problem is solved again and its waves are kept however weak; a wave
reaching the site before then solves it anyway, and the mismatch is settled at the
impulse it actually made.  The impulse all mismatches made is reported
(``accuracy["mismatch_impulse"]``, relative to the budget's momentum content).
Mismatches pending at once may together make more than what was left (each draws on
the same remainder), by at most the number pending over ``SHARES`` of it.  A foam
striking a 200 µm plate (``tests/test_mismatch.py``) created 0.21 % of its energy
without deadlines and balances it to 6e-5 with them.

A wave dropped inside a material (two waves crossing there) would have run to the next
front on its side; where that front is a site, the mismatch is the site's (added to any
it has); where it is a wave, that wave's next event solves it from the states there.
Mismatches no larger than ``ROUNDING`` of the stress scale are rounding.  Entropy
contacts inside a material are not followed: the material's own waves cross them all
the time, and forcing weak waves there multiplies them (the quartz-on-steel contact
comb of ``tests/test_engine_hard.py``, kept without coalescing, went from 17 302 events
to past 200 000).
"""

from __future__ import annotations

from dataclasses import dataclass

from . import balance
from .kinds import FrontKind

BUDGET = 0.25
"""Fraction of the promised balance that site mismatches may spend in all (coalescing
spends at most ``fronttrack.coalesce.BUDGET``)."""

SHARES = 8
"""A new mismatch may make at most this fraction (1 / SHARES) of the budget left."""

ROUNDING = 1e-9
"""Mismatches below this fraction of the stress scale are rounding."""

SITES = (FrontKind.BOUNDARY, FrontKind.INTERFACE, FrontKind.GAP)


@dataclass(eq=False)
class Pending:
    """A mismatch of ``stress`` (Pa) at ``site`` since ``since`` (s), which may make the
    impulse ``allowed`` (Pa s): it is solved again at ``deadline`` (s)."""

    site: object
    stress: float
    since: float
    allowed: float
    deadline: float


@dataclass
class Ledger:
    """The mismatches of one run: those pending by site id, the impulse (Pa s) they
    made, and the budget (Pa s; ``None`` until needed) with
    the momentum content it was taken from (kg/(m^2 s))."""

    pending: dict
    made: float = 0.0
    budget: float | None = None
    content: float = 0.0
    resolved: int = 0

    def report(self) -> dict:
        """``mismatch_impulse``: the impulse all mismatches made, relative to the momentum
        content; ``mismatches_resolved``: sites solved again at a deadline."""
        return {"mismatch_impulse": self.made / self.content if self.content > 0.0 else 0.0,
                "mismatches_resolved": self.resolved}


def new_ledger() -> Ledger:
    return Ledger(pending={})


def note_event(engine, site, group, t: float, dropped_left, dropped_right,
               merged=None) -> None:
    """After an event at time ``t`` (s) among the fronts ``group``, at ``site`` (or
    none), that dropped the waves ``dropped_left`` and ``dropped_right`` (leading first).

    At a site, its pending mismatch is settled and the new one (if any) follows it.
    Waves dropped inside a material would have run to the next front on their side;
    where that front is a site, the mismatch is the site's (added to what it has).
    When both families were dropped and the regions beside the event merge into the
    state ``merged``, a site beside them keeps the change of its side's stress."""
    left, right = _total(dropped_left), _total(dropped_right)
    if site is not None:
        _note(engine, site, left + right, t)
        return
    if merged is not None:
        left = abs(merged.sigma - group[0].prev.region_right.state.sigma)
        right = abs(merged.sigma - group[-1].region_right.state.sigma)
    for dropped, neighbour in ((left, group[0].prev), (right, group[-1].next)):
        if dropped > 0.0 and neighbour is not None:
            pending = engine.mismatches.pending.get(neighbour.id)
            _note(engine, neighbour, dropped + (pending.stress if pending else 0.0), t)


def _total(waves) -> float:
    return sum(abs(w.behind.sigma - w.ahead.sigma) for w in waves)


def _note(engine, site, dropped_stress: float, t: float) -> None:
    """Settle the pending mismatch of ``site`` at time ``t`` and give the one it has now,
    ``dropped_stress`` (Pa), a deadline."""
    if site.kind not in SITES:
        return
    ledger = engine.mismatches
    _settle(ledger, site, t)
    if dropped_stress <= ROUNDING * engine.resolution.stress_scale:
        return
    allowed = _available(engine, ledger, t) / SHARES
    deadline = t + allowed / dropped_stress
    if deadline > engine.t_end:
        allowed = dropped_stress * (engine.t_end - t)
        deadline = engine.t_end
    entry = Pending(site, dropped_stress, t, allowed, deadline)
    ledger.pending[site.id] = entry
    if deadline < engine.t_end:
        engine.push_mismatch(entry)


def is_due(engine, entry: Pending) -> bool:
    """Whether a queued deadline is still the site's pending one (the site may have
    been solved again since, or have ended)."""
    return entry.site.alive and engine.mismatches.pending.get(entry.site.id) is entry


def deferred(engine, entry: Pending) -> bool:
    """Whether a due deadline waits for a lattice: the cells beside its site were solved
    ahead of the queue up to ``site.solved_until`` (``fronttrack.zones``), so solving the
    site now would read them before they begin and send waves into what the lattice
    solved (campaign seed 433: a wave dropped 1.5 mm away put its mismatch on a gap face
    whose far side a lattice had solved 31 ns ahead; the waves sent there ran past the
    wall).  The deadline moves to the lattice's cut, and the impulse the mismatch may
    make grows with it."""
    later = entry.site.solved_until
    if entry.deadline >= later:
        return False
    entry.allowed += entry.stress * (later - entry.deadline)
    entry.deadline = later
    engine.push_mismatch(entry)
    return True


def count_resolved(engine) -> None:
    engine.mismatches.resolved += 1


def _settle(ledger: Ledger, site, t: float) -> None:
    entry = ledger.pending.pop(site.id, None)
    if entry is None:
        return
    ledger.made += min(entry.stress * (t - entry.since), entry.allowed)


def _available(engine, ledger: Ledger, t: float) -> float:
    """The impulse (Pa s) mismatches may still make: the budget less what they made (the
    budget is measured again when this runs short)."""
    if ledger.budget is None or ledger.budget - ledger.made <= 0.0:
        content = balance.live_content(engine, t)[0]
        ledger.content = max(ledger.content, content)
        promise = balance.promised_balance(engine.resolution.report())
        ledger.budget = BUDGET * promise * ledger.content
    return max(ledger.budget - ledger.made, 0.0)
