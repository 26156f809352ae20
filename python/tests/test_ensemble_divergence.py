"""A diverged trajectory of an ensemble is named as ``pl.simulate`` names it: by the time of its last
finite state (the start of the step that was not finite), not by the run's end. Units SI; l = 1 m,
g = 9.81 m/s²."""

from __future__ import annotations

import re

import numpy as np
import pytest

import pendulab as pl


def _diverged_at(e: Exception) -> float:
    m = re.search(r"diverged after t = ([0-9.e+-]+) s", str(e))
    assert m is not None, str(e)
    return float(m.group(1))


@pytest.mark.parametrize("save_every", [2, None])
def test_a_diverged_ensemble_trajectory_is_named_by_its_last_finite_state(save_every: int | None) -> None:
    # RATTLE at dt = 0.9 s (a period is 2 s): the position equation loses its root in the first or
    # second step; the first start's sample at 1.8 s is the first not finite (was named: t_end = 36 s)
    p = pl.Pendulum(length=1.0, g=9.81)
    states = pl.states_from_angles(p, theta=np.linspace(0.1, 3.0, 9))
    dt, t_end = 0.9, 36.0
    with pytest.raises(pl.IntegrationError) as ens:
        pl.simulate_ensemble(p, states, t_end=t_end, dt=dt, save_every=save_every)
    # the first start alone names the same time, the start of its step that failed
    with pytest.raises(pl.IntegrationError) as single:
        pl.simulate(p, p.state(states[0, :3], states[0, 3:]), t_end, method="rattle", dt=dt, save_every=2)
    assert _diverged_at(ens.value) == _diverged_at(single.value) == 0.9, (str(ens.value), str(single.value))
