"""The exact Jacobian of a fit's residuals by forward sensitivities (docs/theory.md T-10.7, T-10.8,
docs/fit.md "Speed"): one run of the core's variational equations replaces the 2k runs of the forward
model a central-difference Jacobian of k unknowns costs. For the rod models (``_core.sensitivities``)
DOP853 carries the state and its derivatives by θ₀, φ₀ [rad], θ̇₀, φ̇₀ [rad/s], l [m], g [m/s²],
damping [1/s], drag [1/m], friction [rad/s²]; for the swinging spring
(``spring_model.motion_tangents``) the triple jump carries them by the start's angles, rates, r₀ [m]
and ṙ₀ [m/s] and by the stiffness [N/m], mass [kg], rest length [m] and g [m/s²].

The residuals r = (y − ŷ(x(τ), v(τ), p))/σ depend on a parameter p both through the motion and
directly (g in the specific force, the pivot offsets, the sensor offsets). The column of p is the total
derivative

∂r/∂p = [r(p + h, x + h ∂x/∂p, v + h ∂v/∂p) − r(p − h, x − h ∂x/∂p, v − h ∂v/∂p)]/(2h),

a central difference of the *cheap* map (motion → predictions, no integration) along the exact
tangent: its error is O(h²) times the map's curvature (h = 10⁻⁶ of the parameter's scale gives
≈ 1e-12 relative), not the integrator's; at a lower bound of the registry (drag = 0) the second-order
one-sided difference is taken. ``t_offset`` moves the clock: ∂x/∂t_offset = −v,
∂v/∂t_offset = −ẍ. Parameters that enter only the predictions (pivot and sensor offsets, ``scale``,
``mass``) have a zero tangent. Any other parameter (a rotating frame's rate, a forcing, a tilt of
gravity) gets a central difference of the full residuals, and the models without sensitivities
(the pivot models) give ``None``: the caller then differences as before.
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np

from .._core import RunOptions, sensitivities, sensitivity_params
from ..model import FloatArray, Pendulum
from ..variants.spring import SwingingSpring
from . import spring_model
from .problem import ATOL, RTOL, STATE_NAMES, Motion, Problem, model_params

SENSITIVE = tuple(sensitivity_params())
MODELS = ("ideal", "damped", "rotating", "spring")
MOTIONLESS = {"pivot_x", "pivot_y", "pivot_z", "scale", "mass", "angle_offset", "force_bias", "rate_bias"}


def _tangents(
    values: Mapping[str, float], p: Pendulum | SwingingSpring, tau: FloatArray
) -> tuple[FloatArray, FloatArray, FloatArray, FloatArray, tuple[str, ...]]:
    """x [m], v [m/s] (N, 3) at the model times ``tau`` [s] and their derivatives (N, 3, k) by the
    names returned: the rod's by :data:`SENSITIVE` (T-10.7), the spring's by
    ``spring_model.TANGENT_NAMES`` (T-10.8)."""
    if isinstance(p, SwingingSpring):
        return (*spring_model.motion_tangents(values, tau), spring_model.TANGENT_NAMES)
    angles = [float(values[k]) for k in STATE_NAMES]
    return (*sensitivities(p.spec, angles, tau, RunOptions(rtol=RTOL, atol=ATOL * p.length)), SENSITIVE)


def _acceleration(p: Pendulum | SwingingSpring, x: FloatArray, v: FloatArray, tau: FloatArray) -> FloatArray:
    """ẍ [m/s²] (N, 3) of the model at the states x [m], v [m/s] at the model times ``tau`` [s]."""
    if isinstance(p, SwingingSpring):
        return spring_model.acceleration(x, p.k_over_m, p.rest_length, p.g)
    return np.asarray(p.diagnostics(x, v, tau)["acceleration"])


def exact_jacobian(
    problem: Problem, values: Mapping[str, float], sigma: Mapping[str, float], step: float = 1e-6
) -> FloatArray | None:
    """∂r/∂u for the free parameters ``problem.free`` at ``values`` (columns in their units), from one
    run of the forward sensitivities; ``None`` for a model the core has none for (the pivot models)
    or a clock offset that starts the model before its start state. A model that cannot be
    run there raises as :meth:`Problem.residuals` does (``InvalidInputError``, ``IntegrationError``).
    ``problem.evaluations`` counts the sensitivity run as one model run (plus two per column that had
    to be differenced), not the predictions it moves."""
    if problem.model not in MODELS:
        return None
    p = problem.pendulum(values)
    tau = problem.obs.t - problem.t0 - values.get("t_offset", 0.0)
    if tau.size == 0 or float(tau.min()) < 0.0 or np.any(np.diff(tau) < 0.0):
        return None
    own = model_params(problem.model)
    x, v, dx, dv, names = _tangents(values, p, tau)
    accel: FloatArray | None = None

    def at(vals: Mapping[str, float], xs: FloatArray, vs: FloatArray) -> FloatArray:
        motion: Motion = (problem.pendulum(vals), xs, vs, tau)
        return problem.residuals(vals, sigma, motion)

    runs = problem.evaluations + 1
    columns = []
    for name in problem.free:
        h = step * max(abs(values[name]), 1e-3 if name != "g" else 1e-2)
        up, down = dict(values), dict(values)
        up[name], down[name] = values[name] + h, values[name] - h
        if name in names:
            k = names.index(name)
            tx, tv = dx[:, :, k], dv[:, :, k]
        elif name == "t_offset":
            if accel is None:
                accel = _acceleration(p, x, v, tau)
            tx, tv = -v, -accel
        elif name in MOTIONLESS:
            tx, tv = np.zeros_like(x), np.zeros_like(v)
        else:  # no sensitivity in the core: the full residuals, differenced
            columns.append((problem.residuals(up, sigma) - problem.residuals(down, sigma)) / (2.0 * h))
            runs += 2
            continue
        if name in own and values[name] - h < float(own[name]["min"]):  # at a bound (drag = 0): one-sided
            twice = dict(values)
            twice[name] = values[name] + 2.0 * h
            r0, r1, r2 = (
                at(values, x, v),
                at(up, x + h * tx, v + h * tv),
                at(twice, x + 2 * h * tx, v + 2 * h * tv),
            )
            columns.append((-3.0 * r0 + 4.0 * r1 - r2) / (2.0 * h))
            continue
        columns.append((at(up, x + h * tx, v + h * tv) - at(down, x - h * tx, v - h * tv)) / (2.0 * h))
    problem.evaluations = runs
    return np.column_stack(columns)
