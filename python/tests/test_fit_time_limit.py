"""``pl.fit``'s ``time_limit`` bounds the whole fit, the error analysis's profile likelihoods too: over
a record shorter than a swing (bench/fit_validate.py case 20, "a third of a swing": 0.5 s of a video's
x, z, data from the independent SciPy integrator) the refits of the profiles (short_record.py,
profile.py) ran with no limit, each up to 3 × 200 model runs, and the limit was checked only between
them: at load 13–15 such a fit took a median of 75 s with the limit at 60 s. Units: s."""

from __future__ import annotations

import math
import sys
import time
import warnings
from pathlib import Path
from typing import Any

import numpy as np
import pytest

import pendulab as pl
from pendulab.fitting import inference, profile
from pendulab.fitting.problem import Problem

sys.path.append(str(Path(__file__).resolve().parents[2] / "bench"))  # last: bench/ has animate.py, compare.py
from fit_validate_cases import cases

CASE_20 = 19  # the index of "a third of a swing" in fit_validate_cases.cases()

#: The limit falls this long after the first profile refit began [s] ...
LEFT = 0.02
#: ... and the fit must return within this much more [s]: a model run and an exact Jacobian (a few ms
#: each) on a loaded machine, and the result's assembly. Before, the refit under way ran on: 3.3 s
#: and 18 model runs past the limit (load 9).
SLACK = 1.0


class _Deadline:
    """Sets the fit's limit to fall LEFT s after its first profile refit began (the search before
    it takes 2–60 s depending on the load: a fixed limit would land in the search on a loaded
    machine), and counts the search's model runs past it."""

    def __init__(self, monkeypatch: pytest.MonkeyPatch) -> None:
        self.search: Any = None
        self.at = math.inf
        self.late = 0
        polished, rise, safe = inference._polished, profile.Rise.__call__, Problem.safe_residuals

        def keep(search: Any, *args: Any) -> Any:
            self.search = search
            return polished(search, *args)

        def first(rise_self: Any, c: float, start: dict[str, float]) -> Any:
            if self.at == math.inf:
                self.at = time.perf_counter() + LEFT
                self.search.clock.time_limit = self.at - self.search.began
            return rise(rise_self, c, start)

        def counted(problem: Any, *args: Any, **kwargs: Any) -> Any:
            if time.perf_counter() > self.at:
                self.late += 1
            return safe(problem, *args, **kwargs)

        monkeypatch.setattr(inference, "_polished", keep)
        monkeypatch.setattr(profile.Rise, "__call__", first)
        monkeypatch.setattr(Problem, "safe_residuals", counted)


def _fit_through_ctrl_c(kw: dict[str, Any]) -> Any:
    """pl.fit(**kw), a KeyboardInterrupt out of it a test failure (not the end of the pytest session)."""
    try:
        return pl.fit(**kw)
    except KeyboardInterrupt:
        pytest.fail("Ctrl-C in the error analysis left pl.fit as KeyboardInterrupt: the fit was lost")


def _case_20() -> tuple[Any, dict[str, Any]]:
    """Case 20, seed 0 of the bench; the search cut at 100 model runs per start (not converged, which
    the profiles do not mind) to keep the test short."""
    case = cases()[CASE_20]
    data = case.make(np.random.default_rng([CASE_20, 1]), 1.0)
    return case, {
        "pendulum": pl.Pendulum(**case.pendulum),
        "fit": case.fit,
        "max_evaluations": 100,
        **data.kw,
    }


def test_the_time_limit_cuts_the_profiles_of_a_short_record(monkeypatch: pytest.MonkeyPatch) -> None:
    """The refits of the profiles ran with no limit (profile.py: ``time_limit=None``), the limit checked
    only between them: a refit begun just before it ran to its end. Now each is cut at a model run
    past the limit: the fit returns within SLACK of it, and the parameters whose profiles it cut short
    are not determined, their reason and the warning naming the time limit and how to raise it."""
    deadline = _Deadline(monkeypatch)
    _, kw = _case_20()
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        res = pl.fit(**kw)
    past = time.perf_counter() - deadline.at
    # the search itself ran to its end (its message is SciPy's): the limit fell in the profiles, and
    # the fit is marked interrupted all the same, some of its results incomplete
    assert res.interrupted and not res.message.startswith("interrupted"), res.message
    assert past < SLACK and deadline.late <= 2, (past, deadline.late)
    said = [str(w.message) for w in caught if "time limit of" in str(w.message)]
    advice = "give a larger limit (pl.fit's time_limit=, pendulab fit's --time-limit)"
    assert said and all(advice in s for s in said), [str(w.message) for w in caught]
    assert not any("the fit stopped" in why for why in res.reasons.values()), res.reasons
    cut = [n for n in res.names if "time limit" in res.reasons.get(n, "")]
    assert {"length", "g"} <= set(cut), res.reasons
    for name in cut:  # not determined: no bar that pretends its profile closed
        assert not res.determined[name] and res.stderr[name] == math.inf, name


