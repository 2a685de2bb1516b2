"""A free fragment ringing, as one closed-form object.

A fragment bounded by two free faces (open gaps or free boundaries) touches nothing:
its waves reflect at both faces with stress reflection ``-1`` and ring for ever, every
reflection and crossing an event.  Where those waves are weak enough to be linear
within the record tolerance, their pattern at the replacement time ``t0`` is propagated
in closed form instead (``characteristics.free_slab``: d'Alembert in the fragment, free
at both faces, period ``2 L / C``) and no event is spent inside it.  The fragment keeps
one region per stretch between its sites (its faces and any entropy contact inside),
at the mean motion ``u0`` and zero stress; the closed form gives its faces' velocities
at any time (for its gaps' closure and the faces' records) and its state anywhere.

**Linearisation error.**  The closed form is linear in the exact Riemann invariants
``u +- phi(sigma)`` of the fragment's isentrope (``phi = int d sigma / (rho0 C_L)``, the
stress function): its variable is ``w = Z (phi(sigma) - phi(0))`` (``w = 0`` at a free
face, ``w ~ sigma`` for weak waves), and it moves every part of the pattern at the
Lagrangian sound speed ``C`` at zero stress, ``Z = rho0 C``; the material moves it at
``C_L(sigma)``.  Over the range ``[-W, W]`` of ``w`` the pattern reaches (``W = max P -
min P``):

- *split*: a wave whose jump does not satisfy ``dw = +- Z du`` (a shock: third order
  in its strength; a ray: rounding) is taken as that wave plus one of
  ``(dw -+ Z du) / 2`` in the other direction, and a contact inside between two
  isentropes as transparent (its whole jump of ``w``): their sum bounds the error at
  any point and is held to the record tolerance ``tol``;
- *drift*: along a characteristic ``C_L - C`` is, to first order, ``C' w``, whose
  integral over a period is zero (each part of the pattern spends half a period at
  ``+s`` and half at ``-s`` of its own amplitude, and sweeps the other family, of zero
  mean, twice), so its integral up to any time is at most half that of ``|C' w|`` over
  a period.  The pattern's displacement from the closed form stays within
  ``dC1 L / C + dC2 T``, with ``dC1 = max |C_L(+-W) - C|`` and ``dC2 = |C_L(W) +
  C_L(-W) - 2 C| / 2`` (the second-order, secular part) over the remaining time ``T``.
  Like coalescing (``fronttrack.coalesce``) the displacement is held to the resolution
  length ``l``, or for a weak pattern its total variation times it to ``VISIBILITY tol
  l``.

A pattern whose tension would reach a spall strength, a scene with a cumulative-damage
criterion or planned fractures, and a stretch whose cells do not share one isentrope
table are not replaced; nor is a fragment beside a gap whose far face has tracked
waves behind it (every one of them would change when the gap closes: the demo's thin
spalled layers), or one that would not ring free for ``MIN_PERIODS`` periods.

**Its gaps.**  A gap's width is advanced with each face's closed-form displacement
(``advance_gap``) and its closing found in closed form (``closure_time``: the faces'
velocities are piecewise constant); a lattice beside it sees the ring's face velocity
until it next changes (``far_face``).  A wave reaching the gap from across reflects at
its own free face and leaves the ring alone.  The ring ends when a gap of it closes:
its waves are handed back at that instant (``hand_back``), and the closure is solved
as any other.

**Conservation.**  Mass is exact (Lagrangian).  Momentum: ``rho0 L u0`` is the
fragment's momentum at ``t0`` and a constant of the closed form.  Energy: each region
of the fragment holds at ``t0`` exactly the total energy of its cells: its kinetic
energy at ``u0`` and, as internal energy, the rest, of which the part above the
isentrope at zero stress is the ringing energy carried (``ringing_energy``, J/m^2).
The run's balance sees no change.  When the ringing ends, its waves are handed back
at the closed form's state (one-characteristic waves on the isentrope); the energy of
the handed-back cells, on their isentropes, differs from the carried total by the
linearisation's error, which is put back as one internal-energy offset over the
fragment (``energy_offset``, J/kg) so that the total is kept exactly.  Each
replacement is listed in ``accuracy["fragments_ringing"]``.
"""

from __future__ import annotations

import dataclasses
import itertools
import math

import numpy as np

from characteristics.free_slab import FreeSlab
from materials import State, WavediagramError

