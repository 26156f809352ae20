"""The run as one description crossing the border (python/rust/spec.rs): ``ModelSpec`` built once by
the model classes, ``RunOptions``, and the classes that take ``(spec, state, options)``. SI units."""

from __future__ import annotations

import pickle

import numpy as np
import pytest

import pendulab as pl
from pendulab import _core


def test_the_spec_is_built_once_and_pickles_to_the_same_run() -> None:
    times = np.linspace(0.0, 2.0, 21)
    path = np.column_stack([0.01 * np.sin(3 * times), np.zeros_like(times), np.zeros_like(times)])
    for p in (pl.Pendulum(damping=0.2, drag=0.05), pl.Pendulum(pivot_samples=(times, path))):
        assert p.spec is p.spec
        back = pickle.loads(pickle.dumps(p))
        assert (back.spec.name, back.spec.length, back.spec.g) == (p.model, p.length, p.g)
        s0 = p.state_from_angles(theta=0.7, phi_dot=1.0)
        a = pl.simulate(p, s0, t_end=1.0, method="rattle", dt=1e-3)
        b = pl.simulate(back, s0, t_end=1.0, method="rattle", dt=1e-3)
        assert np.array_equal(a.x, b.x) and np.array_equal(a.v, b.v)
    spring = pl.SwingingSpring.resonant()
    assert pickle.loads(pickle.dumps(spring.spec)).name == "spring"


def test_a_spec_of_the_wrong_kind_or_options_missing_are_named() -> None:
    p = pl.Pendulum()
    s0 = p.state_from_angles(theta=0.5)
    with pytest.raises(_core.InvalidInputError, match="t_end"):
        _core.Solver(p.spec, s0.pair, _core.RunOptions(method="rattle", dt=1e-3))
    with pytest.raises(_core.InvalidInputError, match="off the sphere"):
        _core.Stepper(pl.SwingingSpring.resonant().spec, s0.pair, _core.RunOptions())
    with pytest.raises(_core.InvalidInputError, match="'string' model"):
        _core.StringStepper(p.spec, s0.pair, _core.RunOptions(method="rattle", dt=1e-3))
    with pytest.raises(_core.InvalidInputError, match="either save_every or save_times"):
        _core.RunOptions(save_every=2, save_times=np.array([0.0, 1.0]))
    with pytest.raises(_core.InvalidInputError, match="rattle"):
        _core.RunOptions(method="no_such_method")
    with pytest.raises(_core.InvalidInputError, match="x0 must have 3 components"):
        _core.Stepper(p.spec, (np.zeros(2), np.zeros(3)), _core.RunOptions())


def test_options_default_to_the_cores_solve_options() -> None:
    o = _core.RunOptions()
    assert (o.t0, o.t_end, o.method, o.dt) == (0.0, None, "rattle", 1e-3)


def test_the_theory_bindings_take_the_spec_of_their_own_model() -> None:
    """The states, the exact solution, the reduced flow and the linear crane read l, m, g (and the
    crane's radius, rate, damping) from the spec, and refuse a spec of another model by name."""
    p = pl.Pendulum(length=2.0, g=9.81, mass=0.5)
    s0 = p.state_from_angles(theta=0.7, phi_dot=1.0)
    x, v = _core.state_from_angles(p.spec, [0.7, 0.0, 0.0, 1.0])
    assert np.array_equal(x, s0.x) and np.array_equal(v, s0.v)
    assert abs(float(np.linalg.norm(x)) - 2.0) < 1e-15  # the spec's l, not a default
    sol = _core.ExactSolution(p.spec, s0.pair)
    assert sol.period_z == pl.exact(p, s0).period_z
    damped = pl.Pendulum(length=2.0, damping=0.1)
    with pytest.raises(_core.InvalidInputError, match='not the "damped" model'):
        _core.ExactSolution(damped.spec, s0.pair)
    with pytest.raises(_core.InvalidInputError, match="ideal pendulum's"):
        _core.reduced_flow(damped.spec, s0.pair, _core.RunOptions(dt=1e-3), 10)
    with pytest.raises(_core.InvalidInputError, match='not the "ideal" model'):
        _core.slewing_linear(p.spec, [0.0, 0.0, 0.0, 0.0], np.array([0.0, 1.0]))
    with pytest.raises(_core.InvalidInputError, match="off the sphere"):
        _core.state_on_ts2(pl.SwingingSpring.resonant().spec, s0.x, s0.v)
