"""The records made at every event keep their dataclass behaviour with the faster
``__init__`` of ``materials.frozen.slot_init``, and the event log's ``log`` stores what
``append`` stores."""

from __future__ import annotations

import copy
import dataclasses
import math
import pickle

import pytest

from fronttrack.event_log import EventLog, EventRecord
from fronttrack.outgoing import WaveSpec
from materials import RiemannSolution, Shock, State
from materials.frozen import slot_init


def test_a_state_is_still_a_frozen_dataclass_of_its_fields():
    state = State(1.5e9, 20.0, 1.2e-4, 3.0e3)
    assert state.plastic_strain == 0.0  # the default of the field
    assert (state.sigma, state.u, state.v, state.e) == (1.5e9, 20.0, 1.2e-4, 3.0e3)
    same = State(sigma=1.5e9, u=20.0, v=1.2e-4, e=3.0e3, plastic_strain=0.0)
    assert state == same and hash(state) == hash(same)
    assert state != State(1.5e9, 20.0, 1.2e-4, 3.0e3, 1e-3)
    with pytest.raises(dataclasses.FrozenInstanceError):
        state.sigma = 0.0
    moved = dataclasses.replace(state, u=-5.0)
    assert (moved.u, moved.sigma) == (-5.0, 1.5e9)
    assert pickle.loads(pickle.dumps(state)) == state == copy.copy(state)
    assert repr(state) == ("State(sigma=1500000000.0, u=20.0, v=0.00012, e=3000.0, "
                           "plastic_strain=0.0)")


def test_waves_solutions_and_specs_keep_their_fields_and_defaults():
    ahead, behind = State(0.0, 0.0, 1e-4, 0.0), State(1e9, 10.0, 0.99e-4, 5.0)
    shock = Shock(ahead, behind, 5983.0, 1)
    assert (shock.ahead, shock.behind, shock.speed, shock.direction) == (ahead, behind, 5983.0, 1)
    solution = RiemannSolution((), (shock,), ahead, behind)
    assert solution.separated is False and math.isnan(solution.bonded_sigma)
    assert solution.release_floor is None
    assert solution.fronts_in_order() == [shock]
    spec = WaveSpec(None, ahead, behind, table=None)
    with pytest.raises(dataclasses.FrozenInstanceError):
        spec.table = 1


def test_slot_init_refuses_a_class_it_would_change():
    @dataclasses.dataclass(frozen=True, slots=True)
    class Listed:
        items: list = dataclasses.field(default_factory=list)

    with pytest.raises(TypeError, match="Listed needs the generated __init__"):
        slot_init(Listed)


def test_logging_fields_stores_what_appending_a_record_stores():
    record = EventRecord(t=1e-6, x=2e-3, kind="collision", incoming=[3, 4], outgoing=[7],
                         site=None)
    appended, logged = EventLog(), EventLog()
    appended.append(record)
    appended.append(dataclasses.replace(record, kind="transmission", site=9, nodes=2))
    logged.log(1e-6, 2e-3, "collision", [3, 4], [7])
    logged.log(1e-6, 2e-3, "transmission", [3, 4], [7], 9, 2)
    assert list(appended) == list(logged)
    assert logged[1] == EventRecord(t=1e-6, x=2e-3, kind="transmission", incoming=[3, 4],
                                    outgoing=[7], site=9, nodes=2)
