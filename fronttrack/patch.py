"""The interior of a lattice, kept as arrays.

A lattice of ``N x M`` nodes makes about ``2 N M`` ray segments and ``N M`` cells that
begin and end inside it.  They are stored here as arrays, and become ``FrontRecord``
and ``RegionRecord`` objects only when a user asks for the solution's fronts or
regions (a diagram, a JSON file); the queries of a ``Solution`` read the arrays.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from materials import State

from .fronts import MIXED, FrontRecord, RegionRecord, polygon_of
from .kinds import FrontKind


@dataclass(frozen=True)
class LatticePatch:
    """Segments and cells that began and ended inside one lattice (SI units).

    ``layers``: the layer of each cell.  Segments: ``seg_id``, ``seg_x0``, ``seg_t0``,
    ``seg_t1``, ``seg_speed``,
    ``seg_direction``, ``seg_invariant``, ``seg_fan``, ``seg_ray_index``,
    ``seg_ray_count``, ``seg_left``/``seg_right`` (region ids), ``seg_jump`` (Pa).
    Cells: ``cell_id``, the state arrays, ``cell_t0``/``cell_t1``, and their boundary
    chains as point arrays (``chain_x``, ``chain_t``, grouped by cell and side:
    ``chain_start[i]`` and ``chain_split[i]`` delimit cell ``i``'s left chain, then its
    right chain up to ``chain_start[i + 1]``).  ``lineage``: that of all its segments
    (``fronttrack.zones._lineage``).
    """

    material: object
    layers: np.ndarray
    table: object
    seg_id: np.ndarray
    seg_x0: np.ndarray
    seg_t0: np.ndarray
    seg_t1: np.ndarray
    seg_speed: np.ndarray
    seg_direction: np.ndarray
    seg_invariant: np.ndarray
    seg_fan: np.ndarray
    seg_ray_index: np.ndarray
    seg_ray_count: np.ndarray
    seg_left: np.ndarray
    seg_right: np.ndarray
    seg_jump: np.ndarray
    cell_id: np.ndarray
    cell_sigma: np.ndarray
    cell_u: np.ndarray
    cell_v: np.ndarray
    cell_e: np.ndarray
    cell_t0: np.ndarray
    cell_t1: np.ndarray
    chain_x: np.ndarray
    chain_t: np.ndarray
    chain_start: np.ndarray
    chain_split: np.ndarray
    lineage: int = MIXED

    def state(self, index: int) -> State:
        """The state of cell ``index`` (position in the arrays, not its id)."""
        return State(sigma=float(self.cell_sigma[index]), u=float(self.cell_u[index]),
                     v=float(self.cell_v[index]), e=float(self.cell_e[index]))

    def polygon(self, index: int) -> list[tuple[float, float]]:
        """Boundary of cell ``index`` as ``(X, t)`` vertices (m, s)."""
        start, split, end = (int(self.chain_start[index]), int(self.chain_split[index]),
                             int(self.chain_start[index + 1]))
        left = list(zip(self.chain_x[start:split].tolist(), self.chain_t[start:split].tolist(),
                        strict=True))
        right = list(zip(self.chain_x[split:end].tolist(), self.chain_t[split:end].tolist(),
                         strict=True))
        return polygon_of(left, right)

    def front_records(self) -> list[FrontRecord]:
        """The segments as frozen front records."""
        x1 = self.seg_x0 + self.seg_speed * (self.seg_t1 - self.seg_t0)
        return [FrontRecord(
            id=int(self.seg_id[i]), kind=FrontKind.RAY, x0=float(self.seg_x0[i]),
            t0=float(self.seg_t0[i]), x1=float(x1[i]), t1=float(self.seg_t1[i]),
            speed=float(self.seg_speed[i]), direction=int(self.seg_direction[i]),
            jump=float(self.seg_jump[i]), fan=int(self.seg_fan[i]),
            ray_index=int(self.seg_ray_index[i]), ray_count=int(self.seg_ray_count[i]),
            invariant=float(self.seg_invariant[i]), left_region=int(self.seg_left[i]),
            right_region_id=int(self.seg_right[i]), lineage=self.lineage)
            for i in range(len(self.seg_id))]

    def region_records(self) -> list[RegionRecord]:
        """The cells as frozen region records."""
        return [RegionRecord(id=int(self.cell_id[i]), state=self.state(i),
                             material=self.material, layer=int(self.layers[i]),
                             t_start=float(self.cell_t0[i]),
                             t_end=None if math.isnan(self.cell_t1[i]) else float(
                                 self.cell_t1[i]),
                             in_fan=True, vertices=tuple(self.polygon(i)),
                             birth=self.birth(i))
                for i in range(len(self.cell_id))]

    def birth(self, index: int) -> tuple[float, float]:
        """The first vertex of cell ``index``'s left boundary (where it began)."""
        start = int(self.chain_start[index])
        return float(self.chain_x[start]), float(self.chain_t[start])
