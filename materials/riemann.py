"""One Riemann solver for every interaction the engine meets.

Two uniform states meet at a point: ``L`` (left material) and ``R`` (right
material).  A left-going wave runs into ``L`` and a right-going wave into ``R``;
the states behind them meet at a contact with equal stress and particle
velocity (impedance matching).  With the wave curves of ``materials.wavecurves``,
``u = u_L - g_L(sigma)`` on the left and ``u = u_R + g_R(sigma)`` on the right, so
the contact stress is the root of the increasing function

    phi(sigma) = g_L(sigma) + g_R(sigma) + u_R - u_L,

found by a bracketed, safeguarded Newton iteration inside both materials'
ranges of validity.  The same solver serves impact, collision, overtaking
(the overtaken and overtaking waves are replaced by the states they bound),
transmission and reflection at interfaces, and reflection at boundaries
(``solve_boundary``: one wave curve against a prescribed stress or velocity).  Two
states of one small-strain elastic–plastic solid that both stay elastic are solved in
closed form first, by superposition (``materials.elastic_contact``): the same answer,
without wave curves.

Contacts that cannot carry tension: if the root lies below ``-tensile_strength``
(0 for an unbonded interface or a gas, the spall strength inside a solid), the
contact separates into two free surfaces; each side then unloads to
``sigma = 0`` on its own and a gap opens because ``u_R > u_L``.  A tension beyond
what the equations of state can carry separates the contact too (cavitation), with
``bonded_sigma`` the most tension they carry.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass

from .elastic_contact import elastic_contact
from .elastic_plastic import ElasticPlastic
from .errors import NoSolutionError, StateOutOfRangeError
from .frozen import slot_init
from .roots import EPS as _EPS
from .roots import bracket_near, bracketed_newton
from .state import LEFT, RIGHT, State
from .wavecurves import WEAK_VOLUME_JUMP


@slot_init
@dataclass(frozen=True, slots=True)
class RiemannSolution:
    """Outcome of a Riemann problem.

    ``left_waves``: left-going waves, leading (leftmost) first; ``right_waves``:
    right-going waves, leading (rightmost) first.  ``left_star``/``right_star``:
    the states on the two sides of the contact (``None`` on a boundary's outer
    side).  ``separated``: the contact opened.  ``bonded_sigma``: the contact
    stress the problem would have had without separation (Pa); below
    ``-tensile_strength`` when ``separated``.  ``release_floor``: ``(material name,
    stress in Pa)`` when a face released toward a lower stress than its equation of
    state reaches (``release_target``), else ``None``.
    """

    left_waves: tuple
    right_waves: tuple
    left_star: State | None
    right_star: State | None
    separated: bool = False
    bonded_sigma: float = math.nan
    release_floor: tuple[str, float] | None = None

    def fronts_in_order(self) -> list:
        """All waves in their order along X just after the interaction."""
        return [*self.left_waves, *reversed(self.right_waves)]


STRENGTH_TOLERANCE = 1e-12
"""Relative margin within which a tension counts as having reached the strength."""


def _acoustic_guess(z_left, z_right, left: State, right: State) -> float:
    """Contact stress if both waves were acoustic with the ahead states' impedances."""
    if not z_left + z_right > 0.0:
        return max(left.sigma, right.sigma)  # cold gases: no acoustic estimate
    return (z_right * left.sigma + z_left * right.sigma
            + z_left * z_right * (left.u - right.u)) / (z_left + z_right)


