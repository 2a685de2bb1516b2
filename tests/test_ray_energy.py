"""The energy a ray creates (``characteristics.ray_energy``).

A ray is a jump between two cells of one isentrope.  At the characteristic speed of its
middle state an expansion ray creates energy, third order in its step; a compression ray
loses it.  The tests take the states from the exact wave curve of LiF (Mie-Grueneisen,
library parameters) and the residuals from the jump conditions, independently of the
engine; then the state behind a ray that carries the energy its jump needs
(``conserving_state``), and the two campaign seeds whose rays created energy, inline.
"""

import math

import pytest

from characteristics.ray_energy import conserving_state, energy_residual, volume_at_energy
from fronttrack.runner import run
from fronttrack.scene import Accuracy, Boundary, Layer, Scene
from materials import LEFT, RIGHT, IdealGas, State
from materials.library import get

LIF = get("LiF")
SHOCKED = LIF.wave_curve(LIF.reference_state(), RIGHT).state_at(20e9)
"""LiF behind a 20 GPa shock (u about 1.2 km/s): the isentropes below start here."""


def _triple(s):
    return s.sigma, s.u, s.e


def _ray(direction: int, jump: float, expansion: bool):
    """A ray of ``direction`` on the isentrope of ``SHOCKED`` whose stress jump is ``jump``
    (Pa) about 10 GPa: ``(ahead, behind, speeds)`` with the cells as ``(sigma, u, e)`` and
    the sound speeds of the ahead cell, of the middle state and of the behind cell."""
    curve = LIF.wave_curve(SHOCKED, direction)  # J_{-d} of SHOCKED held: both families
    high, middle, low = (curve.state_at(10e9 + k * jump) for k in (0.5, 0.0, -0.5))
    ahead, behind = (high, low) if expansion else (low, high)
    speeds = tuple(LIF.sound_speed(s.v, s.e) for s in (ahead, middle, behind))
    return _triple(ahead), _triple(behind), speeds


def _residuals(direction, ahead, behind, speed):
    """Energy (W/m^2) and momentum (Pa) residuals of the jump at ``speed`` (m/s)."""
    left, right = (behind, ahead) if direction > 0 else (ahead, behind)
    rho0 = LIF.rho0
    momentum = rho0 * speed * (left[1] - right[1]) - (left[0] - right[0])
    return energy_residual(rho0, speed, left, right), momentum


@pytest.mark.parametrize("direction", [RIGHT, LEFT])
def test_an_expansion_ray_creates_energy_third_order_in_its_step(direction):
    jumps = (2e9, 1e9, 0.5e9)
    created, momenta = [], []
    for jump in jumps:
        ahead, behind, speeds = _ray(direction, jump, expansion=True)
        energy, momentum = _residuals(direction, ahead, behind, direction * speeds[1])
        assert energy > 0.0
        created.append(energy)
        momenta.append(abs(momentum))
        # no speed is both momentum-exact and energy-conserving: at the chord speed
        # (R_p = 0, inside the band of the two cells' speeds) it still creates
        chord = (behind[0] - ahead[0]) / (LIF.rho0 * (behind[1] - ahead[1]))
        assert min(speeds[0], speeds[2]) < abs(chord) < max(speeds[0], speeds[2])
        assert _residuals(direction, ahead, behind, chord)[0] > 0.0
    for k in range(len(jumps) - 1):
        # halving the step divides both residuals by eight (third order)
        assert created[k] / created[k + 1] == pytest.approx(8.0, rel=0.15)
        assert momenta[k] / momenta[k + 1] == pytest.approx(8.0, rel=0.15)


@pytest.mark.parametrize("direction", [RIGHT, LEFT])
def test_a_compression_ray_loses_energy_third_order_in_its_step(direction):
    losses = []
    for jump in (2e9, 1e9):
        ahead, behind, speeds = _ray(direction, jump, expansion=False)
        losses.append(_residuals(direction, ahead, behind, direction * speeds[1])[0])
        assert losses[-1] < 0.0
    assert losses[0] / losses[1] == pytest.approx(8.0, rel=0.15)


def _state(triple) -> State:
    """The LiF state of stress, velocity and energy ``triple`` (its volume from the EOS)."""
    sigma, u, e = triple
    v = LIF.v0
    for _ in range(60):  # secant on the stress at this energy (monotone in v)
        h = 1e-7 * v
        slope = (LIF.stress(v + h, e) - LIF.stress(v, e)) / h
        v -= (LIF.stress(v, e) - sigma) / slope
    return State(sigma=sigma, u=u, v=v, e=e)


