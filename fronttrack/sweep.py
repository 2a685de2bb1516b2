"""Sweeps and Monte Carlo: one scene run at many values of its fields.

``sweep(scene, {"layer.0.velocity": ["200 m/s", "400 m/s"]}, outputs=[...])``
runs every combination of the values (paths of ``fronttrack.parameters``) and
returns a ``Table``: one row per point, a column per parameter and per output,
and an ``error`` column holding the message of a point that failed (a state
beyond an equation of state, say) instead of stopping the sweep.  Points run
serially, in processes (``concurrent.futures``, the default) or on a Dask
cluster (``backend="dask"``, the optional extra ``wavediagram[distributed]``);
every backend runs the same code on the same scene, so their tables are equal
bit for bit.

``monte_carlo`` samples material and scene fields from normal distributions
(optionally correlated, e.g. ``c0`` with ``s`` of a Us–up fit) and returns the
quantiles of each output.

Outputs are named (``OUTPUTS``; ``NAME:PROBE`` for a probe's record) or are
module-level functions of a ``Solution`` (they must pickle to run in processes).
"""

from __future__ import annotations

import concurrent.futures
import csv
import itertools
import json
import math
import numbers
import sys
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from materials.library import FIELD_DIMENSIONS

from .design import one_dimensional_window
from .errors import SceneError
from .parameters import field_value, portable, restored, with_field
from .runner import run
from .scene import Scene
from .solution import Solution, station
from .units import to_si

BACKENDS = ("serial", "processes", "dask")


def _max_tension(solution: Solution) -> float:
    found = solution.max_tension()
    return 0.0 if found is None else -found["sigma"]


def _first_spall(solution: Solution, key: str) -> float:
    if not solution.spalls:
        return math.nan
    return getattr(min(solution.spalls, key=lambda s: s.t), key)


OUTPUTS: dict[str, Callable[[Solution], float]] = {
    "max_tension": _max_tension,
    "spall_count": lambda solution: len(solution.spalls),
    "spall_x": lambda solution: _first_spall(solution, "x"),
    "spall_t": lambda solution: _first_spall(solution, "t"),
    "events": lambda solution: solution.stats["events"],
    "momentum_error": lambda solution: solution.conservation()["momentum_relative_error"],
    "energy_error": lambda solution: solution.conservation()["energy_relative_error"],
}
"""Scalar outputs of a run: the largest tension (Pa, positive), the number of spall
planes, the first one's X (m) and time (s, NaN without one), events, and the relative
momentum and energy balance."""

PROBE_OUTPUTS: dict[str, Callable[[Solution, str], float]] = {
    "peak_sigma": lambda solution, probe: float(solution.history(probe).sigma.max()),
    "peak_u": lambda solution, probe: float(
        max(solution.history(probe).u.max(), solution.history(probe).u_end.max())),
    "final_u": lambda solution, probe: float(solution.history(probe).u_end[-1]),
    "arrival": lambda solution, probe: one_dimensional_window(solution, probe).first_shock,
    "window": lambda solution, probe: one_dimensional_window(solution, probe).duration,
}
"""Outputs of one probe, written ``NAME:PROBE``: peak stress (Pa), peak and final
particle velocity (m/s), the first shock's arrival and the one-dimensional window (s)."""


def output_name(output: str | Callable) -> str:
    """The column name of an output (a function's name for a function)."""
    return output if isinstance(output, str) else output.__name__


def evaluate(solution: Solution, output: str | Callable) -> float:
    """The value of one output of ``solution``; raises ``SceneError`` for an unknown name."""
    if callable(output):
        return output(solution)
    check_output(output)
    name, _, probe = output.partition(":")
    return PROBE_OUTPUTS[name](solution, probe) if probe else OUTPUTS[name](solution)


