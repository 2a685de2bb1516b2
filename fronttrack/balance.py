"""The momentum and energy balance of a run, and what the accuracy settings promise.

Per unit area of the plates, between ``t = 0`` and ``t_end``,

    P(t_end) - P(0) = I        (I: impulse of the boundary stresses)
    E(t_end) - E(0) = W        (W: work of the boundary stresses; E = sum m (e + u^2/2))

hold exactly for the equations the engine solves.  Shocks and contacts satisfy their
jump conditions to rounding; the characteristics of a simple wave move at the
characteristic speed of their own state, which leaves a residual second order in the
characteristic step; waves weaker than the negligible stress are dropped, and the
stress mismatch each one leaves behind acts as a small force until the next wave
passes.  The residuals are reported relative to a scale that cannot vanish: momentum
against the momentum content ``sum m |u|`` (plates moving towards each other carry
almost no net momentum), energy against the energy content ``sum m (|e| + u^2/2)`` or
the work, the larger (an explosive's total energy stays zero while its heat of
detonation, carried as ``e = -q`` by the products, turns into motion and heat).

The settings promise a balance within ``BALANCE_FACTOR`` times the larger of the
record tolerance and the estimated record error, as fractions of the stress scale (a
relative error ``f`` in stresses and velocities is about ``2 f`` in energy).  A run
whose balance is beyond that, or that created energy beyond it, says so in one line.
"""

from __future__ import annotations

import math

BALANCE_FACTOR = 2.0
"""Promised relative balance per unit relative record tolerance (energy is quadratic)."""

ROUNDING = 1e-9
"""Balances below this relative size are rounding (shock-only scenes reach ~1e-12)."""


def promised_balance(report: dict) -> float:
    """The relative momentum and energy balance the accuracy settings promise."""
    scale = report["stress_scale"]
    if not scale > 0.0:
        return ROUNDING
    record = max(report["stress_tolerance"], report["estimated_record_error"])
    return max(BALANCE_FACTOR * record / scale, ROUNDING)


def live_content(engine, t: float) -> tuple[float, float]:
    """The momentum content ``sum rho0 |u| dX`` (kg/(m^2 s)) and energy content
    ``sum rho0 (|e| + u^2/2) dX`` (J/m^2) of the live regions at time ``t`` (s): the
    scales the balance is measured on, as a run holds them (walking its fronts).

    Asked at many events of a long run (``fronttrack.coalesce.budget``) over every
    front, so each front's position (``Front.position``, inlined) is computed once."""
    momentum = energy = 0.0
    front = engine.head
    if front is None:
        return momentum, energy
    x = front.position(t)
    following = front.next
    while following is not None:
        speed = following.speed
        x_next = following.x0 if speed == 0.0 else following.x0 + speed * (t - following.t0)
        region, width = front.region_right, x_next - x
        if region is not None and width > 0.0:
            mass = region.material.rho0 * width
            state = region.state
            momentum += mass * abs(state.u)
            energy += mass * (abs(state.e) + 0.5 * state.u ** 2)
        front, x, following = following, x_next, following.next
    return momentum, energy


def balance(solution) -> dict:
    """The run's balance at ``t_end``: relative momentum residual, signed relative energy
    residual (positive: energy created), and the promise they are held to."""
    c = solution.conservation()
    momentum, energy = float(c["momentum_relative_error"]), float(c["energy_error"]
                                                                 / c["energy_scale"])
    return {
        # a record that is not finite (a face expanded to vacuum) is not a balance: None
        "momentum_error": momentum if math.isfinite(momentum) else None,
        "energy_error": energy if math.isfinite(energy) else None,
        "promised": promised_balance(solution.accuracy_report),
    }


def warnings(report: dict, entry: dict) -> list[str]:
    """One-line warnings for a balance ``entry`` (from ``balance``) beyond its promise,
    with the setting that most likely explains it (from the accuracy ``report``)."""
    promised = entry["promised"]
    if entry["momentum_error"] is None or entry["energy_error"] is None:
        return ["the momentum and energy balance could not be measured (a record at a "
                "boundary is not finite, e.g. a gas expanded to vacuum there)"]
    found = []
    if entry["energy_error"] > promised:
        found.append(f"energy created: {entry['energy_error']:.2g} of the total, beyond the "
                     f"{promised:.2g} the accuracy settings promise{_hint(report)}")
    elif -entry["energy_error"] > promised:
        found.append(f"energy lost: {-entry['energy_error']:.2g} of the total, beyond the "
                     f"{promised:.2g} the accuracy settings promise{_hint(report)}")
    if entry["momentum_error"] > promised:
        found.append(f"momentum balance off by {entry['momentum_error']:.2g} of the momentum "
                     f"content, beyond the {promised:.2g} the accuracy settings promise"
                     f"{_hint(report)}")
    return found


def _hint(report: dict) -> str:
    """The settings that most likely explain a balance beyond its promise: neglected
    entropy contacts if any; else the fans' finite characteristic steps (a
    characteristic's jump misses the Rankine-Hugoniot energy by a third-order defect,
    and a lattice's cells lie on one isentrope table within its tolerance) and any waves
    dropped below the negligible stress."""
    if report.get("neglected_contact_energy", 0.0) > 0.0:
        return " (entropy contacts were neglected: set accuracy.entropy_contacts = true)"
    if report.get("dropped_waves", 0):
        return (f" ({report['dropped_waves']} waves below the negligible stress "
                f"{report['negligible_stress']:.3g} Pa were dropped, and fans are cut into "
                "characteristics of finite step: lower accuracy.negligible_stress or raise "
                "accuracy.rays_per_fan)")
    return (" (fans are cut into characteristics of finite step: raise "
            "accuracy.rays_per_fan)")
