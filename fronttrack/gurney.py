"""Gurney's estimate of the terminal velocity of explosive-driven plates, and the velocity
of a plate in a run to compare with it.

Gurney's model (R. W. Gurney, BRL Report 405, 1943; the plane geometries as collected by
J. E. Kennedy, Sandia SC-RR-70-790, 1970, and P. W. Cooper, *Explosives Engineering*,
1996, ch. 27) assumes that a charge of mass ``C`` per unit area turns an energy ``E`` per
unit mass into kinetic energy of the plates and the products, the products keeping a
uniform density and a velocity linear in position between the faces.  Momentum (where
no wall takes it) and energy then fix the plate velocity ``V`` in terms of the Gurney
velocity ``sqrt(2E)``:

- infinitely tamped (a rigid wall behind the charge, plate ``M``): the products move
  from rest at the wall to ``V`` at the plate, ``E C = M V^2/2 + C V^2/6``,

      V = sqrt(2E) (M/C + 1/3)^(-1/2);

- symmetric sandwich (a plate ``M`` on each face of the charge ``C``): by symmetry the
  mid-plane is at rest and each half is a tamped charge ``C/2``,

      V = sqrt(2E) (2M/C + 1/3)^(-1/2);

- open-faced sandwich (plate ``M`` on one face, the other free): the products' rest plane
  sits where the momentum balances, and

      V = sqrt(2E) [((1 + 2M/C)^3 + 1) / (6 (1 + M/C)) + M/C]^(-1/2).

The model claims a few per cent for ``0.1 < M/C < 10`` or so (Kennedy).  For products that
expand without limit (all three geometries), the whole heat of detonation ``q`` ends as
kinetic energy, so ``E = q`` is the asymptotic energy of the products' equation of state
(``gurney_energy``); the model's error is then that of its velocity profile alone.
"""

from __future__ import annotations

import math

from .errors import SceneError

GEOMETRIES = ("open-faced", "tamped", "symmetric")


def gurney_velocity(geometry: str, mass_ratio: float, energy: float) -> float:
    """Gurney's terminal plate velocity (m/s).

    Parameters
    ----------
    geometry : str
        ``"open-faced"``, ``"tamped"`` or ``"symmetric"`` (module docstring).
    mass_ratio : float
        ``M/C``: one plate's mass per unit area over the whole charge's.
    energy : float [J/kg]
        The Gurney energy ``E`` (``sqrt(2E)`` is the Gurney velocity).
    """
    if not (math.isfinite(mass_ratio) and mass_ratio > 0.0):
        raise SceneError(f"gurney: mass_ratio M/C must be > 0, got {mass_ratio!r}")
    if not (math.isfinite(energy) and energy > 0.0):
        raise SceneError(f"gurney: energy must be > 0 J/kg, got {energy!r}")
    r = mass_ratio
    if geometry == "open-faced":
        factor = ((1.0 + 2.0 * r) ** 3 + 1.0) / (6.0 * (1.0 + r)) + r
    elif geometry == "tamped":
        factor = r + 1.0 / 3.0
    elif geometry == "symmetric":
        factor = 2.0 * r + 1.0 / 3.0
    else:
        raise SceneError(f"gurney: geometry must be one of {', '.join(GEOMETRIES)}, "
                         f"got {geometry!r}")
    return math.sqrt(2.0 * energy / factor)


def gurney_energy(explosive) -> float:
    """``E`` (J/kg) of products that expand without limit: their heat of detonation ``q``
    (``e + q -> 0`` at vacuum, so all of it becomes kinetic energy)."""
    return explosive.products.q


def plate_velocity(solution, layer: int, t: float) -> float:
    """Mean velocity (m/s) of layer ``layer`` at time ``t``: its momentum over its mass."""
    lo = sum(s.thickness for s in solution.scene.layers[:layer])
    hi = lo + solution.scene.layers[layer].thickness
    tol = 1e-9 * solution.scene.length
    momentum = mass = 0.0
    for x0, x1, record in solution.cells_at(t):
        if x0 >= lo - tol and x1 <= hi + tol:
            m = record.material.rho0 * (x1 - x0)
            momentum += m * record.state.u
            mass += m
    return momentum / mass
