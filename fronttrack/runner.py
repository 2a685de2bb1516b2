"""Running a scene: the engine, with the cumulative-damage loop and the error estimate.

``run(scene)`` is what users call.  A scene with a cumulative-damage criterion is run
again with each failure found inserted as a fracture (``fronttrack.damage``); with
``accuracy.estimate_error`` and simple waves present, it is run again at half the
characteristic step and the difference reported (``fronttrack.error_estimate``).
``accuracy.max_seconds`` bounds the wall-clock time of all these runs together: the
run under way when it passes stops where it is (``Engine.stop_early``).
"""

from __future__ import annotations

import time

from . import balance, collector, fits, viscoplastic_scene
from .damage import run_with_damage
from .engine import Engine
from .error_estimate import estimate_error
from .errors import SceneError
from .scene import Scene
from .solution import Solution


def run(scene: Scene, progress=None) -> Solution:
    """Evolve ``scene`` to ``scene.t_end`` and return its ``Solution``.

    ``progress``, if given, is called as ``progress(events, t)`` every thousand events.
    The solution's ``accuracy_report`` holds the run's momentum and energy ``balance``
    (``fronttrack.balance``) and ``warnings``: one line for each balance beyond what the
    accuracy settings promise, and for each material compressed beyond its fitted data
    (``fronttrack.fits``).
    With ``accuracy.max_seconds`` the solution may end before ``t_end``; its
    ``stats["stopped"]`` then says when and why.  A scene with a viscoplastic layer is
    solved on its characteristic grid instead (``fronttrack.viscoplastic_scene``): a
    ``GridSolution`` with the same probe records.  Python's cyclic garbage collector is
    paused meanwhile (``fronttrack.collector``).
    """
    with collector.paused():
        return _run(scene, progress)


def _run(scene: Scene, progress=None) -> Solution:
    """``run`` itself, with the collector as it is."""
    if not isinstance(scene, Scene):
        raise SceneError(f"scene: expected a Scene (ft.load_scene reads a scene file), "
                         f"got {scene!r:.60}")
    if viscoplastic_scene.applies(scene):     # relaxation between fronts: the grid
        return viscoplastic_scene.run(scene)
    limit = scene.accuracy.max_seconds
    deadline = None if limit is None else time.perf_counter() + limit
    if scene.spall_criterion is not None:
        solution = run_with_damage(scene, progress, deadline)
    else:
        solution = Engine(scene, progress, deadline=deadline).run()
    if scene.accuracy.estimate_error:
        if "stopped" in solution.stats:
            estimate = {"method": "not estimated: the run stopped before t_end"}
        elif solution.stats["rays"] == 0:
            estimate = {"method": "exact: no simple waves in this solution", "sigma": 0.0,
                        "u": 0.0}
        else:
            estimate = estimate_error(solution, deadline)
        solution.accuracy_report["error_estimate"] = estimate
    report = solution.accuracy_report
    report["balance"] = balance.balance(solution)
    cavitated = ([f"{report['cavitations']} fracture(s) where a material without a spall "
                  "strength was pulled to the most tension its equation of state carries "
                  "(cavitation; see spall)"] if report.get("cavitations") else [])
    floors = [f"{name}: a face released toward zero stress stopped at {floor['stress'] / 1e9:.4g} "
              "GPa, the lowest its equation of state reaches on the release path (the end of "
              "its volume range); the expansion beyond (melt, vapour) is not modelled and the "
              f"stress kept there loses energy ({floor['faces']} face event(s))"
              for name, floor in report.get("release_floors", {}).items()]
    report["warnings"] = (report.get("warnings", []) + cavitated + floors
                          + fits.fit_warnings(solution)
                          + balance.warnings(report, report["balance"]))
    return solution
