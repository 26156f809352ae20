"""The error analysis after the fit's time limit is bounded by a fixed amount (search.LATE_SECONDS):
where the model has no exact sensitivities (the pivot models) the Jacobian at the values reached takes
one run of the whole record per unknown, and a long record made that overrun grow without bound
(halved from two runs per unknown, but still k runs). Now each forward difference is begun only if it
ends within LATE_SECONDS of the limit; otherwise no bars at all. The swinging spring is the example:
its exact sensitivities (T-10.8) are switched off for the bound's tests (``_without_sensitivities``),
and with them on, the late Jacobian is one run and the bars are kept. The clock is the test's
(search.wall_clock), advancing a fixed step per model run, so nothing here measures time. The data
are SciPy's DOP853 of the spring's equations written here (not pendulab's integrators). SI."""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest
from conftest import fit_run_clock
from scipy.integrate import solve_ivp

import pendulab as pl
from pendulab.fitting import search, sensitivity
from pendulab.fitting.inference import LATE_REASON

K_OVER_M, REST, G = 4.0 * 9.81, 0.75, 9.81  # 1/s², m, m/s²: the 1:1:2 resonance of a 1 m hang


def _spring() -> tuple[np.ndarray, np.ndarray]:
    """Positions [m] of a swinging spring, 4 s at 50 Hz, σ 1 mm: ẍ = −(k/m)(|x| − l₀) x/|x| + g⃗."""

    def rhs(_: float, s: np.ndarray) -> np.ndarray:
        x, v = s[:3], s[3:]
        r = float(np.linalg.norm(x))
        return np.concatenate([v, -K_OVER_M * (r - REST) * x / r + np.array([0.0, 0.0, -G])])

    t = np.linspace(0.0, 4.0, 201)
    s0 = [0.15, 0.05, -1.02, 0.0, 0.2, 0.0]
    sol = solve_ivp(rhs, (0.0, 4.0), s0, "DOP853", t_eval=t, rtol=1e-12, atol=1e-12)
    assert sol.success, sol.message
    return t, sol.y[:3].T + 1e-3 * np.random.default_rng(3).standard_normal((len(t), 3))


def _fit(monkeypatch: pytest.MonkeyPatch, step: float, limit: float) -> tuple[pl.FitResult, int, int]:
    """The spring fitted under ``limit`` [s] on a clock that advances ``step`` [s] per model run: the
    result, the runs made, and the run at which the clock passed the limit."""
    runs = fit_run_clock(monkeypatch, step)
    t, x = _spring()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        res = pl.fit(
            t,
            positions=x,
            pendulum=pl.SwingingSpring(30.0, 0.8, 9.81, 1.0),
            fit="stiffness,length,g",
            sigma=1e-3,
            time_limit=limit,
        )
    return res, runs[0], math.floor(limit / step) + 1


def _without_sensitivities(monkeypatch: pytest.MonkeyPatch) -> None:
    """The spring fitted as a model without exact sensitivities: its Jacobians by differences."""
    monkeypatch.setattr(sensitivity, "MODELS", tuple(m for m in sensitivity.MODELS if m != "spring"))


def test_a_late_jacobian_that_would_outrun_the_bound_gives_no_bars(monkeypatch: pytest.MonkeyPatch) -> None:
    """0.3 s per run, 3 s limit: the 9 forward differences (2.7 s) would end 1.7 s or more past the
    limit, so after the run at the values reached at most LATE_SECONDS/0.3 = 3 of them are begun and
    none kept: every parameter not determined, with the reason."""
    _without_sensitivities(monkeypatch)
    res, runs, at_limit = _fit(monkeypatch, 0.3, 3.0)
    assert res.interrupted and not res.converged, res.message
    k = len(res.names)
    assert k == 9
    for name in res.names:
        assert not res.determined[name] and math.isinf(res.stderr[name]), (name, res.stderr)
        assert res.reasons[name] == LATE_REASON
    # the search stops at its first run past the limit, then the run at the values reached and the
    # forward differences begun within LATE_SECONDS: not the k of the whole Jacobian
    assert runs <= at_limit + 2 + math.floor(search.LATE_SECONDS / 0.3), (runs, at_limit)


def test_a_late_jacobian_within_the_bound_keeps_the_bars(monkeypatch: pytest.MonkeyPatch) -> None:
    """1 ms per run, 0.05 s limit (cut in the search): the 9 forward differences take 9 ms, within the
    bound, so the bars are computed as before the bound."""
    _without_sensitivities(monkeypatch)
    res, runs, at_limit = _fit(monkeypatch, 1e-3, 0.05)
    assert res.interrupted and not res.converged, res.message
    assert not any(r == LATE_REASON for r in res.reasons.values()), res.reasons
    assert res.determined["stiffness"] and math.isfinite(res.stderr["stiffness"]), res.reasons
    assert runs <= at_limit + 2 + len(res.names), (runs, at_limit)


def test_the_springs_late_jacobian_is_one_run_and_keeps_the_bars(monkeypatch: pytest.MonkeyPatch) -> None:
    """With the spring's exact sensitivities, the case that gave no bars above (0.3 s per run, 3 s
    limit) ends with one run at the values reached and one sensitivity run: every bar is computed."""
    res, runs, at_limit = _fit(monkeypatch, 0.3, 3.0)
    assert res.interrupted and not res.converged, res.message
    assert not any(r == LATE_REASON for r in res.reasons.values()), res.reasons
    assert res.determined["stiffness"] and math.isfinite(res.stderr["stiffness"]), res.reasons
    # the run at the values reached, then the Jacobian: this clock counts each column's two moved
    # predictions (Problem.residuals on the tangent's motion, no integration) as runs too
    assert runs <= at_limit + 2 + 2 * len(res.names), (runs, at_limit)
