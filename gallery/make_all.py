"""Regenerate the whole gallery and rewrite ``gallery/README.md``.

    python gallery/make_all.py

Runs every ``gallery/NN_short_name.py`` in its own process (in order), collects
the ``[stats]`` line of each solve and the ``[figure] path | caption`` line of
each figure, and writes the README: every figure with its one-line caption, the
command to regenerate, and a table of the solves (events, fronts, spall planes,
solve time) with each script's wall time.  Exits with status 1 if a script
fails (the README then lists the failure).
"""

from __future__ import annotations

import ast
import os
import re
import subprocess
import sys
import time
from pathlib import Path

HERE = Path(__file__).absolute().parent
ROOT = HERE.parent
README = HERE / "README.md"
SCRIPT = re.compile(r"^\d\d_[a-z0-9_]+\.py$")
STATS = re.compile(r"^\[stats\] (?P<label>.*): events=(?P<events>\d+) fronts=(?P<fronts>\d+) "
                   r"spalls=(?P<spalls>\d+) solve=(?P<solve>[\d.]+)s$")
FIGURE = re.compile(r"^\[figure\] (?P<path>\S+) \| (?P<caption>.*)$")

INTRO = """\
# Gallery: plane shock waves in solids

Teaching figures made with the front-tracking engine of this repository: every
diagram is the exact solution of its scene (shocks are jumps, fans are tracked
as rays on the isentrope), plotted in mm, µs, GPa (compression positive) and
m/s. Each script `gallery/NN_short_name.py` reads its scene
`gallery/scenes/NN_short_name*.toml` (the scene-file format of
`fronttrack/scene_file.py`), runs it and writes its figures to
`gallery/figures/`; every script also runs alone, e.g.
`python gallery/04_rigid_wall.py`.

Regenerate everything (figures, this README and the table at the end) with

    python gallery/make_all.py

Spall uses the engine's instantaneous threshold. Where it would cascade into
many fractures, a scene sets `spall_spacing` in `[accuracy]`; the caption then
says so and how much tension was carried instead.
"""


def scripts() -> list[Path]:
    """The gallery scripts, in order."""
    return sorted(p for p in HERE.iterdir() if SCRIPT.match(p.name))


def title_of(script: Path) -> str:
    """First line of a script's docstring."""
    doc = ast.get_docstring(ast.parse(script.read_text(encoding="utf-8"))) or script.stem
    return doc.strip().splitlines()[0].rstrip(".")


def run(script: Path) -> dict:
    """Run one script; return its figures, stats, wall time and failure (if any)."""
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(p for p in (str(ROOT), env.get("PYTHONPATH")) if p)
    env.setdefault("MPLBACKEND", "Agg")
    start = time.perf_counter()
    done = subprocess.run([sys.executable, str(script)], cwd=ROOT, env=env,
                          capture_output=True, text=True)
    wall = time.perf_counter() - start
    figures, stats = [], []
    for line in done.stdout.splitlines():
        if (match := FIGURE.match(line)) is not None:
            figures.append((match["path"], match["caption"]))
        elif (match := STATS.match(line)) is not None:
            stats.append(match.groupdict())
    failure = None
    if done.returncode != 0:
        lines = done.stderr.strip().splitlines()
        failure = lines[-1] if lines else f"exit status {done.returncode}"
    return {"figures": figures, "stats": stats, "wall": wall, "failure": failure}


def readme(results: dict[Path, dict], total: float) -> str:
    """The text of ``gallery/README.md``."""
    out = [INTRO]
    for script, result in results.items():
        out.append(f"## {script.stem}: {title_of(script)}\n")
        out.append(f"Script `gallery/{script.name}`"
                   + _scene_list(script) + f"; {result['wall']:.1f} s.\n")
        if result["failure"]:
            out.append(f"**Failed:** `{result['failure']}`\n")
        for path, caption in result["figures"]:
            relative = Path(path).relative_to("gallery").as_posix()
            name = Path(path).stem
            out.append(f"![{name}]({relative})\n")
            out.append(f"{caption}\n")
    out.append("## Solve statistics\n")
    out.append(f"Last regenerated with `python gallery/make_all.py` in {total:.0f} s "
               f"(all scripts, one after the other).\n")
    out.append("| script | solve | events | fronts | spall planes | solve time (s) |")
    out.append("|---|---|---:|---:|---:|---:|")
    for script, result in results.items():
        for row in result["stats"]:
            out.append(f"| {script.stem} | {row['label']} | {row['events']} | {row['fronts']} "
                       f"| {row['spalls']} | {float(row['solve']):.2f} |")
    out.append("")
    out.append("| script | wall time (s) |")
    out.append("|---|---:|")
    for script, result in results.items():
        flag = " (failed)" if result["failure"] else ""
        out.append(f"| {script.stem} | {result['wall']:.1f}{flag} |")
    out.append(f"| **total** | **{total:.1f}** |")
    return "\n".join(out) + "\n"


def _scene_list(script: Path) -> str:
    scenes = sorted((HERE / "scenes").glob(f"{script.stem}*.toml"))
    if not scenes:
        return " (scene built in the script)"
    names = ", ".join(f"`scenes/{p.name}`" for p in scenes)
    return f", scene{'s' if len(scenes) > 1 else ''} {names}"


def main() -> int:
    results = {}
    start = time.perf_counter()
    for script in scripts():
        print(f"{script.name} ...", end=" ", flush=True)
        result = run(script)
        results[script] = result
        status = "FAILED: " + result["failure"] if result["failure"] else "ok"
        print(f"{result['wall']:.1f} s, {len(result['figures'])} figure(s), {status}",
              flush=True)
        for row in result["stats"]:
            print(f"    [stats] {row['label']}: events={row['events']} solve={row['solve']}s")
    total = time.perf_counter() - start
    README.write_text(readme(results, total), encoding="utf-8")
    print(f"wrote {README.relative_to(ROOT)}; total {total:.1f} s")
    return 1 if any(r["failure"] for r in results.values()) else 0


if __name__ == "__main__":
    sys.exit(main())
