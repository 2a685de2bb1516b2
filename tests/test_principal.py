"""The closed-form principal Hugoniot (``materials.principal``) against the generic wave
curve, which finds the same states by a root in volume, and against the jump conditions."""

from __future__ import annotations

import math

import pytest

from materials import LEFT, RIGHT, MieGruneisen, StateOutOfRangeError, get
from materials.principal import PrincipalHugoniotCurve
from materials.wavecurves import HydrodynamicWaveCurve

STRESSES = [1e8, 1e9, 1e10, 5e10, 2e11]


@pytest.mark.parametrize("name", ["Cu", "Al2024", "PMMA"])
@pytest.mark.parametrize("direction", [LEFT, RIGHT])
def test_closed_form_matches_the_volume_root(name, direction):
    """Same g, slope, volume, energy and shock speed as the generic curve: the generic
    one is good to its root tolerance and the rounding of ``v0 - v`` (``ulp(v0) / (v0 - v)``,
    below 1e-13 here), so 1e-12 relative."""
    mat = get(name)
    a = mat.reference_state(u=250.0)
    closed = mat.wave_curve(a, direction)
    generic = HydrodynamicWaveCurve(mat, a, direction)
    assert isinstance(closed, PrincipalHugoniotCurve)
    for sigma in STRESSES:
        g, dg = closed.velocity_change(sigma)
        g_ref, dg_ref = generic.velocity_change(sigma)
        assert g == pytest.approx(g_ref, rel=1e-12)
        # the generic slope divides by the Hugoniot's tangent: a few more ulps lost
        assert dg == pytest.approx(dg_ref, rel=1e-10)
        b, b_ref = closed.state_at(sigma), generic.state_at(sigma)
        assert (b.v, b.e, b.u) == pytest.approx((b_ref.v, b_ref.e, b_ref.u), rel=1e-12)
        (shock,), (shock_ref,) = closed.waves(sigma), generic.waves(sigma)
        assert shock.speed == pytest.approx(shock_ref.speed, rel=1e-12)


def test_jump_conditions_hold_to_rounding():
    """Mass, momentum and energy across the closed-form shock, to a few ulps."""
    mat = get("Cu")
    a = mat.reference_state()
    curve = mat.wave_curve(a, RIGHT)
    for sigma in STRESSES:
        (shock,) = curve.waves(sigma)
        b, speed = shock.behind, shock.speed
        assert mat.rho0 * speed * b.u == pytest.approx(b.sigma, rel=1e-15)
        assert speed * (b.v - a.v) / mat.v0 == pytest.approx(-b.u, rel=1e-14)
        assert b.e == pytest.approx(0.5 * b.sigma * (a.v - b.v), rel=1e-14)
        assert mat.stress(b.v, b.e) == pytest.approx(sigma, rel=1e-13)


def test_only_the_reference_state_gets_the_closed_form():
    mat = MieGruneisen("m", rho0=2700.0, c0=5300.0, s=1.4, gamma0=2.0)
    shocked = mat.wave_curve(mat.reference_state(), RIGHT).state_at(1e10)
    assert not isinstance(mat.wave_curve(shocked, RIGHT), PrincipalHugoniotCurve)
    assert isinstance(mat.wave_curve(mat.reference_state(u=-3.0), LEFT), PrincipalHugoniotCurve)


def test_beyond_the_equation_of_state_is_refused_and_its_edge_reached():
    """Above the curve's highest stress the closed form raises like the generic curve;
    at that stress it returns the limiting volume."""
    mat = get("PMMA")
    curve = mat.wave_curve(mat.reference_state(), RIGHT)
    top = curve.sigma_max()
    assert curve.state_at(top).v >= mat.volume_range()[0]
    with pytest.raises(StateOutOfRangeError, match="outside the range"):
        curve.velocity_change(top * 1.01)
    assert math.isfinite(curve.velocity_change(0.5 * top)[0])
