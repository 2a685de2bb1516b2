"""Shared plumbing of the gallery scripts: load a scene next to the script, run it, save.

Every gallery script is ``gallery/NN_short_name.py``; its scene (when a TOML
file can express it) is ``gallery/scenes/NN_short_name.toml`` (variants add a
suffix: ``NN_short_name_variant.toml``) and its figures go to
``gallery/figures/``.  Units inside the engine are SI; figures use mm, µs, GPa
(compression positive) and m/s, like the rest of the project.

Each solve prints one ``[stats]`` line (events, fronts, solve time) and each
saved figure a ``[figure]`` line with its one-line caption; ``make_all.py``
collects them into ``gallery/README.md``.
"""

from __future__ import annotations

import io
import math
import re
import sys
import textwrap
from pathlib import Path

HERE = Path(__file__).absolute().parent
ROOT = HERE.parent
if str(ROOT) not in sys.path:  # run from anywhere; an explicit PYTHONPATH takes precedence
    sys.path.append(str(ROOT))

import matplotlib  # noqa: E402

matplotlib.use("Agg")

import numpy as np  # noqa: E402
from matplotlib.figure import Figure  # noqa: E402
from PIL import Image  # noqa: E402

from fronttrack.plotting import number_list, plot_sigma_u, plot_xt, region_numbers  # noqa: E402
from fronttrack.runner import run  # noqa: E402
from fronttrack.scene_file import load_scene  # noqa: E402

SCENES = HERE / "scenes"
FIGURES = HERE / "figures"
DPI = 130
"""Resolution of the gallery PNGs: sharp on screen, small enough to commit."""

MM, US, GPA = 1e3, 1e6, 1e-9
"""SI to mm, µs and GPa."""

CAPTION_FONTSIZE = 9.0
NOTE = {"fontsize": 8, "color": "#222222",
        "bbox": {"boxstyle": "round,pad=0.3", "fc": "white", "ec": "#888888", "lw": 0.6,
                 "alpha": 0.92}}
"""Style of the boxed notes written on the diagrams (numbers, remarks)."""
RED = "#8b0000"
BLUE = "#1f4e9c"


def scene(name: str):
    """The scene ``gallery/scenes/<name>.toml`` (SI ``Scene``)."""
    return load_scene(SCENES / f"{name}.toml")


def solve(scene_or_name, label: str | None = None):
    """Run a scene (a ``Scene`` or the name of a gallery scene file); print its statistics."""
    if isinstance(scene_or_name, str):
        label = label or scene_or_name
        scene_or_name = scene(scene_or_name)
    solution = run(scene_or_name)
    stats = solution.stats
    # cumulative-damage spall reruns the scene once per fracture: count every run
    events = stats.get("events_all_runs", stats["events"])
    seconds = stats.get("solve_time_all_runs", stats["solve_time"])
    print(f"[stats] {label or scene_or_name.title}: events={events} "
          f"fronts={stats['fronts']} spalls={len(solution.spalls)} "
          f"solve={seconds:.2f}s", flush=True)
    return solution


def save(figure, name: str, caption: str = "") -> Path:
    """Write ``figure`` to ``gallery/figures/<name>.png``; print it with its caption."""
    FIGURES.mkdir(parents=True, exist_ok=True)
    path = FIGURES / f"{name}.png"
    buffer = io.BytesIO()
    figure.savefig(buffer, dpi=DPI, format="png")
    buffer.seek(0)
    # a 256-colour palette: the figures are flat colours and lines, and the files
    # come out three times smaller than full RGBA
    image = Image.open(buffer).convert("RGB")
    image.quantize(colors=256, method=Image.Quantize.MEDIANCUT,
                   dither=Image.Dither.NONE).save(path, optimize=True)
    line = " ".join(caption.split())
    print(f"[figure] {path.relative_to(ROOT).as_posix()} | {line}", flush=True)
    return path


def script_name(file: str) -> str:
    """``NN_short_name`` of a gallery script, from its ``__file__``."""
    return Path(file).stem


