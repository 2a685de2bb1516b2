"""The attenuation curve: the largest stress each Lagrangian station ever sees.

The solution is a tiling of the X–t plane by constant-state regions, so the
peak at a station X is the largest stress among the regions whose closure
meets the line X in a segment.  Computed for many stations at once with numpy
(in chunks of regions, to bound memory).  Units: m, Pa.
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
        xs = np.array([p[0] for p in region.polygon()])
        lo, hi = xs.min(), xs.max()
        rows.append((lo, hi, np.count_nonzero(xs == lo) > 1, np.count_nonzero(xs == hi) > 1))
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
