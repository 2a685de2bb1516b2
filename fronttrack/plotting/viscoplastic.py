"""Figures of a viscoplastic scene solved on its characteristic grid.

``xt.png``: the Lagrangian X–t diagram of the viscoplastic layer shaded by stress (each
grid level's nodes, the odd columns filled by linear interpolation in X), the
precursor's path on its first transit, and the flyer, window and faces marked;
``records.png``: the particle-velocity records of the scene's probes and the
precursor's amplitude against distance.  Position in mm, time in µs, stress in GPa,
velocity in m/s.
"""

from __future__ import annotations

import pathlib

import numpy as np
from matplotlib.colors import Normalize
from matplotlib.figure import Figure

from .stress_shading import light_cmap
from .style import GPA, MM, SIGMA_LABEL, T_LABEL, U_LABEL, US, X_LABEL, title_of

DPI = 150


def stress_map(run) -> np.ndarray:
    """The grid's stress ``[level, column]`` (Pa) with the columns a level has no node
    in filled by linear interpolation between its neighbours."""
    filled = run.sigma.copy()
    columns = np.arange(filled.shape[1])
    for level in filled:
        known = np.isfinite(level)
        level[~known] = np.interp(columns[~known], columns[known], level[known])
    return filled


def plot_xt(solution, ax) -> None:
    """The viscoplastic layer's X–t stress map on ``ax``."""
    run = solution.run
    sigma = stress_map(run) * GPA
    top = max(float(np.max(np.abs(sigma))), 1e-12)
    x0, x1 = solution.origin * MM, (solution.origin + run.thickness) * MM
    t1 = (sigma.shape[0] - 1) * run.dt * US
    image = ax.imshow(sigma, origin="lower", aspect="auto", extent=(x0, x1, 0.0, t1),
                      cmap=light_cmap(), norm=Normalize(-top, top), interpolation="nearest")
    ax.figure.colorbar(image, ax=ax, label=SIGMA_LABEL)
    times = np.arange(run.precursor_x.size) * run.dt * US
    ax.plot(x0 + run.precursor_x * MM, times, color="black", lw=1.0,
            label="elastic precursor (first transit)")
    for x in (x0, x1):
        ax.axvline(x, color="#555555", lw=0.8, ls="--")
    ax.set_xlim(x0, x1)
    ax.set_ylim(0.0, t1)
    ax.set_xlabel(X_LABEL)
    ax.set_ylabel(T_LABEL)
    ax.legend(loc="upper left", fontsize=8)
    ax.set_title(title_of(solution, f"X–t diagram of {run.material.name} "
                                    f"(characteristic grid)"), fontsize=10)


def plot_records(solution, ax_u, ax_p) -> None:
    """Probe velocity records on ``ax_u``, the precursor amplitude on ``ax_p``."""
    for name, record in solution.probe_histories().items():
        ax_u.plot(record.t * US, record.u, lw=1.2, label=name)
    ax_u.set_xlabel(T_LABEL)
    ax_u.set_ylabel(U_LABEL)
    ax_u.set_title("probe records", fontsize=10)
    if solution.scene.probes:
        ax_u.legend(fontsize=8)
    run = solution.run
    ax_p.plot((solution.origin + run.precursor_x) * MM, run.precursor_sigma * GPA,
              color="black", lw=1.2, label="precursor amplitude")
    ax_p.axhline(run.material.hel * GPA, color="#c0392b", ls="--", lw=1.0,
                 label=f"HEL {run.material.hel * GPA:.3g} GPa")
    ax_p.set_xlabel(X_LABEL)
    ax_p.set_ylabel(SIGMA_LABEL)
    ax_p.set_title("precursor decay", fontsize=10)
    ax_p.legend(fontsize=8)


def save_figures(solution, outdir) -> list[pathlib.Path]:
    """Write ``xt.png`` and ``records.png`` of ``solution`` into ``outdir``."""
    outdir = pathlib.Path(outdir)
    outdir.mkdir(parents=True, exist_ok=True)
    figure = Figure(figsize=(8.0, 6.0), layout="constrained")
    plot_xt(solution, figure.add_subplot())
    paths = [outdir / "xt.png", outdir / "records.png"]
    figure.savefig(paths[0], dpi=DPI)
    figure = Figure(figsize=(11.0, 4.5), layout="constrained")
    ax_u, ax_p = figure.subplots(1, 2)
    plot_records(solution, ax_u, ax_p)
    figure.savefig(paths[1], dpi=DPI)
    return paths