@dataclass
class Table:
    """Rows of a sweep: ``columns`` in order, each row a dict (``error`` is ``None`` or the
    message of the point's failure).  Values are SI."""

    columns: list[str]
    rows: list[dict[str, Any]] = field(default_factory=list)

    def column(self, name: str) -> list:
        """The values of column ``name``, one per row."""
        return [row[name] for row in self.rows]

    def to_csv(self, path: str | Path) -> Path:
        """Write the table as CSV (floats in full precision); return the path."""
        path = Path(path)
        with path.open("w", newline="") as handle:
            writer = csv.DictWriter(handle, fieldnames=self.columns)
            writer.writeheader()
            for row in self.rows:
                writer.writerow({k: repr(v) if isinstance(v, float) else v
                                 for k, v in row.items()})
        return path

    def to_json(self, path: str | Path | None = None) -> str:
        """The table as JSON (``{"columns": [...], "rows": [...]}``; NaN as null); written
        to ``path`` if given."""
        rows = [{k: None if isinstance(v, float) and math.isnan(v) else v
                 for k, v in row.items()} for row in self.rows]
        text = json.dumps({"columns": self.columns, "rows": rows}, default=_plain)
        if path is not None:
            Path(path).write_text(text)
        return text

    def to_pandas(self):
        """A ``pandas.DataFrame`` of the table (needs pandas)."""
        import pandas

        return pandas.DataFrame(self.rows, columns=self.columns)


def _plain(value: Any) -> Any:
    """JSON for values of parameters that are not plain (a material, numpy scalars)."""
    if isinstance(value, np.generic):
        return value.item()
    return getattr(value, "name", repr(value))


def _point(task: tuple[bytes, dict[str, Any], list]) -> dict[str, Any]:
    """Run one point: the scene with its assignments, then its outputs (a worker's job)."""
    data, assignment, outputs = task
    row: dict[str, Any] = dict(assignment)
    try:
        scene = restored(data)
        for path, value in assignment.items():
            scene = with_field(scene, path, value)
        solution = run(scene)
        for output in outputs:
            row[output_name(output)] = evaluate(solution, output)
        row["error"] = None
    except Exception as error:  # noqa: BLE001 - a failing point is a row, not an abort
        for output in outputs:
            row.setdefault(output_name(output), math.nan)
        row["error"] = f"{type(error).__name__}: {error}"
    return row


def run_points(scene: Scene, assignments: Sequence[dict[str, Any]], outputs: Sequence,
               backend: str = "processes", workers: int | None = None, client=None,
               progress: Callable[[int, int], None] | None = None) -> Table:
    """Run ``scene`` at each assignment (``{path: value}``) and tabulate ``outputs``.

    ``backend``: ``"serial"``, ``"processes"`` (``workers`` processes, default the
    CPU count) or ``"dask"`` (``client``, a ``dask.distributed.Client``; a local
    cluster is started when none is given).  ``progress(done, total)`` is called as
    points finish; by default a line on a terminal's standard error.
    """
    if backend not in BACKENDS:
        raise SceneError(f"backend: must be one of {BACKENDS}, got {backend!r}")
    outputs = [outputs] if isinstance(outputs, str) or callable(outputs) else list(outputs)
    for output in outputs:
        if isinstance(output, str):
            check_output(output, scene)
    data = portable(scene)
    tasks = [(data, dict(a), outputs) for a in assignments]
    progress = progress if progress is not None else _terminal_progress()
    names = list(assignments[0]) if assignments else []
    table = Table(columns=[*names, *map(output_name, outputs), "error"])
    if backend == "serial":
        for task in tasks:
            table.rows.append(_point(task))
            progress(len(table.rows), len(tasks))
    elif backend == "processes":
        with concurrent.futures.ProcessPoolExecutor(max_workers=workers) as pool:
            futures = [pool.submit(_point, task) for task in tasks]
            for done, _ in enumerate(concurrent.futures.as_completed(futures), 1):
                progress(done, len(tasks))
            table.rows = [future.result() for future in futures]
    else:
        table.rows = _dask_points(tasks, client, progress)
    return table


