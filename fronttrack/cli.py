"""The ``wavediagram`` command line.

    wavediagram demo [-o DIR]                 built-in plate-impact scene -> annotated figures
    wavediagram run SCENE.toml [-o DIR] [--json FILE] [--no-figures]
    wavediagram match FLYER VELOCITY LAYER... [--json FILE] [--mirrored] [--release PATH]
    wavediagram sweep SCENE.toml --set PATH=VALUES... -o DIR [--quantity NAME]...
    wavediagram materials

Bad input (a malformed scene, an unknown material, a quantity without units, a
state outside an equation of state, an output path that cannot be written) is
reported on one line naming the field, with exit status 2; output paths are checked
before the solve.  Ctrl-C exits with status 130 and leaves the outputs as they
were; an internal error (a bug) is one line with exit status 3.  No traceback is
shown (set ``WAVEDIAGRAM_DEBUG=1`` to see one).  Quantities on the command line
carry units ("1000 m/s", "60 s").
"""

from __future__ import annotations

import argparse
import csv
import dataclasses
import json
import os
import sys
import warnings
from importlib import resources
from pathlib import Path

from materials import WavediagramError, library

from . import viscoplastic_scene
from .cli_exports import (
    add_export_flags,
    check_export_flags,
    write_exports,
    write_window_records,
)
from .cli_sweep import add_sweep_command
from .fits import FitExtrapolationWarning
from .impedance_match import detonation_match, format_table, impedance_match, to_json_dict
from .outputs import OutputSet, check_output_dir, check_output_file
from .runner import run
from .scene_file import load_scene
from .tension_report import unlimited_tension
from .units import parse_quantity

USER_ERROR, INTERNAL_ERROR, INTERRUPTED = 2, 3, 130
"""Exit statuses: the input's fault, a bug, Ctrl-C (128 + SIGINT)."""


def main(argv: list[str] | None = None) -> int:
    """Run the command line ``argv``; return the exit status (0 on success)."""
    parser = _parser()
    args = parser.parse_args(argv)
    try:
        return args.handler(args)
    except WavediagramError as error:
        _say(f"wavediagram: error: {_one_line(error)}")
        return USER_ERROR
    except KeyboardInterrupt:
        _say("wavediagram: interrupted; no output written")
        return INTERRUPTED
    except Exception as error:
        if os.environ.get("WAVEDIAGRAM_DEBUG"):
            raise
        _say(f"wavediagram: internal error ({type(error).__name__}: {_one_line(error)}); "
             f"please report it with the scene (WAVEDIAGRAM_DEBUG=1 shows the traceback)")
        return INTERNAL_ERROR


def _say(line: str) -> None:
    """Print ``line`` on stderr on a line of its own (after any progress line)."""
    start = "\r\x1b[K" if sys.stderr.isatty() else ""
    print(f"{start}{line}", file=sys.stderr, flush=True)


def _one_line(error: BaseException) -> str:
    """The message of ``error`` on one line of at most 500 characters."""
    text = " ".join(str(error).split())
    return text if len(text) <= 500 else f"{text[:497]}..."


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
    run_.add_argument("--time-limit", default=None, metavar="TIME",
                      help='stop the solve after this long, e.g. "60 s", and write the '
                           'solution up to the time reached (overrides accuracy.max_seconds)')
    add_export_flags(run_)
    run_.set_defaults(handler=_run)

    match = commands.add_parser("match", help="impedance match a flyer onto a stack")
    match.add_argument("flyer", help="flyer material (library name)")
    match.add_argument("velocity", help='impact velocity with units, e.g. "1000 m/s", or '
                       '"detonation" when the flyer is an explosive (its CJ detonation)')
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
    check_output_dir(args.output, "-o")
    source = resources.files("fronttrack").joinpath("scenes", "demo.toml")
    with resources.as_file(source) as path:
        scene = load_scene(path)
    solution = _solve(scene, quiet=False)
    written = _write_outputs(solution, args.output, json_path=None, figures=True,
                             quiet=False)
    print(f"wrote {len(written)} files to {args.output}/ "
          f"(start with {args.output / 'xt_su.png'})")
    return 0


def _run(args) -> int:
    scene = load_scene(args.scene)
    check_export_flags(args)
    changes = {}
    if args.estimate_error:
        changes["estimate_error"] = True
    if args.time_limit is not None:
        changes["max_seconds"] = parse_quantity(args.time_limit, "time", "--time-limit")
    if changes:
        scene = dataclasses.replace(
            scene, accuracy=dataclasses.replace(scene.accuracy, **changes)).validate()
    if args.output is not None:
        check_output_dir(args.output, "-o")
        for name in ["solution.json"] * (args.json is None) + _probe_files(scene):
            check_output_file(args.output / name, "-o", inputs=(args.scene,))
    if args.json is not None:
        check_output_file(args.json, "--json", inputs=(args.scene,))
    if viscoplastic_scene.applies(scene):    # solved on its characteristic grid
        viscoplastic_scene.check_cli_options(args)
        written = viscoplastic_scene.write_outputs(viscoplastic_scene.run(scene), args.output,
                                                   args.json, figures=not args.no_figures)
        for path in [] if args.quiet else written:
            print(f"wrote {path}")
        return 0
    solution = _solve(scene, quiet=args.quiet)
    written = _write_outputs(solution, args.output, json_path=args.json,
                             figures=not args.no_figures, compact=args.json_compact,
                             quiet=args.quiet, image=(args.image_format, args.dpi))
    written += write_exports(solution, args)
    if not args.quiet:
        for path in written:
            print(f"wrote {path}")
    return 0


