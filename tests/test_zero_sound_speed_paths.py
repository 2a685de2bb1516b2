"""Waves at zero sound speed (a gas at zero pressure) in the newer paths of the engine.

Campaign seeds 141 and 169 (``tests/random_scenes.py``) crashed with a
ZeroDivisionError: the dropped-wave ledger (``fronttrack.dropped``) divided a layer's
thickness by the speed of a wave at rest, and the snap width of a lattice grid
(``characteristics.grid``) divided the negligible stress by a zero impedance.  A wave
at rest carries its mismatch to ``t_end``; a join at zero sound speed snaps nothing.
Each scene now runs past the event where it crashed (2 836th and 35th) to its end or
to the event limit set here, a named error.
"""

import dataclasses

import pytest
from random_scenes import campaign_scene

import fronttrack as ft
from fronttrack.engine import EventLimitError


@pytest.mark.parametrize(("seed", "max_events"), [(141, 3000), (169, 400)])
def test_scene_runs_past_its_zero_speed_event(seed, max_events):
    scene = campaign_scene(seed)
    scene = dataclasses.replace(
        scene, accuracy=dataclasses.replace(scene.accuracy, max_events=max_events))
    try:
        solution = ft.run(scene)
    except EventLimitError as error:
        assert "max_events" in str(error)
        return
    balance = solution.accuracy_report["balance"]
    assert balance["energy_error"] <= balance["promised"]
