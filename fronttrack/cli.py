"""The ``wavediagram`` command line.

    wavediagram demo [-o DIR]                 built-in plate-impact scene -> annotated figures
    wavediagram run SCENE.toml [-o DIR] [--json FILE] [--no-figures]
    wavediagram match FLYER VELOCITY LAYER... [--json FILE] [--mirrored] [--release PATH]
    wavediagram sweep SCENE.toml --set PATH=VALUES... -o DIR [--quantity NAME]...
    wavediagram materials

Bad input (a malformed scene, an unknown material, a quantity without units, a
state outside an equation of state) is reported on one line naming the field,
with exit status 2.  Quantities on the command line carry units ("1000 m/s").
"""

from __future__ import annotations

import argparse
import csv
import dataclasses
import json
import sys
from importlib import resources
from pathlib import Path

from materials import WavediagramError, library

from .cli_exports import (
    add_export_flags,
    check_export_flags,
    write_exports,
    write_window_records,
)
from .cli_sweep import add_sweep_command
from .impedance_match import format_table, impedance_match, to_json_dict
from .runner import run
from .scene_file import load_scene
from .tension_report import unlimited_tension
from .units import parse_quantity

USER_ERRORS = (WavediagramError, FileNotFoundError)
"""Errors that are the input's fault: reported on one line, exit status 2."""


def main(argv: list[str] | None = None) -> int:
    parser = _parser()
    args = parser.parse_args(argv)
    try:
        return args.handler(args)
    except USER_ERRORS as error:
        print(f"wavediagram: error: {error}", file=sys.stderr)
        return 2


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="wavediagram",
        description="Exact X-t and stress-particle-velocity diagrams of plane shock waves "
                    "in solids, by front tracking.")
    commands = parser.add_subparsers(dest="command", required=True)

    demo = commands.add_parser("demo", help="run the built-in Cu-on-Al plate impact and "
                                            "write its annotated diagrams")
    demo.add_argument("-o", "--output", default="wavediagram-demo", type=Path,
                      help="output directory (default: %(default)s)")
    demo.set_defaults(handler=_demo)

    run_ = commands.add_parser("run", help="run a TOML scene")
    run_.add_argument("scene", type=Path, help="scene file (TOML, quantities with units)")
    run_.add_argument("-o", "--output", type=Path, default=None,
                      help="directory for figures, solution.json and probe CSVs")
    run_.add_argument("--json", type=Path, default=None, help="write the solution JSON here")
    run_.add_argument("--no-figures", action="store_true", help="skip the figures")
    run_.add_argument("--quiet", action="store_true", help="no progress or summary output")
    run_.add_argument("--estimate-error", action="store_true",
                      help="run again at half the ray step and report the estimated error")
    add_export_flags(run_)
    run_.set_defaults(handler=_run)

    match = commands.add_parser("match", help="impedance match a flyer onto a stack")
    match.add_argument("flyer", help="flyer material (library name)")
    match.add_argument("velocity", help='impact velocity with units, e.g. "1000 m/s"')
    match.add_argument("layers", nargs="+", help="target layers, first struck first")
    match.add_argument("--json", type=Path, default=None, help="write the states as JSON")
    match.add_argument("--release", choices=("isentrope", "hugoniot"), default="isentrope",
                       help="release path where a wave unloads (default: %(default)s)")
    match.add_argument("--mirrored", action="store_true",
                       help="use the mirrored-Hugoniot shortcut for reflected waves "
                            "(labelled as such)")
    match.set_defaults(handler=_match)

    add_sweep_command(commands)

    mats = commands.add_parser("materials", help="list the material library with sources")
    mats.set_defaults(handler=_materials)
    return parser


# --- commands ---------------------------------------------------------------------
def _demo(args) -> int:
    source = resources.files("fronttrack").joinpath("scenes", "demo.toml")
    with resources.as_file(source) as path:
        scene = load_scene(path)
    solution = _solve(scene, quiet=False)
    written = _write_outputs(solution, args.output, json_path=None, figures=True)
    print(f"wrote {len(written)} files to {args.output}/ "
          f"(start with {args.output / 'xt_su.png'})")
    return 0


