"""``pl.fit``: the spherical pendulum that best explains measured data, by nonlinear least squares.

Minimises ½ Σ ρ(r_i²) over the free parameters, r = (measured − predicted)/σ per value (data.py),
with SciPy's trust-region reflective ``least_squares`` (search.py; bounds from the model registry;
``loss`` for a robust ρ, e.g. "soft_l1" against outliers), finite-difference Jacobians of the forward
model (problem.py: the exact solution or DOP853 at rtol 1e-12), from starting values read off the data
(start.py) — several for frame-free data, whose phase at t₀ is unknown. When σ is not given, the
search runs in units of the noise floor read off the data first (noise.py), so that neither its
anchor nor a robust loss depends on the units of the numbers. Data that show no motion above their
noise are refused before any search. Errors come from the linearised covariance (identify.py), scaled
by the residual variance when σ is not given and widened for correlated residuals (Newey–West,
goodness.py); parameters the data cannot determine are reported as such, with the reason and the
combination they do determine; the goodness of fit is always checked and what looks wrong is said.
Units: SI throughout (docs/fit.md).
"""

from __future__ import annotations

import math
import time
import warnings
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np

from .._blas import one_blas_thread
from .._core import InvalidInputError
from .._progress import tqdm
from ..model import FloatArray, Pendulum, State
from ..variants.compound import CompoundPendulum
from ..variants.spring import SwingingSpring
from .blocks import check_blocks
from .body import BodyFit, pendulum_of
from .data import KINDS, Observations, observations, residual
from .goodness import EXACT, Goodness, check_kind, findings
from .goodness import misfit as misfit_found
from .identify import Correlation, analyse, jacobian
from .noise import columns_for_noise, floor_of, spread_of
from .problem import PIVOT_NAMES, POSITIVE, Problem, bounds_of, scale_of
from .result import FitResult
from .search import Search, TimeUp, polish, windows_of
from .settings import (
    check_motion,
    check_settings,
    fit_list,
    free_names,
    initial_values,
    is_planar,
    off_origin,
)
from .start import gravity_starts, phase_starts, sideways_starts, signed_start, starting_values

#: Dissipation laws, in the order the nested search frees them (estimator.py, :func:`_nested_start`).
DISSIPATION = ("damping", "friction", "drag")


