"""Crane files (pendulab.crane.scenario, ``pendulab crane run``; docs/cranes.md "Crane files"): the
shipped example runs and keeps its energy balance, the file's crane equals the one built in Python,
and bad contents are one clear error naming the key."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from test_cli import assert_user_error, invoke

from pendulab import InvalidInputError, crane
from pendulab.crane.scenario import load, parse

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "cranes" / "gantry_zvd.toml"


def test_the_example_runs_from_the_command_line(tmp_path: Path) -> None:
    out = tmp_path / "run.csv"
    code, text, err = invoke("crane", "run", str(EXAMPLE), "--out", str(out))
    assert code == 0, err
    assert "sway modes 0.91, 7.9949 rad/s; shaper zvd" in text
    data = np.genfromtxt(out, delimiter=",", skip_header=1, names=True)  # after the # metadata line
    work = sum(data[k] for k in data.dtype.names if k.startswith("work_"))
    assert np.abs(data["energy_J"] - data["energy_J"][0] - work).max() < 1e-6


def test_the_file_builds_the_same_crane_as_python() -> None:
    sc = load(EXAMPLE)
    s = crane.shaper("zvd", omega=float(sc.crane.modes()[0]))
    np.testing.assert_allclose(sc.shaper.times, s.times, rtol=1e-15)
    path = crane.move(5.0, 0.5, 0.5, shaper=s, t_start=1.0)
    t = np.linspace(0, 30, 301)
    np.testing.assert_allclose(sc.crane.pivot.position(t), path.position(t), atol=1e-15)
    assert sc.crane.hoist.length([12.0])[0] == pytest.approx(8.0)
    assert sc.move_end == pytest.approx(path.t_end)


BASE = {"crane": {"rope": 10.0}, "simulation": {"t_end": 5.0}}


@pytest.mark.parametrize(
    ("patch", "needle"),
    [
        ({"crane": {"rope": 10.0, "ropes": 3.0}}, "ropes"),
        ({"crane": {"rope": -1.0}}, "crane.rope"),
        ({"crane": {"rope": "10"}}, "crane.rope"),
        ({"shaper": {"kind": "zv"}}, "needs a [move]"),
        (
            {
                "move": {"distance": 1.0, "v_max": 1.0, "a_max": 1.0},
                "shaper": {"kind": "zv", "omega": 1.0, "rope": 2.0},
            },
            "not both",
        ),
        ({"move": {"distance": 1.0, "v_max": 1.0, "a_max": 1.0}, "shaper": {"kind": "zz"}}, "zz"),
        ({"wind": {"turbulence": 1.0}}, "steady wind"),
        ({"hoist": {"t": [0.0, 1.0], "length": [9.0, 8.0]}}, "hoist"),
    ],
)
def test_bad_files(patch: dict, needle: str) -> None:
    with pytest.raises(InvalidInputError, match=needle.replace("[", r"\[").replace("]", r"\]")):
        parse({**BASE, **patch})


ROPE = r"allowed: rope length at t = 0 in m, >= 1e-6 and <= 1e4"


@pytest.mark.parametrize(
    ("patch", "message"),
    [
        ({"crane": {"rope": -1.0}}, r"crane\.rope = -1\.0: must be >= 1e-6; " + ROPE),
        (
            {"crane": {"rope": float("nan")}},
            r"crane\.rope = nan is not a finite number \(nan and inf are not "
            r"allowed\); " + ROPE,
        ),
        ({"crane": {"rope": "10"}}, r"crane\.rope = '10' is not a number; " + ROPE),
        (
            {"crane": {"rope": 10.0, "ropes": 3.0}},
            r"unknown key crane\.ropes = 3\.0 \(did you mean 'rope'\?\); allowed keys in \[crane\]: rope, "
            r"payload_mass, hook_mass, rigging, damping, g",
        ),
        (
            {"simulation": {"t_end": 5.0, "output_spacing": 0.0}},
            r"simulation\.output_spacing = 0\.0: must be > 0; allowed: time between output rows in s, > 0 "
            r"and <= 1e6 \(DOP853 chooses its own steps\)",
        ),
        (
            {"crane": {"rope": -1.0, "g": "x"}},
            r"2 problems: \(1\) crane\.rope = -1\.0: must be >= 1e-6; "
            + ROPE
            + r" \(2\) crane\.g = 'x' is not a "
            r"number; allowed: gravitational acceleration in m/s², > 0 and <= 1000",
        ),
    ],
)
def test_bad_values_name_the_key_the_value_and_what_is_allowed(patch: dict, message: str) -> None:
    """Crane file errors were pydantic's words (``[crane.rope]: Input should be greater than 0``): now a
    pendulum scenario file's (pendulab.scenario.errors), naming the key, the value and what is allowed."""
    with pytest.raises(InvalidInputError, match="^<crane file>: " + message + "$"):
        parse({**BASE, **patch})


