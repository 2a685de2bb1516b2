"""The front-tracking event queue.

The scene's initial data is piecewise constant, so every layer boundary is a
Riemann problem at ``t = 0``.  The engine keeps the live fronts ordered in X
(a doubly linked list), computes when each pair of neighbours meets, and keeps
those meeting times in a heap with lazy invalidation (an entry is stale once
either front has died or the two are no longer neighbours).  It pops the
earliest event, gathers every front that passes through the same point at
that time (symmetric scenes make several meet on purpose), and replaces them
by the solution of one Riemann problem between the state left of the group and
the state right of it:

- at a boundary: the reflected wave from ``solve_boundary``;
- at an interface or entropy contact: ``solve_contact`` with the contact's
  tensile strength (0 if unbonded, the weaker spall strength if bonded); if
  the contact would go beyond it, it opens into a gap (two free surfaces);
- at an open gap: each surface reflects as a free surface; the gap closes
  (a new impact) when the Eulerian positions of its two surfaces meet;
- inside a material (collision, overtaking, ray crossings): ``solve_contact``
  with the material's spall strength; a tension beyond it fractures the
  material there (spall).  The two star states may differ in entropy; the
  difference is kept as a new contact unless it is negligible or neglected.

Outgoing fans are split into rays (``characteristics.rays``).  Waves weaker
than the negligible stress are dropped and their total is reported.
"""

from __future__ import annotations

import dataclasses
import heapq
import itertools
import math
import time

from characteristics.rays import discretise_fan, ray_count
from materials import LEFT, RIGHT, Fan, NoSolutionError, State, solve_boundary, solve_contact
from materials.riemann import STRENGTH_TOLERANCE

from .damage import run_with_damage
from .error_estimate import estimate_error
from .fronts import Front, Region, inside_fan
from .scene import Scene
from .solution import EventRecord, Solution, SpallRecord

NEGLIGIBLE_FRACTION = 1e-6
"""Default negligible wave: this fraction of the scene's stress scale.  Echoes in a
multi-layer stack multiply at every crossing of an interface; those weaker than
a millionth of the peak are dropped (their total is reported) unless the scene
asks for a smaller ``accuracy.negligible_stress``."""

NEGLIGIBLE_SPLIT_FRACTION = 1e-3
"""In a scene with elastic–plastic solids (``Material.splits_waves``) the default
negligible wave is at least this fraction of the stress scale: every interaction
there splits waves into elastic and plastic parts, so their number grows
geometrically with time, and the ones below a thousandth of the peak are dropped
(their total is reported)."""

NEGLIGIBLE_RAY_FRACTION = 1e-3
"""In a scene with fans the default negligible wave is at least this fraction of
the stress one ray carries: the fans resolve stress only to a ray step, and the
echoes a thousand times weaker (left by rays crossing shocks and contacts in a
ringing plate) would otherwise multiply the events without improving anything."""

ENTROPY_JUMP_TOLERANCE = 1e-12
"""Entropy contacts whose relative volume jump is below this are rounding, never tracked.
Larger ones are tracked unless they would reflect less than the negligible stress."""


SPALL_SPACING_FRACTION = 0.0
"""Default smallest distance between two spall planes, as a fraction of the thickness of
the layer they are in (see ``Engine._near_spall``)."""


class EventLimitError(RuntimeError):
    """The scene needed more events than ``accuracy.max_events`` allows."""


def initial_state(layer) -> State:
    """A layer's initial state: its stress reached along its wave curve, moving at ``velocity``."""
    if layer.initial is not None:
        return layer.initial
    material = layer.material
    reference = material.reference_state()
    if layer.stress != 0.0:
        reference = material.wave_curve(reference, RIGHT).state_at(layer.stress)
    return reference.moving(layer.velocity)