@one_blas_thread
def fit(
    t: Any,
    *,
    positions: Any = None,
    horizontal: Any = None,
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
    planar: bool | None = None,
    body: CompoundPendulum | None = None,
) -> FitResult:
    """Fits a pendulum to data: times ``t`` [s] with one or more of ``positions`` [m] (N, 3) or (N, 2)
    = (x, z) seen along y, ``horizontal`` [m] (N, 2) = (x, y) seen from above, ``angles`` = (θ, φ)
    [rad], ``planar_angle`` [rad], ``specific_force`` |a − g⃗| [m/s²], ``angular_speed`` |ω| [rad/s].

    ``pendulum``: the model and the starting/fixed values of its parameters (default the ideal
    ``Pendulum()``; a :class:`pendulab.SwingingSpring` for the spring, whose ``length`` is the rest
    length and ``stiffness`` k [N/m]); ``fit``: the parameters to fit (``pl.models()`` names,
    ``"state"``, ``"pivot"`` or single ``theta0``, ``phi0``, ``theta_dot0``, ``phi_dot0``, the
    spring's ``r0`` [m] and ``r_dot0`` [m/s], ``pivot_x/y/z``, ``t_offset`` [s], and the systematic
    terms ``scale`` [1] (positions' scale bar), ``angle_offset`` [rad] (an encoder's zero),
    ``force_bias`` [m/s²], ``rate_bias`` [rad/s], ``perspective`` [1/m]: 1/(a camera's distance));
    the start at the first time is fitted too unless ``state0`` is given. ``pivot`` [m]: the pivot in
    the data's frame when known (default: the origin,
    or fitted when the positions do not hang from it). ``sigma``: the noise of one value (a number,
    or kind → number; for angles that of θ and of the arc sin θ·φ; None: the search runs in units of
    the noise floor read off the data and the error bars take the residual's scatter). ``loss``:
    SciPy's "linear", "soft_l1", "huber", "cauchy" or "arctan" (robust against outliers; scale 1 σ or
    the noise floor). ``planar``: a hinge (φ₀ = φ̇₀ = 0 held): default True for data of a planar
    angle alone, False otherwise. ``body``: a :class:`pendulab.CompoundPendulum` of known geometry
    swinging with ``pendulum``'s model, g and laws: its l_eq and M replace the pendulum's length and
    mass (body.py), and ``res.body`` gives the pivot torques and, with ``length`` fitted, the part
    position it implies. At most ``max_evaluations`` runs of the model per start. Returns a
    :class:`FitResult` whose ``goodness`` says whether the model explains the data (each finding is
    also warned); Ctrl-C returns the best values so far (``converged`` False), and so does reaching
    ``time_limit`` [s] (the error analysis after it adds a few model runs per unknown). Raises
    :class:`pendulab.InvalidInputError` naming bad data or settings, and for data that show no motion
    above their noise."""
    if body is not None:
        pendulum = pendulum_of(body, pendulum)
    pendulum = Pendulum() if pendulum is None else pendulum
    model = check_settings(pendulum, time_limit, loss, max_evaluations)
    data = {
        "positions": positions,
        "horizontal": horizontal,
        "angles": angles,
        "planar_angle": planar_angle,
        "specific_force": specific_force,
        "angular_speed": angular_speed,
    }
    obs = observations(t, data, sigma)
    if state0 is not None and not isinstance(state0, State):
        raise InvalidInputError(f"state0 must be a pendulab.State, got {type(state0).__name__}")
    planar = is_planar(planar, obs, fit)
    values = initial_values(pendulum, model, state0, pivot)
    fit_names = fit_list(fit)
    if pivot is None and not (set(PIVOT_NAMES) | {"pivot"}) & set(fit_names) and off_origin(obs, model):
        fit_names.append("pivot")  # positions that do not hang from the origin: the pivot is unknown
        warnings.warn(
            "the positions do not hang from the origin: the pivot's position is fitted too "
            "(give pivot=(x, y, z) [m] if you know it)",
            UserWarning,
            stacklevel=2,
        )
    free = free_names(fit_names, model, state0 is not None, obs.columns, planar)
    if planar and state0 is None:  # the swing's plane is x–z, θ₀ signed (a negative first angle)
        values.update(phi0=0.0, phi_dot0=0.0)
    floors = {k: floor_of(obs.t, columns_for_noise(k, v)) for k, v in obs.values.items()}
    spreads = {k: spread_of(columns_for_noise(k, v)) for k, v in obs.values.items()}
    check_motion(floors, spreads, {k: float(np.max(np.abs(v))) for k, v in obs.values.items()})
    if len(obs) <= len(free):
        raise InvalidInputError(f"{len(obs)} samples cannot determine {len(free)} unknowns: give more data")
    start = starting_values(obs, values, set(free))
    if planar and "planar_angle" in obs.values:
        start |= signed_start(obs, start, set(free))
    starts, mirror_blind = _starts(obs, start, free)
    problem = Problem(model, start, free, obs)
    period = 2.0 * math.pi * math.sqrt(start["length"] / max(abs(start["g"]), 1e-9))
    scales = np.array([scale_of(n, start[n], start["length"], period) for n in free])
    lower, upper = (np.array(b) for b in zip(*(bounds_of(model, n, start[n]) for n in free), strict=True))
    sig = {
        k: s if s is not None else (floors[k] if floors[k] > 0.0 else max(spreads[k], 1.0) * 1e-9)
        for k, s in obs.sigma.items()
    }
    logged = np.array([n in POSITIVE and start[n] > 0.0 for n in free])
    search = Search(
        problem,
        start,
        scales,
        (lower, upper),
        sig,
        loss=loss,
        max_evaluations=max_evaluations,
        time_limit=time_limit,
        logged=logged,
    )
    show = progress if progress is not None else len(obs) * len(starts) > 200_000
    interrupted, message, n_starts = _run(search, starts, period, show)
    converged = not interrupted and search.result is not None and int(search.result.status) > 0
    if search.result is not None and not interrupted:
        u, message = search.result.x, str(search.result.message)
    elif search.best_u is not None or search.last_u is not None:  # interrupted (in a window: its last)
        u = search.best_u if search.best_u is not None else search.last_u
    elif interrupted:  # stopped in the nested models before the full one ran: the start read off the data
        u = np.array([start[n] for n in free], dtype=np.float64)
    else:
        raise InvalidInputError(
            "the model could not be evaluated at any start: check the data and the pendulum"
        )
    u = _unsigned(np.array(u, dtype=np.float64), free)
    res = _conclude(
        search,
        np.asarray(u, dtype=np.float64),
        floors,
        spreads,
        converged=converged,
        interrupted=interrupted,
        message=message,
        mirror_blind=mirror_blind,
        planar=planar,
        n_starts=n_starts,
    )
    if body is not None:
        res.body = BodyFit.of(body, res.params, res.stderr)
    return res


