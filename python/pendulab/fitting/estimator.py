"""``pl.fit``: the spherical pendulum that best explains measured data, by nonlinear least squares.

Minimises ½ Σ ρ(r_i²) over the free parameters (T-10.2), r = (measured − predicted)/σ per value
(data.py), with SciPy's trust-region reflective ``least_squares`` (search.py; bounds from the model registry;
``loss`` for a robust ρ, e.g. "soft_l1" against outliers), finite-difference Jacobians of the forward
model (problem.py: the exact solution or DOP853 at rtol 1e-12), from starting values read off the data
(start.py) — several for frame-free data, whose phase at t₀ is unknown. When σ is not given, the
search runs in units of the noise floor read off the data first (noise.py), so that neither its
anchor nor a robust loss depends on the units of the numbers. Data that show no motion above their
noise are refused before any search. Errors come from the linearised covariance (identify.py), scaled
by the residual variance when σ is not given and widened for correlated residuals (Newey–West,
goodness.py); parameters the data cannot determine are reported as such, with the reason and the
combination they do determine; the goodness of fit is always checked and what looks wrong is said.

:func:`fit` reads as its steps: the settings checked (settings.py), the data cleaned (data.py), the
unknowns, their starting values and the noise floors (:class:`_Setup` here), the search built
(:func:`_search_of`) and run from its starts (multistart.py), the best values taken
(:func:`_optimum`), and the statistics at the optimum (inference.py). The names of those modules
are also importable from here.
Units: SI throughout (docs/fit.md).
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from .._blas import one_blas_thread
from .._core import InvalidInputError
from .._warn import warn_user
from ..model import FloatArray, Pendulum, State
from ..variants.compound import CompoundPendulum
from ..variants.spring import SwingingSpring
from .body import BodyFit, pendulum_of
from .data import Observations, observations
from .inference import conclude, robust_weights
from .mirror_sign import broken_by
from .multistart import (
    DISSIPATION,
    FLOOR_CHI2,
    FLOOR_PERIODS,
    at_noise_floor,
    nested_start,
    run_starts,
    search_starts,
)
from .noise import columns_for_noise, floor_of, spread_of
from .problem import PIVOT_NAMES, POSITIVE, Problem, bounds_of, scale_of
from .result import FitResult
from .search import Clock, Search
from .settings import (
    check_motion,
    check_settings,
    fit_list,
    free_names,
    initial_values,
    is_planar,
    need_scipy,
    off_origin,
)
from .start import signed_start, starting_values

__all__ = [
    "DISSIPATION",
    "FLOOR_CHI2",
    "FLOOR_PERIODS",
    "at_noise_floor",
    "conclude",
    "fit",
    "nested_start",
    "robust_weights",
    "run_starts",
    "search_starts",
]


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
    terms ``scale`` [1] (the scale bar of positions and horizontal, no other kind), ``angle_offset``
    [rad] (an encoder's zero), ``force_bias`` [m/s²], ``rate_bias`` [rad/s], ``perspective`` [1/m]:
    1/(a camera's distance)); the start at the first time is fitted too unless ``state0`` is given.
    ``pivot`` [m]: the pivot in
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
    ``time_limit`` [s], which bounds the whole call, from reading the data to the error bars (its
    clock starts as ``fit`` is called): the data's reading and checks, the starting values, the
    search and, over a record shorter than a swing, the profile likelihoods of the error analysis
    (each refit is cut at a model run past the limit; what it leaves unprofiled is reported not
    determined, naming the limit); the rest of the error analysis adds one run of the record and its
    Jacobian past it: one run of the exact sensitivities, or differences for at most 1 s
    (``fitting.search.LATE_SECONDS``), else the parameters are reported not determined. Raises
    :class:`pendulab.InvalidInputError` naming bad data or settings, and for data that show no motion
    above their noise; an ImportError without SciPy (``pip install 'pendulab[fit]'``)."""
    clock = Clock(time_limit)  # time_limit bounds the whole call: the data's reading counts too
    need_scipy()
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
    setup = _Setup.read(obs, pendulum, model, fit, state0, pivot, planar)
    search, period = _search_of(setup, model, loss, max_evaluations, clock)
    show = progress if progress is not None else len(obs) * len(setup.starts) > 200_000
    interrupted, message, n_starts = run_starts(search, setup.starts, period, show)
    u, converged, message = _optimum(search, setup.start, interrupted, message)
    res = conclude(
        search,
        u,
        setup.floors,
        setup.spreads,
        converged=converged,
        interrupted=interrupted,
        message=message,
        mirror_blind=setup.mirror_blind,
        mirror_told=setup.mirror_told,
        planar=setup.planar,
        n_starts=n_starts,
    )
    if body is not None:
        res.body = BodyFit.of(body, res.params, res.stderr)
    return res