def _run(args) -> int:
    scene = load_scene(args.scene)
    check_export_flags(args)
    if args.estimate_error:
        scene = dataclasses.replace(
            scene, accuracy=dataclasses.replace(scene.accuracy, estimate_error=True))
    solution = _solve(scene, quiet=args.quiet)
    written = _write_outputs(solution, args.output, json_path=args.json,
                             figures=not args.no_figures, compact=args.json_compact,
                             quiet=args.quiet)
    written += write_exports(solution, args)
    if not args.quiet:
        for path in written:
            print(f"wrote {path}")
    return 0


def _match(args) -> int:
    flyer = library.get(args.flyer)
    velocity = parse_quantity(args.velocity, "velocity", "velocity")
    stack = [library.get(name) for name in args.layers]
    rows = impedance_match(flyer, velocity, stack, release=args.release, mirrored=args.mirrored)
    print(format_table(rows))
    if args.json is not None:
        args.json.write_text(json.dumps(to_json_dict(rows), indent=2))
        print(f"wrote {args.json}")
    return 0


def _materials(args) -> int:
    print(library.listing())
    return 0


# --- helpers ------------------------------------------------------------------------
def _solve(scene, quiet: bool):
    # On a terminal the progress line rewrites itself; in a log each report is a line.
    terminal = sys.stderr.isatty()
    start, end = ("\r\x1b[K", "") if terminal else ("", "\n")

    def progress(events: int, t: float) -> None:
        print(f"{start}  {events} events, t = {t * 1e6:.4g} of {scene.t_end * 1e6:.4g} us",
              end=end, file=sys.stderr, flush=True)

    solution = run(scene, progress=None if quiet else progress)
    if not quiet:
        stats, report = solution.stats, solution.accuracy_report
        print(f"{start}{scene.title or 'scene'}: {stats['events']} events, "
              f"{stats['fronts']} fronts, "
              f"{len(solution.spalls)} spall planes, solved in {stats['solve_time']:.3g} s "
              f"(release: {report['release']}, {report['dropped_waves']} waves below "
              f"{report['negligible_stress']:.3g} Pa dropped)", file=sys.stderr)
        for found in unlimited_tension(solution):
            print(f"note: {found.message()}", file=sys.stderr)
        estimate = report.get("error_estimate")
        if estimate:
            print(f"estimated error of the probe records: {estimate['sigma'] / 1e6:.3g} MPa, "
                  f"{estimate['u']:.3g} m/s ({estimate['method']})", file=sys.stderr)
    return solution


def _write_outputs(solution, outdir: Path | None, json_path: Path | None,
                   figures: bool, compact: bool = False, quiet: bool = False) -> list[Path]:
    written = []
    if outdir is not None:
        outdir.mkdir(parents=True, exist_ok=True)
        json_path = json_path or outdir / "solution.json"
        written += _write_probe_csvs(solution, outdir)
        written += write_window_records(solution, outdir, figures)
        if figures:
            from .plotting.figures import save_standard_figures

            written += save_standard_figures(solution, outdir,
                                             progress=None if quiet else _figure_progress)
    if json_path is not None:
        json_path.parent.mkdir(parents=True, exist_ok=True)
        json_path.write_text(json.dumps(solution.to_dict(polygons=not compact),
                                        separators=(",", ":")))
        written.append(json_path)
    return written


def _figure_progress(name: str, index: int, count: int) -> None:
    """Report each figure as it is drawn (on a terminal, on one rewritten line)."""
    start, end = ("\r\x1b[K", "") if sys.stderr.isatty() else ("", "\n")
    print(f"{start}  figure {index}/{count}: {name}", end=end if index < count else "\n",
          file=sys.stderr, flush=True)


def _write_probe_csvs(solution, outdir: Path) -> list[Path]:
    """One CSV per probe: the step history (each row a step start time and its state)."""
    written = []
    for name, history in solution.probe_histories().items():
        path = outdir / f"probe_{name}.csv"
        with path.open("w", newline="") as handle:
            writer = csv.writer(handle)
            writer.writerow(["t_s", "sigma_Pa", "u_m_per_s", "rho_kg_per_m3"])
            for t, state in zip(history.t, history.states, strict=True):
                rho = 1.0 / state.v if state.v > 0 else ""
                writer.writerow([repr(float(t)), repr(state.sigma), repr(state.u), rho])
        written.append(path)
    return written


if __name__ == "__main__":
    sys.exit(main())