def solve_contact(left_material, left: State, right_material, right: State,
                  tensile_strength: float = math.inf, release: str = "isentrope",
                  ) -> RiemannSolution:
    """Contact state and outgoing waves when ``left`` meets ``right``.

    ``tensile_strength`` (Pa, >= 0) is the largest tension the contact carries:
    ``inf`` for a bonded interface that never fails, 0 for an unbonded one,
    the spall strength inside a material.
    """
    # Tension *reaching* the strength separates: equality is decided within the
    # rounding of a computed stress (1e-12 relative), never by the last bits.
    floor = -tensile_strength * (1.0 - STRENGTH_TOLERANCE)
    if left_material is right_material and isinstance(left_material, ElasticPlastic):
        elastic = elastic_contact(left_material, left, right, floor)
        if elastic is not None:  # both sides stay elastic: the superposition
            *waves_and_stars, sigma = elastic
            return RiemannSolution(*waves_and_stars, bonded_sigma=sigma)
    curve_l = left_material.wave_curve(left, LEFT, release)
    curve_r = right_material.wave_curve(right, RIGHT, release)
    if not math.isfinite(left.v) or not math.isfinite(right.v):
        # a gas expanded to vacuum (v = inf, sigma = 0) carries no stress and cannot be
        # compressed again: to the other side the contact is a free surface
        return _against_vacuum(curve_l, left, curve_r, right)
    du = right.u - left.u
    curve_l, curve_r = _settle(curve_l, curve_r, du)

    def phi(sigma):
        g_l, dg_l = curve_l.velocity_change(sigma)
        g_r, dg_r = curve_r.velocity_change(sigma)
        return g_l + g_r + du, dg_l + dg_r

    guess = _acoustic_guess(curve_l.impedance, curve_r.impedance, left, right)
    if hasattr(curve_l, "linear_breaks") and hasattr(curve_r, "linear_breaks"):
        sigma = _piecewise_linear_root(phi, curve_l, curve_r, guess)
        if sigma is not None and sigma >= floor:
            return _bonded(curve_l, curve_r, sigma)
    # phi is a sum of particle velocities: its rounding noise is a few ulps of them.
    z_min = min(curve_l.impedance, curve_r.impedance)
    stress_scale = abs(left.sigma) + abs(right.sigma) + abs(guess)
    noise = 4.0 * _EPS * (abs(left.u) + abs(right.u)
                          + (stress_scale / z_min if z_min > 0.0 else abs(du)))
    noise += _volume_noise(curve_l, left, guess) + _volume_noise(curve_r, right, guess)
    # phi increases with sigma; below the floor the contact separates instead.
    local = bracket_near(phi, guess, lower=floor, f_tol=noise)
    if local is not None:
        lo, hi, start, f_lo, f_hi = local
        sigma = bracketed_newton(phi, lo, hi, start, f_lo=f_lo, f_hi=f_hi, f_tol=noise)
        return _bonded(curve_l, curve_r, sigma)
    hi, phi_hi = _upper_bracket(phi, curve_l, curve_r, left, right, guess)
    if phi_hi < 0.0:
        raise NoSolutionError(
            f"impact of {left_material.name} on {right_material.name} needs a stress above "
            f"{hi / 1e9:.6g} GPa, beyond the range of validity of their equations of state "
            f"(closing velocity {-du:.6g} m/s)"
        )
    lo, phi_lo = _lower_bracket(phi, curve_l, curve_r, min(left.sigma, right.sigma, guess),
                                hi, floor)
    if phi_lo > 0.0:
        if lo == floor:
            return _separate(curve_l, curve_r, _bonded_estimate(phi, curve_l, curve_r, floor))
        # the tension would leave an equation of state: the material cavitates there (a
        # gas cannot pull at all: vacuum forms), and bonded_sigma is that limit
        return _separate(curve_l, curve_r, lo)
    sigma = bracketed_newton(phi, lo, hi, guess, f_lo=phi_lo, f_hi=phi_hi,
                             f_tol=noise * max(1.0, max(abs(lo), abs(hi)) / max(stress_scale, 1.0)))
    return _bonded(curve_l, curve_r, sigma)


def _piecewise_linear_root(phi, curve_l, curve_r, guess: float) -> float | None:
    """The contact stress (Pa) when both wave curves are piecewise linear in ``sigma``.

    Then ``phi`` is piecewise linear and increasing, with its slope changing only at
    the curves' ``linear_breaks()`` (yield stresses).  Its sign at the breaks picks
    the piece that holds the root, and one evaluation inside that piece gives it:
    ``sigma = p - phi(p)/phi'(p)``, exact up to rounding, with no iteration.  Returns
    ``None`` if the root lies outside the curves' common stress range (the general
    path then decides between cavitation and an error).
    """
    low_l, high_l = curve_l.sigma_limits()
    low_r, high_r = curve_r.sigma_limits()
    low, high = max(low_l, low_r), min(high_l, high_r)
    breaks = sorted({b for b in curve_l.linear_breaks() + curve_r.linear_breaks()
                     if low < b < high})
    below = above = None
    for b in breaks:
        if phi(b)[0] >= 0.0:
            above = b
            break
        below = b
    # a point inside the piece, near its break: the range's ends are far off (a volume
    # 1000 v0), and the rounding of the root grows with the distance to the point
    if below is not None and above is not None:
        inside = 0.5 * (below + above)
    elif above is not None:
        inside = above - max(abs(above - guess), abs(above), 1.0)
    elif below is not None:
        inside = below + max(abs(guess - below), abs(below), 1.0)
    else:
        inside = guess
    below = low if below is None else below
    above = high if above is None else above
    inside = min(max(inside, below), above)
    value, slope = phi(inside)
    if not slope > 0.0:
        return None
    sigma = inside - value / slope
    if not low <= sigma <= high:
        return None
    return min(max(sigma, below), above)


