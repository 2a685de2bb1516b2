"""Records of the kind an experiment gives: profiles, gauge histories, VISAR, attenuation.

Records are read continuously from the solution: straight between the rays of
simple waves, jumps at shocks and contacts (``Solution.history``, ``Solution.profile``);
they are drawn as such.

- ``plot_profiles``: stress (or particle velocity) against Lagrangian X at
  chosen instants;
- ``plot_histories``: stress and particle velocity against time at every probe
  of the scene (in-material gauges);
- ``plot_free_surface_velocity``: the velocity of a surface against time, the
  record of a VISAR or PDV, with its peak and the "pullback" (the drop from
  the first peak to the following minimum); when the record rises again after
  it (the spall signal) the acoustic estimate of the spall strength
  ½ ρ0 C0 Δu_pb is shown;
- ``plot_peak_stress``: the largest compressive stress that each X ever sees
  (the attenuation curve of a pulse), with the largest tension.

Units: mm, µs, GPa (compression positive), m/s.
"""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np

from .attenuation import peak_stress_steps
from .style import GPA, MM, SIGMA_LABEL, T_LABEL, U_LABEL, US, X_LABEL, title_of

QUANTITIES = {"sigma": (SIGMA_LABEL, GPA), "u": (U_LABEL, 1.0)}


