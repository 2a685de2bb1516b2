"""Records inside a free fragment that rang in closed form (``fronttrack.fragment``).

While a fragment rings in closed form the run keeps one region per stretch of it, at
its mean motion; a record at a station inside (a face's free-surface velocity, a probe)
is read from the closed form instead (``characteristics.free_slab``): the state at
``(X, t)`` is the one of the closed form's stress function ``w`` and velocity ``u`` on
the stretch's isentrope, and a history there steps at every passage of a wave of the
pattern, as the tracked waves would make it step.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from characteristics.free_slab import FreeSlab
from materials import State


@dataclass(frozen=True)
class RingRecord:
    """A fragment that rang in closed form from ``slab.t0`` to ``t_end`` (s): its sites'
    positions ``sites`` (m, faces first and last) and each stretch's isentrope table."""

    slab: FreeSlab
    t_end: float
    sites: tuple
    tables: tuple
    last: bool = False

    def covers(self, x: float, t: float) -> bool:
        """Whether ``(x, t)`` (m, s) lies in the fragment while it rang (its right face
        belongs to the next cell, as on a front, unless it is the stack's right end:
        ``last``)."""
        inside = self.slab.x_lo <= x < self.slab.x_hi or (self.last and x == self.slab.x_hi)
        return inside and self.slab.t0 <= t <= self.t_end

    def state(self, x: float, t: float) -> State:
        """The closed form's state at ``(x, t)`` (m, s) on its stretch's isentrope."""
        w, u = self.slab.state(x, t)
        stretch = min(int(np.searchsorted(self.sites, x, side="right")) - 1,
                      len(self.tables) - 1)
        table = self.tables[max(stretch, 0)]
        v = table.volume_at_phi(table.phi_at_stress(0.0) + float(w) / self.slab.z)
        sigma, e, _ = table.point_at_volume(v)
        return State(sigma=float(sigma), u=float(u), v=float(v), e=float(e))

    def knots(self, x: float) -> tuple[list[float], list[State]]:
        """The history at station ``x`` (m) from ``slab.t0`` to ``t_end``: coordinates
        (s) and states, a repeated coordinate at each wave's passage (a jump)."""
        times = self.slab.passages(x, self.slab.t0, self.t_end)
        edges = np.concatenate([[self.slab.t0], times, [self.t_end]])
        states = [self.state(x, 0.5 * (a + b)) for a, b in zip(edges[:-1], edges[1:],
                                                                 strict=True)]
        coords, out = [float(edges[0])], [states[0]]
        for k, tc in enumerate(times):
            coords += [float(tc), float(tc)]
            out += [states[k], states[k + 1]]
        coords.append(float(edges[-1]))
        out.append(states[-1])
        return coords, out


def records(engine) -> tuple[RingRecord, ...]:
    """The rings of a run (``engine.free_rings``), for the records of its solution."""
    return tuple(RingRecord(slab=r.slab, t_end=r.t_end if r.t_end is not None else
                            engine.t_end, sites=tuple(s.x0 for s in r.sites),
                            tables=tuple(r.tables), last=r.sites[-1].next is None)
                 for r in engine.free_rings.every)


def splice(rings, x: float, coords: list, states: list, before) -> tuple[list, list]:
    """A history's knots (``coords``, s; ``states``) at station ``x`` (m) with the
    closed form in place of the regions of every ring covering it.  ``before(t)``: the
    state at the station just before ``t`` (the region a ring replaced there is not
    passed by a front, so the knots do not know it)."""
    for ring in rings:
        if not ring.covers(x, ring.slab.t0):
            continue
        t0, t1 = ring.slab.t0, ring.t_end
        earlier = [k for k, c in enumerate(coords) if c < t0]
        after = [k for k, c in enumerate(coords) if c > t1]
        ring_coords, ring_states = ring.knots(x)
        head_c = [coords[k] for k in earlier]
        head_s = [states[k] for k in earlier]
        if head_s:
            last = before(t0)
            head_s[-1] = last
            head_c.append(t0)
            head_s.append(last)
        coords = head_c + ring_coords + [coords[k] for k in after]
        states = head_s + ring_states + [states[k] for k in after]
    return coords, states
