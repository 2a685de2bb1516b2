"""A layer of elastic–viscoplastic solid on its characteristic grid (Davison §10.3).

The solid of ``materials.viscoplastic``: its characteristics are the straight lines
``dX/dt = +-C0`` and along them

    d(sigma + Z u) = -2 mu phi dt  (C+),   d(sigma - Z u) = -2 mu phi dt  (C-),
    d eps_p = phi dt  (particle paths),     phi = d eps_p/dt (the overstress law).

The grid is the characteristic net itself: ``dX = thickness / cells``, ``dt = dX / C0``,
nodes at ``(i dX, n dt)`` with ``i + n`` even (a diamond lattice), so that C+ lines,
C- lines and particle paths meet only at nodes.  A node takes the C+ relation from
``(i-1, n-1)``, the C- relation from ``(i+1, n-1)`` and the particle path from
``(i, n-2)``.

What is exact and what is integrated:

- *exact*: the characteristic paths (straight, the grid lines), the elastic jump
  conditions at the one discontinuity of the problem (the precursor started by the
  impact and its reflections, which run along grid lines: its two sides are kept
  apart, ``sigma -+ Z u`` and ``eps_p`` continuous across it), and the boundary
  conditions (a piston at constant velocity at ``X = 0``, a free surface at the
  other end);
- *integrated, second order*: the relaxation source ``-2 mu phi``, by the
  trapezoidal rule along each characteristic segment and particle path (implicit
  in the new node's rate: one monotone scalar equation per node,
  ``Viscoplastic.implicit_rate``).  Along the precursor this is the trapezoidal rule
  for its decay law ``d sigma_p/dt = -mu phi``; the error is O(dt^2) (the tests
  measure the order).  With ``tau = 0`` the implicit step is a return mapping onto
  the yield surface (the elastic–plastic limit, first order at the plastic wave);
  with ``tau = inf`` nothing relaxes and the grid is exact.

This is a separate solver from the front-tracking engine (the relaxation of a state
between fronts is what the engine's constant regions cannot carry); its records
are histories at stations, the free-surface velocity and the precursor's amplitude.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from materials.errors import MaterialError
from materials.viscoplastic import Viscoplastic


@dataclass(frozen=True)
class _Front:
    index: int
    direction: int
    ahead: tuple
    behind: tuple


@dataclass(frozen=True)
class ViscoplasticRun:
    """Records of a layer on its characteristic grid (SI units).

    ``dt`` (s) and ``dx`` (m) the grid steps; ``sigma``, ``u``, ``plastic_strain``:
    arrays ``[level, node]`` (NaN where ``i + n`` is odd; on the precursor the state
    behind it); ``precursor_x``, ``precursor_sigma``: the precursor's amplitude
    (stress just behind it) against distance on its first transit.
    """

    material: Viscoplastic
    thickness: float
    dt: float
    dx: float
    sigma: np.ndarray
    u: np.ndarray
    plastic_strain: np.ndarray
    precursor_x: np.ndarray
    precursor_sigma: np.ndarray

    def _column(self, x: float) -> int:
        if not 0.0 <= x <= self.thickness:
            raise MaterialError(f"station x = {x!r} m is outside the layer "
                                f"(0 to {self.thickness!r} m)")
        return int(round(x / self.dx))

    def history(self, x: float, field: str = "u") -> tuple[np.ndarray, np.ndarray]:
        """``(t, value)`` at the node column nearest ``x`` (m): ``field`` is ``"u"``,
        ``"sigma"`` or ``"plastic_strain"``; one value every ``2 dt``."""
        column = self._column(x)
        values = getattr(self, field)[:, column]
        levels = np.nonzero(np.isfinite(values))[0]
        return levels * self.dt, values[levels]

    def free_surface_velocity(self) -> tuple[np.ndarray, np.ndarray]:
        """``(t, u)`` of the free surface (m/s)."""
        return self.history(self.thickness, "u")


def run_layer(material: Viscoplastic, thickness: float, piston_velocity: float,
              t_end: float, cells: int) -> ViscoplasticRun:
    """A layer at rest, struck at ``t = 0`` by a piston at ``piston_velocity`` (m/s) at
    ``X = 0`` and free at ``X = thickness`` (m), integrated to ``t_end`` (s) on a grid of
    ``cells`` intervals (even)."""
    if not (isinstance(cells, int) and cells >= 2 and cells % 2 == 0):
        raise MaterialError(f"cells must be an even integer >= 2, got {cells!r}")
    if not (thickness > 0.0 and math.isfinite(thickness)):
        raise MaterialError(f"thickness must be finite and > 0 m, got {thickness!r}")
    if not (t_end > 0.0 and math.isfinite(t_end)):
        raise MaterialError(f"t_end must be finite and > 0 s, got {t_end!r}")
    return _Grid(material, thickness, float(piston_velocity), cells).run(t_end)


class _Grid:
    """The diamond characteristic lattice and its update rules (module docstring)."""

    def __init__(self, mat: Viscoplastic, thickness: float, u0: float, cells: int):
        self.mat, self.n_cells, self.u0 = mat, cells, u0
        self.dx = thickness / cells
        self.dt = self.dx / mat.C0
        self.thickness = thickness
        self.z = mat.impedance
        self.mu_dt = mat.mu * self.dt

    def _rate(self, sigma, ep):
        """``phi`` of a jump state (0 for tau = 0: a state left beyond the yield surface
        by a jump relaxes at its next node, by the return mapping)."""
        if self.mat.relaxation_time == 0.0:
            return 0.0
        return float(self.mat.rate(self.mat.deviator(sigma, ep)))

    # --- node rules (arrays or floats) -------------------------------------------------
    def interior(self, left, right, below):
        (sl, ul, _, pl), (sr, ur, _, pr), (_, _, eb, pb) = left, right, below
        z, dt, mdt = self.z, self.dt, self.mu_dt
        ap = sl + z * ul - mdt * pl
        am = sr - z * ur - mdt * pr
        base = eb + dt * pb
        phi = self.mat.implicit_rate(0.5 * (ap + am), mdt, base, dt)
        return (0.5 * (ap + am) - mdt * phi, (ap - am) / (2.0 * z), base + dt * phi,
                self._kept(phi))

    def piston(self, right, below):
        (sr, ur, _, pr), (_, _, eb, pb) = right, below
        z, dt, mdt = self.z, self.dt, self.mu_dt
        am = sr - z * ur - mdt * pr
        base = eb + dt * pb
        phi = self.mat.implicit_rate(am + z * self.u0, mdt, base, dt)
        return am + z * self.u0 - mdt * phi, self.u0, base + dt * phi, self._kept(phi)

    def free(self, left, below):
        (sl, ul, _, pl), (_, _, eb, pb) = left, below
        z, dt, mdt = self.z, self.dt, self.mu_dt
        ap = sl + z * ul - mdt * pl
        base = eb + dt * pb
        phi = self.mat.implicit_rate(0.0, 0.0, base, dt)
        return 0.0, (ap - mdt * phi) / z, base + dt * phi, self._kept(phi)

    def behind_front(self, direction: int, along, ahead):
        """State behind a front at a node: the characteristic along the front from the
        previous front node (``along``, its behind side) and the jump from ``ahead``."""
        z, mdt = self.z, self.mu_dt
        s, u, _, p = along
        sa, ua, ea, _ = ahead
        if direction > 0:
            carried, jumped = s + z * u - mdt * p, sa - z * ua      # C+ and sigma - Z u
        else:
            carried, jumped = s - z * u - mdt * p, sa + z * ua      # C- and sigma + Z u
        phi = float(self.mat.implicit_rate(0.5 * (carried + jumped), 0.5 * mdt, ea, 0.0))
        sigma = 0.5 * (carried + jumped) - 0.5 * mdt * phi
        u = direction * (carried - mdt * phi - jumped) / (2.0 * z)
        return sigma, u, ea, self._kept(phi)

    def _kept(self, phi):
        """The rate a node hands on to the next segment.  With ``tau = 0`` none: the
        return mapping's rate is an impulse spent at its node (the trapezoidal rule would
        replay it on the next segment and oscillate; this is backward Euler, first order,
        in the rate-independent limit)."""
        if self.mat.relaxation_time == 0.0:
            return 0.0 * phi
        return phi

    # --- the march ------------------------------------------------------------------------
    def run(self, t_end: float) -> ViscoplasticRun:
        n_cells = self.n_cells
        levels = int(math.ceil(t_end / self.dt - 1e-9)) + 1
        sig = np.full((levels, n_cells + 1), np.nan)
        vel, eps_p, phi = sig.copy(), sig.copy(), sig.copy()
        rest = (0.0, 0.0, 0.0, 0.0)
        even = np.arange(0, n_cells + 1, 2)
        sig[0, even] = vel[0, even] = eps_p[0, even] = phi[0, even] = 0.0
        start = (self.z * self.u0, self.u0, 0.0, self._rate(self.z * self.u0, 0.0))
        fronts = [_Front(0, 1, rest, start)]
        sig[0, 0], vel[0, 0], eps_p[0, 0], phi[0, 0] = start
        fields = (sig, vel, eps_p, phi)
        precursor = [(0.0, start[0])]
        first_transit = True

        def value(m, iq, ip, n):
            """State at node ``iq`` of level ``m`` seen from node ``ip`` of level ``n``."""
            if m < 0:
                return rest
            front = fronts[m]
            if iq == front.index:
                if front.direction > 0:
                    behind = ip - n < front.index - m
                else:
                    behind = ip + n > front.index + m
                return front.behind if behind else front.ahead
            return tuple(f[m, iq] for f in fields)

        for n in range(1, levels):
            nodes = np.arange(n % 2, n_cells + 1, 2)
            inner = nodes[(nodes > 0) & (nodes < n_cells)]
            below = (tuple(f[n - 2, inner] for f in fields) if n >= 2
                     else tuple(np.zeros(inner.size) for _ in fields))
            out = self.interior(tuple(f[n - 1, inner - 1] for f in fields),
                                tuple(f[n - 1, inner + 1] for f in fields), below)
            for f, v in zip(fields, out, strict=True):
                f[n, inner] = v
            old = fronts[n - 1]
            index = old.index + old.direction
            # the boundary nodes, and the nodes reading a front node of level n-1 or n-2
            # (recomputed with the front's side they lie on)
            suspects = {0, n_cells, old.index - 1, old.index + 1, index}
            if n >= 2:
                suspects.add(fronts[n - 2].index)
            fronts.append(None)   # placeholder: the front of this level, set below
            for i in sorted(suspects):
                if i < 0 or i > n_cells or (i + n) % 2:
                    continue
                state = self._node(i, n, value)
                for f, v in zip(fields, state, strict=True):
                    f[n, i] = v
            # the front at level n: ahead from the node rule, behind from the jump
            ahead = tuple(f[n, index] for f in fields)
            prev_behind = old.behind
            behind = self.behind_front(old.direction, prev_behind, ahead)
            direction = old.direction
            if index in (0, n_cells):     # reflection at a boundary: a corner node
                ahead, behind = behind, self._reflect(index, behind)
                direction = -direction
                first_transit = False
            elif first_transit:
                precursor.append((index * self.dx, behind[0]))
            fronts[n] = _Front(index, direction, ahead, behind)
            for f, v in zip(fields, behind, strict=True):
                f[n, index] = v
        self._check_range(sig, eps_p)
        return ViscoplasticRun(self.mat, self.thickness, self.dt, self.dx, sig, vel, eps_p,
                               np.array([p[0] for p in precursor]),
                               np.array([p[1] for p in precursor]))

    def _check_range(self, sigma, plastic_strain) -> None:
        """The model needs the relaxed modulus ``p'(eps)`` below the elastic one ``M``
        (``materials.viscoplastic``); a convex equilibrium pressure leaves that range at
        large compression."""
        mat = self.mat
        eps = np.nanmax(mat.strain(sigma, plastic_strain))
        if not mat.pressure_slope(eps) < mat.modulus:
            raise MaterialError(f"piston velocity {self.u0!r} m/s compresses {mat.name} to "
                                f"eps = {eps:.4g}, where the slope of the equilibrium "
                                f"pressure reaches the elastic modulus M: beyond the range "
                                f"of hugoniot_slope {mat.hugoniot_slope!r}")

    def _node(self, i: int, n: int, value):
        """One node by its rule, its inputs read from the side of the fronts it lies on."""
        below = value(n - 2, i, i, n)
        if i == 0:
            return self.piston(value(n - 1, 1, i, n), below)
        if i == self.n_cells:
            return self.free(value(n - 1, i - 1, i, n), below)
        return tuple(float(v) for v in self.interior(value(n - 1, i - 1, i, n),
                                                    value(n - 1, i + 1, i, n), below))

    def _reflect(self, index: int, incoming):
        """The state a boundary leaves behind the reflected front (exact jump)."""
        s, u, ep, _ = incoming
        if index == self.n_cells:      # free surface: sigma = 0, sigma + Z u continuous
            state = (0.0, u + s / self.z, ep)
        else:                          # piston: u = u0, sigma - Z u continuous
            state = (s + self.z * (self.u0 - u), self.u0, ep)
        return (*state, self._rate(state[0], ep))
