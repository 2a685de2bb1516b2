"""A shock meets a lower-impedance material: Al 2024 into PMMA.

The scene of 02_into_copper with a PMMA sample.  At the Al|PMMA interface a
weaker shock goes into the PMMA and a release fan comes back into the
aluminium: the interface state is where the Al release isentrope crosses the
PMMA Hugoniot.  The release later meets the flyer's own release and the flyer
spalls.
"""

from __future__ import annotations

import common

NAME = common.script_name(__file__)


def main() -> None:
    solution = common.solve(NAME)
    at = solution.state_at
    al = at(5.5e-3, 0.20e-6)          # behind the first shock in the Al base plate
    pmma = at(7.0e-3, 0.45e-6)        # behind the transmitted shock in PMMA
    first = common.numbers_at(solution, (4.5e-3, 0.2e-6), (5.5e-3, 0.2e-6))
    figure, ax_xt, ax_su = common.xt_su_figure(
        solution, "Shock from Al 2024 into PMMA (lower impedance): transmitted shock "
        "weaker, reflected wave a release")
    g = common.GPA
    common.note(ax_su, f"Al, first shock ({first}):\n  {al.sigma * g:.2f} GPa, {al.u:.0f} m/s\n"
                f"PMMA = released Al:\n  {pmma.sigma * g:.2f} GPa, "
                f"{pmma.u:.0f} m/s", xy=(0.02, 0.97))
    spall = solution.spalls[0] if solution.spalls else None
    spall_text = (f" The release reflected from the interface meets the release from the "
                  f"flyer's back face inside the flyer, which spalls at X = "
                  f"{spall.x * common.MM:.2f} mm, t = {spall.t * common.US:.2f} µs "
                  f"(1.2 GPa, spall_spacing 0.5 mm)." if spall else "")
    text = (f"The shock in the aluminium ({al.sigma * g:.2f} GPa, u = {al.u:.0f} m/s) "
            f"reaches the PMMA at 0.25 µs. PMMA has a fifth of the impedance of Al (ρ0C0 = 3.1 "
            f"against 15 MPa·s/m): the interface state is where the Al release isentrope "
            f"(dashed, from state {first}; it lies almost on the flyer's Hugoniot, the mirror "
            f"image of the Al Hugoniot) meets the PMMA Hugoniot: {pmma.sigma * g:.2f} GPa, at a "
            f"higher velocity, {pmma.u:.0f} m/s. The reflected wave is a release fan.{spall_text}")
    common.caption(figure, text)
    common.save(figure, NAME, f"Al 2024 at 1 km/s into PMMA: the Al shock "
                f"({al.sigma * g:.2f} GPa, {al.u:.0f} m/s) transmits a weaker shock "
                f"({pmma.sigma * g:.2f} GPa, {pmma.u:.0f} m/s) and reflects a release fan.")


if __name__ == "__main__":
    main()
