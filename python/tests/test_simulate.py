"""The Python API of the core engine: simulate, Stepper, diagnostics, saving, interruption.

Each test states the physics or contract it checks."""

from __future__ import annotations

import os
import signal
import threading

import numpy as np
import pytest

import pendulab as pl

ALL = pl.method_names()
GEOMETRIC = [m["name"] for m in pl.methods() if m["preserves_ts2"]]


def test_the_readme_example_runs_and_conserves(pendulum: pl.Pendulum, rosette: pl.State) -> None:
    """RATTLE keeps |x| = l and J₃ to round-off and the energy error small over 10⁵ steps."""
    tr = pl.simulate(pendulum, rosette, t_end=100.0, method="rattle", dt=1e-3, save_every=10)
    assert tr.t.shape == (10_001,) and tr.x.shape == (10_001, 3) and tr.v.shape == (10_001, 3)
    assert tr.t[-1] == 100.0
    assert np.max(np.abs(tr.constraint_error)) < 1e-14
    assert np.max(np.abs(tr.j3 - tr.j3[0])) < 1e-12
    assert np.max(np.abs(tr.energy - tr.energy[0])) / (9.81 * 1.0) < 1e-5
    assert tr.tension.shape == (10_001,) and np.all(tr.tension > 0)
    assert "rattle" in tr.summary()


def test_summary_names_the_requested_output_times(pendulum: pl.Pendulum, rosette: pl.State) -> None:
    """A run with save_at records how many times were asked for; the summary says the samples are at
    them (DOP853's dense output, a fixed-step method landing on each), with a first step if given."""
    times = np.linspace(0.0, 1.0, 7)
    tr = pl.simulate(pendulum, rosette, t_end=1.0, method="dop853", dt=0.01, save_at=times, project=False)
    assert tr.options["save_at_times"] == 7
    assert "dop853, adaptive steps, rtol = 1e-10, atol = 1e-12, first step 0.01 s, not projected, " in (
        tr.summary()
    )
    assert "saved at 7 requested times" in tr.summary()
    tr = pl.simulate(pendulum, rosette, t_end=1.0, method="rattle4", save_at=times[2:])
    assert "rattle4, dt = 0.001 s, " in tr.summary() and "saved at 5 requested times" in tr.summary()


@pytest.mark.parametrize("method", ALL)
def test_every_method_runs_from_python(method: str, pendulum: pl.Pendulum) -> None:
    """Every registered method integrates a start away from the poles for 1 s; those that declare
    TS² preservation keep |x| = l to round-off."""
    s0 = pendulum.state_from_angles(theta=1.0, phi_dot=3.5)
    tr = pl.simulate(pendulum, s0, t_end=1.0, method=method, dt=1e-3, rtol=1e-12, atol=1e-14)
    assert tr.t[0] == 0.0 and tr.t[-1] == 1.0
    assert np.all(np.isfinite(tr.x))
    if method in GEOMETRIC or method == "dop853":
        assert np.max(np.abs(tr.constraint_error)) < 1e-13, method
    assert abs(tr.energy[-1] - tr.energy[0]) < 1e-6 * 9.81


def test_methods_table_declares_orders_and_properties() -> None:
    """The registry exposes order and structure flags; RATTLE is the default."""
    table = {m["name"]: m for m in pl.methods()}
    assert table["rattle"]["default"] and table["rattle"]["symplectic"] and table["rattle"]["order"] == 2
    assert [table[f"rattle{k}"]["order"] for k in (4, 6, 8)] == [4, 6, 8]
    assert table["dop853"]["adaptive"] and table["dop853"]["dense_output"]
    assert not table["rk4"]["preserves_ts2"]


def test_dop853_from_cartesian_state(pendulum: pl.Pendulum, rosette: pl.State) -> None:
    """The issue's second example: a state from (x, v) and DOP853 at rtol 1e-12 agree with RATTLE8."""
    s1 = pendulum.state(rosette.x, rosette.v)
    tr = pl.simulate(pendulum, s1, t_end=10.0, method="dop853", rtol=1e-12, atol=1e-14)
    ref = pl.simulate(pendulum, s1, t_end=10.0, method="rattle8", dt=2e-3, save_every=10**9)
    assert np.linalg.norm(tr.x[-1] - ref.x[-1]) < 1e-9
    assert tr.stats["steps"] < 5_000


