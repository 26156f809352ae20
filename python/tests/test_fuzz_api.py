"""Property tests (hypothesis) of every public entry point under hostile and extreme input (issue 13).

For each entry point, generated arguments — ordinary values, the extremes of float64, NaN, ±inf,
subnormals, integers beyond float range (10**400), strings, None, bools, nested lists, arrays of the
wrong shape — and every method of ``pl.method_names()``. Each call must either return a result whose
numbers are all finite, or raise ``pl.InvalidInputError`` / ``pl.IntegrationError`` with a one-line
message of bounded length naming the input; any other exception fails. No call may plan unbounded
work: inputs whose (valid) work would exceed what a test can afford are skipped before the call, and
the limits of :mod:`pendulab.validate` refuse the rest up front.

Examples per entry point: ``FUZZ_EXAMPLES`` (default 60, derandomised, for CI; ``make fuzz`` runs
10 000 each and prints the counts). Units: SI.
"""

from __future__ import annotations

import math
import os
import re
import warnings
from collections import Counter
from collections.abc import Callable
from typing import Any

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import pendulab as pl
from pendulab.validate import LIMITS, SHOW_CHARS

EXAMPLES = int(os.environ.get("FUZZ_EXAMPLES", "60"))
LONG = EXAMPLES > 1000
FUZZ = settings(
    max_examples=EXAMPLES,
    deadline=None,
    derandomize=not LONG,
    database=None,
    suppress_health_check=list(HealthCheck),
)
COUNTS: Counter[str] = Counter()
OUTCOMES: Counter[tuple[str, str]] = Counter()
WORK = 20_000 if LONG else 200_000
"""The most steps (or points) a generated call that passes validation may cost here (valid calls
beyond it are skipped; invalid ones — beyond the limits — are always made)."""

EXTREMES = [0.0, -0.0, 1e308, -1e308, 5e-324, 1e-300, 1e300, 1e16, -1e16, 1e-12, 1e12, math.pi]
NUMBERS = st.one_of(
    st.floats(-10, 10),
    st.floats(allow_nan=True, allow_infinity=True),
    st.sampled_from([*EXTREMES, math.nan, math.inf, -math.inf]),
    st.integers(-5, 5),
)
JUNK = st.one_of(
    st.none(),
    st.booleans(),
    st.text(max_size=12),
    st.just(10**400),
    st.just(-(10**400)),
    st.just("1.0"),
    st.just([1.0, 2.0]),
    st.just({"a": 1}),
    st.just(b"\x00" * 3),
    st.just(np.array([np.nan])),
    st.just("x" * 2000),
)
HOSTILE = st.one_of(NUMBERS, NUMBERS, NUMBERS, JUNK)
POSITIVE = st.one_of(st.floats(0.01, 10.0), HOSTILE)
VEC = st.one_of(
    st.lists(HOSTILE, min_size=3, max_size=3),
    st.lists(st.floats(-2, 2), min_size=3, max_size=3),
    st.lists(HOSTILE, max_size=5),
    JUNK,
)
METHODS = st.sampled_from(pl.method_names())
MODELS = [m["name"] for m in pl.models()]
PARAM_NAMES = sorted({p["name"] for m in pl.models() for p in m["params"][3:]} | {"bogus"})


@pytest.fixture(autouse=True)
def _report_counts() -> Any:
    """``make fuzz``: after each test, the number of generated calls of its entry point and their outcomes."""
    before = dict(COUNTS)
    yield
    if LONG:
        for name, n in sorted(COUNTS.items()):
            if n != before.get(name, 0):
                outcomes = ", ".join(f"{k[1]} {v}" for k, v in sorted(OUTCOMES.items()) if k[0] == name)
                print(f"\nfuzz: {name}: {n} generated calls ({outcomes})", flush=True)


def _finite(*values: Any) -> bool:
    for v in values:
        if v is None:
            continue
        a = np.asarray(v)
        if a.dtype.kind in "fc" and not np.all(np.isfinite(a)):
            return False
    return True


