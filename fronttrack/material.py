"""Materials for the Python API: a library entry by name, or a model from its fields.

``material("Cu")`` is the library's copper (``materials.library``).
``material("MyPMMA", model="mie-gruneisen", rho0="1186 kg/m3", c0="2.6 km/s", s=1.52,
gamma0=0.97)`` builds a material as a scene file's ``[materials.MyPMMA]`` table
does; quantities are SI numbers or strings with units (``fronttrack.units``).
"""

from __future__ import annotations

from typing import Any

from materials import Material, MaterialError
from materials.library import FIELD_DIMENSIONS, get, material_from_spec

from .errors import SceneError
from .units import to_si


def material(name: str, **spec: Any) -> Material:
    """The library material ``name``, or, with fields, the material they specify.

    Parameters
    ----------
    name : str
        A library name or alias (``wavediagram materials`` lists them), or the name
        to give a material built from ``spec``.
    **spec
        ``model`` and its fields (``materials.library.MODELS``); dimensional fields
        are SI numbers or strings with units.

    Raises
    ------
    SceneError
        An unknown name, a missing or bad field (the message names it).
    """
    try:
        if not spec:
            return get(name)
        values = {key: value if key not in FIELD_DIMENSIONS
                  else to_si(value, FIELD_DIMENSIONS[key], f"material.{key}")
                  for key, value in spec.items()}
        return material_from_spec(name, values)
    except MaterialError as error:
        raise SceneError(f"material: {error}") from None
