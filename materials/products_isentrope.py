"""The stress function of a detonation-products isentrope, tabulated once (Chebyshev panels).

Along the isentrope ``K`` of the products (``materials.products``) the Riemann-invariant
integral has no closed form for JWL products.  In ``y = V^(-omega/2)`` (``V = v/v0``; ``y
= 0`` is vacuum) the stress function measured from vacuum,

    Phi(y) = -rho0 int_inf^v C_L dv' = int_0^y h(y') dy',
    h(y) = (2/omega) sqrt(v0 [A R1 exp(-R1 V) + B R2 exp(-R2 V)] V^(2 + omega)
                          + v0 (1 + omega) omega rho0 K),

has a smooth integrand (``h`` tends to a constant at vacuum; for gamma-law products it
*is* that constant).  ``h`` is tabulated as Chebyshev series on panels of ``y`` (each
converged to rounding, halved where it is not), ``Phi`` is the series' exact
antiderivative, so the integral ``J = int rho0 C_L dv = Phi(y_start) - Phi(y)`` costs two
series evaluations instead of a quadrature, and ``y(Phi)`` is a Newton inversion on the
panel's series.  This is the products' counterpart of the Chebyshev isentrope tables of
``characteristics.isentrope`` (Mie–Grüneisen solids), built in ``y`` so that it reaches
vacuum.
"""

from __future__ import annotations

import bisect

import numpy as np

PANEL_WIDTH = 0.05
"""Width of a base panel in ``y``.  The exponential terms change by a factor e over at
least ~0.03 in ``y`` for the tabulated explosives (R1 <= 5, omega >= 0.25); a panel whose
24-point series does not converge to rounding is halved (``MAX_HALVINGS``)."""

POINTS = 24
"""Chebyshev points per panel."""

MAX_HALVINGS = 8
"""A panel whose series does not converge is halved, at most this many times."""

CONVERGED = 1e-14
"""A series is converged when its last three coefficients are below this fraction of the
integrand's largest value on the panel."""

NEWTON_STEPS = 6
"""Newton steps of the inversion ``y(Phi)`` on one panel: ``Phi`` is nearly linear there
(``h`` varies by a few per cent across a panel), so the error falls like 1e-4, 1e-8, 1e-16."""

_THETA = np.pi * (np.arange(POINTS) + 0.5) / POINTS
_UNIT = np.cos(_THETA)
_TRANSFORM = (2.0 / POINTS) * np.cos(np.outer(_THETA, np.arange(POINTS)))
_TRANSFORM[:, 0] *= 0.5


def _clenshaw_float(coefs: list[float], z: float) -> float:
    """The series ``coefs`` at a float ``z`` in ``[-1, 1]`` (no numpy overhead)."""
    b1 = b2 = 0.0
    for c in coefs[:0:-1]:
        b1, b2 = 2.0 * z * b1 - b2 + c, b1
    return z * b1 - b2 + coefs[0]


def _clenshaw(coefs: np.ndarray, z: np.ndarray) -> np.ndarray:
    """Row ``i`` of the series ``coefs`` at ``z[i]`` in ``[-1, 1]``."""
    b1 = np.zeros_like(z)
    b2 = np.zeros_like(z)
    for k in range(coefs.shape[-1] - 1, 0, -1):
        b1, b2 = 2.0 * z * b1 - b2 + coefs[..., k], b1
    return z * b1 - b2 + coefs[..., 0]