class Engine:
    """Evolves one scene; ``run()`` returns a ``Solution``."""

    def __init__(self, scene: Scene, progress=None, fractures=()):
        """``fractures``: ``(x, t)`` points (m, s) at which the material is made to
        fracture (the failures a cumulative-damage criterion found, ``fronttrack.damage``)."""
        self.scene = scene.validate()
        self.fractures = tuple(fractures)
        self.acc = scene.accuracy
        self.progress = progress
        self._ids = itertools.count()
        self._region_ids = itertools.count()
        self._wave_ids = itertools.count()
        self._seq = itertools.count()
        self._heap: list = []
        self.fronts: list[Front] = []
        self.regions: list[Region] = []
        self.events: list[EventRecord] = []
        self.spalls: list[SpallRecord] = []
        self.dropped_stress = 0.0
        self.dropped_count = 0
        self.neglected_entropy = 0.0
        self.neglected_contacts = 0
        self.unresolved_contacts = 0
        self.suppressed_spalls = 0
        self.suppressed_tension = 0.0
        self.min_stress: tuple[float, float, float] | None = None
        length = scene.length
        self.x_tol = 1e-10 * length
        self.t_end = scene.t_end
        self.initial_states: list[State] = []

    # --- set-up -------------------------------------------------------------
    def _new_front(self, kind: str, x0: float, t0: float, **kw) -> Front:
        front = Front(id=next(self._ids), kind=kind, x0=x0, t0=t0, **kw)
        self.fronts.append(front)
        return front

    def _new_region(self, state: State, material, layer: int, t: float,
                    left_point, right_point) -> Region:
        region = Region(id=next(self._region_ids), state=state, material=material, layer=layer,
                        t_start=t, left_points=[left_point], right_points=[right_point])
        self.regions.append(region)
        self._note_stress(region, left_point, right_point)
        return region

    def _note_stress(self, region: Region, left_point, right_point) -> None:
        """Keep the lowest stress (largest tension) and where and when it first appears:
        a later region within the rounding of a computed stress (1e-12 relative) of it,
        as the echoes of a held tension are, is the same tension, not a new maximum."""
        sigma = region.state.sigma
        if (self.min_stress is None
                or sigma < self.min_stress[0] - STRENGTH_TOLERANCE * abs(self.min_stress[0])):
            x = 0.5 * (left_point[0] + right_point[0])
            self.min_stress = (sigma, x, region.t_start)

    def _build(self) -> None:
        scene = self.scene
        states = [initial_state(layer) for layer in scene.layers]
        self.initial_states = states
        self.stress_scale = self._stress_scale(states)
        if self.acc.stress_tolerance is not None:
            self.ray_step = self.acc.stress_tolerance
        else:
            self.ray_step = self.stress_scale / self.acc.rays_per_fan
        self.negligible = self._default_negligible()
        left = self._new_front("boundary", 0.0, 0.0, side="left")
        fronts = [left]
        x = 0.0
        for i, layer in enumerate(scene.layers):
            x_next = x + layer.thickness
            region = self._new_region(states[i], layer.material, i, 0.0, (x, 0.0), (x_next, 0.0))
            fronts[-1].region_right = region
            if i + 1 < len(scene.layers):
                nxt = scene.layers[i + 1]
                bond = nxt.bond
                strength = 0.0 if bond == "unbonded" else min(
                    layer.material.spall_strength, nxt.material.spall_strength)
                fronts.append(self._new_front("interface", x_next, 0.0, bond=bond,
                                              strength=strength))
            x = x_next
        fronts.append(self._new_front("boundary", x, 0.0, side="right"))
        for a, b in zip(fronts[:-1], fronts[1:], strict=True):
            a.next, b.prev = b, a
        self.head = left
        for front in fronts:
            self._push_site(front, 0.0)
        for x, t in self.fractures:
            if t <= self.t_end:
                heapq.heappush(self._heap, (t, next(self._seq), "fracture", x, None))
        for boundary, spec in ((left, scene.left), (fronts[-1], scene.right)):
            boundary.boundary_steps = self._boundary_steps(spec, boundary)

    def _default_negligible(self) -> float:
        """The negligible wave (Pa): the scene's choice, else ``NEGLIGIBLE_FRACTION`` of
        the stress scale, raised to ``NEGLIGIBLE_RAY_FRACTION`` of a ray step when the
        scene can make fans (isentropic release of a material that makes them) and to
        ``NEGLIGIBLE_SPLIT_FRACTION`` of the scale when a solid splits waves."""
        if self.acc.negligible_stress is not None:
            return self.acc.negligible_stress
        negligible = NEGLIGIBLE_FRACTION * self.stress_scale
        fans = self.acc.release == "isentrope" and any(
            layer.material.makes_fans for layer in self.scene.layers)
        if fans:
            negligible = max(negligible, NEGLIGIBLE_RAY_FRACTION * self.ray_step)
        if any(layer.material.splits_waves for layer in self.scene.layers):
            negligible = max(negligible, NEGLIGIBLE_SPLIT_FRACTION * self.stress_scale)
        return negligible

    def _stress_scale(self, states: list[State]) -> float:
        """Largest stress the initial Riemann problems produce (Pa): scales rays and thresholds."""
        scene = self.scene
        scale = max(abs(s.sigma) for s in states)
        for i in range(len(states) - 1):
            a, b = scene.layers[i].material, scene.layers[i + 1].material
            if states[i].u != states[i + 1].u or states[i].sigma != states[i + 1].sigma:
                sol = solve_contact(a, states[i], b, states[i + 1], 0.0, self.acc.release)
                scale = max(scale, abs(sol.bonded_sigma))
        for spec, state, mat, side in ((scene.left, states[0], scene.layers[0].material, "left"),
                                       (scene.right, states[-1], scene.layers[-1].material,
                                        "right")):
            for _, value in spec.history:
                if spec.kind == "stress":
                    scale = max(scale, abs(value))
                elif spec.kind == "velocity":
                    sol = solve_boundary(mat, state, side, velocity=value,
                                         release=self.acc.release)
                    scale = max(scale, abs(sol.bonded_sigma))
        if scale == 0.0:
            scale = max(layer.material.rho0 * layer.material.sound_speed(s.v, s.e) * 1.0
                        for layer, s in zip(scene.layers, states, strict=True))
        return scale

    def _boundary_steps(self, spec, boundary: Front) -> list[tuple[float, float]]:
        """Times (s) and values at which a prescribed history changes the boundary value.

        Ramps are replaced by steps at sub-intervals small enough that each step
        carries at most one ray's stress; the value of each step is the
        history's value at the middle of its sub-interval (second order).
        """
        if spec.kind not in ("velocity", "stress") or len(spec.history) < 2:
            return []
        side = boundary.side
        layer = self.scene.layers[0] if side == "left" else self.scene.layers[-1]
        impedance = layer.material.rho0 * layer.material.sound_speed(layer.material.v0, 0.0)
        steps = []
        for (t0, y0), (t1, y1) in zip(spec.history[:-1], spec.history[1:], strict=True):
            if t1 == t0:  # a step
                steps.append((t1, y1))
                continue
            jump = abs(y1 - y0) * (impedance if spec.kind == "velocity" else 1.0)
            count = max(1, math.ceil(jump / self.ray_step)) if jump > 0 else 0
            for k in range(count):
                ta = t0 + (t1 - t0) * k / count
                tb = t0 + (t1 - t0) * (k + 1) / count
                steps.append((ta if k else max(ta, 0.0), spec.value_at(0.5 * (ta + tb))))
            if count:
                steps.append((t1, y1))
        # the value before the first step is value_at(0); drop steps with no change
        result, last = [], spec.value_at(0.0)
        for t, value in steps:
            if value != last and t <= self.t_end:
                result.append((t, value))
                last = value
        return result

    # --- queue --------------------------------------------------------------
    def _push_site(self, front: Front, t: float) -> None:
        if t <= self.t_end:
            heapq.heappush(self._heap, (t, next(self._seq), "site", front, front.gap_version))

    def _push_pair(self, a: Front, b: Front, now: float) -> None:
        closing = a.speed - b.speed
        if closing <= 0.0:
            return
        gap = b.position(now) - a.position(now)
        t = now + max(gap, 0.0) / closing
        if t <= self.t_end:
            heapq.heappush(self._heap, (t, next(self._seq), "pair", a, b))

    def _push_gap_closure(self, gap: Front) -> None:
        left, right = gap.prev.region_right.state.u, gap.region_right.state.u
        gap.gap_version += 1
        if left > right:
            t = gap.gap_time + gap.gap_width / (left - right)
            self._push_site(gap, t)

    # --- main loop ----------------------------------------------------------
    def run(self) -> Solution:
        start = time.perf_counter()
        self._build()
        count = 0
        while self._heap:
            entry = heapq.heappop(self._heap)
            t = entry[0]
            if entry[2] == "fracture":
                self._fracture(entry[3], t)
                continue
            if entry[2] == "pair":
                a, b = entry[3], entry[4]
                if not (a.alive and b.alive and a.next is b):
                    continue
                x = self._meeting_point(a, b, t)
                seed = [a, b]
            else:
                front, version = entry[3], entry[4]
                if not front.alive or version != front.gap_version:
                    continue
                x = front.x0
                seed = [front]
            count += 1
            if count > self.acc.max_events:
                raise EventLimitError(
                    f"accuracy.max_events: the scene needed more than {self.acc.max_events} "
                    f"events before t = {t * 1e6:.6g} us (t_end = {self.t_end * 1e6:.6g} us); "
                    f"raise max_events, shorten t_end or coarsen the fans (rays_per_fan)")
            self._process(seed, t, x, timer=entry[2] == "site")
            if self.progress is not None and count % 1000 == 0:
                self.progress(count, t)
        self._finish()
        elapsed = time.perf_counter() - start
        return Solution.from_engine(self, elapsed)

    def _meeting_point(self, a: Front, b: Front, t: float) -> float:
        if a.speed == 0.0:
            return a.x0
        if b.speed == 0.0:
            return b.x0
        return 0.5 * (a.position(t) + b.position(t))

    def _gather(self, seed: list[Front], t: float, x: float) -> list[Front]:
        """All consecutive fronts through ``(x, t)``, at most one site among them."""
        group = list(seed)
        sites = sum(f.is_site for f in group)
        while True:
            p = group[0].prev
            if p is None or abs(p.position(t) - x) > self.x_tol or (p.is_site and sites):
                break
            group.insert(0, p)
            sites += p.is_site
        while True:
            n = group[-1].next
            if n is None or abs(n.position(t) - x) > self.x_tol or (n.is_site and sites):
                break
            group.append(n)
            sites += n.is_site
        return group

    # --- one event ------------------------------------------------------------
    def _process(self, seed: list[Front], t: float, x: float, timer: bool) -> None:
        group = self._gather(seed, t, x)
        sites = [f for f in group if f.is_site]
        site = sites[0] if sites else None
        before = group[0].prev
        region_left = before.region_right if before is not None else None
        region_right = group[-1].region_right
        incoming = [f for f in group if not f.is_site]
        if site is not None and site.kind == "gap":
            # the faces moved with the states next to them since the last update
            opening = site.region_right.state.u - site.prev.region_right.state.u
            site.gap_width += opening * (t - site.gap_time)
            site.gap_time = t
        kind, solution, new_site = self._solve(site, region_left, region_right, t, x, incoming,
                                               timer)
        if site is None and new_site is None and not incoming:
            return
        self._replace(group, site, new_site, solution, region_left, region_right, t, x,
                      incoming, kind)

    def _contact_strength(self, site: Front | None, material) -> float:
        """Tension (Pa) the material or contact at an event can carry.

        Under a cumulative-damage criterion the material itself never fails
        instantly.  An unbonded contact carries tension up to the negligible
        stress: a rounding-level tension (a free-surface state is zero only to a
        few ulps of the stresses that made it) must not open a gap.
        """
        if site is None or site.kind == "contact":
            strength = (material.spall_strength if self.scene.spall_criterion is None
                        else math.inf)
        else:
            strength = site.strength
        return max(strength, self.negligible)

    def _fracture(self, x: float, t: float) -> None:
        """Fracture the material at ``(x, t)``: two free surfaces, an opening gap.

        The region there is cut in two at ``x`` and the two halves become the faces
        of a new gap; each face then reflects as a free surface.  A point on a
        front, or not in tension, is left alone (the failure found by the damage
        integration is always inside a tensile region).
        """
        before = self.head
        while before.next is not None and before.next.position(t) <= x:
            before = before.next
        after, region = before.next, before.region_right
        if (after is None or region is None or region.state.sigma >= 0.0
                or x - before.position(t) <= self.x_tol or after.position(t) - x <= self.x_tol):
            return
        x_left, x_right = before.position(t), after.position(t)
        region.left_points.append((x_left, t))
        region.right_points.append((x_right, t))
        region.t_end = t
        left = self._new_region(region.state, region.material, region.layer, t, (x_left, t),
                                (x, t))
        right = self._new_region(region.state, region.material, region.layer, t, (x, t),
                                 (x_right, t))
        gap = self._new_front("gap", x, t, bond="unbonded")
        gap.gap_time, gap.region_right = t, right
        before.earlier_regions.append((t, region.id))
        before.region_right = left
        before.next, gap.prev, gap.next, after.prev = gap, before, after, gap
        self.spalls.append(SpallRecord(x=x, t=t, tension=-region.state.sigma,
                                       strength=self.scene.spall_criterion.threshold))
        material, state = region.material, region.state
        sol = _combine(solve_boundary(material, state, "right", stress=0.0,
                                      release=self.acc.release),
                       solve_boundary(material, state, "left", stress=0.0,
                                      release=self.acc.release))
        self._replace([gap], gap, None, sol, left, right, t, x, [], "spall")

    def _solve(self, site, region_left, region_right, t, x, incoming, timer):
        """Riemann problem at the event; returns ``(kind, solution, new_site)``."""
        release = self.acc.release
        if site is not None and site.kind == "boundary":
            spec = self.scene.left if site.side == "left" else self.scene.right
            region = region_right if site.side == "left" else region_left
            value = self._boundary_value(site, spec, t)
            if timer:
                self._schedule_next_step(site, t)
            if spec.kind in ("free", "stress"):
                sol = solve_boundary(region.material, region.state, site.side, stress=value,
                                     release=release)
            else:
                sol = solve_boundary(region.material, region.state, site.side, velocity=value,
                                     release=release)
            return ("reflection" if incoming else "boundary"), sol, None
        if site is not None and site.kind == "gap":
            if timer:  # the closure (any wave arriving at that instant joins the impact)
                site.kind = "interface"
                site.bond = "unbonded"
                site.strength = 0.0
                site.gap_version += 1
                self._log_site_kind(site, t)
                sol = solve_contact(region_left.material, region_left.state,
                                    region_right.material, region_right.state,
                                    self._contact_strength(site, None), release)
                return "gap-close", sol, None
            left = solve_boundary(region_left.material, region_left.state, "right", stress=0.0,
                                  release=release)
            right = solve_boundary(region_right.material, region_right.state, "left",
                                   stress=0.0, release=release)
            return "reflection", _combine(left, right), None
        strength = self._contact_strength(site, region_left.material)
        sol = solve_contact(region_left.material, region_left.state, region_right.material,
                            region_right.state, strength, release)
        if site is None:
            kind = _interaction_kind(incoming)
        elif not incoming:
            kind = "impact"
        else:
            kind = "transmission"
        new_site = None
        if (sol.separated and (site is None or site.kind == "contact")
                and self._near_spall(x, region_left.layer)):
            # inside the zone of an earlier fracture: carried as tension, and reported,
            # unless the tension would leave the equations of state (then it fractures)
            try:
                carried = solve_contact(region_left.material, region_left.state,
                                        region_right.material, region_right.state, math.inf,
                                        release)
            except NoSolutionError:
                carried = None
            if carried is not None:
                self.suppressed_spalls += 1
                self.suppressed_tension = max(self.suppressed_tension, -sol.bonded_sigma)
                sol = carried
        if sol.separated:
            if site is None or site.kind == "contact":
                kind = "spall"
                self.spalls.append(SpallRecord(x=x, t=t, tension=-sol.bonded_sigma,
                                               strength=strength))
            else:
                kind = "gap-open"
            if site is None:
                new_site = self._new_front("gap", x, t, bond="unbonded")
                new_site.gap_time = t
            else:
                site.kind = "gap"
                site.gap_width, site.gap_time = 0.0, t
                self._log_site_kind(site, t)
        return kind, sol, new_site

    def _near_spall(self, x: float, layer: int) -> bool:
        """True if ``x`` (m) is within the spall spacing of an earlier fracture.

        With an instantaneous threshold, the level set of the spall strength leaves
        the first fracture point faster than sound (it is tangent to the time axis
        there), so the model fractures a whole zone into ever thinner plates, each
        ringing on its own.  Fractures closer than the spacing to an earlier one are
        suppressed (the tension is carried and the count reported).
        """
        spacing = self.spall_spacing(layer)
        return spacing > 0.0 and any(abs(x - s.x) < spacing for s in self.spalls)

    def spall_spacing(self, layer: int) -> float:
        """Smallest distance (m) between spall planes in ``layer``: the scene's
        ``accuracy.spall_spacing``, or ``SPALL_SPACING_FRACTION`` of the layer thickness."""
        if self.acc.spall_spacing is not None:
            return self.acc.spall_spacing
        return SPALL_SPACING_FRACTION * self.scene.layers[layer].thickness

    def _log_site_kind(self, site: Front, t: float) -> None:
        site.history.append((t, site.kind))

    def _boundary_value(self, site: Front, spec, t: float) -> float:
        """Prescribed stress (Pa) or velocity (m/s) of a boundary at time ``t`` (s)."""
        if spec.kind in ("free", "wall"):
            return 0.0
        value = spec.value_at(0.0)
        for step_time, step_value in site.boundary_steps:
            if step_time <= t * (1.0 + 1e-15):
                value = step_value
        return value

    def _schedule_next_step(self, site: Front, t: float) -> None:
        """Queue the boundary's first prescribed step after ``t`` (its timer event)."""
        later = (step_time for step_time, _ in site.boundary_steps
                 if step_time > t * (1.0 + 1e-15))
        step_time = next(later, None)
        if step_time is not None:
            self._push_site(site, step_time)

    # --- rebuilding the front list ----------------------------------------------
    def _wave_fronts(self, waves, material, t, x, incoming, direction):
        """Front specs (front, state behind it on the contact side) for one family of waves."""
        specs = []
        if not waves:
            return specs
        ahead = waves[0].ahead
        behind = waves[-1].behind
        if abs(behind.sigma - ahead.sigma) <= self.negligible:
            self.dropped_stress += abs(behind.sigma - ahead.sigma)
            self.dropped_count += 1
            return None
        parent = next((f for f in incoming if f.direction == direction), None)
        for wave in waves:
            if isinstance(wave, Fan):
                rays = discretise_fan(wave, material, ray_count(wave, self.ray_step))
                if len(rays) == 1 and parent is not None and parent.kind == "ray":
                    fan, index, count = parent.fan, parent.ray_index, parent.ray_count
                else:
                    fan, index, count = next(self._wave_ids), None, len(rays)
                for ray in rays:
                    front = self._new_front("ray", x, t, speed=ray.speed, fan=fan,
                                            ray_index=ray.index if index is None else index,
                                            ray_count=count, direction=direction,
                                            jump=ray.behind.sigma - ray.ahead.sigma)
                    specs.append((front, ray.ahead, ray.behind))
            else:
                wave_id = (parent.wave if parent is not None and parent.kind == "shock"
                           else next(self._wave_ids))
                front = self._new_front("shock", x, t, speed=wave.speed, wave=wave_id,
                                        direction=direction,
                                        jump=wave.behind.sigma - wave.ahead.sigma)
                specs.append((front, wave.ahead, wave.behind))
        return specs

    def _replace(self, group, site, new_site, sol, region_left, region_right, t, x, incoming,
                 kind):
        material_left = region_left.material if region_left is not None else None
        material_right = region_right.material if region_right is not None else None
        left_specs = self._wave_fronts(sol.left_waves, material_left, t, x, incoming, LEFT)
        right_specs = self._wave_fronts(sol.right_waves, material_right, t, x, incoming, RIGHT)
        left_star = sol.left_star if left_specs is not None else (
            region_left.state if region_left is not None else None)
        right_star = sol.right_star if right_specs is not None else (
            region_right.state if region_right is not None else None)
        left_specs = left_specs or []
        right_specs = right_specs or []
        middle = site if site is not None else new_site
        if middle is None and left_star is not None and right_star is not None:
            middle = self._entropy_contact(left_star, right_star, material_left, t, x,
                                           group)
            if middle is None:
                left_star = right_star = _merged(left_star, right_star)
        # Fronts left to right, each with the state on its right.
        items, right_of = [], []
        for k, (front, _, behind) in enumerate(left_specs):
            items.append(front)
            right_of.append(left_star if k == len(left_specs) - 1 else behind)
        if middle is not None:
            items.append(middle)
            right_of.append(right_star)
        for front, ahead, _ in reversed(right_specs):
            items.append(front)
            right_of.append(ahead)
        between = right_of[:-1]
        self._splice(group, items, between, region_left, region_right, t, x, middle)
        if middle is not None and middle.kind == "gap":
            self._push_gap_closure(middle)
        self.events.append(EventRecord(
            t=t, x=x, kind=kind, incoming=[f.id for f in incoming],
            outgoing=[f.id for f in items if not f.is_site],
            site=middle.id if middle is not None else None))

    def _entropy_contact(self, left: State, right: State, material, t: float,
                         x: float, group) -> Front | None:
        """A contact for the entropy jump between two star states, if it matters.

        A contact that would reflect less than the negligible stress from the
        scene's largest wave (``Material.contact_reflection``: the impedance jump,
        and for an elastic–plastic solid the offset of the yield stresses) is not
        tracked (every later crossing would be an event for nothing): the two
        states are merged and the largest relative volume jump so neglected is
        reported.  Jumps below ``ENTROPY_JUMP_TOLERANCE`` are rounding.  So is, when
        the scene sets ``accuracy.contact_resolution``, a contact born closer than that
        to the neighbouring contact (elastic–plastic spall zones otherwise build combs of
        contacts nanometres apart that every later wave must cross); those are counted.
        """
        jump = abs(left.v - right.v) / max(left.v, right.v)
        keep = self.acc.entropy_contacts and jump > ENTROPY_JUMP_TOLERANCE
        if keep and self.negligible > 0.0 and math.isfinite(left.v + right.v):
            keep = material.contact_reflection(left, right, self.stress_scale) > self.negligible
        if keep and self._contact_within(group, x, self.acc.contact_resolution):
            keep = False
            self.unresolved_contacts += 1
        if keep:
            return self._new_front("contact", x, t, bond="bonded")
        self.neglected_entropy = max(self.neglected_entropy, jump)
        self.neglected_contacts += jump > ENTROPY_JUMP_TOLERANCE
        return None

    @staticmethod
    def _contact_within(group, x: float, distance: float) -> bool:
        """True if the nearest site on either side of ``group`` is an entropy contact
        closer than ``distance`` (m) to ``x``."""
        if distance <= 0.0:
            return False
        for front, step in ((group[0].prev, "prev"), (group[-1].next, "next")):
            while front is not None and not front.is_site:
                front = getattr(front, step)
            if front is not None and front.kind == "contact" and abs(front.x0 - x) < distance:
                return True
        return False

    def _splice(self, group, items, between, region_left, region_right, t, x, middle):
        """Kill ``group`` (except a continuing site), link ``items`` and make their regions."""
        before, after = group[0].prev, group[-1].next
        point = (x, t)
        for front in group:
            if front is middle:
                continue
            front.alive = False
            front.t1, front.x1 = t, x
            front.right_region_id = front.region_right.id if front.region_right else None
        for front in group[:-1]:
            region = front.region_right
            if region is not None and region.t_end is None:
                region.left_points.append(point)
                region.right_points.append(point)
                region.t_end = t
        if not items:
            self._merge(before, after, region_left, region_right, t, x)
            return
        if region_left is not None:
            region_left.right_points.append(point)
        if region_right is not None:
            region_right.left_points.append(point)
        chain = ([before] if before is not None else []) + items + (
            [after] if after is not None else [])
        for a, b in zip(chain[:-1], chain[1:], strict=True):
            a.next, b.prev = b, a
        if before is None:
            self.head = items[0]
        layer_left = region_left.layer if region_left is not None else region_right.layer
        layer_right = region_right.layer if region_right is not None else layer_left
        continuing = middle.region_right if middle is not None else None
        for k, front in enumerate(items):
            front.left_region = (items[k - 1].region_right.id if k > 0 else
                                 (region_left.id if region_left is not None else None))
            if k + 1 < len(items):
                state = between[k]
                on_right = middle is not None and items.index(middle) <= k
                material = region_right.material if on_right else region_left.material
                layer = layer_right if on_right else layer_left
                region = self._new_region(state, material, layer, t, point, point)
                region.in_fan = inside_fan(front, items[k + 1])
                front.region_right = region
            else:
                front.region_right = region_right
        if continuing is not None and middle.region_right is not continuing:
            middle.earlier_regions.append((t, continuing.id))
        for a, b in zip(chain[:-1], chain[1:], strict=True):
            self._push_pair(a, b, t)

    def _merge(self, before, after, region_left, region_right, t, x):
        """No front leaves the event: the two neighbouring regions become one."""
        x_left = before.position(t)
        x_right = after.position(t)
        for region, top in ((region_left, (x_left, t)), (region_right, (x_right, t))):
            region.right_points.append((x, t) if region is region_left else (x_right, t))
            region.left_points.append(top if region is region_left else (x, t))
            region.t_end = t
        state = _merged(region_left.state, region_right.state)
        merged = self._new_region(state, region_left.material, region_left.layer, t,
                                  (x_left, t), (x_right, t))
        merged.in_fan = inside_fan(before, after)
        before.next, after.prev = after, before
        before.earlier_regions.append((t, region_left.id))
        before.region_right = merged
        self._push_pair(before, after, t)

    def _finish(self) -> None:
        t = self.t_end
        front = self.head
        while front is not None:
            if front.alive:
                front.t1, front.x1 = t, front.position(t)
                front.right_region_id = front.region_right.id if front.region_right else None
            region = front.region_right
            if region is not None and region.t_end is None:
                region.left_points.append((front.position(t), t))
                region.right_points.append((front.next.position(t), t))
                region.t_end = t
            front = front.next