from . import coalesce, ringing
from .fronts import UNKNOWN, inside_fan
from .kinds import BoundaryKind, FrontKind

MAX_FRONTS = 400
"""A fragment holding more fronts than this is not looked at (the walk stays cheap)."""

MIN_PERIODS = 1.0
"""A fragment is replaced only if it would ring free (no gap of it closing, the run not
ending) for at least this many periods: a ring costs a hand-back, whose waves are
one-characteristic waves, and saves about a period's events per period."""

RETRY_PERIODS = 1.0
"""A fragment refused is looked at again after this many of its periods."""


@dataclasses.dataclass
class Ring:
    """One free fragment ringing in closed form, live in the engine."""

    slab: FreeSlab
    sites: list            # faces and interior contacts, left to right
    regions: list          # the regions between consecutive sites
    tables: list           # the isentrope table of each stretch
    material: object
    energy: float          # total energy per unit area at t0 (J/m^2)
    entry: dict            # its line in accuracy["fragments_ringing"]
    t_end: float | None = None   # when it was handed back


class Rings:
    """The engine's live rings, by region id and by face id, and refusals."""

    def __init__(self):
        self.every: list[Ring] = []
        self.by_region: dict[int, Ring] = {}
        self.by_face: dict[int, list[Ring]] = {}  # a gap can face two
        self.retry: dict[tuple[int, int], float] = {}

    def __bool__(self) -> bool:
        return bool(self.by_face)


def _face_kind(engine, site) -> bool:
    """A free face a fragment ends at: an open gap, or a free boundary without later
    steps."""
    if site.kind == FrontKind.GAP:
        return True
    if site.kind == FrontKind.BOUNDARY and site.piston_velocity is None:
        spec = engine.scene.left if site.side == "left" else engine.scene.right
        return spec.kind == BoundaryKind.FREE and not [
            s for s, _ in site.boundary_steps if s > site.t0]
    return False


def _fragment(engine, group):
    """``(left face, fronts inside, right face)`` of the free fragment one of whose faces
    ``group`` reaches, or ``None``."""
    if len(group) < 2:
        return None
    if group[-1].is_site and not group[0].is_site:
        face, step = group[-1], "prev"
    elif group[0].is_site and not group[-1].is_site:
        face, step = group[0], "next"
    else:
        return None
    if not _face_kind(engine, face) or (face.kind == FrontKind.BOUNDARY and (
            (face.side == "left") != (step == "next"))):
        return None
    inside, front = [], getattr(face, step)
    while front is not None and not (front.is_site and front.kind not in (
            FrontKind.CONTACT, FrontKind.INTERFACE)):
        inside.append(front)
        if len(inside) > MAX_FRONTS:
            return None
        front = getattr(front, step)
    if front is None or not _face_kind(engine, front):
        return None
    if step == "prev":
        inside.reverse()
        return front, inside, face
    return face, inside, front


def try_replace(engine, group, t: float) -> bool:
    """Replace the free fragment whose face ``group`` reaches at ``t`` by its closed-form
    ringing, if its waves are linear within the record tolerance (module docstring);
    ``True`` if replaced (the event is then done: the closed form holds it)."""
    res = engine.resolution
    if (res.coalesce_length <= 0.0 or res.negligible <= 0.0
            or engine.scene.spall_criterion is not None or engine.fractures):
        return False
    found = _fragment(engine, group)
    if found is None:
        return False
    left, inside, right = found
    key = (left.id, right.id)
    if engine.free_rings.retry.get(key, -math.inf) > t:
        return False
    sites = [left] + [f for f in inside if f.is_site] + [right]
    if any(s.kind == FrontKind.INTERFACE and s.bond != "bonded" for s in sites[1:-1]):
        return False
    waves = [f for f in inside if not f.is_site]
    if not waves or not (_quiet_beyond(engine, left, "left")
                         and _quiet_beyond(engine, right, "right")):
        return False
    bounds = [left, *inside, right]
    regions = [f.region_right for f in bounds[:-1]]
    material = regions[0].material
    if any(r.material is not material for r in regions):
        return False
    tables = _tables(engine, bounds, regions)
    # an isentrope that ends before zero stress (its faces held at a release floor,
    # ``materials.wavecurves``) has no free ringing
    if tables is None or not all(table.covers(0.0) for table in tables):
        return False
    edges = np.array([f.position(t) for f in bounds])
    if np.any(np.diff(edges) < 0.0):
        return False
    stretch = _stretch_of(bounds)
    c = tables[0].speed_at_stress(0.0)
    z = material.rho0 * c
    w = np.array([_linear(tables[k], r.state.sigma, z) for k, r in zip(stretch, regions,
                                                                        strict=True)])
    u = np.array([r.state.u for r in regions])
    slab = FreeSlab.from_cells(edges, w, u, t, c, z)
    error = linearisation_error(engine, slab, tables[0], bounds, w, u, t)
    if error is not None and _lifetime(engine, slab, left, right, t) < MIN_PERIODS * slab.period:
        error = None   # handed back before it saves anything
    stretches = None if error is None else _stretch_states(
        slab, sites, bounds, regions, tables, material, t, res.stress_scale)
    if stretches is None:
        engine.free_rings.retry[key] = t + RETRY_PERIODS * slab.period
        return False
    _replace(engine, slab, sites, bounds, regions, tables, material, t, error, stretches)
    return True


