"""The one validation layer (issue 13): the table of limits, the cases the issue reported, files
(size and nesting caps, errors naming the file, stale temporary files, no directories created) and
the stop of unprojected runs that leave TS². Units: SI."""

from __future__ import annotations

import errno
import math
import os
import time
import warnings
from pathlib import Path

import numpy as np
import pytest
from conftest import REPO, SCENARIOS
from typer.testing import CliRunner

import pendulab as pl
from pendulab import cli
from pendulab.validate import LIMITS, SHOW_CHARS, show


def _cli(*args: str) -> tuple[int, str, str]:
    r = CliRunner().invoke(cli.app, list(args))
    assert r.exception is None or isinstance(r.exception, SystemExit), r.exception
    return r.exit_code, r.stdout, r.stderr


def _one_error(err: str) -> str:
    lines = [ln for ln in err.splitlines() if ln.strip()]
    assert len(lines) == 1 and lines[0].startswith("error: "), err
    return lines[0]


# --- the table -------------------------------------------------------------------------------------


def test_the_table_is_the_registry_and_is_documented() -> None:
    table = {p["name"]: p for p in pl.limits()}
    assert {
        "length",
        "mass",
        "g",
        "position",
        "velocity",
        "angle",
        "angle_rate",
        "time",
        "dt",
        "steps",
    } <= set(table)
    assert {"samples", "saved_bytes", "file_bytes", "file_nesting"} <= set(table)
    for p in table.values():
        assert math.isfinite(p["min"]) and math.isfinite(p["max"]) and p["min"] <= p["max"], p
    for m in pl.models():  # every model parameter has finite bounds now
        for p in m["params"]:
            assert math.isfinite(p["min"]) and math.isfinite(p["max"]), (m["name"], p)
    doc = (REPO / "docs" / "limits.md").read_text(encoding="utf-8")
    for name, p in table.items():
        assert f"| `{name}` |" in doc and p["allowed"] in doc, name


def test_values_are_abbreviated_to_80_characters() -> None:
    assert len(show("x" * 10**6)) <= SHOW_CHARS
    with pytest.raises(pl.InvalidInputError) as e:
        pl.Pendulum(length="x" * 889_000)
    assert "length" in str(e.value) and len(str(e.value)) < 200


@pytest.mark.parametrize(
    ("kwargs", "name"),
    [
        ({"mass": 1e308}, "mass"),
        ({"length": 1e-300}, "length"),
        ({"g": 1e300}, "g"),
        ({"length": None}, "length"),
        ({"mass": "1.0"}, "mass"),
        ({"g": 10**400}, "g"),
        ({"damping": "a"}, "damping"),
        ({"damping": 1e300}, "damping"),
        ({"model": 3}, "model"),
        ({"length": True}, "length"),
    ],
)
def test_pendulum_parameters_name_the_bad_value(kwargs: dict, name: str) -> None:
    with pytest.raises(pl.InvalidInputError, match=rf"\b{name}\b"):
        pl.Pendulum(**kwargs)


def test_states_from_extreme_rates_and_positions_are_refused(pendulum: pl.Pendulum) -> None:
    with pytest.raises(pl.InvalidInputError, match="theta_dot"):
        pl.Pendulum(length=2.0).state_from_angles(theta=1.0, theta_dot=1e308)
    with pytest.raises(pl.InvalidInputError, match="speed"):  # a finite rate, a velocity beyond the bound
        pl.Pendulum(length=1e4).state_from_angles(theta=1.0, theta_dot=1e9)
    with pytest.raises(pl.InvalidInputError, match=r"x\[0\]"):
        pendulum.state([1e16, 0.0, 0.0], [0.0, 1.0, 0.0], project=True)
    with pytest.raises(pl.InvalidInputError, match="v"):
        pendulum.state([1.0, 0.0, 0.0], [None, 1.0, 0.0], project=True)
    # far (1e8 l) but within the limits: projected onto TS² to rounding
    s = pendulum.state([1e8, 3.0, -2.0], [0.5, 1e7, 3.0], project=True)
    assert abs(np.linalg.norm(s.x) - 1.0) < 1e-14
    assert abs(s.x @ s.v) <= 1e-12 * np.linalg.norm(s.v)


def test_runs_that_plan_unbounded_work_are_refused_at_once(pendulum: pl.Pendulum, rosette: pl.State) -> None:
    start = time.perf_counter()
    with pytest.raises(pl.InvalidInputError, match="dt"):
        pl.simulate(pendulum, rosette, 0.1, dt=1e-308)
    with pytest.raises(pl.InvalidInputError, match="t_end"):
        pl.simulate(pendulum, rosette, 1e308)
    with pytest.raises(pl.InvalidInputError, match="steps"):
        pl.simulate(pendulum, rosette, 1e11)  # 1e14 steps at the default dt = 1e-3 s
    with pytest.raises(pl.InvalidInputError, match="steps"):
        pl.Stepper(pendulum, rosette, dt=1e-9).step_to(1e6)
    with pytest.raises(pl.InvalidInputError, match="save_every"):
        pl.simulate(pendulum, rosette, 1.0, save_every=10**400)
    code, _, err = _cli("run", str(SCENARIOS / "rosette.toml"), "--dt", "1e-308", "--t-end", "0.1")
    assert code == 2 and "dt" in _one_error(err)
    code, _, err = _cli("run", str(SCENARIOS / "rosette.toml"), "--t-end", "1e308")
    assert code == 2 and "t_end" in _one_error(err)
    assert time.perf_counter() - start < 10.0
    assert LIMITS["steps"]["max"] == 1e10


