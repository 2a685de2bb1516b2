"""Viscoplastic scenes through ``ft.run`` and ``wavediagram run``
(``fronttrack.viscoplastic_scene``).

References: the elastic (tau = inf) impact in closed form (acoustic impedance match,
a free-surface velocity twice the particle velocity, an unbonded contact opening when
the flyer's release would pull it); the decayed precursor from the book's decay law
``d sigma_p / dX = -(mu / C0) phi(S_p)`` integrated by scipy (DOP853) from the flyer's
elastic impedance-match stress.  Davison's steel (PHYSICS.md).
"""

from __future__ import annotations

import csv
import json
import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import fronttrack as ft
from characteristics.viscoplastic_grid import run_layer
from fronttrack.cli import main
from materials import LinearElastic
from materials.viscoplastic import Viscoplastic

RHO, LAM, MU, Y = 7870.0, 123.1e9, 79.29e9, 1.0e9
M = LAM + 2.0 * MU
C0 = math.sqrt(M / RHO)
Z = RHO * C0

SCENE = """
title = "Elastic flyer on viscoplastic steel"
t_end = "0.9 us"

[materials.vpsteel]
model = "viscoplastic"
rho0 = "7870 kg/m3"
lambda = "123.1 GPa"
mu = "79.29 GPa"
yield_strength = "1 GPa"
relaxation_time = "50 ns"

[materials.flyer]
model = "linear-elastic"
rho0 = "2700 kg/m3"
C = "6400 m/s"

[[layer]]
material = "flyer"
thickness = "1 mm"
velocity = "600 m/s"

[[layer]]
material = "vpsteel"
thickness = "4 mm"
bond = "unbonded"
{window}
[[probe]]
name = "rear"
at = "{rear}"
"""

WINDOW = """
[materials.window]
model = "linear-elastic"
rho0 = "1186 kg/m3"
C = "2750 m/s"

[[layer]]
material = "window"
thickness = "10 mm"

[[probe]]
name = "in_window"
at = "7 mm"
"""


def precursor_at(distance: float, start: float, tau: float) -> float:
    """The precursor's stress after ``distance`` (m) from ``start`` (Pa), by scipy."""
    s_y = 2.0 * Y / 3.0

    def rhs(_, s):
        over = max(4.0 * MU * s[0] / (3.0 * M) / s_y - 1.0, 0.0)
        return [-(MU / C0) * s_y / (2.0 * MU * tau) * over]

    return solve_ivp(rhs, (0.0, distance), [start], method="DOP853", rtol=1e-12,
                     atol=1e-3).y[0, -1]


def first_step(record) -> float:
    """The velocity of the first nonzero sample of a record."""
    return float(record.u[np.nonzero(record.u)[0][0]])


def test_elastic_flyer_on_elastic_target_is_exact():
    """tau = inf: a 2 mm flyer of half the steel's impedance at 500 m/s, unbonded.  The
    free surface moves at 2 u_c (u_c = Z_f V / (Z_f + Z)) from L / C0 for the flyer's
    round trip (as the grid represents it), then stops: the flyer's release would pull
    the contact (Z_f < Z), which opens."""
    flyer = LinearElastic("half", RHO / 2.0, C0)
    target = Viscoplastic("elastic steel", RHO, LAM, MU, Y, math.inf)
    scene = ft.Scene([ft.Layer(flyer, "2 mm", velocity="500 m/s"),
                      ft.Layer(target, "4 mm", bond="unbonded")], t_end="1.5 us",
                     probes=[ft.Probe("fs", "right")])
    solution = ft.run(scene)
    record = solution.history("fs")
    trip = solution.accuracy_report["flyer_round_trip"]
    assert trip["flyer"] == pytest.approx(2 * 2e-3 / C0, rel=1e-15)
    assert abs(trip["grid"] - trip["flyer"]) <= solution.run.dt
    u_c = (Z / 2.0) * 500.0 / (Z / 2.0 + Z)
    arrive = 4e-3 / C0
    during = (record.t > arrive + 1e-12) & (record.t < arrive + trip["grid"] - 1e-12)
    after = record.t > arrive + trip["grid"] + 1e-12
    assert during.sum() > 20 and after.sum() > 20
    assert record.u[during] == pytest.approx(2.0 * u_c, rel=1e-12)
    assert np.all(np.abs(record.u[after]) <= 1e-9 * u_c)
    assert np.all(record.u[record.t < arrive - 1e-12] == 0.0)
    assert np.all(record.sigma == 0.0)     # a free face