@pytest.mark.parametrize("direction", [RIGHT, LEFT])
def test_the_state_behind_an_expansion_ray_carries_the_energy_its_jump_needs(direction):
    shifts = []
    for jump in (2e9, 1e9):
        ahead, behind, speeds = _ray(direction, jump, expansion=True)
        speed = direction * speeds[1]
        b = _state(behind)
        shifted = conserving_state(LIF, speed, _state(ahead), b)
        # stress and velocity held (so the Riemann invariants), stress consistent with
        # the new energy and volume to the EOS's rounding
        assert (shifted.sigma, shifted.u) == (b.sigma, b.u)
        assert LIF.stress(shifted.v, shifted.e) == pytest.approx(b.sigma, rel=1e-9)
        # the jump conserves energy to rounding of the energy flux it carries
        energy, _ = _residuals(direction, ahead, (shifted.sigma, shifted.u, shifted.e),
                               speed)
        flux = abs(b.sigma * b.u) + LIF.rho0 * abs(speed) * abs(b.e)
        assert abs(energy) <= 1e-10 * flux
        shifts.append(shifted.e - b.e)
    # the energy comes from the state behind (below the isentrope), third order in the step
    assert shifts[0] < 0.0 and shifts[1] < 0.0
    assert shifts[0] / shifts[1] == pytest.approx(8.0, rel=0.15)


@pytest.mark.parametrize("direction", [RIGHT, LEFT])
def test_the_state_behind_a_compression_ray_is_left_as_it_is(direction):
    # a compression ray loses energy: it may, as a dropped wave does
    ahead, behind, speeds = _ray(direction, 2e9, expansion=False)
    b = _state(behind)
    assert conserving_state(LIF, direction * speeds[1], _state(ahead), b) is b


def test_a_ray_whose_state_behind_cannot_give_the_energy_keeps_that_state():
    # a gas state at 100 Pa behind a ray that would create more energy than the state
    # holds: at its stress no state of the energy asked for exists (e < 0), so it keeps
    # its own (campaign seed 235 crashed in a Riemann solve from such a state)
    gas = IdealGas("g", 1.4, 1.0)
    ahead = State(sigma=1e5, u=0.0, v=1.0, e=1e5 / 0.4)
    behind = State(sigma=1e2, u=1000.0, v=100.0, e=1e4 / 0.4)
    assert conserving_state(gas, 100.0, ahead, behind) is behind


def _campaign_180() -> Scene:
    """Campaign seed 180: LiF 10 um at 1.5 km/s (0.16 GPa) on W 10 um and a 50 um
    PS_foam layer at 500 m/s, unbonded; a free face and a piston pulling at 100 m/s; two
    rays per fan.  The LiF layer rings, and its release rays reach 6.4 GPa of tension."""
    layers = (Layer(get("LiF"), 1e-05, 1500.0, stress=162114082.31419194, bond="bonded"),
              Layer(get("W"), 1e-05, 0.0, bond="bonded"),
              Layer(get("PS_foam"), 5e-05, 500.0, bond="unbonded"))
    return Scene(layers=layers, t_end=4.5238754015433675e-08, left=Boundary("free"),
                 right=Boundary("velocity", ((0.0, 0.0), (1.3571626204630101e-08, -100.0))),
                 accuracy=Accuracy(rays_per_fan=2))


def _campaign_327() -> Scene:
    """Campaign seed 327: 1 mm of gas (gamma 1.4, 1.06 MPa) at -300 m/s bonded to 50 um
    of Cu; free faces.  The gas expands to vacuum in a fan of eight rays."""
    gas = IdealGas("M0", 1.4, 10.935565333808952)
    layers = (Layer(gas, 0.001, -300.0, stress=1063999.221645791, bond="bonded"),
              Layer(get("Cu"), 5e-05, 0.0, bond="bonded"))
    return Scene(layers=layers, t_end=3.4627918699298446e-06, left=Boundary("free"),
                 right=Boundary("free"), accuracy=Accuracy(rays_per_fan=8))


def test_campaign_180_a_ringing_lif_layer_creates_no_energy():
    # +14.7 % before the states behind expansion rays carried the energy their jumps need
    # (8.9 GPa rays, two per fan); now it loses 4.8 % (its compression rays lose energy)
    balance = run(_campaign_180()).accuracy_report["balance"]
    assert balance["energy_error"] <= 0.0


def test_campaign_327_a_gas_fan_to_vacuum_keeps_its_promise():
    # +0.63 % before (promise 0.2 %), +0.050 % with the shift of the states behind
    # expansion rays; its momentum, 0.53 % (the fans' rays, third order each), is
    # within the promise (0.057 %, energy -0.030 %) since a gas's rays span at most
    # step / stress_scale of its sound speed over the square root of its share of the
    # energy (``fronttrack.resolution.sound_bound``): 50 m/s, not 231
    balance = run(_campaign_327()).accuracy_report["balance"]
    assert abs(balance["energy_error"]) <= balance["promised"]
    assert balance["momentum_error"] <= balance["promised"]


