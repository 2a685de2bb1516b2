"""The solution of a scene: fronts, regions, events, and the queries on them.

Everything a user asks for is a query on the exact piecewise-constant
solution: the state at ``(X, t)``, the history at a Lagrangian station (a step
function with exact step times), a profile at an instant, the Eulerian
position ``x(X, t) = x(X, 0) + int u dt``, free-surface velocities, the largest
tension, the spall events, and the conservation balance

    d/dt int rho0 u dX           = sigma(left) - sigma(right),
    d/dt int rho0 (e + u^2/2) dX = (sigma u)(left) - (sigma u)(right),

(stress positive in compression), integrated exactly over the boundary
histories.  Units are SI throughout.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from materials import State


@dataclass(frozen=True)
class EventRecord:
    """One interaction: time (s), position (m), kind, ids of the fronts in and out."""

    t: float
    x: float
    kind: str
    incoming: list
    outgoing: list
    site: int | None = None


@dataclass(frozen=True)
class SpallRecord:
    """A fracture: position ``x`` (m), time ``t`` (s), the tension the bonded problem
    would have reached (Pa, positive) and the strength that failed (Pa)."""

    x: float
    t: float
    tension: float
    strength: float


class StateSeries:
    """Arrays of the fields of a sequence of states (``self.states``)."""

    states: tuple | list

    @property
    def sigma(self) -> np.ndarray:
        """Stress (Pa, compression positive) of each state."""
        return np.array([s.sigma for s in self.states])

    @property
    def u(self) -> np.ndarray:
        """Particle velocity (m/s) of each state."""
        return np.array([s.u for s in self.states])

    @property
    def rho(self) -> np.ndarray:
        """Density (kg/m³); zero for a gas expanded into vacuum (infinite volume)."""
        return np.array([1.0 / s.v for s in self.states])


@dataclass(frozen=True)
class History(StateSeries):
    """A step-function record at one station: ``values[k]`` holds on ``[t[k], t[k+1])``."""

    t: np.ndarray
    states: list

    def integral(self, values: np.ndarray, t_end: float) -> float:
        """Exact integral of a step quantity from 0 to ``t_end`` (s)."""
        edges = np.append(self.t, t_end)
        widths = np.clip(np.minimum(edges[1:], t_end) - edges[:-1], 0.0, None)
        return float(np.dot(values, widths))


@dataclass
class Solution:
    """The exact front-tracking solution of one scene."""

    scene: object
    fronts: list
    regions: list
    events: list
    spalls: list
    stats: dict
    accuracy_report: dict
    min_stress: tuple | None
    initial_states: list
    _arrays: dict = field(default_factory=dict, repr=False)

    @classmethod
    def from_engine(cls, engine, elapsed: float) -> Solution:
        fronts = engine.fronts
        stats = {
            "events": len(engine.events),
            "fronts": len(fronts),
            "regions": len(engine.regions),
            "rays": sum(f.kind == "ray" for f in fronts),
            "shocks": sum(f.kind == "shock" for f in fronts),
            "contacts": sum(f.kind == "contact" for f in fronts),
            "solve_time": elapsed,
        }
        report = {
            "release": engine.acc.release,
            "entropy_contacts": engine.acc.entropy_contacts,
            "ray_stress_step": engine.ray_step,
            "stress_scale": engine.stress_scale,
            "negligible_stress": engine.negligible,
            "dropped_waves": engine.dropped_count,
            "dropped_stress_total": engine.dropped_stress,
            "neglected_entropy_volume_jump": engine.neglected_entropy,
            "neglected_entropy_contacts": engine.neglected_contacts,
            "contact_resolution": engine.acc.contact_resolution,
            "contacts_below_resolution": engine.unresolved_contacts,
            "spall_spacing": [engine.spall_spacing(i) for i in range(len(engine.scene.layers))],
            "suppressed_spalls": engine.suppressed_spalls,
            "largest_suppressed_tension": engine.suppressed_tension,
        }
        return cls(scene=engine.scene, fronts=fronts, regions=engine.regions,
                   events=engine.events, spalls=engine.spalls, stats=stats,
                   accuracy_report=report, min_stress=engine.min_stress,
                   initial_states=engine.initial_states)

    # --- geometry -----------------------------------------------------------
    def _front_arrays(self):
        """Front segments as arrays: one segment per front and per region on its right."""
        if not self._arrays:
            x0, t0, t1, speed, right = [], [], [], [], []
            for f in self.fronts:
                if f.t1 is None or f.t1 < f.t0:
                    continue
                start = f.t0
                pieces = [*f.earlier_regions, (f.t1, f.right_region_id)]
                for end, region in pieces:
                    x0.append(f.position(start))
                    t0.append(start)
                    t1.append(end)
                    speed.append(f.speed)
                    right.append(-1 if region is None else region)
                    start = end
            self._arrays = {"x0": np.array(x0), "t0": np.array(t0), "t1": np.array(t1),
                            "speed": np.array(speed), "right": np.array(right)}
            self._region_by_id = {r.id: r for r in self.regions}
        return self._arrays

    def _spatial_order(self, index: np.ndarray, pos: np.ndarray, t: float) -> np.ndarray:
        """Order (left to right at time ``t``) of the front segments ``index``.

        Fronts at one point meet at an event there.  Those born at it are ordered as an
        instant later (fastest rightmost); those about to arrive, when ``t`` is within
        rounding of the event but before it, as an instant earlier (slowest rightmost).
        Each front counts as the one its age or its remaining life says it is closer to.
        Last key: the latest-born.
        """
        a = self._front_arrays()
        speed, t0, t1 = a["speed"][index], a["t0"][index], a["t1"][index]
        arriving = (t1 - t) < (t - t0)
        return np.lexsort((t0, np.where(arriving, -speed, speed), pos[index]))

    def region_at(self, x: float, t: float):
        """The region containing Lagrangian position ``x`` (m) at time ``t`` (s).

        On a front the region to its right is returned (to its left at the right end).
        """
        a = self._front_arrays()
        t = min(max(t, 0.0), self.scene.t_end)
        live = (a["t0"] <= t) & ((a["t1"] > t) | (a["t1"] >= self.scene.t_end))
        pos = a["x0"] + a["speed"] * (t - a["t0"])
        pos = np.where(a["speed"] == 0.0, a["x0"], pos)
        candidates = np.nonzero(live & (pos <= x) & (a["right"] >= 0))[0]
        if candidates.size == 0:
            candidates = np.nonzero(live & (a["right"] >= 0))[0]
            best = candidates[np.argmin(pos[candidates])]
        else:
            # rightmost front at or left of x, ties at one point ordered as below
            best = candidates[self._spatial_order(candidates, pos, t)[-1]]
        return self._region_by_id[int(a["right"][best])]

    def state_at(self, x: float, t: float) -> State:
        """State (stress Pa, velocity m/s, volume, energy) at ``(x, t)``."""
        return self.region_at(x, t).state

    def crossing_times(self, x: float) -> np.ndarray:
        """Times (s) at which a moving front passes the station ``x`` (m)."""
        a = self._front_arrays()
        moving = a["speed"] != 0.0
        with np.errstate(divide="ignore", invalid="ignore"):
            tc = a["t0"] + (x - a["x0"]) / np.where(moving, a["speed"], 1.0)
        ok = moving & (tc >= a["t0"] - 1e-18) & (tc <= a["t1"] + 1e-18)
        ok &= tc < self.scene.t_end
        return np.unique(tc[ok])

    def station(self, at) -> float:
        """Lagrangian position (m) of a probe location: ``"left"``, ``"right"``, metres,
        or the name of one of the scene's probes."""
        if at == "left":
            return 0.0
        if at == "right":
            return self.scene.length
        probe = next((p for p in self.scene.probes if isinstance(at, str) and p.name == at), None)
        if probe is not None:
            return self.station(probe.at)
        return min(max(float(at), 0.0), self.scene.length)

    def history(self, at) -> History:
        """Step-function history at a station: ``at`` is ``"left"``, ``"right"`` or X (m)."""
        x = self.station(at)
        resolution = 1e-12 * self.scene.t_end
        times = []
        for t in self.crossing_times(x):
            if t > resolution and (not times or t - times[-1] > resolution):
                times.append(float(t))
        edges = [0.0, *times, self.scene.t_end]
        starts, states = [], []
        for t0, t1 in zip(edges[:-1], edges[1:], strict=True):
            if t1 <= t0:
                continue
            state = self.state_at(x, 0.5 * (t0 + t1))
            if states and state == states[-1]:
                continue
            starts.append(t0)
            states.append(state)
        return History(t=np.array(starts), states=states)

    def probe_histories(self) -> dict:
        """Histories at every probe of the scene, by probe name."""
        return {p.name: self.history(p.at) for p in self.scene.probes}

    def profile(self, t: float) -> list[tuple[float, float, object]]:
        """``(x_left, x_right, region)`` intervals covering the stack at time ``t`` (s)."""
        a = self._front_arrays()
        t = min(max(t, 0.0), self.scene.t_end)
        live = (a["t0"] <= t) & ((a["t1"] > t) | (a["t1"] >= self.scene.t_end))
        pos = np.where(a["speed"] == 0.0, a["x0"], a["x0"] + a["speed"] * (t - a["t0"]))
        index = np.nonzero(live)[0]
        order = index[self._spatial_order(index, pos, t)]
        intervals = []
        for i, j in zip(order[:-1], order[1:], strict=True):
            if a["right"][i] >= 0 and pos[j] > pos[i]:
                intervals.append((float(pos[i]), float(pos[j]),
                                  self._region_by_id[int(a["right"][i])]))
        return intervals

    # --- derived quantities ---------------------------------------------------
    def eulerian_position(self, at, t: float) -> float:
        """Eulerian position (m) at time ``t`` of the material point at station ``at``.

        ``x(X, t) = x(X, 0) + int_0^t u dt``, with ``x(X, 0) = int_0^X v/v0 dX`` so
        that a pre-stressed layer starts compressed.
        """
        x = self.station(at)
        hist = self.history(at)
        return self.initial_eulerian(x) + hist.integral(hist.u, t)

    def initial_eulerian(self, x: float) -> float:
        """Eulerian position (m) at ``t = 0`` of the Lagrangian point ``x`` (m)."""
        total = 0.0
        for x0, x1, region in self.profile(0.0):
            if x0 >= x:
                break
            total += (min(x1, x) - x0) * region.state.v / region.material.v0
        return total

    def max_tension(self) -> dict | None:
        """Largest tension reached in any region: ``{"sigma", "x", "t"}`` (Pa, m, s).

        ``None`` when no region is in tension beyond the negligible stress (a
        rounding-level tension of a few ulps is not a tension).
        """
        negligible = self.accuracy_report.get("negligible_stress", 0.0)
        if self.min_stress is None or self.min_stress[0] >= -negligible:
            return None
        sigma, x, t = self.min_stress
        return {"sigma": sigma, "x": x, "t": t}

    def conservation(self, t: float | None = None) -> dict:
        """Momentum and energy balance at time ``t`` (default ``t_end``), per unit area.

        Returns the totals at 0 and ``t``, the boundary impulse and work, and the
        residuals ``momentum_error`` and ``energy_error`` (absolute) with their
        relative sizes against the largest momentum/energy scale.
        """
        t = self.scene.t_end if t is None else t

        def totals(pieces):
            p = e = 0.0
            for mass, s in pieces:
                p += mass * s.u
                e += mass * (s.e + 0.5 * s.u * s.u)
            return p, e

        p0, e0 = totals((layer.material.rho0 * layer.thickness, state)
                        for layer, state in zip(self.scene.layers, self.initial_states,
                                                strict=True))
        p1, e1 = totals((r.material.rho0 * (x1 - x0), r.state) for x0, x1, r in self.profile(t))
        left, right = self.history("left"), self.history("right")
        impulse = left.integral(left.sigma, t) - right.integral(right.sigma, t)
        work = (left.integral(left.sigma * left.u, t)
                - right.integral(right.sigma * right.u, t))
        kinetic_scale = max(abs(p0), abs(p1), abs(impulse), 1e-300)
        energy_scale = max(abs(e0), abs(e1), abs(work), 1e-300)
        return {
            "t": t,
            "momentum": (p0, p1), "impulse": impulse,
            "momentum_error": p1 - p0 - impulse,
            "momentum_relative_error": abs(p1 - p0 - impulse) / kinetic_scale,
            "energy": (e0, e1), "work": work,
            "energy_error": e1 - e0 - work,
            "energy_relative_error": abs(e1 - e0 - work) / energy_scale,
            "mass": sum(r.material.rho0 * (x1 - x0) for x0, x1, r in self.profile(t)),
        }

    # --- export -------------------------------------------------------------
    def to_dict(self, probes: bool = True) -> dict:
        """A JSON-ready document of the solution (SI units)."""
        regions = []
        for r in self.regions:
            s = r.state
            temperature = r.material.temperature(s.v, s.e) if math.isfinite(s.v) else None
            regions.append({
                "id": r.id, "layer": r.layer, "material": r.material.name,
                "sigma": s.sigma, "u": s.u, "v": _finite_or_none(s.v),
                "rho": 1.0 / s.v if s.v > 0 else None, "e": s.e,
                "plastic_strain": s.plastic_strain,
                "temperature": temperature, "t_start": r.t_start, "t_end": r.t_end,
                "in_fan": r.in_fan, "polygon": [list(p) for p in r.polygon()],
            })
        fronts = [{
            "id": f.id, "kind": f.kind, "x0": f.x0, "t0": f.t0, "x1": f.x1, "t1": f.t1,
            "speed": f.speed, "direction": f.direction, "jump": f.jump, "wave": f.wave,
            "fan": f.fan, "ray_index": f.ray_index, "ray_count": f.ray_count,
            "bond": f.bond or None, "left_region": f.left_region,
            "right_region": f.right_region_id, "kind_history": f.history,
            "earlier_right_regions": f.earlier_regions,
        } for f in self.fronts]
        events = [{"t": e.t, "x": e.x, "kind": e.kind, "incoming": e.incoming,
                   "outgoing": e.outgoing, "site": e.site} for e in self.events]
        doc = {
            "title": self.scene.title,
            "t_end": self.scene.t_end,
            "regions": regions,
            "fronts": fronts,
            "events": events,
            "spall": [{"X": s.x, "t": s.t, "tension": s.tension, "strength": s.strength}
                      for s in self.spalls],
            "max_tension": self.max_tension(),
            "stats": self.stats,
            "accuracy": self.accuracy_report,
        }
        if probes:
            doc["probes"] = {
                name: {"at": _probe_at(p), "t": h.t.tolist(), "sigma": h.sigma.tolist(),
                       "u": h.u.tolist()}
                for (name, h), p in zip(self.probe_histories().items(), self.scene.probes,
                                        strict=True)
            }
        return doc


def _finite_or_none(value: float):
    return value if math.isfinite(value) else None


def _probe_at(probe):
    return probe.at if isinstance(probe.at, str) else float(probe.at)