def test_cli_names_the_file_as_typed_and_the_key(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(tmp_path)
    Path("bad.toml").write_text("[crane]\nrope = -1.0\n[simulation]\nt_end = 5.0\n")
    message = "error: ./bad.toml: crane.rope = -1.0: must be >= 1e-6; allowed: rope length at t = 0 in m"
    assert_user_error(*invoke("crane", "run", "./bad.toml"), message)
    Path("bad.toml").write_text("[crane\n")
    assert_user_error(*invoke("crane", "run", ".//bad.toml"), "error: .//bad.toml: not valid TOML: ")


def test_cli_user_errors(tmp_path: Path) -> None:
    bad = tmp_path / "bad.toml"
    bad.write_text("[crane]\nrope = 10.0\n")
    assert_user_error(*invoke("crane", "run", str(bad)), "simulation")
    assert_user_error(*invoke("crane", "run", str(EXAMPLE), "--out", str(tmp_path / "x.parquet")), ".csv")


def test_pendulab_run_quiet_prints_nothing_for_a_crane_file(tmp_path: Path) -> None:
    """`pendulab run FILE -q` prints nothing but errors (docs/cli.md) for a crane file too (it printed
    the crane's report and 'wrote …')."""
    out = tmp_path / "run.csv"
    code, text, err = invoke("run", str(EXAMPLE), "-q", "--out", str(out))
    assert code == 0 and text == "" and err == "", (text, err)
    assert out.stat().st_size > 0
    code, text, _ = invoke("run", str(EXAMPLE))
    assert code == 0 and "sway modes 0.91, 7.9949 rad/s; shaper zvd" in text


def test_more_than_five_problems_say_how_many_more_and_the_error_holds_all() -> None:
    """The message showed five problems and "(and 2 more)", but the other two were lost: the error
    (``crane.CraneFileError``, an ``InvalidInputError``) now holds every one in ``problems``."""
    bad = {
        "crane": {"rope": -1.0, "payload_mass": -2.0, "damping": "x", "g": "y", "ropes": 1.0},
        "simulation": {"t_end": -5.0, "rtol": "z"},
    }
    with pytest.raises(crane.CraneFileError) as err:
        parse(bad, "many.toml")
    e = err.value
    assert isinstance(e, InvalidInputError) and e.source == "many.toml"
    assert len(e.problems) == 7 and e.problems[0].startswith("unknown key crane.ropes = 1.0")
    keys = (
        "crane.rope",
        "crane.payload_mass",
        "crane.damping",
        "crane.g",
        "simulation.t_end",
        "simulation.rtol",
    )
    assert all(any(p.startswith(f"{k} = ") for p in e.problems) for k in keys), e.problems
    shown = " ".join(f"({k}) {p}" for k, p in enumerate(e.problems[:5], 1))
    assert str(e) == f"many.toml: 7 problems: {shown} (and 2 more)", str(e)
    assert e.problems[5] not in str(e) and e.problems[6] not in str(e)
    with pytest.raises(crane.CraneFileError) as two:
        parse({"crane": {"rope": -1.0, "g": "x"}, "simulation": {"t_end": 5.0}})
    assert len(two.value.problems) == 2 and "more)" not in str(two.value)
