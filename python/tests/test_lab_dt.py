"""What a lab session's ``dt`` [s] is (docs/web.md, "Notices"): the step of a fixed-step method. The
lab's ``dop853`` does not use it — it chooses all its steps, the first too, also when the scenario file
gives a first step — and keeps it as the step of a fixed-step method chosen next. A crane file's
``output_spacing`` (the time between the rows of a crane run) is no step: its session's dt is the
default step, 1e-3 s (it was the file's 0.05 s)."""

from __future__ import annotations

from pathlib import Path

import pytest

import pendulab as pl
from pendulab.server.protocol import parse_command
from pendulab.server.session import Session, resolve_scenario

ROSETTE = Path(__file__).resolve().parents[2] / "examples" / "scenarios" / "rosette.toml"


def _dop853_file(tmp_path: Path, name: str, dt_line: str) -> Path:
    text = ROSETTE.read_text(encoding="utf-8")
    assert "dt = 1.0e-3" in text and 'method = "rattle"' in text
    path = tmp_path / f"{name}.toml"
    path.write_text(text.replace('"rattle"', '"dop853"').replace("dt = 1.0e-3", dt_line), encoding="utf-8")
    return path


def _one_step(s: Session) -> float:
    s.apply(parse_command('{"type": "step", "n": 1}'))
    s.take_pending_steps()
    return s.t


def test_the_labs_dop853_chooses_its_first_step_whatever_the_sessions_dt(tmp_path: Path) -> None:
    given = Session(resolve_scenario(_dop853_file(tmp_path, "given", "dt = 1.0e-4")))
    left_out = Session(resolve_scenario(_dop853_file(tmp_path, "auto", "")))
    assert (given.status()["dt"], left_out.status()["dt"]) == (1e-4, 1e-3)
    assert given.status()["adaptive"] is True
    first = _one_step(given)
    assert first == _one_step(left_out) != 1e-4
    sc = pl.load_scenario(tmp_path / "given.toml")
    auto = pl.Stepper(sc.pendulum(), sc.initial_state(), method="dop853")  # dt left out: automatic
    auto.step(1)
    assert auto.t == first and (given.state.x == auto.state.x).all()


def test_the_kept_dt_is_the_step_of_a_fixed_step_method_chosen_next(tmp_path: Path) -> None:
    s = Session(resolve_scenario(_dop853_file(tmp_path, "given", "dt = 2.0e-3")))
    t = _one_step(s)
    s.apply(parse_command('{"type": "set_method", "method": "rattle"}'))
    assert s.status()["dt"] == 2e-3 and s.status()["adaptive"] is False
    assert _one_step(s) == pytest.approx(t + 2e-3, abs=1e-15)


def test_a_crane_files_output_spacing_is_not_the_sessions_step() -> None:
    sc = pl.load_scenario("crane_hoist")
    assert sc.spec.simulation.output_spacing == 0.05
    status = Session(resolve_scenario("crane_hoist")).status()
    assert status["method"] == "dop853" and status["dt"] == 1e-3
