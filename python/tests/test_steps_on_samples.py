"""``simulate(..., steps_on_samples=True)`` on a sampled pivot: dt the longest fixed step, each
interval between samples taken in ⌈span/dt⌉ equal steps (core ``Stepper::set_steps_on_breaks``;
docs/integrators.md, "Sampled pivot"). The claims, each against a reference that does not share the
runs' steps: on unevenly spaced samples the error falls as dt^p when dt is halved near the spacing
(it did not on the split grid), and the same dt costs fewer steps for no more error. SI units:
l = 1 m, g = 9.81 m/s², samples 7 … 13 ms apart.
"""

from __future__ import annotations

import numpy as np
import pytest
from sampled_paths import A_UP, ORDERS, G, accelerating, error, start, uneven, wavy

import pendulab as pl


def test_the_accelerating_pivot_is_the_ideal_pendulum_under_g_plus_its_acceleration() -> None:
    """The reference of the next test: a tight DOP853 run on the sampled pivot meets the exact solution."""
    p = accelerating(uneven(1))
    exact = pl.exact(pl.Pendulum(length=1.0, g=G + A_UP), start(p))
    tr = pl.simulate(p, start(p), 3.0, method="dop853", rtol=1e-13, atol=1e-14, save_at=np.linspace(0, 3, 31))
    assert error(tr, exact.state(tr.t)[0]) < 1e-10


@pytest.mark.parametrize("method", sorted(ORDERS))
def test_halving_dt_near_the_spacing_cuts_the_error_against_the_exact_solution_by_two_to_the_order(
    method: str,
) -> None:
    """dt = 13 ms ≥ every gap: one step per interval; 6.5 ms < every gap: two. With the steps on the
    samples the error at 20 saved times falls by 2^p (p the method's order); on the split grid (the
    default) the steps that hold a sample are cut there at points that do not move with dt, and the
    observed order falls short of p by more than half."""
    p = accelerating(uneven(1))
    s0 = start(p)
    save = np.linspace(0.15, 3.0, 20)
    x_exact = pl.exact(pl.Pendulum(length=1.0, g=G + A_UP), s0).state(save)[0]

    def err(dt: float, on: bool) -> float:
        tr = pl.simulate(p, s0, 3.0, method=method, dt=dt, save_at=save, steps_on_samples=on)
        return error(tr, x_exact)

    observed = {on: float(np.log2(err(0.013, on) / err(0.0065, on))) for on in (True, False)}
    assert abs(observed[True] - ORDERS[method]) < 0.15, observed
    assert observed[False] < ORDERS[method] - 0.5, observed


def test_the_same_dt_takes_fewer_steps_for_no_more_error() -> None:
    """Samples 6 … 14 ms apart, ``rk4`` at dt = 10 ms, against DOP853 at rtol 1e-13: the steps on the
    samples are Σ⌈gap/dt⌉ (no step split), fewer than the split grid's, and the error is not larger."""
    times = uneven(3, spread=0.8)
    p = wavy(times)
    s0 = start(p)
    on = pl.simulate(p, s0, 3.0, method="rk4", dt=0.01, save_every=10, steps_on_samples=True)
    split = pl.simulate(p, s0, 3.0, method="rk4", dt=0.01, save_every=10)
    assert on.options["steps_on_samples"] is True and "steps_on_samples" not in split.options
    # every interval between samples in ⌈gap/dt⌉ equal steps, the one holding t_end = 3 s up to it
    inside = np.flatnonzero((times >= 0.0) & (times < 3.0))
    lo, hi = times[inside], times[inside + 1]
    n = np.ceil((hi - lo) / 0.01)
    n[-1] = np.ceil((3.0 - lo[-1]) / ((hi[-1] - lo[-1]) / n[-1]) - 1e-9)
    assert on.stats["steps"] == int(n.sum()), (on.stats, n.sum())
    assert split.stats["steps"] > 1.25 * on.stats["steps"], (split.stats, on.stats)

    def err(tr: pl.Trajectory) -> float:
        ref = pl.simulate(p, s0, 3.0, method="dop853", rtol=1e-13, atol=1e-14, save_at=tr.t)
        return error(tr, ref.x)

    assert err(on) <= err(split), (err(on), err(split))


def test_steps_on_samples_is_off_by_default_and_a_bool() -> None:
    p = wavy(uneven(1))
    with pytest.raises(pl.InvalidInputError, match="steps_on_samples"):
        pl.simulate(p, start(p), 0.1, dt=0.01, steps_on_samples="yes")  # type: ignore[arg-type]
    steps = {
        on: pl.simulate(p, start(p), 0.1, dt=0.01, steps_on_samples=on).stats["steps"] for on in (False, True)
    }
    assert pl.simulate(p, start(p), 0.1, dt=0.01).stats["steps"] == steps[False] != steps[True], steps
