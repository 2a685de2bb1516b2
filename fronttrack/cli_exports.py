"""Exports ``wavediagram run`` writes on request, beside its standard outputs.

- ``--dt TIME``: every probe record also on a uniform time step,
  ``probe_<name>_resampled.csv`` (``fronttrack.exports.resampled``);
- ``--peaks``: peak stress, peak tension and impulse against depth,
  ``peaks.csv`` and ``peaks.json`` (``--stations N`` of them);
- ``--json-compact``: the solution JSON without region polygons (the bulk of a
  large run's JSON);
- always, for an interface probe with an optical window: ``window_<name>.csv`` and
  its figure (``fronttrack.windows``).
"""

from __future__ import annotations

from pathlib import Path

from .errors import SceneError
from .exports import peak_table, resampled, write_csv, write_json
from .outputs import IMAGE_FORMATS
from .units import parse_quantity
from .windows import window_record


def add_export_flags(parser) -> None:
    """Add the export options to the ``run`` subcommand's ``parser``."""
    parser.add_argument("--dt", default=None, metavar="TIME",
                        help='also write each probe record every TIME, e.g. "10 ns"')
    parser.add_argument("--peaks", action="store_true",
                        help="write peak stress, tension and impulse against depth")
    parser.add_argument("--stations", type=int, default=101,
                        help="stations across the stack for --peaks (default: %(default)s)")
    parser.add_argument("--json-compact", action="store_true",
                        help="leave the region polygons out of the solution JSON")
    parser.add_argument("--format", choices=IMAGE_FORMATS, default="png", dest="image_format",
                        help="figure file format (default: %(default)s)")
    parser.add_argument("--dpi", type=float, default=150.0,
                        help="resolution of PNG figures, dots per inch (default: %(default)s)")


def check_export_flags(args) -> None:
    """Refuse bad export options before the solve (``SceneError`` naming the option)."""
    if args.dt is not None:
        args.dt = parse_quantity(args.dt, "time", "--dt")
        if not args.dt > 0.0:
            raise SceneError(f"--dt: must be > 0 s, got {args.dt!r}")
    if (args.dt is not None or args.peaks) and args.output is None:
        raise SceneError("--dt and --peaks write into the output directory: give -o DIR")
    if not 20.0 <= args.dpi <= 1200.0:
        raise SceneError(f"--dpi: must be in 20..1200, got {args.dpi:g}")
    if not 2 <= args.stations <= 100_000:
        raise SceneError(f"--stations: must be in 2..100000, got {args.stations}")


def write_exports(solution, args) -> list[Path]:
    """Write the exports ``args`` asks for into ``args.output``; return the paths."""
    written = []
    if args.dt is not None:
        for name, history in solution.probe_histories().items():
            written.append(write_csv(resampled(history, args.dt),
                                     args.output / f"probe_{name}_resampled.csv"))
    if args.peaks:
        table = peak_table(solution, args.stations)
        written.append(write_csv(table, args.output / "peaks.csv"))
        written.append(write_json(table, args.output / "peaks.json"))
    return written


def write_window_records(solution, outdir: Path, figures: bool) -> list[Path]:
    """Per interface probe with an optical window: ``window_<name>.csv`` (samples of the
    true and the apparent velocity, jumps as repeated times) and its figure."""
    written = []
    for probe in solution.scene.probes:
        if probe.window is None:
            continue
        record = window_record(solution, probe.name)
        columns = {"t_s": record.t, "u_m_per_s": record.u,
                   "u_apparent_m_per_s": record.u_apparent, "u_far_face_m_per_s": record.u_far}
        written.append(write_csv(columns, outdir / f"window_{probe.name}.csv"))
        if figures:
            from matplotlib.figure import Figure

            from .window_figure import plot_window_velocity

            figure = Figure(figsize=(7.0, 4.4), layout="constrained")
            plot_window_velocity(solution, probe.name, ax=figure.add_subplot())
            figure.savefig(outdir / f"window_{probe.name}.png", dpi=130)
            written.append(outdir / f"window_{probe.name}.png")
    return written