def check(name: str, call: Callable[[], Any], result_values: Callable[[Any], tuple[Any, ...]]) -> None:
    """Runs ``call``: a result must be finite; an error must be ours, one line, short, not internal."""
    COUNTS[name] += 1
    try:
        with warnings.catch_warnings():  # warnings are allowed (e.g. θ > 2π rad); errors are judged
            warnings.simplefilter("ignore")
            out = call()
    except (pl.InvalidInputError, pl.IntegrationError) as e:
        msg = str(e)
        OUTCOMES[(name, type(e).__name__)] += 1
        assert "\n" not in msg.strip(), msg
        assert len(msg) < 6 * SHOW_CHARS + 600, f"{len(msg)} characters: {msg[:300]}"
        assert not re.search(r"\bn[12] =|invalid u =|RecursionError|Traceback", msg), msg
        return
    except pl.ScenarioError as e:  # a ValueError naming the file
        OUTCOMES[(name, "ScenarioError")] += 1
        assert "\n" not in str(e).strip()
        return
    OUTCOMES[(name, "ok")] += 1
    values = result_values(out)
    assert _finite(*values), f"{name}: a non-finite number left the call silently"


def _pendulum_or_none(length: Any, g: Any, mass: Any) -> pl.Pendulum | None:
    try:
        return pl.Pendulum(length=length, g=g, mass=mass)
    except pl.InvalidInputError:
        return None


PENDULUMS = st.builds(
    _pendulum_or_none,
    st.one_of(st.floats(0.05, 20.0), st.sampled_from([1e-6, 1e4, 1e-3, 1e3])),
    st.one_of(st.floats(-30.0, 30.0), st.sampled_from([0.0, 1e4, -1e4, 1e3])),
    st.one_of(st.floats(0.1, 10.0), st.sampled_from([1e-6, 1e6])),
).filter(lambda p: p is not None)


def _start(p: pl.Pendulum, theta: float, phi_dot: float) -> pl.State:
    return p.state_from_angles(theta=theta, phi=0.3, theta_dot=0.1, phi_dot=phi_dot)


STARTS = st.tuples(st.floats(0.0, math.pi), st.floats(-5.0, 5.0))


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


def _affordable(t0: Any, t_end: Any, dt: Any, method: str, n: int = 1) -> bool:
    """False when a call would pass validation yet cost more than :data:`WORK` steps here."""
    try:
        t0f, tef = float(0.0 if t0 is None else t0), float(t_end)
        dtf = 1e-3 if dt is None else float(dt)
    except (TypeError, ValueError, OverflowError):
        return True
    if not all(map(math.isfinite, (t0f, tef, dtf))) or tef <= t0f:
        return True
    if method == "dop853":
        return tef - t0f <= 20.0 * n
    if dtf <= 0:
        return True
    steps = (tef - t0f) / dtf * n
    return steps <= WORK or steps > LIMITS["steps"]["max"]


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


@FUZZ
@given(
    p=PENDULUMS,
    rows=st.one_of(
        st.lists(st.lists(st.floats(-1.0, 1.0), min_size=6, max_size=6), min_size=1, max_size=4), VEC, JUNK
    ),
    t_end=st.one_of(st.just(0.1), HOSTILE),
    dt=st.one_of(st.just(1e-3), HOSTILE),
    length=st.one_of(st.none(), HOSTILE),
    g=st.one_of(st.none(), HOSTILE),
    save_every=st.one_of(st.none(), st.integers(-1, 50), JUNK),
)
def test_simulate_ensemble(
    p: pl.Pendulum, rows: Any, t_end: Any, dt: Any, length: Any, g: Any, save_every: Any
) -> None:
    if not _affordable(0.0, t_end, dt, "rattle", n=4):
        return
    # rows from angles so that some start on TS²; the others are refused by the kernel's own check
    if isinstance(rows, list) and rows and isinstance(rows[0], list) and len(rows[0]) == 6:
        rows = [_start(p, r[0] * 3, r[1]).as_array() for r in rows]

    def call() -> pl.EnsembleResult:
        return pl.simulate_ensemble(p, rows, t_end, dt=dt, length=length, g=g, save_every=save_every)

    check("simulate_ensemble", call, lambda r: (r.x, r.v))


# --- exact solution, reduction, maps, sweeps -------------------------------------------------------


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


@FUZZ
@given(
    p=PENDULUMS,
    start=STARTS,
    t_end=st.one_of(st.floats(0.01, 1.0), HOSTILE),
    dt=st.one_of(st.floats(1e-3, 0.05), HOSTILE),
)
def test_reduced_flow(p: pl.Pendulum, start: tuple[float, float], t_end: Any, dt: Any) -> None:
    if not _affordable(0.0, t_end, dt, "rk4"):
        return
    s = _start(p, *start)
    check("reduced_flow", lambda: pl.reduced_flow(p, s, t_end, dt), lambda tr: (tr.t, tr.x, tr.v))