def test_ctrl_c_in_a_profile_returns_the_fit(monkeypatch: pytest.MonkeyPatch) -> None:
    """Ctrl-C during a profile's refit (no time limit) raised KeyboardInterrupt out of pl.fit and lost
    the fit, where Ctrl-C in the search returns the best values: now the fit is returned, the
    parameters whose profiles were not finished not determined with a reason and a warning naming
    Ctrl-C (not the time limit), and no other profile is begun after it."""
    rise, safe = profile.Rise.__call__, Problem.safe_residuals
    profiling: list[float] = []

    def first(rise_self: Any, c: float, start: dict[str, float]) -> Any:
        profiling.append(c)
        return rise(rise_self, c, start)

    def pressed(problem: Any, *args: Any, **kwargs: Any) -> Any:
        if profiling:
            raise KeyboardInterrupt
        return safe(problem, *args, **kwargs)

    monkeypatch.setattr(profile.Rise, "__call__", first)
    monkeypatch.setattr(Problem, "safe_residuals", pressed)
    _, kw = _case_20()
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        res = _fit_through_ctrl_c(kw)
    assert len(profiling) == 1
    # Ctrl-C left res.interrupted False here, the fit marked complete with bars not determined
    assert res.interrupted and not res.message.startswith("interrupted"), res.message
    assert repr(res).endswith(", interrupted)"), repr(res)
    why = "Ctrl-C stopped the fit before the profile likelihood was checked"
    assert any(why in str(w.message) for w in caught), [str(w.message) for w in caught]
    cut = [n for n in res.names if why in res.reasons.get(n, "")]
    assert {"length", "g"} <= set(cut), res.reasons
    assert not any("time limit" in r for r in res.reasons.values()), res.reasons
    for name in cut:
        assert not res.determined[name] and res.stderr[name] == math.inf, name
    assert all(math.isfinite(v) for v in res.params.values()), res.params  # the search's optimum is kept


def test_a_robust_loss_says_why_it_is_not_profiled() -> None:
    """A short record fitted with a robust loss is never profiled, yet its reason said "the fit stopped
    before the profile likelihood was checked", which it had not: it now says that the profile is not
    computed with a robust loss and what to do."""
    _, kw = _case_20()
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        res = pl.fit(loss="soft_l1", **kw)
    why = "the profile likelihood is not computed with a robust loss (soft_l1); to check these bars"
    assert any(why in str(w.message) for w in caught), [str(w.message) for w in caught]
    robust = [n for n in res.names if why in res.reasons.get(n, "")]
    assert {"length", "g"} <= set(robust), res.reasons
    assert not any("stopped" in r for r in res.reasons.values()), res.reasons


@pytest.mark.parametrize(("step", "said"), [("polish", "the polish"), ("check_blocks", "the block check")])
def test_ctrl_c_in_the_polish_or_the_block_check_returns_the_fit(
    monkeypatch: pytest.MonkeyPatch, step: str, said: str
) -> None:
    """Ctrl-C in the polish or the block check of a misfit (inference.py) raised KeyboardInterrupt out
    of pl.fit: now that step ends, the profiles are skipped (their parameters not determined, the
    reason naming Ctrl-C, none begun) and a warning names Ctrl-C and the step."""

    def pressed(*args: Any, **kwargs: Any) -> Any:
        raise KeyboardInterrupt

    profiling: list[float] = []
    rise = profile.Rise.__call__

    def counted(rise_self: Any, c: float, start: dict[str, float]) -> Any:
        profiling.append(c)
        return rise(rise_self, c, start)

    monkeypatch.setattr(inference, step, pressed)
    monkeypatch.setattr(inference, "misfit_found", lambda *a: True)  # the block check runs
    monkeypatch.setattr(profile.Rise, "__call__", counted)
    _, kw = _case_20()
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        res = _fit_through_ctrl_c(kw)
    texts = [str(w.message) for w in caught]
    assert any(t.startswith(f"Ctrl-C stopped {said}") for t in texts), texts
    assert res.interrupted, step
    assert not profiling
    why = "Ctrl-C stopped the fit before the profile likelihood was checked"
    assert {"length", "g"} <= {n for n in res.names if why in res.reasons.get(n, "")}, res.reasons
    assert res.blocks is None
