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
  conditions: at ``X = 0`` a piston at constant velocity or an elastic flyer (exact
  as a delay line, ``ElasticFlyer``; its round trip rounded to a whole number of
  boundary steps ``2 dt``, an error below ``dt`` in the arrival of its release, which
  then runs along a grid line), at the other end a free surface or a semi-infinite
  elastic window (``sigma = Z_w u``);
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
    (stress just behind it) against distance on its first transit; ``round_trip`` (s)
    the flyer's round trip as the grid represents it (``None`` for a piston).
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
    round_trip: float | None = None

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


@dataclass(frozen=True)
class ElasticFlyer:
    """A linear elastic flyer plate striking the layer's left face at ``t = 0``.

    ``impedance`` ``rho0 C`` (kg/(m^2 s)) and ``round_trip`` ``2 d / C`` (s) of the flyer,
    its ``velocity`` (m/s), and whether the contact is ``bonded`` (else it opens under
    tension and the face is free from then on).  The flyer carries no relaxation, so its
    waves are exact and it acts on the layer as a delay line: the characteristic
    ``sigma + Z_f u`` arriving at the contact at ``t`` is ``Z_f V`` before the first round
    trip and ``-(sigma - Z_f u)`` of the contact at ``t - 2 d / C`` after it (its free rear
    face reverses the stress).
    """

    impedance: float
    round_trip: float
    velocity: float
    bonded: bool = False


def run_layer(material: Viscoplastic, thickness: float, piston_velocity: float,
              t_end: float, cells: int, window_impedance: float = 0.0) -> ViscoplasticRun:
    """A layer at rest, struck at ``t = 0`` by a piston at ``piston_velocity`` (m/s) at
    ``X = 0``, its right face at ``X = thickness`` (m) free or on a semi-infinite elastic
    window of ``window_impedance`` (kg/(m^2 s), 0: free), integrated to ``t_end`` (s) on a
    grid of ``cells`` intervals (even)."""
    _check_grid(thickness, t_end, cells, window_impedance)
    return _Grid(material, thickness, cells, float(piston_velocity), None,
                 window_impedance).run(t_end)


def run_impact(material: Viscoplastic, thickness: float, flyer: ElasticFlyer, t_end: float,
               cells: int, window_impedance: float = 0.0) -> ViscoplasticRun:
    """As ``run_layer``, the left face struck by an elastic ``flyer`` instead of a piston.

    The flyer's round trip is represented by a whole number of the grid's boundary steps
    ``2 dt``; ``ViscoplasticRun.round_trip`` is the one used (within ``dt`` of the flyer's).
    """
    _check_grid(thickness, t_end, cells, window_impedance)
    if not (flyer.impedance > 0.0 and math.isfinite(flyer.impedance)):
        raise MaterialError(f"flyer impedance must be finite and > 0, got {flyer.impedance!r}")
    if not flyer.round_trip > 0.0:
        raise MaterialError(f"flyer round trip must be > 0 s, got {flyer.round_trip!r}")
    return _Grid(material, thickness, cells, float(flyer.velocity), flyer,
                 window_impedance).run(t_end)


def _check_grid(thickness: float, t_end: float, cells: int, window_impedance: float) -> None:
    if not (isinstance(cells, int) and cells >= 2 and cells % 2 == 0):
        raise MaterialError(f"cells must be an even integer >= 2, got {cells!r}")
    if not (thickness > 0.0 and math.isfinite(thickness)):
        raise MaterialError(f"thickness must be finite and > 0 m, got {thickness!r}")
    if not (t_end > 0.0 and math.isfinite(t_end)):
        raise MaterialError(f"t_end must be finite and > 0 s, got {t_end!r}")
    if not (window_impedance >= 0.0 and math.isfinite(window_impedance)):
        raise MaterialError(f"window impedance must be finite and >= 0, "
                            f"got {window_impedance!r}")