def _combine(left_solution, right_solution):
    """Two independent free-surface reflections on either side of an open gap."""
    from materials import RiemannSolution

    return RiemannSolution(left_waves=left_solution.left_waves,
                           right_waves=right_solution.right_waves,
                           left_star=left_solution.left_star,
                           right_star=right_solution.right_star, separated=True,
                           bonded_sigma=0.0)



def _merged(a: State, b: State) -> State:
    """One state standing for two that differ negligibly (mean of each numeric field;
    ``a``'s type is kept, so a model's extra state fields survive)."""
    shared = {f.name for f in dataclasses.fields(b)}
    means = {f.name: 0.5 * (getattr(a, f.name) + getattr(b, f.name))
             for f in dataclasses.fields(a) if f.name in shared}
    return dataclasses.replace(a, **means)


def _interaction_kind(incoming) -> str:
    directions = {f.direction for f in incoming}
    return "collision" if directions == {LEFT, RIGHT} else "overtake"


def run(scene: Scene, progress=None) -> Solution:
    """Evolve ``scene`` to ``scene.t_end`` and return its ``Solution``.

    With ``accuracy.estimate_error`` and fans present, the scene is run again at
    half the ray step and the estimate is added to ``accuracy_report``.
    """
    if scene.spall_criterion is not None:
        solution = run_with_damage(scene, Engine, progress)
    else:
        solution = Engine(scene, progress).run()
    if scene.accuracy.estimate_error:
        estimate = (estimate_error(solution, run) if solution.stats["rays"] > 0
                    else {"method": "exact: no fans in this solution", "sigma": 0.0, "u": 0.0})
        solution.accuracy_report["error_estimate"] = estimate
    return solution
