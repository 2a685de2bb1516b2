"""Designing an experiment: the questions asked before a plate is cut.

Each function answers one question, stated in its docstring, and is exact where
the physics is: the impedance match is exact (``fronttrack.impedance_match``),
and the functions that run a scene inherit the engine's accuracy (exact to
rounding for scenes made only of shocks).  Quantities are SI numbers or strings
with units; results are SI.

- ``velocity_for``: the impact velocity that puts a chosen stress (or particle
  velocity) into a layer of a stack, the inverse of ``match``.
- ``one_dimensional_window``: how long a station sees the state the first shock
  set, and ``thickness_for_window``: the thickness of a layer that makes it last
  at least a chosen time.
- ``flyer_for_spall``: the flyer thickness that puts the first fracture at a
  chosen depth of the target.
- ``window_choice``: the interface state and the apparent interferometer
  velocity for a sample behind each of several optical windows.
"""

from __future__ import annotations

import dataclasses
import numbers
from dataclasses import dataclass

import numpy as np
from scipy.optimize import brentq

from materials import Material, WavediagramError

from .errors import SceneError
from .fronts import MIXED
from .impedance_match import match
from .runner import run
from .scene import Scene
from .solution import Solution
from .units import to_si
from .windows import OpticalWindow, optical_window

_QUANTITIES = {"sigma": "stress", "u": "velocity"}
_MAX_VELOCITY = 1e5
"""Largest impact velocity (m/s) ``velocity_for`` tries: beyond every fit in the library."""


def velocity_for(target: float | str, flyer: Material | str, stack: list,
                 layer: int = -1, quantity: str = "sigma",
                 release: str = "isentrope") -> float:
    """Which impact velocity puts ``target`` into layer ``layer`` of ``stack``?

    The inverse of ``match``: the velocity ``V`` (m/s) at which the first shock
    leaves ``quantity`` (``"sigma"``, Pa, or ``"u"``, m/s) equal to ``target`` in
    the layer, found as the root of a monotone function to a few ulps, so that
    ``match(flyer, V, stack)`` returns ``target`` to 1e-12.

    Raises
    ------
    SceneError
        ``quantity`` unknown, ``target`` not > 0, ``stack`` empty, ``layer`` not an
        index of it, or the target not reachable below 100 km/s.
    """
    if quantity not in _QUANTITIES:
        raise SceneError(f"quantity: must be one of {tuple(_QUANTITIES)}, got {quantity!r}")
    goal = to_si(target, _QUANTITIES[quantity], "target")
    if not goal > 0.0:
        raise SceneError(f"target: must be > 0, got {goal!r}")
    stack = [stack] if isinstance(stack, (str, Material)) else list(stack)
    if not stack:
        raise SceneError("stack: needs at least one layer")
    row = _layer_index(layer, len(stack), "layer") + 1

    def excess(velocity: float) -> float:
        return getattr(match(flyer, velocity, stack, release=release)[row], quantity) - goal

    high = 100.0
    while True:
        try:
            if excess(high) >= 0.0:
                break
        except WavediagramError as error:
            raise SceneError(f"target: {goal:.6g} is not reachable in layer {layer} "
                             f"({error})") from None
        if high >= _MAX_VELOCITY:
            raise SceneError(f"target: {goal:.6g} is not reached below "
                             f"{_MAX_VELOCITY:.0f} m/s")
        high *= 2.0
    low = high / 2.0 if high > 100.0 else 0.0
    f_low = excess(low) if low > 0.0 else -goal
    if f_low == 0.0:
        return low
    return float(brentq(excess, low, high, xtol=1e-300, rtol=8.9e-16, maxiter=500))


@dataclass(frozen=True)
class Window:
    """The one-dimensional window at a station.

    ``first_shock`` (s): when the first wave reaches the station; ``end`` (s): when
    the first wave that does not descend from it arrives; ``duration = end -
    first_shock``.  ``censored`` is true when none arrived before the run's end
    (``end`` is then ``t_end`` and the true window is longer).
    """

    first_shock: float
    end: float
    duration: float
    censored: bool


def one_dimensional_window(solution: Solution, at) -> Window:
    """How long does the station ``at`` see only the first shock and its own reflections?

    ``at`` is a probe name, ``"left"``, ``"right"`` or X (m).  The window opens when
    the first wave reaches the station and closes when the first wave of another
    lineage arrives (``Front.lineage``): a release from the flyer's back, a
    reflection from an edge of the stack (a free surface, a wall, a gap), or any
    wave that met one of those on its way.  The first shock's own transmissions and
    reflections at the interfaces between layers keep its lineage and leave the
    window open, though they change the state.  (A plane-wave code has no lateral
    edges: the edge release of a finite plate is not modelled.)  Exact for scenes
    made only of shocks, whose arrival times are exact.

    Raises
    ------
    SceneError
        No wave reaches the station before the run's end.
    """
    times, lineages = solution.arrivals(at)
    if times.size == 0:
        raise SceneError(f"at: no shock reaches {at!r} before t_end")
    first = float(times[0])
    # the waves of the first instant (an incident wave and what it sends out, at a
    # station on an interface) within the rounding of the times
    together = times <= first + 1e-12 * solution.scene.t_end
    origin = int(lineages[0]) if np.all(lineages[together] == lineages[0]) else MIXED
    foreign = np.nonzero(~together & ((lineages != origin) | (origin == MIXED)))[0]
    censored = foreign.size == 0
    end = solution.scene.t_end if censored else float(times[foreign[0]])
    return Window(first_shock=first, end=end, duration=end - first, censored=censored)


