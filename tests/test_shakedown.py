"""The wall–free layer of ``benchmarks/shakedown.py``: half of a free slab mirrored about
the wall.

A linear elastic layer between a wall (``u = 0``) and a free face (``sigma = 0``) rings
in its quarter-wave modes, angular frequencies ``(2 n + 1) pi C / (2 L)``: after half a
period, ``2 L / C``, every mode has turned by an odd multiple of ``pi``, so the stress
and velocity fields are those of the start with their signs changed, and after a whole
period, ``4 L / C``, the start again.  The wall stays at rest all along.
"""

import sys
from pathlib import Path

import numpy as np
import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "benchmarks"))

from shakedown import mirrored_slab  # noqa: E402

from materials import ElasticPlastic  # noqa: E402

STEEL = ElasticPlastic("steel", rho0=7870.0, lam=115e9, mu=80e9, yield_strength=1.0e9)
"""Any elastic solid: only its density and longitudinal sound speed enter."""


@pytest.fixture
def layer():
    """A 50 um layer from X = 0 (wall) with 7 random cells (Pa, m/s) at t0 = 1 us."""
    rng = np.random.default_rng(7)
    edges = np.concatenate([[0.0], np.sort(rng.uniform(0.0, 50e-6, 6)), [50e-6]])
    return edges, rng.uniform(-1e9, 1e9, 7), rng.uniform(-50.0, 50.0, 7), 1e-6


def test_mirror_starts_from_the_cells_and_keeps_the_wall_at_rest(layer):
    edges, sigma, u, t0 = layer
    slab = mirrored_slab(edges, sigma, u, t0, STEEL)
    s, v = slab.state(0.5 * (edges[:-1] + edges[1:]), t0)
    scale = np.abs(sigma).max()
    assert np.allclose(s, sigma, rtol=0.0, atol=1e-12 * scale)
    assert np.allclose(v, u, rtol=0.0, atol=1e-12 * scale / slab.z)
    # the wall (X = 0): at rest at any time, to rounding of the impedance's scale
    times = t0 + np.linspace(0.0, 3.0 * slab.period, 301) + 1e-3 * slab.period / 301
    wall = np.array([slab.state(np.array([0.0]), t)[1][0] for t in times])
    assert np.abs(wall).max() < 1e-9 * scale / slab.z
    assert slab.period == pytest.approx(4.0 * 50e-6 / slab.c, rel=1e-12)


def test_half_a_period_later_the_fields_change_sign(layer):
    edges, sigma, u, t0 = layer
    slab = mirrored_slab(edges, sigma, u, t0, STEEL)
    x = 0.5 * (edges[:-1] + edges[1:])
    s, v = slab.state(x, t0 + 0.5 * slab.period)
    scale = np.abs(sigma).max()
    assert np.allclose(s, -sigma, rtol=0.0, atol=1e-9 * scale)
    assert np.allclose(v, -u, rtol=0.0, atol=1e-9 * scale / slab.z)
    s, v = slab.state(x, t0 + slab.period)
    assert np.allclose(s, sigma, rtol=0.0, atol=1e-9 * scale)
