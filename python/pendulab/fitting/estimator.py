"""``pl.fit``: the spherical pendulum that best explains measured data, by nonlinear least squares.

Minimises ½ Σ ρ(r_i²) over the free parameters, r = (measured − predicted)/σ per value (data.py),
with SciPy's trust-region reflective ``least_squares`` (bounds from the model registry; ``loss`` for a
robust ρ, e.g. "soft_l1" against outliers), finite-difference Jacobians of the forward model
(problem.py: the exact solution or DOP853 at rtol 1e-12), from starting values read off the data
(start.py) — several for frame-free data, whose phase at t₀ is unknown. Errors come from the
linearised covariance (identify.py), scaled by the residual variance when σ is not given; parameters
the data cannot determine are reported as such, with the combination they do determine.
Units: SI throughout (docs/fit.md).
"""

from __future__ import annotations

import math
import time
import warnings
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np

from .._core import InvalidInputError
from .._progress import tqdm
from ..model import FloatArray, Pendulum, State
from ..variants.spring import SwingingSpring
from .data import KINDS, observations, residual
from .identify import analyse, jacobian
from .problem import (
    OFFSET_NAMES,
    PIVOT_NAMES,
    STATE_NAMES,
    Problem,
    bounds_of,
    check_model,
    model_params,
    scale_of,
)
from .result import FitResult
from .search import polish, windows_of
from .spring_model import SPRING_STATE
from .start import gravity_starts, phase_starts, sideways_starts, starting_values

POSITIVE = {"length", "mass", "g", "damping", "drag", "stiffness", "r0"}
MAX_EVALUATIONS = 20_000
ANCHOR = 0.1
#: χ²/dof above this, with σ given, is warned about (a fit explaining the data to their noise gives ≈ 1).
MISFIT = 2.0


def _angles_of(state: State) -> dict[str, float]:
    """θ, φ [rad] and θ̇, φ̇ [rad/s] of a state (φ̇ = 0 at a pole, where φ means nothing), with the
    length r₀ = |x| [m] and its rate ṙ₀ [m/s] (used by the spring; r₀ = l on a rod)."""
    x, v = np.asarray(state.x), np.asarray(state.v)
    theta, phi = state.angles()
    ell = float(np.linalg.norm(x))
    e_theta = np.array([math.cos(theta) * math.cos(phi), math.cos(theta) * math.sin(phi), math.sin(theta)])
    e_phi = np.array([-math.sin(phi), math.cos(phi), 0.0])
    rho = math.hypot(x[0], x[1])
    return {
        "theta0": theta,
        "phi0": phi,
        "theta_dot0": float(v @ e_theta) / ell,
        "phi_dot0": float(v @ e_phi) / rho if rho > 1e-12 * ell else 0.0,
        "r0": ell,
        "r_dot0": float(v @ x) / ell,
    }


class _TimeUp(Exception):
    """The search ran past ``time_limit``."""


def _free_names(fit: Any, model: str, state_given: bool, columns: Mapping[str, int]) -> list[str]:
    if isinstance(fit, str):
        fit = [s.strip() for s in fit.split(",") if s.strip()]
    names: list[str] = []
    own = list(model_params(model))
    state = [*STATE_NAMES, *(SPRING_STATE if model == "spring" else ())]
    pivot = list(PIVOT_NAMES) if columns.get("positions", 3) == 3 else ["pivot_x", "pivot_z"]
    allowed = own + state + list(PIVOT_NAMES) + list(OFFSET_NAMES) + ["state", "pivot"]
    for name in fit:
        if not isinstance(name, str) or name not in allowed:
            raise InvalidInputError(
                f"cannot fit {name!r} for the {model!r} model; choose from {', '.join(allowed)}"
            )
        expanded = state if name == "state" else pivot if name == "pivot" else [name]
        names += [n for n in expanded if n not in names]
    if not state_given:
        names += [n for n in state if n not in names]
    if set(PIVOT_NAMES) & set(names) and "positions" not in columns:
        raise InvalidInputError("the pivot position is fitted from positions only; give positions=")
    if "t_offset" in names and model != "ideal":
        raise InvalidInputError(
            "t_offset is fitted for the ideal pendulum only (the exact solution runs backward)"
        )
    if not names:
        raise InvalidInputError("nothing to fit: give fit=[...] or leave state0 unset")
    return names