def _settle(curve_l, curve_r, du: float):
    """A metastable side (an unreacted explosive, whose curve has ``settle``) takes the
    reactive branch when the contact would be compressed at its stress: there
    ``phi(sigma_a) = g_other(sigma_a) + du < 0`` (``materials.explosive``)."""
    if hasattr(curve_l, "settle"):
        other = 0.0 if hasattr(curve_r, "settle") else curve_r.velocity_change(
            curve_l.ahead.sigma)[0]
        curve_l = curve_l.settle(other + du)
    if hasattr(curve_r, "settle"):
        curve_r = curve_r.settle(curve_l.velocity_change(curve_r.ahead.sigma)[0] + du)
    return curve_l, curve_r


def _volume_noise(curve, state: State, sigma: float) -> float:
    """Rounding (m/s) of a curve's velocity change near ``sigma`` from its volume root:
    the volume is a float, and one ulp of it moves ``g`` by ``rho0 C_L ulp(v)``; none for
    a weak jump (acoustic estimate), whose ``g`` comes from the stress jump."""
    z = curve.impedance
    if not (math.isfinite(state.v) and z > 0.0):
        return 0.0
    if abs(sigma - state.sigma) <= WEAK_VOLUME_JUMP * state.v * z * z:
        return 0.0
    return 4.0 * z * math.ulp(state.v)


def _bonded(curve_l, curve_r, sigma: float) -> RiemannSolution:
    """The solution with contact stress ``sigma`` (no separation)."""
    return RiemannSolution(
        left_waves=curve_l.waves(sigma),
        right_waves=curve_r.waves(sigma),
        left_star=curve_l.state_at(sigma),
        right_star=curve_r.state_at(sigma),
        bonded_sigma=sigma,
    )


def _upper_bracket(phi, curve_l, curve_r, left, right, guess):
    """A stress with ``phi >= 0``, or the curves' common maximum if there is none."""
    top = max(left.sigma, right.sigma, guess)
    width = max(top - min(left.sigma, right.sigma, guess), 1e-9 * abs(top), 1.0)
    limit = None
    trial = top + 0.25 * width
    while True:
        if limit is not None and trial >= limit:
            return limit, phi(limit)[0]
        try:
            value = phi(trial)[0]
            if math.isnan(value) or math.isinf(trial):  # no float stress closes it
                raise NoSolutionError("the contact stress is beyond every finite stress")
        except (NoSolutionError, StateOutOfRangeError):
            limit = min(curve_l.sigma_max(), curve_r.sigma_max())
            if math.isnan(limit):
                raise NoSolutionError("the curves' common top stress is undefined") from None
            trial = limit
            continue
        if value >= 0.0:
            return trial, value
        width *= 2.0
        trial = top + width


def _lower_bracket(phi, curve_l, curve_r, bottom, hi, floor):
    """A stress with ``phi <= 0`` not below ``floor``; else the lowest admissible stress."""
    width = max(hi - bottom, 1e-9 * abs(bottom), 1.0)
    trial = max(bottom, floor)
    limit = None
    while True:
        try:
            value = phi(trial)[0]
        except (NoSolutionError, StateOutOfRangeError):
            if limit is not None:
                raise
            limit = max(curve_l.sigma_min(), curve_r.sigma_min(), floor)
            trial = limit
            continue
        if value <= 0.0 or trial == floor or trial == limit:
            return trial, value
        width *= 2.0
        trial = max(bottom - width, floor)
        if limit is not None:
            trial = max(trial, limit)


def _bonded_estimate(phi, curve_l, curve_r, floor) -> float:
    """Contact stress the bonded problem would reach below a failed ``floor`` (for reports).

    Returns the root if it lies inside both materials' ranges, else the lowest
    admissible stress (the tension is at least that).
    """
    lowest = max(curve_l.sigma_min(), curve_r.sigma_min())
    if lowest >= floor:
        return lowest
    try:
        return bracketed_newton(phi, lowest, floor, rel_tol=1e-10)
    except (NoSolutionError, StateOutOfRangeError):
        return lowest


def release_target(curve, sigma: float) -> tuple[float, tuple[str, float] | None]:
    """The stress (Pa) a face released toward ``sigma`` ends at, and the floor it met.

    A material shocked beyond the range of its equation of state's release paths (Cu at
    7 km/s: its Mie-Grüneisen isentrope from 286 GPa leaves the fit's volume range,
    ``v0 (1 + 0.3 / s)``, at 1.6 GPa) cannot release to a free surface inside that
    equation of state.  The face then releases to the lowest stress the release path
    reaches (the state at the volume limit) and keeps it: the expansion beyond, into
    liquid and vapour, is not modelled.  The pressure the face keeps does work on
    nothing, so the run loses energy (never makes it) and its momentum balance shows
    the impulse; the run warns with the material and the stress.  Returns ``(sigma,
    None)`` when ``sigma`` is reachable or when the lowest stress is a tension (a
    tension beyond the range stays an error: the material cavitates elsewhere).
    """
    lowest = getattr(curve, "release_floor", curve.sigma_min)()
    if sigma < lowest and lowest > 0.0:
        return lowest, (curve.material.name, lowest)
    return sigma, None


