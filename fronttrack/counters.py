"""What a run counted: events, lattices, and everything it neglected.

The engine fills one ``Counters`` as it goes and hands it whole to the ``Solution``,
whose ``stats`` and ``accuracy`` report read it.
"""

from __future__ import annotations

from dataclasses import dataclass, field


@dataclass
class Counters:
    """Tallies of one run.

    ``events``: events popped from the queue (the limit ``accuracy.max_events`` counts
    these; the solution's event log holds those that changed something, a lattice
    being one);
    ``lattices`` and ``nodes``: characteristic lattices solved in bulk and their nodes;
    ``riemann_solves``: events that went through the general Riemann solver;
    ``dropped_waves`` and ``dropped_stress``: waves
    weaker than the negligible stress and their total (Pa);
    ``neglected_entropy``: the largest relative volume jump of an entropy contact not
    tracked, ``neglected_contacts`` how many, ``neglected_contact_energy`` the largest
    specific energy jump (J/kg) of one whose energy was not negligible (its lower-energy
    side was kept); ``unresolved_contacts``: contacts merged
    because they were born closer than ``accuracy.contact_resolution`` to another;
    ``cavitations``: fractures of materials without a spall strength, pulled to the most
    tension their equation of state carries; ``suppressed_spalls`` and
    ``suppressed_tension`` (Pa): fractures not made because
    they fell inside an earlier fracture zone or spacing, and the largest tension so
    carried; ``coalesced``: pairs of fronts made one because they ran closer than the
    records resolve (``fronttrack.coalesce``), with the momentum (kg/(m^2 s), absolute
    sum) and energy (J/m^2, signed: never positive) their strips moved;
    ``gathered``: fronts added to an event because events piled up there
    (``fronttrack.cluster``), with the momentum (absolute sum) and energy (signed) their
    strips moved;
    ``release_floors``: for each material that released toward a lower stress than its
    equation of state reaches, the highest such floor (Pa) and how many times
    (``materials.riemann.release_target``); ``ringing``: one entry per ringing layer
    whose remaining echoes were replaced by their limit (``fronttrack.ringing``);
    ``fragments``: one entry per free fragment whose ringing went on in closed form
    (``fronttrack.fragment``);
    ``neglect_cost``: the sum of the bounds (J/m^2) on the energy the neglected entropy
    contacts that could make energy may have moved (``fronttrack.neglect``), and
    ``history_cost`` what the contacts whose yield offset or energy jump was above the
    negligible stress cost (plastic or thermal history forgotten; held to one budget for
    their sum; a thermal one counted at its bound until its carrier's next event, then
    at what it lost: ``fronttrack.neglect.hold``).
    """

    events: int = 0
    lattices: int = 0
    nodes: int = 0
    riemann_solves: int = 0
    dropped_waves: int = 0
    dropped_stress: float = 0.0
    neglected_entropy: float = 0.0
    neglected_contacts: int = 0
    neglected_contact_energy: float = 0.0
    cavitations: int = 0
    unresolved_contacts: int = 0
    suppressed_spalls: int = 0
    suppressed_tension: float = 0.0
    coalesced: int = 0
    coalesced_momentum: float = 0.0
    coalesced_energy: float = 0.0
    gathered: int = 0
    gathered_momentum: float = 0.0
    gathered_energy: float = 0.0
    release_floors: dict[str, tuple[float, int]] = field(default_factory=dict)
    ringing: list[dict] = field(default_factory=list)
    fragments: list[dict] = field(default_factory=list)
    neglect_cost: float = 0.0
    history_cost: float = 0.0

    def note_release_floor(self, name: str, stress: float) -> None:
        """Count a face of ``name`` that released only down to ``stress`` (Pa)."""
        highest, count = self.release_floors.get(name, (stress, 0))
        self.release_floors[name] = (max(highest, stress), count + 1)