def _quiet_beyond(engine, face, side: str) -> bool:
    """Whether nothing moves beyond ``face`` (on its ``side``, away from the fragment):
    a boundary, or a gap whose far face is a ring's or has no wave between it and the
    next site (its velocity is then known until a wave enters from beyond).  A fragment
    beside a gap whose far side rings with tracked waves would have its gap's closing
    changed by every one of them (the demo's thin spalled layers): it is not replaced."""
    if face.kind != FrontKind.GAP:
        return True
    beyond = face.prev if side == "left" else face.next
    far = face.prev.region_right if side == "left" else face.region_right
    return beyond is None or beyond.is_site or far.id in engine.free_rings.by_region


def _stretch_of(bounds) -> list[int]:
    """The stretch (between two of the fragment's sites) of each cell."""
    index, out = 0, []
    for front in bounds[:-1]:
        if front.is_site and front is not bounds[0]:
            index += 1
        out.append(index)
    return out


def _linear(table, sigma: float, z: float) -> float:
    """The linear variable of a stress (Pa): ``Z (phi(sigma) - phi(0))``, with ``phi``
    the stress function of the isentrope (``int d sigma / (rho0 C_L)``), so that the
    invariants ``u +- w / Z`` are the exact Riemann invariants; ``w = 0`` at a free face
    and ``w ~ sigma`` for weak waves."""
    return z * (table.phi_at_stress(sigma) - table.phi_at_stress(0.0))


def _stress(table, w: float, z: float) -> tuple[float, float, float]:
    """``(sigma, e, C_L)`` on ``table``'s isentrope at the linear variable ``w`` (Pa)."""
    return table.point_at_volume(table.volume_at_phi(table.phi_at_stress(0.0) + w / z))


def _tables(engine, bounds, regions):
    """The isentrope table of each stretch between the fragment's sites (every cell of a
    stretch on it), or ``None``."""
    stretches, current = [], None
    for front, region in zip(bounds[:-1], regions, strict=True):
        table = (region.table if region.table is not UNKNOWN  # looked up, never built
                 else engine.tables.table(region.material, region.state, build=False))
        if table is None:
            return None
        if front.is_site and front is not bounds[0]:
            stretches.append(current)
            current = None
        if current is None:
            current = table
        elif table is not current and not current.matches(region.state,
                                                          engine.tables.tolerance):
            return None
    return [*stretches, current]


def linearisation_error(engine, slab: FreeSlab, table, bounds, w, u, t: float):
    """``{"split": Pa, "drift": m, "t_remaining": s}`` if the closed form fits the record
    tolerance for the rest of the run (module docstring), else ``None``.  ``w``, ``u``:
    the cells' linear variable (``_linear``, Pa) and velocity (m/s)."""
    res = engine.resolution
    tol = coalesce.record_tolerance(res)
    # split: each wave's jump off the linear relation of its direction (a site's whole
    # jump of w: the closed form moves through it as if it were not there)
    split = 0.0
    for k, front in enumerate(bounds[1:-1]):
        off = (w[k + 1] - w[k]) - front.direction * slab.z * (u[k + 1] - u[k])
        split += abs(w[k + 1] - w[k]) if front.is_site else 0.5 * abs(off)
    if split > tol:
        return None
    top = float(slab.values.max() - slab.values.min())
    try:
        low, high = _stress(table, -top, slab.z), _stress(table, top, slab.z)
    except (WavediagramError, ValueError):
        return None
    if -low[0] >= bounds[1].region_right.material.spall_strength:
        return None   # its tension could reach the spall strength
    first = max(abs(low[2] - slab.c), abs(high[2] - slab.c))
    second = 0.5 * abs(low[2] + high[2] - 2.0 * slab.c)
    remaining = max(engine.t_end - t, 0.0)
    drift = first * slab.period + second * remaining
    variation = float(np.abs(np.diff(np.append(slab.values, slab.values[0]))).sum())
    length = res.coalesce_length
    if drift > length and variation * drift > coalesce.VISIBILITY * tol * length:
        return None
    return {"split": split, "drift": drift, "t_remaining": remaining}


