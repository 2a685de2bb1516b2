"""What an interferometer reports through a shocked optical window.

A VISAR or PDV probe looks at a sample through a transparent window: the light
crosses the window, reflects from the sample–window interface and comes back.
The interferometer measures the rate of change of the optical path ``L = ∫ n dx``
from a fixed reference plane to the interface, not the interface velocity.
Compression changes the window's refractive index ``n``; the velocity it
reports is the *apparent* velocity.

For an index linear in density, ``n = a + b rho/rho0`` (the form the cited
measurements fit), the path through the window in Lagrangian form is
``∫ n dx = ∫ (a v/v0 + b) dX``; the ``b`` term is the window's mass per area and
does not change, and mass conservation ``d(v/v0)/dt = du/dX`` gives
``d/dt ∫ n dx = a (u_far - u_i)``, with ``u_i`` the interface velocity and
``u_far`` the velocity of the window's far face.  Adding the path outside the
window (index 1) from its far face to the reference plane, the apparent velocity
(positive toward +X, like ``u``) is

    u_app = a u_i + (1 - a) u_far,

exactly, whatever the waves inside the window (shocks, fans, reflections), as
long as the window stays transparent.  While the far face is at rest,
``u_app / u_i = a``: the published "window correction factor".  For a single
shock into the window the same follows from the jump conditions,
``u_app / u_i = (n0 rho1 - n1 rho0) / (rho1 - rho0) = a``.

Units: SI; coefficients are dimensionless.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .errors import SceneError


@dataclass(frozen=True)
class OpticalWindow:
    """A window's refractive index ``n = a + b rho/rho0`` at one wavelength.

    ``a`` is the apparent-to-true velocity ratio while the far face is at rest;
    ``a + b`` is the index at ambient density.  ``wavelength`` (m) of the light the
    fit holds for, ``material`` the library name of the window's material and
    ``source`` the measurement the coefficients come from.
    """

    name: str
    a: float
    b: float
    wavelength: float
    material: str
    source: str

    def index(self, rho_ratio: float) -> float:
        """Refractive index at density ``rho_ratio = rho/rho0`` (dimensionless)."""
        return self.a + self.b * rho_ratio

    def apparent_velocity(self, u_interface, u_far=0.0):
        """Velocity (m/s) the interferometer reports: ``a u_i + (1 - a) u_far``."""
        return self.a * np.asarray(u_interface) + (1.0 - self.a) * np.asarray(u_far)


LIF_INDEX_1550 = 1.38275
"""Ambient index of LiF at 1550 nm and 297 K, from the Sellmeier formula of H. H. Li,
J. Phys. Chem. Ref. Data 5, 329 (1976) (as given in the refractiveindex.info database,
``main/LiF/nk/Li.yml``): ``n^2 = 1 + 0.92549 l^2/(l^2 - 0.07376^2) + 6.96747 l^2/(l^2 -
32.790^2)``, ``l`` in um."""

WINDOWS: dict[str, OpticalWindow] = {
    "LiF": OpticalWindow(
        name="LiF", a=1.2669, b=0.11585, wavelength=1550e-9,  # b = LIF_INDEX_1550 - a
        material="LiF",
        source="a = 1.2669: Jensen, Holtkamp, Rigg and Dolan, 'Accuracy limits and window "
               "corrections for photon Doppler velocimetry', J. Appl. Phys. 101, 013523 "
               "(2007), LiF [100] at 1550 nm (the value could not be read in the paper "
               "itself; it agrees within 0.8 % from 0.3 to 2 km/s with the later fit of Rigg, "
               "Knudson, Scharff and Hixson, J. Appl. Phys. 116, 033515 (2014), Eq. 16, "
               "u = 0.7895 u_app^0.9918 in km/s). b = n0 - a with n0 = 1.38275, the ambient "
               "index at 1550 nm (H. H. Li, J. Phys. Chem. Ref. Data 5, 329 (1976)); the "
               "0.1178 used before gave n0 = 1.3847, 0.002 too high"),
}
"""Windows with a cited fit, by name.  PMMA and sapphire are not listed: no coefficient of
their index against density (or of their apparent-to-true velocity ratio) could be read
in a source with the search tools available, in two searches (the second of 36 queries
over web pages, documentation, code and issues): Barker and Hollenbach, J. Appl. Phys.
41, 4208 (1970) (PMMA, fused silica, sapphire) and the a-axis sapphire study of Jones
and Gupta, J. Appl. Phys. 90, 4990 (2001), were found by title and abstract only (the
latter states that the index at 514.5 nm falls linearly with density, without the
numbers).  Give them as ``OpticalWindow`` with the coefficients of the source you use."""


def optical_window(window: str | OpticalWindow) -> OpticalWindow:
    """The ``OpticalWindow`` called ``window`` (an ``OpticalWindow`` passes through).

    Raises ``SceneError`` naming the windows that have a cited fit; a window without
    one is given as an ``OpticalWindow`` with its coefficients and source.
    """
    if isinstance(window, OpticalWindow):
        return window
    if isinstance(window, str):
        for name, known in WINDOWS.items():
            if window.lower() == name.lower():
                return known
    raise SceneError(f"window: no refractive-index fit for {window!r} (cited fits: "
                     f"{', '.join(WINDOWS)}); from Python, give an OpticalWindow(name, a, b, "
                     f"wavelength, material, source) with the coefficients of "
                     f"n = a + b rho/rho0")


@dataclass(frozen=True)
class WindowRecord:
    """What an interferometer behind a window records at an interface probe.

    Both records are linear between consecutive samples and jump where two
    samples share a time (``History.samples`` style): ``t`` (s), the interface
    velocity ``u`` and the apparent velocity ``u_apparent`` (m/s, positive toward
    +X), with the far face's velocity ``u_far`` (m/s) that enters it.
    """

    probe: str
    window: OpticalWindow
    t: np.ndarray
    u: np.ndarray
    u_far: np.ndarray
    u_apparent: np.ndarray


def window_layer(scene, probe) -> tuple[int, float]:
    """Index of the layer an interface probe looks through, and its far face's X (m)."""
    x = {"left": 0.0, "right": scene.length}.get(probe.at, probe.at)
    edges = [0.0, *scene.interfaces(), scene.length]
    k = min(range(len(edges)), key=lambda i: abs(edges[i] - x))
    layer = k if probe.side == "right" else k - 1
    return layer, edges[layer + 1] if probe.side == "right" else edges[layer]