def _unsigned(u: FloatArray, free: Sequence[str]) -> FloatArray:
    """A negative θ₀ reported as θ₀ > 0 with φ₀ + π (and −θ̇₀) when φ₀ is fitted too: the same state
    (problem.py, state0); with φ₀ held (a hinge) the signed angle is what a user reads."""
    names = list(free)
    if "theta0" in names and "phi0" in names and u[names.index("theta0")] < 0.0:
        i, j = names.index("theta0"), names.index("phi0")
        u[i] = -u[i]
        u[j] = math.remainder(u[j] + math.pi, 2.0 * math.pi)
        if "theta_dot0" in names:
            u[names.index("theta_dot0")] *= -1.0
    return u


def robust_weights(loss: str, z: FloatArray) -> FloatArray:
    """ρ'(z) of SciPy's robust losses at z = r² (scale 1): the weight each residual has at the
    optimum of ½Σρ(r²), as in iteratively reweighted least squares (1 for the linear loss)."""
    if loss == "soft_l1":
        return 1.0 / np.sqrt(1.0 + z)
    if loss == "huber":
        return np.where(z <= 1.0, 1.0, 1.0 / np.sqrt(np.maximum(z, 1.0)))
    if loss == "cauchy":
        return 1.0 / (1.0 + z)
    if loss == "arctan":
        return 1.0 / (1.0 + z * z)
    return np.ones_like(z)


def _starts(obs: Observations, start: dict[str, Any], free: list[str]) -> tuple[list[dict[str, Any]], bool]:
    """The starts of the search (start.py) and whether the data are blind to the mirror y → −y."""
    frame_free = not ({"positions", "horizontal", "angles", "planar_angle"} & set(obs.values))
    starts = phase_starts(start, set(free)) if frame_free else gravity_starts(obs, start, set(free))
    mirror_blind = frame_free or obs.columns.get("positions") == 2  # blind to y → −y (start.py)
    if mirror_blind:
        starts = sideways_starts(starts, set(free))
    return starts, mirror_blind


def _run(search: Search, starts: list[dict[str, Any]], period: float, show: bool) -> tuple[bool, str, int]:
    """The search from the best starts, the nested start for several dissipation laws, and the
    re-weighting of several data kinds of unknown noise; (interrupted, why, number of starts)."""
    problem = search.problem
    windows = windows_of(problem.obs.t, period)
    if len(starts) > 2:  # optimise from the two starts that already fit best on the first window
        first = problem.restricted(windows[0]) if windows else problem
        costs = [search.cost_at(s, first) for s in starts]
        starts = [starts[i] for i in np.argsort(costs)[:2]]
    bar = tqdm(total=len(starts), desc="fit", unit="start", leave=False) if show else None
    robust, search.loss = search.loss, "linear"  # a robust loss refits from the plain optimum
    nested, ran = None, 0
    try:
        nested = _nested_start(search, starts[0], windows)
        if nested is not None:  # already an optimum of the whole record: no windows
            search.from_start(nested, [])
        for s in starts:
            if at_noise_floor(search):  # no other start can do measurably better
                break
            search.from_start(s, windows)
            ran += 1
            if bar is not None:
                bar.update(1)
        # several data kinds with unknown noise: weigh each by its own residual scatter and refit;
        # a robust loss: its scale from the robust spread of the plain fit's residual (noise-free
        # data then stay exact, where a scale of the noise floor made every residual an outlier)
        unknown = [k for k, s in problem.obs.sigma.items() if s is None]
        if (len(problem.obs.values) > 1 and unknown) or robust != "linear":
            predicted = problem.predictions(problem.with_free(search.result.x))
            for kind in unknown:
                part = residual(kind, problem.obs.values[kind], predicted[kind])
                spread = 1.4826 * float(np.median(np.abs(part))) if robust != "linear" else 0.0
                search.sigma[kind] = max(spread or float(np.sqrt(np.mean(part**2))), 1e-300)
            search.loss = robust
            search.best_cost, search.result = math.inf, search.run(search.result.x)
    except (KeyboardInterrupt, TimeUp) as e:
        cause = "Ctrl-C" if isinstance(e, KeyboardInterrupt) else f"the time limit of {search.time_limit:g} s"
        why = f"interrupted ({cause})"
        warnings.warn(f"fit {why}: returning the best values reached", RuntimeWarning, stacklevel=3)
        return True, why, max(ran + (nested is not None), 1)
    finally:
        search.loss = robust
        if bar is not None:
            bar.close()
    return False, "", ran + (nested is not None)


