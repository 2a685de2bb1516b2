"""An a-posteriori error estimate for the fan discretisation.

Shocks, contacts and boundaries are exact; the only approximation in a solution
is the discretisation of simple waves into characteristics a stress step apart
(second order in the step).  Running the scene again with half the step and
comparing the records estimates the error of the coarse run: for a second-order
method the coarse error is about ``4/3`` of the difference between the two runs
(Richardson).  The comparison uses what a user reads off a solution: the probe
histories (stress and velocity, their L1 distance over the whole run), the first
spall time and position, and the largest tension.
"""

from __future__ import annotations

import dataclasses

from .engine import Engine

RICHARDSON_SECOND_ORDER = 4.0 / 3.0
"""Coarse-run error / (coarse - fine) for a second-order method at half the step."""


def refined_accuracy(accuracy, step: float):
    """The same accuracy settings with the characteristic step halved (``step``, Pa, is
    the step the coarse run used)."""
    return dataclasses.replace(accuracy, estimate_error=False, rays_per_fan=None,
                               characteristic_step=0.5 * step)


def estimate_error(solution, deadline=None) -> dict:
    """Error estimate of ``solution`` from a run of its scene at half the step.

    Returns, in SI units: ``sigma`` and ``u`` (largest estimated
    error over all probe histories, Pa and m/s), ``spall_t`` and ``spall_x``
    (s and m, ``None`` if either run has no spall), ``max_tension`` (Pa), and the
    refined run's event count.  If ``deadline`` (a ``time.perf_counter()`` value) stops
    the refined run, only ``method`` is returned, saying so.
    """
    scene = solution.scene
    step = solution.accuracy_report["characteristic_step"]
    fine = Engine(dataclasses.replace(scene, accuracy=refined_accuracy(scene.accuracy, step)),
                  deadline=deadline).run()
    if "stopped" in fine.stats:
        return {"method": "not estimated: the time limit stopped the run at half the step"}
    sigma_error = u_error = 0.0
    for probe in scene.probes:
        coarse_h, fine_h = solution.history(probe.at), fine.history(probe.at)
        d_sigma, d_u = _step_difference(coarse_h, fine_h, scene.t_end)
        sigma_error, u_error = max(sigma_error, d_sigma), max(u_error, d_u)
    spall_t = spall_x = None
    if solution.spalls and fine.spalls:
        spall_t = abs(solution.spalls[0].t - fine.spalls[0].t) * RICHARDSON_SECOND_ORDER
        spall_x = abs(solution.spalls[0].x - fine.spalls[0].x) * RICHARDSON_SECOND_ORDER
    tension = None
    coarse_tension, fine_tension = solution.max_tension(), fine.max_tension()
    if coarse_tension and fine_tension:
        tension = abs(coarse_tension["sigma"] - fine_tension["sigma"]) * RICHARDSON_SECOND_ORDER
    return {
        "method": "difference from a run at half the characteristic step, times 4/3",
        "sigma": sigma_error * RICHARDSON_SECOND_ORDER,
        "u": u_error * RICHARDSON_SECOND_ORDER,
        "spall_t": spall_t, "spall_x": spall_x, "max_tension": tension,
        "refined_events": fine.stats["events"],
    }


def _step_difference(a, b, t_end: float) -> tuple[float, float]:
    """Time-averaged |difference| of two records (stress Pa, velocity m/s).

    The average over the run, not the largest pointwise difference: two records
    whose fronts arrive a characteristic-transit apart differ by a whole step over
    that short interval, which says nothing about the accuracy of the levels.
    """
    return (a.l1_distance(b, "sigma") / t_end, a.l1_distance(b, "u") / t_end)
