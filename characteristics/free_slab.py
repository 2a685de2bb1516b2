"""Linear acoustics of a slab free on both faces, in closed form (d'Alembert).

A slab ``X_a <= X <= X_b`` (Lagrangian, length ``L``) of one material whose waves are
weak enough to be linear moves its stress and velocity as two waves of constant
Lagrangian speed ``C`` and impedance ``Z = rho0 C`` about a mean motion ``u0``:

    sigma = s_R(X - C t) + s_L(X + C t),    u = u0 + (s_R - s_L) / Z

(stress positive in compression: a right-going wave carries ``d sigma = Z du``, a
left-going one ``d sigma = -Z du``).  A free face holds ``sigma = 0``, so it reflects
``s_L -> -s_R`` (stress reflection ``-1``) at both faces, and the two waves are one
periodic function ``P`` of the *unfolded* coordinate ``xi`` in ``[0, 2L)``:

    s_R(X, t) = P(X - X_a - C tau),    s_L(X, t) = -P(2L - (X - X_a) - C tau),

``tau = t - t0``, period ``2L / C`` in time.  So at any time

    sigma(X, t) = P(a) - P(b),    u(X, t) = u0 + (P(a) + P(b)) / Z,
    a = X - X_a - C tau,   b = 2L - (X - X_a) - C tau   (both mod 2L),

and the faces move at ``u0 + 2 P(-C tau) / Z`` (left) and ``u0 + 2 P(L - C tau) / Z``
(right).  ``P`` is built from the piecewise-constant cells of the slab at ``t0``:
``s_R = (sigma + Z (u - u0)) / 2``, ``s_L = (sigma - Z (u - u0)) / 2``; ``u0`` is the
mass-weighted mean velocity, so ``P`` has zero mean over its period.  Momentum per
unit area ``rho0 L u0`` and acoustic energy ``int P^2 dxi / (Z C)`` are constants of the
motion: the closed form conserves both exactly.  Davison (2008), ch. 8 (Riemann
invariants of linear waves), for the reflection at a free surface.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class FreeSlab:
    """The closed-form ringing of a free slab (module docstring).

    ``x_lo``, ``x_hi``: faces (m, Lagrangian); ``t0``: time of the pattern (s); ``c``:
    Lagrangian sound speed (m/s); ``z``: impedance ``rho0 c`` (Pa s/m); ``u0``: mean
    velocity (m/s); ``breaks``: the jumps of ``P`` in ``[0, 2L)`` at ``t0`` (m, sorted,
    starting at 0); ``values``: ``P`` on ``[breaks[k], breaks[k+1])`` (Pa, zero mean).
    """

    x_lo: float
    x_hi: float
    t0: float
    c: float
    z: float
    u0: float
    breaks: np.ndarray
    values: np.ndarray

    @classmethod
    def from_cells(cls, edges, sigma, u, t0: float, c: float, z: float) -> FreeSlab:
        """The slab whose cells ``[edges[k], edges[k+1]]`` (m) hold ``sigma[k]`` (Pa) and
        ``u[k]`` (m/s) at ``t0`` (s)."""
        edges, sigma, u = (np.asarray(a, dtype=float) for a in (edges, sigma, u))
        widths = np.diff(edges)
        length = edges[-1] - edges[0]
        u0 = float(np.dot(widths, u) / length)
        s_right = 0.5 * (sigma + z * (u - u0))
        s_left = 0.5 * (sigma - z * (u - u0))
        local = edges - edges[0]
        # xi in [0, L): s_R at X_a + xi; xi in [L, 2L): -s_L at X_a + 2L - xi
        breaks = np.concatenate([local[:-1], 2.0 * length - local[::-1][:-1]])
        values = np.concatenate([s_right, -s_left[::-1]])
        keep = np.concatenate([[True], np.diff(values) != 0.0])
        breaks, values = breaks[keep], values[keep]
        # rounding: P's mean is moved into u0 (sigma keeps, u = u0 + 2 m / Z + ...)
        mean = float(np.dot(np.diff(np.append(breaks, 2.0 * length)), values)) / (2.0 * length)
        return cls(float(edges[0]), float(edges[-1]), t0, c, z, u0 + 2.0 * mean / z,
                   breaks, values - mean)

    @property
    def length(self) -> float:
        """The slab's Lagrangian length ``L`` (m)."""
        return self.x_hi - self.x_lo

    @property
    def period(self) -> float:
        """The ringing period ``2 L / C`` (s)."""
        return 2.0 * self.length / self.c

    def pattern(self, xi) -> np.ndarray:
        """``P`` (Pa) at unfolded coordinates ``xi`` (m, any real: taken mod ``2L``)."""
        xi = np.mod(np.asarray(xi, dtype=float), 2.0 * self.length)
        return self.values[np.searchsorted(self.breaks, xi, side="right") - 1]

    def state(self, x, t) -> tuple[np.ndarray, np.ndarray]:
        """``(sigma, u)`` (Pa, m/s) at Lagrangian ``x`` (m) and time ``t`` (s)."""
        shift = self.c * (np.asarray(t, dtype=float) - self.t0)
        local = np.asarray(x, dtype=float) - self.x_lo
        pa, pb = self.pattern(local - shift), self.pattern(2.0 * self.length - local - shift)
        return pa - pb, self.u0 + (pa + pb) / self.z

    def face_velocity(self, side: str, t) -> np.ndarray:
        """Velocity (m/s) of the ``"left"`` or ``"right"`` face at ``t`` (s)."""
        return self.u0 + 2.0 * self.pattern(self._face_xi(side, t)) / self.z

    def _face_xi(self, side: str, t):
        offset = 0.0 if side == "left" else self.length
        return offset - self.c * (np.asarray(t, dtype=float) - self.t0)

    def face_changes(self, side: str, t_from: float, t_to: float) -> np.ndarray:
        """The times (s) in ``(t_from, t_to]`` at which the face's velocity changes (a
        jump of ``P`` reaches it), in order."""
        span = 2.0 * self.length
        xi_from = float(self._face_xi(side, t_from))
        xi_to = float(self._face_xi(side, t_to))  # xi decreases with time
        lo = np.floor(xi_to / span)
        hi = np.floor(xi_from / span)
        turns = np.arange(lo, hi + 1.0)
        xi = (turns[:, None] * span + self.breaks[None, :]).ravel()
        xi = xi[(xi >= xi_to) & (xi < xi_from)]
        offset = 0.0 if side == "left" else self.length
        return np.sort(self.t0 + (offset - xi) / self.c)

    def face_displacement(self, side: str, t_from: float, t) -> np.ndarray:
        """How far (m) the face has moved from ``t_from`` at times ``t`` (s), in closed
        form whatever the span: ``u0 (t - t_from) + 2 (Q(xi_from) - Q(xi_t)) / (Z C)``,
        ``Q`` the antiderivative of ``P`` (periodic, as ``P`` has zero mean) and ``xi``
        the face's unfolded coordinate (``du = 2 P / Z`` and ``dxi = -C dt``)."""
        t = np.asarray(t, dtype=float)
        swept = self._antiderivative(self._face_xi(side, t_from)) - self._antiderivative(
            self._face_xi(side, t))
        return self.u0 * (t - t_from) + 2.0 * swept / (self.z * self.c)

    @property
    def face_wander(self) -> float:
        """The most (m) a face's displacement departs from the mean motion ``u0 (t -
        t_from)`` over any span: ``2 (max Q - min Q) / (Z C)``."""
        q = self._antiderivative(self.breaks)
        return 2.0 * float(np.max(q) - np.min(q)) / (self.z * self.c)

    def _antiderivative(self, xi) -> np.ndarray:
        """``Q(xi) = int_0^xi P`` (Pa m), ``xi`` taken mod ``2L``: piecewise linear."""
        widths = np.diff(np.append(self.breaks, 2.0 * self.length))
        done = np.concatenate([[0.0], np.cumsum(self.values * widths)])
        xi = np.mod(np.asarray(xi, dtype=float), 2.0 * self.length)
        k = np.searchsorted(self.breaks, xi, side="right") - 1
        return done[k] + self.values[k] * (xi - self.breaks[k])

    def face_pieces(self, side: str, t_from: float, t_to: float):
        """``(starts, velocities)``: the face's velocity is ``velocities[k]`` (m/s) from
        ``starts[k]`` to the next start (s) within ``[t_from, t_to]``."""
        starts = np.concatenate([[t_from], self.face_changes(side, t_from, t_to)])
        starts = starts[starts < t_to] if starts.size > 1 else starts
        ends = np.append(starts[1:], t_to)
        return starts, self.face_velocity(side, 0.5 * (starts + ends))

    def passages(self, x: float, t_from: float, t_to: float) -> np.ndarray:
        """The times (s) in ``(t_from, t_to)`` at which a wave of the pattern passes the
        station ``x`` (m), in order (at a face: its reflections)."""
        span = 2.0 * self.length
        steps = self.values - np.roll(self.values, 1)
        breaks = self.breaks[steps != 0.0]
        local = x - self.x_lo
        turns = np.arange(0.0, np.floor((t_to - self.t0) / self.period) + 1.0)
        times = []
        for s in {local, span - local}:  # right-going at s, left-going at 2L - s
            first = np.mod(s - breaks, span) / self.c
            times.append((self.t0 + first[None, :] + turns[:, None] * self.period).ravel())
        times = np.unique(np.concatenate(times))
        # two waves passing at once (a crossing at the station) are one passage
        times = times[np.concatenate([[True], np.diff(times) > 1e-9 * self.period])]
        return times[(times > t_from) & (times < t_to)]

    def acoustic_energy(self) -> float:
        """The slab's acoustic energy per unit area (J/m^2), ``int P^2 dxi / (Z C)``: the
        strain energy ``sigma^2 / (2 Z C)`` and the kinetic energy of ``u - u0``."""
        widths = np.diff(np.append(self.breaks, 2.0 * self.length))
        return float(np.dot(widths, self.values ** 2)) / (self.z * self.c)

    def jumps_at(self, t: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """The slab's waves at ``t`` (s): ``(x, direction, jump)`` -- positions (m),
        +1 right-going / -1 left-going, stress behind minus ahead (Pa) -- sorted by x.
        A jump of ``P`` exactly at a face is left out (it is that face's reflection)."""
        span, length = 2.0 * self.length, self.length
        steps = self.values - np.roll(self.values, 1)  # P(b_k) - P(b_k^-)
        s = np.mod(self.breaks + self.c * (t - self.t0), span)
        right = (s > 0.0) & (s < length)
        left = s > length
        x = np.where(right, self.x_lo + s, self.x_lo + span - s)
        direction = np.where(right, 1, -1)
        # behind a right-going wave (smaller X) s_R = P(b^-): jump -step; behind a
        # left-going one (larger X) s_L = -P(b^-): jump +step
        jump = np.where(right, -steps, steps)
        keep = (right | left) & (steps != 0.0)
        order = np.argsort(x[keep], kind="stable")
        return x[keep][order], direction[keep][order], jump[keep][order]
