"""The standard figure set of a solution, written as PNG files.

``save_standard_figures`` writes, at 150 dpi:

- ``xt.png``: the Lagrangian X–t diagram, shaded by stress, regions numbered;
- ``xt_eulerian.png``: the same at Eulerian positions;
- ``sigma_u.png``: the σ–u diagram with the same numbers as ``xt.png``;
- ``sigma_v.png``: the σ–ρ diagram(s), same numbers;
- ``profiles.png``: stress profiles at five instants;
- ``probes.png``: stress and velocity histories at the probes (if any);
- ``free_surface.png``: the free-surface velocity record (the right surface,
  or the left one if only it is free);
- ``peak_stress.png``: peak stress vs position (attenuation);
- ``xt_su.png``: X–t and σ–u side by side (``xt_and_sigma_u``).

Figures are built without pyplot's global state, so a long batch run does
not accumulate open figures.
"""

from __future__ import annotations

import pathlib

from matplotlib.figure import Figure

from .records import (
    plot_free_surface_velocity,
    plot_histories,
    plot_peak_stress,
    plot_profiles,
)
from .style import title_of
from .su import plot_sigma_u, plot_sigma_v
from .xt import XT_FIGSIZE, placed_labels, plot_xt, title_pad

DPI = 150
PROFILE_FRACTIONS = (0.1, 0.3, 0.5, 0.7, 0.9)
"""Instants of the profile figure, as fractions of the scene's end time."""


def xt_and_sigma_u(solution) -> Figure:
    """A two-panel figure: the X–t diagram (left) and the σ–u diagram (right), same numbers."""
    figure = Figure(figsize=(13.0, 5.6))
    grid = figure.add_gridspec(1, 2, width_ratios=(1.25, 1.0), left=0.06, right=0.98,
                               bottom=0.1, top=0.84, wspace=0.3)
    ax_xt = figure.add_subplot(grid[0, 0])
    ax_su = figure.add_subplot(grid[0, 1])
    plot_xt(solution, ax=ax_xt)
    plot_sigma_u(solution, ax=ax_su, numbers=placed_labels(ax_xt))
    pad = title_pad(ax_xt)
    ax_xt.set_title("X–t diagram", fontsize=10, pad=pad)
    ax_su.set_title("σ–u diagram", fontsize=10, pad=pad)
    figure.suptitle(title_of(solution, "wave diagram and states"), fontsize=11)
    return figure


def _free_side(scene) -> str:
    if scene.right.kind != "free" and scene.left.kind == "free":
        return "left"
    return "right"


def save_standard_figures(solution, outdir, prefix="") -> list[pathlib.Path]:
    """Write the standard figures of ``solution`` into ``outdir``; return the paths written.

    File names are ``prefix`` followed by the names in the module docstring.
    """
    outdir = pathlib.Path(outdir)
    outdir.mkdir(parents=True, exist_ok=True)
    written: list[pathlib.Path] = []

    def save(figure: Figure, name: str) -> None:
        path = outdir / f"{prefix}{name}"
        figure.savefig(path, dpi=DPI)
        written.append(path)

    figure = Figure(figsize=XT_FIGSIZE)
    ax_xt = plot_xt(solution, ax=figure.add_subplot())
    numbers = placed_labels(ax_xt)
    save(figure, "xt.png")

    figure = Figure(figsize=XT_FIGSIZE)
    plot_xt(solution, ax=figure.add_subplot(), eulerian=True)
    save(figure, "xt_eulerian.png")

    figure = Figure(figsize=(6.4, 5.0), layout="constrained")
    plot_sigma_u(solution, ax=figure.add_subplot(), numbers=numbers)
    save(figure, "sigma_u.png")

    names = {layer.material.name for layer in solution.scene.layers}
    figure = Figure(figsize=(3.4 * len(names) + 1.4, 5.0), layout="constrained")
    axes = figure.subplots(1, len(names), sharey=True, squeeze=False)[0]
    plot_sigma_v(solution, ax=list(axes), numbers=numbers)
    figure.suptitle(title_of(solution, "σ–ρ diagram"), fontsize=10)
    save(figure, "sigma_v.png")

    figure = Figure(figsize=(7.0, 4.4), layout="constrained")
    times = [f * solution.scene.t_end for f in PROFILE_FRACTIONS]
    plot_profiles(solution, times, ax=figure.add_subplot())
    save(figure, "profiles.png")

    if solution.scene.probes:
        figure = Figure(figsize=(7.0, 6.0), layout="constrained")
        plot_histories(solution, ax=tuple(figure.subplots(2, 1, sharex=True)))
        save(figure, "probes.png")

    figure = Figure(figsize=(7.0, 4.4), layout="constrained")
    plot_free_surface_velocity(solution, side=_free_side(solution.scene),
                               ax=figure.add_subplot())
    save(figure, "free_surface.png")

    figure = Figure(figsize=(7.0, 4.4), layout="constrained")
    plot_peak_stress(solution, ax=figure.add_subplot())
    save(figure, "peak_stress.png")

    save(xt_and_sigma_u(solution), "xt_su.png")
    return written