@dataclass
class _Setup:
    """What the search needs from the data and the settings: the free parameters' names, whether the
    pendulum is a hinge, the noise floor [each kind's unit] and spread of every data kind, the starting
    values (SI units, every parameter) and the starts of the search, and whether the data are blind
    to the mirror y → −y (``mirror_told``: the data blind to y, what tells the motion from its image
    where the model is no symmetric one: mirror_sign.py)."""

    obs: Observations
    free: list[str]
    planar: bool
    floors: dict[str, float]
    spreads: dict[str, float]
    start: dict[str, Any]
    starts: list[dict[str, Any]]
    mirror_blind: bool
    mirror_told: str = ""

    @classmethod
    def read(
        cls,
        obs: Observations,
        pendulum: Pendulum | SwingingSpring,
        model: str,
        fit: str | Sequence[str],
        state0: State | None,
        pivot: Sequence[float] | None,
        planar: bool | None,
    ) -> _Setup:
        """The unknowns named (settings.py), the data's noise checked (no motion above it is refused),
        then the starting values read off the data (start.py) and the starts of the search."""
        if state0 is not None and not isinstance(state0, State):
            raise InvalidInputError(f"state0 must be a pendulab.State, got {type(state0).__name__}")
        planar = is_planar(planar, obs, fit)
        values = initial_values(pendulum, model, state0, pivot)
        free = _free_of(obs, model, fit, state0, pivot, planar)
        if planar and state0 is None:  # the swing's plane is x–z, θ₀ signed (a negative first angle)
            values.update(phi0=0.0, phi_dot0=0.0)
        floors, spreads = _noise_of(obs, free)
        start = starting_values(obs, values, set(free))
        if planar and "planar_angle" in obs.values:
            start |= signed_start(obs, start, set(free))
        starts, blind = search_starts(obs, start, free)
        told = broken_by(model, seen_by(obs, start), free) if blind else ""  # the model's own symmetry
        return cls(obs, free, planar, floors, spreads, start, starts, blind and not told, told)


def seen_by(obs: Observations, values: Mapping[str, Any]) -> dict[str, Any]:
    """``values`` as the data ``obs`` see them, for mirror_sign.broken_by: a camera's ``perspective``
    [1/m] acts on positions (x, z) only, so for data without them (a phone's |a − g⃗|, |ω|) a held
    perspective ≠ 0 cannot break the mirror y → −y and is dropped."""
    return (
        dict(values) if "positions" in obs.values else {k: v for k, v in values.items() if k != "perspective"}
    )


def _free_of(
    obs: Observations,
    model: str,
    fit: str | Sequence[str],
    state0: State | None,
    pivot: Sequence[float] | None,
    planar: bool,
) -> list[str]:
    """The free parameters' names (settings.py), with the pivot added (and warned) for positions that
    do not hang from the origin when no pivot was given."""
    fit_names = fit_list(fit)
    if pivot is None and not (set(PIVOT_NAMES) | {"pivot"}) & set(fit_names) and off_origin(obs, model):
        fit_names.append("pivot")  # positions that do not hang from the origin: the pivot is unknown
        warn_user(
            "the positions do not hang from the origin: the pivot's position is fitted too "
            "(give pivot=(x, y, z) [m] if you know it)",
            UserWarning,
        )
    return free_names(fit_names, model, state0 is not None, obs.columns, planar)


def _noise_of(obs: Observations, free: list[str]) -> tuple[dict[str, float], dict[str, float]]:
    """The noise floor and spread of each data kind [its unit] (noise.py); data without motion above
    their noise, or fewer samples than unknowns, are refused."""
    floors = {k: floor_of(obs.t, columns_for_noise(k, v)) for k, v in obs.values.items()}
    spreads = {k: spread_of(columns_for_noise(k, v)) for k, v in obs.values.items()}
    check_motion(floors, spreads, {k: float(np.max(np.abs(v))) for k, v in obs.values.items()})
    if len(obs) <= len(free):
        raise InvalidInputError(f"{len(obs)} samples cannot determine {len(free)} unknowns: give more data")
    return floors, spreads


def _search_of(
    setup: _Setup, model: str, loss: str, max_evaluations: int, clock: Clock
) -> tuple[Search, float]:
    """The search (search.py) over the free parameters from the start, with each one's scale, its
    bounds (model registry), logarithmic steps for positive ones, and σ per kind (the given one, else
    the noise floor), on the fit's ``clock`` (started at the fit's entry); and the small-swing period
    2π√(l/|g|) [s] that sets its windows."""
    start, free, obs = setup.start, setup.free, setup.obs
    problem = Problem(model, start, free, obs)
    period = 2.0 * math.pi * math.sqrt(start["length"] / max(abs(start["g"]), 1e-9))
    scales = np.array([scale_of(n, start[n], start["length"], period) for n in free])
    lower, upper = (np.array(b) for b in zip(*(bounds_of(model, n, start[n]) for n in free), strict=True))
    floors, spreads = setup.floors, setup.spreads
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
        clock=clock,
        logged=logged,
    )
    return search, period


def _optimum(
    search: Search, start: Mapping[str, float], interrupted: bool, message: str
) -> tuple[FloatArray, bool, str]:
    """(the best values of the free parameters, whether the search converged, why it stopped): the
    search's result; when interrupted, the best values so far (in a window: its last), or the start
    read off the data when the nested models had not yet reached the full one."""
    free = search.free
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
    return np.asarray(u, dtype=np.float64), converged, message


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