def _stretch_states(slab, sites, bounds, regions, tables, material, t: float, scale: float):
    """For each stretch between two of the fragment's sites: ``(state, energy,
    carried)`` -- its region's state at zero stress and the mean velocity, with the
    internal energy that keeps the stretch's total energy (J/m^2, ``energy``) exactly,
    and the part of it above the isentrope at zero stress (``carried``, J/m^2) -- or
    ``None`` if the equation of state has no volume for one of them (its stress zero
    within ``ringing.ENERGY_ROUNDING`` of ``scale``, Pa)."""
    widths = np.diff([f.position(t) for f in bounds])
    out, cell = [], 0
    for j, b in enumerate(sites[1:]):
        mass = energy = 0.0
        while cell < len(regions) and bounds[cell] is not b:
            state = regions[cell].state
            mass += widths[cell]
            energy += widths[cell] * (state.e + 0.5 * state.u ** 2)
            cell += 1
        e = energy / mass - 0.5 * slab.u0 ** 2
        rest = _rest_state(tables[j])
        state = _at_energy(material, rest, e, slab.u0, scale)
        if state is None:
            return None
        out.append((state, material.rho0 * energy, material.rho0 * mass * (e - rest.e)))
    return out


def _replace(engine, slab, sites, bounds, regions, tables, material, t, error,
             stretches) -> None:
    """End the fragment's waves and cells at ``t`` and start its ringing regions (one
    per stretch, ``stretches`` from ``_stretch_states``)."""
    for gap in (sites[0], sites[-1]):
        if gap.kind == FrontKind.GAP:
            advance_gap(engine, gap, t)
    positions = [f.position(t) for f in bounds]
    for k, region in enumerate(regions):
        region.left_points.append((positions[k], t))
        region.right_points.append((positions[k + 1], t))
        region.t_end = t
    for front in bounds[1:-1]:
        if front.is_site:
            continue
        front.alive = False
        front.t1, front.x1 = t, front.position(t)
        front.right_region_id = front.region_right.id
    new_regions = []
    for (a, b), (state, _, _) in zip(itertools.pairwise(sites), stretches, strict=True):
        region = engine.new_region(state, material, regions[0].layer, t, (a.x0, t), (b.x0, t))
        a.earlier_regions.append((t, a.region_right.id))
        a.region_right = region
        a.next, b.prev = b, a
        new_regions.append(region)
    carried = sum(c for _, _, c in stretches)
    ring = Ring(slab=slab, sites=sites, regions=new_regions, tables=tables,
                material=material, energy=sum(e for _, e, _ in stretches), entry={
                    "layer": regions[0].layer, "t": float(t), "x_lo": slab.x_lo,
                    "x_hi": slab.x_hi, "period": slab.period, "sound_speed": float(slab.c),
                    "u": float(slab.u0), "amplitude": float(np.ptp(slab.values)),
                    "split": float(error["split"]), "drift": float(error["drift"]),
                    "ringing_energy": float(carried), "t_end": None, "energy_offset": None})
    rings = engine.free_rings
    for region in new_regions:
        rings.by_region[region.id] = ring
    for face in (sites[0], sites[-1]):
        rings.by_face.setdefault(face.id, []).append(ring)
    engine.counters.fragments.append(ring.entry)
    rings.every.append(ring)
    for gap in (sites[0], sites[-1]):
        if gap.kind == FrontKind.GAP:
            engine.push_gap_closure(gap)


