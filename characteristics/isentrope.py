"""Riemann invariants on an isentrope: the tables the method of characteristics reads.

In Lagrangian coordinates the equations of motion of a material whose stress is a
function of volume and entropy,

    rho0 u_t + sigma_X = 0,        sigma_t + rho0 C_L^2 u_X = 0,

(stress positive in compression, ``C_L^2 = -v0^2 (d sigma / d v)_s``) combine into

    (sigma_t + C_L sigma_X) + rho0 C_L (u_t + C_L u_X) = 0    along dX/dt = +C_L,
    (sigma_t - C_L sigma_X) - rho0 C_L (u_t - C_L u_X) = 0    along dX/dt = -C_L.

On one isentrope ``C_L`` is a function of ``sigma`` alone, and with the *stress
function*

    phi(sigma) = int_{sigma*}^{sigma} d sigma' / (rho0 C_L) = -rho0 int_{v*}^{v} C_L dv'   (m/s),

zero at the state ``*`` that labels the isentrope, the two relations integrate to the
Riemann invariants (Davison ch. 8)

    J+ = u + phi    constant along dX/dt = +C_L,
    J- = u - phi    constant along dX/dt = -C_L.

Where two characteristics cross, ``u = (J+ + J-)/2`` and ``phi = (J+ - J-)/2``; the
state then follows from ``phi`` on the isentrope.  The classes here answer exactly
that, for floats (one event) and numpy arrays (a whole lattice):

- ``TabulatedIsentrope``: a material whose isentropes are known pointwise
  (``Material.isentrope_arrays``; Mie–Grüneisen solids).  ``C_L(v)`` is tabulated as
  Chebyshev series on panels of volume, ``phi(v)`` is the series' exact
  antiderivative, and ``v(phi)`` and ``v(sigma)`` are the inverse series; each series
  is converged to rounding, so states are exact to rounding.
- ``IdealGasIsentrope``: the gamma-law gas in closed form, ``phi = 2 (c - c*)/(gamma - 1)``.

``IsentropeTables`` keeps one table per isentrope met in a run, shared by every
region on it.
"""

from __future__ import annotations

import bisect
import math
from abc import ABC, abstractmethod
from dataclasses import dataclass

import numpy as np

from materials import IdealGas, State, StateOutOfRangeError
from materials.base import AffineEnergyMaterial
from materials.wavecurves import SPINODAL_FRACTION

from . import chebyshev

PANEL_FRACTION = 0.05
"""Width of a table panel, as a fraction of the reference volume ``v0`` (5 % strain)."""

MAX_HALVINGS = 10
"""A panel whose series do not converge is halved, at most this many times."""


LABEL_TOLERANCE = 1e-12
"""Two states lie on one isentrope when their stresses at equal volume differ by less
than this fraction of the stress (rounding of the computations that made them)."""

RESOLVED_FRACTION = 1e-4
"""States are read from a table to about ``1e-16 C_L`` in the invariants (the rounding of
the volume, and of the stress through the bulk modulus); a wave whose invariants span
less than this fraction of ``C_L`` would lose more than 1e-12 of its amplitude, and is
left to the wave curves, which take weak jumps from the exact stress jump
(``Isentrope.resolves``; ``materials.wavecurves``)."""

NEWTON_STEPS = 4
"""Newton steps that invert a panel's series: from a linear interpolation of 24
samples the error falls like 1e-5, 1e-10, 1e-20 (quadratic convergence)."""


