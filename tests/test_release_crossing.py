"""Rays crossing on one plastic release path: the closed form of ``materials.release_crossing``.

The solid is "A" of the class-B reproducer of ``benchmarks/RUN_LENGTH.md`` (d, classes):
a finite-plastic solid shocked to 12 GPa and released past reverse yield, where two
release rays from one state ``M`` meet (``L`` behind the right-going ray, ``R`` behind
the left-going one).  The closed form must give the Riemann solver's solution: both
intersect the same two fans, the one on the path's table (1e-13 of the closed forms,
``tests/test_path_table.py``), the other on the tables of two wave curves and a root
search whose velocity noise is a few ulps of the velocities and of ``sigma / Z``.
"""

from __future__ import annotations

import numpy as np
import pytest

import fronttrack as ft
import materials.release_crossing as release_crossing
from materials import LEFT, RIGHT, FinitePlastic, FinitePlasticWaveCurve, State, solve_contact
from materials.release_crossing import ReleaseFanCurve, ReleasePath, ReleasePaths

A = FinitePlastic("A", 5808.0, 4000.0, 1.4, 1.6, 60e9, 1.88e9)
B = FinitePlastic("B", 18123.0, 3000.0, 1.3, 2.0, 80e9, 1.22e9)


def _released(peak: float, sigma: float) -> State:
    """A state of A shocked from rest to ``peak`` and released to ``sigma`` (Pa)."""
    shocked = FinitePlasticWaveCurve(A, A.reference_state(), RIGHT).state_at(peak)
    return FinitePlasticWaveCurve(A, shocked, LEFT).state_at(sigma)


def _pair(middle: State, left_ray: float, right_ray: float) -> tuple[State, State]:
    """The states behind a right-going and a left-going release ray from ``middle``."""
    left = FinitePlasticWaveCurve(A, middle, RIGHT).state_at(middle.sigma - left_ray)
    right = FinitePlasticWaveCurve(A, middle, LEFT).state_at(middle.sigma - right_ray)
    return left, right


@pytest.mark.parametrize("middle_stress, left_ray, right_ray", [
    (3e9, 30e6, 30e6),       # two rays of one step (the default step here is ~30 MPa)
    (3e9, 1e6, 300e6),       # a weak ray against a strong one
    (0.5e9, 305e6, 305e6),   # the reproducer's rays, ending in tension
    (-1e9, 10e6, 20e6),      # in tension throughout
])
def test_a_crossing_on_one_path_is_the_riemann_solution(middle_stress, left_ray, right_ray):
    middle = _released(12e9, middle_stress)
    assert A.on_reverse_yield(middle)
    left, right = _pair(middle, left_ray, right_ray)
    fast = ReleasePaths().crossing(A, left, right)
    exact = solve_contact(A, left, A, right)
    assert fast is not None
    star, reference = fast.left_star, exact.left_star
    # stress to 1e-12 of the stress scale (12 GPa: 0.012 Pa), velocity to 1e-11 m/s (the
    # Riemann root's noise, 4 ulps of |u_L| + |u_R| + sigma / Z: 1.6e-12 m/s here)
    assert star.sigma == pytest.approx(reference.sigma, abs=1e-12 * 12e9)
    assert star.u == pytest.approx(reference.u, abs=1e-11)
    assert star.v == pytest.approx(reference.v, rel=1e-13)
    assert star.e == pytest.approx(reference.e, rel=1e-12)
    assert star.plastic_strain == pytest.approx(reference.plastic_strain, rel=1e-12)
    assert fast.right_star is star and exact.right_star.v == pytest.approx(star.v, rel=1e-13)
    for ours, theirs in ((fast.left_waves, exact.left_waves),
                         (fast.right_waves, exact.right_waves)):
        (fan,), (wave,) = ours, theirs   # one plastic fan each way
        assert fan.direction == wave.direction
        assert fan.head_speed == pytest.approx(wave.head_speed, rel=1e-12)
        assert fan.tail_speed == pytest.approx(wave.tail_speed, rel=1e-12)
        inside = 0.5 * (fan.ahead.sigma + fan.behind.sigma)   # the state of a one-ray fan
        ray, its = fan.curve.state_at(inside), wave.curve.state_at(inside)
        assert ray.v == pytest.approx(its.v, rel=1e-13)
        assert ray.u == pytest.approx(its.u, abs=1e-11)
        assert fan.curve.characteristic_speed(inside) == pytest.approx(
            wave.curve.characteristic_speed(inside), rel=1e-12)


