"""Equations of state, wave curves and the Riemann solver.

A material's wave curves answer "which states can one wave reach from here";
``solve_contact`` and ``solve_boundary`` intersect them.  Nothing here knows
about fronts or events.
"""

from .base import Material
from .elastic_plastic import ElasticPlastic, ElasticPlasticWaveCurve
from .errors import MaterialError, NoSolutionError, StateOutOfRangeError, WavediagramError
from .finite_plastic import FinitePlastic, FinitePlasticWaveCurve
from .hull import HullWaveCurve
from .ideal_gas import IdealGas
from .library import available, get, material_from_spec
from .linear_elastic import LinearElastic
from .mie_gruneisen import MieGruneisen
from .phase_change import PhaseChangeSolid, PhaseChangeWaveCurve
from .porous import PorousSolid, PorousWaveCurve
from .riemann import RiemannSolution, solve_boundary, solve_contact
from .saturating_plastic import SaturatingPlastic
from .state import LEFT, RIGHT, State
from .waves import Fan, Shock

__all__ = [
    "LEFT", "RIGHT", "ElasticPlastic", "ElasticPlasticWaveCurve", "Fan", "FinitePlastic",
    "FinitePlasticWaveCurve", "HullWaveCurve", "IdealGas",
    "LinearElastic", "Material", "MaterialError", "MieGruneisen", "NoSolutionError",
    "PhaseChangeSolid", "PhaseChangeWaveCurve", "PorousSolid", "PorousWaveCurve",
    "RiemannSolution", "SaturatingPlastic", "Shock", "State", "StateOutOfRangeError",
    "available", "get",
    "material_from_spec", "solve_boundary", "solve_contact", "WavediagramError",
]
