"""Random layered scenes for campaigns and property tests (reproducible from a seed).

``campaign_scene(seed)`` draws 2-6 layers of library and inline materials of every
model (Mie-Grüneisen, linear elastic, elastic-plastic, finite-plastic, ideal gas),
bonded and unbonded contacts, initial velocities and prestresses, every boundary kind
(free, wall, a constant or ramped velocity, a stress pulse), both release paths, 2-16
characteristics per fan and 0.5-5 transit times.  Used by ``benchmarks/campaign.py``
(a thousand scenes, outside the suite) and by ``tests/test_balance_property.py``.
"""

from __future__ import annotations

import random

from fronttrack.scene import Accuracy, Boundary, Layer, Scene
from materials import ElasticPlastic, FinitePlastic, IdealGas, LinearElastic, MieGruneisen
from materials.library import available, entry, get

EXPLOSIVE_MODELS = ("explosive-jwl", "explosive-gamma")

MODELS = ("library", "library", "library", "mie-gruneisen", "linear-elastic",
          "elastic-plastic", "finite-plastic", "ideal-gas")


def _inline_material(rng: random.Random, model: str, index: int):
    """An inline material of ``model`` with parameters in the range of real solids."""
    name = f"M{index}"
    rho0 = rng.uniform(1000.0, 19000.0)
    spall = rng.choice([float("inf"), rng.uniform(0.3e9, 3e9)])
    if model == "mie-gruneisen":
        return MieGruneisen(name, rho0, rng.uniform(1500.0, 8000.0), rng.uniform(0.9, 2.0),
                            rng.uniform(0.5, 2.5), spall_strength=spall)
    if model == "linear-elastic":
        modulus = rho0 * rng.uniform(2000.0, 9000.0) ** 2
        return LinearElastic(name, rho0, (modulus / rho0) ** 0.5, spall_strength=spall)
    if model == "elastic-plastic":
        mu = rng.uniform(5e9, 150e9)
        return ElasticPlastic(name, rho0, rng.uniform(1.0, 3.0) * mu, mu,
                              rng.uniform(0.1e9, 2.5e9), spall_strength=spall)
    if model == "finite-plastic":
        return FinitePlastic(name, rho0, rng.uniform(2500.0, 6500.0), rng.uniform(1.0, 1.8),
                             rng.uniform(1.0, 2.2), rng.uniform(20e9, 130e9),
                             rng.uniform(0.1e9, 2e9), spall_strength=spall)
    return IdealGas(name, rng.choice([1.4, 5.0 / 3.0, 1.2]), rng.uniform(0.1, 50.0))


def _boundary(rng: random.Random, t_end: float) -> Boundary:
    kind = rng.choice(["free", "free", "wall", "velocity", "stress"])
    if kind == "velocity":
        v = rng.choice([100.0, 500.0, -100.0])
        points = rng.choice([((0.0, v),), ((0.0, 0.0), (0.3 * t_end, v))])
        return Boundary(kind, points)
    if kind == "stress":
        p = rng.uniform(0.1e9, 10e9)
        tau = rng.uniform(0.05, 0.5) * t_end
        return Boundary(kind, rng.choice([((0.0, p),), ((0.0, p), (tau, p), (tau, 0.0)),
                                          ((0.0, 0.0), (tau, p))]))
    return Boundary(kind)


def campaign_scene(seed: int, max_events: int = 20_000) -> Scene:
    """One random scene; the same seed gives the same scene."""
    rng = random.Random(seed)
    # explosives detonate at the first compression: campaigns and property tests draw the
    # inert entries (the library's order is unchanged, so a seed gives the same scene)
    names = [n for n in available() if entry(n)["model"] not in EXPLOSIVE_MODELS]
    layers, transit = [], 0.0
    for i in range(rng.randint(2, 6)):
        model = rng.choice(MODELS)
        material = (get(rng.choice(names)) if model == "library"
                    else _inline_material(rng, model, i))
        thickness = rng.choice([0.01e-3, 0.05e-3, 0.2e-3, 1e-3, 3e-3, 10e-3])
        velocity = rng.choice([0.0, 0.0, 100.0, 500.0, 1500.0, -300.0])
        gas = isinstance(material, IdealGas)
        stress = (rng.uniform(0.05e6, 5e6) if gas
                  else rng.choice([0.0, 0.0, 0.0, rng.uniform(-0.5e9, 2e9)]))
        layers.append(Layer(material, thickness, velocity, stress=stress,
                            bond=rng.choice(["bonded", "unbonded"])))
        speed = material.sound_speed(material.v0, 0.0) if not gas else 300.0
        transit += thickness / max(speed, 100.0)
    t_end = rng.uniform(0.5, 5.0) * min(transit, 20e-6)
    accuracy = Accuracy(rays_per_fan=rng.choice([None, 2, 4, 8, 16]),
                        release=rng.choice(["isentrope", "isentrope", "hugoniot"]),
                        max_events=max_events)
    return Scene(layers=tuple(layers), t_end=t_end, left=_boundary(rng, t_end),
                 right=_boundary(rng, t_end), accuracy=accuracy)


def strength_stack_scene(seed: int) -> Scene:
    """A random stack of solids with strength (the sample of ``benchmarks/run_length.py``).

    2-4 inline elastic-plastic or finite-plastic layers (50 µm to 3 mm; the first moving
    at 100-1000 m/s), bonded or unbonded, free or wall ends, run for 1-3 transit times
    at default accuracy.
    """
    rng = random.Random(seed)
    layers, transit = [], 0.0
    for i in range(rng.randint(2, 4)):
        material = _inline_material(rng, rng.choice(["elastic-plastic", "finite-plastic"]), i)
        thickness = rng.choice([0.05e-3, 0.2e-3, 1e-3, 3e-3])
        velocity = rng.uniform(100.0, 1000.0) if i == 0 else 0.0
        layers.append(Layer(material, thickness, velocity,
                            bond=rng.choice(["bonded", "unbonded"])))
        transit += thickness / material.sound_speed(material.v0, 0.0)
    return Scene(layers=tuple(layers), t_end=rng.uniform(1.0, 3.0) * transit,
                 left=Boundary(rng.choice(["free", "free", "wall"])),
                 right=Boundary(rng.choice(["free", "free", "wall"])))
