"""Impedance matching: the first shock from a flyer through a stack of layers.

A flyer plate moving at ``V`` toward +X strikes a stack of layers at rest.
Every layer is taken as semi-infinite, so only the leading shock is followed:

1. Impact: the flyer's reference state moving at ``V`` meets the first layer's
   reference state at rest.  ``solve_contact`` gives the contact state, a
   left-going shock into the flyer and a right-going shock into layer 0.
2. At each interface ``k | k+1`` the state behind the shock in layer ``k`` meets
   layer ``k+1`` at rest.  ``solve_contact`` gives the transmitted shock and
   the wave reflected back into layer ``k``: a reshock (on the Hugoniot centred
   on the shocked state) when layer ``k+1`` has the higher impedance, a release
   fan (on the isentrope, or a rarefaction shock if ``release="hugoniot"``) when
   it has the lower.

With ``mirrored=True`` step 2 uses the classic graphical shortcut instead: the
curve of the reflected wave is replaced by layer ``k``'s *principal* Hugoniot
mirrored about the current particle velocity, ``sigma(u) = sigma_H(2 u_k - u)``.
That curve is the left-going Hugoniot of a virtual flyer of material ``k`` at
``2 u_k``, so the shortcut is an impact problem solved by the same bracketed
root.  The mirrored curve passes through the shocked state ``(u_k, sigma_k)`` but
with the principal Hugoniot's slope there, ``-rho0 (c0 + 2 s u_k)`` for a linear
Us–up fit, instead of the shocked state's impedance ``-rho0 C_L``, and it ignores
the entropy the first shock left behind; its error grows with the stress and
with the size of the reflected jump.  Rows it produces are labelled
``"mirrored Hugoniot"``; the reflected wave is then a jump along the mirrored
curve, reported as a shock with its chord speed, and the density and
temperature behind it are unknown (``None``).

Speeds are Lagrangian (m/s, signed: positive to the right) unless named
Eulerian; the Eulerian (laboratory) speed of a shock is
``u_ahead + U rho0 / rho_ahead`` (mass flux ``rho_a (D - u_a) = rho0 U``).
Stresses are positive in compression.

A state beyond the particle-velocity range of a material's fitted Hugoniot data
(``up_max``) is computed on the extrapolated fit and warned about with a
``FitExtrapolationWarning``, one per material and row.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import asdict, dataclass

from materials import (
    Fan,
    Material,
    RiemannSolution,
    Shock,
    State,
    WavediagramError,
    solve_contact,
)

from . import fits
from .errors import SceneError, located
from .material import material as named_material
from .units import to_si

EXACT = "exact"
MIRRORED = "mirrored Hugoniot"


@dataclass(frozen=True)
class ReflectedWave:
    """The wave sent back into a layer when its shock reaches the next interface.

    ``kind``: ``"shock"`` (``speed``, Lagrangian m/s, negative: it goes left) or
    ``"fan"`` (``head_speed`` and ``tail_speed`` of its first and last
    characteristics).  ``compressive``: a reshock (True) or a release (False).
    ``sigma`` (Pa), ``u`` (m/s), ``rho`` (kg/m^3) and ``temperature`` (K) describe
    the state behind it; ``rho`` and ``temperature`` are ``None`` where unknown.
    """

    kind: str
    compressive: bool
    speed: float | None
    head_speed: float | None
    tail_speed: float | None
    sigma: float
    u: float
    rho: float | None
    temperature: float | None


@dataclass(frozen=True)
class MatchRow:
    """The state behind the first shock in one layer (``layer`` 0, 1, ... or ``"flyer"``).

    ``sigma`` (Pa), ``u`` (m/s), ``rho`` (kg/m^3), ``temperature`` (K, ``None`` if
    the material has no specific heat).  ``shock_speed`` is the Lagrangian speed
    of the shock that brought the layer to this state (m/s; negative for the
    left-going shock in the flyer), ``shock_speed_eulerian`` its laboratory speed.
    ``reflected`` is the wave sent back into this layer at its right interface
    (``None`` for the flyer and the last layer).  ``method``: ``"exact"`` or
    ``"mirrored Hugoniot"``.
    """

    layer: int | str
    material: str
    sigma: float
    u: float
    rho: float
    temperature: float | None
    shock_speed: float
    shock_speed_eulerian: float
    reflected: ReflectedWave | None
    method: str


class MatchError(WavediagramError, ValueError):
    """An impedance match asked of a flyer that does not strike, or of no stack."""


def match(flyer: Material | str, velocity: float | str, stack: list[Material | str],
          release: str = "isentrope", mirrored: bool = False) -> list[MatchRow]:
    """The first shock from a flyer through a stack: ``impedance_match`` for users.

    Parameters
    ----------
    flyer : Material or str
        The flyer's material, or its library name.
    velocity : float or str
        Impact velocity, m/s or a string with a unit (``"1 km/s"``), > 0.
    stack : list of Material or str
        The target's layers, first struck first (semi-infinite, at rest); one
        material alone is a one-layer stack.
    release, mirrored
        As ``impedance_match``.

    Returns
    -------
    list of MatchRow
        The flyer's row, then one per layer (SI: Pa, m/s, kg/m^3, K).

    Raises
    ------
    SceneError
        A velocity that is not > 0, an unknown material name.
    """
    if isinstance(stack, (str, Material)):
        stack = [stack]
    speed = to_si(velocity, "velocity", "velocity")
    if not speed > 0.0:
        raise SceneError(f"velocity: the flyer must move toward the stack, > 0 m/s; "
                         f"got {speed!r}")
    return impedance_match(_as_material(flyer, "flyer"), speed,
                           [_as_material(m, f"stack[{k}]") for k, m in enumerate(stack)],
                           release=release, mirrored=mirrored)


def _as_material(value: Material | str, where: str) -> Material:
    if isinstance(value, Material):
        return value
    with located("material", where):
        return named_material(value)


def impedance_match(flyer: Material, velocity: float, stack: list[Material],
                    release: str = "isentrope", mirrored: bool = False) -> list[MatchRow]:
    """Rows for the flyer and each layer of ``stack`` after the first shock has crossed it.

    ``flyer`` moves at ``velocity`` (m/s, > 0) toward the stack, which is at rest
    and unstressed; layers are semi-infinite.  ``release`` (``"isentrope"`` or
    ``"hugoniot"``) is the path of reflected release waves in the exact method;
    ``mirrored`` selects the mirrored-Hugoniot shortcut at the interfaces.  Raises
    ``MatchError`` for a velocity that is not finite and positive or an empty stack.
    """
    if not (isinstance(velocity, (int, float)) and math.isfinite(velocity) and velocity > 0):
        raise MatchError(f"velocity: the flyer velocity must be finite and > 0 m/s (toward "
                         f"the stack), got {velocity!r} m/s")
    if not stack:
        raise MatchError("layers: the stack needs at least one layer")
    impact = solve_contact(flyer, flyer.reference_state(u=float(velocity)),
                           stack[0], stack[0].reference_state(), release=release)
    _warn_beyond_fits([(flyer, impact.left_star.v)])
    rows = [_row("flyer", flyer, impact.left_star, impact.left_waves, None, EXACT)]
    return rows + _through(impact.right_star, impact.right_waves, stack, release, mirrored)


def _warn_beyond_fits(pieces) -> None:
    """Warn (``FitExtrapolationWarning``) for each ``(material, v)`` beyond its fitted data."""
    for line in fits.extrapolations(pieces):
        warnings.warn(line, fits.FitExtrapolationWarning, stacklevel=3)


def detonation_match(explosive: Material | str, stack: list[Material | str],
                     release: str = "isentrope", mirrored: bool = False) -> list[MatchRow]:
    """The CJ detonation of ``explosive`` arriving at a stack (``wavediagram match PBX9501
    detonation Cu``): the first row is the explosive's CJ state behind its detonation
    (``shock_speed`` is D_CJ) with the wave the first layer reflects into the products;
    then one row per layer as ``impedance_match``.  The Taylor wave behind the CJ point
    is not part of this first-shock estimate: the first layer's state is the peak of the
    pulse it receives.
    """
    explosive = _as_material(explosive, "explosive")
    if not hasattr(explosive, "cj_state"):
        raise MatchError(f"flyer: {explosive.name} is not an explosive; \"detonation\" needs "
                         f"one (wavediagram materials lists them)")
    if isinstance(stack, (str, Material)):
        stack = [stack]
    if not stack:
        raise MatchError("layers: the stack needs at least one layer")
    stack = [_as_material(m, f"stack[{k}]") for k, m in enumerate(stack)]
    rest = explosive.reference_state()
    cj = explosive.cj_state(rest)
    front = Shock(ahead=rest, behind=cj.state, speed=cj.speed, direction=1)
    arrival = solve_contact(explosive, cj.state, stack[0], stack[0].reference_state(),
                            release=release)
    rows = [_row("detonation", explosive, cj.state, (front,), _reflection(explosive, arrival),
                 EXACT)]
    return rows + _through(arrival.right_star, arrival.right_waves, stack, release, mirrored)


def _through(state: State, transmitted: tuple, stack: list[Material], release: str,
             mirrored: bool) -> list[MatchRow]:
    """One row per layer: the shock ``transmitted`` into the first layer (behind it
    ``state``) followed through the stack."""
    rows = []
    for k, material in enumerate(stack):
        reflected = None
        next_state, next_transmitted = state, transmitted
        if k + 1 < len(stack):
            following = stack[k + 1]
            if mirrored:
                solution = solve_contact(material, material.reference_state(u=2.0 * state.u),
                                         following, following.reference_state(),
                                         release="hugoniot")
                reflected = _mirrored_reflection(material, state, solution.right_star)
            else:
                solution = solve_contact(material, state, following,
                                         following.reference_state(), release=release)
                reflected = _reflection(material, solution)
            next_state, next_transmitted = solution.right_star, solution.right_waves
        # Layer 0's state is exact either way; a row is approximate if its state or
        # its reflected wave came from the mirrored curve.
        method = MIRRORED if mirrored and (k > 0 or reflected is not None) else EXACT
        _warn_beyond_fits([(material, state.v)])
        rows.append(_row(k, material, state, transmitted, reflected, method))
        state, transmitted = next_state, next_transmitted
    return rows


def _row(layer: int | str, material: Material, state: State, waves: tuple,
         reflected: ReflectedWave | None, method: str) -> MatchRow:
    """A row for the state behind the waves into the layer, led by a shock: one shock, or a
    detonation and the Taylor wave behind it (an explosive struck or striking), whose
    speed is the detonation's."""
    shock = waves[0] if waves else None
    if not isinstance(shock, Shock):
        raise MatchError(f"{material.name}: the waves into this layer are not led by a shock "
                         f"(an impedance match reports shocked states; `wavediagram run` "
                         f"follows any wave)")
    ahead = shock.ahead
    return MatchRow(
        layer=layer, material=material.name, sigma=state.sigma, u=state.u, rho=state.rho,
        temperature=material.temperature(state.v, state.e), shock_speed=shock.speed,
        shock_speed_eulerian=ahead.u + shock.speed * (ahead.v / material.v0),
        reflected=reflected, method=method,
    )