def _rest_state(table) -> State:
    """The state of zero stress and zero velocity on ``table``'s isentrope."""
    v = table.volume_at_phi(table.phi_at_stress(0.0))
    _, e, _ = table.point_at_volume(v)
    return State(sigma=0.0, u=0.0, v=v, e=e)


def _at_energy(material, rest: State, e: float, u: float, scale: float) -> State | None:
    """The state of zero stress, velocity ``u`` and internal energy ``e`` (its volume
    from the equation of state, near ``rest``'s, the stress zero within
    ``ringing.ENERGY_ROUNDING`` of ``scale``, Pa), or ``None``."""
    v = material.volume_at(rest, 0.0, e, ringing.ENERGY_ROUNDING * scale)
    if v is None:
        return None
    return State(sigma=0.0, u=u, v=v, e=e)


# --- faces --------------------------------------------------------------------------
MAX_FACE_CHANGES = 100_000
"""A gap's closing is sought over windows of time in which a ringing face changes its
velocity at most about this many times (a thin fragment rings ``1e5`` periods in a long
run: listing every change at once would take gigabytes)."""


def _face_ring(engine, gap, side: str, candidate=None):
    """``(slab, face, velocity)`` of the face on ``side`` of ``gap``: a ring's slab and
    its face (``"left"``/``"right"``) in closed form, else ``None`` and the velocity
    (m/s) of the region there.  ``candidate``: ``(side, slab)`` taken as ringing."""
    face = "right" if side == "left" else "left"
    if candidate is not None and candidate[0] == side:
        return candidate[1], face, None
    region = gap.prev.region_right if side == "left" else gap.region_right
    ring = engine.free_rings.by_region.get(region.id)
    if ring is None:
        return None, face, region.state.u
    return ring.slab, face, None


def _pieces(face_ring, t_from: float, t_to: float):
    """``(starts, velocities)`` of a face over ``[t_from, t_to]`` (``_face_ring``)."""
    slab, face, u = face_ring
    if slab is None:
        return np.array([t_from]), np.array([u])
    return slab.face_pieces(face, t_from, t_to)


def _moved(face_ring, t_from: float, t: float) -> float:
    """How far (m) a face moved from ``t_from`` to ``t`` (s)."""
    slab, face, u = face_ring
    if slab is None:
        return u * (t - t_from)
    return float(slab.face_displacement(face, t_from, t))


def _mean_motion(face_ring) -> tuple[float, float]:
    """``(velocity, wander)``: a face's mean velocity (m/s) and the most (m) its
    displacement departs from it over any span."""
    slab, _, u = face_ring
    if slab is None:
        return u, 0.0
    return slab.u0, slab.face_wander


def _displacement(starts, velocities, t_to: float, times) -> np.ndarray:
    """The face's displacement (m) from ``starts[0]`` at ``times`` (s, up to ``t_to``)."""
    ends = np.append(starts[1:], t_to)
    done = np.concatenate([[0.0], np.cumsum(velocities * (ends - starts))])
    k = np.clip(np.searchsorted(starts, times, side="right") - 1, 0, len(starts) - 1)
    return done[k] + velocities[k] * (times - starts[k])


def touches(engine, gap) -> bool:
    """Whether a ring lies on either side of ``gap``."""
    rings = engine.free_rings
    return bool(rings) and (gap.id in rings.by_face or any(
        r is not None and r.id in rings.by_region
        for r in (gap.prev.region_right if gap.prev is not None else None, gap.region_right)))


def far_face(engine, gap, side: str, t: float) -> tuple[float, float]:
    """``(velocity, until)``: the velocity (m/s) at ``t`` of the face across ``gap`` from
    a lattice on its ``side`` (``"left"``: the lattice lies right of the gap) and the time
    (s) until which it holds; a ring's face in closed form (the gap's width is then
    brought up to ``t``, from where the lattice follows it)."""
    far = gap.prev.region_right if side == "left" else gap.region_right
    ring = engine.free_rings.by_region.get(far.id)
    if ring is None:
        return far.state.u, math.inf
    advance_gap(engine, gap, t)
    # a face that keeps its velocity for a whole period keeps it for ever
    starts, velocities = ring.slab.face_pieces("right" if side == "left" else "left", t,
                                               min(engine.t_end, t + ring.slab.period))
    return float(velocities[0]), float(starts[1]) if starts.size > 1 else math.inf


