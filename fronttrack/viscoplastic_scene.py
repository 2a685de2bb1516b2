"""Scenes with an elastic–viscoplastic layer, run on its characteristic grid.

The relaxation of a viscoplastic solid goes on between fronts, which the engine's
constant regions cannot carry, so ``fronttrack.run`` hands such a scene to
``characteristics.viscoplastic_grid`` instead of the engine.  The scenes it takes:

- one viscoplastic layer (the *target*), at rest and unstressed;
- at its left: an elastic flyer layer (``linear-elastic``, moving, its left face free)
  or nothing, with a piston (``left.kind = "velocity"``, one constant velocity);
- at its right: nothing (``right.kind = "free"``) or one elastic window layer at rest,
  thick enough that its far face sends nothing back before ``t_end``.

Anything else is a ``SceneError`` naming the field.  The result, ``GridSolution``, has
the records a user asks of a ``Solution``: ``history(probe)`` (``t``, ``sigma``, ``u``,
``rho``), ``probe_histories()``, the precursor's amplitude against distance, an
accuracy report and a JSON form; ``write_outputs`` writes the probe CSVs,
``solution.json`` and the figures (``xt.png``: the target's X–t stress map with the
precursor's path; ``records.png``: the probes' velocity records).

Grid spacing: ``dX = C0 tau / 4`` (a quarter of the distance the precursor runs in one
relaxation time), between ``MIN_CELLS`` and ``MAX_CELLS`` cells; with a flyer the count
is chosen in that neighbourhood to put the flyer's round trip nearest a whole number of
boundary steps.  Probes read the node column nearest them (within ``dX / 2``), every
``2 dt``; a window probe reads the target's rear face delayed by its depth over the
window's sound speed (a right-going simple wave: the window is elastic and nothing
returns from its far face).
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from characteristics.viscoplastic_grid import (
    ElasticFlyer,
    ViscoplasticRun,
    run_impact,
    run_layer,
)
from materials import LinearElastic
from materials.viscoplastic import Viscoplastic

from .errors import SceneError
from .outputs import OutputSet
from .scene import Scene

MIN_CELLS, MAX_CELLS = 200, 2000
"""Bounds on the grid's cell count across the viscoplastic layer."""
CELLS_PER_RELAXATION = 4.0
"""Cells per distance ``C0 tau`` the precursor runs in one relaxation time."""


def applies(scene: Scene) -> bool:
    """Whether ``scene`` has a viscoplastic layer (and so runs on the grid)."""
    return any(isinstance(layer.material, Viscoplastic) for layer in scene.layers)


@dataclass(frozen=True)
class GridRecord:
    """A probe's record: ``t`` (s) and ``sigma`` (Pa), ``u`` (m/s), ``rho`` (kg/m^3) at
    each sample, linear in between (as a ``History``: ``sigma_end``, ``u_end`` are the
    values each piece ends at, the next sample's)."""

    t: np.ndarray
    sigma: np.ndarray
    u: np.ndarray
    rho: np.ndarray

    @property
    def sigma_end(self) -> np.ndarray:
        return np.append(self.sigma[1:], self.sigma[-1:])

    @property
    def u_end(self) -> np.ndarray:
        return np.append(self.u[1:], self.u[-1:])


