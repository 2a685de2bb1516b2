"""The paths of the waves in state space, for the σ–u and σ–ρ diagrams.

Every wave joins the state ahead of it (the region it runs into: the right
region of a right-going wave) to the state behind it, along its material's
wave curve centred on the ahead state:

- a shock along the Hugoniot centred on the ahead state (a rarefaction shock of
  a Hugoniot release, or of a linear elastic solid, along the same curve);
- a fan along the isentrope through the ahead state; a whole fan (all rays
  issued from one point, see ``plotting.fans``) is one path, from the state
  ahead of its head ray to the state behind its tail ray.

The path is sampled with ``material.wave_curve(ahead, direction, release)``
(``release`` as the solution was computed, ``accuracy_report["release"]``), so
it ends exactly on the behind state.  Paths that coincide on a diagram (same
material and kind, end states equal to 1/2000 of the solution's stress,
velocity and volume spans) are kept once: a slab ringing between two free
surfaces repeats the same few paths to rounding, hundreds of times.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from materials import State

from ..solution import StateSeries
from .fans import fan_groups

RESOLUTION = 2000
"""Paths whose end states differ by less than 1/RESOLUTION of the data spans are one path."""

REFINEMENTS = 8
"""Rounds of step halving where a sampled path turns sharply in velocity."""

MAX_SAMPLES = 40
"""Samples along a path spanning the scene's largest stress jump (fewer for weaker waves)."""


@dataclass(frozen=True)
class WavePath(StateSeries):
    """One wave in state space: ``kind`` shock or fan, its regions and the sampled states."""

    kind: str
    material: object
    ahead: int
    behind: int
    states: tuple[State, ...]


def _waves(solution, keep):
    """``(kind, direction, ahead_id, behind_id)`` of every shock and fan whose two end
    regions pass ``keep(ahead, behind)``, deduplicated."""
    seen, waves = set(), []
    for front in solution.fronts:
        if front.kind == "shock" and front.t1 is not None:
            ahead, behind = ((front.right_region_id, front.left_region) if front.direction > 0
                             else (front.left_region, front.right_region_id))
            waves.append(("shock", front.direction, ahead, behind))
    for rays in fan_groups(solution):
        head, tail = rays[0], rays[-1]
        if head.direction > 0:
            ahead, behind = head.right_region_id, tail.left_region
        else:
            ahead, behind = head.left_region, tail.right_region_id
        waves.append(("fan", head.direction, ahead, behind))
    unique = []
    for wave in waves:
        if None in wave or wave in seen or not keep(wave[2], wave[3]):
            continue
        seen.add(wave)
        unique.append(wave)
    return unique


def wave_paths(solution, numbered=None) -> list[WavePath]:
    """Sampled state-space paths of the waves of the solution (see module docstring).

    ``numbered``: if given, a set of region ids; only the waves joining two of
    them are sampled (the paths a σ–u diagram draws by default).
    """
    regions = {r.id: r for r in solution.regions}
    release = solution.accuracy_report.get("release", "isentrope")
    sigma = [r.state.sigma for r in solution.regions]
    u = [r.state.u for r in solution.regions]
    scale = max(max(sigma) - min(sigma), 1.0)
    v = [r.state.v for r in solution.regions if math.isfinite(r.state.v)]
    resolution = (scale / RESOLUTION, max(max(u) - min(u), 1e-3) / RESOLUTION,
                  max(max(v) - min(v), 1e-12) / RESOLUTION)
    paths, seen = [], set()
    def keep(ahead, behind):
        return numbered is None or (ahead in numbered and behind in numbered)

    for kind, direction, ahead_id, behind_id in _waves(solution, keep):
        ahead, behind = regions[ahead_id], regions[behind_id]
        a, b = ahead.state, behind.state
        key = (ahead.material.name, kind, *_rounded(a, resolution), *_rounded(b, resolution))
        if key in seen:
            continue
        seen.add(key)
        count = max(2, math.ceil(MAX_SAMPLES * abs(b.sigma - a.sigma) / scale))
        states = _sample(ahead.material, a, b, direction, release, count,
                         resolution[1] * RESOLUTION / MAX_SAMPLES)
        paths.append(WavePath(kind, ahead.material, ahead_id, behind_id, states))
    return paths


def _rounded(state: State, resolution) -> tuple[int, int, int]:
    """A state's position on the diagrams, to their resolution."""
    v = state.v if math.isfinite(state.v) else -1.0  # a gas expanded into vacuum
    return tuple(round(value / step) for value, step in
                 zip((state.sigma, state.u, v), resolution, strict=True))


def _sample(material, ahead: State, behind: State, direction: int, release: str,
            count: int, du_max: float) -> tuple[State, ...]:
    """States along the wave curve from ``ahead`` to ``behind`` (straight chord if it fails).

    ``count`` points at equal steps of stress, then steps refined by halving
    where the velocity changes by more than ``du_max`` (m/s): the isentrope of
    a gas flattens as it nears zero pressure.
    """
    if behind.sigma == ahead.sigma or (count <= 2 and abs(behind.u - ahead.u) <= du_max):
        return (ahead, behind)
    curve = material.wave_curve(ahead, direction, release)
    sigmas = np.linspace(ahead.sigma, behind.sigma, count)
    try:
        states = [ahead, *(curve.state_at(float(s)) for s in sigmas[1:-1]), behind]
        for _ in range(REFINEMENTS):
            refined = [states[0]]
            for a, b in zip(states[:-1], states[1:], strict=True):
                if abs(b.u - a.u) > du_max:
                    refined.append(curve.state_at(0.5 * (a.sigma + b.sigma)))
                refined.append(b)
            if len(refined) == len(states):
                break
            states = refined
    except ValueError:  # a state beyond the model's range: draw the chord
        return (ahead, behind)
    return tuple(states)