def _gas_against_a_wall(accuracy: Accuracy | None = None) -> Scene:
    """The first layer of campaign seed 652 alone: 50 um of gas (gamma 1.4, 1.7 MPa,
    c = 228 m/s) between a wall and a free face, for 1.12 us (five transits).  It
    expands to vacuum (escape speed 1 141 m/s) and rings against the wall."""
    gas = IdealGas("M0", 1.4, 45.71519779492362)
    return Scene(layers=(Layer(gas, 5e-05, 0.0, stress=1700950.3252249027),),
                 t_end=1.11842509305313e-06, left=Boundary("wall"), right=Boundary("free"),
                 accuracy=accuracy if accuracy is not None else Accuracy())


def test_a_gas_ringing_against_a_wall_creates_no_energy_beyond_its_promise():
    # campaign seed 652 (three gas layers against a wall) created 1.97 % (promise 0.2 %),
    # +1.85 % on its lattices' rays; this layer alone created 0.54 % (momentum 0.46 %).
    # The scene's velocity step (161 m/s, 0.14 of the escape speed) was 0.7 of the gas's
    # own sound speed, and a ray makes energy at (gamma + 1) rho du^3 / 16, second order
    # per transit in du / c.  With rays of at most step / stress_scale of c (32 m/s):
    # -0.024 %, momentum 0.16 %; at 8, 16, 32 rays per fan the momentum falls
    # 0.12, 0.031, 0.0078 % (second order), as it did not before (0.56, 0.057, 0.002 %,
    # and +0.87, +0.19, +0.044 % energy created)
    balance = run(_gas_against_a_wall()).accuracy_report["balance"]
    assert abs(balance["energy_error"]) <= balance["promised"]
    assert balance["momentum_error"] <= balance["promised"]
    fine = run(_gas_against_a_wall(Accuracy(rays_per_fan=16))).accuracy_report["balance"]
    assert abs(fine["energy_error"]) <= balance["promised"] / 16
    assert fine["momentum_error"] <= balance["momentum_error"] / 3


def test_a_gas_fan_spans_at_most_the_relative_step_of_its_sound_speed():
    # the velocity step of a gas's characteristics is bounded by step / stress_scale of
    # the larger Eulerian sound speed of the states they join (no lower than half the
    # initial one: a wave to vacuum, c = 0) over the square root of the gas's share of
    # the initial energy (its internal energy over the content of all layers); in a
    # solid (du / c = d sigma / (rho0 C_L^2), far below the relative step) the bound does
    # not act and the scene's velocity step stays
    from fronttrack.engine import Engine
    from fronttrack.resolution import SOUND_FLOOR
    engine = Engine(_gas_against_a_wall())
    res = engine.resolution
    gas = engine.scene.layers[0].material
    start = engine.initial_states[0]
    c = gas.eulerian_sound_speed(start.v, start.e)
    relative = res.step / res.stress_scale
    vacuum = State(sigma=0.0, u=1141.0, v=math.inf, e=0.0)
    assert res.velocity_step_of(gas, start, vacuum) == pytest.approx(relative * c, rel=1e-12)
    assert res.velocity_step_of(gas, start) < res.velocity_step / 4
    assert res.velocity_step_of(gas, vacuum) == pytest.approx(relative * SOUND_FLOOR * c,
                                                              rel=1e-12)
    compressed = gas.initial_state(4.0 * start.sigma, 0.0)  # on its Hugoniot: hotter
    assert res.velocity_step_of(gas, compressed) == pytest.approx(
        min(res.velocity_step, relative * gas.eulerian_sound_speed(compressed.v,
                                                                  compressed.e)), rel=1e-12)
    # beside 20 um of copper at 100 m/s (81 % of the energy) the bound is 1/sqrt(0.19)
    # = 2.3 times wider; beside 10 mm of it, the gas holds 0.05 % and is not refined
    cu = get("Cu")
    for thickness in (2e-5, 1e-2):
        scene = Scene(layers=(engine.scene.layers[0], Layer(cu, thickness, 100.0)),
                      t_end=1e-7)
        mixed = Engine(scene).resolution
        gas_energy = gas.rho0 * 5e-05 * start.e
        share = gas_energy / (gas_energy + cu.rho0 * thickness * 0.5 * 100.0**2)
        expected = min(mixed.velocity_step,
                       mixed.step / mixed.stress_scale * c / math.sqrt(share))
        assert mixed.velocity_step_of(gas, start) == pytest.approx(expected, rel=1e-12)
        assert mixed.velocity_step_of(cu, cu.reference_state()) == mixed.velocity_step
    assert share < 1e-3 and mixed.velocity_step_of(gas, start) == mixed.velocity_step
    shocked = Engine(Scene(layers=(Layer(cu, 1e-3, 500.0), Layer(cu, 1e-3)), t_end=1e-7))
    assert shocked.resolution.velocity_step_of(cu, cu.reference_state()) == \
        shocked.resolution.velocity_step


