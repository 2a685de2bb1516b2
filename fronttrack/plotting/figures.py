"""The standard figure set of a solution, written as PNG files.

``save_standard_figures`` writes, at 150 dpi:

- ``xt.png``: the Lagrangian X–t diagram, shaded by stress, regions numbered;
- ``xt_eulerian.png``: the same at Eulerian positions;
- ``sigma_u.png``: the σ–u diagram with the same numbers as ``xt.png``;
- ``sigma_rho.png``: the σ–ρ diagram(s), same numbers;
- ``profiles.png``: stress profiles at five instants;
- ``probes.png``: stress and velocity histories at the probes (if any);
- ``free_surface.png``: the free-surface velocity record (the right surface,
  or the left one if only it is free);
- ``peak_stress.png``: peak stress vs position (attenuation);
- ``xt_su.png``: X–t and σ–u side by side (``xt_and_sigma_u``).

Every figure carries the standard region numbers, those of ``solution.json``
(``fronttrack.numbering``).  Figures are drawn from the solution as it is: the
region numbers, the two X–t geometries and the wave paths are computed once and
shared by the figures that need them.  For a large solution (``PARALLEL_REGIONS``
regions or more, lattice cells included) on a Linux machine with two or more cores, the
Eulerian diagram, the slowest, is drawn in a forked process while the others are
drawn in this one.  Figures are built without pyplot's global state, so a long
batch run does not accumulate open figures.
"""

from __future__ import annotations

import multiprocessing
import os
import pathlib
import sys
from collections.abc import Callable

from matplotlib.figure import Figure

from ..numbering import region_numbers
from ..outputs import IMAGE_FORMATS
from .placed import Placed
from .records import (
    plot_free_surface_velocity,
    plot_histories,
    plot_peak_stress,
    plot_profiles,
)
from .style import title_of
from .su import plot_sigma_rho, plot_sigma_u, sigma_rho_figsize
from .wave_paths import wave_paths
from .xt import XT_FIGSIZE, plot_xt
from .xt_geometry import eulerian_view, lagrangian_view

DPI = 150
PROFILE_FRACTIONS = (0.1, 0.3, 0.5, 0.7, 0.9)
"""Instants of the profile figure, as fractions of the scene's end time."""

PARALLEL_REGIONS = 20_000
"""Regions from which drawing the Eulerian diagram in a second process pays for the fork
(the demo has 81 000; a scene without lattices a few hundred)."""
FORKED = ("xt_eulerian",)
"""The figures drawn in the forked process."""

FIGURE_NAMES = ("xt", "xt_eulerian", "sigma_u", "sigma_rho", "profiles", "probes",
                "free_surface", "peak_stress", "xt_su")
"""The standard figures, in the order they are written (``probes`` only with probes)."""


def xt_and_sigma_u(solution, numbers=None, view=None, paths=None) -> tuple[Figure, Placed, Placed]:
    """A two-panel figure: the X–t diagram (left) and the σ–u diagram (right), same numbers.

    ``numbers`` as for ``plot_sigma_u`` (default: the standard numbers); ``view``
    and ``paths`` the Lagrangian geometry and wave paths, if already computed.
    Returns ``(figure, placed_xt, placed_su)``.
    """
    numbers = region_numbers(solution) if numbers is None else numbers
    figure = Figure(figsize=(13.0, 5.6))
    grid = figure.add_gridspec(1, 2, width_ratios=(1.25, 1.0), left=0.06, right=0.98,
                               bottom=0.1, top=0.84, wspace=0.3)
    ax_xt = figure.add_subplot(grid[0, 0])
    ax_su = figure.add_subplot(grid[0, 1])
    xt = plot_xt(solution, ax=ax_xt, numbers=numbers, view=view)
    su = plot_sigma_u(solution, ax=ax_su, numbers=numbers, paths=paths)
    ax_xt.set_title("X–t diagram", fontsize=10, pad=xt.title_pad)
    ax_su.set_title("σ–u diagram", fontsize=10, pad=xt.title_pad)
    figure.suptitle(title_of(solution, "wave diagram and states"), fontsize=11)
    return figure, xt, su


def _free_side(scene) -> str:
    if scene.right.kind != "free" and scene.left.kind == "free":
        return "left"
    return "right"