def advance_gap(engine, gap, t: float) -> None:
    """Bring ``gap``'s width up to ``t``: its faces moved with the states next to them
    (a ring's face in closed form)."""
    if t <= gap.gap_time:
        return
    if not touches(engine, gap):
        opening = gap.region_right.state.u - gap.prev.region_right.state.u
        gap.gap_width += opening * (t - gap.gap_time)
    else:
        gap.gap_width += (_moved(_face_ring(engine, gap, "right"), gap.gap_time, t)
                          - _moved(_face_ring(engine, gap, "left"), gap.gap_time, t))
    gap.gap_time = t


def closure_time(engine, gap, candidate=None) -> float:
    """The first time (s, at most ``t_end``; ``inf`` if none) the faces of ``gap``, one
    of them a ring's, meet.  ``candidate``: ``(side, slab)``, a fragment on that side
    of the gap taken as ringing by ``slab``.

    The faces' velocities are piecewise constant: the width is followed exactly over
    windows of at most ``MAX_FACE_CHANGES`` changes.  After each, the faces' mean
    motions bound it from below (``width - wander_left - wander_right + (u_right -
    u_left) (t - t_b)``): a gap that this bound keeps open never closes, and no closing
    comes before the bound reaches zero, so the search skips to there."""
    faces = [_face_ring(engine, gap, side, candidate) for side in ("left", "right")]
    t_a, t_end, width = gap.gap_time, engine.t_end, gap.gap_width
    window = t_end - t_a
    for slab, _, _ in faces:
        if slab is not None:
            window = min(window, max(1.0, MAX_FACE_CHANGES / slab.breaks.size) * slab.period)
    (u_lo, wander_lo), (u_hi, wander_hi) = (_mean_motion(face) for face in faces)
    while t_a < t_end:
        t_b = min(t_end, t_a + window)
        lo, hi = (_pieces(face, t_a, t_b) for face in faces)
        times = np.unique(np.concatenate([lo[0], hi[0], [t_b]]))
        widths = width + _displacement(*hi, t_b, times) - _displacement(*lo, t_b, times)
        closed = np.nonzero(widths <= 0.0)[0]
        if closed.size:
            k = int(closed[0])
            if k == 0:
                return t_a
            # linear between times[k-1] (open) and times[k] (closed)
            w0, w1 = widths[k - 1], widths[k]
            return float(times[k - 1] + (times[k] - times[k - 1]) * w0 / (w0 - w1))
        t_a, width = t_b, float(widths[-1])
        margin = width - wander_lo - wander_hi
        if margin > 0.0:
            if u_hi >= u_lo:
                return math.inf
            t_skip = min(t_end, t_a + margin / (u_lo - u_hi))
            width += _moved(faces[1], t_a, t_skip) - _moved(faces[0], t_a, t_skip)
            t_a = t_skip
    return math.inf


def _lifetime(engine, slab: FreeSlab, left, right, t: float) -> float:
    """How long (s) a fragment ringing by ``slab`` from ``t`` would stay free: until the
    first of its gaps closes (its far faces as they are now) or the run ends."""
    end = engine.t_end
    for gap, side in ((left, "right"), (right, "left")):
        if gap.kind == FrontKind.GAP:
            advance_gap(engine, gap, t)
            end = min(end, closure_time(engine, gap, (side, slab)))
    return end - t