# --- figure layout ---------------------------------------------------------------------------
def caption(figure, text: str, width: int = 165, fontsize: float = CAPTION_FONTSIZE,
            y: float = 0.012) -> None:
    """Write ``text`` (wrapped at ``width`` characters) at the bottom of ``figure``.

    A number is never separated from its unit by the wrapping.
    """
    text = re.sub(r"(\d) (GPa|MPa|µs|ns|mm|µm|m/s|km/s|K|%|kg/m³)(?=\W|$)", "\\1\u00a0\\2", text)
    wrapped = "\n".join(textwrap.fill(part, width) for part in text.split("\n"))
    figure.text(0.5, y, wrapped, ha="center", va="bottom", fontsize=fontsize,
                color="#222222", linespacing=1.35)


def xt_su_figure(solution, title: str, size=(13.0, 6.6), bottom: float = 0.17,
                 top: float = 0.82, width_ratios=(1.25, 1.0)):
    """X–t diagram (left) and σ–u diagram (right) with the same region numbers.

    Returns ``(figure, ax_xt, ax_su)``; ``bottom`` leaves room for a caption.
    """
    figure = Figure(figsize=size)
    grid = figure.add_gridspec(1, 2, width_ratios=width_ratios, left=0.055, right=0.985,
                               bottom=bottom, top=top, wspace=0.28)
    ax_xt = figure.add_subplot(grid[0, 0])
    ax_su = figure.add_subplot(grid[0, 1])
    _draw_xt_and_sigma_u(solution, figure, ax_xt, ax_su, title, su_title_pad=True)
    return figure, ax_xt, ax_su


def xt_su_record_figure(solution, title: str, size=(13.0, 8.6), bottom: float = 0.165,
                        top: float = 0.86):
    """X–t diagram (left, full height), σ–u diagram (top right) and a record axes below it.

    Returns ``(figure, ax_xt, ax_su, ax_record)``.
    """
    figure = Figure(figsize=size)
    grid = figure.add_gridspec(2, 2, width_ratios=(1.2, 1.0), height_ratios=(1.25, 1.0),
                               left=0.055, right=0.985, bottom=bottom, top=top, wspace=0.28,
                               hspace=0.38)
    ax_xt = figure.add_subplot(grid[:, 0])
    ax_su = figure.add_subplot(grid[0, 1])
    ax_record = figure.add_subplot(grid[1, 1])
    _draw_xt_and_sigma_u(solution, figure, ax_xt, ax_su, title, su_title_pad=False)
    return figure, ax_xt, ax_su, ax_record


def _draw_xt_and_sigma_u(solution, figure, ax_xt, ax_su, title: str, su_title_pad: bool):
    """The X–t diagram, then the σ–u diagram numbered like it (the numbers of the
    solution's JSON, ``region_numbers``), with titles."""
    placed = plot_xt(solution, ax=ax_xt, numbers=region_numbers(solution))
    plot_sigma_u(solution, ax=ax_su, numbers=placed.numbers)
    pad = placed.title_pad
    ax_xt.set_title("X–t diagram (Lagrangian), regions shaded by stress", fontsize=10,
                    pad=pad)
    ax_su.set_title("σ–u diagram: the same numbered states", fontsize=10,
                    pad=pad if su_title_pad else None)
    figure.suptitle(title, fontsize=12, y=0.985)


def xt_record_figure(solution, title: str, size=(13.0, 6.8), bottom: float = 0.2,
                     top: float = 0.84, width_ratios=(1.1, 1.0), numbers=True):
    """X–t diagram (left) and a record axes (right); returns ``(figure, ax_xt, ax_record)``."""
    figure = Figure(figsize=size)
    grid = figure.add_gridspec(1, 2, width_ratios=width_ratios, left=0.055, right=0.985,
                               bottom=bottom, top=top, wspace=0.25)
    ax_xt = figure.add_subplot(grid[0, 0])
    ax_record = figure.add_subplot(grid[0, 1])
    placed = plot_xt(solution, ax=ax_xt, numbers=numbers)
    ax_xt.set_title("X–t diagram (Lagrangian), regions shaded by stress", fontsize=10,
                    pad=placed.title_pad)
    figure.suptitle(title, fontsize=12, y=0.985)
    return figure, ax_xt, ax_record