def fit(
    t: Any,
    *,
    positions: Any = None,
    angles: Any = None,
    planar_angle: Any = None,
    specific_force: Any = None,
    angular_speed: Any = None,
    pendulum: Pendulum | SwingingSpring | None = None,
    fit: str | Sequence[str] = ("length", "g"),
    state0: State | None = None,
    pivot: Sequence[float] | None = None,
    sigma: float | Mapping[str, float] | None = None,
    loss: str = "linear",
    max_evaluations: int = 2000,
    progress: bool | None = None,
    time_limit: float | None = None,
) -> FitResult:
    """Fits a pendulum to data: times ``t`` [s] with one or more of ``positions`` [m] (N, 3) or (N, 2)
    = (x, z) seen along y, ``angles`` = (θ, φ) [rad], ``planar_angle`` [rad], ``specific_force``
    |a − g⃗| [m/s²], ``angular_speed`` |ω| [rad/s].

    ``pendulum``: the model and the starting/fixed values of its parameters (default the ideal
    ``Pendulum()``; a :class:`pendulab.SwingingSpring` for the spring, whose ``length`` is the rest
    length and ``stiffness`` k [N/m]); ``fit``: the parameters to fit (``pl.models()`` names,
    ``"state"``, ``"pivot"`` or single ``theta0``, ``phi0``, ``theta_dot0``, ``phi_dot0``, the
    spring's ``r0`` [m] and ``r_dot0`` [m/s], ``pivot_x/y/z``, ``t_offset``); the start at the first
    time is fitted too unless ``state0`` is given. ``pivot`` [m]: the pivot in the
    data's frame when known (default the origin). ``sigma``: the noise of one value (a number, or
    kind → number; for angles that of θ and of the arc sin θ·φ; None: estimated from the residual).
    ``loss``: SciPy's "linear", "soft_l1", "huber", "cauchy" or "arctan" (robust against outliers;
    scale 1 σ). At most ``max_evaluations``
    runs of the model per start. Returns a :class:`FitResult`; Ctrl-C returns the best values so far
    (``converged`` False), and so does reaching ``time_limit`` [s] of search (default: none; the
    error analysis after it adds a few model runs per unknown). Raises
    :class:`pendulab.InvalidInputError` naming bad data or settings."""
    from scipy.optimize import least_squares

    pendulum = Pendulum() if pendulum is None else pendulum
    if not isinstance(pendulum, Pendulum | SwingingSpring):
        raise InvalidInputError(
            f"pendulum must be a pendulab.Pendulum or SwingingSpring, got {type(pendulum).__name__}"
        )
    model = check_model(pendulum)
    if time_limit is not None and not (isinstance(time_limit, int | float) and time_limit > 0.0):
        raise InvalidInputError(f"time_limit = {time_limit!r} must be a positive number of seconds or None")
    if loss not in ("linear", "soft_l1", "huber", "cauchy", "arctan"):
        raise InvalidInputError(f"loss = {loss!r}: use linear, soft_l1, huber, cauchy or arctan")
    if (
        isinstance(max_evaluations, bool)
        or not isinstance(max_evaluations, int)
        or not (10 <= max_evaluations <= MAX_EVALUATIONS)
    ):
        raise InvalidInputError(
            f"max_evaluations = {max_evaluations!r} must be an integer from 10 to {MAX_EVALUATIONS}"
        )
    data = {
        "positions": positions,
        "angles": angles,
        "planar_angle": planar_angle,
        "specific_force": specific_force,
        "angular_speed": angular_speed,
    }
    obs = observations(t, data, sigma)
    if state0 is not None and not isinstance(state0, State):
        raise InvalidInputError(f"state0 must be a pendulab.State, got {type(state0).__name__}")
    free = _free_names(fit, model, state0 is not None, obs.columns)
    values: dict[str, float] = {n: float(spec["default"]) for n, spec in model_params(model).items()}
    if isinstance(pendulum, SwingingSpring):
        values.update(
            length=pendulum.rest_length,
            g=pendulum.g,
            mass=pendulum.mass,
            stiffness=pendulum.k_over_m * pendulum.mass,
        )
        for name, spec in model_params(model).items():  # the registry's limits, as a Pendulum checks them
            v = values[name]
            if not (math.isfinite(v) and float(spec["min"]) <= v <= float(spec["max"])):
                raise InvalidInputError(
                    f"the spring's {name} = {v!r} {spec['unit']}: allowed is {spec['allowed']}"
                )
        values.update(r0=pendulum.equilibrium_length, r_dot0=0.0)
    else:
        values.update({k: float(v) for k, v in pendulum.params().items() if k != "model"})
        values.update({k: float(v) for k, v in pendulum.extra.items()})
    values.update(dict.fromkeys(STATE_NAMES, 0.0))
    if state0 is not None:
        values.update(_angles_of(state0))
    given_pivot = (0.0, 0.0, 0.0) if pivot is None else tuple(float(c) for c in pivot)
    if len(given_pivot) != 3 or not all(math.isfinite(c) for c in given_pivot):
        raise InvalidInputError(f"pivot must be 3 finite numbers [m], got {pivot!r}")
    values.update(dict(zip(PIVOT_NAMES, given_pivot, strict=True)))
    values["t_offset"] = 0.0
    if len(obs) <= len(free):
        raise InvalidInputError(f"{len(obs)} samples cannot determine {len(free)} unknowns: give more data")
    start = starting_values(obs, values, set(free))
    frame_free = not ({"positions", "angles", "planar_angle"} & set(obs.values))
    starts = phase_starts(start, set(free)) if frame_free else gravity_starts(obs, start, set(free))
    mirror_blind = frame_free or obs.columns.get("positions") == 2  # blind to y → −y (start.py)
    if mirror_blind:
        starts = sideways_starts(starts, set(free))

    problem = Problem(model, start, free, obs)
    period = 2.0 * math.pi * math.sqrt(start["length"] / max(abs(start["g"]), 1e-9))
    scales = np.array([scale_of(n, start[n], start["length"], period) for n in free])
    lower, upper = zip(*(bounds_of(model, n, start[n]) for n in free), strict=True)
    sig = {k: (s if s is not None else 1.0) for k, s in obs.sigma.items()}
    show = progress if progress is not None else len(obs) * len(starts) > 200_000
    bar = tqdm(total=len(starts), desc="fit", unit="start", leave=False) if show else None
    best: dict[str, Any] = {"cost": math.inf, "u": None, "res": None, "last": None}
    began = time.perf_counter()
    interrupted, why = False, "interrupted"

    u_start = np.array([start[n] for n in free], dtype=np.float64)
    logged = np.array([n in POSITIVE and start[n] > 0.0 for n in free])

    def _anchor(u: FloatArray) -> FloatArray:
        """A faint pull towards the start (ANCHOR per unit of ln p or of the scale): it holds the
        directions the data do not determine (g and l together, from angles) where they began instead
        of letting them drift to a bound, and biases the determined ones by ~ANCHOR²/(JᵀJ), nothing."""
        with np.errstate(divide="ignore", invalid="ignore"):
            z = np.where(
                logged, np.log(np.maximum(u, 1e-300) / np.where(logged, u_start, 1.0)), (u - u_start) / scales
            )
        return ANCHOR * z

    def clip(u: FloatArray) -> FloatArray:
        return np.minimum(np.maximum(u, np.array(lower)), np.array(upper))

    def run(u0: FloatArray, weights: Mapping[str, float], on: Problem = problem, tol: float = 1e-10) -> Any:
        def fun(u: FloatArray) -> FloatArray:
            if (
                time_limit is not None
                and best["last"] is not None
                and time.perf_counter() - began > time_limit
            ):
                raise _TimeUp
            r = on.safe_residuals(u, weights)
            best["last"] = np.array(u, dtype=np.float64)  # on a window too: what an interruption returns
            if on is problem:
                cost = 0.5 * float(r @ r)
                if cost < best["cost"]:
                    best.update(cost=cost, u=np.array(u, dtype=np.float64))
            return np.concatenate([r, _anchor(u)])

        return least_squares(
            fun,
            clip(u0),
            bounds=(lower, upper),
            x_scale=scales,
            loss=loss,
            f_scale=1.0,
            max_nfev=max_evaluations,
            xtol=tol,
            ftol=tol,
            gtol=tol,
            diff_step=1e-8,
            method="trf",
        )

    windows = windows_of(obs.t, period)
    if len(starts) > 2:  # optimise from the two starts that already fit best on the first window
        first = problem.restricted(windows[0]) if windows else problem
        costs = [float(np.sum(first.safe_residuals([s[n] for n in free], sig) ** 2)) for s in starts]
        starts = [starts[i] for i in np.argsort(costs)[:2]]
    try:
        for s in starts:
            u0 = np.array([s[n] for n in free], dtype=np.float64)
            for n_samples in windows:  # continuation: a few periods first, then twice as many, ...
                part = problem.restricted(n_samples)
                u0 = run(u0, sig, part, 1e-8).x
                problem.evaluations += part.evaluations
            res = run(u0, sig)
            if best["res"] is None or res.cost <= best["res"].cost:
                best["res"] = res
            if bar is not None:
                bar.update(1)
        # several data kinds with unknown noise: weigh each by its own residual scatter and refit
        unknown = [k for k, s in obs.sigma.items() if s is None]
        if len(obs.values) > 1 and unknown:
            predicted = problem.predictions(problem.with_free(best["res"].x))
            for kind in unknown:
                part = residual(kind, obs.values[kind], predicted[kind])
                sig[kind] = max(float(np.sqrt(np.mean(part**2))), 1e-300)
            best["cost"], best["res"] = math.inf, run(best["res"].x, sig)
    except (KeyboardInterrupt, _TimeUp) as e:
        interrupted = True
        cause = "Ctrl-C" if isinstance(e, KeyboardInterrupt) else f"the time limit of {time_limit:g} s"
        why = f"interrupted ({cause})"
        warnings.warn(f"fit {why}: returning the best values reached", RuntimeWarning, stacklevel=2)
    finally:
        if bar is not None:
            bar.close()
    if best["res"] is not None and not interrupted:
        u, status, message = best["res"].x, int(best["res"].status), str(best["res"].message)
        converged = status > 0
    elif best["u"] is not None or best["last"] is not None:  # interrupted (in a window: its last values)
        u, converged, message = best["u"] if best["u"] is not None else best["last"], False, why
    else:
        raise InvalidInputError(
            "the model could not be evaluated at any start: check the data and the pendulum"
        )

    def weighted(uu: FloatArray) -> FloatArray:
        return problem.residuals(problem.with_free(uu), sig)

    u = np.asarray(u, dtype=np.float64)
    r = weighted(u)
    positive = np.array([n in POSITIVE and u[i] > 0.0 for i, n in enumerate(free)])
    steps = np.where(positive, 1e-5, scales * 1e-5)
    jac = jacobian(weighted, u, steps, positive)
    if loss == "linear" and not interrupted:
        u, r, jac = polish(weighted, u, r, jac, steps, positive, np.array(lower), np.array(upper))
    final = problem.with_free(u)
    n_res, k = r.size, len(free)
    dof = max(n_res - k, 1)
    chi2 = float(r @ r)
    sigma_known = all(s is not None for s in obs.sigma.values())
    variance = 1.0 if sigma_known else chi2 / dof
    chi2 /= variance  # with σ estimated from the residual, χ²/dof = 1 by construction
    ident = analyse(free, final, jac, variance, POSITIVE)
    g_fit = final["g"]
    if "g" in free and ident.determined["g"] and not 0.01 <= abs(g_fit) <= 1000.0:
        warnings.warn(
            f"the fitted g = {g_fit:.4g} m/s² is far from any planet's (Earth 9.81): "
            "are the data in SI units "
            "(positions in m, not mm or pixels; times in s; angles in rad)?",
            UserWarning,
            stacklevel=2,
        )
    if sigma_known and chi2 / dof > MISFIT:
        warnings.warn(
            f"chi2/dof = {chi2 / dof:.3g}: the fitted motion misses the data by {math.sqrt(chi2 / dof):.3g}× "
            "their noise — a model that lacks something (damping, drag, a moving pivot), a sigma too "
            "small, or a local minimum (try other starting values in pendulum=); see res.plot()",
            UserWarning,
            stacklevel=2,
        )
    if not converged:
        warnings.warn(
            f"the fit did not converge ({message}); the values are the best reached",
            RuntimeWarning,
            stacklevel=2,
        )
    return FitResult.build(
        problem=problem,
        values=final,
        sigma={
            k: (obs.sigma[k] if obs.sigma[k] is not None else sig[k] * math.sqrt(variance))
            for k in obs.values
        },
        sigma_estimated=not sigma_known,
        chi2=chi2,
        dof=dof,
        ident=ident,
        converged=converged,
        message=message,
        seconds=time.perf_counter() - began,
        starts=len(starts),
        interrupted=interrupted,
        kinds=KINDS,
        mirror_blind=mirror_blind,
    )
