"""Running a scene: the engine, with the cumulative-damage loop and the error estimate.

``run(scene)`` is what users call.  A scene with a cumulative-damage criterion is run
again with each failure found inserted as a fracture (``fronttrack.damage``); with
``accuracy.estimate_error`` and simple waves present, it is run again at half the
characteristic step and the difference reported (``fronttrack.error_estimate``).
"""

from __future__ import annotations

from . import balance, fits
from .damage import run_with_damage
from .engine import Engine
from .error_estimate import estimate_error
from .scene import Scene
from .solution import Solution


def run(scene: Scene, progress=None) -> Solution:
    """Evolve ``scene`` to ``scene.t_end`` and return its ``Solution``.

    ``progress``, if given, is called as ``progress(events, t)`` every thousand events.
    The solution's ``accuracy_report`` holds the run's momentum and energy ``balance``
    (``fronttrack.balance``) and ``warnings``: one line for each balance beyond what the
    accuracy settings promise, and for each material compressed beyond its fitted data
    (``fronttrack.fits``).
    """
    if scene.spall_criterion is not None:
        solution = run_with_damage(scene, progress)
    else:
        solution = Engine(scene, progress).run()
    if scene.accuracy.estimate_error:
        estimate = (estimate_error(solution) if solution.stats["rays"] > 0
                    else {"method": "exact: no simple waves in this solution", "sigma": 0.0,
                          "u": 0.0})
        solution.accuracy_report["error_estimate"] = estimate
    report = solution.accuracy_report
    report["balance"] = balance.balance(solution)
    report["warnings"] = (report.get("warnings", []) + fits.fit_warnings(solution)
                          + balance.warnings(report, report["balance"]))
    return solution
