"""Ring-up: a thin low-impedance layer (PMMA) between high-impedance plates (Cu).

A Cu flyer at 500 m/s strikes a Cu plate carrying a 0.2 mm PMMA layer and a Cu
back plate.  The stress in the PMMA climbs in a staircase of reshocks, one per
round trip in the layer, to the stress of the copper around it: the
Cu-on-Cu impedance match.  This is how an embedded gauge or a glue bond sees a
shock.
"""

from __future__ import annotations

import common

NAME = common.script_name(__file__)


def main() -> None:
    def text(n):
        reach = (f"stays within 5 % of it from {n['reach']:.2f} µs" if n["reach"] is not None
                 else "is still below it")
        return (f"The shock from the Cu flyer ({n['target']:.2f} GPa in the copper) enters the "
                f"PMMA, whose impedance is less than a tenth of copper's: the first step in the "
                f"layer is "
                f"only {n['first']:.2f} GPa, and a release fan goes back into the front plate "
                f"(the dip in its record). At each face of the layer the wave reflects from "
                f"stiffer copper as a reshock, so the stress climbs in a staircase "
                f"({n['final']:.2f} GPa at the end of the run) and {reach}. "
                f"X–t zoomed on the layer (dashed verticals); region numbers omitted.")

    def save_text(n):
        return (f"Ring-up of 0.2 mm PMMA between Cu plates (Cu flyer at 500 m/s): the layer "
                f"starts at {n['first']:.2f} GPa and climbs in reshock steps to the copper's "
                f"{n['target']:.2f} GPa.")

    common.layer_figure(NAME, "layer", "Cu front plate",
                 "Ring-up: a thin PMMA layer between Cu plates climbs to the copper's stress",
                 text, save_text, zoom=(3.0, 5.6))


if __name__ == "__main__":
    main()
