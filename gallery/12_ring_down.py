"""Ring-down: a thin high-impedance layer (Cu) between low-impedance plates (PMMA).

A PMMA flyer at 1 km/s strikes a PMMA plate carrying a 0.2 mm Cu layer and a
PMMA back plate.  The stiff layer is hit as if by a flyer: the first shock in
it is almost twice as strong as the PMMA's own.  Each reflection from the soft
PMMA faces is a release, and the stress in the copper rings down, in steps, to
the stress of the PMMA around it.
"""

from __future__ import annotations

import common

NAME = common.script_name(__file__)


def main() -> None:
    def text(n):
        reach = (f"and stays within 5 % of it from {n['reach']:.2f} µs" if n["reach"]
                 is not None else "")
        return (f"The shock in the PMMA ({n['target']:.2f} GPa) reaches the copper, whose "
                f"impedance is more than ten times higher. The copper slows the interface and "
                f"the first shock in the layer carries {n['first']:.2f} GPa, "
                f"{n['first'] / n['target']:.2f} times the PMMA stress (a reshock runs back "
                f"into the front plate: the step in its record). At the layer's far face the "
                f"soft PMMA lets it expand: a release. The record at mid-layer oscillates (the "
                f"waves "
                f"cross it in both directions) with an amplitude that shrinks at every round trip "
                f"(about 0.1 µs) toward the PMMA stress, {reach}. "
                f"X–t zoomed on the layer; region numbers omitted.")

    def save_text(n):
        return (f"Ring-down of 0.2 mm Cu between PMMA plates (PMMA flyer at 1 km/s): the layer "
                f"first takes {n['first']:.2f} GPa, {n['first'] / n['target']:.2f} times the "
                f"PMMA's {n['target']:.2f} GPa, then rings down to it.")

    common.layer_figure(NAME, "layer", "PMMA front plate",
                        "Ring-down: a thin Cu layer between PMMA plates relaxes to the PMMA's "
                        "stress", text, save_text, zoom=(4.0, 6.6))


if __name__ == "__main__":
    main()