#: The best result so far ends the search when its χ²/dof in units of the search's σ (the given σ, or
#: the noise floor read off the data) is at most this: it explains the data to their noise, so a
#: further start could only find an optimum that the data cannot tell from it.
FLOOR_CHI2 = 1.5


def at_noise_floor(search: Search) -> bool:
    """Whether the best result so far explains the data to their noise (χ²/dof ≤ FLOOR_CHI2 in units
    of the search's σ; the anchor's k residuals are left out)."""
    res = search.result
    if res is None or not res.success or search.loss != "linear":
        return False
    k = len(search.free)
    dof = max(int(res.fun.size) - 2 * k, 1)  # res.fun holds the data's residuals and the k anchors
    return bool(2.0 * float(res.cost) <= FLOOR_CHI2 * dof)


def _nested_start(
    search: Search, start: Mapping[str, float], windows: Sequence[int]
) -> dict[str, float] | None:
    """With several dissipation laws free, the optimum of the nested models — the first law alone,
    then with the second, … (DISSIPATION's order), each from the previous optimum with the new law at
    0 — as a start of the full search, so that adding a law never ends in a worse optimum than the
    chain of models without it."""
    free = search.free
    laws = [n for n in DISSIPATION if n in free]
    if len(laws) < 2:
        return None
    problem = search.problem
    current = dict(start) | dict.fromkeys(laws[1:], 0.0)
    for k in range(1, len(laws)):
        keep = [i for i, n in enumerate(free) if n not in laws[k:]]
        smaller = Problem(problem.model, current, [free[i] for i in keep], problem.obs)
        inner = Search(
            smaller,
            current,
            search.scales[keep],
            (search.lower[keep], search.upper[keep]),
            search.sigma,
            loss=search.loss,
            max_evaluations=search.max_evaluations,
            time_limit=search.time_limit,
            logged=search.logged[keep],
        )
        inner.began = search.began
        try:
            res = inner.from_start(current, windows if k == 1 else [])
        finally:
            problem.evaluations += smaller.evaluations
        current = current | dict(zip(smaller.free, (float(x) for x in res.x), strict=True))
        # the next law starts just off its bound 0, where a difference quotient can see it
        added = laws[k]
        current[added] = max(current[added], 0.01 * float(search.scales[free.index(added)]))
    return current


