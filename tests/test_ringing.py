"""Ringing layers ended at their limit (``fronttrack.ringing``).

Linear elastic layers between linear elastic anvils ring with a geometric series that
has a closed form: a wave of stress ``s`` in the layer (impedance ``z``) meeting an
anvil (``Z``) sends ``T s`` into it and reflects ``R s``, with ``T = 2 Z / (Z + z)``
and ``R = (Z - z) / (Z + z)`` (``R = -1`` at a free face).  The stress at the right
anvil's face after the ``n``-th arrival is a partial sum of that series, exact to
rounding in the engine (every wave is a jump, every state a crossing of straight
lines); once the rest of the series is below the record tolerance, the layer and the
anvils take its sum at once.
"""

from __future__ import annotations

import dataclasses

import pytest

import fronttrack as ft
from fronttrack.kinds import FrontKind
from materials import solve_contact

V = 100.0
"""Impact velocity (m/s)."""


def elastic(name: str, rho0: float, c: float) -> tuple[object, float]:
    """A linear elastic solid of density ``rho0`` (kg/m^3) and longitudinal speed ``c``
    (m/s), as ``lambda = mu = rho0 c^2 / 3``; with its impedance ``rho0 c``."""
    modulus = rho0 * c * c / 3.0
    material = ft.material(name, model="linear-elastic", rho0=f"{rho0} kg/m3",
                           **{"lambda": f"{modulus} Pa"}, mu=f"{modulus} Pa")
    return material, material.rho0 * material.C


LAYER, Z_LAYER = elastic("layer", 1200.0, 2500.0)
HEAVY, Z_HEAVY = elastic("heavy anvil", 19000.0, 4000.0)
STEELY, Z_STEELY = elastic("steel-like anvil", 7900.0, 5900.0)
THICKNESS, ANVIL = 10e-6, 4e-3
TAU = THICKNESS / LAYER.C
"""The layer's transit time (s)."""


def sandwich(left, right, t_end: str) -> ft.Scene:
    """``left`` anvil (4 mm) at ``V`` onto the 10 um layer at rest on the ``right`` anvil
    (4 mm), free ends: the far ends answer after 2 us."""
    return ft.Scene(layers=(ft.Layer(left, "4 mm", velocity=f"{V} m/s"),
                            ft.Layer(LAYER, "10 um"), ft.Layer(right, "4 mm")),
                    t_end=t_end)


def quiet_after(solution, entry) -> bool:
    """No wave crosses the layer after its ringing was ended."""
    lo, hi = entry["x_lo"], entry["x_hi"]
    for front in solution.fronts:
        if front.kind in (FrontKind.SHOCK, FrontKind.RAY) and front.t1 > entry["t"]:
            if lo < front.position(max(front.t0, entry["t"])) < hi:
                return False
    return True


@pytest.mark.parametrize("right, z_right", [(HEAVY, Z_HEAVY), (STEELY, Z_STEELY)],
                         ids=["symmetric", "asymmetric"])
