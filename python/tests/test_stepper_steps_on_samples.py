"""``pl.Stepper(..., steps_on_samples=True)``: a sampled pivot stepped by hand with dt the longest fixed
step and the steps on every sample (core ``Stepper::set_steps_on_breaks``; docs/integrators.md, "Sampled
pivot"). The claims: the same bits as ``pl.simulate(..., steps_on_samples=True)`` for the same settings,
however the steps are asked for; against the exact solution (the pivot on (0.3t, −0.2t, t²) m, which
the spline reproduces: the ideal pendulum under g + 2 m/s², ``sampled_paths.py``) the error falls as
dt^p when dt is halved near the spacing; the same checks of the flag as ``simulate``. SI units: l = 1 m,
g = 9.81 m/s², samples 7 … 13 ms apart.
"""

from __future__ import annotations

import numpy as np
import pytest
from sampled_paths import A_UP, ORDERS, G, accelerating, start, uneven, wavy

import pendulab as pl


def stepper(p: pl.Pendulum, method: str, dt: float, on: bool = True) -> pl.Stepper:
    return pl.Stepper(p, start(p), method=method, dt=dt, steps_on_samples=on)


@pytest.mark.parametrize("method", ["rk4", "rattle", "rattle4", "rattle8"])
def test_step_to_every_save_time_gives_simulates_run_bit_for_bit(method: str) -> None:
    """``step_to`` each time of ``save_at`` (between samples: the last step of each shortened) is
    ``simulate``'s run saved there; ``step(10)`` repeated is its ``save_every=10`` run."""
    p = wavy(uneven(3, spread=0.8))
    save = np.linspace(0.0, 3.0, 37)
    tr = pl.simulate(p, start(p), 3.0, method=method, dt=0.004, save_at=save, steps_on_samples=True)
    st = stepper(p, method, 0.004)
    for k, t in enumerate(save[1:], start=1):
        s = st.step_to(t)
        assert st.t == t and np.array_equal(s.x, tr.x[k]) and np.array_equal(s.v, tr.v[k]), (method, t)
    assert st.stats["steps"] == tr.stats["steps"] and st.stats["rhs_evals"] == tr.stats["rhs_evals"]

    every = pl.simulate(p, start(p), 3.0, method=method, dt=0.004, save_every=10, steps_on_samples=True)
    st = stepper(p, method, 0.004)
    for k in range(1, len(every.t) - 1):  # the last sample is t_end = 3 s, after a shortened step
        s = st.step(10)
        assert st.t == every.t[k] and np.array_equal(s.x, every.x[k]) and np.array_equal(s.v, every.v[k])
    s = st.step_to(3.0)
    assert np.array_equal(s.x, every.x[-1]) and st.stats["steps"] == every.stats["steps"]


def test_any_mix_of_step_and_step_to_is_simulates_run_saved_at_the_times_reached() -> None:
    """``step(n)`` ends on the stretch's grid, ``step_to`` shortens a step: saved at the times the
    stepper reached, ``simulate`` takes the same steps (core test: tests/stepper_on_samples.rs)."""
    p = wavy(uneven(5))
    st = stepper(p, "rattle4", 0.006)
    reached, xs = [0.0], [st.state.x]
    for k in range(45):
        s = st.step(1 + k % 4) if k % 2 else st.step_to(st.t + 0.0171)
        reached.append(st.t)
        xs.append(s.x)
    tr = pl.simulate(
        p, start(p), reached[-1], method="rattle4", dt=0.006, save_at=reached, steps_on_samples=True
    )
    assert np.array_equal(tr.t, reached) and np.array_equal(tr.x, np.array(xs))
    assert tr.stats["steps"] == st.stats["steps"]


@pytest.mark.parametrize("method", sorted(ORDERS))
def test_halving_dt_cuts_the_error_against_the_exact_solution_by_two_to_the_order(method: str) -> None:
    """dt = 13 ms ≥ every gap (one step per interval), 6.5 ms < every gap (two): stepped to 20 times,
    the error falls by 2^p on the samples, and by more than half an order less with the default split
    steps (as ``simulate``'s, test_steps_on_samples.py)."""
    p = accelerating(uneven(1))
    save = np.linspace(0.15, 3.0, 20)
    x_exact = pl.exact(pl.Pendulum(length=1.0, g=G + A_UP), start(p)).state(save)[0]

    def err(dt: float, on: bool) -> float:
        st = stepper(p, method, dt, on)
        x = np.array([st.step_to(t).x for t in save])
        return float(np.max(np.linalg.norm(x - x_exact, axis=1)))

    observed = {on: float(np.log2(err(0.013, on) / err(0.0065, on))) for on in (True, False)}
    assert abs(observed[True] - ORDERS[method]) < 0.15, observed
    assert observed[False] < ORDERS[method] - 0.5, observed


def test_after_set_state_the_steps_keep_their_order() -> None:
    """``set_state`` at 1.0047 s (between samples) with the exact state there: the stretch to the next
    sample is planned again, and the error at 3 s still falls by 2^4 (rk4) when dt is halved."""
    p = accelerating(uneven(1))
    exact = pl.exact(pl.Pendulum(length=1.0, g=G + A_UP), start(p))

    def err(dt: float) -> float:
        st = stepper(p, "rk4", dt)
        st.step_to(1.0047)
        st.set_state(exact.state(1.0047))
        x_end = exact.state(3.0).x
        return float(np.linalg.norm(st.step_to(3.0).x - x_end))

    assert abs(np.log2(err(0.013) / err(0.0065)) - 4.0) < 0.15


def test_steps_on_samples_is_checked_as_in_simulate() -> None:
    """A bool, and True only with pivot samples: the same errors as ``simulate``; ``dop853`` takes it
    and steps as without (its steps end on the samples anyway); the repr says dt is the longest."""
    ideal = pl.Pendulum()
    for run in (
        lambda on: pl.Stepper(ideal, start(ideal), dt=0.01, steps_on_samples=on),
        lambda on: pl.simulate(ideal, start(ideal), 0.1, dt=0.01, steps_on_samples=on),
    ):
        with pytest.raises(
            pl.InvalidInputError, match=r"steps_on_samples=True .* 'ideal' .* no pivot_samples"
        ):
            run(True)
        with pytest.raises(pl.InvalidInputError, match="steps_on_samples"):
            run("yes")
    p = wavy(uneven(1))
    assert pl.Stepper(p, start(p), dt=0.01).stats == stepper(p, "rattle", 0.01, on=False).stats
    adaptive = [pl.Stepper(p, start(p), method="dop853", steps_on_samples=on) for on in (True, False)]
    assert [a.step(20).x.tolist() for a in adaptive[:1]] == [adaptive[1].step(20).x.tolist()]
    assert "dt=0.01 s at most, on the samples" in repr(stepper(p, "rk4", 0.01))
    assert "at most" not in repr(adaptive[0]) and "at most" not in repr(stepper(p, "rk4", 0.01, on=False))
