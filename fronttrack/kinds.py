"""The kinds of things a scene and its solution are made of.

String enums: a kind compares equal to its name (``FrontKind.SHOCK == "shock"``) and
prints as it, so files, plots and tests may use either.
"""

from __future__ import annotations

from enum import StrEnum


class FrontKind(StrEnum):
    """What a front is.

    ``SHOCK``: a jump satisfying the Rankine–Hugoniot conditions (also the rarefaction
    shocks of Hugoniot release and of linear elastic solids); ``RAY``: one
    characteristic of a simple wave; ``INTERFACE``: the contact between two layers;
    ``CONTACT``: an entropy jump left inside a material by an interaction; ``GAP``: an
    interface or spall plane that has opened (two free surfaces); ``BOUNDARY``: an end
    of the stack.
    """

    SHOCK = "shock"
    RAY = "ray"
    INTERFACE = "interface"
    CONTACT = "contact"
    GAP = "gap"
    BOUNDARY = "boundary"

    @property
    def is_site(self) -> bool:
        """Sites do not move in X: interfaces, contacts, gaps and boundaries."""
        return self in _SITES


_SITES = frozenset({FrontKind.INTERFACE, FrontKind.CONTACT, FrontKind.GAP, FrontKind.BOUNDARY})
SITE_KINDS = tuple(sorted(_SITES))
WAVE_KINDS = (FrontKind.SHOCK, FrontKind.RAY)


class EventKind(StrEnum):
    """What happened at an event."""

    IMPACT = "impact"
    COLLISION = "collision"
    OVERTAKE = "overtake"
    TRANSMISSION = "transmission"
    REFLECTION = "reflection"
    BOUNDARY = "boundary"
    GAP_OPEN = "gap-open"
    GAP_CLOSE = "gap-close"
    SPALL = "spall"
    LATTICE = "lattice"
    SHOCK_FORMATION = "shock-formation"
    INITIATION = "initiation"
    RINGING = "ringing"


class BoundaryKind(StrEnum):
    """The condition at an end of the stack."""

    FREE = "free"
    WALL = "wall"
    VELOCITY = "velocity"
    STRESS = "stress"


class Bond(StrEnum):
    """Whether a contact carries tension."""

    BONDED = "bonded"
    UNBONDED = "unbonded"


class Release(StrEnum):
    """The unloading path: the isentrope (physical) or the Hugoniot (the impedance-match
    shortcut, rarefaction shocks)."""

    ISENTROPE = "isentrope"
    HUGONIOT = "hugoniot"
