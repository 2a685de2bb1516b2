"""Where the continuous tension field of a lattice first reaches a strength.

In a lattice every ray carries an exact state at each of its nodes, and between two
nodes of a ray the stress is continuous (second order in the node spacing).  The
*level set* ``sigma(X, t) = -S`` of the strength ``S`` is therefore found ray by ray:
between consecutive nodes of a ray where the stress passes ``-S`` the crossing point
is interpolated.  The points so found, sorted in ``X``, sample the curve ``t = T(X)``:
the time each material point first reaches the strength.

With an instantaneous threshold (Davison §12) the first fracture is the lowest point
of that curve (its vertex, from a parabola through the lowest sample and its
neighbours).  The fracture relieves the material around it only as fast as sound
travels, while near its vertex the level set spreads faster than sound
(``|dT/dX| < 1/C``): every point it reaches before the relief fractures too.  The
threshold model therefore fractures a *zone*, continuously, out to where the level
set slows to the sound speed (``|dT/dX| = 1/C``) on each side.  ``fracture_zone``
returns the first point and the two ends of that zone.

An end that is the last sample on its side (the level set still spreads faster than
sound there, as far as the lattice saw it) is *open*: the field beyond was not solved
yet, and a later lattice may find the level set going on (``fronttrack.spall``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class FractureZone:
    """The first fracture ``(x, t)`` (m, s) and the zone the threshold fractures:
    ``x_lo``/``x_hi`` (m) reached at ``t_lo``/``t_hi`` (s); ``slowness`` (s/m) the inverse
    of the relief's sound speed; ``open_lo``/``open_hi``: that end is the last sample of
    the level set, still faster than sound (the module docstring)."""

    x: float
    t: float
    x_lo: float
    t_lo: float
    x_hi: float
    t_hi: float
    slowness: float = 0.0
    open_lo: bool = False
    open_hi: bool = False

    @property
    def width(self) -> float:
        return self.x_hi - self.x_lo


def level_points(lattice, level: float) -> tuple[np.ndarray, np.ndarray]:
    """Points ``(X, t)`` where the stress carried along the lattice's rays passes
    ``level`` (Pa) downward, interpolated linearly between consecutive nodes of a ray."""
    seg_start = lattice.seg_start
    new = seg_start >= 0
    if not np.any(new):
        return np.empty(0), np.empty(0)
    tags = lattice.seg_tag[new]
    starts = seg_start[new]
    order = np.lexsort((lattice.node_t[starts], tags))
    tags, starts = tags[order], starts[order]
    same_ray = tags[1:] == tags[:-1]
    a, b = starts[:-1][same_ray], starts[1:][same_ray]
    sa, sb = lattice.node_sigma[a], lattice.node_sigma[b]
    crossing = (sa > level) & (sb <= level)
    a, b, sa, sb = a[crossing], b[crossing], sa[crossing], sb[crossing]
    f = (sa - level) / (sa - sb)
    x = lattice.node_x[a] + f * (lattice.node_x[b] - lattice.node_x[a])
    t = lattice.node_t[a] + f * (lattice.node_t[b] - lattice.node_t[a])
    return x, t


def face_points(lattice, level: float, x_face: float) -> tuple[np.ndarray, np.ndarray]:
    """Points ``(x_face, t)`` where the stress at the lattice's nodes on a face held at
    a velocity (a wall at ``x_face``, m) passes ``level`` (Pa) downward, interpolated
    linearly in time between consecutive nodes there.

    Along a held face the reflections double the relief that arrives (stress
    reflection ``+1``): a release that reaches the face puts it in the most tension
    near it.  The face's nodes belong to the rays that reflect there, each met once,
    so ``level_points`` samples the level set only a node spacing away from it."""
    on = np.nonzero(lattice.node_x == x_face)[0]
    on = on[np.argsort(lattice.node_t[on], kind="stable")]
    sa, sb = lattice.node_sigma[on[:-1]], lattice.node_sigma[on[1:]]
    crossing = np.nonzero((sa > level) & (sb <= level))[0]
    ta, tb = lattice.node_t[on[:-1]][crossing], lattice.node_t[on[1:]][crossing]
    f = (sa[crossing] - level) / (sa[crossing] - sb[crossing])
    return np.full(crossing.size, x_face), ta + f * (tb - ta)


def fracture_zone(lattice, strength: float, speed: float,
                  carried=(), faces=()) -> FractureZone | None:
    """The first fracture and the zone the threshold model fractures with it (see the
    module docstring); ``speed`` (m/s) is the sound speed of the relief; points inside
    the ``carried`` intervals (earlier zones) are left out; ``faces``: the positions (m)
    of the lattice's ends held at a velocity, sampled by ``face_points``.  ``None`` when
    the tension never passes the strength."""
    samples = [level_points(lattice, -strength),
               *(face_points(lattice, -strength, x) for x in faces)]
    x = np.concatenate([a for a, _ in samples])
    t = np.concatenate([b for _, b in samples])
    outside = np.ones(x.size, bool)
    for lo, hi in carried:
        outside &= (x < lo) | (x > hi)
    x, t = x[outside], t[outside]
    if x.size == 0:
        return None
    x, t = _lower_envelope(x, t)
    first = int(np.argmin(t))
    x_f, t_f = _vertex(x, t, first)
    # a relief with no sound speed (a gas at zero pressure) reaches nothing: every point
    # that reaches the level fractures of itself
    slowness = 1.0 / speed if speed > 0.0 else math.inf
    hi = first
    while hi + 1 < x.size and (t[hi + 1] - t[hi]) < slowness * (x[hi + 1] - x[hi]):
        hi += 1
    lo = first
    while lo > 0 and (t[lo - 1] - t[lo]) < slowness * (x[lo] - x[lo - 1]):
        lo -= 1
    x_lo, t_lo = (x[lo], t[lo]) if lo < first else (x_f, t_f)
    x_hi, t_hi = (x[hi], t[hi]) if hi > first else (x_f, t_f)
    for end in (hi, lo):
        if x[end] in faces:
            # a zone that reaches a held face (``face_points``) fractures the face first:
            # the zone is one piece from the face to its other end, and no plane beside
            # the face leaves a skin on it ringing between stress reflections +1 and -1
            # for ever (the first sample lay 3.9 um off a wall, Cu 3 mm at 100 m/s)
            x_f, t_f = float(x[end]), float(t[end])
    return FractureZone(x=x_f, t=t_f, x_lo=float(min(x_lo, x_f)), t_lo=float(t_lo),
                        x_hi=float(max(x_hi, x_f)), t_hi=float(t_hi), slowness=slowness,
                        open_lo=lo == 0, open_hi=hi == x.size - 1)


def _lower_envelope(x: np.ndarray, t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The points sorted in X, keeping at each X the earliest (a ray may pass the level
    again later, after the tension was relieved and rose again)."""
    order = np.lexsort((t, x))
    x, t = x[order], t[order]
    keep = np.ones(x.size, bool)
    keep[1:] = x[1:] != x[:-1]
    x, t = x[keep], t[keep]
    # drop later passes: a point later than both neighbours by more than their spread
    # is a second crossing of the same material, not the first arrival of the level
    if x.size > 2:
        first_arrival = np.minimum.accumulate(t) == t
        first_arrival |= np.minimum.accumulate(t[::-1])[::-1] == t
        x, t = x[first_arrival], t[first_arrival]
    return x, t


def _vertex(x: np.ndarray, t: np.ndarray, i: int) -> tuple[float, float]:
    """The vertex of the parabola through the lowest sample and its neighbours."""
    if i == 0 or i == x.size - 1:
        return float(x[i]), float(t[i])
    x0, x1, x2 = x[i - 1], x[i], x[i + 1]
    t0, t1, t2 = t[i - 1], t[i], t[i + 1]
    d01, d12 = (t1 - t0) / (x1 - x0), (t2 - t1) / (x2 - x1)
    curvature = (d12 - d01) / (x2 - x0)
    if not curvature > 0.0:
        return float(x1), float(t1)
    # t = t1 + d (x - x1) + curvature (x - x1)(x - x_other) around x1
    slope_at_x1 = d01 + curvature * (x1 - x0)
    x_v = x1 - slope_at_x1 / (2.0 * curvature)
    if not x0 <= x_v <= x2:
        return float(x1), float(t1)
    t_v = t1 + slope_at_x1 * (x_v - x1) + curvature * (x_v - x1) ** 2
    return float(x_v), float(min(t_v, t1))