@FUZZ
@given(
    p=PENDULUMS,
    j_range=st.one_of(st.none(), st.tuples(st.floats(-3, 0), st.floats(0.1, 3)), VEC, JUNK),
    e_range=st.one_of(st.none(), st.tuples(st.floats(-20, 0), st.floats(0.1, 30)), VEC, JUNK),
    grid=st.one_of(st.tuples(st.integers(-1, 12), st.integers(-1, 12)), JUNK, VEC),
)
def test_em_map(p: pl.Pendulum, j_range: Any, e_range: Any, grid: Any) -> None:
    def call() -> pl.EMMap:
        return pl.em_map(p, j_range=j_range, e_range=e_range, grid=grid)

    # W is NaN outside the image and on J₃ = 0 by definition (documented); the axes must be finite
    check("em_map", call, lambda m: (m.J3, m.E, m.energy_unit, m.momentum_unit))


@FUZZ
@given(
    theta0=st.one_of(st.lists(st.floats(0.1, 3.0), min_size=1, max_size=3), VEC, JUNK),
    length=st.one_of(st.lists(st.floats(0.1, 3.0), min_size=1, max_size=2), VEC),
    quantity=st.sampled_from(["final_state", "max_sway", "energy_drift", "rotation_number", "bogus"]),
    t_end=st.one_of(st.just(0.05), HOSTILE),
    dt=st.one_of(st.just(1e-3), HOSTILE),
)
def test_sweep(theta0: Any, length: Any, quantity: str, t_end: Any, dt: Any) -> None:
    if not _affordable(0.0, t_end, dt, "rattle", n=9):
        return

    def call() -> Any:
        return pl.sweep({"theta0": theta0, "length": length}, quantity, t_end=t_end, dt=dt, progress=False)

    def values(sw: Any) -> tuple[Any, ...]:
        ds = sw.to_xarray()
        # rotation_number is NaN for J₃ = 0 by definition (documented); the simulated ones are finite
        return tuple(ds[k].values for k in ds.data_vars if k != "rotation_number")

    check("sweep", call, values)


@FUZZ
@given(
    p=PENDULUMS,
    x=st.one_of(VEC, st.lists(VEC, max_size=3)),
    v=st.one_of(VEC, st.lists(VEC, max_size=3)),
    t=HOSTILE,
)
def test_diagnostics(p: pl.Pendulum, x: Any, v: Any, t: Any) -> None:
    check("Pendulum.diagnostics", lambda: p.diagnostics(x, v, t), lambda d: tuple(d.values()))


def test_counts_reach_the_target() -> None:
    """Runs last (file order): every entry point got its examples."""
    assert set(COUNTS) >= {"Pendulum", "simulate", "exact", "Stepper"}


def test_complex_or_text_states_are_refused_by_name_not_cast() -> None:
    """The audit of issue 30: a State built by hand from complex numbers reached the core (a TypeError
    about 'PyArray<T, D>' from simulate and exact), and simulate_ensemble cast complex starts to real
    with only NumPy's ComplexWarning (text starts were parsed as numbers)."""
    p = pl.Pendulum()
    bad = pl.State(np.array([0.5, 0.0, -(0.75**0.5) + 1j]), np.array([0.0, 0.3, 0.0]))
    for call in (lambda: pl.simulate(p, bad, 0.1), lambda: pl.exact(p, bad)):
        with pytest.raises(pl.InvalidInputError, match=r"state\.x = .*3 real numbers \[m\]"):
            call()
    rows = np.tile([0.5, 0.0, -(0.75**0.5), 0.0, 0.3, 0.0], (4, 1))
    for starts in (rows + 0j, rows + 1j, rows.astype(str)):
        with pytest.raises(pl.InvalidInputError, match=r"(?s)invalid states = .*\(N, 6\) array"):
            pl.simulate_ensemble(p, starts, 0.1, progress=False)
    ok = pl.State([0.5, 0.0, -(0.75**0.5)], [0.0, 0.3, 0.0])  # lists of real numbers stay fine
    assert pl.simulate(p, ok, 0.01).x.shape[1] == 3
