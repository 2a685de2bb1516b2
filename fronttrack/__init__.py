"""Plane shock waves in solids by front tracking: the public Python API.

``import fronttrack as ft`` gives what a notebook needs::

    scene = ft.Scene([ft.Layer("Cu", "2 mm", velocity="1 km/s"),
                      ft.Layer("Al2024", "6 mm", bond="unbonded")],
                     t_end="3 us", probes=[ft.Probe("rear", "right")])
    solution = ft.run(scene)
    solution.history("rear").u

Quantities are SI numbers or strings with units, exactly as scene files write
them.  Every error a user can cause derives from ``ft.WavediagramError``.  The
figure functions (``ft.plot_xt``, ``ft.xt_and_sigma_u``, ...) load matplotlib on
first use, so importing ``fronttrack`` stays light.
"""

import importlib

from materials import MaterialError, State, StateOutOfRangeError, WavediagramError

from .design import (
    Window,
    WindowChoice,
    flyer_for_spall,
    one_dimensional_window,
    thickness_for_window,
    velocity_for,
    window_choice,
)
from .errors import SceneError
from .fits import FitExtrapolationWarning
from .impedance_match import MatchRow, match
from .material import material
from .runner import run
from .scene import Accuracy, Boundary, Layer, Probe, Scene, SpallCriterion
from .scene_file import load_scene, scene_from_dict
from .solution import History, Solution, SpallRecord
from .sweep import MonteCarlo, Table, monte_carlo, sweep
from .units import parse_quantity, to_si
from .windows import OpticalWindow, WindowRecord, optical_window, window_record

FIGURES = {name: "plotting" for name in (
    "Placed", "plot_free_surface_velocity", "plot_histories", "plot_peak_stress",
    "plot_profiles", "plot_sigma_rho", "plot_sigma_u", "plot_xt", "region_numbers",
    "save_standard_figures", "xt_and_sigma_u")} | {"plot_window_velocity": "window_figure"}
"""Figure functions and the module that holds each, imported on first use."""

__all__ = [
    "Accuracy", "Boundary", "FitExtrapolationWarning", "History", "Layer", "MatchRow",
    "MaterialError", "OpticalWindow",
    "Probe", "Scene", "SceneError", "Solution", "SpallCriterion", "SpallRecord", "State",
    "StateOutOfRangeError", "WavediagramError", "Window", "WindowChoice", "flyer_for_spall",
    "load_scene", "match", "material", "one_dimensional_window", "optical_window",
    "parse_quantity", "run", "scene_from_dict", "thickness_for_window", "to_si",
    "velocity_for", "window_choice", "window_record", "WindowRecord", "sweep", "monte_carlo",
    "Table", "MonteCarlo", *FIGURES,
]


def __getattr__(name: str):
    """The figure functions, imported (with matplotlib) when first asked for."""
    if name in FIGURES:
        module = importlib.import_module(f"{__name__}.{FIGURES[name]}")
        return getattr(module, name)
    raise AttributeError(f"module 'fronttrack' has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted(__all__)
