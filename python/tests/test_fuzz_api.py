"""Property tests (hypothesis) of the core public entry points under hostile and extreme input
(issue 13): ``Pendulum``, its states (``state``, ``state_from_angles``), ``simulate`` with every method
of ``pl.method_names()``, ``Stepper`` and the exact solution. The generated arguments, the judgement of
each call (a finite result, or ``pl.InvalidInputError`` / ``pl.IntegrationError`` with a one-line
message of bounded length naming the input) and the work bound are in ``fuzz_inputs.py``; the derived
entry points are in ``test_fuzz_api_derived.py``.

Examples per entry point: ``FUZZ_EXAMPLES`` (default 60, derandomised, for CI; ``make fuzz`` runs
10 000 each and prints the counts). Units: SI.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from fuzz_inputs import (
    COUNTS,
    FUZZ,
    HOSTILE,
    JUNK,
    METHODS,
    MODELS,
    PARAM_NAMES,
    PENDULUMS,
    STARTS,
    VEC,
    _affordable,
    _report_counts,  # noqa: F401  (autouse: the counts of make fuzz)
    _start,
    check,
)
from hypothesis import given
from hypothesis import strategies as st

import pendulab as pl
from pendulab.validate import LIMITS

# --- parameters and states ---------------------------------------------------------------------------


@FUZZ
@given(
    length=HOSTILE,
    g=HOSTILE,
    mass=HOSTILE,
    model=st.one_of(st.none(), st.sampled_from(MODELS), JUNK),
    extra=st.dictionaries(st.sampled_from(PARAM_NAMES), HOSTILE, max_size=3),
)
def test_pendulum(length: Any, g: Any, mass: Any, model: Any, extra: dict[str, Any]) -> None:
    def call() -> pl.Pendulum:
        return pl.Pendulum(length=length, g=g, mass=mass, model=model, **extra)

    check("Pendulum", call, lambda p: (p.length, p.g, p.mass, list(p.extra.values())))


@FUZZ
@given(p=PENDULUMS, x=VEC, v=VEC, project=st.one_of(st.booleans(), JUNK))
def test_state(p: pl.Pendulum, x: Any, v: Any, project: Any) -> None:
    def values(s: pl.State) -> tuple[Any, ...]:
        if s.projection is not None:  # projected: on TS² to rounding
            r = abs(np.linalg.norm(s.x) - p.length) / p.length
            assert r < 1e-12, r
            # x·v after removing the radial part of v: rounding of the given v's size (a v almost
            # all radial keeps a tangential part only as accurate as the data, backward stable)
            v_in = np.linalg.norm(np.asarray(v, dtype=float))
            assert abs(s.x @ s.v) <= 1e-12 * p.length * max(v_in, 1e-300), (s.x, s.v, v)
        return s.x, s.v, p.energy(s), p.tension(s), p.j3(s)

    check("Pendulum.state", lambda: p.state(x, v, project=project), values)


@FUZZ
@given(p=PENDULUMS, theta=HOSTILE, phi=HOSTILE, theta_dot=HOSTILE, phi_dot=HOSTILE)
def test_state_from_angles(p: pl.Pendulum, theta: Any, phi: Any, theta_dot: Any, phi_dot: Any) -> None:
    def call() -> pl.State:
        return p.state_from_angles(theta=theta, phi=phi, theta_dot=theta_dot, phi_dot=phi_dot)

    check("Pendulum.state_from_angles", call, lambda s: (s.x, s.v, p.energy(s), p.tension(s)))


# --- integration -------------------------------------------------------------------------------------


@FUZZ
@given(
    p=PENDULUMS,
    start=STARTS,
    t_end=st.one_of(st.floats(0.01, 2.0), HOSTILE),
    method=METHODS,
    dt=st.one_of(st.none(), st.floats(1e-4, 0.05), HOSTILE),
    rtol=st.one_of(st.just(1e-8), HOSTILE),
    atol=st.one_of(st.just(1e-10), HOSTILE),
    project=st.one_of(st.booleans(), JUNK),
    save_every=st.one_of(st.none(), st.integers(-2, 100), JUNK),
    save_at=st.one_of(st.none(), st.lists(st.floats(0.0, 1.0), max_size=4), JUNK),
    t0=st.one_of(st.just(0.0), HOSTILE),
    drift=st.sampled_from(["raise", "raise", "warn", "bogus"]),
)
def test_simulate(
    p: pl.Pendulum,
    start: tuple[float, float],
    t_end: Any,
    method: str,
    dt: Any,
    rtol: Any,
    atol: Any,
    project: Any,
    save_every: Any,
    save_at: Any,
    t0: Any,
    drift: str,
) -> None:
    if not _affordable(t0, t_end, dt, method):
        return
    s = _start(p, *start)

    def call() -> pl.Trajectory:
        kwargs = {"save_every": save_every, "save_at": save_at, "t0": t0, "drift": drift}
        return pl.simulate(p, s, t_end, method=method, dt=dt, rtol=rtol, atol=atol, project=project, **kwargs)

    def values(tr: pl.Trajectory) -> tuple[Any, ...]:
        return tr.t, tr.x, tr.v, tr.energy, tr.j3, tr.tension, tr.constraint_error

    check("simulate", call, values)


@FUZZ
@given(
    p=PENDULUMS,
    start=STARTS,
    method=METHODS,
    dt=st.one_of(st.floats(1e-4, 0.05), HOSTILE),
    n=st.one_of(st.integers(0, 200), HOSTILE),
    t=st.one_of(st.floats(0.0, 0.5), HOSTILE),
)
def test_stepper(p: pl.Pendulum, start: tuple[float, float], method: str, dt: Any, n: Any, t: Any) -> None:
    s = _start(p, *start)

    def call() -> pl.State:
        stepper = pl.Stepper(p, s, method=method, dt=dt)
        if isinstance(n, int) and not isinstance(n, bool) and n > 2000 and n <= LIMITS["steps"]["max"]:
            return stepper.state
        stepper.step(n)
        if _affordable(stepper.t, t, dt, method):
            stepper.step_to(t)
        return stepper.state

    check("Stepper", call, lambda s: (s.x, s.v))


# --- the exact solution -----------------------------------------------------------------------------


@FUZZ
@given(
    p=PENDULUMS,
    theta=st.one_of(st.floats(0.0, math.pi), st.sampled_from([0.0, math.pi, 1e-8, math.pi - 1e-8])),
    theta_dot=st.one_of(st.floats(-10, 10), st.sampled_from([0.0, 1e-3, -1.5, 1e3, 1e6])),
    phi_dot=st.one_of(st.floats(-10, 10), st.sampled_from([0.0, 1e-12, 1e3, 1e6, 1e9, 1e300])),
    t=st.one_of(st.floats(-100, 100), HOSTILE, st.lists(st.floats(-1e6, 1e6), max_size=5)),
)
def test_exact(p: pl.Pendulum, theta: float, theta_dot: float, phi_dot: float, t: Any) -> None:
    def call() -> Any:
        s = p.state_from_angles(theta=theta, phi=0.0, theta_dot=theta_dot, phi_dot=phi_dot)
        return pl.exact(p, s).state(t)

    def values(out: Any) -> tuple[Any, ...]:
        return (out.x, out.v) if isinstance(out, pl.State) else out

    check("exact", call, values)


def test_counts_reach_the_target() -> None:
    """Runs last (file order): every entry point got its examples."""
    assert set(COUNTS) >= {"Pendulum", "simulate", "exact", "Stepper"}
