"""Checks shared by the engine tests: jump conditions on every front, continuity
across every contact, no NaN anywhere."""

from __future__ import annotations

import math

import numpy as np

from fronttrack.plotting.sites import kind_at


def region_map(solution):
    return {r.id: r for r in solution.regions}


def assert_no_nan(solution):
    """Every state finite, and the event log in time order (the queue never steps back)."""
    times = [e.t for e in solution.events]
    assert all(b >= a for a, b in zip(times[:-1], times[1:], strict=True))
    for r in solution.regions:
        s = r.state
        for value in (s.sigma, s.u, s.e):
            assert math.isfinite(value), (r.id, s)
        assert s.v > 0.0


def assert_shock_jumps(solution, rel=1e-12):
    """Mass and momentum jumps across every shock front, relative to the scene's stress scale.

    Lagrangian jump conditions (compression-positive stress):
    ``U (v_b - v_a) = -v0 (u_b - u_a)`` and ``rho0 U (u_b - u_a) = sigma_b - sigma_a``.
    A wave weaker than the negligible stress may have been dropped beside a shock, so
    the states around it can differ from its own by up to that much.  The mass jump is
    also allowed the rounding of the stored volumes, which dominates in very weak scenes
    (a 1 nm/s impact compresses Cu by 1e-13).
    """
    regions = region_map(solution)
    report = solution.accuracy_report
    scale = rel * report["stress_scale"] + report["negligible_stress"]
    rel = 1.0
    checked = 0
    for f in solution.fronts:
        if f.kind != "shock" or f.left_region is None or f.right_region_id is None:
            continue
        left, right = regions[f.left_region], regions[f.right_region_id]
        a, b = (right.state, left.state) if f.direction > 0 else (left.state, right.state)
        m = left.material
        momentum = m.rho0 * f.speed * (b.u - a.u) - (b.sigma - a.sigma)
        assert abs(momentum) <= rel * scale, (f.id, momentum)
        mass = f.speed * (b.v - a.v) + m.v0 * (b.u - a.u)
        # volumes are stored whole, so a jump of v is resolved only to a few ulp(v)
        volume_rounding = 4.0 * np.finfo(float).eps * max(a.v, b.v) * abs(f.speed)
        assert abs(mass) <= rel * scale / (m.rho0 * abs(f.speed)) + volume_rounding, (
            f.id, mass)
        checked += 1
    return checked


def assert_contacts_continuous(solution, rel=1e-12, wave_impedance=None):
    """sigma and u equal on both sides of every closed interface and entropy contact.

    Allowed: 1e-12 of the scene's stress scale, plus the negligible stress for each
    wave an interaction may send off a contact and drop (one per side, two per side in
    an elastic–plastic solid: elastic and plastic); in u, that stress over the smaller
    impedance of the two states there, or over ``wave_impedance`` (kg/m^2/s) when a
    dropped wave can be slower than sound (a compaction wave in a porous solid).
    """
    report = solution.accuracy_report
    waves = 4.0 if any(layer.material.splits_waves for layer in solution.scene.layers) else 2.0
    scale = rel * report["stress_scale"] + waves * report["negligible_stress"]
    times = sorted({e.t for e in solution.events} | {solution.scene.t_end})
    delta = 1e-9 * solution.scene.length
    u_scale = max(abs(r.state.u) for r in solution.regions) or 1.0
    checked = 0
    for t0, t1 in zip(times[:-1], times[1:], strict=True):
        if t1 - t0 < 1e-9 * solution.scene.t_end:
            continue
        t = 0.5 * (t0 + t1)
        for f in solution.fronts:
            if f.kind not in ("interface", "contact", "gap") or not f.t0 <= t <= (f.t1 or 0.0):
                continue
            if kind_at(f, t) == "gap":  # open (spall planes are born open)
                continue
            x = f.x0
            left_region = solution.region_at(x - delta, t)
            right_region = solution.region_at(x + delta, t)
            left, right = left_region.state, right_region.state
            assert abs(left.sigma - right.sigma) <= scale, (f.id, t, left, right)
            impedance = min(impedance_of(left_region), impedance_of(right_region),
                            wave_impedance or math.inf)
            assert abs(left.u - right.u) <= 1e-12 * u_scale + scale / impedance, (
                f.id, t, left, right)
            checked += 1
    return checked


def impedance_of(region):
    """``rho0 C_L`` (kg/m^2/s) of a region's state."""
    s = region.state
    return region.material.rho0 * region.material.sound_speed(s.v, s.e)


def region_states(solution, layer):
    return np.array([[r.state.sigma, r.state.u] for r in solution.regions if r.layer == layer])


def assert_wave_jumps(shock, rho0: float, tol: float = 1e-12) -> None:
    """Mass, momentum and Rankine–Hugoniot energy across one ``Shock`` of a material of
    reference density ``rho0``, each to ``tol`` of its jump."""
    a, b, u = shock.ahead, shock.behind, shock.speed
    assert abs(rho0 * u * (b.u - a.u) - (b.sigma - a.sigma)) <= tol * abs(b.sigma - a.sigma)
    assert abs(u * (b.v - a.v) * rho0 + (b.u - a.u)) <= tol * abs(b.u - a.u)
    de = 0.5 * (a.sigma + b.sigma) * (a.v - b.v)
    assert abs((b.e - a.e) - de) <= tol * abs(de)