def test_save_at_lands_on_the_requested_times(pendulum: pl.Pendulum, rosette: pl.State) -> None:
    """Saving at given times: fixed-step methods land on them; DOP853's dense output agrees with
    stepping exactly to each time."""
    times = np.array([0.0, 0.123, 1.0, 2.5, 3.14159])
    for method in ("rattle8", "dop853"):
        tr = pl.simulate(
            pendulum, rosette, t_end=4.0, method=method, dt=1e-3, rtol=1e-12, atol=1e-14, save_at=times
        )
        assert np.array_equal(tr.t, times)
        ref = [pl.simulate(pendulum, rosette, t_end=t, method="rattle8", dt=1e-3).x[-1] for t in times[1:]]
        err = np.max(np.linalg.norm(tr.x[1:] - np.array(ref), axis=1))
        assert err < 1e-9, (method, err)


def test_saving_is_separate_from_stepping(pendulum: pl.Pendulum, rosette: pl.State) -> None:
    """2·10⁷ steps keep only the samples asked for (memory bounded by what is saved)."""
    tr = pl.simulate(pendulum, rosette, t_end=2e4, dt=1e-3, save_every=1_000_000, progress=False)
    assert len(tr) == 21 and tr.stats["steps"] == 20_000_000
    assert np.max(np.abs(tr.constraint_error)) < 1e-14


@pytest.mark.parametrize("estimate", [False, True], ids=["plain", "error_estimate"])
def test_ctrl_c_returns_what_was_computed(pendulum: pl.Pendulum, rosette: pl.State, estimate: bool) -> None:
    """SIGINT during a long run stops it cleanly: a warning, interrupted=True, samples up to then."""
    timer = threading.Timer(0.3, lambda: os.kill(os.getpid(), signal.SIGINT))
    timer.start()
    try:
        with pytest.warns(RuntimeWarning, match="interrupted") as said:
            tr = pl.simulate(
                pendulum,
                rosette,
                t_end=1e6,
                dt=1e-4,
                save_every=10_000,
                progress=False,
                error_estimate=estimate,
            )
    finally:
        timer.cancel()
    assert [w.filename for w in said if "interrupted" in str(w.message)] == [__file__]  # the caller's line
    assert tr.interrupted
    assert 0 < tr.t[-1] < 1e6 and len(tr) > 1
    assert np.all(np.isfinite(tr.x))


def test_stepper_is_incremental(pendulum: pl.Pendulum, rosette: pl.State) -> None:
    """init / step / step_to / state give the same numbers as the batch solver."""
    st = pl.Stepper(pendulum, rosette, method="rattle", dt=1e-3)
    st.step(500)
    assert abs(st.t - 0.5) < 1e-15
    s = st.step_to(1.0)
    batch = pl.simulate(pendulum, rosette, t_end=1.0, method="rattle", dt=1e-3)
    assert np.array_equal(s.x, batch.x[-1]) and st.stats["steps"] == 1000
    st.set_state(rosette)
    assert np.array_equal(st.state.x, rosette.x)


def test_negative_gravity_mirrors(pendulum: pl.Pendulum, rosette: pl.State) -> None:
    """g < 0 is the mirror image z → −z of g > 0."""
    mirror = np.array([1.0, 1.0, -1.0])
    down = pl.Pendulum(length=1.0, g=-9.81)
    a = pl.simulate(pendulum, rosette, t_end=5.0)
    b = pl.simulate(down, down.state(rosette.x * mirror, rosette.v * mirror), t_end=5.0)
    assert np.max(np.abs(a.x - b.x * mirror)) < 1e-12


@pytest.mark.parametrize(
    ("kwargs", "needle"),
    [
        ({"length": 0.0}, "length"),
        ({"length": -1.0}, "length"),
        ({"length": float("nan")}, "length"),
        ({"mass": 0.0}, "mass"),
        ({"g": float("inf")}, "g"),
    ],
)
def test_bad_parameters_are_named(kwargs: dict[str, float], needle: str) -> None:
    """Bad parameters raise InvalidInputError (a ValueError) naming the parameter."""
    with pytest.raises(pl.InvalidInputError, match=needle):
        pl.Pendulum(**kwargs)