def _step_line(edges: np.ndarray, values: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The vertices of a step curve (``values[k]`` from ``edges[k]`` to ``edges[k + 1]``),
    with runs of equal values joined: a lattice gives tens of thousands of edges."""
    change = np.concatenate([[True], values[1:] != values[:-1]])
    starts = np.nonzero(change)[0]
    left, right = edges[starts], edges[np.append(starts[1:], len(values))]
    return (np.column_stack([left, right]).ravel(),
            np.repeat(values[starts], 2))


def _resolution_note(solution) -> str:
    """What the steps of the attenuation curve resolve."""
    if not solution.stats.get("rays"):
        return "exact: steps where fronts meet (no fans in this solution)"
    return (f"exact between fronts; steps in fans are rays "
            f"({solution.scene.accuracy.rays_per_fan} rays in the strongest fan)")


def _mark_interfaces(ax, solution) -> None:
    for x in solution.scene.interfaces():
        ax.axvline(x * MM, color="#777777", lw=0.8, ls=(0, (5, 3)), zorder=1)


def plot_profiles(solution, times, ax=None, quantity="sigma"):
    """Profiles of ``quantity`` (``"sigma"`` in GPa or ``"u"`` in m/s) vs X (mm).

    ``times`` are instants in seconds; each profile is labelled in µs.
    """
    if quantity not in QUANTITIES:
        raise ValueError(f"quantity must be one of {tuple(QUANTITIES)}, got {quantity!r}")
    label, factor = QUANTITIES[quantity]
    if ax is None:
        _, ax = plt.subplots(figsize=(7.0, 4.4))
    times = list(times)
    colors = plt.get_cmap("viridis")(np.linspace(0.0, 0.9, max(len(times), 1)))
    for t, color in zip(times, colors, strict=True):
        x, values = solution.profile(t).samples(quantity)
        ax.plot(x * MM, values * factor, color=color, lw=1.4, label=f"t = {t * US:.3g} µs")
    _mark_interfaces(ax, solution)
    ax.axhline(0.0, color="#999999", lw=0.6, zorder=0)
    ax.set_xlim(0.0, solution.scene.length * MM)
    ax.set_xlabel(X_LABEL)
    ax.set_ylabel(label)
    ax.set_title(title_of(solution, "stress profiles" if quantity == "sigma"
                          else "particle-velocity profiles"), fontsize=10)
    ax.legend(fontsize=7.5, loc="best")
    ax.grid(True, lw=0.3, alpha=0.5)
    return ax


def plot_histories(solution, ax=None):
    """Stress (GPa) and particle velocity (m/s) vs time (µs) at every probe.

    ``ax``: ``None`` (a new figure with two panels, stress above velocity), a
    pair of axes (stress, velocity), or one axes (velocity on a twin right axis,
    dashed).  Returns the pair of axes used.
    """
    if ax is None:
        _, (ax_s, ax_u) = plt.subplots(2, 1, sharex=True, figsize=(7.0, 6.0))
        twin = False
    elif isinstance(ax, list | tuple | np.ndarray):
        ax_s, ax_u = ax
        twin = False
    else:
        ax_s, ax_u, twin = ax, ax.twinx(), True
    t_end = solution.scene.t_end
    colors = plt.get_cmap("tab10")
    for k, (probe, (name, history)) in enumerate(zip(solution.scene.probes,
                                                     solution.probe_histories().items(),
                                                     strict=True)):
        where = probe.at if isinstance(probe.at, str) else f"X = {probe.at * MM:.3g} mm"
        label = f"{name} ({where})"
        t, sigma = history.samples("sigma")
        ax_s.plot(t * US, sigma * GPA, color=colors(k), lw=1.4, label=label)
        t, u = history.samples("u")
        ax_u.plot(t * US, u, color=colors(k), lw=1.4 if not twin else 1.0,
                  ls="-" if not twin else "--", label=label)
    ax_s.set_ylabel(SIGMA_LABEL)
    ax_u.set_ylabel(U_LABEL)
    ax_u.set_xlabel(T_LABEL)
    ax_s.set_xlabel(T_LABEL if twin else "")
    ax_s.set_xlim(0.0, t_end * US)
    ax_s.set_title(title_of(solution, "probe histories"), fontsize=10)
    for panel in (ax_s, ax_u):
        panel.axhline(0.0, color="#999999", lw=0.6, zorder=0)
        if not twin:
            panel.grid(True, lw=0.3, alpha=0.5)
    if solution.scene.probes:
        ax_s.legend(fontsize=7.5, loc="best")
    return ax_s, ax_u


def pullback(velocity) -> tuple[int | None, int | None, bool]:
    """The first peak of a record (its values at its knots) and the low point after it.

    Returns ``(i_peak, i_low, rebound)``: indices into ``velocity`` of the first
    peak (the value before the first fall) and of the lowest value before the
    record rises again (or after the peak, if it never rises); ``rebound`` says
    whether it rises again, the signature of spall.  ``i_low`` is ``None`` if the
    record never falls.
    """
    v = np.asarray(velocity, dtype=float)
    if v.size == 0:
        return None, None, False
    steps = np.diff(v)
    falls = np.nonzero(steps < 0.0)[0]
    if falls.size == 0:
        return int(np.argmax(v)), None, False
    peak = int(falls[0])
    rises = np.nonzero(steps[peak + 1:] > 0.0)[0]
    end = peak + 1 + int(rises[0]) + 1 if rises.size else v.size
    low = peak + 1 + int(np.argmin(v[peak + 1:end]))
    return peak, low, bool(rises.size)


def plot_free_surface_velocity(solution, side="right", ax=None):
    """The velocity history of the ``side`` surface (VISAR/PDV record, m/s vs µs).

    Drawn as the continuous record (jumps at shocks), signed toward the outside of the stack
    (``+u`` for the right surface, ``-u`` for the left), and annotated with the
    peak velocity and, if the record falls after its first peak, the pullback
    ``Δu_pb``, with the acoustic spall-strength estimate ``½ ρ0 C0 Δu_pb`` when
    the record rises again after the drop.
    """
    if side not in ("left", "right"):
        raise ValueError(f"side must be 'left' or 'right', got {side!r}")
    if ax is None:
        _, ax = plt.subplots(figsize=(7.0, 4.4))
    sign = 1.0 if side == "right" else -1.0
    edges, values = solution.history(side).samples("u")
    edges, values = edges * US, sign * values
    ax.plot(edges, values, color="#1f4e9c", lw=1.6)
    ax.set_xlim(0.0, solution.scene.t_end * US)
    top = float(values.max()) if values.size else 0.0
    i_top = int(np.argmax(values)) if values.size else 0
    ax.annotate(f"max {top:.1f} m/s", (edges[i_top], top), xytext=(4, 6),
                textcoords="offset points", fontsize=8)
    peak, low, rebound = pullback(values)
    if low is not None:
        _annotate_pullback(ax, solution, side, edges, values, peak, low, rebound)
    ax.axhline(0.0, color="#999999", lw=0.6, zorder=0)
    ax.set_ylim(bottom=min(0.0, float(values.min())) - 0.05 * max(top, 1.0), top=1.15 * top
                if top > 0 else None)
    ax.set_xlabel(T_LABEL)
    ax.set_ylabel(f"{side} surface velocity (m/s, outward > 0)")
    kind = (solution.scene.right if side == "right" else solution.scene.left).kind
    what = "free-surface velocity" if kind == "free" else f"{side} surface velocity"
    ax.set_title(title_of(solution, what), fontsize=10)
    ax.grid(True, lw=0.3, alpha=0.5)
    return ax


def _annotate_pullback(ax, solution, side, edges, values, peak, low, rebound) -> None:
    layer = solution.scene.layers[-1 if side == "right" else 0]
    material = layer.material
    drop = float(values[peak] - values[low])
    c0 = material.sound_speed(material.v0, 0.0)
    strength = 0.5 * material.rho0 * c0 * drop
    t_mid = edges[low]
    ax.annotate("", xy=(t_mid, values[low]), xytext=(t_mid, values[peak]),
                arrowprops={"arrowstyle": "<->", "color": "#8b0000", "lw": 1.0})
    ax.plot([edges[peak], t_mid], [values[peak]] * 2, color="#8b0000", lw=0.6, ls=":")
    text = f"pullback Δu = {drop:.1f} m/s"
    if rebound:
        text += f"\n½ρ0C0Δu = {strength * GPA:.2f} GPa ({material.name})"
    # the text sits in the free lower right corner, with a leader to the dip
    ax.annotate(text, (t_mid, values[low]), xytext=(0.97, 0.3), textcoords="axes fraction",
                fontsize=8, color="#8b0000", ha="right", va="center",
                bbox={"boxstyle": "round,pad=0.3", "fc": "white", "ec": "#8b0000", "lw": 0.6},
                arrowprops={"arrowstyle": "-", "color": "#8b0000", "lw": 0.6})


def plot_peak_stress(solution, ax=None):
    """Peak compressive stress (GPa) vs X (mm) over the whole run: the attenuation curve.

    Drawn exactly, as steps between the X where fronts begin and end
    (``attenuation.peak_stress_steps``): no sampling, so the curve keeps its value
    up to a free surface.  Where a fan overtakes a shock each ray is a step; the
    note on the figure says how many rays the strongest fan had.  The largest
    tension at each X is drawn dashed when there is any.
    """
    if ax is None:
        _, ax = plt.subplots(figsize=(7.0, 4.4))
    edges, top, bottom = peak_stress_steps(solution)
    ax.plot(*_step_line(edges * MM, top * GPA), color="#c0392b", lw=1.6,
            label="peak compression")
    if np.any(bottom < 0.0):
        ax.plot(*_step_line(edges * MM, np.minimum(bottom, 0.0) * GPA), color="#1f4e9c",
                lw=1.2, ls="--", label="peak tension")
    ax.text(0.01, 0.02, _resolution_note(solution), transform=ax.transAxes, fontsize=7,
            color="#444444", ha="left", va="bottom")
    _mark_interfaces(ax, solution)
    ax.axhline(0.0, color="#999999", lw=0.6, zorder=0)
    ax.set_xlim(0.0, solution.scene.length * MM)
    ax.set_xlabel(X_LABEL)
    ax.set_ylabel(SIGMA_LABEL)
    ax.set_title(title_of(solution, "peak stress vs position"), fontsize=10)
    ax.legend(fontsize=7.5, loc="best")
    ax.grid(True, lw=0.3, alpha=0.5)
    return ax