def check_output(output: str, scene: Scene | None = None) -> None:
    """Raise ``SceneError`` now for an output name no run could evaluate (with ``scene``,
    also for a ``NAME:PROBE`` whose probe is not a station of it)."""
    name, _, probe = output.partition(":")
    if probe and name in PROBE_OUTPUTS:
        if scene is not None:
            try:
                station(scene, probe)
            except SceneError as error:
                raise SceneError(f"outputs: {output!r}: {error}") from None
        return
    if not probe and name in OUTPUTS:
        return
    raise SceneError(f"outputs: unknown output {output!r} (use one of "
                     f"{', '.join(OUTPUTS)}, or NAME:PROBE with NAME one of "
                     f"{', '.join(PROBE_OUTPUTS)})")


def _dask_points(tasks: list, client, progress) -> list[dict[str, Any]]:
    """Run the points on a Dask cluster (``client``, or a local one started for them)."""
    try:
        from dask.distributed import Client, as_completed
    except ImportError:
        raise SceneError('backend: "dask" needs dask.distributed (pip install '
                         '"wavediagram[distributed]")') from None
    own = client is None
    client = Client(processes=True) if own else client
    try:
        futures = client.map(_point, tasks, pure=False)
        for done, _ in enumerate(as_completed(futures), 1):
            progress(done, len(tasks))
        return client.gather(futures)
    finally:
        if own:
            client.close()


def _terminal_progress() -> Callable[[int, int], None]:
    """A progress line on standard error when it is a terminal, else nothing."""
    if not sys.stderr.isatty():
        return lambda done, total: None

    def show(done: int, total: int) -> None:
        end = "\n" if done == total else ""
        print(f"\r\x1b[K  {done}/{total} points", end=end, file=sys.stderr, flush=True)

    return show


def sweep(scene: Scene, parameters: dict[str, Sequence], outputs: Sequence,
          backend: str = "processes", workers: int | None = None, client=None,
          progress: Callable[[int, int], None] | None = None) -> Table:
    """Run ``scene`` at every combination of ``parameters`` and tabulate ``outputs``.

    Parameters
    ----------
    scene : Scene
        The scene to vary.
    parameters : dict
        ``{path: values}``: paths of ``fronttrack.parameters`` (``"layer.0.velocity"``,
        ``"material.Cu.c0"``, ...), values SI numbers or strings with units.
    outputs : sequence
        Names of ``OUTPUTS``, ``NAME:PROBE`` of ``PROBE_OUTPUTS``, or functions of a
        ``Solution``.
    backend, workers, client, progress
        As ``run_points``.

    Returns
    -------
    Table
        A row per combination (the last parameter varying fastest).

    Raises
    ------
    SceneError
        Before any run: a path that names no field, values that are not a list, a
        value its field cannot take, or an output no run could evaluate.
    """
    names = list(parameters)
    for name in names:  # an unknown path or a value no run could take fails before any run
        values = parameters[name]
        if isinstance(values, (str, bytes)) or not isinstance(values, Sequence | np.ndarray):
            raise SceneError(f"parameters[{name}]: expected a list of values, "
                             f"got {values!r:.60}")
        field_value(scene, name)
        for value in values:
            with_field(scene, name, value)
    combos = itertools.product(*(list(parameters[name]) for name in names))
    assignments = [dict(zip(names, combo, strict=True)) for combo in combos]
    return run_points(scene, assignments, outputs, backend, workers, client, progress)


@dataclass(frozen=True)
class MonteCarlo:
    """Result of ``monte_carlo``: every sample (``table``), and per output its ``mean``,
    standard deviation ``std`` and ``quantiles`` (``{q: value}``), over the samples
    that ran (``failed`` counts the others)."""

    table: Table
    mean: dict[str, float]
    std: dict[str, float]
    quantiles: dict[str, dict[float, float]]
    failed: int


