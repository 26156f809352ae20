"""The generated input of the property tests of the public API (test_fuzz_api*.py, issue 13).

Strategies: ordinary values, the extremes of float64, NaN, ±inf, subnormals, integers beyond float
range (10**400), strings, None, bools, nested lists, arrays of the wrong shape (``HOSTILE``, ``JUNK``,
``VEC``), pendulums (``PENDULUMS``: l [m], g [m/s²], m [kg]) and starts (``STARTS``: θ [rad], φ̇
[rad/s]). ``check`` judges one call: it must either return a result whose numbers are all finite, or
raise ``pl.InvalidInputError`` / ``pl.IntegrationError`` with a one-line message of bounded length
naming the input; any other exception fails. No call may plan unbounded work: inputs whose (valid)
work would exceed what a test can afford (``WORK`` steps, ``_affordable``) are skipped before the
call, and the limits of :mod:`pendulab.validate` refuse the rest up front. ``COUNTS`` and
``OUTCOMES`` count the calls per entry point for ``make fuzz`` (the autouse fixture
``_report_counts``, imported by each test file, prints them).
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
from hypothesis import HealthCheck, settings
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
