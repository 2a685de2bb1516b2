"""The interferometer's view: true and apparent velocity behind an optical window.

One figure per interface probe with a window: the interface velocity the run
computes and the apparent velocity an interferometer reports through the
shocked window (``fronttrack.windows``).  Units: µs and m/s.
"""

from __future__ import annotations

import matplotlib.pyplot as plt

from .plotting.style import T_LABEL, U_LABEL, US, title_of
from .windows import window_record


def plot_window_velocity(solution, probe: str, ax=None):
    """Draw the true and the apparent velocity at ``probe``; return the ``WindowRecord``."""
    record = window_record(solution, probe)
    if ax is None:
        _, ax = plt.subplots(figsize=(7.0, 4.4))
    ax.plot(record.t * US, record.u, color="#1f4e9c", lw=1.5, label="interface velocity")
    ax.plot(record.t * US, record.u_apparent, color="#8b0000", lw=1.2, ls="--",
            label=f"apparent through {record.window.name} (a = {record.window.a:g})")
    ax.set_xlabel(T_LABEL)
    ax.set_ylabel(U_LABEL)
    ax.set_xlim(0.0, solution.scene.t_end * US)
    ax.set_title(title_of(solution, f"interferometer at {probe}"), fontsize=10)
    ax.legend(fontsize=8, loc="best")
    return record
