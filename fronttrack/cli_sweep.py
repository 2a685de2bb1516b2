"""``wavediagram sweep``: a scene run at every combination of field values, from the shell.

    wavediagram sweep SCENE.toml --set layer.0.velocity="200..1200 m/s/11" -o DIR
        [--set PATH=VALUES ...] [--quantity NAME ...] [--backend serial|processes|dask]
        [--workers N]

``VALUES`` is a range ``FROM..TO UNIT/COUNT`` (``COUNT`` evenly spaced values, both
ends included) or a comma-separated list (``"1 mm,2 mm"``); paths are those of
``fronttrack.parameters``, quantities those of ``fronttrack.sweep``.  Writes
``DIR/sweep.csv`` and ``DIR/sweep.json``; a point that fails is a row with its error.
"""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np

from .errors import SceneError
from .scene_file import load_scene
from .sweep import BACKENDS, sweep

_RANGE = re.compile(r"\s*(?P<lo>[-+.\deE]+)\s*\.\.\s*(?P<hi>[-+.\deE]+)\s*(?P<unit>.*?)\s*"
                    r"/\s*(?P<count>\d+)\s*\Z")


def add_sweep_command(commands) -> None:
    """Add the ``sweep`` subcommand to the ``wavediagram`` subparsers ``commands``."""
    parser = commands.add_parser("sweep", help="run a scene at every combination of field "
                                               "values and tabulate the results")
    parser.add_argument("scene", type=Path, help="scene file (TOML)")
    parser.add_argument("--set", action="append", required=True, dest="assignments",
                        metavar="PATH=VALUES",
                        help='a field and its values: "layer.0.velocity=200..1200 m/s/11" '
                             'or "layer.1.thickness=1 mm,2 mm" (repeat for a grid)')
    parser.add_argument("-o", "--output", type=Path, required=True,
                        help="directory for sweep.csv and sweep.json")
    parser.add_argument("--quantity", action="append", dest="quantities", metavar="NAME",
                        help="an output column (repeatable; default: spall and tension, "
                             "and peak stress and velocity at every probe)")
    parser.add_argument("--backend", choices=BACKENDS, default="processes",
                        help="where the points run (default: %(default)s)")
    parser.add_argument("--workers", type=int, default=None,
                        help="processes for the processes backend (default: CPU count)")
    parser.set_defaults(handler=run_sweep_command)


def sweep_values(text: str, path: str) -> list[str]:
    """The values of ``--set PATH=text``: a range ``FROM..TO UNIT/COUNT`` or a list."""
    found = _RANGE.match(text)
    if found is None:
        values = [item.strip() for item in text.split(",")]
        if not all(values):
            raise SceneError(f"--set {path}: expected FROM..TO UNIT/COUNT or a comma-"
                             f"separated list of values, got {text!r}")
        return values
    try:
        lo, hi = float(found["lo"]), float(found["hi"])
    except ValueError:
        raise SceneError(f"--set {path}: bad range {text!r}") from None
    count = int(found["count"])
    if not 1 <= count <= 100_000:
        raise SceneError(f"--set {path}: COUNT must be in 1..100000, got {count}")
    unit = f" {found['unit']}" if found["unit"] else ""
    return [f"{value!r}{unit}" for value in np.linspace(lo, hi, count).tolist()]


def run_sweep_command(args) -> int:
    """The ``sweep`` subcommand: run, write the table, say what was written."""
    scene = load_scene(args.scene)
    parameters = {}
    for assignment in args.assignments:
        path, equals, text = assignment.partition("=")
        if not equals:
            raise SceneError(f"--set: expected PATH=VALUES, got {assignment!r}")
        parameters[path.strip()] = sweep_values(text, path.strip())
    quantities = args.quantities or [
        "max_tension", "spall_count", "spall_x", "spall_t", "events",
        *(f"{name}:{probe.name}" for probe in scene.probes for name in ("peak_sigma",
                                                                         "peak_u"))]
    table = sweep(scene, parameters, quantities, backend=args.backend, workers=args.workers)
    args.output.mkdir(parents=True, exist_ok=True)
    csv_path = table.to_csv(args.output / "sweep.csv")
    json_path = args.output / "sweep.json"
    table.to_json(json_path)
    failed = sum(row["error"] is not None for row in table.rows)
    print(f"{len(table.rows)} points, {failed} failed; wrote {csv_path} and {json_path}")
    return 0