def test_states_are_validated_or_projected(pendulum: pl.Pendulum) -> None:
    """Off-TS² states are refused with the residual named; project=True moves them and says how far."""
    with pytest.raises(ValueError, match=r"\|x\| - l"):
        pendulum.state([0.0, 0.0, -1.1], [0.0, 0.0, 0.0])
    with pytest.raises(ValueError, match="x·v"):
        pendulum.state([0.0, 0.0, -1.0], [0.0, 0.1, 0.2])
    with pytest.raises(ValueError, match=r"x\[0\] = nan"):
        pendulum.state([np.nan, 0.0, -1.0], [0.0, 0.0, 0.0])
    with pytest.raises(ValueError, match="3 numbers"):
        pendulum.state([0.0, -1.0], [0.0, 0.0])
    s = pendulum.state([0.0, 0.0, -1.1], [0.3, 0.0, 0.2], project=True)
    assert s.projection is not None
    assert s.projection[0] == pytest.approx(0.1) and s.projection[1] == pytest.approx(0.2)
    assert np.linalg.norm(s.x) == pytest.approx(1.0, abs=1e-15)


@pytest.mark.parametrize(
    ("kwargs", "needle"),
    [
        ({"method": "euler"}, "euler"),
        ({"dt": 0.0}, "dt"),
        ({"dt": -1e-3}, "dt"),
        ({"dt": float("nan")}, "dt"),
        ({"t_end": 0.0}, "t_end"),
        ({"t_end": float("nan")}, "t_end"),
        ({"save_every": 0}, "save_every"),
        ({"save_every": 2, "save_at": [0.5]}, "either"),
        ({"save_at": [0.5, 0.2]}, "increasing"),
        ({"save_at": [5.0]}, "within"),
        ({"method": "dop853", "rtol": 0.0}, "rtol"),
        ({"method": "dop853", "atol": -1.0}, "atol"),
        ({"t_end": 1e6, "dt": 1e-3}, "bytes"),
    ],
)
def test_bad_solver_settings_are_named(
    kwargs: dict[str, object], needle: str, pendulum: pl.Pendulum, rosette: pl.State
) -> None:
    """Every bad setting raises InvalidInputError naming it, before any work is done."""
    args: dict[str, object] = {"t_end": 1.0} | kwargs
    with pytest.raises(pl.InvalidInputError, match=needle):
        pl.simulate(pendulum, rosette, **args)  # type: ignore[arg-type]


def test_angle_method_refuses_at_the_pole(pendulum: pl.Pendulum) -> None:
    """A planar swing passes the bottom pole; rk4_angles raises IntegrationError there."""
    s0 = pendulum.state_from_angles(theta=0.5)
    with pytest.raises(pl.IntegrationError, match="pole"):
        pl.simulate(pendulum, s0, t_end=2.0, method="rk4_angles")


def test_dop853_conserve_keeps_energy_and_j3(pendulum: pl.Pendulum) -> None:
    """conserve=True projects v onto E = E0, J3 = J3_0 after each DOP853 step (GNI IV.4): near the
    separatrix that removes the energy drift, so the phase error falls by orders of magnitude."""
    s0 = pendulum.state_from_angles(theta=np.radians(179), phi_dot=0.5)
    ref = pl.simulate(pendulum, s0, t_end=30.0, method="rattle8", dt=1e-3, save_every=10**9)
    errs = []
    for conserve in (False, True):
        tr = pl.simulate(pendulum, s0, t_end=30.0, method="dop853", rtol=1e-12, atol=1e-14, conserve=conserve)
        errs.append(np.linalg.norm(tr.x[-1] - ref.x[-1]))
        if conserve:
            assert abs(tr.energy[-1] - tr.energy[0]) < 1e-13 and abs(tr.j3[-1] - tr.j3[0]) < 1e-15
    assert errs[1] < 0.01 * errs[0], errs