def numbers_at(solution, *points) -> str:
    """The region numbers (as on the figures and in the JSON) at the points ``(X, t)`` (m, s),
    as a list with ranges ("3, 4"); regions without a number are left out."""
    numbers = region_numbers(solution)
    found = {numbers[r.id] for r in (solution.region_at(x, t) for x, t in points)
             if r.id in numbers}
    return number_list(sorted(found)) if found else "unnumbered"


def plot_record(ax, edges, values, label=None, color=BLUE, **kwargs):
    """A step record (edges µs, values) on ``ax``."""
    ax.stairs(values, edges, baseline=None, color=color, lw=kwargs.pop("lw", 1.5),
              label=label, **kwargs)
    ax.grid(True, lw=0.3, alpha=0.5)


def note(ax, text: str, xy=(0.02, 0.97), ha="left", va="top", **kwargs):
    """A boxed note in axes-fraction coordinates."""
    style = dict(NOTE)
    style.update(kwargs)
    return ax.text(*xy, text, transform=ax.transAxes, ha=ha, va=va, zorder=20, **style)


def mark(ax, x, y, text, offset=(10, 10), color=RED, marker="o", ha="left", va="bottom",
         fontsize=8):
    """A marker at data point ``(x, y)`` with a boxed text joined to it by a leader."""
    ax.plot([x], [y], marker=marker, ms=6, mfc="none", mec=color, mew=1.4, zorder=21,
            ls="none")
    ax.annotate(text, (x, y), xytext=offset, textcoords="offset points", ha=ha, va=va,
                fontsize=fontsize, color=color, zorder=22,
                bbox={"boxstyle": "round,pad=0.25", "fc": "white", "ec": color, "lw": 0.6,
                      "alpha": 0.95},
                arrowprops={"arrowstyle": "-", "color": color, "lw": 0.7})


# --- thin-layer figures (ring-up, ring-down, gauge packages) ---------------------------------
def layer_figure(name, layer_probe, plate_probe, title, layer_text, save_text, zoom,
                 plate_label="0.1 mm before the layer", layer_label="mid-thickness"):
    """X–t (zoomed on a thin layer) and the stress histories in the layer and the plate.

    ``layer_probe`` and ``plate_probe`` name probes of the scene; ``layer_text`` and
    ``save_text`` turn the numbers (GPa, µs) into the caption and the README line;
    ``zoom`` is the X range (mm) of the X–t panel.
    """
    solution = solve(name)
    g = GPA
    figure, ax_xt, ax_rec = xt_record_figure(solution, title, numbers=False)
    histories = solution.probe_histories()
    layer, plate = histories[layer_probe], histories[plate_probe]
    t_end = solution.scene.t_end
    edges, values = steps(plate, plate.sigma * g, t_end)
    plot_record(ax_rec, edges, values, color="#777777", lw=1.2,
                label=f"{plate_probe}, {plate_label}")
    edges, values = steps(layer, layer.sigma * g, t_end)
    plot_record(ax_rec, edges, values, color=RED, lw=1.7,
                label=f"{layer_probe} ({layer_label})")
    target = plate.sigma[1] if len(plate.sigma) > 1 else plate.sigma[0]
    ax_rec.axhline(target * g, color="#222222", lw=0.8, ls=":",
                   label=f"plate state (impedance match) {target * g:.2f} GPa")
    first = layer.sigma[1]
    ax_rec.set_xlim(plate.t[1] * US - 0.05, t_end * US)
    ax_rec.set_ylim(0.0, 1.25 * max(max(layer.sigma), target) * g)
    ax_rec.set_xlabel("time t (µs)")
    ax_rec.set_ylabel("stress σ (GPa, compression > 0)")
    ax_rec.set_title("stress histories", fontsize=10)
    ax_rec.legend(fontsize=8, loc="lower right")
    jumps = [(t, s) for t, s in zip(layer.t, layer.sigma, strict=True) if t > 0]
    x0, x1 = zoom
    ax_xt.set_xlim(x0, x1)
    ax_xt.set_ylim(0.0, t_end * US)
    for text in list(ax_xt.texts):   # the layer names of the full diagram
        text.remove()
    spans = []                        # (label, start, end) of runs of equal layers, mm
    x = 0.0
    for item in solution.scene.layers:
        end = x + item.thickness * MM
        if (spans and spans[-1][0].name == item.material.name
                and spans[-1][1].name == item.name):
            spans[-1] = (item.material, item, spans[-1][2], end)
        else:
            spans.append((item.material, item, x, end))
        x = end
    for _, item, a, b in spans:
        left, right = max(a, x0), min(b, x1)
        if right - left > 0.02 * (x1 - x0):
            label = item.material.name if right - left < 0.3 * (x1 - x0) else (
                f"{item.name} ({item.material.name})")
            ax_xt.text(0.5 * (left + right), 0.01 * t_end * US, label, ha="center",
                       va="bottom", fontsize=7.5, zorder=9,
                       bbox={"fc": "white", "ec": "none", "alpha": 0.85, "pad": 1})
    reach = None      # from then on the layer stays within 5 % of the plate state
    for t, s in jumps:
        if abs(s - target) >= 0.05 * target:
            reach = None
        elif reach is None:
            reach = t
    numbers = {"first": first * g, "target": target * g, "steps": len(jumps),
               "reach": reach * US if reach is not None else None,
               "peak": max(layer.sigma) * g, "final": layer.sigma[-1] * g,
               "arrival": layer.t[1] * US}
    caption(figure, layer_text(numbers))
    save(figure, name, save_text(numbers))



