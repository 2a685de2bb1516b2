"""Random plate-impact stacks from the material library (a fixed sample, reproducible):
every scene ends either with a solution that has no NaN, continuous contacts and a
bounded balance, or with a named error (event limit, a state outside an equation of
state).  Found: a root search that bisected in place between two neighbouring floats,
and spall planes born open that a check took for closed interfaces."""

from __future__ import annotations

import random

import pytest
from engine_helpers import assert_contacts_continuous, assert_no_nan

from fronttrack.engine import EventLimitError
from fronttrack.runner import run
from fronttrack.scene import Accuracy, Boundary, Layer, Scene
from materials.errors import NoSolutionError, StateOutOfRangeError
from materials.library import available, get

SCENES = 24


def random_scene(seed: int) -> Scene:
    """2-4 layers, 50 µm to 3 mm, a flyer at -300 to 1500 m/s, bonded or unbonded,
    free or wall ends, 4 or 8 rays per fan, run for 0.5-2 transit times at 3 km/s."""
    rng = random.Random(seed)
    names = available("mie-gruneisen")
    layers = []
    for i in range(rng.randint(2, 4)):
        material = get(rng.choice(names))
        thickness = rng.choice([0.05e-3, 0.2e-3, 1e-3, 3e-3])
        velocity = (rng.choice([0.0, 100.0, 500.0, 1500.0, -300.0]) if i == 0
                    else rng.choice([0.0, 0.0, -200.0]))
        layers.append(Layer(material, thickness, velocity,
                            bond=rng.choice(["bonded", "unbonded"])))
    length = sum(layer.thickness for layer in layers)
    return Scene(layers=tuple(layers), left=Boundary(rng.choice(["free", "free", "wall"])),
                 right=Boundary(rng.choice(["free", "free", "wall"])),
                 t_end=rng.choice([0.5, 1.0, 2.0]) * length / 3000.0,
                 accuracy=Accuracy(rays_per_fan=rng.choice([4, 8]), max_events=3000))


@pytest.mark.parametrize("seed", range(SCENES))
def test_random_stack_solves_or_names_its_limit(seed):
    scene = random_scene(seed)
    try:
        solution = run(scene)
    except EventLimitError as error:
        assert "accuracy.max_events" in str(error)
        return
    except (NoSolutionError, StateOutOfRangeError) as error:
        # a tension or compression beyond an equation of state: named, with the range
        # (seed 6: a water face at a gap that cannot unload to zero stress releases to
        # the end of its equation of state, and a fan from there leaves the isentrope
        # table labelling it: "leaves the range")
        assert any(words in str(error) for words in ("beyond", "outside", "leaves the range"))
        return
    assert_no_nan(solution)
    assert_contacts_continuous(solution)
    balance = solution.conservation()
    # coarse fans (4-8 rays) and waves dropped below 1e-3 of a ray: percent level
    assert balance["momentum_relative_error"] < 0.02
    assert balance["energy_relative_error"] < 0.1
    # neglecting waves may lose energy; no run creates it beyond what its settings
    # promise (seed 1 made 0.94 % against 0.63 %: a release ray overtaking a shock, its
    # entropy jump neglected with the hotter fan cell left behind the shock;
    # fronttrack.neglect keeps such a contact once its cost exceeds its budget)
    promised = solution.accuracy_report["balance"]
    assert promised["energy_error"] <= promised["promised"]
