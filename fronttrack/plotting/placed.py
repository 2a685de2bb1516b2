"""What a plot function placed on its axes, returned to the caller.

Plot functions return a ``Placed`` record instead of storing what they drew as
attributes of the matplotlib axes: the axes, the reader-facing number of each
numbered region (``fronttrack.numbering``), where each number was written (in
the axes' data units), the text artists placed (numbers and annotations, for
layout checks), the title pad that clears the key above an X–t diagram, and the
stress colour bar, if any.
"""

from __future__ import annotations

from dataclasses import dataclass, field


@dataclass(frozen=True)
class Placed:
    """The result of one diagram.

    Attributes
    ----------
    ax : matplotlib.axes.Axes
        The axes drawn on.
    numbers : dict
        ``{region_id: number}`` of the numbered regions shown (numbers 1, 2, …).
    labels : dict
        ``{region_id: (x, y)}``: where the region's number was written, in data
        units (mm and µs on an X–t diagram, m/s and GPa on a σ–u diagram).
    texts : tuple
        The ``matplotlib.text.Text`` artists placed (numbers, annotations).
    title_pad : float
        Space (pt) between the axes and its title that clears the key (6 if none).
    colorbar : matplotlib.colorbar.Colorbar or None
        The stress colour bar, if the regions were shaded.
    """

    ax: object
    numbers: dict = field(default_factory=dict)
    labels: dict = field(default_factory=dict)
    texts: tuple = ()
    title_pad: float = 6.0
    colorbar: object = None