def _conclude(
    search: Search,
    u: FloatArray,
    floors: Mapping[str, float],
    spreads: Mapping[str, float],
    *,
    converged: bool,
    interrupted: bool,
    message: str,
    mirror_blind: bool,
    planar: bool,
    n_starts: int,
) -> FitResult:
    """The polish, the error analysis (identify.py) with the goodness of fit (goodness.py), the
    warnings, and the :class:`FitResult`."""
    problem, free, sig = search.problem, search.free, search.sigma

    def weighted(uu: FloatArray) -> FloatArray:
        return problem.residuals(problem.with_free(uu), sig)

    r = weighted(u)
    # logarithmic steps for positive parameters well away from 0 (a damping at its bound 0 gets
    # additive ones, one-sided there: jacobian())
    positive = np.array([n in POSITIVE and u[i] > 0.01 * search.scales[i] for i, n in enumerate(free)])
    steps = np.where(positive, 1e-5, search.scales * 1e-5)

    def jac_of(uu: FloatArray) -> FloatArray | None:
        return search.exact_jacobian(problem, uu)  # forward sensitivities (sensitivity.py) or None

    exact = jac_of(u)
    jac = exact if exact is not None else jacobian(weighted, u, steps, positive)
    if search.loss == "linear" and not interrupted:
        bounds = (search.lower, search.upper)
        u, r, jac = polish(weighted, u, r, jac, steps, positive, *bounds, search.time_up, jac_of)
    final = problem.with_free(u)
    n_res, k = r.size, len(free)
    dof = max(n_res - k, 1)
    if search.loss != "linear":  # the robust loss's weights (IRLS): outliers leave the error analysis
        w = np.sqrt(robust_weights(search.loss, r * r))
        r, jac = r * w, jac * w[:, None]
    chi2 = float(r @ r)
    obs = problem.obs
    sigma_known = all(s is not None for s in obs.sigma.values())
    variance = 1.0 if sigma_known else chi2 / dof
    pred = problem.predictions(final)
    checks = {
        kind: check_kind(obs.t, residual(kind, obs.values[kind], pred[kind]), floors[kind], spreads[kind])
        for kind in obs.values
    }
    lag1 = max((c.lag1 for c in checks.values()), default=0.0)
    sample = np.concatenate([np.repeat(np.arange(len(obs)), obs.columns[kind]) for kind in obs.values])
    exact = all(c.spread > 0.0 and c.rms <= EXACT * c.spread for c in checks.values())
    correlation = None if exact else Correlation(r, sample, len(obs), lag1)  # round-off has no statistics
    logged = {n for i, n in enumerate(free) if positive[i]}
    ident = analyse(free, final, jac, variance, logged, correlation)
    misfit = chi2  # Σ r² in units of the search's σ (the data's own floor when σ is not given)
    chi2 /= variance  # with σ estimated from the residual, χ²/dof = 1 by construction
    chi2_p = None
    if sigma_known:
        from scipy import stats

        chi2_p = float(stats.chi2.sf(chi2, dof))
    said = findings(checks, chi2_p, chi2, dof, robust=search.loss != "linear")
    # a misfit: the record's blocks fitted on their own, the error bars widened by their disagreement
    blocks = (
        None
        if interrupted or not misfit_found(checks, chi2_p)
        else check_blocks(search, final, ident, sigma_known)
    )
    said += blocks.findings() if blocks is not None else []
    g_fit = final["g"]
    if "g" in free and ident.determined["g"] and not 0.01 <= abs(g_fit) <= 1000.0:
        said.append(
            f"the fitted g = {g_fit:.4g} m/s² is far from any planet's (Earth 9.81): are the data in SI "
            "units (positions in m, not mm or pixels; times in s; angles in rad)?"
        )
    for text in said:
        warnings.warn(text, UserWarning, stacklevel=3)
    if not converged and not interrupted:
        warnings.warn(
            f"the fit did not converge ({message}); the values are the best reached",
            RuntimeWarning,
            stacklevel=3,
        )
    goodness = Goodness(checks, chi2_p, {n: ident.inflation.get(n, 1.0) for n in free}, said)
    return FitResult.build(
        problem=problem,
        values=final,
        predictions=pred,
        sigma={
            k: (obs.sigma[k] if obs.sigma[k] is not None else sig[k] * math.sqrt(variance))
            for k in obs.values
        },
        sigma_estimated=not sigma_known,
        chi2=chi2,
        dof=dof,
        ident=ident,
        converged=converged,
        message=message if message else "interrupted",
        seconds=time.perf_counter() - search.began,
        starts=n_starts,
        interrupted=interrupted,
        kinds=KINDS,
        mirror_blind=mirror_blind,
        goodness=goodness,
        bounds={n: (float(search.lower[i]), float(search.upper[i])) for i, n in enumerate(free)},
        planar=planar,
        misfit=misfit,
        search_sigma=dict(sig),
        variance=variance,
        blocks=blocks,
    )
