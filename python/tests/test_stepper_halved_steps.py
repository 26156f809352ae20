"""``pl.Stepper(..., halved_steps=True)``: every fixed step (each sub-step between a sampled pivot's
samples, each step shortened onto a ``step_to`` time) taken as two equal halves, passed to the core
``Stepper`` as ``simulate`` passes it to its ``Solver`` for the error estimate's dt/2 companion
(``RunOptions(halved_steps=True)``, core ``Stepper::set_halved_steps``; docs/integrators.md). The
claims: without breaks it is the run at dt/2 bit for bit; on a sampled pivot it is the error
estimate's companion run bit for bit, and not the run at dt/2 (which splits on the samples elsewhere);
the flag is checked. SI units: l = 1 m, g = 9.81 m/s², samples 7 … 13 ms apart.
"""

from __future__ import annotations

import numpy as np
import pytest
from sampled_paths import start, uneven, wavy

import pendulab as pl
from pendulab.simulation import _simulate_halved


@pytest.mark.parametrize("method", ["rk4", "rattle4"])
def test_without_breaks_the_halved_steps_are_the_run_at_half_the_step_bit_for_bit(method: str) -> None:
    """An ideal pendulum: 300 halved steps of 10 ms are 600 steps of 5 ms (the same bits and counts);
    to 3.217 s, 21 more steps of 10 ms and the shortened one of 7 ms, each as two halves."""
    p = pl.Pendulum()
    s0 = p.state_from_angles(theta=1.2, phi_dot=1.5)
    halved = pl.Stepper(p, s0, method=method, dt=0.01, halved_steps=True)
    half = pl.Stepper(p, s0, method=method, dt=0.005)
    a, b = halved.step(300), half.step(600)
    assert np.array_equal(a.x, b.x) and np.array_equal(a.v, b.v)
    assert halved.stats == half.stats and halved.stats["steps"] == 600
    # a step shortened onto t is halved too (two of 3.5 ms), not the dt/2 grid's 5 ms and 2 ms
    halved.step_to(3.217)
    assert halved.stats["steps"] == 600 + 2 * 21 + 2


@pytest.mark.parametrize("method", ["rk4", "rattle"])
def test_on_a_sampled_pivot_it_is_the_error_estimates_companion_bit_for_bit(method: str) -> None:
    """``step_to`` each save time with halved steps is the dt/2 companion of ``simulate``'s error
    estimate (``_simulate_halved``) saved there; the run at dt/2 differs (the samples split its steps
    elsewhere), and without the flag the stepper is the plain run."""
    p = wavy(uneven(2, t_end=1.2))
    save = np.linspace(0.0, 1.0, 11)
    kw = {"method": method, "dt": 0.016, "save_at": save}
    companion = _simulate_halved(p, start(p), 1.0, **kw)
    plain = pl.simulate(p, start(p), 1.0, **kw)
    at_half = pl.simulate(p, start(p), 1.0, **(kw | {"dt": 0.008}))
    st = pl.Stepper(p, start(p), method=method, dt=0.016, halved_steps=True)
    xs = np.array([st.step_to(t).x for t in save[1:]])
    assert np.array_equal(xs, companion.x[1:]) and st.stats["steps"] == companion.stats["steps"]
    assert not np.array_equal(xs, at_half.x[1:])
    whole = pl.Stepper(p, start(p), method=method, dt=0.016)
    assert np.array_equal(np.array([whole.step_to(t).x for t in save[1:]]), plain.x[1:])


def test_halved_steps_is_checked_and_leaves_dop853_alone() -> None:
    """A bool (named in the error); ``dop853`` steps as without it."""
    p = pl.Pendulum()
    s0 = p.state_from_angles(theta=0.5)
    with pytest.raises(pl.InvalidInputError, match=r"halved_steps.*True or False"):
        pl.Stepper(p, s0, dt=0.01, halved_steps="yes")  # type: ignore[arg-type]
    adaptive = [pl.Stepper(p, s0, method="dop853", halved_steps=on) for on in (True, False)]
    assert np.array_equal(adaptive[0].step(20).x, adaptive[1].step(20).x)