class ProductsIsentropeTable:
    """``Phi(y)`` and its inverse on the isentrope ``k`` (J/kg) of ``products``.

    Panels start at vacuum (``y = 0``) and are added upward when a query first needs them.
    Methods take floats or numpy arrays of ``y >= 0`` (or of ``Phi >= 0``).
    """

    def __init__(self, products, k: float):
        self.products = products
        self.k = k
        self._edges = [0.0]  # panel edges in y, ascending
        self._phi_edges = [0.0]  # Phi at the edges
        self._h: list[np.ndarray] = []  # series of h per panel
        self._phi: list[np.ndarray] = []  # series of Phi per panel
        self._phi_lists: list[list[float]] = []  # the same as lists (float queries)
        self._h_lists: list[list[float]] = []
        self._stack = None

    def integrand(self, y):
        """``h(y) = dPhi/dy`` (m/s) in closed form."""
        p = self.products
        y = np.asarray(y, dtype=float)
        with np.errstate(divide="ignore", over="ignore", invalid="ignore"):
            big_v = np.where(y > 0.0, y, 1.0) ** (-2.0 / p.omega)
            cold = p.v0 * (p.A * p.R1 * np.exp(-p.R1 * big_v) + p.B * p.R2 * np.exp(-p.R2 * big_v))
            term = cold * big_v ** (2.0 + p.omega)
        term = np.where((y > 0.0) & np.isfinite(term), term, 0.0)
        return 2.0 / p.omega * np.sqrt(term + p.v0 * (1.0 + p.omega) * p.omega * p.rho0 * self.k)

    # --- construction ---------------------------------------------------------------
    def _extend(self, y_top: float) -> None:
        """Add base panels (halved where needed) until the table reaches ``y_top``."""
        start = self._edges[-1]
        count = max(1, int(np.ceil((y_top - start) / PANEL_WIDTH)))
        edges = start + PANEL_WIDTH * np.arange(count + 1)
        for lo, hi, h_coefs in self._panels(edges[:-1], edges[1:], 0):
            phi_coefs = np.polynomial.chebyshev.chebint(h_coefs, scl=0.5 * (hi - lo), lbnd=-1.0)
            phi_coefs[0] += self._phi_edges[-1]
            self._h.append(h_coefs)
            self._phi.append(phi_coefs)
            self._phi_lists.append(phi_coefs.tolist())
            self._h_lists.append(h_coefs.tolist())
            self._edges.append(float(hi))
            self._phi_edges.append(float(np.polynomial.chebyshev.chebval(1.0, phi_coefs)))
        self._stack = None

    def _panels(self, lo: np.ndarray, hi: np.ndarray, depth: int) -> list:
        """``(lo, hi, series of h)`` for the panels ``[lo[i], hi[i]]``, ascending, each
        converged (halved where it is not)."""
        y = 0.5 * (lo + hi)[:, None] + 0.5 * (hi - lo)[:, None] * _UNIT
        values = self.integrand(y)
        coefs = values @ _TRANSFORM
        good = (np.max(np.abs(coefs[:, -3:]), axis=1)
                <= CONVERGED * np.max(np.abs(values), axis=1)) | (depth >= MAX_HALVINGS)
        out = []
        for i in range(len(lo)):
            if good[i]:
                out.append((lo[i], hi[i], coefs[i]))
            else:
                mid = 0.5 * (lo[i] + hi[i])
                out += self._panels(np.array([lo[i], mid]), np.array([mid, hi[i]]), depth + 1)
        return out

    def _arrays(self):
        if self._stack is None:
            width = max(len(c) for c in self._phi)
            phi = np.zeros((len(self._phi), width))
            h = np.zeros((len(self._h), width))
            for i, (a, b) in enumerate(zip(self._phi, self._h, strict=True)):
                phi[i, :len(a)] = a
                h[i, :len(b)] = b
            self._stack = (np.array(self._edges), np.array(self._phi_edges), phi, h)
        return self._stack

    # --- queries --------------------------------------------------------------------
    def phi(self, y):
        """``Phi(y)`` (m/s), zero at vacuum."""
        if isinstance(y, float):
            if y > self._edges[-1]:
                self._extend(y)
            i = min(max(bisect.bisect_right(self._edges, y) - 1, 0), len(self._edges) - 2)
            lo, hi = self._edges[i], self._edges[i + 1]
            return _clenshaw_float(self._phi_lists[i], (2.0 * y - lo - hi) / (hi - lo))
        y = np.asarray(y, dtype=float)
        top = float(np.max(y)) if y.size else 0.0
        if top > self._edges[-1]:
            self._extend(top)
        edges, _, phi, _ = self._arrays()
        i = np.clip(np.searchsorted(edges, y, side="right") - 1, 0, len(edges) - 2)
        lo, hi = edges[i], edges[i + 1]
        out = _clenshaw(phi[i], (2.0 * y - lo - hi) / (hi - lo))
        return float(out) if out.ndim == 0 else out

    def y_at_phi(self, target):
        """The ``y`` where ``Phi(y) = target`` (``target >= 0``; 0 at vacuum)."""
        scalar = isinstance(target, float)
        target = np.maximum(np.asarray(target, dtype=float), 0.0)
        top = float(np.max(target)) if target.size else 0.0
        while top > self._phi_edges[-1]:
            self._extend(self._edges[-1] + PANEL_WIDTH * max(
                1.0, (top - self._phi_edges[-1]) / float(self.integrand(self._edges[-1]))))
        if scalar:
            return self._y_at_phi_float(float(target))
        edges, phi_edges, phi, h = self._arrays()
        i = np.clip(np.searchsorted(phi_edges, target, side="right") - 1, 0, len(edges) - 2)
        lo, hi = edges[i], edges[i + 1]
        f_lo, f_hi = phi_edges[i], phi_edges[i + 1]
        y = lo + (hi - lo) * (target - f_lo) / (f_hi - f_lo)
        for _ in range(NEWTON_STEPS):
            z = (2.0 * y - lo - hi) / (hi - lo)
            y = np.clip(y - (_clenshaw(phi[i], z) - target) / _clenshaw(h[i], z), lo, hi)
        return float(y) if y.ndim == 0 else y

    def _y_at_phi_float(self, target: float) -> float:
        """``y_at_phi`` for a float inside the table (no numpy overhead)."""
        edges, phi_edges = self._edges, self._phi_edges
        i = min(max(bisect.bisect_right(phi_edges, target) - 1, 0), len(edges) - 2)
        lo, hi = edges[i], edges[i + 1]
        y = lo + (hi - lo) * (target - phi_edges[i]) / (phi_edges[i + 1] - phi_edges[i])
        phi, h = self._phi_lists[i], self._h_lists[i]
        for _ in range(NEWTON_STEPS):
            z = (2.0 * y - lo - hi) / (hi - lo)
            y = min(max(y - (_clenshaw_float(phi, z) - target) / _clenshaw_float(h, z), lo), hi)
        return y