def with_thickness(scene: Scene, layer: int, thickness: float) -> Scene:
    """``scene`` with layer ``layer`` of ``thickness`` (m); probes beyond it keep their
    depth in their own layer (their X moves with the change)."""
    old = scene.layers[layer]
    shift = thickness - old.thickness
    start = sum(lay.thickness for lay in scene.layers[:layer])
    probes = tuple(
        dataclasses.replace(p, at=p.at + shift)
        if not isinstance(p.at, str) and p.at >= start + old.thickness and shift else p
        for p in scene.probes)
    layers = list(scene.layers)
    layers[layer] = dataclasses.replace(old, thickness=thickness)
    return dataclasses.replace(scene, layers=tuple(layers), probes=probes)


def thickness_for_window(scene: Scene, at: str, duration: float | str, layer: int = 0,
                         largest: float | str | None = None) -> float:
    """Which thickness of layer ``layer`` gives the probe ``at`` a window of ``duration``?

    The smallest thickness (m) at which ``one_dimensional_window`` at the probe
    lasts at least ``duration`` (s), searched up to ``largest`` (default 100 times
    the layer's thickness).  The scene is run at each trial thickness; its
    ``t_end`` must reach past the window wanted.  For scenes made only of shocks
    the window is exact, so the answer is exact to the root's tolerance (1e-12 of
    the thickness).

    Raises
    ------
    SceneError
        ``duration`` not > 0 or ``layer`` not a layer index; another wave closes the
        window sooner whatever the thickness, or the run ends before a window of
        ``duration`` could be seen.
    """
    wanted = to_si(duration, "time", "duration")
    if not wanted > 0.0:
        raise SceneError(f"duration: must be > 0 s, got {wanted!r}")
    current = scene.layers[_layer_index(layer, len(scene.layers), "layer")].thickness
    top = 100.0 * current if largest is None else to_si(largest, "length", "largest")

    def shortfall(thickness: float) -> float:
        trial = with_thickness(scene, layer, thickness)
        window = one_dimensional_window(run(trial), at)
        if window.censored and window.duration < wanted:
            raise SceneError(f"t_end: the run ends {window.duration * 1e6:.6g} us after the "
                             f"first shock reaches {at!r}, before a window of "
                             f"{wanted * 1e6:.6g} us could close")
        return window.duration - wanted

    low, high = 1e-6 * current, top
    if shortfall(high) < 0.0:
        raise SceneError(f"duration: the window at {at!r} stays shorter than "
                         f"{wanted * 1e6:.6g} us for layer[{layer}] up to "
                         f"{high * 1e3:.6g} mm: another wave closes it")
    if shortfall(low) >= 0.0:
        return low
    return float(brentq(shortfall, low, high, xtol=1e-12 * current, rtol=8.9e-16))


def flyer_for_spall(scene: Scene, depth: float | str, flyer: int = 0, target: int = 1,
                    tolerance: float = 1e-9) -> float:
    """Which flyer thickness puts the first fracture at ``depth`` into the target?

    ``depth`` (m) is measured from the target's impact face (its side toward the
    flyer).  The releases from the flyer's back and from the target's far face
    meet inside the target; where the tension first reaches the strength the
    target spalls (``Solution.spalls``).  A thicker flyer moves that plane
    toward the impact face.  The acoustic estimate (the two releases meet where
    their travel times agree) starts the search; the scene is then run at trial
    thicknesses and the depth of the first fracture solved for, to ``tolerance``
    of the target's thickness.  The answer is exact where the run is (shock-only
    scenes); with release fans the first fracture moves by steps of the ray
    spacing, and the answer is within the run's accuracy.

    Raises
    ------
    SceneError
        ``flyer`` or ``target`` not a layer index (or the same layer), ``depth`` not
        inside the target, or no thickness up to the target's puts the first fracture
        at ``depth``.
    """
    wanted = to_si(depth, "length", "depth")
    flyer = _layer_index(flyer, len(scene.layers), "flyer")
    target = _layer_index(target, len(scene.layers), "target")
    if flyer == target:
        raise SceneError(f"target: must be another layer than the flyer (both {flyer})")
    target_layer = scene.layers[target]
    if not 0.0 < wanted < target_layer.thickness:
        raise SceneError(f"depth: must be inside the target (0 to "
                         f"{target_layer.thickness * 1e3:.6g} mm), got {wanted * 1e3:.6g} mm")

    def miss(thickness: float) -> float:
        trial = with_thickness(scene, flyer, thickness)
        inside = [s for s in run(trial).spalls if s.layer == target]
        if not inside:
            raise SceneError(f"depth: a {thickness * 1e3:.6g} mm flyer does not spall "
                             f"layer[{target}] before t_end")
        x = min(inside, key=lambda s: s.t).x
        start = sum(lay.thickness for lay in trial.layers[:target])
        reached = x - start if flyer < target else start + target_layer.thickness - x
        return reached - wanted

    guess = (target_layer.thickness - wanted) * (_sound_speed(scene.layers[flyer].material)
                                                 / _sound_speed(target_layer.material))
    low, high = _bracket(miss, guess, target_layer.thickness)
    return float(brentq(miss, low, high, xtol=tolerance * target_layer.thickness,
                        rtol=8.9e-16))