def _off_table(table, state: State, gap: float) -> State:
    """``state`` at its stress and velocity with the energy (and the volume) that put it
    ``gap`` (Pa, a stress gap at equal volume) off ``table``, below its isentrope."""
    m = table.material
    slope = m.stress(state.v, state.e + 1.0) - m.stress(state.v, state.e)  # Pa per J/kg
    e = state.e - gap / slope
    return State(sigma=state.sigma, u=state.u, v=volume_at_energy(m, state.v, state.e, e), e=e)


def test_a_cell_shifted_off_its_table_joins_a_zone_within_the_tolerance_of_its_offset():
    # campaign seed 340 (five metal layers): a cell behind expansion rays lies 2.3 times
    # the tables' tolerance below its table (the energy the rays' jumps took), and a
    # zone's table made near it 1.2 tolerances away; judged from its state alone the cell
    # was off the zone's table, the zone shrank and its lattices fell apart (2 869 events
    # before the shift, the 10 s time limit with it).  A cell is on a zone's table within
    # the tolerance plus its own table's offset; a cell on its own table, no wider.
    from fronttrack.engine import Engine
    from fronttrack.zones import _on
    al = get("Al1100")
    engine = Engine(Scene(layers=(Layer(al, 1e-3, 500.0), Layer(al, 1e-3)), t_end=1e-7))
    tol = engine.tables.tolerance
    on_own = al.wave_curve(al.reference_state(), RIGHT).state_at(2e9)
    own = engine.tables.table(al, on_own)
    shifted = _off_table(own, on_own, 2.3 * tol)
    near = engine.tables.table(al, _off_table(own, on_own, 1.1 * tol))
    assert near is not own and near.stress_gap(shifted) == pytest.approx(1.2 * tol, rel=0.05)
    cell = engine.new_region(shifted, al, 0, 0.0, (0.0, 0.0), (1e-4, 0.0), table=own)
    assert own.stress_gap(cell.state) == pytest.approx(2.3 * tol, rel=0.05)
    assert _on(engine, cell, near)
    plain = engine.new_region(on_own, al, 0, 0.0, (0.0, 0.0), (1e-4, 0.0), table=own)
    assert near.stress_gap(plain.state) == pytest.approx(1.1 * tol, rel=0.05)
    assert not _on(engine, plain, near)


def test_a_zone_leaves_out_a_colder_isentrope_whose_sweep_would_create_energy():
    # 3 mm of LiF at 100 m/s onto a wall, free at the left (issue 12): the recompression
    # near the free face steepens into a shock that leaves what it crosses 44.6 J/kg above
    # the first shock's isentrope, 193 kPa at equal volume, within the tables' tolerance of
    # 197 kPa.  A zone on the hotter table took the 2.7 mm still on the colder one and its
    # nodes replaced them by the hotter states: +0.76 % of the energy, the lattices' events
    # +0.85 %, against a promise of 0.2 % (63 events).  A zone takes a cell of another
    # table only if the energy its rays may make or lose sweeping the material between the
    # sites around it is within the budget of a neglected entropy contact (``zones._takes``).
    scene = Scene(layers=(Layer(LIF, 3e-3, 100.0),), t_end=10e-6,
                  left=Boundary("free"), right=Boundary("wall"))
    balance = run(scene).accuracy_report["balance"]
    assert balance["energy_error"] <= 0.0  # nothing created
    assert -balance["energy_error"] <= balance["promised"]


def test_a_balance_beyond_its_promise_names_the_fans_step_as_well():
    """Energy made by coarse fans (a characteristic's third-order defect, cells on a
    nearby isentrope table) is not the dropped waves' doing alone: the warning names
    both settings, and without dropped waves the fans' step only."""
    from fronttrack import balance

    entry = {"momentum_error": 0.0, "energy_error": 0.0076, "promised": 0.002}
    dropped = balance.warnings({"dropped_waves": 40, "negligible_stress": 1.97e5}, entry)
    assert len(dropped) == 1 and "energy created: 0.0076" in dropped[0]
    assert "accuracy.negligible_stress" in dropped[0] and "accuracy.rays_per_fan" in dropped[0]
    (none,) = balance.warnings({"dropped_waves": 0, "negligible_stress": 1.97e5}, entry)
    assert "accuracy.rays_per_fan" in none and "negligible_stress" not in none