def test_the_exact_solution_refuses_rather_than_returning_nan() -> None:
    p = pl.Pendulum(g=0.0)
    with pytest.raises(pl.InvalidInputError, match="phi_dot"):
        p.state_from_angles(theta=1e-3, theta_dot=-1.5, phi_dot=1e300)
    s = p.state_from_angles(theta=1e-3, theta_dot=-1.5, phi_dot=1e9)  # |v| = 1e6 m/s: allowed
    out = pl.exact(p, s).state(0.5)
    assert np.all(np.isfinite(out.x)) and np.all(np.isfinite(out.v))
    with pytest.raises(pl.InvalidInputError, match=r"\bt\b"):
        pl.exact(p, s).state(1e300)


def test_an_unprojected_run_that_leaves_ts2_stops_with_advice() -> None:
    p = pl.Pendulum(g=1e4)
    s = p.state_from_angles(theta=math.pi - 1e-3, phi_dot=0.5)
    with pytest.raises(pl.IntegrationError, match="project=True") as e:
        pl.simulate(p, s, 1.0, method="dop853", project=False, rtol=1e-6, atol=1e-6)
    assert "1e-02" in str(e.value) or "0.01" in str(e.value)
    with pytest.warns(RuntimeWarning, match="left TS²") as said:
        tr = pl.simulate(p, s, 1.0, method="dop853", project=False, rtol=1e-6, atol=1e-6, drift="warn")
    assert [w.filename for w in said] == [__file__]  # the caller's line
    assert np.max(np.abs(tr.constraint_error)) > 1e-2
    with pytest.raises(pl.IntegrationError, match="'rattle'"):
        pl.simulate(
            pl.Pendulum(), pl.Pendulum().state_from_angles(2.0, phi_dot=3.0), 50.0, method="rk4", dt=0.1
        )
    with pytest.warns(RuntimeWarning, match="left TS²") as said:  # simulate inside simulate: the same line
        start = pl.Pendulum().state_from_angles(2.0, phi_dot=3.0)
        pl.simulate(pl.Pendulum(), start, 50.0, method="rk4", dt=0.1, drift="warn", error_estimate=True)
    assert [w.filename for w in said] == [__file__]
    # within the tolerance nothing is said: rk4 at a small step
    pl.simulate(pl.Pendulum(), pl.Pendulum().state_from_angles(1.0, phi_dot=1.0), 1.0, method="rk4", dt=1e-3)


def test_divergence_does_not_suggest_the_method_in_use() -> None:
    p = pl.Pendulum(g=1e4, length=1e-6)
    s = p.state_from_angles(theta=2.0, phi_dot=1e6)
    for method in ("rattle", "rk4"):
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", RuntimeWarning)
                pl.simulate(p, s, 1.0, method=method, dt=1.0, drift="warn")
        except pl.IntegrationError as e:
            assert f"use '{method}'" not in str(e), str(e)
        except pl.InvalidInputError:
            pass


# --- files -------------------------------------------------------------------------------------------


def test_dev_zero_and_huge_files_are_refused_before_reading_them_whole(tmp_path: Path) -> None:
    start = time.perf_counter()
    for command in ("validate", "run"):  # not a regular file: refused at once, in one line
        code, _, err = _cli(command, "/dev/zero")
        assert code == 2 and "/dev/zero" in _one_error(err)
    big = tmp_path / "big.toml"
    big.write_text('title = "' + "x" * (1 << 20) + '"\n')
    code, _, err = _cli("validate", str(big))
    assert code == 2 and "big.toml" in _one_error(err)
    assert time.perf_counter() - start < 5.0


@pytest.mark.parametrize(
    "line",
    [
        "k = " + "[" * 5000 + "]" * 5000,
        "k = " + "{ a = " * 300 + "1" + " }" * 300,
        ".".join(["k"] * 3000) + " = 1",
    ],
)
def test_deep_nesting_is_refused_in_one_line(tmp_path: Path, line: str) -> None:
    f = tmp_path / "deep.toml"
    f.write_text((SCENARIOS / "rosette.toml").read_text() + "\n[extra]\n" + line + "\n")
    code, _, err = _cli("validate", str(f))
    assert code == 2 and "nest" in _one_error(err) and "deep.toml" in err
    with pytest.raises(pl.ScenarioError, match="nest"):
        pl.Scenario.from_toml_str(line)


