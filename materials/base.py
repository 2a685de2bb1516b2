"""The equation-of-state interface every material implements.

A material answers thermodynamic questions about uniform states: the stress
``sigma(v, e)``, the Lagrangian sound speed ``C_L``, the Hugoniot centred on any
state, and the isentrope through any state with its Riemann-invariant integral.
Wave curves (``materials.wavecurves``) are built from these answers and the
Riemann solver only ever talks to wave curves.

Most solid and gas models in the book have a stress that is *affine in energy*,

    sigma(v, e) = A(v) + B(v) e,        B = (d sigma / d e)_v = Gamma / v,

(Mie–Grüneisen: ``B = rho0 Gamma0``; ideal gas: ``B = (gamma - 1)/v``; a linear
elastic solid: ``B = 0``).  For such a material the Rankine–Hugoniot energy
equation centred on a state ``a``,

    e - e_a = 1/2 (sigma_a + sigma(v, e)) (v_a - v),

is linear in ``e`` and solves in closed form:

    e_H(v) = [e_a + 1/2 (sigma_a + A(v)) (v_a - v)] / [1 - 1/2 B(v) (v_a - v)].

Along an isentrope ``de/dv = -sigma(v, e)``, so ``(d sigma/dv)_s = A' + B' e - B sigma``
and ``C_L^2 = -v0^2 (d sigma/dv)_s``.  ``AffineEnergyMaterial`` implements all of
this from the three functions ``A``, ``A'`` and ``B`` (with ``B'``).
"""

from __future__ import annotations

import bisect
import functools
import math
from abc import ABC, abstractmethod

import numpy as np

from .errors import MaterialError, StateOutOfRangeError, WavediagramError
from .quadrature import (
    UNIT_NODES,
    UNIT_WEIGHTS,
    panel_edges,
    points_for,
    unit_rule,
    unit_rule_lists,
)
from .state import RIGHT, State

_CHEB_POINTS = 20
"""Chebyshev points per panel for the tabulated isentrope function ``F``."""

_SCALAR_RULE_POINTS = 8
"""Quadrature rules up to this many points are evaluated with floats, not arrays."""


def _clenshaw(series: tuple[float, tuple[float, ...]], x: float) -> float:
    """Chebyshev series ``sum c_k T_k(x)`` at a float ``x`` (Clenshaw recurrence);
    ``series`` is ``(c_0, (c_n, ..., c_1))``, the tail stored in the order it is used.
    ``2 x`` is formed once (exact: the same products as ``2.0 * x * b1``), as this runs
    about a million times in a run of finite-plastic layers."""
    first, tail = series
    x2 = 2.0 * x
    b1 = b2 = 0.0
    for c in tail:
        b1, b2 = x2 * b1 - b2 + c, b1
    return x * b1 - b2 + first

ROOM_TEMPERATURE = 298.15
"""Temperature (K) of the unstressed reference state."""


def require_number(name: str, value: float, what: str) -> float:
    """Return ``value`` as a float, or raise ``MaterialError`` naming ``name`` if it is not one."""
    try:
        return float(value)
    except (TypeError, ValueError) as exc:
        raise MaterialError(f"{what}: {name} must be a number, got {value!r}") from exc


def require_positive(name: str, value: float, what: str) -> float:
    """Return ``value`` as a float if it is finite and > 0, else raise ``MaterialError``."""
    try:
        number = float(value)
    except (TypeError, ValueError) as exc:
        raise MaterialError(f"{what}: {name} must be a number, got {value!r}") from exc
    if not math.isfinite(number) or number <= 0.0:
        raise MaterialError(f"{what}: {name} must be finite and > 0, got {value!r}")
    return number


VOLUME_SECANT_STEPS = 40
"""Most secant steps of ``Material.volume_at`` (a change of energy at fixed stress moves
the volume by a small fraction: a few steps; a gas whose energy halves, a dozen)."""

