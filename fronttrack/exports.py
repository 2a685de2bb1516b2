"""Tables a user asks of a solution: peak stress and impulse against depth, records on a
uniform time step.

- ``peak_table``: at stations across the stack, the largest compression and the
  largest tension each ever sees (Pa, from the regions: exact) and the impulse
  per unit area ``∫ sigma dt`` over the run (Pa s, exact for the records, which
  are linear between their break points).
- ``resampled``: a record read at ``0, dt, 2 dt, ...`` (right limits at jumps).

Both come as plain dicts of lists (SI) that ``write_csv`` and ``write_json`` store.
"""

from __future__ import annotations

import csv
import json
import math
from pathlib import Path

import numpy as np

from .errors import SceneError
from .plotting.attenuation import peak_stress
from .solution import History, Solution


def peak_table(solution: Solution, stations: int = 101) -> dict[str, list[float]]:
    """Peak compression, peak tension and impulse at ``stations`` evenly spaced X.

    Returns ``{"X_m", "peak_sigma_Pa", "peak_tension_Pa", "impulse_Pa_s"}``; the
    tension is positive (0 where a station never goes into tension).
    """
    if not (isinstance(stations, int) and 2 <= stations <= 100_000):
        raise SceneError(f"stations: must be an integer in 2..100000, got {stations!r}")
    x, top, bottom = peak_stress(solution, n=stations)
    t_end = solution.scene.t_end
    impulse = []
    for station in x:
        history = solution.history(float(station))
        impulse.append(history.integral(history.sigma, t_end, history.sigma_end))
    return {"X_m": x.tolist(), "peak_sigma_Pa": top.tolist(),
            "peak_tension_Pa": np.maximum(-bottom, 0.0).tolist(), "impulse_Pa_s": impulse}


def resampled(history: History, dt: float) -> dict[str, list[float]]:
    """``history`` read every ``dt`` (s) from 0 to its end: ``{"t_s", "sigma_Pa",
    "u_m_per_s", "rho_kg_per_m3"}`` (right limits at jumps; density linear in volume
    between break points)."""
    if not (isinstance(dt, float) and math.isfinite(dt) and dt > 0.0):
        raise SceneError(f"dt: must be a time > 0 s, got {dt!r}")
    count = math.floor(history.stop / dt + 1e-9) + 1
    if count > 10_000_000:
        raise SceneError(f"dt: {dt!r} s gives {count} samples; the limit is 10000000")
    t = np.arange(count) * dt
    return {"t_s": t.tolist(), "sigma_Pa": history.at(t, "sigma").tolist(),
            "u_m_per_s": history.at(t, "u").tolist(),
            "rho_kg_per_m3": (1.0 / history.at(t, "v")).tolist()}


def write_csv(columns: dict[str, list[float]], path: Path) -> Path:
    """Store a dict of equal-length columns as CSV (floats in full precision)."""
    with Path(path).open("w", newline="") as handle:
        writer = csv.writer(handle)
        writer.writerow(columns)
        for row in zip(*columns.values(), strict=True):
            writer.writerow([repr(float(value)) for value in row])
    return Path(path)


def write_json(columns: dict[str, list[float]], path: Path, compact: bool = False) -> Path:
    """Store a dict of columns as JSON (non-finite values as null)."""
    clean = {k: [v if math.isfinite(v) else None for v in values]
             for k, values in columns.items()}
    Path(path).write_text(json.dumps(clean, separators=(",", ":")) if compact
                          else json.dumps(clean, indent=1))
    return Path(path)