# --- queries on a solution -----------------------------------------------------------------------
def region_center(region) -> tuple[float, float]:
    """A point well inside a region's polygon (mm, µs)."""
    from shapely.geometry import Polygon

    polygon = Polygon([(x * MM, t * US) for x, t in region.polygon()])
    if not polygon.is_valid:
        polygon = polygon.buffer(0)
    point = polygon.representative_point()
    return point.x, point.y


def most_tensile_region(solution, t_max: float | None = None):
    """The earliest region whose stress is within 0.1 % of the most tensile one (or ``None``).

    ``t_max`` (s) restricts the search to regions that start before it.
    """
    regions = [r for r in solution.regions if t_max is None or r.t_start < t_max]
    low = min(r.state.sigma for r in regions)
    if low >= 0.0:
        return None
    near = [r for r in regions if r.state.sigma <= low * (1.0 - 1e-3)]
    return min(near, key=lambda r: r.t_start)


def steps(history, values, t_end: float):
    """Edges (µs) and values of a step history, for ``ax.stairs``."""
    return np.append(history.t, t_end) * US, np.asarray(values)


def surface_velocity(solution, side: str = "right"):
    """``(edges µs, velocity m/s)`` of a surface, signed outward (``+u`` right, ``-u`` left)."""
    history = solution.history(side)
    sign = 1.0 if side == "right" else -1.0
    return steps(history, sign * history.u, solution.scene.t_end)


def value_at(history, t: float, quantity: str = "sigma") -> float:
    """Value of a step history at time ``t`` (s)."""
    k = int(np.searchsorted(history.t, t, side="right")) - 1
    state = history.states[max(k, 0)]
    return state.sigma if quantity == "sigma" else state.u


def signed(value: float, decimals: int = 2) -> str:
    """``value`` with ``decimals`` decimals and a true minus sign (U+2212) when negative."""
    return f"{value:.{decimals}f}".replace("-", "\u2212")


def fmt(value: float, digits: int = 3) -> str:
    """A number with ``digits`` significant figures, without scientific notation."""
    if value == 0 or not math.isfinite(value):
        return f"{value:g}"
    decimals = max(digits - 1 - int(math.floor(math.log10(abs(value)))), 0)
    return f"{value:.{decimals}f}"
