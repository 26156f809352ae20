"""Property tests (hypothesis) of the derived public entry points under hostile and extreme input
(issue 13): ``simulate_ensemble``, ``reduced_flow``, ``em_map``, ``sweep`` and
``Pendulum.diagnostics``; and states built by hand from complex numbers or text, refused by name. The
generated arguments, the judgement of each call and the work bound are in ``fuzz_inputs.py``; the core
entry points are in ``test_fuzz_api.py``.

Examples per entry point: ``FUZZ_EXAMPLES`` (default 60, derandomised, for CI; ``make fuzz`` runs
10 000 each and prints the counts). Units: SI.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest
from fuzz_inputs import (
    FUZZ,
    HOSTILE,
    JUNK,
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


def test_states_built_by_hand_from_integers_or_float32_are_float64() -> None:
    """A State from integer or float32 arrays (or lists of integers) holds float64 arrays: simulate,
    exact and the ensemble take it, with the numbers of the same state made by Pendulum.state (the
    one-file lab audit: integer arrays reached the core as a TypeError about 'PyArray<T, D>')."""
    p = pl.Pendulum()
    made = p.state([0.0, 0.0, -1.0], [1.0, 0.0, 0.0])
    reference = pl.simulate(p, made, 0.5).x
    for x, v in [
        (np.array([0, 0, -1]), np.array([1, 0, 0])),
        ([0, 0, -1], [1, 0, 0]),
        (np.array([0, 0, -1], np.float32), np.array([1, 0, 0], np.uint8)),
    ]:
        s = pl.State(x, v)
        assert s.x.dtype == np.float64 and s.v.dtype == np.float64 and not s.x.flags.writeable
        assert np.array_equal(pl.simulate(p, s, 0.5).x, reference)
        assert np.array_equal(pl.exact(p, s).state(0.5).x, pl.exact(p, made).state(0.5).x)
        assert np.array_equal(pl.simulate_ensemble(p, [s], 0.5, progress=False).final_x[0], reference[-1])
