"""The pendulum on a string from Python, scenario files and the CLI: a motion that never goes slack
is the rod pendulum's; the string leaves where the tension of T-2.3 vanishes, z* = 2E/(3 m g); flight
is the exact parabola; an elastic snap keeps E and an inelastic one loses exactly the radial kinetic
energy ½ m (x̂·v)²; the run in chunks (progress bar, Ctrl-C) is the one-call run bit for bit;
save_at lands on its times exactly; bad settings are refused with the reason. SI units (m, kg, s, J)."""

from __future__ import annotations

import math
import warnings
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from conftest import SCENARIOS
from typer.testing import CliRunner

import pendulab as pl
from pendulab import _chunks, _core
from pendulab.cli import app
from pendulab.variants import string_pendulum

G = 9.81


def launch(p: pl.Pendulum, v0_squared: float) -> pl.State:
    """A planar launch from the bottom with speed √v0_squared [m/s] along e₁."""
    return p.state([0.0, 0.0, -p.length], [math.sqrt(v0_squared), 0.0, 0.0])


def test_never_slack_equals_the_rod(pendulum: pl.Pendulum, rosette: pl.State) -> None:
    string = pl.Pendulum(model="string")
    for method in ("rattle", "rattle4"):
        # the string's stepper is unfused: the rod with the same arithmetic
        a = pl.simulate(pendulum, rosette, 2.0, method=method, dt=1e-3, arithmetic="unfused")
        b = pl.simulate(string, rosette, 2.0, method=method, dt=1e-3)
        assert b.taut is not None and b.taut.all() and len(b.events["t"]) == 0
        np.testing.assert_array_equal(a.t, b.t)
        np.testing.assert_array_equal(a.x, b.x)
        np.testing.assert_array_equal(a.v, b.v)


def test_slack_at_zero_tension_parabola_and_inelastic_snap() -> None:
    p = pl.Pendulum(length=1.5, g=G, mass=2.0, model="string")
    s0 = launch(p, 3.5 * G * 1.5)  # passes the horizontal (2 g l), cannot loop (5 g l)
    e0 = p.energy(s0)
    tr = pl.simulate(p, s0, 3.0, method="rattle8", dt=1e-3)
    ev = tr.events
    assert list(ev["kind"][:2]) == ["slack", "taut"]
    z_star = 2.0 * e0 / (3.0 * p.mass * G)  # T = (m/l)(2E/m − 3 g z) = 0
    assert z_star == pytest.approx(0.75, rel=1e-15)
    assert ev["x"][0, 2] == pytest.approx(z_star, abs=1e-12)
    assert abs(p.tension(pl.State(ev["x"][0], ev["v_after"][0]))) < 1e-12 * p.mass * G
    # flight: the parabola, inside the sphere, energy exact
    t_leave, t_snap = ev["t"][0], ev["t"][1]
    flying = (tr.t > t_leave) & (tr.t < t_snap)
    assert flying.sum() > 100 and not tr.taut[flying].any()
    tau = tr.t[flying] - t_leave
    want = ev["x"][0] + np.outer(tau, ev["v_after"][0]) - np.outer(0.5 * G * tau**2, [0.0, 0.0, 1.0])
    np.testing.assert_allclose(tr.x[flying], want, rtol=0, atol=1e-15)
    assert (np.linalg.norm(tr.x[flying], axis=1) < p.length).all()
    assert t_snap - t_leave == pytest.approx(4.0 * ev["v_after"][0, 2] / G, rel=1e-15)
    # inelastic snap: loses exactly ½ m (x̂·v)², the energy balance E + lost = E0 holds throughout
    n = ev["x"][1] / np.linalg.norm(ev["x"][1])
    radial_ke = 0.5 * p.mass * float(n @ ev["v_before"][1]) ** 2
    assert ev["energy_lost"][1] == pytest.approx(radial_ke, rel=1e-14)
    assert abs(float(n @ ev["v_after"][1])) < 1e-14 * np.linalg.norm(ev["v_after"][1])  # round-off
    assert np.max(np.abs(tr.energy + tr.energy_lost - e0)) < 1e-12 * abs(e0)
    assert (tr.tension[~tr.taut] == 0).all() and (tr.tension[tr.taut] >= -1e-9).all()


