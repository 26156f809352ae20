"""A crane file's ``[simulation] output_spacing`` [s], the time between the output rows of the crane's
adaptive (DOP853) run, was called ``dt`` (which elsewhere is a step). New files say ``output_spacing``;
an older file's ``dt`` is read as it (the same run, silently: the file is not wrong, only older), a
``[simulation]`` with both keys is refused naming both, an older file's bad ``dt`` is named as written;
what Python writes (``Scenario.to_toml``) says ``output_spacing``; ``--dt`` of ``pendulab run`` still sets
it. docs/cranes.md "Crane files", docs/scenarios.md "Cranes"."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from test_cli import assert_user_error, invoke

import pendulab as pl
from pendulab import InvalidInputError
from pendulab.crane.scenario import load, parse

HOIST = Path(__file__).resolve().parents[2] / "examples" / "scenarios" / "crane_hoist.toml"
SMALL = "[crane]\nrope = 10.0\n[move]\ndistance = 2.0\nv_max = 0.5\na_max = 0.5\n[simulation]\nt_end = 6.0\n"


def test_the_shipped_files_say_output_spacing() -> None:
    gantry = HOIST.parents[1] / "cranes" / "gantry_zvd.toml"
    for path in (HOIST, gantry):
        text = path.read_text(encoding="utf-8")
        assert "output_spacing = 0.05" in text and "\ndt =" not in text, path
    assert load(gantry).output_spacing == 0.05
    assert pl.load_scenario(HOIST).spec.simulation.output_spacing == 0.05


def test_an_older_files_dt_is_read_as_output_spacing_and_gives_the_same_run(tmp_path: Path) -> None:
    new = pl.Scenario.from_toml_str(SMALL + "output_spacing = 0.25\n", "new.toml")
    old = pl.Scenario.from_toml_str(SMALL + "dt = 0.25\n", "old.toml")
    assert old.spec == new.spec and old.spec.simulation.output_spacing == 0.25
    assert old.expected_samples() == new.expected_samples() == 25
    a, b = old.run(), new.run()
    assert len(a.t) == 25 and np.array_equal(a.t, b.t) and np.array_equal(a.payload, b.payload)
    assert parse({"crane": {"rope": 10.0}, "simulation": {"t_end": 1.0, "dt": 0.5}}).output_spacing == 0.5
    path = tmp_path / "old.toml"
    path.write_text(SMALL + "dt = 0.25\n", encoding="utf-8")
    code, _, err = invoke("validate", str(path))
    assert code == 0, err
    assert invoke("crane", "run", str(path), "--out", str(tmp_path / "run.csv"))[0] == 0
    assert pl.io.read_metadata(tmp_path / "run.csv")["file"]["simulation"]["output_spacing"] == 0.25


def test_both_keys_are_refused_naming_both(tmp_path: Path) -> None:
    text = SMALL + "output_spacing = 0.25\ndt = 0.1\n"
    needle = "output_spacing = 0.25 and dt = 0.1 both given: dt is the older name of output_spacing"
    with pytest.raises(pl.ScenarioError, match=r"\[simulation\] output_spacing = 0\.25 and dt = 0\.1 both"):
        pl.Scenario.from_toml_str(text, "both.toml")
    path = tmp_path / "both.toml"
    path.write_text(text, encoding="utf-8")
    assert_user_error(*invoke("validate", str(path)), "both.toml", needle)
    assert_user_error(*invoke("crane", "run", str(path)), "both.toml", needle)
    with pytest.raises(InvalidInputError, match=r"output_spacing = 0\.25 and dt = 0\.1 both given"):
        load(path)


def test_a_bad_value_is_named_by_the_key_the_file_has() -> None:
    with pytest.raises(pl.ScenarioError, match=r"simulation\.dt = -1\.0: must be > 0") as old:
        pl.Scenario.from_toml_str(SMALL + "dt = -1.0\n", "old.toml")
    assert "time between output rows in s" in str(old.value)
    with pytest.raises(pl.ScenarioError, match=r"simulation\.output_spacing = 0\.0: must be > 0"):
        pl.Scenario.from_toml_str(SMALL + "output_spacing = 0.0\n", "new.toml")


def test_written_files_say_output_spacing_and_dt_overrides_set_it() -> None:
    old = pl.Scenario.from_toml_str(SMALL + "dt = 0.25\n", "old.toml")
    text = old.to_toml()
    assert "output_spacing = 0.25" in text and "\ndt =" not in text, text
    assert pl.Scenario.from_toml_str(text) == old
    wider = old.with_overrides(dt=0.5)  # pendulab run --dt: the crane's output spacing
    assert wider.spec.simulation.output_spacing == 0.5 and wider.expected_samples() == 13
    assert wider.source == "old.toml (with dt = 0.5)"
    assert len(wider.run().t) == 13
    with pytest.raises(pl.ScenarioError, match="its \\[simulation\\] has t_end, output_spacing, sway"):
        old.with_overrides(method="rk4")