class Isentrope(ABC):
    """One isentrope of one material: states and characteristic speeds from the invariants.

    ``through`` is the labelling state (``phi = 0`` there).  Methods take floats; the
    ``*_array`` methods take numpy arrays.  A state past the table's range raises
    ``StateOutOfRangeError``.
    """

    material: object
    through: State
    _resolution: float | None = None

    @abstractmethod
    def phi_at_stress(self, sigma: float) -> float:
        """The stress function (m/s) at stress ``sigma`` (Pa)."""

    @abstractmethod
    def volume_at_phi(self, phi: float) -> float:
        """Specific volume (m^3/kg) where the stress function is ``phi`` (m/s)."""

    @abstractmethod
    def arrays_at_phi(self, phi: np.ndarray) -> tuple[np.ndarray, ...]:
        """``(sigma, v, e, C_L)`` at the stress-function values ``phi`` (arrays)."""

    @abstractmethod
    def arrays_at_stress(self, sigma: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """``(phi, C_L)`` at the stresses ``sigma`` (arrays)."""

    @abstractmethod
    def point_at_volume(self, v: float) -> tuple[float, float, float]:
        """``(sigma, e, C_L)`` at volume ``v`` on the isentrope (floats)."""

    @abstractmethod
    def stress_gap(self, state: State) -> float:
        """How far ``state`` lies from this isentrope: the difference (Pa) between its
        stress and the isentrope's at its volume."""

    @abstractmethod
    def rounding(self, state: State) -> float:
        """The stress gap (Pa) below which ``state`` lies on the isentrope to rounding."""

    def matches(self, state: State, tolerance: float = 0.0) -> bool:
        """True when ``state`` lies on this isentrope to rounding, or within ``tolerance``
        (Pa, a stress gap at equal volume the caller neglects)."""
        if not math.isfinite(state.v):
            return False
        return self.stress_gap(state) <= max(self.rounding(state), tolerance)

    # --- built on the above ---------------------------------------------------------
    def covers(self, sigma: float) -> bool:
        """Whether the isentrope reaches stress ``sigma`` (Pa) inside its range (a state
        within the tolerance of another isentrope may lie past this one's end)."""
        try:
            self.phi_at_stress(sigma)
        except StateOutOfRangeError:
            return False
        return True

    def resolves(self, spread: float) -> bool:
        """Whether a wave spanning ``spread`` (m/s) in an invariant is read from the table
        to better than 1e-12 of its amplitude (``RESOLVED_FRACTION``)."""
        if self._resolution is None:
            self._resolution = RESOLVED_FRACTION * self.speed_at_stress(self.through.sigma)
        return spread >= self._resolution

    def invariants(self, state: State) -> tuple[float, float]:
        """``(J+, J-)`` (m/s) of a state on this isentrope."""
        phi = self.phi_at_stress(state.sigma)
        return state.u + phi, state.u - phi

    def state(self, j_plus: float, j_minus: float) -> State:
        """The state whose invariants are ``j_plus`` and ``j_minus``."""
        phi = 0.5 * (j_plus - j_minus)
        v = self.volume_at_phi(phi)
        sigma, e, _ = self.point_at_volume(v)
        return State(sigma=sigma, u=0.5 * (j_plus + j_minus), v=v, e=e)

    def state_at_stress(self, sigma: float, j: float, direction: int) -> State:
        """The state of stress ``sigma`` whose invariant ``J-`` (``direction = +1``: the state
        lies behind a right-going wave) or ``J+`` (``direction = -1``) is ``j``.

        The stress is returned exactly as given (a free surface stays at zero)."""
        phi = self.phi_at_stress(sigma)
        v = self.volume_at_phi(phi)
        _, e, _ = self.point_at_volume(v)
        u = j + phi if direction > 0 else j - phi
        return State(sigma=float(sigma), u=u, v=v, e=e)

    def speed(self, j_plus: float, j_minus: float) -> float:
        """Lagrangian sound speed (m/s) of the state with these invariants."""
        return self.point_at_volume(self.volume_at_phi(0.5 * (j_plus - j_minus)))[2]

    def speed_at_stress(self, sigma: float) -> float:
        """Lagrangian sound speed (m/s) at stress ``sigma`` on this isentrope."""
        return self.point_at_volume(self.volume_at_phi(self.phi_at_stress(sigma)))[2]


# --- Chebyshev tables for a material with pointwise isentropes ------------------------
@dataclass(frozen=True)
class _Panel:
    """One panel ``[v_lo, v_hi]`` of a table: series in ``v`` of ``phi`` and ``C_L``, and the
    inverse series ``v(phi)`` on ``[phi_lo, phi_hi]`` and ``v(sigma)`` on
    ``[sigma_lo, sigma_hi]`` (``phi`` and ``sigma`` fall as ``v`` grows)."""

    v_lo: float
    v_hi: float
    phi: np.ndarray
    c: np.ndarray
    phi_lo: float
    phi_hi: float
    v_of_phi: np.ndarray
    sigma_lo: float
    sigma_hi: float
    v_of_sigma: np.ndarray


class TabulatedIsentrope(Isentrope):
    """The isentrope of ``material`` through ``through``, tabulated on panels of volume.

    Panels of ``PANEL_FRACTION * v0`` are anchored at ``through.v`` and built outward
    when a query first reaches them (halved where a series does not converge to
    rounding), so a table costs only the range a run uses.
    """

    def __init__(self, material: AffineEnergyMaterial, through: State):
        self.material = material
        self.through = through
        self.rho0 = material.rho0
        v_min, v_max = material.volume_range()
        self._limits = [v_min * (1.0 + 1e-9), v_max * (1.0 - 1e-9)]
        self._width = PANEL_FRACTION * material.v0
        c_star = math.sqrt(max(material.sound_speed_squared(through.v, through.e), 0.0))
        self._c_floor = SPINODAL_FRACTION * c_star
        self._closed = [False, False]  # no panel can be added below / above
        self._panels: list[_Panel] = []  # ascending in v
        self._label = material._isentrope_label(through)
        self._extend(upward=True)
        self._refresh()

    # --- construction -------------------------------------------------------------
    def _extend(self, upward: bool) -> None:
        """Add the next base panel above (or below) the table, halved as needed."""
        side = 1 if upward else 0
        if self._closed[side]:
            raise StateOutOfRangeError(self._range_message())
        if not self._panels:
            start, phi_start = self.through.v, 0.0
        elif upward:
            start, phi_start = self._panels[-1].v_hi, self._panels[-1].phi_lo
        else:
            start, phi_start = self._panels[0].v_lo, self._panels[0].phi_hi
        end = start + self._width if upward else start - self._width
        limit = self._limits[side]
        if (end >= limit) if upward else (end <= limit):
            end, self._closed[side] = limit, True
        if upward:
            end = self._spinodal_cut(start, end)
        lo, hi = (start, end) if upward else (end, start)
        new = self._build(lo, hi, phi_start, from_low=upward, depth=0)
        self._panels = self._panels + new if upward else new + self._panels

    def _spinodal_cut(self, start: float, end: float) -> float:
        """``end``, or the volume before it where ``C_L`` falls to the floor (closing the table)."""
        _, _, c2 = self.material.isentrope_arrays(self.through, np.array([end]))
        if c2[0] > self._c_floor**2:
            return end
        lo, hi = start, end
        for _ in range(60):
            mid = 0.5 * (lo + hi)
            c2 = self.material.isentrope_arrays(self.through, np.array([mid]))[2][0]
            lo, hi = (mid, hi) if c2 > self._c_floor**2 else (lo, mid)
        self._closed[1] = True
        return lo

    def _build(self, lo: float, hi: float, phi_known: float, from_low: bool,
               depth: int) -> list[_Panel]:
        """Panels covering ``[lo, hi]``; ``phi_known`` is ``phi`` at ``lo`` if ``from_low``
        else at ``hi``."""
        v = chebyshev.points(lo, hi)
        sigma, _, c2 = self.material.isentrope_arrays(self.through, v)
        c = np.sqrt(np.maximum(c2, 0.0))
        c_coefs = chebyshev.coefficients(c)
        sigma_coefs = chebyshev.coefficients(sigma)
        converged = (chebyshev.converged(c_coefs, float(np.max(c)))
                     and chebyshev.converged(sigma_coefs, float(np.max(np.abs(sigma)))))
        if not converged and depth < MAX_HALVINGS:
            mid = 0.5 * (lo + hi)
            if from_low:
                first = self._build(lo, mid, phi_known, True, depth + 1)
                return first + self._build(mid, hi, first[-1].phi_lo, True, depth + 1)
            second = self._build(mid, hi, phi_known, False, depth + 1)
            return self._build(lo, mid, second[0].phi_hi, False, depth + 1) + second
        phi_coefs = -self.rho0 * chebyshev.antiderivative(c_coefs, lo, hi)
        if from_low:
            phi_coefs[0] += phi_known
        else:
            phi_coefs[0] += phi_known - chebyshev.evaluate(phi_coefs.tolist(), lo, hi, hi)
        phi_lo = chebyshev.evaluate(phi_coefs.tolist(), lo, hi, hi)
        phi_hi = chebyshev.evaluate(phi_coefs.tolist(), lo, hi, lo)
        phi_samples = chebyshev.values(phi_coefs, lo, hi, v)
        v_of_phi = _inverse(phi_coefs, -self.rho0 * c_coefs, v, phi_samples, lo, hi)
        # the stress series' own end values keep v(sigma) consistent with it
        sigma_lo = chebyshev.evaluate(sigma_coefs.tolist(), lo, hi, hi)
        sigma_hi = chebyshev.evaluate(sigma_coefs.tolist(), lo, hi, lo)
        v_of_sigma = _inverse(sigma_coefs, chebyshev.derivative(sigma_coefs, lo, hi), v,
                              sigma, lo, hi)
        return [_Panel(lo, hi, phi_coefs, c_coefs, phi_lo, phi_hi, v_of_phi, sigma_lo,
                       sigma_hi, v_of_sigma)]

    def _refresh(self) -> None:
        """The sorted edges used to find a panel."""
        panels = self._panels
        self._v_edges = [p.v_lo for p in panels] + [panels[-1].v_hi]
        self._phi_keys = [-p.phi_hi for p in panels] + [-panels[-1].phi_lo]
        self._sigma_keys = [-p.sigma_hi for p in panels] + [-panels[-1].sigma_lo]
        self._phi_lists = [(p.v_of_phi.tolist(), p.phi_lo, p.phi_hi) for p in panels]
        self._sigma_lists = [(p.v_of_sigma.tolist(), p.sigma_lo, p.sigma_hi) for p in panels]
        self._stack = self._stress_stack = None

    def _range_message(self) -> str:
        lo, hi = self._limits
        return (f"{self.material.name}: the isentrope through {self.through.sigma / 1e9:.6g} GPa "
                f"leaves the range of its equation of state (densities {1.0 / hi:.6g} to "
                f"{1.0 / lo:.6g} kg/m3, or a sound speed below {SPINODAL_FRACTION:g} of its "
                f"value there)")

    # --- queries ------------------------------------------------------------------
    def _index_by_phi(self, phi: float) -> int:
        while -phi < self._phi_keys[0] or -phi > self._phi_keys[-1]:
            self._extend(upward=-phi > self._phi_keys[-1])
            self._refresh()
        return min(max(bisect.bisect_right(self._phi_keys, -phi) - 1, 0), len(self._panels) - 1)

    def _index_by_sigma(self, sigma: float) -> int:
        while -sigma < self._sigma_keys[0] or -sigma > self._sigma_keys[-1]:
            self._extend(upward=-sigma > self._sigma_keys[-1])
            self._refresh()
        return min(max(bisect.bisect_right(self._sigma_keys, -sigma) - 1, 0),
                   len(self._panels) - 1)

    def volume_at_phi(self, phi: float) -> float:
        index = self._index_by_phi(phi)  # may extend the table (and renew the lists)
        coefs, lo, hi = self._phi_lists[index]
        return chebyshev.evaluate(coefs, lo, hi, phi)

    def volume_at_stress(self, sigma: float) -> float:
        """Specific volume (m^3/kg) at stress ``sigma`` (Pa) on this isentrope."""
        if sigma == self.through.sigma:
            return self.through.v
        index = self._index_by_sigma(sigma)
        coefs, lo, hi = self._sigma_lists[index]
        return chebyshev.evaluate(coefs, lo, hi, sigma)

    def phi_at_volume(self, v: float) -> float:
        """The stress function (m/s) at volume ``v``."""
        while v < self._v_edges[0] or v > self._v_edges[-1]:
            self._extend(upward=v > self._v_edges[-1])
            self._refresh()
        i = min(max(bisect.bisect_right(self._v_edges, v) - 1, 0), len(self._panels) - 1)
        p = self._panels[i]
        return chebyshev.evaluate(p.phi.tolist(), p.v_lo, p.v_hi, v)

    def phi_at_stress(self, sigma: float) -> float:
        if sigma == self.through.sigma:
            return 0.0
        return self.phi_at_volume(self.volume_at_stress(sigma))

    def point_at_volume(self, v: float) -> tuple[float, float, float]:
        mat = self.material
        e = (self._label - mat._f(v)) / mat._energy_factor(v)
        sigma = float(mat._a(v) + mat._b(v) * e)
        c2 = mat.sound_speed_squared(v, e)
        return sigma, float(e), math.sqrt(c2) if c2 > 0.0 else 0.0

    def arrays_at_phi(self, phi: np.ndarray) -> tuple[np.ndarray, ...]:
        phi = np.asarray(phi, dtype=float)
        if phi.size:
            self._index_by_phi(float(np.max(phi)))
            self._index_by_phi(float(np.min(phi)))
        if self._stack is None:
            panels = self._panels
            self._stack = (np.array(self._phi_keys), np.array([p.v_of_phi for p in panels]),
                           np.array([p.phi_lo for p in panels]),
                           np.array([p.phi_hi for p in panels]))
        keys, coefs, lo, hi = self._stack
        index = np.clip(np.searchsorted(keys, -phi, side="right") - 1, 0, len(lo) - 1)
        v = chebyshev.evaluate_many(coefs[index], lo[index], hi[index], phi)
        sigma, e, c2 = self.material.isentrope_arrays(self.through, v)
        return sigma, v, e, np.sqrt(np.maximum(c2, 0.0))

    def arrays_at_stress(self, sigma: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        sigma = np.asarray(sigma, dtype=float)
        if sigma.size:
            self._index_by_sigma(float(np.max(sigma)))
            self._index_by_sigma(float(np.min(sigma)))
        if self._stress_stack is None:
            self._stress_stack = self._stacked_by_stress()
        keys, coefs, lo, hi, v_edges, phi_coefs, c_coefs = self._stress_stack
        last = len(lo) - 1
        index = np.clip(np.searchsorted(keys, -sigma, side="right") - 1, 0, last)
        v = chebyshev.evaluate_many(coefs[index], lo[index], hi[index], sigma)
        vi = np.clip(np.searchsorted(v_edges, v, side="right") - 1, 0, last)
        phi = chebyshev.evaluate_many(phi_coefs[vi], v_edges[vi], v_edges[vi + 1], v)
        c = chebyshev.evaluate_many(c_coefs[vi], v_edges[vi], v_edges[vi + 1], v)
        return phi, c

    def _stacked_by_stress(self) -> tuple[np.ndarray, ...]:
        """The panels' series as arrays for ``arrays_at_stress`` (zero-padded)."""
        panels = self._panels

        def padded(name):
            width = max(len(getattr(p, name)) for p in panels)
            out = np.zeros((len(panels), width))
            for i, p in enumerate(panels):
                out[i, :len(getattr(p, name))] = getattr(p, name)
            return out

        return (np.array(self._sigma_keys), padded("v_of_sigma"),
                np.array([p.sigma_lo for p in panels]), np.array([p.sigma_hi for p in panels]),
                np.array(self._v_edges), padded("phi"), padded("c"))

    @staticmethod
    def labels(material, state: State, tolerance: float = 0.0) -> tuple[float, float] | None:
        """The isentrope label ``K`` of ``state`` and the width in ``K`` within which a
        label's isentrope passes within ``tolerance`` (Pa, at least the rounding) of it."""
        label = material._isentrope_label(state)
        b = abs(float(material._b(state.v)))
        if b == 0.0:
            return label, 0.0
        stress = max(_mg_rounding(material, state), tolerance)
        return label, stress * material._energy_factor(state.v) / b

    def stress_gap(self, state: State) -> float:
        mat = self.material
        label = mat._isentrope_label(state)
        return abs(label - self._label) * abs(float(mat._b(state.v))) / mat._energy_factor(
            state.v)

    def rounding(self, state: State) -> float:
        return _mg_rounding(self.material, state)


def _mg_rounding(material, state: State) -> float:
    """``LABEL_TOLERANCE`` of the stress, or of a millionth of the bulk modulus near zero."""
    c2 = material.sound_speed_squared(state.v, state.e)
    return LABEL_TOLERANCE * max(abs(state.sigma), 1e-6 * material.rho0 * abs(c2))


class IdealGasIsentrope(Isentrope):
    """``p v^gamma`` constant: ``c = c* (p/p*)^((gamma-1)/(2 gamma))``,
    ``phi = 2 (c - c*)/(gamma - 1)``, ``C_L = (v0/v) c``; vacuum where ``c = 0``."""

    def __init__(self, material: IdealGas, through: State):
        self.material = material
        self.through = through
        self.gamma = material.gamma
        self._c_star = material.eulerian_sound_speed(through.v, through.e)
        self._p_star = through.sigma
        self._exponent = (self.gamma - 1.0) / (2.0 * self.gamma)

    def _sound(self, phi):
        return np.maximum(self._c_star + 0.5 * (self.gamma - 1.0) * phi, 0.0)

    def phi_at_stress(self, sigma: float) -> float:
        if sigma < 0.0:
            raise StateOutOfRangeError(f"{self.material.name}: a gas carries no tension "
                                       f"({sigma / 1e9:.6g} GPa asked)")
        c = self._c_star * (sigma / self._p_star) ** self._exponent
        return 2.0 * (c - self._c_star) / (self.gamma - 1.0)

    def volume_at_phi(self, phi: float) -> float:
        c = float(self._sound(phi))
        if c <= 0.0:
            return math.inf
        return self.through.v * (self._c_star / c) ** (2.0 / (self.gamma - 1.0))

    def point_at_volume(self, v: float) -> tuple[float, float, float]:
        if math.isinf(v):
            return 0.0, 0.0, 0.0
        sigma, e, c2 = self.material.isentrope_arrays(self.through, np.array([v]))
        return float(sigma[0]), float(e[0]), math.sqrt(max(float(c2[0]), 0.0))

    def arrays_at_stress(self, sigma: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        sigma = np.asarray(sigma, dtype=float)
        if np.any(sigma < 0.0):
            raise StateOutOfRangeError(f"{self.material.name}: a gas carries no tension")
        c = self._c_star * (sigma / self._p_star) ** self._exponent
        phi = 2.0 * (c - self._c_star) / (self.gamma - 1.0)
        return phi, self.arrays_at_phi(phi)[3]

    def arrays_at_phi(self, phi: np.ndarray) -> tuple[np.ndarray, ...]:
        c = self._sound(np.asarray(phi, dtype=float))
        with np.errstate(divide="ignore"):
            v = np.where(c > 0.0, self.through.v * (self._c_star / np.where(c > 0.0, c, 1.0))
                         ** (2.0 / (self.gamma - 1.0)), np.inf)
        ratio = np.where(np.isfinite(v), self.through.v / np.where(np.isfinite(v), v, 1.0), 0.0)
        e = self.through.e * ratio ** (self.gamma - 1.0)
        sigma = (self.gamma - 1.0) * e * ratio / self.through.v
        c_l = self.material.v0 * ratio / self.through.v * c
        return sigma, v, e, c_l

    @staticmethod
    def labels(material, state: State, tolerance: float = 0.0) -> tuple[float, float] | None:
        """The label ``p v^gamma`` of ``state`` and its window; ``None`` for a cold gas."""
        if not state.sigma > 0.0:
            return None
        label = state.sigma * state.v**material.gamma
        return label, max(LABEL_TOLERANCE * label, tolerance * state.v**material.gamma)

    def stress_gap(self, state: State) -> float:
        if not state.sigma > 0.0:
            return math.inf
        mine = self._p_star * (self.through.v / state.v) ** self.gamma
        return abs(mine - state.sigma)

    def rounding(self, state: State) -> float:
        return LABEL_TOLERANCE * abs(state.sigma)


def _inverse(coefs: np.ndarray, slope: np.ndarray, v: np.ndarray, samples: np.ndarray,
             lo: float, hi: float) -> np.ndarray:
    """Chebyshev series of ``v(y)`` on ``[y(hi), y(lo)]`` for the decreasing series
    ``y(v) = coefs`` on ``[lo, hi]`` (``slope`` its derivative's series), known at the
    Chebyshev points ``v`` as ``samples``: Newton's method on the series from a linear
    interpolation of the samples."""
    y_lo = chebyshev.evaluate(coefs.tolist(), lo, hi, hi)
    y_hi = chebyshev.evaluate(coefs.tolist(), lo, hi, lo)
    targets = chebyshev.points(y_lo, y_hi)
    ascending = samples[0] < samples[-1]
    guess = (np.interp(targets, samples, v) if ascending
             else np.interp(targets, samples[::-1], v[::-1]))
    for _ in range(NEWTON_STEPS):
        guess = np.clip(guess - (chebyshev.values(coefs, lo, hi, guess) - targets)
                        / chebyshev.values(slope, lo, hi, guess), lo, hi)
    return chebyshev.coefficients(guess)


def _kind(material):
    """The table class for a material, or ``None`` if its simple waves have no isentrope
    table (linear elastic and elastic–plastic solids, whose waves are discontinuities
    or follow branches the state does not tell)."""
    if not getattr(material, "makes_fans", False):
        return None
    if isinstance(material, IdealGas):
        return IdealGasIsentrope
    if isinstance(material, AffineEnergyMaterial) and not getattr(material, "is_linear", False):
        return TabulatedIsentrope
    return None


def isentrope_for(material, state: State) -> Isentrope | None:
    """A table of the isentrope of ``material`` through ``state``, or ``None`` (a material
    without tables, a vacuum, a cold gas, a state outside the equation of state)."""
    kind = _kind(material)
    if kind is None or not math.isfinite(state.v) or not kind.labels(material, state):
        return None
    try:
        return kind(material, state)
    except StateOutOfRangeError:
        return None


class IsentropeTables:
    """The isentropes of one run, one table per isentrope, shared by every region on it.

    Tables are indexed per material by their label (an invariant of the isentrope:
    ``K = e E(v) + F(v)`` for a Mie–Grüneisen solid, ``p v^gamma`` for a gas), so finding
    the table of a state is a bisection, however many isentropes a run meets.  States
    whose stress lies within ``tolerance`` (Pa) of a table's isentrope at their volume
    share it: an entropy difference that small reflects nothing the run resolves (the
    same rule by which the engine neglects entropy contacts).
    """

    def __init__(self, tolerance: float = 0.0):
        self.tolerance = tolerance
        self._labels: dict[int, list[float]] = {}
        self._tables: dict[int, list[Isentrope]] = {}
        self.built = 0

    def table(self, material, state: State, build: bool = True) -> Isentrope | None:
        """The table through ``state``: the nearest existing one within the tolerance,
        else a new one (``build``) or ``None``."""
        kind = _kind(material)
        if kind is None or not math.isfinite(state.v):
            return None
        window = kind.labels(material, state, self.tolerance)
        if window is None:
            return None
        label, width = window
        labels = self._labels.setdefault(id(material), [])
        tables = self._tables.setdefault(id(material), [])
        lo = bisect.bisect_left(labels, label - width)
        hi = bisect.bisect_right(labels, label + width)
        # a state near the end of the range may lie within the tolerance of an
        # isentrope that ends before its stress: that table is not its own
        near = [t for t in tables[lo:hi] if t.material is material
                and t.matches(state, self.tolerance) and t.covers(state.sigma)]
        if near:
            return min(near, key=lambda t: t.stress_gap(state))
        if not build:
            return None
        table = isentrope_for(material, state)
        if table is not None:
            at = bisect.bisect_left(labels, label)
            labels.insert(at, label)
            tables.insert(at, table)
            self.built += 1
        return table
