"""A fracture zone the lattices find one window at a time is one zone (issue 13).

Cu/Al 2024/Cu/Al 2024, 1 mm each, the Cu at 1 km/s, default accuracy: from 0.7429 us
the threshold fractures the second Cu plate near its Al interface, a level set moving
at 6-13 km/s toward the impact face, faster than sound (Cu: 3.94 km/s).  At 8 rays per
fan one lattice spans it (one zone 2.883-2.914 mm, three planes); at default accuracy
each lattice saw a few ns of it and the next found the level set going on as a new
first point: a plane every 5-12 um, 15 planes from 2.923 to 2.838 mm by 0.7516 us, each
fragment rung one transit at a time.  The lattices' finds are replayed here on the
stack's engine (its spall spacing, 4 um): the first one (a single sample of the level
set, at 2.9231 mm and 0.74293 us) and the next (2.9128-2.9182 mm from 0.74373 us, the
level set 10.3 um on in 0.80 ns: 12.9 km/s), as the run found them (rounded).
"""

from __future__ import annotations

from types import SimpleNamespace

from characteristics.fracture import FractureZone
from fronttrack import spall
from fronttrack.engine import Engine
from fronttrack.scene import Layer, Scene
from materials import get

CU_LAYER = 2


def _stack_engine() -> Engine:
    cu, al = get("Cu"), get("Al2024")
    return Engine(Scene(layers=(Layer(cu, 1e-3, 1000.0), Layer(al, 1e-3), Layer(cu, 1e-3),
                                Layer(al, 1e-3)), t_end=2e-6))


def _slowness() -> float:
    """Cu's bulk sound speed at rest, 3 940 m/s, inverted (s/m)."""
    cu = get("Cu")
    return 1.0 / cu.sound_speed(cu.v0, 0.0)


def _found(x, t, x_lo, t_lo, x_hi, t_hi) -> SimpleNamespace:
    """A lattice that found the level set's samples from ``x_lo`` to ``x_hi`` (mm, us),
    its last samples on both sides (open ends)."""
    zone = FractureZone(x=x * 1e-3, t=t * 1e-6, x_lo=x_lo * 1e-3, t_lo=t_lo * 1e-6,
                        x_hi=x_hi * 1e-3, t_hi=t_hi * 1e-6, slowness=_slowness(),
                        open_lo=True, open_hi=True)
    return SimpleNamespace(fracture=zone)


def _plans(engine) -> list:
    """The planned fractures, by time."""
    return sorted((entry[4] for entry in engine._heap if entry[3] == "fracture"),
                  key=lambda plan: plan.t)


def test_the_level_set_going_on_extends_the_zone():
    engine = _stack_engine()
    transit = spall.spacing(engine) * _slowness()
    assert abs(transit - 4e-6 / 3940.0) < 1e-13  # 1.015 ns: one spacing, 4 um, at 3.94 km/s
    spall.schedule(engine, _found(2.9231, 0.74293, 2.9231, 0.74293, 2.9231, 0.74293),
                   CU_LAYER, 0.7429e-6)
    first = _plans(engine)
    assert [(round(p.x * 1e3, 4), p.open_end) for p in first] == [(2.9231, False)]
    # the next lattice: the level set 10.3 um on, 0.80 ns later (faster than sound)
    spall.schedule(engine, _found(2.9128, 0.74373, 2.9128, 0.74373, 2.9182, 0.74383),
                   CU_LAYER, 0.7430e-6)
    zones = engine.fracture_zones
    assert len(zones) == 1  # one zone, not two
    assert abs(zones[0].x_lo - 2.9128e-3) < 1e-9 and abs(zones[0].x_hi - 2.9231e-3) < 1e-9
    assert engine.counters.suppressed_spalls == 1  # its first point: no plane
    plans = _plans(engine)[1:]
    # only the open far end, one transit late; the end at 2.9182 mm is inside the zone
    assert [(round(p.x * 1e3, 4), p.open_end) for p in plans] == [(2.9128, True)]
    assert abs(plans[0].t - (0.74373e-6 + transit)) < 1e-15
    # a third lattice finds it going on again before that plane: the plane is outgrown
    spall.schedule(engine, _found(2.9006, 0.74440, 2.9006, 0.74440, 2.9059, 0.74450),
                   CU_LAYER, 0.7437e-6)
    assert len(engine.fracture_zones) == 1
    assert abs(engine.fracture_zones[0].x_lo - 2.9006e-3) < 1e-9
    assert spall.outgrown(engine, plans[0], CU_LAYER)
    assert not spall.outgrown(engine, _plans(engine)[-1], CU_LAYER)  # the new end


def test_a_level_set_slower_than_sound_is_a_new_fracture():
    """2 um beyond the end 0.90 ns later (2.2 km/s, within the transit): the relief got
    there first, so the point is a new fracture with its own plane; so is one reached
    faster than sound but later than a spacing's transit after the end (its plane made,
    the relief begun)."""
    engine = _stack_engine()
    spall.schedule(engine, _found(2.9231, 0.74293, 2.9231, 0.74293, 2.9231, 0.74293),
                   CU_LAYER, 0.7429e-6)
    spall.schedule(engine, _found(2.9211, 0.74383, 2.9211, 0.74383, 2.9211, 0.74383),
                   CU_LAYER, 0.7438e-6)
    assert len(engine.fracture_zones) == 2
    assert engine.counters.suppressed_spalls == 0
    assert [round(p.x * 1e3, 4) for p in _plans(engine)] == [2.9231, 2.9211]
    # 40 um on in 2 ns (20 km/s) but 2 ns after the end: not a continuation either
    spall.schedule(engine, _found(2.8811, 0.74583, 2.8811, 0.74583, 2.8811, 0.74583),
                   CU_LAYER, 0.7458e-6)
    assert len(engine.fracture_zones) == 3
    assert engine.counters.suppressed_spalls == 0
