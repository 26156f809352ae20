"""The clock of ``pl.fit`` (fitting/search.py, :class:`Clock`): one clock per fit, given to every search
of the fit when it is made (the profiles' refits used to get a search of their own whose start time was
patched afterwards). Units: s."""

from __future__ import annotations

import math
import time
import warnings
from typing import Any

import numpy as np
import pytest

import pendulab as pl
from pendulab.fitting import estimator, profile
from pendulab.fitting.search import Clock, Search


def _swing() -> dict[str, Any]:
    """Noisy positions of an elliptical swing: l 0.8 m, g 9.79 m/s², 12 s at 50 Hz."""
    p = pl.Pendulum(length=0.8, g=9.79)
    t = np.linspace(0.0, 12.0, 600)
    x, _ = pl.exact(p, p.state_from_angles(0.4, 0.2, 0.1, 0.5)).state(t)
    noisy = x + 1e-3 * np.random.default_rng(7).standard_normal(x.shape)
    return {"t": t, "positions": noisy, "fit": ["length", "g"]}


@pytest.fixture
def made(monkeypatch: pytest.MonkeyPatch) -> list[Search]:
    """Every :class:`Search` made while the test runs, in order."""
    searches: list[Search] = []
    init = Search.__init__

    def record(self: Search, *args: Any, **kwargs: Any) -> None:
        init(self, *args, **kwargs)
        searches.append(self)

    monkeypatch.setattr(Search, "__init__", record)
    return searches


def test_a_profile_refit_is_made_with_the_fits_clock(made: list[Search]) -> None:
    """profile.Rise made each refit's search with the fit's time_limit, then set its ``began`` to the
    fit's: now the search is made with the fit's clock itself, and no search's start can be patched."""
    res = pl.fit(**_swing(), time_limit=600.0)
    fit_search = made[0]
    assert fit_search.time_limit == 600.0 and all(s.clock is fit_search.clock for s in made)
    values = {**res.fixed, **res.params}
    period = 2.0 * math.pi * math.sqrt(values["length"] / values["g"])
    made.clear()
    rise = profile.Rise(res, "g", period, clock=fit_search)
    d, _, _ = rise(values["g"] * (1.0 + 1e-4), values)
    assert d > 0.0 and made and all(s.clock is fit_search.clock for s in made)
    with pytest.raises(AttributeError):
        made[0].began = 0.0  # type: ignore[misc]
    made.clear()
    profile.Rise(res, "g", period)(values["g"], values)  # FitResult.profile's: no limit
    assert made and all(s.time_limit is None and not s.time_up() for s in made)


def test_a_clock_counts_from_its_start() -> None:
    clock = Clock(2.0, began=0.0)  # long ago
    assert clock.time_up() and not Clock(2.0).time_up() and Clock(2.0).time_up(ahead=3.0)
    assert not Clock(None, began=0.0).time_up(ahead=1e9)


#: The data's preparation slowed by this much [s] ...
SLOW = 2.5
#: ... past a limit of this [s] (the fit of these data alone takes 0.15 s at load 15).
LIMIT = 2.0


def test_the_time_limit_counts_the_datas_reading(monkeypatch: pytest.MonkeyPatch) -> None:
    """The limit's clock started when the search was made, so reading and checking the data (and the
    starting values read off them) did not count: a fit whose preparation alone took longer than the
    limit still searched for the whole limit after it. Now the clock starts at pl.fit's entry: such a
    fit stops at the search's first model runs, marked interrupted, with the time it took counted
    from the call."""
    read = estimator._Setup.read

    def slow(*args: Any, **kwargs: Any) -> Any:
        time.sleep(SLOW)
        return read(*args, **kwargs)

    import scipy.optimize  # noqa: F401  # imported first: the import cannot be interrupted (docs/fit.md)

    monkeypatch.setattr(estimator._Setup, "read", slow)
    began = time.perf_counter()
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        res = pl.fit(**_swing(), time_limit=LIMIT)
    took = time.perf_counter() - began
    assert (
        res.interrupted
        and not res.converged
        and res.message == f"interrupted (the time limit of {LIMIT:g} s)"
    )
    assert any(f"time limit of {LIMIT:g} s" in str(w.message) for w in caught), [
        str(w.message) for w in caught
    ]
    assert SLOW <= res.seconds <= took, (res.seconds, took)  # counted from the call (was 0.15 s)
    # the search ran its first model runs only, then the error analysis: 4 model runs (the fit: 19)
    assert res.evaluations <= 10, res.evaluations