class Material(ABC):
    """A material's equation of state and the wave curves it induces.

    Attributes: ``name``; ``rho0`` reference density (kg/m^3); ``spall_strength``
    the tension (Pa, positive number) at which it fractures, ``math.inf`` if it
    never does.
    """

    name: str
    rho0: float
    spall_strength: float = math.inf
    makes_fans: bool = True
    """Whether isentropic release (or compression) in this model is a centred fan;
    ``False`` for models whose every wave is a discontinuity."""
    splits_waves: bool = False
    """Whether one wave of this model can split into several (an elastic precursor
    and a plastic wave): such solids multiply waves at every interaction."""
    linear_branches: bool = False
    """Whether every wave of one family on one branch moves at one speed (stress linear
    in strain on each branch): trains of such waves are coalesced
    (``fronttrack.coalesce``)."""
    gaseous: bool = False
    """Whether this is a gas (ideal gas, detonation products): its stress vanishes with its
    energy and it carries no tension, so a release to zero stress must end where its
    energy does (``HydrodynamicWaveCurve._volume``), not at a rounding offset from it."""

    @functools.cached_property
    def v0(self) -> float:
        """Reference specific volume (m^3/kg)."""
        return 1.0 / self.rho0

    # --- equation of state -------------------------------------------------
    @abstractmethod
    def stress(self, v: float, e: float) -> float:
        """Longitudinal stress (Pa, compression positive) at volume ``v`` and energy ``e``."""

    def stress_with_history(self, history: State, v: float, e: float) -> float:
        """Stress (Pa) at ``(v, e)`` of a point with the history variables of ``history``
        (a porous body's distension); ``stress(v, e)`` for a material without any."""
        return self.stress(v, e)

    def volume_at(self, near: State, sigma: float, e: float, tolerance: float
                  ) -> float | None:
        """The specific volume (m^3/kg) near ``near.v`` at which a point with ``near``'s
        history (``stress_with_history``) has stress ``sigma`` (Pa) at specific internal
        energy ``e`` (J/kg), to ``tolerance`` (Pa), by secant steps; ``None`` where they
        do not find it (no such state near, or one outside ``volume_range``).  Used where
        energy moves at a fixed stress: a layer's limit state, a fragment's rest state,
        the cell behind a ray that carries its jump's energy."""
        v_min, v_max = self.volume_range()

        def residual(v):
            if not v_min < v < v_max:
                return math.nan
            try:
                return self.stress_with_history(near, v, e) - sigma
            except (WavediagramError, ValueError):
                return math.nan

        v0, f0 = near.v, residual(near.v)
        if abs(f0) <= tolerance:
            return v0
        v1 = v0 * (1.0 - 1e-7)
        f1 = residual(v1)
        for _ in range(VOLUME_SECANT_STEPS):
            if not math.isfinite(f0 + f1) or f1 == f0:
                return None
            v0, f0, v1 = v1, f1, v1 - f1 * (v1 - v0) / (f1 - f0)
            f1 = residual(v1)
            if abs(f1) <= tolerance:
                return v1
        return None

    @abstractmethod
    def sound_speed(self, v: float, e: float) -> float:
        """Lagrangian isentropic sound speed ``C_L = v0 sqrt(-(d sigma/dv)_s)`` (m/s)."""

    @abstractmethod
    def volume_range(self) -> tuple[float, float]:
        """Open interval of specific volume in which the model is valid."""

    def temperature(self, v: float, e: float) -> float | None:
        """Temperature (K), or ``None`` when the model has no specific heat."""
        return None

    def reference_state(self, u: float = 0.0) -> State:
        """The unstressed reference state (``v = v0``, ``e = 0``) moving at ``u``."""
        return State(sigma=self.stress(self.v0, 0.0), u=u, v=self.v0, e=0.0)

    def initial_state(self, stress: float = 0.0, u: float = 0.0) -> State:
        """A layer's initial state at ``stress`` (Pa) moving at ``u`` (m/s).

        A solid starts unstressed at its reference state; a prestressed solid reaches
        its stress along its wave curve from there (a shock if compressive, the
        isentrope if tensile), as a specimen loaded uniaxially would.
        """
        state = self.reference_state()
        if stress != 0.0:
            state = self.wave_curve(state, RIGHT).state_at(stress)
        return state.moving(u)

    def state(self, v: float, e: float, u: float = 0.0) -> State:
        """The state at ``(v, e)`` moving at ``u``, checked against the model's range."""
        self.check_volume(v)
        return State(sigma=self.stress(v, e), u=u, v=v, e=e)

    def check_volume(self, v: float) -> None:
        """Raise ``StateOutOfRangeError`` if ``v`` is outside the model's range."""
        v_min, v_max = self.volume_range()
        if not v_min < v < v_max:
            raise StateOutOfRangeError(
                f"{self.name}: density {1.0 / v:.6g} kg/m3 is outside the range of its "
                f"equation of state ({1.0 / v_max:.6g} to {1.0 / v_min:.6g} kg/m3)"
            )

    # --- Hugoniot and isentrope ---------------------------------------------
    @abstractmethod
    def hugoniot(self, ahead: State, v: float) -> tuple[float, float, float]:
        """Point of the Hugoniot centred on ``ahead`` at volume ``v``: ``(sigma, e, dsigma/dv)``."""

    @abstractmethod
    def hugoniot_volume_limit(self, ahead: State) -> float:
        """Smallest volume the Hugoniot centred on ``ahead`` reaches inside the model's range."""

    @abstractmethod
    def isentrope(self, through: State, v: float) -> tuple[float, float]:
        """``(sigma, e)`` on the isentrope through ``through`` at volume ``v``."""

    @abstractmethod
    def riemann_integral(self, through: State, v: float, start: float | None = None) -> float:
        """``J = integral from through.v to v of rho0 C_L dv'`` along the isentrope (m/s).

        With ``start`` the integral runs from ``start`` instead of ``through.v`` (the
        isentrope is still the one through ``through``): wave curves extend a known
        integral by a short piece.

        This is the Riemann-invariant integral: along a right-going simple wave
        ``u - u_through = -J`` (and ``+J`` for a left-going one), because
        ``d sigma / (rho0 C_L) = -rho0 C_L dv``.
        """

    def yield_offset(self, left: State, right: State) -> float:
        """How far apart (Pa) the yield stresses of two states of this material at equal
        stress lie: the plastic history a contact between them carries.  A material
        without strength has none: 0."""
        return 0.0

    def contact_reflection(self, left: State, right: State, amplitude: float) -> float:
        """Stress (Pa) a wave of ``amplitude`` (Pa) reflects from a contact between two
        states of this material at equal stress and velocity (an entropy jump).

        Acoustically a contact between impedances ``Z_l`` and ``Z_r`` reflects
        ``amplitude |Z_l - Z_r| / (Z_l + Z_r)``; the reference density cancels, so
        the Lagrangian sound speeds stand for the impedances.  Between two states with
        no sound speed (cold gases) nothing crosses, and nothing is reflected: 0.
        """
        c_l = self.sound_speed(left.v, left.e)
        c_r = self.sound_speed(right.v, right.e)
        if not c_l + c_r > 0.0:
            return 0.0
        return amplitude * abs(c_l - c_r) / (c_l + c_r)

    def wave_curve(self, ahead: State, direction: int, release: str = "isentrope"):
        """States one wave of the given direction can reach from ``ahead``.

        ``release`` chooses the unloading path: ``"isentrope"`` (physical, a
        centred fan) or ``"hugoniot"`` (a rarefaction shock on the Hugoniot
        centred on ``ahead``, the impedance-match shortcut).
        """
        from .wavecurves import HydrodynamicWaveCurve

        return HydrodynamicWaveCurve(self, ahead, direction, release)

    def __repr__(self) -> str:
        return f"{type(self).__name__}({self.name!r})"


