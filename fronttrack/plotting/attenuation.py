"""The attenuation curve: the largest stress each Lagrangian station ever sees.

The solution is a tiling of the X–t plane by constant-state regions, so the
peak at a station X is the largest stress among the regions whose closure
meets the line X in a segment.  It is therefore constant between the X where
the regions begin and end (the X of the fronts' end points): ``peak_stress_steps``
gives it exactly there, as steps, with no sampling; where a fan overtakes a
shock the steps are the rays (one step per ray crossing).  ``peak_stress``
reads it at chosen stations.  Units: m, Pa.
"""

from __future__ import annotations

import numpy as np


def _extents(regions) -> np.ndarray:
    """Per region: X-extent ``(lo, hi)`` (m) and whether a vertical edge lies at each end.

    A region touching a station only at one vertex (a wave reflecting there)
    never holds at that station; one with a vertical edge there (a site) does.
    """
    rows = []
    for region in regions:
        xs = [p[0] for p in region.vertices]
        lo, hi = min(xs), max(xs)
        rows.append((lo, hi, xs.count(lo) > 1, xs.count(hi) > 1))
    return np.array(rows, dtype=float).reshape(-1, 4)


def peak_stress(solution, n=200):
    """Largest compression and largest tension (Pa) reached at ``n`` stations in X (m).

    A region covers every X strictly between the extremes of its polygon (a
    connected region's projection on X is an interval) and an extreme X where it
    has a vertical edge, so the peak at X is the largest stress among the
    regions covering it.  Returns ``(X, max_sigma, min_sigma)`` arrays.
    """
    x = np.linspace(0.0, solution.scene.length, n)
    extents = _extents(solution.regions)
    sigma = np.array([r.state.sigma for r in solution.regions])
    top = np.full(n, -np.inf)
    bottom = np.full(n, np.inf)
    chunk = max(1, 2_000_000 // n)
    for start in range(0, len(sigma), chunk):
        lo, hi, edge_lo, edge_hi = (extents[start:start + chunk, k:k + 1] for k in range(4))
        covers = ((lo < x) & (x < hi)) | ((x == lo) & (edge_lo > 0)) | ((x == hi) & (edge_hi > 0))
        s = sigma[start:start + chunk, None]
        top = np.maximum(top, np.where(covers, s, -np.inf).max(axis=0))
        bottom = np.minimum(bottom, np.where(covers, s, np.inf).min(axis=0))
    return x, top, bottom


def _paint(order, first, last, values, size: int) -> np.ndarray:
    """Each interval ``k`` of ``size`` takes the value of the first of ``order`` covering it.

    Region ``i`` covers intervals ``first[i]`` to ``last[i] - 1``; a union–find
    pointer skips intervals already painted, so every interval is visited once.
    """
    result = np.full(size, np.nan)
    following = list(range(size + 1))

    def find(k: int) -> int:
        root = k
        while following[root] != root:
            root = following[root]
        while following[k] != root:
            following[k], k = root, following[k]
        return root

    for i in order:
        k = find(int(first[i]))
        while k < last[i]:
            result[k] = values[i]
            following[k] = k + 1
            k = find(k + 1)
    return result


def peak_stress_steps(solution) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The exact attenuation curve as steps: ``(edges, max_sigma, min_sigma)`` (m, Pa).

    ``edges`` (n + 1) are the X where regions begin or end; between ``edges[k]``
    and ``edges[k + 1]`` the largest compression ever reached is ``max_sigma[k]``
    and the largest tension ``min_sigma[k]`` (the lowest stress).
    """
    regions = solution.regions
    extents = _extents(regions)
    sigma = np.array([r.state.sigma for r in regions])
    edges = np.unique(extents[:, :2])
    first = np.searchsorted(edges, extents[:, 0])
    last = np.searchsorted(edges, extents[:, 1])
    size = len(edges) - 1
    top = _paint(np.argsort(-sigma, kind="stable"), first, last, sigma, size)
    bottom = _paint(np.argsort(sigma, kind="stable"), first, last, sigma, size)
    return edges, top, bottom
