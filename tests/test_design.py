"""Design functions against closed forms: the inverse of the impedance match, the
one-dimensional window of a shock-only scene, spall-plane placement fed back into runs."""

from __future__ import annotations

import pytest

import fronttrack as ft
from fronttrack.design import with_thickness
from materials import LinearElastic

FLYER = LinearElastic("flyer", rho0=8930.0, C=4700.0)
TARGET = LinearElastic("target", rho0=2700.0, C=6400.0)


@pytest.mark.parametrize("flyer, stack", [("Cu", ["Al2024"]), ("W", ["Cu", "PMMA"]),
                                          ("PMMA", ["Ta", "LiF"])])
@pytest.mark.parametrize("velocity", [137.0, 1234.5, 3000.0])
def test_velocity_for_inverts_match(flyer, stack, velocity):
    rows = ft.match(flyer, velocity, stack)
    for layer in range(len(stack)):
        for quantity in ("sigma", "u"):
            target = getattr(rows[layer + 1], quantity)
            found = ft.velocity_for(target, flyer, stack, layer=layer, quantity=quantity)
            assert found == pytest.approx(velocity, rel=1e-12)
            again = getattr(ft.match(flyer, found, stack)[layer + 1], quantity)
            assert again == pytest.approx(target, rel=1e-12)


def test_velocity_for_refuses_what_it_cannot_reach():
    with pytest.raises(ft.SceneError, match="target: must be > 0"):
        ft.velocity_for("-1 GPa", "Cu", ["Cu"])
    with pytest.raises(ft.SceneError, match="quantity: must be one of"):
        ft.velocity_for("1 GPa", "Cu", ["Cu"], quantity="rho")
    with pytest.raises(ft.SceneError, match="velocity: the flyer must move toward"):
        ft.match("Cu", "-500 m/s", ["Al2024"])
    with pytest.raises(ft.SceneError, match=r"stack\[1\]: .*Unobtainium"):
        ft.match("Cu", "500 m/s", ["Al2024", "Unobtainium"])


def impact(flyer_thickness: float, target_thickness: float, depth: float) -> ft.Scene:
    return ft.Scene([ft.Layer(FLYER, flyer_thickness, velocity=300.0),
                     ft.Layer(TARGET, target_thickness)], t_end=3e-6,
                    probes=[ft.Probe("gauge", flyer_thickness + depth)])


@pytest.mark.parametrize("flyer_thickness, target_thickness, depth", [
    (1e-3, 4e-3, 1.5e-3),     # the release from the flyer's back closes the window
    (2e-3, 3e-3, 1.5e-3),     # the reflection from the target's rear closes it
])
def test_window_of_a_shock_only_impact_is_the_closed_form(flyer_thickness, target_thickness,
                                                          depth):
    """Linear elastic plates: the shock reaches the gauge at depth/C_t; the flyer's release
    arrives 2 d_f/C_f later, the rear's reflection 2 (d_t - depth)/C_t later."""
    window = ft.one_dimensional_window(
        ft.run(impact(flyer_thickness, target_thickness, depth)), "gauge")
    assert window.first_shock == pytest.approx(depth / TARGET.C, rel=1e-12)
    closed = min(2 * flyer_thickness / FLYER.C, 2 * (target_thickness - depth) / TARGET.C)
    assert window.duration == pytest.approx(closed, rel=1e-12)
    assert not window.censored


WINDOW_LAYER = LinearElastic("window", rho0=2640.0, C=6600.0)


