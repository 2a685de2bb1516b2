"""Pullback analysis of a free-surface velocity record: the spall strength it implies.

A plate-impact spall experiment records the velocity ``u_fs(t)`` of the target's
rear free surface (VISAR, PDV).  The shock brings it up to a plateau ``u_max``;
the release from the back of the flyer then pulls it down.  If the target
fractures inside, the new (spall) surface sends a recompression wave, the
*spall signal*, that stops the fall at a minimum ``u_min`` and turns the record
up again.  The drop ``Δu = u_max - u_min`` is the *pullback*, and the tension
the material carried when it broke is inferred from it:

- acoustic (linear) estimate, ``σ* = ½ ρ0 C Δu``.  A release of amplitude σ*
  reaching a free surface changes its velocity by ``2 σ*/(ρ0 C)`` (the wave and
  its reflection each bring ``σ*/(ρ0 C)``); the velocity the record loses before
  the spall signal arrives is that of the release that pulled the spall plane
  into tension.  In a linear elastic solid (a single speed ``C``) this is
  exact for the tension the spall plane carried before it broke.  For metals
  ``C`` is either the longitudinal (elastic) speed ``C0`` or, more often
  (G. I. Kanel et al.), the bulk speed ``CB``: the release at the free surface
  is plastic.  Both are reported; the answer differs by the ratio ``C0/CB``
  (1.27 for Davison's steel).
- elastic–plastic estimate (G. V. Stepanov, "Spall fracture of metals by
  elastic–plastic loading waves", Problemy Prochnosti / Strength of Materials,
  1976; used by G. I. Kanel, S. V. Razorenov and V. E. Fortov, *Shock-Wave
  Phenomena and the Properties of Condensed Matter*, Springer 2004, ch. on spall):

      σ* = ρ0 C0 Δu / (1 + C0/CB) = ρ0 Δu C0 CB / (C0 + CB).

  The material at the free surface has been released to zero stress through
  reverse yield, so the tension that arrives there is a plastic wave (impedance
  ``ρ0 CB``: the surface slows by ``σ*/(ρ0 CB)``), whereas the spall signal that
  ends the fall reloads it elastically (impedance ``ρ0 C0``: a further
  ``σ*/(ρ0 C0)`` in the reflection).  Hence ``Δu = σ* (1/(ρ0 CB) + 1/(ρ0 C0))``.
  It lies between the two acoustic estimates and reduces to them when
  ``C0 = CB``.  Kanel's further correction for the overtaking of the slow
  plastic release by the faster elastic spall signal needs the slopes of the
  record; in the ideal elastic–plastic solid every wave is a jump, so it is not
  applied here.

The estimates are reported beside what the exact solution knows: the largest
tension any region carried (``Solution.max_tension``), the first fracture
(``Solution.spalls``: the strength that failed and the tension the bonded
material would have reached) and the tension the spall plane carried just
before it broke.  With an instantaneous threshold and waves that are jumps, the
tension at a material point rises in steps and overshoots the strength in the
step that fractures it; the free surface can only ever see tension that was
carried.  In a linear elastic solid ``½ ρ0 C Δu`` is exactly that carried
tension (tests/test_pullback.py).  In the ideal elastic–plastic solid much of the
tension arrives as plastic release waves (at ``CB``) that the elastic spall
signal (at ``C0``) overtakes before they reach the surface: for Davison's steel
(5 mm on 10 mm at 230 m/s, spall strength 2.5 GPa) all three estimates read
about half the strength (gallery/25_ep_spall_pullback.py).

Units: SI throughout (s, m/s, kg/m³, Pa).  Velocities are signed outward (``+u``
for the right surface, ``-u`` for the left), as a VISAR sees them.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from materials import ElasticPlastic, LinearElastic, Material, WavediagramError

DEFAULT_TOLERANCE = 1e-3
"""Falls and rises smaller than this fraction of the record's largest speed are
ignored (the small steps that dropped waves and reverberations leave)."""


class NoPullbackError(WavediagramError, ValueError):
    """The record has no pullback: it never falls after its peak, or never rises again."""


@dataclass(frozen=True)
class Pullback:
    """The pullback of a record (SI units, velocities outward positive).

    ``u_max`` holds from ``t_peak`` (s); the record then falls to its first
    minimum ``u_min``, reached at ``t_min``; ``t_rebound`` is when it rises
    again (the arrival of the spall signal), ``None`` if it does not before the
    record ends (then ``u_min`` is only the lowest value seen so far).
    """

    t_peak: float
    u_max: float
    t_min: float
    u_min: float
    t_rebound: float | None

    @property
    def delta_u(self) -> float:
        """The pullback ``Δu = u_max - u_min`` (m/s)."""
        return self.u_max - self.u_min

    def acoustic(self, rho0: float, c: float) -> float:
        """Acoustic spall-strength estimate ``½ ρ0 C Δu`` (Pa); ``rho0`` kg/m³, ``c`` m/s."""
        return acoustic_spall_strength(rho0, c, self.delta_u)

    def stepanov(self, rho0: float, c0: float, cb: float) -> float:
        """Elastic–plastic estimate ``ρ0 C0 Δu / (1 + C0/CB)`` (Pa)."""
        return stepanov_spall_strength(rho0, c0, cb, self.delta_u)


def acoustic_spall_strength(rho0: float, c: float, delta_u: float) -> float:
    """``σ* = ½ ρ0 C Δu`` (Pa) from the density (kg/m³), a wave speed and the pullback (m/s)."""
    return 0.5 * rho0 * c * delta_u


def stepanov_spall_strength(rho0: float, c0: float, cb: float, delta_u: float) -> float:
    """Stepanov's elastic–plastic estimate ``σ* = ρ0 C0 Δu / (1 + C0/CB)`` (Pa).

    ``c0`` is the longitudinal (elastic) speed, ``cb`` the bulk (plastic) speed (m/s).
    """
    return rho0 * c0 * delta_u / (1.0 + c0 / cb)


def wave_speeds(material: Material) -> tuple[float, float]:
    """``(C0, CB)`` of a material in its reference state (m/s).

    Elastic–plastic: the longitudinal and bulk speeds.  Any other model has a
    single reference sound speed (linear elastic ``C``; a hydrodynamic solid's
    ``C_L`` at ``v0``), returned twice.
    """
    if isinstance(material, ElasticPlastic):
        return material.C0, material.CB
    if isinstance(material, LinearElastic):
        return material.C, material.C
    c = material.sound_speed(material.v0, 0.0)
    return c, c


def find_pullback(t, u, tolerance: float | None = None,
                  require_rebound: bool = True) -> Pullback:
    """The pullback of a record: ``u[k]`` (m/s) from ``t[k]`` (s), constant or linear up to
    the next point (a step record, or a continuous one given at its knots, whose
    extremes are knots).

    The peak is the largest value reached before the record first falls by more
    than ``tolerance`` (m/s; default ``DEFAULT_TOLERANCE`` of the largest
    ``|u|``); the minimum is the lowest value after it before the record rises by
    more than ``tolerance`` (the rebound).  Raises ``NoPullbackError`` if the
    record never falls after its peak, or, with ``require_rebound``, if it never
    rises again (no spall signal: the fall may not have ended).
    """
    t = np.asarray(t, dtype=float)
    u = np.asarray(u, dtype=float)
    if t.shape != u.shape or t.ndim != 1:
        raise ValueError(f"t and u must be 1-d arrays of one length, got shapes "
                         f"{t.shape} and {u.shape}")
    if u.size == 0:
        raise NoPullbackError("the record is empty")
    if tolerance is None:
        tolerance = DEFAULT_TOLERANCE * float(np.max(np.abs(u)))
    if not (math.isfinite(tolerance) and tolerance >= 0.0):
        raise ValueError(f"tolerance must be a finite speed >= 0 m/s, got {tolerance!r}")
    peak, fall = 0, None
    for k in range(1, u.size):
        if u[k] > u[peak]:
            peak = k
        elif u[k] < u[peak] - tolerance:
            fall = k
            break
    if fall is None:
        raise NoPullbackError(
            f"no pullback: the record rises to {u[peak]:.6g} m/s and never falls by more "
            f"than {tolerance:.3g} m/s after it (until t = {t[-1] * 1e6:.6g} us)")
    low, rebound = fall, None
    for k in range(fall + 1, u.size):
        if u[k] < u[low]:
            low = k
        elif u[k] > u[low] + tolerance:
            rebound = k
            break
    if rebound is None and require_rebound:
        raise NoPullbackError(
            f"no spall signal: the record falls from {u[peak]:.6g} m/s to {u[low]:.6g} m/s "
            f"and does not rise again by more than {tolerance:.3g} m/s before it ends "
            f"(t = {t[-1] * 1e6:.6g} us); follow the scene longer, or pass "
            f"require_rebound=False for the drop so far")
    return Pullback(t_peak=float(t[peak]), u_max=float(u[peak]), t_min=float(t[low]),
                    u_min=float(u[low]),
                    t_rebound=None if rebound is None else float(t[rebound]))


def surface_record(solution, side: str = "right") -> tuple[np.ndarray, np.ndarray]:
    """``(t s, u m/s)`` of a free surface of ``solution``, signed outward.

    Raises ``ValueError`` if that end of the scene is not a free surface.
    """
    if side not in ("left", "right"):
        raise ValueError(f"side must be 'left' or 'right', got {side!r}")
    boundary = solution.scene.right if side == "right" else solution.scene.left
    if boundary.kind != "free":
        raise ValueError(f"the {side} end of the scene is a {boundary.kind!r} boundary, "
                         f"not a free surface: a pullback needs a free-surface record")
    history = solution.history(side)
    sign = 1.0 if side == "right" else -1.0
    t, u = history.t, history.u
    if history.u_end[-1] != u[-1]:  # a record still falling (or rising) at its end
        t, u = np.append(t, history.stop), np.append(u, history.u_end[-1])
    return np.asarray(t, dtype=float), sign * u


def pullback(solution, side: str = "right", tolerance: float | None = None,
             require_rebound: bool = True) -> Pullback:
    """The pullback of the ``side`` free-surface record of ``solution`` (``find_pullback``)."""
    t, u = surface_record(solution, side)
    return find_pullback(t, u, tolerance, require_rebound)


@dataclass(frozen=True)
class SpallEstimate:
    """What a pullback implies (Pa), beside what the exact solution knows.

    ``acoustic_longitudinal`` ½ ρ0 C0 Δu, ``acoustic_bulk`` ½ ρ0 CB Δu,
    ``stepanov`` ρ0 C0 Δu/(1 + C0/CB), from ``record`` (a ``Pullback``) and the
    surface material's ``rho0``, ``c0``, ``cb``.  True values: ``max_tension``
    (the largest tension any region carried, Pa, positive, at ``max_tension_x``
    m and ``max_tension_t`` s; 0 if none), ``spall_strength`` (the strength of
    the first fracture, ``None`` without spall), ``fracture_tension`` (the
    tension the bonded material would have reached there) and
    ``carried_tension`` (the largest tension on either side of the first spall
    plane just before it broke).
    """

    record: Pullback
    rho0: float
    c0: float
    cb: float
    acoustic_longitudinal: float
    acoustic_bulk: float
    stepanov: float
    max_tension: float
    max_tension_x: float | None
    max_tension_t: float | None
    spall_strength: float | None
    fracture_tension: float | None
    carried_tension: float | None
    spall_x: float | None
    spall_t: float | None

    def estimates(self) -> dict[str, float]:
        """The three estimates by name (Pa)."""
        return {"acoustic_longitudinal": self.acoustic_longitudinal,
                "acoustic_bulk": self.acoustic_bulk, "stepanov": self.stepanov}

    def relative_errors(self, reference: float | None = None) -> dict[str, float]:
        """Each estimate's error relative to ``reference`` (Pa; default the spall
        strength, or the largest tension if nothing fractured)."""
        if reference is None:
            reference = self.spall_strength if self.spall_strength else self.max_tension
        if not reference:
            raise ValueError("no reference tension: the solution carried no tension")
        return {name: value / reference - 1.0 for name, value in self.estimates().items()}


def spall_estimates(solution, side: str = "right", tolerance: float | None = None,
                    material: Material | None = None) -> SpallEstimate:
    """Pullback of the ``side`` free surface and the spall strengths it implies.

    ``material`` defaults to that of the layer at that surface (its ``rho0``
    and ``wave_speeds``).  Raises ``NoPullbackError`` if the record has no
    pullback followed by a rebound.
    """
    record = pullback(solution, side, tolerance)
    if material is None:
        layers = solution.scene.layers
        material = layers[-1].material if side == "right" else layers[0].material
    c0, cb = wave_speeds(material)
    rho0 = material.rho0
    tension = solution.max_tension()
    first = min(solution.spalls, key=lambda s: s.t) if solution.spalls else None
    return SpallEstimate(
        record=record, rho0=rho0, c0=c0, cb=cb,
        acoustic_longitudinal=record.acoustic(rho0, c0),
        acoustic_bulk=record.acoustic(rho0, cb),
        stepanov=record.stepanov(rho0, c0, cb),
        max_tension=0.0 if tension is None else -tension["sigma"],
        max_tension_x=None if tension is None else tension["x"],
        max_tension_t=None if tension is None else tension["t"],
        spall_strength=None if first is None else first.strength,
        fracture_tension=None if first is None else first.tension,
        carried_tension=None if first is None else carried_tension(solution, first),
        spall_x=None if first is None else first.x,
        spall_t=None if first is None else first.t,
    )


def carried_tension(solution, spall) -> float:
    """Largest tension (Pa, >= 0) on either side of a spall plane just before it broke.

    ``spall`` is a ``SpallRecord``; the states are those of the regions whose
    closures meet the fracture point from below (the two waves that met there
    and the region between them), read at a time a hair before the fracture, and
    the state at the plane an instant before it.
    """
    x, t = spall.x, spall.t
    scale = max(solution.scene.length, 1e-300)
    tension = 0.0
    for region in solution.regions:
        if region.t_start >= t:
            continue
        points = region.polygon()
        if any(abs(px - x) <= 1e-9 * scale and abs(pt - t) <= 1e-9 * max(t, 1e-300)
               for px, pt in points):
            tension = max(tension, -region.state.sigma)
    # a fracture inserted inside a region (cumulative-damage criteria) is no vertex:
    # the state at the plane an instant before it broke
    before = solution.state_at(x, t * (1.0 - 1e-9))
    return max(tension, -before.sigma)
