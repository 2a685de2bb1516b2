"""Rays crossing on the plastic release path of a perfectly plastic ``FinitePlastic`` solid.

A thin finite-plastic layer rings: its release fans cross one another, and every ray
crossing is a Riemann problem between the state left of the two rays and the state right
of them.  Mostly both lie on the reverse-yield surface ``S = -(2/3) Y`` and on one
plastic release path (the states of one fan, released from one yield point).  With no
hardening the deviator is constant along that path and the hydrostatic energy obeys
``de_h/dv = -(A + B e_h) - kappa S``, so the stress is a function of the volume alone
along it, ``sigma(v)``, with the Lagrangian speed ``C = v0 sqrt(-dsigma/dv)`` and the
path integral ``J(v) = int rho0 C dv`` (``materials.path_table``: tabulated to rounding).

Across a release fan of direction ``d`` from ``a`` the velocity is
``u = u_a - d (J(v) - J(v_a))``.  When both outgoing waves of the problem between ``L``
and ``R`` are releases along that path (the star volume ``v*`` above ``v_L`` and
``v_R``), equal velocity at the contact gives the star state in closed form:

    J(v*) = (J(v_L) + J(v_R) + u_R - u_L) / 2,      u* = (u_L + u_R + J(v_R) - J(v_L)) / 2,

and ``sigma* = sigma(v*)``: the Riemann solution itself (``materials.solve_contact``
intersects the same two fans), without two wave curves, their tables and a root search
on their velocity changes.  The tables of the paths met are kept (``ReleasePaths``,
one per run), so a burst of crossings on one path builds one.  Anything else is left
to the Riemann solver (``None``): a hardening solid, a state off the reverse-yield
surface, a compression on either side (an elastic reload, off the path), states on two
paths (their stresses at one volume further apart than ``PATH_MATCH``), a star stress
below the tensile floor (spall) or beyond the path's range.
"""

from __future__ import annotations

import math

from .errors import NoSolutionError, StateOutOfRangeError
from .finite_plastic import FinitePlastic, FinitePlasticWaveCurve
from .riemann import STRENGTH_TOLERANCE, RiemannSolution
from .roots import EPS, bracket_near, bracketed_newton
from .state import LEFT, RIGHT, State
from .waves import Fan

PATH_MATCH = 1e-12
"""Two states lie on one release path when their stresses at one volume differ by less
than this fraction of the path's modulus there, ``v (rho0 C)^2`` (Pa): a relative volume
jump below the engine's rounding of entropy contacts (``ENTROPY_JUMP_TOLERANCE``).
States of one fan differ by 1e-16 to 1e-13 of it; states across a plastic-strain or
entropy contact by 1e-3 and more."""

KEPT_PATHS = 8
"""Release paths a run keeps (most recently met first)."""


class ReleasePath:
    """One plastic release path of a perfectly plastic solid, from a state on its
    reverse-yield surface towards larger volumes: its table and closed form."""

    def __init__(self, material: FinitePlastic, state: State):
        self.material = material
        self._curve = FinitePlasticWaveCurve(material, state, RIGHT)
        if not self._curve.on_reverse_yield:
            raise StateOutOfRangeError(f"{material.name}: the state at {state.sigma:.6g} Pa "
                                       f"does not release along a plastic path")
        self.table = self._curve.release_table()

    def holds(self, state: State) -> bool:
        """Whether ``state``'s stress and volume lie on this path (``PATH_MATCH``) within
        its table (its deviator is the caller's to check)."""
        v = float(state.v)
        if not self.table.start <= v <= self.table.end:
            return False
        sigma, slope = self.table.stress(v)
        return abs(sigma - state.sigma) <= -PATH_MATCH * v * slope

    def integral(self, v: float) -> float:
        """``J(v) = int rho0 C dv`` from the path's start (m/s)."""
        return self.table.integral(v)

    def speed(self, v: float) -> float:
        """Lagrangian characteristic speed ``C`` at ``v`` (m/s)."""
        return math.sqrt(-self.table.stress(v)[1]) / self.material.rho0

    def volume_at_integral(self, target: float, start: float) -> float | None:
        """The volume beyond ``start`` where ``J`` reaches ``target`` (m/s), ``None``
        beyond the path's range."""

        def residual(v):
            return self.table.integral(v) - target, math.sqrt(-self.table.stress(v)[1])

        return self._root(residual, start, 4.0 * EPS * (abs(target) + abs(self.integral(start))))

    def volume_at_stress(self, sigma: float, start: float) -> float | None:
        """The volume beyond ``start`` where the stress falls to ``sigma`` (Pa), ``None``
        beyond the path's range."""

        def residual(v):
            stress, slope = self.table.stress(v)
            return stress - sigma, slope

        return self._root(residual, start, 16.0 * EPS * (abs(sigma) + self.material.hel))

    def _root(self, residual, start: float, noise: float) -> float | None:
        """Root of a monotone ``residual`` on the path beyond ``start`` (the tangent from
        ``start`` brackets it: ``J`` is concave and ``sigma`` convex along the path).
        A target not beyond ``start`` is ``start`` itself: a state's stress lies within
        ``PATH_MATCH`` of the path's, and a fan's inner stress within rounding of its
        ahead state's (seed 24 of ``benchmarks/pile_up.py``: 1.31339e10 Pa on both) may
        fall on either side."""
        value, slope = residual(start)
        if value * slope >= 0.0:
            return start
        local = bracket_near(residual, start, lower=start, upper=self.table.end, f_tol=noise)
        if local is None:
            return None
        lo, hi, guess, f_lo, f_hi = local
        if lo == hi:
            return lo
        return bracketed_newton(residual, lo, hi, guess, f_lo=f_lo, f_hi=f_hi, f_tol=noise)

    def state(self, v: float, sigma: float, u: float) -> State:
        """The state at ``v`` on the path with stress ``sigma`` and velocity ``u``."""
        return self._curve.release_state(v, sigma, u)


