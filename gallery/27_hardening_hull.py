"""Saturating hardening and the convex-hull construction: precursor, fan, shock.

A compressive wave in uniaxial strain follows the upper concave hull of the
loading path σ(ε) from the state ahead to the state behind: where the hull is
a chord (a Rayleigh line, slope ρ0 U²) the wave is a shock at U; where it runs
on the path itself (a concave stretch) it is a centred fan whose rays move at
C = √(dσ/dε / ρ0).  An ideal or linearly hardening elastic–plastic solid has a
convex plastic branch and gives the usual elastic precursor + plastic shock.  A
hardening law that saturates (Voce, Y = Ysat − (Ysat − Y0) exp(−ε̄/εr)) makes the
branch concave just beyond the HEL: the plastic part of the wave becomes a fan
followed by a shock, tangent to the path where the fan ends.

The path is that of ``materials.finite_plastic.monotone_loading_path`` for an
Al 6061-like solid with Γ0 = 0 (the stress is then a function of the strain
alone and the construction is exact); the waves are those of
``concave_hull_waves`` (the parameters of tests/test_finite_plastic.py).
No scene is solved: this is the construction itself.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import common
import numpy as np
from matplotlib.figure import Figure

from fronttrack.plotting import light_cmap
from materials.finite_plastic import concave_hull_waves, monotone_loading_path

NAME = common.script_name(__file__)
MM, US, GPA = common.MM, common.US, common.GPA

RHO, C0, S, G = 2703.0, 5350.0, 1.34, 26.0e9          # Al 6061-like, Gamma0 = 0
Y0, Y_SAT, EPS_R = 0.29e9, 0.6e9, 0.004                 # Voce hardening
EPS_END, EPS_WEAK = 0.03, 0.010                          # the load, and a weaker one
T_SHOW = 2.0e-6                                          # X–t and profile time (s)
FAN = "#1f4e9c"
CHORD = "#8b0000"
PATH = "#444444"


def flow(accumulated: float) -> float:
    """Voce flow stress Y(ε̄) (Pa)."""
    return Y_SAT - (Y_SAT - Y0) * math.exp(-accumulated / EPS_R)


def hugoniot_pressure(eps):
    """The pressure of the Γ0 = 0 solid, ρ0 c0² ε / (1 − s ε)² (Pa)."""
    eps = np.asarray(eps, dtype=float)
    return RHO * C0 * C0 * eps / (1.0 - S * eps) ** 2


def construction(eps_end: float):
    """Samples ``(eps, sigma)`` of the loading path to ``eps_end`` and its hull pieces."""
    eps = np.union1d(np.linspace(0.0, eps_end, 6001), [Y0 / (2.0 * G)])
    sigma = monotone_loading_path(RHO, C0, S, G, flow, eps)
    return eps, sigma, concave_hull_waves(eps, sigma, RHO)


def hull_states(eps, sigma, pieces):
    """Along the hull: indices, particle velocity (m/s) and the speed of each step.

    A shock from i to j brings Δu = U Δε; a fan is the limit of the consecutive
    small chords, Δu = C Δε each.  Returns ``(index, u, speed)`` arrays, one
    entry per hull vertex (``speed[k]`` is that of the step ending at vertex k).
    """
    index, u, speed = [0], [0.0], [math.nan]
    for piece in pieces:
        i, j = piece["start"], piece["end"]
        steps = [(i, j)] if piece["kind"] == "shock" else list(
            zip(range(i, j), range(i + 1, j + 1), strict=True))
        for a, b in steps:
            c = math.sqrt((sigma[b] - sigma[a]) / (eps[b] - eps[a]) / RHO)
            index.append(b)
            u.append(u[-1] + c * (eps[b] - eps[a]))
            speed.append(c)
    return np.array(index), np.array(u), np.array(speed)


def profile(eps, sigma, index, speed, t: float):
    """``(X mm, sigma GPa)`` of the wave at time ``t``: a state holds between rays."""
    xs, values = [0.0], [sigma[index[-1]] * GPA]
    for k in range(len(index) - 1, 0, -1):         # from the slowest ray to the fastest
        x = speed[k] * t * MM
        xs.extend([x, x])
        values.extend([sigma[index[k]] * GPA, sigma[index[k - 1]] * GPA])
    xs.append(1e3)
    values.append(0.0)
    return np.array(xs), np.array(values)


def names(kinds: list[str]) -> list[str]:
    """Teaching names of hull pieces: the first shock is the elastic precursor."""
    return ["precursor" if k == 0 and kind == "shock" else kind
            for k, kind in enumerate(kinds)]


class Hull(NamedTuple):
    """The construction for the figure: the loading path (``eps``, ``sigma``), the
    hull's corner indices ``a`` (HEL), ``b`` (fan tail), ``c`` (end), the states along
    the hull (``index``, ``speed``), the velocities behind each wave and the wave speeds
    (m/s), and the weaker and stronger loads compared in the caption."""

    eps: np.ndarray
    sigma: np.ndarray
    a: int
    b: int
    c: int
    index: np.ndarray
    speed: np.ndarray
    u_a: float
    u_b: float
    u_c: float
    u_precursor: float
    c_head: float
    c_tail: float
    u_shock: float
    weak: tuple
    strong: tuple


def build() -> Hull:
    """The hull of the loading path to ``EPS_END``, and of a weaker and a stronger load."""
    eps, sigma, pieces = construction(EPS_END)
    kinds = [p["kind"] for p in pieces]
    if kinds != ["shock", "fan", "shock"]:
        raise RuntimeError(f"expected precursor, fan and shock, got {kinds}")
    precursor, fan, shock = pieces
    a, b, c = precursor["end"], fan["end"], shock["end"]
    index, u, speed = hull_states(eps, sigma, pieces)
    u_at = dict(zip(index.tolist(), u.tolist(), strict=True))
    (c_head, c_tail) = fan["speeds"]
    return Hull(eps, sigma, a, b, c, index, speed, u_at[a], u_at[b], u_at[c],
                precursor["speeds"][0], c_head, c_tail, shock["speeds"][0],
                construction(EPS_WEAK), construction(2.0 * EPS_END))


def draw_path(ax_p, h: Hull) -> None:
    """The loading path σ(ε), its upper concave hull, and the Voce law (inset)."""
    eps, sigma, a, b, c = h.eps, h.sigma, h.a, h.b, h.c
    pct = 100.0
    # the loading path and its hull ---------------------------------------------------------
    eps_hel = eps[a]
    plastic = eps >= eps_hel
    for y, label in ((Y0, "plastic branches at Y = Y0 (lower), Ysat (upper)"), (Y_SAT, None)):
        ax_p.plot(eps[plastic] * pct, (hugoniot_pressure(eps[plastic]) + 2 * y / 3) * GPA,
                  color="#999999", lw=0.8, ls="--", label=label)
    ax_p.plot(eps * pct, sigma * GPA, color=PATH, lw=1.2, label="loading path σ(ε) (Voce)")
    ax_p.plot([0, eps[a] * pct], [0, sigma[a] * GPA], color=CHORD, lw=2.0,
              label="hull: chord = shock (Rayleigh line)")
    ax_p.plot(eps[a:b + 1] * pct, sigma[a:b + 1] * GPA, color=FAN, lw=3.2, alpha=0.8,
              label="hull on the path = fan")
    ax_p.plot([eps[b] * pct, eps[c] * pct], [sigma[b] * GPA, sigma[c] * GPA], color=CHORD,
              lw=2.0)
    for k, key, off in ((a, "A", (-14, 4)), (b, "B", (-14, 4)), (c, "C", (-14, 4))):
        ax_p.plot([eps[k] * pct], [sigma[k] * GPA], "o", color="black", ms=4, zorder=5)
        ax_p.annotate(key, (eps[k] * pct, sigma[k] * GPA), xytext=off,
                      textcoords="offset points", fontsize=10, fontweight="bold")
    ax_p.annotate("O", (0, 0), xytext=(6, 8), textcoords="offset points", fontsize=10,
                  fontweight="bold")
    ax_p.set_xlim(0.0, EPS_END * pct * 1.02)
    ax_p.set_ylim(0.0, sigma[c] * GPA * 1.08)
    ax_p.set_xlabel("compression ε = 1 − v/v0 (%)")
    ax_p.set_ylabel("stress σ (GPa, compression > 0)")
    ax_p.set_title("loading path and its upper concave hull", fontsize=10)
    ax_p.legend(fontsize=8, loc="upper left")
    ax_p.grid(True, lw=0.3, alpha=0.5)
    inset = ax_p.inset_axes([0.6, 0.1, 0.36, 0.3])
    ebar = np.linspace(0.0, 0.025, 200)
    inset.plot(ebar * pct, [flow(x) * GPA for x in ebar], color=PATH, lw=1.3)
    inset.axhline(Y_SAT * GPA, color="#999999", lw=0.7, ls="--")
    inset.set_xlabel("ε̄ (%)", fontsize=7, labelpad=1)
    inset.set_ylabel("Y (GPa)", fontsize=7, labelpad=1)
    inset.set_title("Voce: Y = Ysat − (Ysat − Y0) exp(−ε̄/εr)", fontsize=7)
    inset.tick_params(labelsize=6.5)
    inset.set_ylim(0.0, 0.7)
    inset.grid(True, lw=0.3, alpha=0.5)



def draw_sheared(ax_h, h: Hull) -> None:
    """The path minus the last shock's Rayleigh line: the hull's chords and fan stand out."""
    (eps, sigma, a, b, c, u_precursor, c_head, c_tail, u_shock) = (
        h.eps, h.sigma, h.a, h.b, h.c, h.u_precursor, h.c_head, h.c_tail, h.u_shock)
    pct = 100.0
    plastic = eps >= eps[a]
    weak_sigma = h.weak[1]
    # the sheared view ------------------------------------------------------------------------
    k_shift = RHO * u_shock**2           # subtract the Rayleigh line of the last shock
    def sheared(e, s):
        return (np.asarray(s) - k_shift * np.asarray(e)) * 1e-6

    for y, text, where in ((Y0, "plastic branch at Y = Y0", 0.45),
                           (Y_SAT, "plastic branch at Y = Ysat", 0.75)):
        branch = sheared(eps[plastic], hugoniot_pressure(eps[plastic]) + 2 * y / 3)
        ax_h.plot(eps[plastic] * pct, branch, color="#999999", lw=0.8, ls="--")
        j = int(where * (np.count_nonzero(plastic) - 1))
        ax_h.text(eps[plastic][j] * pct, branch[j] + 4, text, fontsize=7, color="#777777",
                  ha="right" if y == Y0 else "center", va="bottom",
                  rotation=-30 if y == Y0 else -4, rotation_mode="anchor")
    ax_h.plot(eps * pct, sheared(eps, sigma), color=PATH, lw=1.3)
    ax_h.plot([0, eps[a] * pct], sheared([0, eps[a]], [0, sigma[a]]), color=CHORD, lw=2.0)
    ax_h.plot(eps[a:b + 1] * pct, sheared(eps[a:b + 1], sigma[a:b + 1]), color=FAN, lw=3.2,
              alpha=0.8)
    ax_h.plot([eps[b] * pct, eps[c] * pct], sheared([eps[b], eps[c]], [sigma[b], sigma[c]]),
              color=CHORD, lw=2.0)
    y_a, y_b, y_c = (float(sheared(eps[k], sigma[k])) for k in (a, b, c))
    for k, key, off in ((a, "A", (-4, 6)), (b, "B", (-4, 6)), (c, "C", (-12, 6))):
        ax_h.plot([eps[k] * pct], [sheared(eps[k], sigma[k])], "o", color="black", ms=4,
                  zorder=5)
        ax_h.annotate(key, (eps[k] * pct, sheared(eps[k], sigma[k])), xytext=off,
                      textcoords="offset points", fontsize=10, fontweight="bold", ha="right")
    w = int(np.searchsorted(eps, EPS_WEAK))
    ax_h.plot([eps[w] * pct], [sheared(eps[w], sigma[w])], "s", mfc="white", mec=FAN, ms=6,
              mew=1.4, zorder=5)
    ax_h.annotate(f"W: a load ending here ({weak_sigma[-1] * GPA:.2f} GPa)\n"
                  f"= precursor + fan, no shock", (eps[w] * pct, sheared(eps[w], sigma[w])),
                  xytext=(1.45, 0.72 * y_a), textcoords="data", fontsize=8, color=FAN,
                  va="top",
                  arrowprops={"arrowstyle": "-", "color": FAN, "lw": 0.7})
    ax_h.annotate(f"precursor O→A: chord,\nU = {u_precursor:.0f} m/s",
                  (0.4 * eps[a] * pct, 0.4 * y_a), xytext=(0.3, 0.22 * y_a),
                  textcoords="data", fontsize=8, color=CHORD, va="center",
                  arrowprops={"arrowstyle": "-", "color": CHORD, "lw": 0.7})
    mid = (a + b) // 2
    ax_h.annotate(f"fan A→B: the hull follows the concave path,\n"
                  f"C = {c_head:.0f} → {c_tail:.0f} m/s",
                  (eps[mid] * pct, sheared(eps[mid], sigma[mid])),
                  xytext=(0.75, 1.42 * y_b), textcoords="data", fontsize=8, color=FAN,
                  arrowprops={"arrowstyle": "-", "color": FAN, "lw": 0.7})
    between = slice(b, c + 1)
    chord = y_b + (y_c - y_b) * (eps[between] - eps[b]) / (eps[c] - eps[b])
    dip = float(np.max(chord - sheared(eps[between], sigma[between])))
    ax_h.annotate(f"shock B→C: chord tangent to the path at B,\nU = {u_shock:.0f} m/s "
                  f"(= the fan's tail speed);\nthe path dips {dip:.1f} MPa below it",
                  (0.5 * (eps[b] + eps[c]) * pct, 0.5 * (y_b + y_c)),
                  xytext=(2.33, 0.8 * y_b), textcoords="data", fontsize=8, color=CHORD,
                  ha="center", va="top",
                  arrowprops={"arrowstyle": "-", "color": CHORD, "lw": 0.7})
    ax_h.set_xlim(0.0, EPS_END * pct * 1.02)
    lo = float(np.min(sheared(eps, sigma)))
    ax_h.set_ylim(min(lo, 0.0) - 10.0, max(y_a, y_b, y_c) * 1.6)
    ax_h.set_xlabel("compression ε (%)")
    ax_h.set_ylabel(f"σ − ρ0 U²ε (MPa), ρ0 U² = {k_shift * GPA:.1f} GPa")
    ax_h.set_title("the same, minus the last shock's Rayleigh line (a shear keeps the hull)",
                   fontsize=10)
    ax_h.grid(True, lw=0.3, alpha=0.5)



def draw_xt(ax_xt, h: Hull) -> tuple[float, float, float]:
    """The composite wave in the X–t plane; returns the X (mm) of precursor, fan head, tail."""
    (sigma, a, b, c, index, speed, u_a, u_c, u_precursor, c_head, c_tail, u_shock) = (
        h.sigma, h.a, h.b, h.c, h.index, h.speed, h.u_a, h.u_c, h.u_precursor, h.c_head,
        h.c_tail, h.u_shock)
    # lines from the origin ---------------------------------------------------------------
    t_top = T_SHOW * US
    cmap, top = light_cmap(), sigma[c] * GPA

    def shade(value):
        return cmap(0.5 + 0.5 * value / top)

    x_pre, x_head, x_tail = (v * T_SHOW * MM for v in (u_precursor, c_head, c_tail))
    ax_xt.fill([0, x_tail, 0], [0, t_top, t_top], color=shade(sigma[c] * GPA), lw=0)
    ax_xt.fill([0, x_pre, x_head], [0, t_top, t_top], color=shade(sigma[a] * GPA), lw=0)
    ax_xt.fill([0, x_head, x_tail], [0, t_top, t_top],
               color=shade(0.5 * (sigma[a] + sigma[b]) * GPA), lw=0)
    fan_k = [k for k in range(1, len(index)) if a < index[k] <= b]
    for k in fan_k[:: max(1, len(fan_k) // 12)] + [fan_k[-1]]:
        ax_xt.plot([0, speed[k] * T_SHOW * MM], [0, t_top], color=FAN, lw=0.6)
    ax_xt.plot([0, x_pre], [0, t_top], color=CHORD, lw=2.0)
    ax_xt.plot([0, x_tail], [0, t_top], color=CHORD, lw=2.4)
    ax_xt.set_xlim(0.0, x_pre * 1.05)
    ax_xt.set_ylim(0.0, t_top)
    ax_xt.set_xlabel("Lagrangian position X (mm)")
    ax_xt.set_ylabel("time t (µs)")
    ax_xt.set_title("X–t: the composite wave from an impact at X = 0, t = 0", fontsize=10)
    ax_xt.annotate(f"precursor U = {u_precursor:.0f} m/s", (0.75 * x_pre, 0.75 * t_top),
                   xytext=(14, -14), textcoords="offset points", fontsize=8, color=CHORD,
                   ha="left", va="top", bbox={"fc": "white", "ec": "none", "alpha": 0.85},
                   arrowprops={"arrowstyle": "-", "color": CHORD, "lw": 0.7})
    ax_xt.annotate(f"fan {c_head:.0f} → {c_tail:.0f} m/s\n+ shock U = {u_shock:.0f} m/s",
                   (0.45 * x_tail, 0.45 * t_top), xytext=(0.18 * x_tail, 0.55 * t_top),
                   textcoords="data", fontsize=8, color=FAN, ha="center", va="bottom",
                   bbox={"fc": "white", "ec": "none", "alpha": 0.85},
                   arrowprops={"arrowstyle": "-", "color": FAN, "lw": 0.7})
    ax_xt.text(0.22 * x_tail, 0.95 * t_top,
               f"behind the shock:\nσ = {sigma[c] * GPA:.2f} GPa, u = {u_c:.1f} m/s",
               fontsize=7.5, ha="center", va="top",
               bbox={"fc": "white", "ec": "#aaaaaa", "lw": 0.5, "alpha": 0.9})
    zoom = ax_xt.inset_axes([0.6, 0.07, 0.37, 0.33])
    zoom.fill([0, x_tail, 0], [0, t_top, t_top], color=shade(sigma[c] * GPA), lw=0)
    zoom.fill([0, x_pre, x_head], [0, t_top, t_top], color=shade(sigma[a] * GPA), lw=0)
    for k in fan_k[:: max(1, len(fan_k) // 12)] + [fan_k[-1]]:
        zoom.plot([0, speed[k] * T_SHOW * MM], [0, t_top], color=FAN, lw=0.6)
    zoom.plot([0, x_pre], [0, t_top], color=CHORD, lw=1.6)
    zoom.plot([0, x_tail], [0, t_top], color=CHORD, lw=2.0)
    zoom.set_xlim(x_tail - 0.4, x_pre + 0.15)
    zoom.set_ylim(0.88 * t_top, t_top)
    zoom.tick_params(labelsize=6.5)
    zoom.set_title("zoom near the top", fontsize=7)
    t_label = 0.93 * t_top
    zoom.annotate(f"HEL state {sigma[a] * GPA:.3f} GPa,\nu = {u_a:.1f} m/s",
                  (0.5 * (c_head + u_precursor) * t_label * 1e-3, t_label),
                  xytext=(x_pre + 0.1, 0.895 * t_top), textcoords="data", fontsize=6.5,
                  ha="right", va="bottom", color="#333333",
                  arrowprops={"arrowstyle": "-", "color": "#333333", "lw": 0.6})
    ax_xt.indicate_inset_zoom(zoom, edgecolor="#888888")

    return x_pre, x_head, x_tail


def draw_profile(ax_s, h: Hull, x_pre: float, x_head: float, x_tail: float) -> None:
    """The stress profile at ``T_SHOW``: step, ramp, step."""
    (eps, sigma, a, b, c, index, speed, u_precursor) = (
        h.eps, h.sigma, h.a, h.b, h.c, h.index, h.speed, h.u_precursor)
    # the stress profile -------------------------------------------------------------------
    xs, values = profile(eps, sigma, index, speed, T_SHOW)
    ax_s.plot(xs, values, color=PATH, lw=1.6)
    x0 = x_tail - 0.9
    ax_s.set_xlim(x0, x_pre + 0.35)
    ax_s.set_ylim(-0.1, sigma[c] * GPA * 1.15)
    ax_s.set_xlabel("Lagrangian position X (mm)")
    ax_s.set_ylabel("stress σ (GPa, compression > 0)")
    ax_s.set_title(f"stress profile at t = {T_SHOW * US:.1f} µs: step, ramp, step",
                   fontsize=10)
    ax_s.grid(True, lw=0.3, alpha=0.5)
    top_axis = ax_s.secondary_xaxis("top", functions=(lambda x: x * 1e-3 / T_SHOW,
                                                       lambda v: v * T_SHOW * 1e3))
    top_axis.set_xlabel("X/t (m/s): the wave is self-similar", fontsize=8, labelpad=2)
    top_axis.tick_params(labelsize=8)
    common.mark(ax_s, x_pre, 0.5 * sigma[a] * GPA,
                f"precursor to the HEL\n{sigma[a] * GPA:.3f} GPa at {u_precursor:.0f} m/s",
                offset=(-8, 150), color=CHORD, ha="right")
    common.mark(ax_s, 0.5 * (x_head + x_tail), 0.5 * (sigma[a] + sigma[b]) * GPA,
                f"fan: ramp {sigma[a] * GPA:.2f} → {sigma[b] * GPA:.2f} GPa\n"
                f"over {x_head - x_tail:.2f} mm at t = {T_SHOW * US:.0f} µs", offset=(25, 25),
                color=FAN)
    common.mark(ax_s, x_tail, 0.5 * (sigma[b] + sigma[c]) * GPA,
                f"shock {sigma[b] * GPA:.2f} → {sigma[c] * GPA:.2f} GPa", offset=(-20, 10),
                color=CHORD, ha="right")



def caption_text(h: Hull) -> str:
    """The figure's caption: the material, the hull's three waves and the compared loads."""
    (eps, sigma, a, b, c, u_a, u_b, u_c, u_precursor, c_head, c_tail, u_shock) = (
        h.eps, h.sigma, h.a, h.b, h.c, h.u_a, h.u_b, h.u_c, h.u_precursor, h.c_head, h.c_tail,
        h.u_shock)
    pct = 100.0
    weak_kinds = [p["kind"] for p in h.weak[2]]
    strong_eps, strong_sigma, strong_pieces = h.strong
    strong_fan = strong_pieces[1] if len(strong_pieces) > 1 else None
    c_elastic = math.sqrt(C0**2 + 4.0 * G / (3.0 * RHO))
    strong = (f"a load twice as strong ({strong_sigma[-1] * GPA:.2f} GPa) shrinks the fan to "
              f"{strong_fan['speeds'][0]:.0f} → {strong_fan['speeds'][1]:.0f} m/s (to "
              f"ε = {strong_eps[strong_fan['end']] * pct:.2f} %) and its shock carries the rest"
              if strong_fan is not None and strong_fan["kind"] == "fan"
              else f"a load twice as strong has waves {[p['kind'] for p in strong_pieces]}")
    text = (f"Al 6061-like solid, ρ0 = {RHO:.0f} kg/m³, c0 = {C0:.0f} m/s, s = {S}, Γ0 = 0 "
            f"(σ depends on ε alone), G = {G * GPA:.0f} GPa, Voce hardening Y0 = "
            f"{Y0 * GPA:.2f} GPa, Ysat = {Y_SAT * GPA:.2f} GPa, εr = {EPS_R * pct:.1f} %. "
            f"Loading to ε = {EPS_END * pct:.0f} % ({sigma[c] * GPA:.3f} GPa): the hull is "
            f"the chord O→A (elastic precursor to the HEL, {sigma[a] * GPA:.3f} GPa at "
            f"ε = {eps[a] * pct:.3f} %, U = {u_precursor:.0f} m/s, above the elastic sound "
            f"speed {c_elastic:.0f} m/s), the concave path A→B (a fan, C = {c_head:.0f} → "
            f"{c_tail:.0f} m/s, to {sigma[b] * GPA:.3f} GPa at ε = {eps[b] * pct:.2f} %) and "
            f"the chord B→C tangent at B (a shock at U = {u_shock:.0f} m/s, riding on the "
            f"fan's tail). Particle velocity {u_a:.1f}, {u_b:.1f}, {u_c:.1f} m/s behind "
            f"precursor, fan and shock. Each wave is slower than the one ahead (speeds "
            f"√(slope/ρ0) fall along a concave hull), so the structure is stable. A weaker "
            f"load ending inside the concave stretch (W, ε = {EPS_WEAK * pct:.0f} %) gives "
            f"{' + '.join(names(weak_kinds))}; {strong}. Linear hardening keeps the branch convex: "
            f"precursor + one plastic shock.")
    return text


def main() -> None:
    h = build()
    eps, sigma, a, b, c = h.eps, h.sigma, h.a, h.b, h.c
    weak_kinds, strong_pieces = [p["kind"] for p in h.weak[2]], h.strong[2]
    figure = Figure(figsize=(13.0, 10.6))
    grid = figure.add_gridspec(2, 2, left=0.065, right=0.985, top=0.925, bottom=0.2,
                               wspace=0.22, hspace=0.42)
    draw_path(figure.add_subplot(grid[0, 0]), h)
    draw_sheared(figure.add_subplot(grid[0, 1]), h)
    x_pre, x_head, x_tail = draw_xt(figure.add_subplot(grid[1, 0]), h)
    draw_profile(figure.add_subplot(grid[1, 1]), h, x_pre, x_head, x_tail)
    figure.suptitle("Saturating (Voce) hardening: the convex-hull construction gives "
                    "precursor + fan + shock", fontsize=12, y=0.985)
    common.caption(figure, caption_text(h), width=170)
    common.save(figure, NAME,
                f"Voce hardening (Y0 {Y0 * GPA:.2f} → Ysat {Y_SAT * GPA:.2f} GPa) makes the "
                f"plastic loading path concave beyond the HEL: loading to {sigma[c] * GPA:.2f} "
                f"GPa gives a precursor at {h.u_precursor:.0f} m/s to {sigma[a] * GPA:.3f} GPa, "
                f"a fan {h.c_head:.0f} → {h.c_tail:.0f} m/s to {sigma[b] * GPA:.2f} GPa and a "
                f"shock at {h.u_shock:.0f} m/s (the upper concave hull of σ(ε)).")
    print(f"precursor U = {h.u_precursor:.2f} m/s to {sigma[a] * GPA:.4f} GPa (eps "
          f"{eps[a]:.6f}, u {h.u_a:.3f}); fan {h.c_head:.2f} -> {h.c_tail:.2f} m/s to "
          f"{sigma[b] * GPA:.4f} GPa (eps {eps[b]:.6f}, u {h.u_b:.3f}); shock {h.u_shock:.2f} "
          f"m/s to {sigma[c] * GPA:.4f} GPa (u {h.u_c:.3f}); weak {weak_kinds}; "
          f"strong {[p['kind'] for p in strong_pieces]}")


if __name__ == "__main__":
    main()