class AffineEnergyMaterial(Material):
    """A material whose stress is affine in energy: ``sigma = A(v) + B(v) e``.

    Subclasses provide ``_a(v)``, ``_a_prime(v)``, ``_b(v)`` and ``_b_prime(v)``
    (each accepting floats and numpy arrays) and ``volume_range``.  The Hugoniot
    is the closed form of the module docstring for any ``B(v)``.

    The isentrope implemented here assumes a constant ``B`` (Mie–Grüneisen with
    ``Gamma/v`` constant; subclasses with another ``B`` override it).  Then
    ``d/dv [e E(v)] = -A(v) E(v)`` with ``E(v) = exp(B (v - v0))``, so every
    isentrope is labelled by the constant

        K = e E(v) + F(v),    F(v) = int_{v0}^{v} A(w) E(w) dw,

    and ``e(v) = (K - F(v)) / E(v)`` in closed form once the material function
    ``F`` is known.  ``F`` is tabulated at panel edges when first needed and
    completed inside a panel by a 20-point Gauss–Legendre rule, which is exact to
    rounding for the analytic ``A``.  The Riemann-invariant integral
    ``J = int rho0 C_L dv`` is one more Gauss–Legendre quadrature on panels.
    """

    _PANEL_FRACTION = 0.05
    """Width of the quadrature panels, as a fraction of ``v0``.  The integrands'
    nearest singularities (the ``1/s`` pole, the spinodal) lie at least ~0.4 v0
    away, so 20-point Gauss–Legendre on such panels is exact to rounding."""

    _SINGULARITY_FRACTION = 0.4
    """Distance of the integrands' nearest singularity, as a fraction of ``v0`` (see above)."""

    @abstractmethod
    def _a(self, v):
        """Cold-curve-like part ``A(v)`` of the stress (Pa)."""

    @abstractmethod
    def _a_prime(self, v):
        """``dA/dv`` (Pa kg/m^3)."""

    @abstractmethod
    def _b(self, v):
        """``B(v) = (d sigma/d e)_v`` (kg/m^3)."""

    @abstractmethod
    def _b_prime(self, v):
        """``dB/dv``."""

    def stress(self, v: float, e: float) -> float:
        return float(self._a(v) + self._b(v) * e)

    def sound_speed(self, v: float, e: float) -> float:
        c2 = self.sound_speed_squared(v, e)
        if not c2 > 0.0:
            raise StateOutOfRangeError(
                f"{self.name}: no real sound speed at density {1.0 / v:.6g} kg/m3 "
                f"(the state is beyond the material's spinodal)"
            )
        return math.sqrt(c2)

    def sound_speed_squared(self, v, e):
        """``C_L^2 = v0^2 (B sigma - A' - B' e)`` (m^2/s^2); negative beyond the spinodal."""
        sigma = self._a(v) + self._b(v) * e
        slope = self._a_prime(v) + self._b_prime(v) * e - self._b(v) * sigma
        return -self.v0 * self.v0 * slope

    # --- Hugoniot -----------------------------------------------------------
    def hugoniot(self, ahead: State, v: float) -> tuple[float, float, float]:
        dv = ahead.v - v
        a, a1 = float(self._a(v)), float(self._a_prime(v))
        b, b1 = float(self._b(v)), float(self._b_prime(v))
        num = ahead.e + 0.5 * (ahead.sigma + a) * dv
        den = 1.0 - 0.5 * b * dv
        e = num / den
        dnum = 0.5 * a1 * dv - 0.5 * (ahead.sigma + a)
        dden = -0.5 * b1 * dv + 0.5 * b
        de = (dnum * den - num * dden) / (den * den)
        sigma = a + b * e
        return sigma, e, a1 + b1 * e + b * de

    def hugoniot_volume_limit(self, ahead: State) -> float:
        return self.volume_range()[0]

    # --- isentrope (constant B) -----------------------------------------------
    def _energy_factor(self, v):
        """``E(v) = exp(B (v - v0))`` (floats or arrays)."""
        if isinstance(v, float):
            return math.exp(self._b_ref * (v - self.v0))
        return np.exp(self._b_ref * (np.asarray(v, dtype=float) - self.v0))

    @functools.cached_property
    def _b_ref(self) -> float:
        return float(self._b(self.v0))

    def _f_table(self) -> tuple[list, np.ndarray, list]:
        """Panel edges and per-panel Chebyshev coefficients of ``F`` (built once).

        On each panel ``F`` is sampled at Chebyshev points (each sample a
        Gauss–Legendre integral from the panel start) and represented by its
        Chebyshev interpolant; ``F`` is analytic over several panel widths, so
        the interpolant matches the quadrature to rounding and evaluating it is a
        short Clenshaw recurrence instead of a quadrature.
        """
        table = self.__dict__.get("_f_table_cache")
        if table is None:
            v_min, v_max = self.volume_range()
            h = self._PANEL_FRACTION * self.v0
            below = np.arange(self.v0, v_min - h, -h)
            above = np.arange(self.v0, v_max + h, h)
            edges = np.concatenate([below[::-1], above[1:]])
            starts, ends = edges[:-1], edges[1:]
            # F at the panel starts, accumulated outwards from F(v0) = 0 on both sides
            # so that F keeps its relative precision near v0, where it is small.
            pieces = self._f_pieces(starts, ends)
            origin = len(below) - 1
            cumulative = np.zeros(len(edges))
            cumulative[origin + 1:] = np.cumsum(pieces[origin:])
            cumulative[:origin] = -np.cumsum(pieces[:origin][::-1])[::-1]
            x = np.cos(np.pi * (np.arange(_CHEB_POINTS) + 0.5) / _CHEB_POINTS)
            mid, half = 0.5 * (starts + ends), 0.5 * (ends - starts)
            samples = mid[:, None] + half[:, None] * x
            values = cumulative[:-1, None] + self._f_pieces(
                np.broadcast_to(starts[:, None], samples.shape), samples)
            k = np.arange(_CHEB_POINTS)
            theta = np.pi * (k + 0.5) / _CHEB_POINTS
            coefs = (2.0 / _CHEB_POINTS) * values @ np.cos(np.outer(theta, k))
            coefs[:, 0] *= 0.5
            table = (edges.tolist(), coefs,
                     [(row[0], tuple(row[:0:-1])) for row in coefs.tolist()])
            self.__dict__["_f_table_cache"] = table
        return table

    def _f_pieces(self, starts, ends):
        """``int_{start}^{end} A E dw`` for arrays of panel ends (Gauss–Legendre)."""
        starts = np.asarray(starts, dtype=float)
        width = np.asarray(ends, dtype=float) - starts
        nodes = starts[..., None] + width[..., None] * UNIT_NODES
        return width * ((self._a(nodes) * self._energy_factor(nodes)) @ UNIT_WEIGHTS)

    def _f(self, v):
        """The material function ``F(v) = int_{v0}^{v} A(w) E(w) dw`` (floats or arrays)."""
        edges, coefs, series = self._f_table()
        last = len(edges) - 2
        if isinstance(v, float):
            i = min(max(bisect.bisect_right(edges, v) - 1, 0), last)
            a, b = edges[i], edges[i + 1]
            return _clenshaw(series[i], (2.0 * v - a - b) / (b - a))
        v = np.asarray(v, dtype=float)
        index = np.clip(np.searchsorted(edges, v, side="right") - 1, 0, last)
        a, b = np.asarray(edges)[index], np.asarray(edges)[index + 1]
        x = (2.0 * v - a - b) / (b - a)
        c = coefs[index]
        b1 = b2 = np.zeros_like(v)
        for k in range(c.shape[-1] - 1, 0, -1):
            b1, b2 = 2.0 * x * b1 - b2 + c[..., k], b1
        return x * b1 - b2 + c[..., 0]

    def _isentrope_label(self, through: State) -> float:
        return self._label_cache(through.v, through.e)

    @functools.cached_property
    def _label_cache(self):
        @functools.lru_cache(maxsize=1024)
        def label(v, e):
            return float(e * self._energy_factor(v) + self._f(v))

        return label

    def isentrope(self, through: State, v: float) -> tuple[float, float]:
        label = self._isentrope_label(through)
        e = float((label - self._f(v)) / self._energy_factor(v))
        return float(self._a(v) + self._b(v) * e), e

    def isentrope_arrays(self, through: State, v):
        """``(sigma, e, C_L^2)`` on the isentrope through ``through`` at the volumes ``v``
        (an array): ``e = (K - F(v)) / E(v)`` and ``sigma = A + B e``, vectorised."""
        v = np.asarray(v, dtype=float)
        label = self._isentrope_label(through)
        e = (label - self._f(v)) / self._energy_factor(v)
        sigma = self._a(v) + self._b(v) * e
        return sigma, e, self.sound_speed_squared(v, e)

    def riemann_integral(self, through: State, v: float, start: float | None = None) -> float:
        label = self._isentrope_label(through)
        total = 0.0
        start = through.v if start is None else start
        panel = self._PANEL_FRACTION * self.v0
        edges = (start, v) if abs(v - start) <= panel else panel_edges(start, v, panel).tolist()
        points = points_for(edges[1] - edges[0], self._SINGULARITY_FRACTION * self.v0)
        scalar = points <= _SCALAR_RULE_POINTS
        unit_nodes, unit_weights = unit_rule_lists(points) if scalar else unit_rule(points)
        for a, b in zip(edges[:-1], edges[1:], strict=True):
            if scalar:
                # a short piece: a few float evaluations beat numpy's per-call overhead
                c2 = []
                for x in unit_nodes:
                    node = a + (b - a) * x
                    e_node = (label - self._f(node)) / self._energy_factor(node)
                    c2.append(self.sound_speed_squared(node, e_node))
            else:
                nodes = a + (b - a) * unit_nodes
                e_nodes = (label - self._f(nodes)) / self._energy_factor(nodes)
                c2 = self.sound_speed_squared(nodes, e_nodes).tolist()
            if not min(c2) > 0.0:
                raise StateOutOfRangeError(
                    f"{self.name}: the isentrope leaves the region of real sound speed near "
                    f"density {1.0 / b:.6g} kg/m3"
                )
            weights = unit_weights if scalar else unit_weights.tolist()
            total += (b - a) * math.fsum(w * math.sqrt(c) for w, c in zip(
                weights, c2, strict=True))
        return self.rho0 * total