def monte_carlo(scene: Scene, uncertainties: dict[str, float | str], outputs: Sequence,
                samples: int = 200, seed: int = 0,
                correlations: dict[tuple[str, str], float] | None = None,
                quantiles: Sequence[float] = (0.05, 0.5, 0.95), backend: str = "processes",
                workers: int | None = None, client=None) -> MonteCarlo:
    """How do the outputs move when fields are uncertain?

    Each field at a path of ``uncertainties`` is drawn from a normal distribution
    about its value in ``scene`` with the standard deviation given (SI, or a string
    with the field's unit; a dimensionless field takes a number).  ``correlations``
    maps pairs of paths to their correlation coefficient (``c0`` and ``s`` of one
    fit are strongly anticorrelated).  ``samples`` draws from
    ``numpy.random.default_rng(seed)``; with zero uncertainty every sample is the
    scene itself and the quantiles are its deterministic outputs.
    """
    if isinstance(samples, bool) or not isinstance(samples, numbers.Integral) or samples < 1:
        raise SceneError(f"samples: must be an integer >= 1, got {samples!r}")
    paths = list(uncertainties)
    nominal = np.array([_numeric(scene, p) for p in paths])
    sigma = np.array([_deviation(scene, p, uncertainties[p]) for p in paths])
    corr = np.eye(len(paths))
    for (a, b), r in (correlations or {}).items():
        if a not in paths or b not in paths or not -1.0 <= r <= 1.0:
            raise SceneError(f"correlations: ({a!r}, {b!r}) must pair two uncertain fields "
                             f"with a coefficient in -1..1, got {r!r}")
        corr[paths.index(a), paths.index(b)] = corr[paths.index(b), paths.index(a)] = r
    normal = np.random.default_rng(seed).standard_normal((samples, len(paths)))
    draws = nominal + (normal @ _correlated_root(corr).T) * sigma
    assignments = [{p: float(value) for p, value in zip(paths, row, strict=True)}
                   for row in draws]
    table = run_points(scene, assignments, outputs, backend, workers, client)
    ran = [row for row in table.rows if row["error"] is None]
    stats_mean, stats_std, stats_q = {}, {}, {}
    for output in map(output_name, outputs):
        values = np.array([row[output] for row in ran], dtype=float)
        stats_mean[output] = float(values.mean()) if len(values) else math.nan
        stats_std[output] = float(values.std(ddof=1)) if len(values) > 1 else 0.0
        stats_q[output] = {q: float(np.quantile(values, q)) if len(values) else math.nan
                           for q in quantiles}
    return MonteCarlo(table=table, mean=stats_mean, std=stats_std, quantiles=stats_q,
                      failed=len(table.rows) - len(ran))


def _numeric(scene: Scene, path: str) -> float:
    """The value (SI) of the numeric field at ``path``; raises ``SceneError`` otherwise."""
    value = field_value(scene, path)
    if isinstance(value, bool) or not isinstance(value, int | float | np.number):
        raise SceneError(f"uncertainties[{path}]: not a numeric field (value {value!r})")
    return float(value)


def _deviation(scene: Scene, path: str, value: float | str) -> float:
    """A standard deviation in SI: a string is read in the unit of its field."""
    dimension = "dimensionless"
    if isinstance(value, str):
        head, last = path.split(".", 1)[0], path.rsplit(".", 1)[-1]
        dimension = (getattr(scene, head).kind if head in ("left", "right")
                     else FIELD_DIMENSIONS.get(last) or _SCENE_DIMENSIONS.get(last))
    deviation = to_si(value, dimension or "dimensionless", f"uncertainties[{path}]")
    if deviation < 0.0:
        raise SceneError(f"uncertainties[{path}]: must be >= 0, got {deviation!r}")
    return deviation


_SCENE_DIMENSIONS = {"thickness": "length", "velocity": "velocity", "stress": "stress",
                     "t_end": "time"}


def _correlated_root(corr: np.ndarray) -> np.ndarray:
    """A matrix ``L`` with ``L L^T = corr`` (Cholesky; eigen-decomposition when singular)."""
    try:
        return np.linalg.cholesky(corr)
    except np.linalg.LinAlgError:
        values, vectors = np.linalg.eigh(corr)
        return vectors * np.sqrt(np.clip(values, 0.0, None))
