"""Cumulative-damage spall: Tuler–Butcher and incubation-time criteria.

An instantaneous threshold fractures a point the moment its tension ``T = -sigma``
reaches the spall strength.  Real spall takes time: Tuler and Butcher (Int. J.
Fract. Mech. 4, 431, 1968) fracture a point when

    K(t) = integral over the time with T > sigma_0 of (T - sigma_0)^lambda dt

reaches a material constant ``K_c`` (Pa^lambda s).  With ``lambda = 0`` the
integral is the time spent beyond ``sigma_0``: the incubation-time criterion.

In a front-tracked solution the stress at a fixed Lagrangian station is a step
function of time with exact step times, so ``K`` is piecewise linear in time
and the instant it reaches ``K_c`` is exact at that station.  The damage is
integrated at ``stations`` points per layer (cell centres of equal cells); the
first station to fail, at its exact time, is the fracture.  The scene is then
run again with the fracture inserted there (``Engine(..., fractures=...)``),
which changes the solution only after that instant, and the search resumes for
the next failure.  The fracture plane is thus located to half a station
spacing, its time exactly for that plane.
"""

from __future__ import annotations

import time

from materials import WavediagramError

from .engine import Engine
from .scene import Scene, SpallCriterion

MAX_FRACTURES = 64
"""Runs stop with an error beyond this many cumulative-damage fractures."""


MARGIN = 1e-12
"""Relative rounding margin of the damage integral (see ``failure_time``)."""


class FractureLimitError(WavediagramError, RuntimeError):
    """A cumulative-damage scene asked for more than ``MAX_FRACTURES`` fractures."""


def damage_rate(tension: float, criterion: SpallCriterion) -> float:
    """``(T - sigma_0)^lambda`` for a tension ``T`` (Pa) beyond the threshold, else 0."""
    excess = tension - criterion.threshold
    if excess <= 0.0:
        return 0.0
    return 1.0 if criterion.exponent == 0.0 else excess**criterion.exponent


def failure_time(history, t_end: float, criterion: SpallCriterion) -> float | None:
    """First time (s) at which the damage of a station's ``history`` reaches ``damage``.

    ``history`` is a step-function record (``Solution.history``): on each step the
    rate is constant, so the damage grows linearly and the crossing is exact.
    Returns ``None`` if the station survives to ``t_end``.  Damage that reaches
    ``damage`` only at the very end of a step (within rounding: the relief
    arrives as the point would fail) does not fail the point.
    """
    damage = 0.0
    ends = [*history.t[1:], t_end]
    for start, end, state in zip(history.t, ends, history.states, strict=True):
        rate = damage_rate(-state.sigma, criterion)
        if rate > 0.0 and end > start:
            if damage + rate * (end - start) > criterion.damage * (1.0 + MARGIN):
                return float(start + (criterion.damage - damage) / rate)
            damage += rate * (end - start)
    return None


def stations(scene: Scene) -> list[float]:
    """Lagrangian stations (m) of the damage integration: cell centres in every layer."""
    points, x0 = [], 0.0
    count = scene.spall_criterion.stations
    for layer in scene.layers:
        width = layer.thickness / count
        points.extend(x0 + (k + 0.5) * width for k in range(count))
        x0 += layer.thickness
    return points


def first_failure(solution, spacing: float, fractures) -> tuple[float, float] | None:
    """``(x, t)`` of the earliest station failure, skipping stations closer than
    ``spacing`` (m) to an earlier fracture (and the fracture planes themselves)."""
    scene = solution.scene
    criterion = scene.spall_criterion
    best = None
    for x in stations(scene):
        if any(abs(x - fx) <= max(spacing, 1e-12 * scene.length) for fx, _ in fractures):
            continue
        t = failure_time(solution.cell_history(x), scene.t_end, criterion)
        if t is not None and (best is None or t < best[1]):
            best = (x, t)
    return best


def run_with_damage(scene: Scene, progress=None, deadline=None):
    """Solve ``scene`` with its cumulative-damage criterion (see the module docstring).

    Each failure found adds a fracture and the scene is run again; the returned
    solution has them all, and its ``accuracy_report["spall_criterion"]`` records the
    criterion and the runs.  ``deadline`` (a ``time.perf_counter()`` value) stops the
    run under way when it passes, and with it the search (``Engine.stop_early``).
    """
    criterion = scene.spall_criterion
    spacing = scene.accuracy.spall_spacing or 0.0
    fractures: list[tuple[float, float]] = []
    started = time.perf_counter()
    events = 0
    while True:
        solution = Engine(scene, progress, fractures=fractures, deadline=deadline).run()
        events += solution.stats["events"]
        found = None if "stopped" in solution.stats else first_failure(
            solution, spacing, fractures)
        if found is None:
            break
        if len(fractures) >= MAX_FRACTURES:
            raise FractureLimitError(
                f"spall: more than {MAX_FRACTURES} fractures by t = {found[1] * 1e6:.6g} us; "
                f"raise spall.threshold or spall.damage, or set accuracy.spall_spacing")
        fractures.append(found)
    width = max(layer.thickness for layer in scene.layers) / criterion.stations
    # the returned run's own counts are in "events"/"solve_time"; the totals of all runs too
    solution.stats["events_all_runs"] = events
    solution.stats["solve_time_all_runs"] = time.perf_counter() - started
    solution.accuracy_report["spall_criterion"] = {
        "kind": "incubation time" if criterion.exponent == 0.0 else "Tuler-Butcher",
        "threshold": criterion.threshold, "exponent": criterion.exponent,
        "damage": criterion.damage, "stations_per_layer": criterion.stations,
        "plane_resolution": 0.5 * width,
        "runs": len(fractures) + 1,
    }
    return solution