def test_scene_file_flyer_on_viscoplastic_target_shows_the_decayed_precursor(tmp_path):
    path = tmp_path / "vp.toml"
    path.write_text(SCENE.format(window="", rear="right"))
    solution = ft.run(ft.load_scene(path))
    record = solution.history("rear")
    z_f = 2700.0 * 6400.0
    u_c = z_f * 600.0 / (z_f + Z)
    sigma_p = precursor_at(4e-3, Z * u_c, 50e-9)
    # the free face first jumps to twice the decayed precursor's particle velocity
    # (grid: dX = C0 tau / 4 here, second order; measured error 6e-6)
    assert first_step(record) == pytest.approx(2.0 * sigma_p / Z, rel=2e-4)
    assert first_step(record) < 0.5 * (2.0 * u_c)          # well below the elastic step
    run = solution.run
    assert run.precursor_sigma[-1] == pytest.approx(
        precursor_at(run.precursor_x[-1], Z * u_c, 50e-9), rel=2e-4)
    assert np.all(np.isfinite(record.u)) and np.all(np.isfinite(record.rho))


def test_command_line_writes_records_json_and_figures(tmp_path):
    path = tmp_path / "vp.toml"
    path.write_text(SCENE.format(window=WINDOW, rear="5 mm"))
    out = tmp_path / "out"
    assert main(["run", str(path), "-o", str(out), "--quiet"]) == 0
    for name in ("xt.png", "records.png", "solution.json", "probe_rear.csv",
                 "probe_in_window.csv"):
        assert (out / name).is_file(), name
    data = json.loads((out / "solution.json").read_text())
    assert data["solver"].startswith("characteristic grid")
    with (out / "probe_rear.csv").open() as handle:
        rows = list(csv.DictReader(handle))
    rear_u = np.array([float(r["u_m_per_s"]) for r in rows])
    rear_t = np.array([float(r["t_s"]) for r in rows])
    # on the window: the precursor transmits u = 2 sigma_p / (Z + Z_w)
    z_f, z_w = 2700.0 * 6400.0, 1186.0 * 2750.0
    sigma_p = precursor_at(4e-3, Z * z_f * 600.0 / (z_f + Z), 50e-9)
    assert rear_u[np.nonzero(rear_u)[0][0]] == pytest.approx(2.0 * sigma_p / (Z + z_w),
                                                             rel=2e-4)
    # 2 mm into the window: the interface record delayed by 2 mm / C_w
    with (out / "probe_in_window.csv").open() as handle:
        rows = list(csv.DictReader(handle))
    window_t = np.array([float(r["t_s"]) for r in rows])
    window_u = np.array([float(r["u_m_per_s"]) for r in rows])
    assert window_t == pytest.approx(rear_t + 2e-3 / 2750.0, rel=1e-12)
    assert window_u == pytest.approx(rear_u, rel=1e-15)


def test_command_line_refuses_options_the_grid_does_not_serve(tmp_path, capsys):
    path = tmp_path / "vp.toml"
    path.write_text(SCENE.format(window="", rear="right"))
    assert main(["run", str(path), "-o", str(tmp_path / "out"), "--peaks"]) == 2
    error = capsys.readouterr().err
    assert "--peaks" in error and error.count("\n") == 1


def test_piston_scene_is_the_grid_run():
    mat = Viscoplastic("steel", RHO, LAM, MU, Y, 50e-9)
    scene = ft.Scene([ft.Layer(mat, "4 mm")], t_end="0.6 us",
                     left=ft.Boundary("velocity", "300 m/s"),
                     probes=[ft.Probe("mid", "2 mm")])
    solution = ft.run(scene)
    direct = run_layer(mat, 4e-3, 300.0, 0.6e-6, solution.stats["cells"])
    t, u = direct.history(2e-3, "u")
    record = solution.history("mid")
    assert np.array_equal(record.t, t) and np.array_equal(record.u, u)
    assert record.u_end[-1] == record.u[-1] and np.array_equal(record.u_end[:-1], u[1:])


@pytest.mark.parametrize("change, field", [
    ({"left": ft.Boundary("wall")}, "left.kind"),
    ({"right": ft.Boundary("wall")}, "right.kind"),
    ({"probes": [ft.Probe("in_flyer", "0.5 mm")]}, r"probe\[in_flyer\].at"),
    ({"layers": "two"}, r"layer\[1\].material"),
    ({"layers": "steel flyer"}, r"layer\[0\].material"),
    ({"layers": "thin window"}, r"layer\[2\].thickness"),
    ({"spall_criterion": ft.SpallCriterion.incubation("1 GPa", "0.1 us")}, "spall"),
])
def test_unsupported_scenes_name_the_field(change, field):
    mat = Viscoplastic("steel", RHO, LAM, MU, Y, 50e-9)
    flyer = ft.Layer(LinearElastic("al", 2700.0, 6400.0), "1 mm", velocity="500 m/s")
    target = ft.Layer(mat, "4 mm")
    layers = {"two": [ft.Layer(mat, "1 mm", velocity="500 m/s"), target],
              "steel flyer": [ft.Layer("Cu", "1 mm", velocity="500 m/s"), target],
              "thin window": [flyer, target,
                              ft.Layer(LinearElastic("w", 1186.0, 2750.0), "0.1 mm")],
              }.get(change.pop("layers", None), [flyer, target])
    scene = ft.Scene(layers, t_end="0.9 us", **change)
    with pytest.raises(ft.SceneError, match=field) as raised:
        ft.run(scene)
    assert "\n" not in str(raised.value)