# --- ending -------------------------------------------------------------------------
def hand_back(engine, ring: Ring, t: float) -> None:
    """End ``ring`` at ``t``: its waves and cells at the closed form's state, the total
    energy kept by one internal-energy offset (module docstring)."""
    rings = engine.free_rings
    slab, material = ring.slab, ring.material
    for face in (ring.sites[0], ring.sites[-1]):
        if face.kind == FrontKind.GAP:
            advance_gap(engine, face, t)
    for region in ring.regions:
        rings.by_region.pop(region.id, None)
    for face in (ring.sites[0], ring.sites[-1]):
        beside = rings.by_face.get(face.id, [])
        if ring in beside:
            beside.remove(ring)
        if not beside:
            rings.by_face.pop(face.id, None)
    x, direction, jump = slab.jumps_at(t)
    x_tol = engine.resolution.x_tol
    pieces = []   # per stretch: (fronts, cell states)
    cells_all = []
    for j, (a, b) in enumerate(zip(ring.sites[:-1], ring.sites[1:], strict=True)):
        inside = (x > a.x0 + x_tol) & (x < b.x0 - x_tol)
        xs, ds = x[inside], direction[inside]
        edges = np.concatenate([[a.x0], xs, [b.x0]])
        mids = 0.5 * (edges[:-1] + edges[1:])
        w, u = slab.state(mids, t)
        table = ring.tables[j]
        states = [_on_table(table, float(a), float(v), slab.z) for a, v in zip(w, u, strict=True)]
        pieces.append((xs, ds, edges, states))
        cells_all += [(float(w), st) for w, st in zip(np.diff(edges), states, strict=True)]
    rho0 = material.rho0
    mass = sum(w for w, _ in cells_all)
    handed = rho0 * sum(w * (s.e + 0.5 * s.u ** 2) for w, s in cells_all)
    offset = (ring.energy - handed) / (rho0 * mass)
    for j, (a, b) in enumerate(zip(ring.sites[:-1], ring.sites[1:], strict=True)):
        xs, ds, edges, states = pieces[j]
        states = [_offset(material, s, offset, engine.resolution.stress_scale)
                  for s in states]
        old = ring.regions[j]
        old.left_points.append((a.x0, t))
        old.right_points.append((b.x0, t))
        old.t_end = t
        table = ring.tables[j]
        fronts = []
        for k, (xk, dk) in enumerate(zip(xs, ds, strict=True)):
            ahead, behind = (states[k + 1], states[k]) if dk > 0 else (states[k], states[k + 1])
            fronts.append(_ray(engine, table, float(xk), int(dk), ahead, behind, t))
        chain = [a, *fronts, b]
        a.earlier_regions.append((t, old.id))
        for k, (p, q) in enumerate(zip(chain[:-1], chain[1:], strict=True)):
            p.next, q.prev = q, p
            p.region_right = engine.new_region(
                states[k], material, old.layer, t, (edges[k], t), (edges[k + 1], t),
                table=table, in_fan=inside_fan(p, q))
            if k > 0:
                p.left_region = chain[k - 1].region_right.id
        b.left_region = chain[-2].region_right.id
        for p, q in zip(chain[:-1], chain[1:], strict=True):
            engine.push_pair(p, q, t)
    ring.entry["t_end"] = ring.t_end = t
    for face in (ring.sites[0], ring.sites[-1]):
        if face.kind == FrontKind.GAP:  # its closing, from the faces handed back
            engine.push_gap_closure(face)
    ring.entry["energy_offset"] = float(offset)
    ring.entry["handed_back_waves"] = int(sum(len(p[0]) for p in pieces))


def _on_table(table, w: float, u: float, z: float) -> State:
    """The state of linear variable ``w`` (Pa, ``_linear``) and velocity ``u`` on
    ``table``'s isentrope."""
    v = table.volume_at_phi(table.phi_at_stress(0.0) + w / z)
    sigma, e, _ = table.point_at_volume(v)
    return State(sigma=sigma, u=u, v=v, e=e)


def _offset(material, state: State, offset: float, scale: float) -> State:
    """``state`` with ``offset`` (J/kg) more internal energy at the same stress (its
    volume from the equation of state, as ``_at_energy``; kept where none is found)."""
    if offset == 0.0:
        return state
    e = state.e + offset
    v = material.volume_at(state, state.sigma, e, ringing.ENERGY_ROUNDING * scale)
    return dataclasses.replace(state, e=e, v=v if v is not None else state.v)


def _ray(engine, table, x: float, direction: int, ahead: State, behind: State, t: float):
    """A one-characteristic wave of the handed-back pattern."""
    a, b = table.invariants(ahead), table.invariants(behind)
    middle = (0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]))
    return engine.new_front(FrontKind.RAY, x, t, speed=direction * table.speed(*middle),
                            fan=engine.next_wave_id(), ray_count=1, direction=direction,
                            jump=behind.sigma - ahead.sigma,
                            invariant=middle[0 if direction > 0 else 1],
                            lineage=engine.next_wave_id())


def end_at_face(engine, group, t: float) -> None:
    """Hand back every ring whose face is in ``group`` (an event there: its gap closes,
    or a lattice or wave reaches the gap from across)."""
    rings = engine.free_rings
    if not rings:
        return
    for front in group:
        for ring in list(rings.by_face.get(front.id, ())):
            hand_back(engine, ring, t)