class _Grid:
    """The diamond characteristic lattice and its update rules (module docstring)."""

    def __init__(self, mat: Viscoplastic, thickness: float, cells: int, u0: float,
                 flyer: ElasticFlyer | None, window_impedance: float):
        self.mat, self.n_cells, self.u0, self.flyer = mat, cells, u0, flyer
        self.dx = thickness / cells
        self.dt = self.dx / mat.C0
        self.thickness = thickness
        self.z = mat.impedance
        self.zw = window_impedance
        self.mu_dt = mat.mu * self.dt
        # the flyer: its round trip in boundary steps (2 dt), the outgoing characteristic
        # sigma - Z_f u of the contact at each even level, and whether it has separated
        self.trip = (0 if flyer is None
                     else max(1, int(round(flyer.round_trip / (2.0 * self.dt)))))
        self.outgoing: dict[int, float] = {}
        self.separated = False

    def _start(self):
        """Contact state at ``t = 0+``: the piston's velocity, or the elastic impedance
        match of the flyer (``u = Z_f V / (Z_f + Z)``), behind the precursor ``sigma = Z u``."""
        u = self.u0
        if self.flyer is not None:
            zf = self.flyer.impedance
            u = zf * self.u0 / (zf + self.z)
            self.outgoing[0] = self.z * u - zf * u
        return self.z * u, u

    def _incoming(self, n: int) -> float:
        """``sigma + Z_f u`` arriving at the contact from the flyer at level ``n``."""
        if n < 2 * self.trip:
            return self.flyer.impedance * self.u0
        return -self.outgoing[n - 2 * self.trip]

    def _left_face(self, n: int, c_minus: float):
        """``(sigma0, ks, u_of)`` of the left face at level ``n``: its stress is ``sigma0 -
        ks phi`` and ``u_of(sigma, phi)`` its velocity, given the C- value ``c_minus``
        (before the new node's relaxation term ``-mdt phi``)."""
        z, mdt = self.z, self.mu_dt
        if self.flyer is None:
            return c_minus + z * self.u0, mdt, lambda sigma, phi: self.u0
        if self.separated:
            return 0.0, 0.0, lambda sigma, phi: (sigma - c_minus + mdt * phi) / z
        zf, a = self.flyer.impedance, self._incoming(n)
        return ((z * a + zf * c_minus) / (z + zf), zf * mdt / (z + zf),
                lambda sigma, phi: (a - sigma) / zf)

    def _contact(self, n: int, sigma: float, u: float) -> bool:
        """Record the flyer's outgoing characteristic at level ``n``; ``True`` if an
        unbonded contact has just opened under tension (then redo the node as free)."""
        if self.flyer is None or self.separated:
            return False
        if sigma < 0.0 and not self.flyer.bonded:
            self.separated = True
            return True
        self.outgoing[n] = sigma - self.flyer.impedance * u
        return False

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

    def left(self, n, right, below):
        """The left face (piston or flyer contact) at level ``n``."""
        (sr, ur, _, pr), (_, _, eb, pb) = right, below
        dt, mdt = self.dt, self.mu_dt
        base = eb + dt * pb
        while True:
            sigma0, ks, u_of = self._left_face(n, sr - self.z * ur - mdt * pr)
            phi = float(self.mat.implicit_rate(sigma0, ks, base, dt))
            sigma = sigma0 - ks * phi
            u = u_of(sigma, phi)
            if not self._contact(n, sigma, u):
                return sigma, u, base + dt * phi, self._kept(phi)

    def right(self, left, below):
        """The right face: free (``Z_w = 0``) or on the window, ``sigma = Z_w u``."""
        (sl, ul, _, pl), (_, _, eb, pb) = left, below
        z, zw, dt, mdt = self.z, self.zw, self.dt, self.mu_dt
        ap = sl + z * ul - mdt * pl
        base = eb + dt * pb
        phi = self.mat.implicit_rate(zw * ap / (z + zw), zw * mdt / (z + zw), base, dt)
        u = (ap - mdt * phi) / (z + zw)
        return zw * u, u, base + dt * phi, self._kept(phi)

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
        sigma_start, u_start = self._start()
        start = (sigma_start, u_start, 0.0, self._rate(sigma_start, 0.0))
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
                ahead, behind = behind, self._reflect(index, n, behind)
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
                               np.array([p[1] for p in precursor]),
                               2.0 * self.trip * self.dt if self.flyer else None)

    def _check_range(self, sigma, plastic_strain) -> None:
        """The model needs the relaxed modulus ``p'(eps)`` below the elastic one ``M``
        (``materials.viscoplastic``); a convex equilibrium pressure leaves that range at
        large compression."""
        mat = self.mat
        eps = np.nanmax(mat.strain(sigma, plastic_strain))
        if not mat.pressure_slope(eps) < mat.modulus:
            raise MaterialError(f"impact velocity {self.u0!r} m/s compresses {mat.name} to "
                                f"eps = {eps:.4g}, where the slope of the equilibrium "
                                f"pressure reaches the elastic modulus M: beyond the range "
                                f"of hugoniot_slope {mat.hugoniot_slope!r}")

    def _node(self, i: int, n: int, value):
        """One node by its rule, its inputs read from the side of the fronts it lies on."""
        below = value(n - 2, i, i, n)
        if i == 0:
            return self.left(n, value(n - 1, 1, i, n), below)
        if i == self.n_cells:
            return self.right(value(n - 1, i - 1, i, n), below)
        return tuple(float(v) for v in self.interior(value(n - 1, i - 1, i, n),
                                                    value(n - 1, i + 1, i, n), below))

    def _reflect(self, index: int, n: int, incoming):
        """The state a boundary leaves behind the reflected front at level ``n`` (exact
        jump: the characteristic the front carries is continuous across it)."""
        s, u, ep, _ = incoming
        if index == self.n_cells:      # sigma + Z u continuous, sigma = Z_w u
            u_new = (s + self.z * u) / (self.z + self.zw)
            state = (self.zw * u_new, u_new, ep)
        else:                          # sigma - Z u continuous, the left face's condition
            while True:
                sigma0, _, u_of = self._left_face(n, s - self.z * u)
                state = (sigma0, u_of(sigma0, 0.0), ep)
                if not self._contact(n, *state[:2]):
                    break
        return (*state, self._rate(state[0], ep))
