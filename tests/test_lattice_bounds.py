"""A characteristic lattice stops before anything it does not model reaches it
(``characteristics.lattice``): here, a shock bounding a zone whose last slot is a contact
every ray has already passed.  Before, nothing watched that end: the zone ran on until
a ray reflected from the free surface came back through the contact, and its rays were
spliced beyond the shock, which had crossed the contact meanwhile (the list of fronts
out of order; the isolated stack of ``tests/test_conservation_bugs.py`` created 23 % of
its energy that way at 4 characteristics per fan)."""

import math

import numpy as np
import pytest

from characteristics import lattice as moc
from characteristics.isentrope import IsentropeTables
from materials import get


def test_a_bound_reaching_a_site_at_the_end_of_a_zone_stops_it():
    cu = get("Cu")
    rest = cu.initial_state(0.0, 0.0)
    table = IsentropeTables().table(cu, rest)
    jp, jm = table.invariants(rest)
    # a C- characteristic at 1.5 mm runs into material at rest (left of it) from a state
    # 2 m/s behind it (J+ is constant across it); a contact at 1 mm, a free face at 0
    step = -4.0  # J- = u - phi drops by 2 du across it
    own = jm + 0.5 * step
    speed = table.speed(jp, own)
    bound_speed = -1.01 * speed  # a shock behind it, slightly faster
    zone = moc.Zone(
        table=table, family=np.array([0, -1], dtype=np.int8),
        own=np.array([math.nan, own]), x0=np.array([1e-3, 1.5e-3]), t0=np.zeros(2),
        speed=np.array([0.0, -speed]), jp=np.full(3, jp),
        jm=np.array([jm, jm, jm + step]),
        left=moc.Reflector(0.0, "stress", 0.0), right=moc.Bound(2e-3, 0.0, bound_speed),
        t_now=0.0, horizon=math.inf, sites=(moc.Site(moc.PASS, 1e-3),))
    lattice = moc.solve(zone)
    # the shock reaches the contact at 1 mm / |U|: the zone must stop by then (the ray
    # passed the contact at 0.5 mm / c, and comes back to it only at 2.5 mm / c)
    arrival = 1e-3 / abs(bound_speed)
    assert lattice.cut == pytest.approx(arrival, rel=1e-12)
    assert lattice.reason == "right bound"
    assert 0.5e-3 / speed < lattice.cut < 2.5e-3 / speed
