"""Initiation of explosive layers: a detonator at a face, at a time.

An explosive layer (``materials.explosive.Explosive``) detonates by itself wherever a
compression enters it (the Riemann solver takes the detonation branch of its wave
curve then).  A detonator needs no incoming wave: ``Layer(initiate=...)`` names the
face (``"left"`` or ``"right"``) and the time (``"0.5 us"``; 0 when not given), and at
that event the face's Riemann problem is solved with the explosive ``ignited``: from
an unreacted state its wave is the CJ detonation and its Taylor wave (or an
overdriven detonation if the neighbour drives it harder), whatever the face is (a
free surface, a wall, a piston, an interface).  The reaction zone is infinitely thin;
the run to detonation of a shock-initiated explosive is not modelled.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from materials import solve_boundary, solve_contact

from .errors import SceneError
from .kinds import BoundaryKind, EventKind
from .units import to_si

SIDES = ("left", "right")


@dataclass(frozen=True, slots=True)
class Initiation:
    """A detonator: the layer's ``side`` (``"left"`` or ``"right"``) fires at ``time`` (s)."""

    side: str
    time: float


def parse(value, where: str = "layer.initiate") -> Initiation | None:
    """``"left"``, ``"right"``, a time (``"1 us"``: the left face then), or a side and a
    time (``"right 0.5 us"``); ``None`` or ``""`` for no detonator."""
    if value is None or value == "":
        return None
    if isinstance(value, Initiation):
        return value
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        return _checked(Initiation("left", float(value)), where)
    if not isinstance(value, str):
        raise SceneError(f"{where}: expected \"left\", \"right\" or a time, got {value!r}")
    words = value.split(maxsplit=1)
    side, rest = "left", value.strip()
    if words and words[0] in SIDES:
        side, rest = words[0], words[1] if len(words) > 1 else ""
    time = to_si(rest, "time", where) if rest else 0.0
    return _checked(Initiation(side, time), where)


def _checked(initiation: Initiation, where: str) -> Initiation:
    if not (math.isfinite(initiation.time) and initiation.time >= 0.0):
        raise SceneError(f"{where}: the initiation time must be >= 0 s, got "
                         f"{initiation.time!r}")
    return initiation


def check(scene) -> None:
    """Raise ``SceneError`` for a detonator on a layer that is not an explosive or that
    fires after ``t_end``."""
    for i, layer in enumerate(scene.layers):
        fire = layer.initiate
        if fire is None:
            continue
        if not hasattr(layer.material, "ignited"):
            raise SceneError(f"layer[{i}].initiate: {layer.material.name} is not an explosive "
                             f"(only explosive layers can be initiated)")
        if fire.time > scene.t_end:
            raise SceneError(f"layer[{i}].initiate: the initiation time "
                             f"{fire.time * 1e6:.6g} us is after t_end "
                             f"({scene.t_end * 1e6:.6g} us); it must be in [0, t_end]")


def schedule(engine, sites: list) -> None:
    """Queue each detonator's face (``sites[i]`` is the face left of layer ``i``,
    ``sites[-1]`` the right end) at its time and remember it."""
    engine.initiations = {}
    for i, layer in enumerate(engine.scene.layers):
        fire = layer.initiate
        if fire is None:
            continue
        site = sites[i] if fire.side == "left" else sites[i + 1]
        engine.initiations[site.id] = (fire.time, i)
        if fire.time > 0.0:
            engine.push_site(site, fire.time)


def solve(engine, site, region_left, region_right, t, timer):
    """The detonator's Riemann problem at ``site`` if it fires now, else ``None``.

    Returns ``(EventKind.INITIATION, solution)``.  At a boundary with a prescribed history
    the event is also that boundary's timer (``timer``): its next step is queued.
    """
    fire = getattr(engine, "initiations", {}).get(site.id) if site is not None else None
    if fire is None or t != fire[0]:
        return None
    del engine.initiations[site.id]  # a detonator fires once
    layer = fire[1]
    release = engine.resolution.release
    left_material = region_left.material if region_left is not None else None
    right_material = region_right.material if region_right is not None else None
    if region_right is not None and region_right.layer == layer:
        right_material = right_material.ignited
    else:
        left_material = left_material.ignited
    if region_left is None or region_right is None:
        spec = engine.scene.left if region_left is None else engine.scene.right
        region, material = ((region_right, right_material) if region_left is None
                            else (region_left, left_material))
        side = "left" if region_left is None else "right"
        kw = _boundary_condition(engine, site, spec, t, timer)
        return EventKind.INITIATION, solve_boundary(material, region.state, side,
                                                    release=release, **kw)
    sol = solve_contact(left_material, region_left.state, right_material, region_right.state,
                        site.strength if site.strength > 0.0 else math.inf, release)
    return EventKind.INITIATION, sol


def _boundary_condition(engine, site, spec, t, timer) -> dict:
    """The face's condition now: a stress or a velocity (a piston is held bonded at the
    instant of initiation)."""
    from . import interactions  # it calls this module: imported when first needed

    value = interactions.boundary_value(site, spec, t)
    if timer:
        interactions._schedule_next_step(engine, site, t)  # noqa: SLF001
    if spec.kind in (BoundaryKind.FREE, BoundaryKind.STRESS):
        return {"stress": value}
    return {"velocity": value}
