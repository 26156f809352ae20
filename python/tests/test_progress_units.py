"""Progress bars count what they say: an ensemble's bar counts trajectory-steps (n, total and unit
"step"), a chunked run's (``simulate``, the string pendulum, the crane's LQR loop) seconds of simulated
time (unit "s"), not per mille of the work under a label of items."""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest
from tqdm.std import tqdm as text_bar

import pendulab as pl
from pendulab import _progress, crane
from pendulab.ensemble import run as ensemble_run

BARS: list[text_bar[Any]] = []


class _Recorded(text_bar):  # type: ignore[type-arg]
    def __init__(self, *args: Any, **kwargs: Any) -> None:
        super().__init__(*args, **kwargs)
        BARS.append(self)


@pytest.fixture
def bars(monkeypatch: pytest.MonkeyPatch) -> list[text_bar[Any]]:
    BARS.clear()
    for module in (_progress, ensemble_run):  # _progress.seconds_bar: the chunked runs' and the LQR loop's
        monkeypatch.setattr(module, "tqdm", _Recorded)
    return BARS


def test_an_ensemble_bar_counts_trajectory_steps(bars: list[text_bar[Any]]) -> None:
    p = pl.Pendulum()
    starts = pl.states_from_angles(p, theta=np.linspace(0.1, 1.0, 7))
    pl.simulate_ensemble(p, starts, t_end=0.5, dt=1e-3, progress=True)
    (bar,) = bars
    assert (bar.n, bar.total, bar.unit) == (7 * 500, 7 * 500, "step")
    assert bar.desc == "7 trajectories × 500 steps"


def test_a_chunked_simulate_bar_counts_simulated_seconds(bars: list[text_bar[Any]]) -> None:
    p = pl.Pendulum()
    pl.simulate(p, p.state_from_angles(0.5), 3.0, t0=1.0, dt=1e-3, method="rattle", progress=True)
    (bar,) = bars
    assert bar.unit == "s"
    assert bar.total == pytest.approx(2.0, abs=1e-12)
    assert bar.n == pytest.approx(2.0, abs=1e-12)  # all of it done
    assert bar.desc == "rattle, simulated s from t=1"
    assert "2.00/2.00" in str(bar)  # 2 s of 2 s, not "1000/1000"


def test_a_string_pendulum_bar_counts_simulated_seconds(bars: list[text_bar[Any]]) -> None:
    # the span comes from the core's runner: its start t0 and its t_end
    p = pl.Pendulum(model="string", restitution=0.5)
    pl.simulate(
        p, p.state_from_angles(2.0, phi_dot=1.0), 2.5, t0=-0.5, method="rattle", dt=1e-3, progress=True
    )
    (bar,) = bars
    assert (bar.unit, bar.desc) == ("s", "rattle, simulated s from t=-0.5")
    assert bar.total == pytest.approx(3.0, abs=1e-12)
    assert bar.n == pytest.approx(3.0, abs=1e-12)


def test_the_lqr_loop_bar_counts_simulated_seconds(bars: list[text_bar[Any]]) -> None:
    control = crane.lqr(0.5, q=(1.0, 1.0, 50.0, 1.0), a_max=0.6)
    control.simulate(3.0, t_end=300.0, t_start=100.0, sway=0.1, progress=True)
    (bar,) = bars
    assert (bar.unit, bar.total, bar.desc) == ("s", 200.0, "LQR loop, simulated s from t=100")
    assert bar.n == pytest.approx(200.0, abs=1e-9)