def test_window_stays_open_through_the_first_shocks_own_reflections():
    """Flyer 2 mm, sample 1 mm, window 4 mm (linear elastic), gauge 0.5 mm into the sample.
    The first shock's reflection from the sample-window interface reaches the gauge
    2 (1 - 0.5) mm / C_t after it, and its echoes from the impact face follow: they
    descend from the first shock and leave the window open.  The flyer's release (its
    shock reflected from its free back) arrives 2 d_f / C_f after the first shock, long
    before the window's free rear echoes back (2 x 4 mm / 6600 m/s after entry)."""
    depth, flyer = 0.5e-3, 2e-3
    scene = ft.Scene([ft.Layer(FLYER, flyer, velocity=300.0), ft.Layer(TARGET, 1e-3),
                      ft.Layer(WINDOW_LAYER, 4e-3)], t_end=3e-6,
                     probes=[ft.Probe("gauge", flyer + depth)])
    solution = ft.run(scene)
    times, lineages = solution.arrivals("gauge")
    reflection = depth / TARGET.C + 2 * (1e-3 - depth) / TARGET.C
    assert times[1] == pytest.approx(reflection, rel=1e-12) and lineages[1] == lineages[0]
    window = ft.one_dimensional_window(solution, "gauge")
    assert window.first_shock == pytest.approx(depth / TARGET.C, rel=1e-12)
    assert window.duration == pytest.approx(2 * flyer / FLYER.C, rel=1e-12)
    assert window.duration > 2 * (1e-3 - depth) / TARGET.C  # the old, any-wave answer
    assert not window.censored


def test_thickness_for_window_is_exact_for_shocks():
    scene = impact(1e-3, 4e-3, 1.5e-3)
    thickness = ft.thickness_for_window(scene, "gauge", "0.6 us", layer=0)
    assert thickness == pytest.approx(0.6e-6 * FLYER.C / 2, rel=1e-12)
    with pytest.raises(ft.SceneError, match="another wave closes it"):
        ft.thickness_for_window(scene, "gauge", "0.9 us", layer=0)


def test_flyer_for_spall_shock_only_is_exact_and_fed_back():
    """Equal elastic plates: the releases meet d_f from the target's rear, so a depth D
    from the impact face needs d_f = d_t - D; the run at that thickness spalls there."""
    plate = LinearElastic("plate", rho0=2700.0, C=6400.0, spall_strength=0.5e9)
    scene = ft.Scene([ft.Layer(plate, "1 mm", velocity="300 m/s"), ft.Layer(plate, "4 mm")],
                     t_end="3 us")
    thickness = ft.flyer_for_spall(scene, "2.5 mm")
    assert thickness == pytest.approx(1.5e-3, rel=1e-12)
    first = min(ft.run(with_thickness(scene, 0, thickness)).spalls, key=lambda s: s.t)
    assert first.x - thickness == pytest.approx(2.5e-3, rel=1e-12)


def test_flyer_for_spall_with_release_fans_fed_back():
    """Al 2024 on Al 2024 at 300 m/s with isentropic release fans: the first fracture of
    the run at the thickness found lies at the depth asked for, within the tolerance."""
    scene = ft.Scene([ft.Layer("Al2024", "1 mm", velocity="300 m/s"),
                      ft.Layer("Al2024", "2 mm")], t_end="0.6 us",
                     accuracy=ft.Accuracy(rays_per_fan=4))
    thickness = ft.flyer_for_spall(scene, "1.2 mm", tolerance=1e-6)
    spalls = ft.run(with_thickness(scene, 0, thickness)).spalls
    first = min(spalls, key=lambda s: s.t)
    assert first.x - thickness == pytest.approx(1.2e-3, abs=2e-9)
    assert first.tension >= first.strength
    assert 0.7e-3 < thickness < 0.9e-3  # the acoustic estimate is 0.8 mm


def test_window_choice_states_and_apparent_velocity():
    (choice,) = ft.window_choice("Cu", "500 m/s", "Al2024", windows=["LiF"])
    rows = ft.match("Cu", "500 m/s", ["Al2024", "LiF"])
    assert (choice.sigma, choice.u, choice.sample_sigma) == (rows[2].sigma, rows[2].u,
                                                             rows[1].sigma)
    assert choice.reflected == "release"  # LiF is softer than Al 2024
    assert choice.apparent_u == pytest.approx(1.2669 * choice.u, rel=1e-15)
