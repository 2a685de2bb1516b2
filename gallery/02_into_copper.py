"""A shock meets a higher-impedance material: Al 2024 into Cu.

An Al 2024 flyer (5 mm) at 1 km/s strikes an Al 2024 base plate (1.5 mm) bonded
to a Cu sample (2 mm).  At the Al|Cu interface a stronger shock goes into the
copper and a reshock comes back into the aluminium; both sides end in the same
state, the crossing of the Al reshock Hugoniot with the Cu principal Hugoniot.
"""

from __future__ import annotations

import common

NAME = common.script_name(__file__)


def main() -> None:
    solution = common.solve(NAME)
    at = solution.state_at
    al = at(5.5e-3, 0.20e-6)          # behind the first shock in the Al base plate
    cu = at(7.0e-3, 0.45e-6)          # behind the transmitted shock in Cu
    reshocked = at(5.9e-3, 0.55e-6)   # Al behind the reflected reshock
    first = common.numbers_at(solution, (4.5e-3, 0.2e-6), (5.5e-3, 0.2e-6))
    second = common.numbers_at(solution, (7.0e-3, 0.45e-6), (5.9e-3, 0.55e-6),
                               (3.9e-3, 0.85e-6))
    free = common.numbers_at(solution, (8.45e-3, 0.95e-6))   # behind the Cu free face's release
    back = common.numbers_at(solution, (0.05e-3, 0.95e-6))   # behind the flyer back's release
    figure, ax_xt, ax_su = common.xt_su_figure(
        solution, "Shock from Al 2024 into Cu (higher impedance): transmitted shock "
        "stronger, reflected wave a reshock")
    g = common.GPA
    common.note(ax_su, f"Al, first shock ({first}):\n  {al.sigma * g:.2f} GPa, {al.u:.0f} m/s\n"
                f"Cu = reshocked Al ({second}):\n  {cu.sigma * g:.2f} GPa, {cu.u:.0f} m/s\n"
                f"reshock: {(reshocked.sigma - al.sigma) * g:+.2f} GPa,\n"
                f"  {reshocked.u - al.u:+.0f} m/s".replace("-", "\u2212"),
                xy=(0.015, 0.84))
    text = (f"The shock in the aluminium ({al.sigma * g:.2f} GPa, u = {al.u:.0f} m/s) "
            f"reaches the copper at 0.25 µs. Cu has 2.4 times the impedance of Al "
            f"(ρ0C0 = 35 against 15 MPa·s/m), so the interface state is where the Al reshock "
            f"Hugoniot (a left-going wave from state {first}: it rises to the left) meets the Cu "
            f"Hugoniot from rest: {cu.sigma * g:.2f} GPa at {cu.u:.0f} m/s. A stronger shock "
            f"runs into the Cu and a reshock back into the Al. The Cu free surface (state "
            f"{free}) and the flyer's back face (state {back}) reflect release fans.")
    common.caption(figure, text)
    common.save(figure, NAME, f"Al 2024 at 1 km/s into Cu: the Al shock "
                f"({al.sigma * g:.2f} GPa) transmits a stronger shock "
                f"({cu.sigma * g:.2f} GPa, {cu.u:.0f} m/s) and reflects a reshock.")


if __name__ == "__main__":
    main()