@dataclass
class GridSolution:
    """A viscoplastic scene solved on the characteristic grid (module docstring).

    ``run`` is the grid's ``ViscoplasticRun``; ``origin`` (m) the Lagrangian position of
    the target's left face in the stack; ``stats`` and ``accuracy_report`` as for a
    ``Solution`` (the report says what is exact and what is integrated).
    """

    scene: Scene
    run: ViscoplasticRun
    origin: float
    window: LinearElastic | None
    stats: dict = field(default_factory=dict)
    accuracy_report: dict = field(default_factory=dict)
    spalls: tuple = ()

    def history(self, probe: str) -> GridRecord:
        """The record of the probe named ``probe``."""
        found = [p for p in self.scene.probes if p.name == probe]
        if not found:
            names = ", ".join(p.name for p in self.scene.probes) or "none"
            raise SceneError(f"probe: no probe named {probe!r} (probes: {names})")
        x = _position(self.scene, found[0].at)
        run, mat = self.run, self.run.material
        rear = self.origin + run.thickness
        if x <= rear * (1.0 + 1e-12):
            local = min(max(x - self.origin, 0.0), run.thickness)
            t, sigma = run.history(local, "sigma")
            _, u = run.history(local, "u")
            _, plastic = run.history(local, "plastic_strain")
            rho = mat.rho0 / (1.0 - mat.strain(sigma, plastic))
            return GridRecord(t, sigma, u, rho)
        t, sigma = run.history(run.thickness, "sigma")
        _, u = run.history(run.thickness, "u")
        window = self.window
        rho = window.rho0 / (1.0 - sigma / (window.rho0 * window.C**2))
        return GridRecord(t + (x - rear) / window.C, sigma, u, rho)

    def probe_histories(self) -> dict[str, GridRecord]:
        """``{probe name: record}`` of every probe of the scene."""
        return {p.name: self.history(p.name) for p in self.scene.probes}

    def to_json_dict(self) -> dict:
        """The solution as JSON-ready data (SI units)."""
        run = self.run
        return {
            "solver": "characteristic grid (characteristics.viscoplastic_grid)",
            "title": self.scene.title,
            "t_end": self.scene.t_end,
            "target": {"material": run.material.name, "x0": self.origin,
                       "x1": self.origin + run.thickness, "C0": run.material.C0,
                       "hel": run.material.hel},
            "grid": {"dx": run.dx, "dt": run.dt, "cells": int(round(run.thickness / run.dx))},
            "precursor": {"x": (self.origin + run.precursor_x).tolist(),
                          "sigma": run.precursor_sigma.tolist()},
            "probes": {name: {"t": r.t.tolist(), "sigma": r.sigma.tolist(),
                              "u": r.u.tolist(), "rho": r.rho.tolist()}
                       for name, r in self.probe_histories().items()},
            "stats": self.stats,
            "accuracy": self.accuracy_report,
        }

    def write_json(self, stream, **_ignored) -> None:
        """Write ``to_json_dict`` to ``stream``."""
        json.dump(self.to_json_dict(), stream, indent=1)


def run(scene: Scene) -> GridSolution:
    """Solve a viscoplastic ``scene`` on the characteristic grid (module docstring)."""
    layers = scene.layers
    index = _target_index(scene)
    target = layers[index]
    mat = target.material
    if scene.spall_criterion is not None:
        raise SceneError("spall: a viscoplastic scene takes no spall criterion (the grid "
                         "has no fracture)")
    for i, layer in enumerate(layers):
        if layer.stress != 0.0 or layer.initial is not None:
            raise SceneError(f"layer[{i}].stress: a viscoplastic scene starts unstressed")
        if i != index and not isinstance(layer.material, LinearElastic):
            raise SceneError(f"layer[{i}].material: beside a viscoplastic layer only a "
                             f"linear-elastic flyer or window, got {layer.material.name}")
    if target.velocity != 0.0:
        raise SceneError(f"layer[{index}].velocity: the viscoplastic layer starts at rest")
    if index > 1 or len(layers) > index + 2:
        raise SceneError("layer: a viscoplastic scene is [flyer,] viscoplastic layer "
                         "[, window]")
    flyer = layers[0] if index == 1 else None
    window = layers[index + 1] if len(layers) > index + 1 else None
    t_end = scene.t_end
    if scene.right.kind != "free":
        raise SceneError(f"right.kind: a viscoplastic scene needs a free right end, "
                         f"got {scene.right.kind!r}")
    window_impedance = 0.0
    if window is not None:
        if window.velocity != 0.0:
            raise SceneError(f"layer[{index + 1}].velocity: the window starts at rest")
        echo = target.thickness / mat.C0 + 2.0 * window.thickness / window.material.C
        if echo < t_end:
            raise SceneError(f"layer[{index + 1}].thickness: the window's far face would "
                             f"send a wave back at {echo * 1e6:.4g} us, before t_end "
                             f"{t_end * 1e6:.4g} us (the grid takes it as semi-infinite)")
        window_impedance = window.material.impedance
    _check_probes(scene, flyer)
    cells = _cells(mat, target.thickness)
    if flyer is None:
        velocity = _piston_velocity(scene)
        result = run_layer(mat, target.thickness, velocity, t_end, cells, window_impedance)
    else:
        if scene.left.kind != "free":
            raise SceneError(f"left.kind: a flyer's left face must be free, got "
                             f"{scene.left.kind!r}")
        elastic = flyer.material
        driver = ElasticFlyer(elastic.impedance, 2.0 * flyer.thickness / elastic.C,
                              flyer.velocity, bonded=target.bond == "bonded")
        cells = _cells_for_trip(mat, target.thickness, cells, driver.round_trip)
        result = run_impact(mat, target.thickness, driver, t_end, cells, window_impedance)
    origin = flyer.thickness if flyer is not None else 0.0
    report = _report(result, driver.round_trip if flyer is not None else None)
    stats = {"solver": "viscoplastic characteristic grid", "cells": cells,
             "levels": int(result.sigma.shape[0]), "events": 0, "fronts": 0}
    return GridSolution(scene, result, origin, None if window is None else window.material,
                        stats, report)


