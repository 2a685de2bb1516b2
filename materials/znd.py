"""The ZND profile: the steady reaction zone of a CJ detonation (Davison §13.2).

The engine keeps the reaction zone infinitely thin.  Its structure, for a plane CJ
detonation of speed ``D`` into unreacted explosive at rest (``sigma_a``, ``v_a = v0``,
``e = 0``), follows from the jump conditions alone between the front and any point of
a steady reaction zone: every state lies on the Rayleigh line

    sigma - sigma_a = rho0^2 D^2 (v0 - v),        e = 1/2 (sigma + sigma_a)(v0 - v),

from the von Neumann spike (the unreacted Hugoniot's point on the line: the lead shock
does not react) to the CJ point (complete reaction).  The mixture of reacted fraction
``lambda`` at common stress and volume has the energy ``e = (1 - lambda) e_u(sigma, v) +
lambda e_p(sigma, v)``, each phase's energy from its own equation of state, so along the
line ``lambda(v) = (e - e_u)/(e_p - e_u)``: 0 at the spike, 1 at CJ.

Reaction rate (a stated law): ``d lambda/dt = k (1 - lambda)^(1/2)``, which completes in
the finite time ``2/k``: ``lambda(t) = 1 - (1 - k t/2)^2``.  A material point is at the
Lagrangian distance ``D t`` behind the front when it has reacted for a time ``t``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .errors import MaterialError
from .state import State


@dataclass(frozen=True)
class ZNDProfile:
    """The reaction zone: arrays from the spike (index 0) to the CJ point (last).

    ``distance`` (m): Lagrangian distance behind the front; ``time`` (s) since the
    front passed; ``reacted`` (lambda); ``sigma`` (Pa), ``u`` (m/s, relative to the
    unreacted explosive), ``v`` (m^3/kg), ``e`` (J/kg).
    """

    distance: np.ndarray
    time: np.ndarray
    reacted: np.ndarray
    sigma: np.ndarray
    u: np.ndarray
    v: np.ndarray
    e: np.ndarray
    speed: float


def znd_profile(explosive, rate: float, points: int = 200) -> ZNDProfile:
    """The ZND profile of ``explosive``'s CJ detonation from rest with the rate constant
    ``rate`` (1/s) of ``d lambda/dt = k (1 - lambda)^(1/2)``.

    Raises ``MaterialError`` if ``rate`` is not > 0 or if the Rayleigh line of the CJ
    detonation misses the unreacted Hugoniot (no spike inside its range).
    """
    if not (isinstance(rate, (int, float)) and math.isfinite(rate) and rate > 0.0):
        raise MaterialError(f"{explosive.name}: the reaction rate k must be > 0 1/s, got "
                            f"{rate!r}")
    ahead = explosive.reference_state()
    cj = explosive.cj_state(ahead)
    d, rho0, v0 = cj.speed, explosive.rho0, ahead.v
    slope = rho0 * rho0 * d * d
    spike = _spike(explosive.unreacted, ahead, slope)
    time = 2.0 / rate * np.linspace(0.0, 1.0, points)
    reacted = 1.0 - (1.0 - 0.5 * rate * time) ** 2
    v = np.array([_volume_at(explosive, ahead, slope, lam, spike, cj.state.v)
                  for lam in reacted])
    sigma = ahead.sigma + slope * (v0 - v)
    e = 0.5 * (sigma + ahead.sigma) * (v0 - v)
    u = np.sqrt((sigma - ahead.sigma) * (v0 - v))
    return ZNDProfile(distance=d * time, time=time, reacted=reacted, sigma=sigma, u=u, v=v,
                      e=e, speed=d)


def _spike(unreacted, ahead: State, slope: float) -> float:
    """Volume of the von Neumann spike: the unreacted Hugoniot on the Rayleigh line."""
    def gap(v):
        return unreacted.hugoniot(ahead, v)[0] - ahead.sigma - slope * (ahead.v - v)

    lo, hi = unreacted.hugoniot_volume_limit(ahead), ahead.v * (1.0 - 1e-9)
    if not gap(lo) > 0.0 > gap(hi):
        raise MaterialError(f"{unreacted.name}: the CJ Rayleigh line does not meet the "
                            f"unreacted Hugoniot inside its range (no von Neumann spike)")
    return _bisect(gap, lo, hi)


def _volume_at(explosive, ahead: State, slope: float, reacted: float, v_spike: float,
               v_cj: float) -> float:
    """The volume on the Rayleigh line where the mixture has reacted the fraction given."""
    if reacted <= 0.0:
        return v_spike
    if reacted >= 1.0:
        return v_cj

    def excess(v):
        sigma = ahead.sigma + slope * (ahead.v - v)
        e = 0.5 * (sigma + ahead.sigma) * (ahead.v - v)
        e_u = _energy(explosive.unreacted, v, sigma)
        e_p = _energy(explosive.products, v, sigma)
        return (e - e_u) / (e_p - e_u) - reacted

    return _bisect(excess, v_spike, v_cj)


def _energy(phase, v: float, sigma: float) -> float:
    """Energy (J/kg) at which ``phase`` has stress ``sigma`` at volume ``v`` (its stress is
    affine in energy: two evaluations give it exactly)."""
    s0, s1 = phase.stress(v, 0.0), phase.stress(v, 1.0e6)
    return (sigma - s0) / (s1 - s0) * 1.0e6


def _bisect(func, lo: float, hi: float) -> float:
    """Root of ``func`` between ``lo`` and ``hi`` (opposite signs), to an ulp."""
    f_lo = func(lo)
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if mid in (lo, hi):
            break
        f_mid = func(mid)
        if (f_mid > 0.0) == (f_lo > 0.0):
            lo, f_lo = mid, f_mid
        else:
            hi = mid
    return 0.5 * (lo + hi)