def _reflection(material: Material, solution: RiemannSolution) -> ReflectedWave | None:
    """The exact reflected wave of an interface problem (``None`` if there is none)."""
    if not solution.left_waves:
        return None
    waves = solution.left_waves
    wave = waves[0]  # the leading one (a family of several: its first and last waves)
    behind = solution.left_star
    common = dict(compressive=behind.sigma > wave.ahead.sigma, sigma=behind.sigma, u=behind.u,
                  rho=behind.rho, temperature=material.temperature(behind.v, behind.e))
    if any(isinstance(w, Fan) for w in waves):
        last = waves[-1]
        return ReflectedWave("fan", speed=None,
                             head_speed=wave.head_speed if isinstance(wave, Fan) else wave.speed,
                             tail_speed=last.tail_speed if isinstance(last, Fan) else last.speed,
                             **common)
    return ReflectedWave("shock", speed=wave.speed, head_speed=None, tail_speed=None, **common)


def _mirrored_reflection(material: Material, state: State, star: State) -> ReflectedWave | None:
    """The jump from ``state`` to ``star`` along the mirrored Hugoniot, with its chord speed.

    ``rho0 U (u_b - u_a) = sigma_b - sigma_a`` gives ``U``; only ``sigma`` and ``u``
    are known behind the jump.
    """
    if star.sigma == state.sigma:
        return None
    speed = (star.sigma - state.sigma) / (material.rho0 * (star.u - state.u))
    return ReflectedWave("shock", compressive=star.sigma > state.sigma, speed=speed,
                         head_speed=None, tail_speed=None, sigma=star.sigma, u=star.u,
                         rho=None, temperature=None)