def _target_index(scene: Scene) -> int:
    found = [i for i, layer in enumerate(scene.layers)
             if isinstance(layer.material, Viscoplastic)]
    if len(found) > 1:
        raise SceneError(f"layer[{found[1]}].material: a scene can hold one viscoplastic "
                         f"layer (the grid solves one)")
    return found[0]


def _piston_velocity(scene: Scene) -> float:
    left = scene.left
    values = {value for _, value in left.history} if left.kind == "velocity" else set()
    if len(values) != 1:
        raise SceneError("left.kind: a viscoplastic layer without a flyer needs a piston "
                         "of one constant velocity (left.kind = \"velocity\", one value)")
    return values.pop()


def _check_probes(scene: Scene, flyer) -> None:
    start = flyer.thickness if flyer is not None else 0.0
    for probe in scene.probes:
        if _position(scene, probe.at) < start * (1.0 - 1e-12):
            raise SceneError(f"probe[{probe.name}].at: the grid records the viscoplastic "
                             f"layer and the window, not the flyer (from "
                             f"{start * 1e3:.6g} mm)")


def _position(scene: Scene, at) -> float:
    return {"left": 0.0, "right": scene.length}.get(at, at) if isinstance(at, str) else at


def _cells(mat: Viscoplastic, thickness: float) -> int:
    """Even cell count with ``dX <= C0 tau / CELLS_PER_RELAXATION`` within the bounds."""
    if mat.relaxation_time == 0.0 or math.isinf(mat.relaxation_time):
        wanted = MIN_CELLS
    else:
        wanted = thickness * CELLS_PER_RELAXATION / (mat.C0 * mat.relaxation_time)
    cells = int(min(max(math.ceil(wanted), MIN_CELLS), MAX_CELLS))
    return cells + cells % 2


def _cells_for_trip(mat: Viscoplastic, thickness: float, cells: int, trip: float) -> int:
    """The even count in ``[cells, 1.125 cells]`` whose boundary step ``2 dt`` divides the
    flyer's round trip most nearly (relative to ``dt``)."""
    def miss(n: int) -> float:
        steps = trip * n * mat.C0 / (2.0 * thickness)
        return abs(steps - max(1, round(steps)))

    return min(range(cells, cells + cells // 8 + 2, 2), key=miss)


def _report(result: ViscoplasticRun, trip: float | None) -> dict:
    report = {
        "method": "characteristic grid: characteristics, precursor jump and boundary "
                  "conditions exact; relaxation by the trapezoidal rule (second order in "
                  "dt)",
        "dx": result.dx, "dt": result.dt,
        "probe_position": "node column nearest the probe (within dx/2), every 2 dt",
        "warnings": [],
    }
    if trip is not None:
        report["flyer_round_trip"] = {"flyer": trip, "grid": result.round_trip}
    return report


CLI_OPTIONS = {"--dt": lambda a: a.dt is not None, "--peaks": lambda a: a.peaks,
               "--estimate-error": lambda a: a.estimate_error,
               "--time-limit": lambda a: a.time_limit is not None,
               "--format": lambda a: a.image_format != "png"}
"""Options of ``wavediagram run`` that the grid's outputs do not serve."""


def check_cli_options(args) -> None:
    """Refuse, naming it, an option of ``wavediagram run`` a grid solution cannot serve."""
    for option, given in CLI_OPTIONS.items():
        if given(args):
            raise SceneError(f"{option}: not available for a scene with a viscoplastic "
                             f"layer (solved on the characteristic grid)")


def write_outputs(solution: GridSolution, outdir: Path | None, json_path: Path | None,
                  figures: bool) -> list[Path]:
    """Probe CSVs (the engine's columns), the JSON and the figures, written whole."""
    with OutputSet() as outputs:
        if outdir is not None:
            json_path = json_path or outdir / "solution.json"
            for name, record in solution.probe_histories().items():
                rows = ["t_s,sigma_Pa,u_m_per_s,rho_kg_per_m3"] + [
                    f"{t!r},{s!r},{u!r},{r!r}" for t, s, u, r in
                    zip(record.t.tolist(), record.sigma.tolist(), record.u.tolist(),
                        record.rho.tolist(), strict=True)]
                outputs.temporary(outdir / f"probe_{name}.csv").write_text(
                    "\n".join(rows) + "\n")
            if figures:
                from .plotting.viscoplastic import save_figures

                save_figures(solution, outputs.staging_dir(outdir))
        if json_path is not None:
            with outputs.temporary(json_path).open("w") as stream:
                solution.write_json(stream)
        return outputs.commit()