def _toml_readers() -> dict[str, tuple[Path, object]]:
    from pendulab.crane.scenario import load as load_crane
    from pendulab.sweeps.file import load_sweep_file

    return {
        "scenario": (SCENARIOS / "rosette.toml", pl.load_scenario),
        "sweep": (REPO / "examples" / "sweeps" / "sway.toml", load_sweep_file),
        "crane": (REPO / "examples" / "cranes" / "gantry_zvd.toml", load_crane),
    }


@pytest.mark.parametrize("reader", ["scenario", "sweep", "crane"])
def test_every_toml_reader_takes_a_bom_and_refuses_hostile_text_clearly(tmp_path: Path, reader: str) -> None:
    """The audit of issue 30: a 5001-digit integer was a bare ValueError (a traceback from
    ``pendulab validate``) in every TOML reader; the crane reader refused a UTF-8 BOM and recursed on
    deep nesting (RecursionError)."""
    path, load = _toml_readers()[reader]
    base = path.read_bytes()
    f = tmp_path / f"{reader}.toml"
    f.write_bytes(b"\xef\xbb\xbf" + base)
    load(f)  # type: ignore[operator]
    for tail, words in [
        (b"\nzz = 1" + b"0" * 5000 + b"\n", "more than 4300 digits"),
        (b"\nzz = " + b"[" * 50_000 + b"]" * 50_000 + b"\n", "nest more than 16 levels"),
    ]:
        f.write_bytes(base + tail)
        with pytest.raises((pl.InvalidInputError, pl.ScenarioError), match=words) as refused:
            load(f)  # type: ignore[operator]
        assert str(f) in str(refused.value)


def test_validate_refuses_an_over_long_integer_in_one_line(tmp_path: Path) -> None:
    f = tmp_path / "long.toml"
    f.write_text((SCENARIOS / "rosette.toml").read_text() + "\n[extra]\nk = 1" + "0" * 5000 + "\n")
    code, _, err = _cli("validate", str(f))  # a traceback and exit code 1 before
    assert code == 2 and "more than 4300 digits" in _one_error(err) and "long.toml" in err


def test_missing_files_and_directories_are_named(tmp_path: Path) -> None:
    code, _, err = _cli("run", str(tmp_path / "nope.toml"))
    assert code == 2 and "nope.toml" in _one_error(err)
    out = tmp_path / "no_such_dir" / "out.csv"
    code, _, err = _cli("run", str(SCENARIOS / "rosette.toml"), "--out", str(out), "--t-end", "0.1")
    assert code == 2 and "does not exist" in _one_error(err)
    assert not out.parent.exists()  # --out does not create directories
    tr = pl.simulate(pl.Pendulum(), pl.Pendulum().state_from_angles(1.0), 0.01)
    with pytest.raises(OSError, match="does not exist") as e:
        tr.to_csv(out)
    assert e.value.filename == str(out)


@pytest.mark.parametrize("code", [errno.ENOSPC, errno.EROFS, errno.EACCES])
def test_a_full_disk_or_read_only_directory_is_one_line_naming_the_file(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, code: int
) -> None:
    def fail(*args: object, **kwargs: object) -> None:
        raise OSError(code, os.strerror(code))

    monkeypatch.setattr(pl.io, "csv_rows", fail)  # the CSV writer's rows, written after the header
    out = tmp_path / "out.csv"
    rc, _, err = _cli("run", str(SCENARIOS / "rosette.toml"), "--t-end", "0.1", "--out", str(out), "--quiet")
    line = _one_error(err)
    assert rc == 2 and str(out) in line and os.strerror(code) in line
    assert not out.exists() and not list(tmp_path.glob(".*.tmp"))


def test_stale_temporary_files_of_the_same_target_are_removed(tmp_path: Path) -> None:
    out = tmp_path / "out.csv"
    dead = tmp_path / ".out.csv.pid999999999.abc.tmp"  # a writer that no longer runs
    old = tmp_path / ".out.csv.xyz.tmp"  # an older writer's, without a pid, over an hour old
    alive = tmp_path / f".out.csv.pid{os.getpid()}.keep.tmp"  # a writer still running
    other = tmp_path / ".other.csv.pid999999999.abc.tmp"  # another target's
    for f in (dead, old, alive, other):
        f.write_text("partial")
    os.utime(old, (time.time() - 7200, time.time() - 7200))
    tr = pl.simulate(pl.Pendulum(), pl.Pendulum().state_from_angles(1.0), 0.01)
    tr.to_csv(out)
    assert out.exists() and not dead.exists() and not old.exists()
    assert alive.exists() and other.exists()


def test_scenario_run_errors_name_the_file(tmp_path: Path) -> None:
    f = tmp_path / "drift.toml"
    f.write_text(
        "[pendulum]\nlength = 1.0\nmass = 1.0\ng = 9.81\n[initial]\ntheta = 2.0\nphi_dot = 3.0\n"
        '[simulation]\nt_end = 50.0\nmethod = "rk4"\ndt = 0.1\n'
    )
    code, _, err = _cli("run", str(f), "--quiet")
    line = _one_error(err)
    assert code == 2 and "drift.toml" in line and "left TS²" in line
