"""The clock of ``pl.fit`` (fitting/search.py, :class:`Clock`): one clock per fit, given to every search
of the fit when it is made (the profiles' refits used to get a search of their own whose start time was
patched afterwards). Units: s."""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import pytest

import pendulab as pl
from pendulab.fitting import profile
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