def _figure_makers(solution) -> dict[str, Callable[[], Figure]]:
    """A function drawing each standard figure, sharing numbers, geometry and paths."""
    numbers = region_numbers(solution)
    shared: dict[str, object] = {}

    def view():
        if "view" not in shared:
            shared["view"] = lagrangian_view(solution)
        return shared["view"]

    def paths():
        if "paths" not in shared:
            shared["paths"] = wave_paths(solution, set(numbers))
        return shared["paths"]

    def xt(eulerian=False):
        figure = Figure(figsize=XT_FIGSIZE)
        plot_xt(solution, ax=figure.add_subplot(), numbers=numbers, eulerian=eulerian,
                view=eulerian_view(solution) if eulerian else view())
        return figure

    def sigma_u():
        figure = Figure(figsize=(6.4, 5.0), layout="constrained")
        plot_sigma_u(solution, ax=figure.add_subplot(), numbers=numbers, paths=paths())
        return figure

    def sigma_rho():
        figure = Figure(figsize=sigma_rho_figsize(solution), layout="constrained")
        count = len({layer.material.name for layer in solution.scene.layers})
        axes = figure.subplots(1, count, sharey=True, squeeze=False)[0]
        plot_sigma_rho(solution, ax=list(axes), numbers=numbers, paths=paths())
        return figure

    def record(draw, size=(7.0, 4.4), rows=1):
        def make():
            figure = Figure(figsize=size, layout="constrained")
            axes = figure.subplots(rows, 1, sharex=True) if rows > 1 else figure.add_subplot()
            draw(tuple(axes) if rows > 1 else axes)
            return figure
        return make

    times = [f * solution.scene.t_end for f in PROFILE_FRACTIONS]
    makers = {
        "xt": xt, "xt_eulerian": lambda: xt(eulerian=True), "sigma_u": sigma_u,
        "sigma_rho": sigma_rho,
        "profiles": record(lambda ax: plot_profiles(solution, times, ax=ax)),
        "probes": record(lambda ax: plot_histories(solution, ax=ax), (7.0, 6.0), rows=2),
        "free_surface": record(lambda ax: plot_free_surface_velocity(
            solution, side=_free_side(solution.scene), ax=ax)),
        "peak_stress": record(lambda ax: plot_peak_stress(solution, ax=ax)),
        "xt_su": lambda: xt_and_sigma_u(solution, numbers, view(), paths())[0],
    }
    if not solution.scene.probes:
        del makers["probes"]
    return makers


def _parallel(solution, parallel: bool | None) -> bool:
    """Whether to fork: asked for, or (``None``) a large solution and two cores on Linux
    (where forking a process that has drawn with matplotlib's Agg backend is safe)."""
    if parallel is None:
        parallel = (solution.stats.get("regions", 0) >= PARALLEL_REGIONS
                    and (os.cpu_count() or 1) >= 2 and sys.platform.startswith("linux"))
    return parallel and "fork" in multiprocessing.get_all_start_methods()


def _draw(makers: dict, names, paths: dict, progress, count: int, order: dict,
          dpi: float = DPI) -> None:
    """Draw and write the figures ``names`` (raster formats at ``dpi``)."""
    for name in names:
        if progress is not None:
            progress(paths[name].name, order[name], count)
        makers[name]().savefig(paths[name], dpi=dpi)


def save_standard_figures(solution, outdir, prefix="", progress=None,
                          parallel: bool | None = None, image_format: str = "png",
                          dpi: float = DPI) -> list[pathlib.Path]:
    """Write the standard figures of ``solution`` into ``outdir``; return the paths written.

    File names are ``prefix`` followed by the names in the module docstring, with the
    extension of ``image_format`` (one of ``IMAGE_FORMATS``); ``dpi`` sets the
    resolution of raster formats.
    ``progress``, if given, is called as ``progress(name, index, count)`` before each
    figure is drawn (``index`` from 1; the forked ones are reported first).
    ``parallel``: draw ``FORKED`` in a forked process (``None``: when it pays, see the
    module docstring).
    """
    outdir = pathlib.Path(outdir)
    outdir.mkdir(parents=True, exist_ok=True)
    makers = _figure_makers(solution)
    if image_format not in IMAGE_FORMATS:
        raise ValueError(f"image_format must be one of {IMAGE_FORMATS}, got {image_format!r}")
    paths = {name: outdir / f"{prefix}{name}.{image_format}" for name in makers}
    order = {name: index for index, name in enumerate(makers, start=1)}
    forked = [name for name in makers if name in FORKED] if _parallel(solution, parallel) else []
    child = None
    if forked:
        child = multiprocessing.get_context("fork").Process(
            target=_draw, args=(makers, forked, paths, None, len(makers), order, dpi))
        child.start()
        if progress is not None:
            for name in forked:
                progress(f"{paths[name].name} (in a second process)", order[name],
                         len(makers))
    _draw(makers, [name for name in makers if name not in forked], paths, progress,
          len(makers), order, dpi)
    if child is not None:
        child.join()
        if child.exitcode != 0:  # the fork failed: draw its figures here
            _draw(makers, forked, paths, None, len(makers), order, dpi)
    return list(paths.values())
