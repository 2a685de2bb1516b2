"""A PMMA-insulated stress gauge between two Al 2024 sample plates: ring-up of the package.

A manganin foil gauge is sandwiched between two 50 µm PMMA sheets and glued
between Al 2024 plates; an Al 2024 flyer at 500 m/s drives a shock through the
front plate.  The gauge sits in PMMA, a fifth of the aluminium's impedance, so
it first reads a fraction of the stress in the sample and rings up to it in a
few round trips of the package (the foil itself, a few µm, is left out).
"""

from __future__ import annotations

import common

NAME = common.script_name(__file__)


def main() -> None:
    def text(n):
        reach = (f"it stays within 5 % of the sample stress from {n['reach']:.2f} µs"
                 if n["reach"] is not None else "it has not reached the sample stress")
        return (f"The shock in the Al 2024 sample carries {n['target']:.2f} GPa. Entering the "
                f"100 µm PMMA package it drops to {n['first']:.2f} GPa "
                f"({n['first'] / n['target'] * 100:.0f} %), the first reading of the gauge; each "
                f"reflection from the aluminium faces adds a reshock, and {reach}, "
                f"{n['reach'] - n['arrival']:.2f} µs after the shock arrives. The gauge therefore "
                f"records a rise time set by the "
                f"package, not by the shock: thinner insulation (or a gauge in a matched "
                f"material) shortens it. The Al record before the package shows the release "
                f"sent back by the soft layer. X–t zoomed on the package; region numbers "
                f"omitted.")

    def save_text(n):
        return (f"PMMA-insulated gauge in Al 2024 (flyer at 500 m/s): the gauge first reads "
                f"{n['first']:.2f} GPa and rings up to the sample's {n['target']:.2f} GPa.")

    common.layer_figure(NAME, "gauge", "Al ahead",
                        "Gauge package: a PMMA-insulated gauge in Al 2024 rings up to the "
                        "sample stress", text, save_text, zoom=(4.0, 6.2),
                        layer_label="between the PMMA sheets")


if __name__ == "__main__":
    main()
