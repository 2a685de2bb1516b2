"""The balance attribution of ``benchmarks/balance_attribution.py`` accounts for a run's
whole residual, in energy and in momentum.

Between two events every front is straight and every region constant, so the residual of
a run is the sum over fronts of each front's flux residual times the time it lived, plus
the changes at events (``balance_attribution.Attribution``).  The stress terms of the
fronts' rates telescope into the boundaries' flux, so only a scene whose boundaries push
can tell their sign: campaign seed 433 (10 mm of gas at 2.6 MPa, 3 mm of finite-plastic
solid at -300 m/s and 3 mm of LiF in tension against a wall on the right; 738 events)
feels the wall's stress all run long.
"""

import sys
from pathlib import Path
from types import SimpleNamespace

import pytest

from fronttrack import coalesce, fragment, ringing, zones
from fronttrack import engine as engine_module
from fronttrack.runner import run

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "benchmarks"))

import balance_attribution  # noqa: E402
from random_scenes import campaign_scene  # noqa: E402

PATCHED = [(engine_module.Engine, "_process"), (engine_module.outgoing, "wave_fronts"),
           (engine_module.Engine, "_entropy_contact"), (coalesce, "_replace"),
           (zones, "try_zone"), (fragment, "try_replace"), (ringing, "try_end")]
"""What ``Attribution.install`` patches (restored after each test)."""


@pytest.mark.parametrize("quantity", [balance_attribution.ENERGY, balance_attribution.MOMENTUM],
                         ids=lambda q: q.name)
def test_attribution_sums_to_the_residual(monkeypatch, quantity):
    """The fronts' and the events' shares add up to the run's residual (J/m^2 or
    kg/(m s)) to rounding; a rate of the wrong sign in a front's stress term would leave
    twice the wall's impulse unaccounted for."""
    for owner, name in PATCHED:
        monkeypatch.setattr(owner, name, getattr(owner, name))
    attribution = balance_attribution.Attribution(quantity)
    attribution.install()
    solution = run(campaign_scene(433, max_events=200_000))
    attribution.advance(solution.scene.t_end)
    conservation = solution.conservation()
    assert abs(conservation["impulse"]) > 0.01 * conservation["momentum_scale"]
    attribution.jumps["lattice"] += attribution.work - conservation[quantity.boundary]
    total = sum(attribution.by_tag.values()) + sum(attribution.jumps.values())
    assert total == pytest.approx(conservation[quantity.error],
                                  abs=1e-9 * conservation[quantity.scale])


def test_windows_of_time_split_the_whole_residual(monkeypatch):
    """``--windows`` splits what the fronts made and the changes at events over windows
    of simulated time without losing any (J/m^2, to rounding of the energy content); the
    symmetric Al 2024 impact of ``--al`` to 1.2 us at 4 rays (spall at about 1 us) puts
    its neglected contacts' losses in more than one window."""
    for owner, name in PATCHED:
        monkeypatch.setattr(owner, name, getattr(owner, name))
    args = SimpleNamespace(seed=None, scene=None, al=1.2, rays=4)
    scene, name = balance_attribution._scene(args)
    assert name == "symmetric Al to 1.2 us, 4 rays" and scene.t_end == pytest.approx(1.2e-6)
    attribution = balance_attribution.Attribution(balance_attribution.ENERGY, scene.t_end / 4)
    attribution.install()
    solution = run(scene)
    attribution.advance(solution.scene.t_end)
    scale = solution.conservation()["energy_scale"]
    total = sum(attribution.by_tag.values()) + sum(attribution.jumps.values())
    windows = [sum(counter.values()) for counter in attribution.by_window.values()]
    assert sum(windows) == pytest.approx(total, abs=1e-12 * scale)
    assert set(attribution.by_window) <= set(range(5))
    assert sum(abs(w) > 1e-7 * scale for w in windows) >= 2