def test_elastic_snaps_keep_the_energy() -> None:
    p = pl.Pendulum(model="string", restitution=1.0)
    s0 = p.state_from_angles(0.2, 0.0, 5.5, 3.0)
    tr = pl.simulate(p, s0, 4.0, method="rattle8", dt=1e-3)
    assert list(tr.events["kind"]).count("taut") >= 3
    np.testing.assert_allclose(tr.events["energy_lost"], 0.0, atol=1e-13)
    e0 = p.energy(s0)
    assert np.max(np.abs(tr.energy - e0)) < 1e-11 * abs(e0)
    assert np.max(np.abs(tr.j3 - tr.j3[0])) < 1e-12 * abs(tr.j3[0])


def test_scenario_and_cli(tmp_path: Path) -> None:
    sc = pl.load_scenario(SCENARIOS / "string_slack.toml")
    assert sc.pendulum().model == "string"
    assert pl.Scenario.from_toml_str(sc.to_toml()) == sc
    out = tmp_path / "string.csv"
    result = CliRunner().invoke(app, ["run", str(SCENARIOS / "string_slack.toml"), "--out", str(out)])
    assert result.exit_code == 0, result.output
    assert "went slack 1x, snapped taut 1x" in result.output
    header = out.read_text().splitlines()[1]
    assert "taut [1]" in header and "energy_lost [J]" in header
    assert '"kind": "slack"' in out.read_text().splitlines()[0]


@pytest.mark.parametrize(
    ("call", "needle"),
    [
        (lambda: pl.Pendulum(model="string", restitution=1.5), "restitution"),
        (lambda: pl.Pendulum(model="string", restitution=float("nan")), "restitution"),
        (
            lambda: pl.simulate(
                pl.Pendulum(model="string"), launch(pl.Pendulum(), 1.0), 1.0, method="dop853"
            ),
            "rattle4",
        ),
        (
            lambda: pl.simulate(
                pl.Pendulum(model="string"), launch(pl.Pendulum(), 1.0), 1.0, save_at=[0.5], save_every=2
            ),
            "save_every or save_at",
        ),
        (
            lambda: pl.simulate(pl.Pendulum(model="string"), launch(pl.Pendulum(), 1.0), 1.0, save_every=0),
            "save_every = 0",
        ),
        (lambda: pl.Stepper(pl.Pendulum(model="string"), launch(pl.Pendulum(), 1.0)), "hybrid"),
    ],
)
def test_bad_settings_are_refused(call: object, needle: str) -> None:
    with pytest.raises(pl.InvalidInputError, match=needle):
        call()  # type: ignore[operator]


def test_scenario_refuses_an_adaptive_method() -> None:
    text = (SCENARIOS / "string_slack.toml").read_text().replace('"rattle8"', '"dop853"')
    with pytest.raises(pl.ScenarioError, match="cannot integrate the 'string' model"):
        pl.Scenario.from_toml_str(text)


def _one_call(
    p: pl.Pendulum, s0: pl.State, t_end: float, method: str, dt: float, **kw: Any
) -> dict[str, Any]:
    """The run in one call of the core (``_core.string_simulate``), no chunks."""
    run = _core.RunOptions(t0=0.0, t_end=t_end, method=method, dt=dt, **kw)
    return _core.string_simulate(p.spec, s0.pair, run)


_StringRunner = _core.StringRunner


class _CountingRunner:
    """``_core.StringRunner`` that counts its chunks and can raise KeyboardInterrupt after one (as a
    Ctrl-C arriving while that chunk ran would: the chunk completes, then Python sees the signal)."""

    def __init__(self, *args: Any, interrupt_after: int | None = None, **kw: Any) -> None:
        self._inner = _StringRunner(*args, **kw)
        self.chunks = 0
        self.interrupt_after = interrupt_after

    def advance(self, budget: int) -> bool:
        done = self._inner.advance(budget)
        self.chunks += 1
        if self.chunks == self.interrupt_after:
            raise KeyboardInterrupt
        return done

    def __getattr__(self, name: str) -> Any:
        return getattr(self._inner, name)


