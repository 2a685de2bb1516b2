"""An a-posteriori error estimate for the fan discretisation.

Shocks, contacts and boundaries are exact; the only approximation in a
solution is the speed given to each ray of a fan (second order in the stress
step a ray carries).  Running the scene again with half the ray stress step
and comparing the records estimates the error of the coarse run: for a
second-order method the coarse error is about ``4/3`` of the difference between
the two runs (Richardson).  The comparison uses what a user reads off a
solution: the probe histories (stress and velocity, compared as step functions
over the whole run), the first spall time and position, and the largest
tension.
"""

from __future__ import annotations

import dataclasses

import numpy as np

RICHARDSON_SECOND_ORDER = 4.0 / 3.0
"""Coarse-run error / (coarse - fine) for a second-order method at half the step."""


def refined_accuracy(accuracy):
    """The same accuracy settings with half the stress step per ray."""
    accuracy = dataclasses.replace(accuracy, estimate_error=False)
    if accuracy.stress_tolerance is not None:
        return dataclasses.replace(accuracy, stress_tolerance=0.5 * accuracy.stress_tolerance)
    return dataclasses.replace(accuracy, rays_per_fan=2 * accuracy.rays_per_fan)


def estimate_error(solution, run) -> dict:
    """Error estimate of ``solution`` from a run of its scene at half the ray step.

    ``run`` is the engine's ``run`` function (passed in to keep this module free
    of the engine).  Returns, in SI units: ``sigma`` and ``u`` (largest estimated
    error over all probe histories, Pa and m/s), ``spall_t`` and ``spall_x``
    (s and m, ``None`` if either run has no spall), ``max_tension`` (Pa), and the
    refined run's event count.
    """
    scene = solution.scene
    fine = run(dataclasses.replace(scene, accuracy=refined_accuracy(scene.accuracy)))
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
        "method": "difference from a run at half the ray stress step, times 4/3",
        "sigma": sigma_error * RICHARDSON_SECOND_ORDER,
        "u": u_error * RICHARDSON_SECOND_ORDER,
        "spall_t": spall_t, "spall_x": spall_x, "max_tension": tension,
        "refined_events": fine.stats["events"],
    }


def _step_difference(a, b, t_end: float) -> tuple[float, float]:
    """Time-averaged |difference| of two step histories (stress Pa, velocity m/s).

    The average over the run, not the largest pointwise difference: two step
    functions whose steps arrive a ray-transit apart differ by a whole step over
    that short interval, which says nothing about the accuracy of the levels.
    """
    times = np.union1d(a.t, b.t)
    ends = np.append(times[1:], t_end)
    mids = 0.5 * (times + ends)
    ia = np.searchsorted(a.t, mids, side="right") - 1
    ib = np.searchsorted(b.t, mids, side="right") - 1
    widths = (ends - times) / t_end
    d_sigma = float(np.sum(np.abs(a.sigma[ia] - b.sigma[ib]) * widths))
    d_u = float(np.sum(np.abs(a.u[ia] - b.u[ib]) * widths))
    return d_sigma, d_u