def _separate(curve_l, curve_r, bonded_sigma: float):
    """Both sides unload to a free surface; a gap opens between them."""
    sigma_l, floor_l = release_target(curve_l, 0.0)
    sigma_r, floor_r = release_target(curve_r, 0.0)
    return RiemannSolution(
        left_waves=curve_l.waves(sigma_l),
        right_waves=curve_r.waves(sigma_r),
        left_star=curve_l.state_at(sigma_l),
        right_star=curve_r.state_at(sigma_r),
        separated=True,
        bonded_sigma=bonded_sigma,
        release_floor=floor_l or floor_r,
    )


def _against_vacuum(curve_l, left: State, curve_r, right: State) -> RiemannSolution:
    """A side expanded to vacuum sends no wave; the other unloads to a free surface."""
    floors = []

    def side(curve, state):
        if not math.isfinite(state.v):
            return (), state
        sigma, floor = release_target(curve, 0.0)
        floors.append(floor)
        return curve.waves(sigma), curve.state_at(sigma)

    left_waves, left_star = side(curve_l, left)
    right_waves, right_star = side(curve_r, right)
    return RiemannSolution(left_waves=left_waves, right_waves=right_waves,
                           left_star=left_star, right_star=right_star, separated=True,
                           bonded_sigma=0.0, release_floor=next(filter(None, floors), None))


def solve_boundary(material, state: State, boundary_at: str, *, stress: float | None = None,
                   velocity: float | None = None, release: str = "isentrope",
                   ) -> RiemannSolution:
    """Reflection at a boundary of prescribed ``stress`` (Pa) or ``velocity`` (m/s).

    ``boundary_at`` is ``"right"`` when the boundary is the right end of the
    material (the reflected wave goes left) and ``"left"`` otherwise.  A free
    surface is ``stress=0``; an immovable wall is ``velocity=0``.
    """
    if (stress is None) == (velocity is None):
        raise ValueError("give exactly one of stress or velocity")
    if boundary_at not in ("left", "right"):
        raise ValueError(f"boundary_at must be 'left' or 'right', got {boundary_at!r}")
    direction = LEFT if boundary_at == "right" else RIGHT
    if not math.isfinite(state.v):
        # a gas expanded to vacuum: no wave can run into it, the boundary sees nothing
        sides = ((), (), state, None) if direction == LEFT else ((), (), None, state)
        return RiemannSolution(*sides, bonded_sigma=0.0)
    curve = material.wave_curve(state, direction, release)
    if hasattr(curve, "settle"):  # an unreacted explosive detonates if compressed
        compression = (float(stress) - state.sigma if stress is not None
                       else direction * (float(velocity) - state.u))
        curve = curve.settle(-compression)
    floor = None
    if stress is not None:
        sigma, floor = release_target(curve, float(stress))
        curve.check_stress(sigma)
    else:
        target = direction * (float(velocity) - state.u)  # required g
        lo, hi = curve.sigma_limits()

        def residual(s):
            g, dg = curve.velocity_change(s)
            return g - target, dg

        z = material.rho0 * material.sound_speed(state.v, state.e)
        guess = state.sigma + z * target
        noise = (4.0 * _EPS * (abs(state.u) + abs(float(velocity))
                               + (abs(guess) / z if z > 0.0 else abs(target)))
                 + _volume_noise(curve, state, guess))
        local = bracket_near(residual, guess, lo, hi, f_tol=noise)
        if local is not None:
            lo, hi, guess, r_lo, r_hi = local
        else:
            try:
                r_lo, r_hi = residual(lo)[0], residual(hi)[0]
            except StateOutOfRangeError:  # an end of the range no wave reaches (inf)
                r_lo = r_hi = math.nan
            if not (r_hi >= 0.0 and r_lo <= 0.0):
                reach = (f"{lo / 1e9:.6g} to {hi / 1e9:.6g} GPa" if math.isfinite(hi) else
                         f"from {lo / 1e9:.6g} GPa up to where it leaves that range")
                raise NoSolutionError(
                    f"{material.name}: a boundary velocity of {velocity:.6g} m/s needs a "
                    f"stress outside the range of its equation of state ({reach})"
                )
        sigma = bracketed_newton(residual, lo, hi, guess, f_lo=r_lo, f_hi=r_hi, f_tol=noise)
    star = curve.state_at(sigma)
    if velocity is not None:
        # the prescribed velocity holds exactly (a wall is at rest, not at 1e-14 m/s)
        star = dataclasses.replace(star, u=float(velocity))
    waves = curve.waves(sigma)
    if direction == LEFT:
        return RiemannSolution(waves, (), star, None, bonded_sigma=sigma, release_floor=floor)
    return RiemannSolution((), waves, None, star, bonded_sigma=sigma, release_floor=floor)