def test_ring_up_follows_the_partial_sums_then_takes_the_exact_limit(right, z_right):
    """The layer rings up between a heavy anvil at 100 m/s and a heavy (or steel-like)
    one at rest.  The right anvil's face stress after arrival ``n`` is
    ``T_R s1 (1 + r + ... + r^n)`` with ``s1 = V Z_L z / (Z_L + z)`` the impact stress
    and ``r = R_L R_R``: exact to 1e-12 for the first arrivals.  The sum is the two
    anvils' direct contact stress ``V Z_L Z_R / (Z_L + Z_R)``; after the ringing is
    ended every state beside the layer is that limit to rounding, not to a tolerance."""
    solution = ft.run(sandwich(HEAVY, right, "1.2 us"))
    z_left = Z_HEAVY
    s1 = V * z_left * Z_LAYER / (z_left + Z_LAYER)
    reflect = [(z - Z_LAYER) / (z + Z_LAYER) for z in (z_left, z_right)]
    r = reflect[0] * reflect[1]
    transmit = 1.0 + reflect[1]
    station = ANVIL + THICKNESS + 1e-6
    for n in range(4):
        t = (2 * n + 2) * TAU + 1e-6 / right.C
        expected = transmit * s1 * sum(r ** k for k in range(n + 1))
        assert solution.state_at(station, t).sigma == pytest.approx(expected, rel=1e-12)
    (entry,) = solution.accuracy_report["ringing_replaced"]
    limit = V * z_left * z_right / (z_left + z_right)
    assert entry["reflection"] == pytest.approx(r, rel=1e-12)
    assert entry["sigma"] == pytest.approx(limit, rel=1e-12)
    tolerance = solution.accuracy_report["stress_tolerance"]
    assert entry["remaining_stress"] <= tolerance
    # the series' rest at the end, from its closed form: the right anvil's face stress
    # then (read before the ending) is short of the limit by exactly that rest
    before = solution.state_at(station, entry["t"] - 1e-15)
    assert entry["remaining_stress"] >= limit - before.sigma
    t_end = solution.scene.t_end
    for x in (ANVIL - 1e-6, ANVIL + THICKNESS / 2, station):
        state = solution.state_at(x, t_end)
        assert state.sigma == pytest.approx(limit, rel=1e-12)
        assert state.u == pytest.approx(V * z_left / (z_left + z_right), rel=1e-12)
    assert quiet_after(solution, entry)


def test_ending_the_ringing_keeps_energy_and_counts_the_layers_momentum():
    """The layer keeps its total energy (the run's energy balance stays at rounding:
    linear elastic waves are exact); its momentum jumps by ``rho0 d (u* - u)``, which
    the entry reports, read here from the layer before and after; the run's momentum
    residual changes by exactly that across the ending, and by nothing else."""
    solution = ft.run(sandwich(HEAVY, HEAVY, "1.2 us"))
    (entry,) = solution.accuracy_report["ringing_replaced"]
    t, middle = entry["t"], ANVIL + THICKNESS / 2
    before, after = solution.state_at(middle, t - 1e-15), solution.state_at(middle, t + 1e-15)
    assert entry["momentum"] == pytest.approx(LAYER.rho0 * THICKNESS * (after.u - before.u),
                                              rel=1e-9)
    c = solution.conservation()
    assert abs(c["energy_error"]) <= 1e-12 * c["energy_scale"]
    jump = (solution.conservation(t + 1e-15)["momentum_error"]
            - solution.conservation(t - 1e-15)["momentum_error"])
    assert jump == pytest.approx(entry["momentum"], rel=1e-6)
    # the energy the layer keeps is within the rest of the series' work on it
    rest = entry["remaining_stress"] * THICKNESS * after.sigma / (LAYER.rho0 * LAYER.C ** 2)
    assert abs(entry["energy_offset"]) * LAYER.rho0 * THICKNESS <= 2.0 * rest


