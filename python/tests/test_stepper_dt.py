"""``pl.Stepper``'s dt has :func:`pl.simulate`'s rule: a fixed-step method's step [s] (left out or None:
1e-3 s), ``dop853``'s first step [s] (left out or None: chosen automatically). The Stepper refused
``dt=None`` and gave ``dop853`` a first step of 1e-3 s when dt was left out; a bad dt of a fixed-step
method is named with the method's rule, as dop853's is (docs/reference/api.md, docs/limits.md)."""

from __future__ import annotations

import numpy as np
import pytest

import pendulab as pl


@pytest.fixture
def start() -> tuple[pl.Pendulum, pl.State]:
    p = pl.Pendulum()
    return p, p.state_from_angles(theta=0.5, phi_dot=1.0)


@pytest.mark.parametrize("given", [{}, {"dt": None}])
def test_dop853_without_dt_chooses_its_first_step_as_simulate_does(start, given) -> None:
    p, s0 = start
    st = pl.Stepper(p, s0, method="dop853", **given)
    st.step(1)
    auto = pl.simulate(p, s0, 10.0, method="dop853")
    assert st.t == auto.t[1] != 1e-3  # the automatic first step, not 1 ms
    st.step_to(10.0)
    np.testing.assert_array_equal(st.state.x, auto.x[-1])
    assert st.stats["steps"] == auto.stats["steps"]
    assert repr(st).startswith("Stepper(dop853, adaptive, t=10 s"), repr(st)
    assert "adaptive (first step automatic)" in st._repr_html_()


def test_dop853_keeps_a_given_first_step(start) -> None:
    p, s0 = start
    st = pl.Stepper(p, s0, method="dop853", dt=1e-4)
    st.step(1)
    assert st.t == 1e-4
    given = pl.simulate(p, s0, 10.0, method="dop853", dt=1e-4)
    np.testing.assert_array_equal(st.step_to(10.0).x, given.x[-1])
    assert repr(st).startswith("Stepper(dop853, adaptive, first step 0.0001 s, t=10 s"), repr(st)
    assert "adaptive, first step" in st._repr_html_()


@pytest.mark.parametrize("method", ["rattle", "rattle4", "rk4"])
def test_a_fixed_step_method_without_dt_takes_1_ms(start, method) -> None:
    p, s0 = start
    default, none = pl.Stepper(p, s0, method=method), pl.Stepper(p, s0, method=method, dt=None)
    given = pl.Stepper(p, s0, method=method, dt=1e-3)
    for st in (default, none, given):
        st.step(250)
        assert repr(st).startswith(f"Stepper({method}, dt=0.001 s, t=0.25 s"), repr(st)
    np.testing.assert_array_equal(default.state.x, given.state.x)
    np.testing.assert_array_equal(none.state.x, given.state.x)
    tr = pl.simulate(p, s0, 0.25, method=method, arithmetic="unfused" if "rattle" in method else "auto")
    st = pl.Stepper(p, s0, method=method, arithmetic="unfused" if "rattle" in method else "auto")
    np.testing.assert_array_equal(st.step(250).x, tr.x[-1])


@pytest.mark.parametrize("dt", [0.0, -1e-3, float("nan"), 1e-13, "1e-3"])
def test_a_bad_dt_of_a_fixed_step_method_names_the_method_and_the_rule(start, dt) -> None:
    p, s0 = start
    rule = (
        r"invalid dt = .*: a finite number in \[1e-12, 1e6\] s \(the step of rattle4\), or None for 0\.001 s"
    )
    with pytest.raises(pl.InvalidInputError, match=rule):
        pl.Stepper(p, s0, method="rattle4", dt=dt)
    with pytest.raises(pl.InvalidInputError, match=rule):
        pl.simulate(p, s0, 1.0, method="rattle4", dt=dt)