def _patch_runner(
    monkeypatch: pytest.MonkeyPatch, interrupt_after: int | None = None
) -> list[_CountingRunner]:
    made: list[_CountingRunner] = []

    def make(*args: Any, **kw: Any) -> _CountingRunner:
        made.append(_CountingRunner(*args, interrupt_after=interrupt_after, **kw))
        return made[-1]

    monkeypatch.setattr(string_pendulum, "StringRunner", make)
    monkeypatch.setattr(_chunks, "_CHUNK_SECONDS", 1e-9)  # chunks of the minimum, 1000 steps
    return made


@pytest.mark.parametrize("save_every", [1, 7])
def test_chunked_run_with_progress_is_the_one_call_run_bit_for_bit(
    monkeypatch: pytest.MonkeyPatch, save_every: int
) -> None:
    p = pl.Pendulum(model="string", restitution=1.0)
    s0 = p.state_from_angles(0.2, 0.0, 5.5, 3.0)  # 3D, leaves and snaps back again and again
    made = _patch_runner(monkeypatch)
    tr = pl.simulate(p, s0, 20.0, method="rattle", dt=1e-3, save_every=save_every, progress=True)
    assert made[0].chunks >= 10 and not tr.interrupted
    one = _one_call(p, s0, 20.0, "rattle", 1e-3, save_every=save_every)
    assert len(one["events"]["t"]) >= 10
    for key in ("t", "x", "v", "taut"):
        np.testing.assert_array_equal(getattr(tr, key), one[key], err_msg=key)
    assert tr.events is not None
    for key, want in one["events"].items():
        np.testing.assert_array_equal(tr.events[key], want, err_msg=key)
    assert tr.stats == dict(one["stats"])


def test_ctrl_c_returns_the_run_so_far_flagged_interrupted(monkeypatch: pytest.MonkeyPatch) -> None:
    p = pl.Pendulum(model="string", restitution=1.0)
    s0 = p.state_from_angles(0.2, 0.0, 5.5, 3.0)
    _patch_runner(monkeypatch, interrupt_after=4)
    with pytest.warns(RuntimeWarning, match="interrupted at t = 13 s") as said:
        tr = pl.simulate(p, s0, 20.0, method="rattle", dt=1e-3)
    assert [w.filename for w in said] == [__file__]  # the caller's line
    assert tr.interrupted and tr.taut is not None and tr.events is not None
    # chunks of 10000, 1000, 1000, 1000 steps: to t = 13 s, the samples and events of the full run there
    one = _one_call(p, s0, 20.0, "rattle", 1e-3)
    n = len(tr.t)
    assert tr.t[-1] == 13.0 and 0 < n < len(one["t"])
    np.testing.assert_array_equal(tr.t, one["t"][:n])
    np.testing.assert_array_equal(tr.x, one["x"][:n])
    np.testing.assert_array_equal(tr.taut, one["taut"][:n])
    k = len(tr.events["t"])
    assert k > 0 and tr.events["t"][-1] <= 13.0 < one["events"]["t"][k]
    np.testing.assert_array_equal(tr.events["v_after"], one["events"]["v_after"][:k])