def window_record(solution, name: str) -> WindowRecord:
    """The true and apparent velocity at the interface probe ``name`` (which has a window).

    ``u_app = a u_i + (1 - a) u_far`` on the union of the break points of the
    interface's and the far face's records, where both are linear: exact
    wherever those records are.
    """
    probe = next((p for p in solution.scene.probes if p.name == name), None)
    if probe is None:
        names = ", ".join(repr(p.name) for p in solution.scene.probes) or "none"
        raise SceneError(f"probe: no probe named {name!r} (probes: {names})")
    if probe.window is None:
        raise SceneError(f"probe[{name}].window: the probe has no optical window")
    _, far = window_layer(solution.scene, probe)
    interface, far_face = solution.history(probe.at), solution.history(far)
    grid = np.union1d(interface.t, far_face.t)
    grid = grid[grid < interface.stop]
    u0, u1 = _pieces(interface, grid)
    f0, f1 = _pieces(far_face, grid)
    t = np.repeat(np.append(grid, interface.stop), 2)[1:-1]
    u = np.column_stack([u0, u1]).ravel()
    u_far = np.column_stack([f0, f1]).ravel()
    return WindowRecord(probe=name, window=probe.window, t=t, u=u, u_far=u_far,
                        u_apparent=probe.window.apparent_velocity(u, u_far))


def _pieces(history, grid: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Velocity at the start and at the end of each piece ``[grid[j], grid[j + 1]]``.

    Every piece lies inside one piece of ``history`` (``grid`` holds its break
    points), where the record is linear.
    """
    starts = np.array([s.u for s in history.states])
    ends = np.array([s.u for s in history.ends])
    right = np.append(history.t[1:], history.stop)
    k = np.clip(np.searchsorted(history.t, grid, side="right") - 1, 0, len(history.t) - 1)
    upper = np.append(grid[1:], history.stop)
    width = right[k] - history.t[k]
    safe = np.where(width > 0.0, width, 1.0)

    def value(at: np.ndarray) -> np.ndarray:
        f = np.where(width > 0.0, (at - history.t[k]) / safe, 0.0)
        return starts[k] + f * (ends[k] - starts[k])

    return value(grid), value(upper)