class ReleaseFanCurve:
    """The wave curve of a release fan along a ``ReleasePath`` from ``ahead``: the
    states and speeds its rays carry (``characteristics.simple_waves.discretise_fan``)."""

    def __init__(self, path: ReleasePath, ahead: State, direction: int):
        self.path = path
        self.material = path.material
        self.ahead = ahead
        self.direction = direction
        self._j_ahead = path.integral(float(ahead.v))
        self._last: tuple[float, float] | None = None

    def _volume(self, sigma: float) -> float:
        if self._last is None or self._last[0] != sigma:
            v = self.path.volume_at_stress(sigma, float(self.ahead.v))
            if v is None:
                raise NoSolutionError(f"{self.material.name}: stress {sigma:.6g} Pa is not on "
                                      f"the release path from {self.ahead.sigma:.6g} Pa")
            self._last = (sigma, v)
        return self._last[1]

    def state_at(self, sigma: float) -> State:
        """The state of stress ``sigma`` (Pa) inside the fan."""
        if sigma == self.ahead.sigma:
            return self.ahead
        v = self._volume(sigma)
        u = self.ahead.u - self.direction * (self.path.integral(v) - self._j_ahead)
        return self.path.state(v, sigma, u)

    def characteristic_speed(self, sigma: float) -> float:
        """Unsigned Lagrangian speed (m/s) of the characteristic of stress ``sigma``."""
        return self.path.speed(self._volume(sigma) if sigma != self.ahead.sigma
                               else float(self.ahead.v))


class ReleasePaths:
    """The release paths a run met, most recent first, and the crossings on them."""

    def __init__(self):
        self._paths: list[ReleasePath] = []

    def crossing(self, material, left: State, right: State,
                 tensile_strength: float = math.inf,
                 release: str = "isentrope") -> RiemannSolution | None:
        """The Riemann solution of ``left`` against ``right`` (one material) when both
        outgoing waves are releases along one plastic path (module notes), else ``None``."""
        if release != "isentrope" or not isinstance(material, FinitePlastic) \
                or material.hardening != 0.0 or not math.isfinite(left.v + right.v) \
                or not (material.on_reverse_yield(left) and material.on_reverse_yield(right)):
            return None
        try:
            path = self._path(material, left, right)
            return None if path is None else _crossing(path, left, right, tensile_strength)
        except (NoSolutionError, StateOutOfRangeError):
            return None

    def _path(self, material, left: State, right: State) -> ReleasePath | None:
        """A kept path holding both states (moved to the front), or a new one from the
        denser of them; ``None`` when they lie on no common path.  Both states lie on the
        reverse-yield surface."""
        for k, path in enumerate(self._paths):
            if path.material is material and path.holds(left) and path.holds(right):
                self._paths.insert(0, self._paths.pop(k))
                return path
        path = ReleasePath(material, left if left.v <= right.v else right)
        self._paths.insert(0, path)
        del self._paths[KEPT_PATHS:]
        return path if path.holds(left) and path.holds(right) else None


def _crossing(path: ReleasePath, left: State, right: State,
              tensile_strength: float) -> RiemannSolution | None:
    """The two release fans from ``left`` and ``right`` along ``path`` and their star
    state (module notes), ``None`` if either side compresses or the star state lies
    beyond the path or below the tensile floor."""
    v_l, v_r = float(left.v), float(right.v)
    j_l, j_r = path.integral(v_l), path.integral(v_r)
    j_star = 0.5 * (j_l + j_r + right.u - left.u)
    if not j_star > max(j_l, j_r):
        return None  # a compression on one side: an elastic reload, off the path
    v_star = path.volume_at_integral(j_star, max(v_l, v_r))
    if v_star is None:
        return None
    sigma = path.table.stress(v_star)[0]
    if sigma < -tensile_strength * (1.0 - STRENGTH_TOLERANCE):
        return None  # the contact separates: the Riemann solver's spall
    star = path.state(v_star, sigma, 0.5 * (left.u + right.u + j_r - j_l))
    tail = path.speed(v_star)
    left_fan = Fan(ahead=left, behind=star, head_speed=-path.speed(v_l), tail_speed=-tail,
                   direction=LEFT, curve=ReleaseFanCurve(path, left, LEFT))
    right_fan = Fan(ahead=right, behind=star, head_speed=path.speed(v_r), tail_speed=tail,
                    direction=RIGHT, curve=ReleaseFanCurve(path, right, RIGHT))
    return RiemannSolution((left_fan,), (right_fan,), star, star, bonded_sigma=sigma)