@pytest.mark.parametrize("face", ["free face", "gap"])
def test_a_layer_on_a_free_face_rings_down_to_rest(face):
    """A 10 um layer at 100 m/s strikes a heavy anvil (8 mm) at rest; its other face is
    free (the end of the stack, or a gap opening at once from a 1 mm plate behind it,
    unbonded, moving away at 200 m/s: faster than the layer's rebounds), ``R = -1``:
    echoes alternate in sign, ``r = -R``.  The anvil's face stress after arrival ``n``
    is ``s1 (1 - T (1 - R + R^2 - ...))`` (``n`` terms); its sum is zero, and the layer
    ends at rest with zero stress (the anvil's answer to a free face)."""
    behind = (ft.Layer(HEAVY, "1 mm", velocity="-200 m/s"),) if face == "gap" else ()
    x_layer = 1e-3 if behind else 0.0
    scene = ft.Scene(layers=(*behind, ft.Layer(LAYER, "10 um", velocity=f"{V} m/s",
                                               bond="unbonded"),
                             ft.Layer(HEAVY, "8 mm")), t_end="1.8 us")
    solution = ft.run(scene)
    s1 = V * Z_HEAVY * Z_LAYER / (Z_HEAVY + Z_LAYER)
    big_r = (Z_HEAVY - Z_LAYER) / (Z_HEAVY + Z_LAYER)
    station = x_layer + THICKNESS + 1e-6
    for n in range(4):
        t = (2 * n + 1) * TAU + 1e-6 / HEAVY.C
        expected = s1 * (1.0 - (1.0 + big_r) * sum((-big_r) ** k for k in range(n)))
        assert solution.state_at(station, t).sigma == pytest.approx(expected, rel=1e-12,
                                                                    abs=1e-12 * s1)
    (entry,) = solution.accuracy_report["ringing_replaced"]
    assert entry["reflection"] == pytest.approx(-big_r, rel=1e-12)
    assert entry["sigma"] == 0.0
    assert entry["u"] == pytest.approx(0.0, abs=1e-12 * V)
    layer = solution.state_at(x_layer + THICKNESS / 2, solution.scene.t_end)
    assert (layer.sigma, layer.u) == (0.0, entry["u"])
    assert entry["energy_offset"] >= 0.0  # the rest of the ringing is kept as heat
    # the ending moves no energy; the run's balance is the rounding of its events
    c = solution.conservation()
    jump = (solution.conservation(entry["t"] + 1e-15)["energy_error"]
            - solution.conservation(entry["t"] - 1e-15)["energy_error"])
    assert abs(jump) <= 1e-13 * c["energy_scale"]
    assert abs(c["energy_error"]) <= 1e-10 * c["energy_scale"]
    assert quiet_after(solution, entry)


def test_the_tungsten_ring_up_ends_at_the_anvils_contact_state():
    """10 um of PMMA between tungsten anvils (Mie-Grueneisen: nonlinear, so no closed
    form for the series): the layer is ended at the Riemann solution of the two anvils'
    states, which is within the stress tolerance of the direct tungsten-tungsten contact
    (the series of weak shocks in tungsten ends near, not on, its single-shock state)."""
    tungsten = ft.material("W")
    rest = tungsten.reference_state()
    limit = solve_contact(tungsten, dataclasses.replace(rest, u=V), tungsten, rest,
                          release="isentrope").left_star
    scene = ft.Scene(layers=(ft.Layer("W", "4 mm", velocity=f"{V} m/s"),
                             ft.Layer("PMMA", "10 um"), ft.Layer("W", "4 mm")),
                     t_end="0.5 us")
    solution = ft.run(scene)
    (entry,) = solution.accuracy_report["ringing_replaced"]
    layer = solution.state_at(4.005e-3, solution.scene.t_end)
    assert (layer.sigma, layer.u) == (entry["sigma"], entry["u"])
    assert abs(entry["sigma"] - limit.sigma) <= solution.accuracy_report["stress_tolerance"]
    assert quiet_after(solution, entry)


@pytest.mark.parametrize("setting", [{"coalesce_length": "0 m"}, {"negligible_stress": "0 Pa"}])
def test_a_scene_that_keeps_every_front_or_wave_keeps_every_echo(setting):
    """``coalesce_length = 0 m`` keeps every front, ``negligible_stress = 0`` every wave:
    the layer rings on (the default run ends it at 0.49 us)."""
    scene = dataclasses.replace(sandwich(HEAVY, HEAVY, "0.6 us"),
                                accuracy=ft.Accuracy(**setting))
    assert ft.run(scene).accuracy_report["ringing_replaced"] == []
    assert len(ft.run(sandwich(HEAVY, HEAVY, "0.6 us")).accuracy_report["ringing_replaced"]) == 1
