"""Phase times of the demo and the start-up of the command line; writes ``benchmarks/DEMO.md``.

    python benchmarks/demo_phases.py

Not run by the tests (it takes about a minute on a 2-core machine).  Measures:

- start-up: ``import fronttrack.cli`` in a fresh interpreter (best of five), and
  whether it imported matplotlib or shapely (it must not: they are imported only
  when figures are drawn);
- ``wavediagram run`` of a small scene with ``--no-figures`` (best of three, end to end);
- the demo scene in phases: solving, the region numbers, each standard figure
  (drawn one after the other), all of them again as the demo draws them (the
  Eulerian diagram in a forked process), the JSON document (``to_dict``,
  serialising, writing) and the probe CSVs;
- ``wavediagram demo`` end to end (one run).
"""

from __future__ import annotations

import json
import platform
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).absolute().parent
ROOT = HERE.parent
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))

SMALL_SCENE = ROOT / "gallery" / "scenes" / "04_rigid_wall.toml"
DEMO_SCENE = ROOT / "fronttrack" / "scenes" / "demo.toml"
PROBE = ("import sys, time; t = time.perf_counter(); import fronttrack.cli; "
         "print(time.perf_counter() - t, 'matplotlib' in sys.modules, 'shapely' in sys.modules)")


def _wall(command: list[str], repeat: int) -> float:
    """Best wall time (s) of ``command`` over ``repeat`` runs."""
    best = float("inf")
    for _ in range(repeat):
        start = time.perf_counter()
        subprocess.run(command, check=True, capture_output=True, cwd=ROOT)
        best = min(best, time.perf_counter() - start)
    return best


def startup() -> dict:
    """Import time of the command line and the heavy modules it left out."""
    runs = [subprocess.run([sys.executable, "-c", PROBE], check=True, capture_output=True,
                           text=True, cwd=ROOT).stdout.split() for _ in range(5)]
    return {"import_s": min(float(r[0]) for r in runs),
            "matplotlib": runs[0][1] == "True", "shapely": runs[0][2] == "True"}


def demo_phases(outdir: Path) -> list[tuple[str, float]]:
    """Solve the demo scene and write its outputs, timing each phase (s)."""
    from fronttrack.cli import _write_probe_csvs
    from fronttrack.numbering import region_numbers
    from fronttrack.runner import run
    from fronttrack.scene_file import load_scene

    phases = []
    start = time.perf_counter()
    solution = run(load_scene(DEMO_SCENE))
    phases.append(("solve", time.perf_counter() - start))
    start = time.perf_counter()
    region_numbers(solution)
    phases.append(("region records and numbers", time.perf_counter() - start))

    start = time.perf_counter()
    import matplotlib  # noqa: F401  (its import is a phase of its own)
    import shapely  # noqa: F401

    from fronttrack.plotting import save_standard_figures
    phases.append(("import matplotlib, shapely and the plotting package",
                   time.perf_counter() - start))
    clock = {"name": None, "t": time.perf_counter()}

    def progress(name, index, count):
        now = time.perf_counter()
        if clock["name"] is not None:
            phases.append((f"figure {clock['name']}", now - clock["t"]))
        clock.update(name=name, t=now)

    save_standard_figures(solution, outdir, progress=progress, parallel=False)
    phases.append((f"figure {clock['name']}", time.perf_counter() - clock["t"]))
    start = time.perf_counter()
    save_standard_figures(solution, outdir)
    phases.append(("all figures again, as the demo draws them (Eulerian one forked)",
                   time.perf_counter() - start))
    start = time.perf_counter()
    doc = solution.to_dict()
    phases.append(("JSON document (to_dict)", time.perf_counter() - start))
    start = time.perf_counter()
    text = json.dumps(doc, separators=(",", ":"))
    (outdir / "solution.json").write_text(text)
    phases.append((f"JSON serialise and write ({len(text) / 1e6:.0f} MB)",
                   time.perf_counter() - start))
    start = time.perf_counter()
    _write_probe_csvs(solution, outdir)
    phases.append(("probe CSVs", time.perf_counter() - start))
    phases.append(("(lattice segments drawn)", float(solution.stats["fronts"])))
    return phases


def main() -> None:
    up = startup()
    small = _wall([sys.executable, "-m", "fronttrack.cli", "run", str(SMALL_SCENE),
                   "--no-figures", "--quiet"], 3)
    with tempfile.TemporaryDirectory() as tmp:
        phases = demo_phases(Path(tmp))
    with tempfile.TemporaryDirectory() as tmp:
        demo = _wall([sys.executable, "-m", "fronttrack.cli", "demo", "-o", tmp], 1)
    segments = phases.pop()[1]
    figures = sum(t for name, t in phases if name.startswith("figure "))
    parallel = next(t for name, t in phases if name.startswith("all figures again"))
    lines = ["# Demo and start-up phase times", "",
             "Generated by `python benchmarks/demo_phases.py`.", "",
             f"Machine: {platform.machine()}, Python {platform.python_version()}, shared "
             "by other jobs: compare rows of one run, not runs.", "",
             f"- `import fronttrack.cli`: {up['import_s']:.2f} s; matplotlib imported: "
             f"{up['matplotlib']}, shapely imported: {up['shapely']}.",
             f"- `wavediagram run {SMALL_SCENE.relative_to(ROOT)} --no-figures`: "
             f"{small:.2f} s end to end (best of 3).",
             f"- `wavediagram demo`: {demo:.1f} s end to end; its phases, in process "
             f"({segments:.0f} fronts, lattice segments included):", "",
             "| phase | time (s) |", "|---|---:|"]
    lines += [f"| {name} | {t:.2f} |" for name, t in phases]
    lines += [f"| **all figures, one after the other** | **{figures:.2f}** |",
              f"| **all figures, Eulerian diagram forked** | **{parallel:.2f}** |", ""]
    (HERE / "DEMO.md").write_text("\n".join(lines))
    print("\n".join(lines))


if __name__ == "__main__":
    main()