# --- output --------------------------------------------------------------------------------
UNITS = {"sigma": "Pa", "u": "m/s", "rho": "kg/m3", "temperature": "K",
         "shock_speed": "m/s (Lagrangian)", "shock_speed_eulerian": "m/s (laboratory)",
         "speed": "m/s (Lagrangian)", "head_speed": "m/s (Lagrangian)",
         "tail_speed": "m/s (Lagrangian)"}
"""Units of the numbers in ``to_json_dict`` (SI throughout)."""


def to_json_dict(rows: list[MatchRow]) -> dict:
    """A JSON-ready dict: ``{"units": UNITS, "rows": [...]}`` with one SI dict per row.

    Row keys: ``layer``, ``material``, ``method``, ``sigma`` (Pa), ``u`` (m/s),
    ``rho`` (kg/m^3), ``temperature`` (K or null), ``shock_speed`` and
    ``shock_speed_eulerian`` (m/s) and ``reflected`` (null or a dict with
    ``kind``, ``compressive``, ``speed``, ``head_speed``, ``tail_speed``,
    ``sigma``, ``u``, ``rho``, ``temperature``).
    """
    return {"units": dict(UNITS), "rows": [asdict(row) for row in rows]}


_COLUMNS = ("layer", "material", "sigma GPa", "u m/s", "rho g/cm3", "Us km/s", "T K",
            "reflected wave (km/s)", "method")


def format_table(rows: list[MatchRow]) -> str:
    """A plain-text table: GPa, m/s, g/cm^3, Lagrangian km/s and K, one line per row."""
    lines = [_COLUMNS]
    for row in rows:
        lines.append((str(row.layer), row.material, f"{row.sigma / 1e9:.4f}", f"{row.u:.2f}",
                      f"{row.rho / 1e3:.4f}", f"{row.shock_speed / 1e3:.4f}",
                      "-" if row.temperature is None else f"{row.temperature:.0f}",
                      _describe(row.reflected), row.method))
    widths = [max(len(line[i]) for line in lines) for i in range(len(_COLUMNS))]
    text = ["  ".join(cell.ljust(w) for cell, w in zip(line, widths, strict=True)).rstrip()
            for line in lines]
    text.insert(1, "  ".join("-" * w for w in widths))
    return "\n".join(text)


def _describe(wave: ReflectedWave | None) -> str:
    if wave is None:
        return "-"
    what = "reshock" if wave.compressive else "release"
    if wave.kind == "fan":
        return f"{what} fan {wave.head_speed / 1e3:.4f} to {wave.tail_speed / 1e3:.4f}"
    return f"{what} shock {wave.speed / 1e3:.4f}"