def _match(args) -> int:
    if args.json is not None:
        check_output_file(args.json, "--json")
    flyer = library.get(args.flyer)
    stack = [library.get(name) for name in args.layers]
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", FitExtrapolationWarning)
        if args.velocity == "detonation":  # an explosive's CJ detonation drives the stack
            rows = detonation_match(flyer, stack, release=args.release, mirrored=args.mirrored)
        else:
            velocity = parse_quantity(args.velocity, "velocity", "velocity")
            rows = impedance_match(flyer, velocity, stack, release=args.release,
                                   mirrored=args.mirrored)
    print(format_table(rows))
    for warning in caught:
        _say(f"wavediagram: warning: {warning.message}")
    if args.json is not None:
        with OutputSet() as outputs:
            outputs.temporary(args.json).write_text(json.dumps(to_json_dict(rows), indent=2))
            outputs.commit()
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
        rang = len(report["fragments_ringing"])
        rang = f", {rang} free fragments rang in closed form" if rang else ""
        carried = report["suppressed_spalls"]
        carried = (f" ({carried} fractures inside a zone or closer than "
                   f"{report['spall_spacing'] * 1e6:.3g} um to a plane carried as tension)"
                   if carried else "")
        print(f"{start}{scene.title or 'scene'}: {stats['events']} events, "
              f"{stats['fronts']} fronts, "
              f"{len(solution.spalls)} spall planes{carried}, "
              f"solved in {stats['solve_time']:.3g} s "
              f"(release: {report['release']}, {report['dropped_waves']} waves below "
              f"{report['negligible_stress']:.3g} Pa dropped, {report['coalesced_fronts']} "
              f"pairs of fronts closer than {report['coalesce_length'] * 1e6:.3g} um "
              f"coalesced, {len(report['ringing_replaced'])} ringing layers ended at their "
              f"limit{rang})", file=sys.stderr)
        balance = report["balance"]
        if balance["momentum_error"] is not None and balance["energy_error"] is not None:
            print(f"balance: momentum {balance['momentum_error']:.2g} of its content, energy "
                  f"{balance['energy_error']:+.2g} of the total (promised within "
                  f"{balance['promised']:.2g})", file=sys.stderr)
        for line in report["warnings"]:
            print(f"wavediagram: warning: {line}", file=sys.stderr)
        for found in unlimited_tension(solution):
            print(f"note: {found.message()}", file=sys.stderr)
        estimate = report.get("error_estimate")
        if estimate and "sigma" in estimate:
            print(f"estimated error of the probe records: {estimate['sigma'] / 1e6:.3g} MPa, "
                  f"{estimate['u']:.3g} m/s ({estimate['method']})", file=sys.stderr)
        elif estimate:
            print(f"error not estimated: {estimate['method']}", file=sys.stderr)
    stopped = solution.stats.get("stopped")
    if stopped:
        _say(f"wavediagram: warning: {stopped['reason']}; the solution ends at "
             f"t = {stopped['t'] * 1e6:.6g} us of {stopped['t_end'] * 1e6:.6g} us")
    return solution


def _probe_files(scene) -> list[str]:
    """The names of the probe CSV files a run of ``scene`` writes."""
    return [f"probe_{probe.name}.csv" for probe in scene.probes]


def _write_outputs(solution, outdir: Path | None, json_path: Path | None,
                   figures: bool, compact: bool = False, quiet: bool = False,
                   image: tuple[str, float] = ("png", 150.0)) -> list[Path]:
    """Write the requested files whole (``fronttrack.outputs.OutputSet``); their paths.
    ``compact``: the JSON without region polygons; ``image``: the figures' format and
    dpi.  Window records follow the set."""
    with OutputSet() as outputs:
        if outdir is not None:
            json_path = json_path or outdir / "solution.json"
            _write_probe_csvs(solution, outdir, outputs)
            if figures:
                from .plotting.figures import save_standard_figures

                save_standard_figures(solution, outputs.staging_dir(outdir),
                                      progress=None if quiet else _figure_progress,
                                      image_format=image[0], dpi=image[1])
        if json_path is not None:
            with outputs.temporary(json_path).open("w") as stream:
                solution.write_json(stream, polygons=not compact,
                                    progress=None if quiet else _json_progress(json_path))
        written = outputs.commit()
    if outdir is not None:
        written += write_window_records(solution, outdir, figures)
    return written


def _figure_progress(name: str, index: int, count: int) -> None:
    """Report each figure as it is drawn (on a terminal, on one rewritten line)."""
    start, end = ("\r\x1b[K", "") if sys.stderr.isatty() else ("", "\n")
    print(f"{start}  figure {index}/{count}: {name}", end=end if index < count else "\n",
          file=sys.stderr, flush=True)


def _json_progress(path: Path):
    """A ``progress(done, total)`` printing the share of ``path`` written on stderr."""
    terminal = sys.stderr.isatty()
    start, end = ("\r\x1b[K", "") if terminal else ("", "\n")

    def progress(done: int, total: int) -> None:
        print(f"{start}  writing {path}: {100 * done // max(total, 1)} % of {total} records",
              end=end if done < total else "\n", file=sys.stderr, flush=True)

    return progress


def _write_probe_csvs(solution, outdir: Path, outputs: OutputSet) -> None:
    """One CSV per probe: the step history (each row a step start time and its state)."""
    for history, file_name in zip(solution.probe_histories().values(),
                                  _probe_files(solution.scene), strict=True):
        with outputs.temporary(outdir / file_name).open("w", newline="") as handle:
            writer = csv.writer(handle)
            writer.writerow(["t_s", "sigma_Pa", "u_m_per_s", "rho_kg_per_m3"])
            for t, state in zip(history.t, history.states, strict=True):
                rho = 1.0 / state.v if state.v > 0 else ""
                writer.writerow([repr(float(t)), repr(state.sigma), repr(state.u), rho])

if __name__ == "__main__":
    sys.exit(main())