def test_crossings_off_one_release_path_go_to_the_riemann_solver():
    middle = _released(12e9, 3e9)
    left, right = _pair(middle, 30e6, 30e6)
    paths = ReleasePaths()
    # another path: shocked to 13 GPa, released to the same stress (entropy 0.2 GPa apart)
    other = _released(13e9, right.sigma)
    assert A.on_reverse_yield(other) and abs(other.v - right.v) > 1e-4 * right.v
    assert paths.crossing(A, left, State(other.sigma, right.u, other.v, other.e,
                                         other.plastic_strain)) is None
    # closing at 100 m/s: the star state reloads the left side elastically
    closing = State(left.sigma, right.u + 100.0, left.v, left.e, left.plastic_strain)
    assert solve_contact(A, closing, A, right).left_star.v < closing.v
    assert paths.crossing(A, closing, right) is None
    # a star stress below the tensile floor: the Riemann solver separates the contact
    apart = State(left.sigma, right.u - 2000.0, left.v, left.e, left.plastic_strain)
    assert solve_contact(A, apart, A, right, tensile_strength=1e9).separated
    assert paths.crossing(A, apart, right, tensile_strength=1e9) is None
    # released elastically only (not to reverse yield)
    elastic = _released(12e9, 11e9)
    assert not A.on_reverse_yield(elastic)
    assert paths.crossing(A, *_pair(elastic, 30e6, 30e6)) is None


def test_a_fan_within_rounding_of_its_ahead_state_starts_there():
    """Seed 24 of ``benchmarks/pile_up.py`` stopped on NoSolutionError: a fan from
    1.31339e10 Pa whose inner stress lay within rounding of it, above the path's stress
    at the ahead volume (a state lies on a path to ``PATH_MATCH``, 0.14 Pa here)."""
    middle = _released(12e9, 3e9)
    path = ReleasePath(A, middle)
    ahead = State(middle.sigma + 0.01, middle.u, middle.v, middle.e, middle.plastic_strain)
    assert path.holds(ahead)
    for direction in (LEFT, RIGHT):
        state = ReleaseFanCurve(path, ahead, direction).state_at(ahead.sigma - 0.005)
        assert state.v == ahead.v and state.u == ahead.u
        assert state.sigma == ahead.sigma - 0.005


def test_a_ringing_flyer_records_the_riemann_solver_s_solution(monkeypatch):
    """0.1 mm of A at 755 m/s onto 0.3 mm of B (the class-B reproducer, thinner), six
    rays a fan: its release fans cross on the plastic path (1 159 crossings of 5 278
    events).  Solved by the Riemann solver instead, the run is the same to rounding."""
    scene = ft.Scene(layers=(ft.Layer(A, "0.1 mm", velocity="755 m/s"),
                             ft.Layer(B, "0.3 mm", bond="bonded")),
                     t_end="0.04 us", accuracy=ft.Accuracy(rays_per_fan=6))
    taken = []
    crossing = ReleasePaths.crossing

    def counted(self, *args, **kwargs):
        solution = crossing(self, *args, **kwargs)
        taken.append(solution is not None)
        return solution

    monkeypatch.setattr(ReleasePaths, "crossing", counted)
    fast = ft.run(scene)
    monkeypatch.setattr(release_crossing.ReleasePaths, "crossing", lambda *a, **k: None)
    exact = ft.run(scene)
    assert sum(taken) > 1000
    assert fast.stats["events"] == exact.stats["events"]
    times = np.linspace(0.0, 0.04e-6, 81)
    tolerance = fast.accuracy_report["velocity_tolerance"]
    for side in ("left", "right"):
        ours, theirs = (s.history(side).at(times, "u") for s in (fast, exact))
        assert np.max(np.abs(ours - theirs)) <= 1e-6 * tolerance
    ours, theirs = (s.accuracy_report["balance"] for s in (fast, exact))
    for key in ("momentum_error", "energy_error"):
        assert ours[key] == pytest.approx(theirs[key], abs=1e-9)