def test_save_at_lands_on_the_times_parabola_in_flight_fine_run_when_taut() -> None:
    p = pl.Pendulum(length=1.5, g=G, mass=2.0, model="string")
    s0 = launch(p, 3.5 * G * 1.5)
    dense = pl.simulate(p, s0, 3.0, method="rattle8", dt=1e-3)
    assert dense.events is not None
    t_leave, t_snap = dense.events["t"][:2]
    mid = 0.5 * (t_leave + t_snap)
    times = np.array([0.0, 0.1234567, t_leave - 0.0105, mid, mid + 1.3e-4, t_snap + 0.2345, 2.5])
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        tr = pl.simulate(p, s0, 3.0, method="rattle8", dt=1e-3, save_at=times)
    np.testing.assert_array_equal(tr.t, times)  # exactly the times, nothing else
    assert tr.taut is not None and tr.events is not None
    assert list(tr.taut) == [True, True, True, False, False, True, True]
    # the events are those of the dense run (to round-off), listed up to t_end
    assert list(tr.events["kind"]) == list(dense.events["kind"])
    np.testing.assert_allclose(tr.events["t"], dense.events["t"], rtol=0, atol=1e-12)
    # in flight: the exact parabola from the leave
    x_e, v_e = dense.events["x"][0], dense.events["v_after"][0]
    for i in np.flatnonzero(~tr.taut):
        tau = times[i] - t_leave
        np.testing.assert_allclose(tr.x[i], x_e + v_e * tau - [0, 0, 0.5 * G * tau**2], rtol=0, atol=1e-14)
        np.testing.assert_allclose(tr.v[i], v_e - [0, 0, G * tau], rtol=0, atol=1e-14)
    # taut: a run 10x finer ending at that time (rattle8: they agree to round-off)
    np.testing.assert_array_equal(tr.x[0], s0.x)
    for i in np.flatnonzero(tr.taut)[1:]:
        fine = pl.simulate(p, s0, float(times[i]), method="rattle8", dt=1e-4, save_every=10**9)
        assert fine.t[-1] == times[i]
        np.testing.assert_allclose(tr.x[i], fine.x[-1], rtol=0, atol=1e-13)
        np.testing.assert_allclose(tr.v[i], fine.v[-1], rtol=0, atol=1e-12)
        assert abs(np.linalg.norm(tr.x[i]) - p.length) < 1e-14


@pytest.mark.parametrize(
    ("save_at", "needle"),
    [
        ([0.5, 0.2], "0.5 s is followed by 0.2 s"),
        ([0.1, float("nan")], r"save_at\[1\] = nan"),
        ([0.1, 1.5], r"1.5 s is not a finite time within \[t0, t_end\] = \[0, 1\] s"),
        ([-0.25, 0.5], "-0.25 s is not a finite time"),
        ([], "no save times"),
    ],
)
def test_bad_save_at_is_refused_naming_the_value(save_at: list[float], needle: str) -> None:
    p = pl.Pendulum(model="string")
    with pytest.raises(pl.InvalidInputError, match=needle):
        pl.simulate(p, launch(p, 1.0), 1.0, save_at=save_at)


def test_scenario_with_save_at() -> None:
    text = (
        (SCENARIOS / "string_slack.toml").read_text().replace("save_every = 10", "save_at = [0.5, 1.0, 4.0]")
    )
    assert "save_at" in text
    tr = pl.Scenario.from_toml_str(text).run(progress=False)
    np.testing.assert_array_equal(tr.t, [0.5, 1.0, 4.0])
    assert tr.events is not None and list(tr.events["kind"]) == ["slack", "taut"]


def test_a_scenario_may_start_the_string_slack() -> None:
    """A Cartesian start strictly inside the sphere is a slack string (the lab's scenario download of a
    slack moment round-trips): at rest at z = −l/2 the bob falls freely and the string snaps taut at
    the bottom after √(2 (l/2)/g); a start outside the sphere is still refused."""
    text = """
[pendulum]
model = "string"
length = 1.0
mass = 1.0
restitution = 0.0
[initial]
x = [0.0, 0.0, -0.5]
v = [0.0, 0.0, 0.0]
[simulation]
t_end = 1.0
method = "rattle"
dt = 1e-3
"""
    sc = pl.Scenario.from_toml_str(text)
    assert pl.Scenario.from_toml_str(sc.to_toml()) == sc
    tr = sc.run(progress=False)
    assert not tr.taut[0] and tr.taut[-1]
    assert tr.events is not None
    snap = np.asarray(tr.events["t"])[np.asarray(tr.events["kind"]) == "taut"][0]
    assert abs(snap - np.sqrt(2 * 0.5 / 9.81)) < 1e-12
    with pytest.raises(pl.ScenarioError, match="not on TS²"):
        pl.Scenario.from_toml_str(text.replace("-0.5", "-1.5"))