def _layer_index(index, count: int, field: str) -> int:
    """``index`` (Python style: negative counts from the end) of one of ``count`` layers,
    as a non-negative int; raises ``SceneError`` naming ``field`` and the range."""
    if isinstance(index, bool) or not isinstance(index, numbers.Integral) \
            or not -count <= index < count:
        raise SceneError(f"{field}: must be a layer index from {-count} to {count - 1}, "
                         f"got {index!r}")
    return int(index) % count


def _sound_speed(material: Material) -> float:
    """Lagrangian sound speed (m/s) of ``material`` at rest and unstressed."""
    return material.sound_speed(material.v0, 0.0)


def _bracket(func, guess: float, scale: float) -> tuple[float, float]:
    """An interval around ``guess`` (> 0) on which ``func`` changes sign, widened by 1.25
    at a time up to ``scale`` (the acoustic guess is usually within a few per cent)."""
    low, high = guess / 1.25, min(guess * 1.25, scale)
    f_low, f_high = func(low), func(high)
    for _ in range(12):
        if f_low * f_high <= 0.0:
            return low, high
        if abs(f_low) < abs(f_high):
            low, f_low = low / 1.25, func(low / 1.25)
        else:
            high = min(high * 1.25, scale)
            f_high = func(high)
    raise SceneError(f"depth: no flyer from {low * 1e3:.6g} to {high * 1e3:.6g} mm puts the "
                     f"first fracture there (misses {f_low:.3g} and {f_high:.3g} m)")


@dataclass(frozen=True)
class WindowChoice:
    """A sample behind one optical window, after the first shock reaches the window.

    ``sigma`` (Pa) and ``u`` (m/s): the interface state; ``sample_sigma`` the state
    the sample had before (Pa); ``reflected``: ``"reshock"`` or ``"release"`` (the
    wave sent back into the sample; ``None`` when the impedances match);
    ``apparent_u`` (m/s): what the interferometer reports through the window while
    its far face is at rest; ``correction`` = ``apparent_u / u``.
    """

    window: str
    material: str
    sigma: float
    u: float
    sample_sigma: float
    reflected: str | None
    apparent_u: float
    correction: float


def window_choice(flyer: Material | str, velocity: float | str, sample: Material | str,
                  windows: tuple = ("LiF",), release: str = "isentrope") -> list[WindowChoice]:
    """Which window should the interferometer look through, and what will it see?

    A flyer strikes ``sample`` at ``velocity``; the first shock crosses the sample
    into each candidate window (names with a cited fit, or ``OpticalWindow``
    objects; the window's material comes from the library).  For each, the exact
    interface state (impedance match with a reshock or an isentropic release back
    into the sample) and the apparent velocity ``a u`` an interferometer reports
    (``fronttrack.windows``).
    """
    choices = []
    for candidate in [windows] if isinstance(windows, (str, OpticalWindow)) else windows:
        optics: OpticalWindow = optical_window(candidate)
        rows = match(flyer, velocity, [sample, optics.material], release=release)
        sample_row, window_row = rows[1], rows[2]
        reflected = sample_row.reflected
        apparent = float(optics.apparent_velocity(window_row.u))
        choices.append(WindowChoice(
            window=optics.name, material=window_row.material, sigma=window_row.sigma,
            u=window_row.u, sample_sigma=sample_row.sigma,
            reflected=None if reflected is None else
            ("reshock" if reflected.compressive else "release"),
            apparent_u=apparent, correction=apparent / window_row.u))
    return choices


__all__ = ["Window", "WindowChoice", "flyer_for_spall", "one_dimensional_window",
           "thickness_for_window", "velocity_for", "window_choice", "with_thickness"]
