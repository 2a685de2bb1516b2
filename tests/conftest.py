"""Shared fixtures for the ``materials`` test suite.

Materials (SI units; sigma positive in compression, see PHYSICS.md):

- Mie–Grüneisen solids on linear Us–up fits.  Cu: S. P. Marsh (ed.), *LASL Shock
  Hugoniot Data* (1980), with cv = 385 J/(kg K); Al 6061, PMMA and W with the
  parameters of the project brief (same compilation).
- Linear elastic solids: the X-cut quartz gauge of PHYSICS.md (2649 kg/m^3,
  5749 m/s) and Davison's reference steel built from its Lamé constants
  (lambda = 123.1 GPa, mu = 79.29 GPa, rho0 = 7870 kg/m^3; C0 ~ 5983 m/s).
- An ideal gas with gamma = 1.4 (reference density 1.2 kg/m^3).

Fixtures are session-scoped: the materials are immutable apart from their
internal quadrature caches, and session scope is what lets the hypothesis
tests use them (hypothesis refuses function-scoped fixtures).

Property tests are derandomised by default, so that a run of the suite (and CI)
is reproducible; ``pytest --hypothesis-profile=explore`` draws fresh random
examples, more of them, for hunting new failures.
"""

from __future__ import annotations

import math

import pytest
from hypothesis import settings

from materials import IdealGas, LinearElastic, MieGruneisen

settings.register_profile("reproducible", derandomize=True)
settings.register_profile("explore", max_examples=1000)
settings.load_profile("reproducible")


def make_copper() -> MieGruneisen:
    """Cu, Marsh LASL 1980: rho0 8930, c0 3940, s 1.489, Gamma0 1.99, cv 385."""
    return MieGruneisen("Cu", 8930.0, 3940.0, 1.489, 1.99, cv=385.0)


def make_aluminium() -> MieGruneisen:
    """Al 6061: rho0 2703, c0 5350, s 1.34, Gamma0 2.0, cv 896."""
    return MieGruneisen("Al6061", 2703.0, 5350.0, 1.34, 2.0, cv=896.0)


def make_pmma() -> MieGruneisen:
    """PMMA: rho0 1186, c0 2598, s 1.516, Gamma0 0.97."""
    return MieGruneisen("PMMA", 1186.0, 2598.0, 1.516, 0.97)


def make_tungsten() -> MieGruneisen:
    """W: rho0 19224, c0 4029, s 1.237, Gamma0 1.54."""
    return MieGruneisen("W", 19224.0, 4029.0, 1.237, 1.54)


def make_quartz() -> LinearElastic:
    """X-cut quartz gauge (elastic): rho0 2649 kg/m^3, C 5749 m/s."""
    return LinearElastic("quartz", 2649.0, 5749.0)


def make_steel() -> LinearElastic:
    """Davison's steel, elastic part only: lambda 123.1 GPa, mu 79.29 GPa, rho0 7870."""
    return LinearElastic.from_lame("steel", 7870.0, 123.1e9, 79.29e9)


def make_gas() -> IdealGas:
    """Gamma-law gas, gamma = 1.4, reference density 1.2 kg/m^3."""
    return IdealGas("air", 1.4, rho0=1.2)


@pytest.fixture(scope="session")
def copper():
    return make_copper()


@pytest.fixture(scope="session")
def aluminium():
    return make_aluminium()


@pytest.fixture(scope="session")
def pmma():
    return make_pmma()


@pytest.fixture(scope="session")
def tungsten():
    return make_tungsten()


@pytest.fixture(scope="session")
def quartz():
    return make_quartz()


@pytest.fixture(scope="session")
def steel():
    return make_steel()


@pytest.fixture(scope="session")
def gas():
    return make_gas()


@pytest.fixture(scope="session")
def mie_gruneisen_solids(copper, aluminium, pmma, tungsten):
    """The four Mie–Grüneisen fixtures, by name."""
    return {m.name: m for m in (copper, aluminium, pmma, tungsten)}


@pytest.fixture(scope="session")
def elastic_solids(quartz, steel):
    """The two linear elastic fixtures, by name."""
    return {m.name: m for m in (quartz, steel)}


@pytest.fixture(scope="session")
def solids(mie_gruneisen_solids, elastic_solids):
    """All six solid fixtures, by name (sorted keys give hypothesis a stable order)."""
    return {**mie_gruneisen_solids, **elastic_solids}



# --- jump conditions ------------------------------------------------------------------------
def storage_rounding(material, a, b) -> float:
    """Relative resolution of a jump ``a -> b`` held as two stored states.

    The states store u, v and sigma, not their jumps: du and dv carry the absolute
    rounding ulp(u), ulp(v) of the states, and the stored stress can only match the
    EOS at the stored volume to |d sigma_H/dv| ulp(v) (large near a Hugoniot's
    limiting compression).  For the jumps the tests generate (>= ~0.1 GPa in solids)
    this is below 1e-13, so the 1e-12 tolerances are what is tested; it matters for
    weak (kPa) shocks and for gas shocks of pressure ratio ~1e4.
    """
    du, dv, ds = abs(b.u - a.u), abs(b.v - a.v), abs(b.sigma - a.sigma)
    r = 0.0
    if du > 0.0:
        r += 2.0 * (math.ulp(a.u) + math.ulp(b.u)) / du
    if dv > 0.0:
        r += 2.0 * (math.ulp(a.v) + math.ulp(b.v)) / dv
    if ds > 0.0:
        slope = abs(material.hugoniot(a, b.v)[2])
        r += 4.0 * slope * math.ulp(b.v) / ds
    return r


def assert_jump_conditions(shock, material, rel: float = 1e-12) -> None:
    """The three jump conditions of PHYSICS.md across ``shock``.

    mass U (v_b - v_a)/v0 = -(u_b - u_a); momentum rho0 U (u_b - u_a) = sigma_b - sigma_a;
    energy e_b - e_a = 1/2 (sigma_a + sigma_b)(v_a - v_b).  Each is checked relative to
    the larger of its two sides, to ``rel`` (1e-12) plus ``storage_rounding``, and the
    energy (whose terms can cancel) relative to its terms and to a few ulp of the energies.
    """
    a, b, U = shock.ahead, shock.behind, shock.speed
    tol = rel + storage_rounding(material, a, b)
    du, dv, ds = b.u - a.u, b.v - a.v, b.sigma - a.sigma
    mass = U * dv / material.v0
    assert abs(mass + du) <= tol * max(abs(mass), abs(du)), "mass jump"
    momentum = material.rho0 * U * du
    assert abs(momentum - ds) <= tol * max(abs(momentum), abs(ds)), "momentum jump"
    de, work = b.e - a.e, 0.5 * (a.sigma + b.sigma) * (a.v - b.v)
    # The work's scale is that of its terms, 1/2 (|sigma_a| + |sigma_b|)|dv|: when a
    # shock goes from tension to compression sigma_a + sigma_b cancels.
    terms = 0.5 * (abs(a.sigma) + abs(b.sigma)) * abs(a.v - b.v)
    assert abs(de - work) <= (tol * max(abs(de), terms)
                              + 4e-16 * max(abs(a.e), abs(b.e))), "energy jump"
    assert shock.direction * U > 0.0, "speed sign vs direction"


@pytest.fixture(scope="session")
def jump_conditions():
    """``assert_jump_conditions(shock, material)`` as a fixture (usable under hypothesis)."""
    return assert_jump_conditions


@pytest.fixture(scope="session")
def jump_rounding():
    """``storage_rounding(material, a, b)`` as a fixture."""
    return storage_rounding
