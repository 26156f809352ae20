"""The fit's data reader (pendulab/fitting/table.py) refuses the CSVs of ``pendulab crane run`` and
``pendulab crane grid`` by name: a crane's payload hangs from a moving trolley (maybe below a hook, on a
hoisted rope), which no model of the fit describes, and a grid has no time series. The refusal names
the columns found, what a fit needs and the command that writes a fittable file; ``pendulab fit`` and
the lab's ``POST /api/fit`` say the same (keyed ``data_crane_run``, ``data_crane_grid``)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from test_cli import assert_user_error, invoke

import pendulab as pl
from pendulab.fitting.table import MAKES_FITTABLE, parse_table, read_table

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "cranes" / "gantry_zvd.toml"
GRID = ("--ropes", "6:10:2", "--ratios", "2:8:2", "--shapers", "none", "--settle", "5")


@pytest.fixture(scope="module")
def crane_files(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Path]:
    d = tmp_path_factory.mktemp("crane_csv")
    run, grid = d / "run.csv", d / "grid.csv"
    assert invoke("crane", "run", str(EXAMPLE), "--out", str(run))[0] == 0
    assert invoke("crane", "grid", *GRID, "--out", str(grid))[0] == 0
    # as written before the crane CSVs had their '# pendulab crane …' line: the header first
    old_run, old_grid = d / "old_run.csv", d / "old_grid.csv"
    old_run.write_text(run.read_text().split("\n", 1)[1])
    old_grid.write_text(grid.read_text().split("\n", 1)[1])
    return {"run": run, "grid": grid, "old_run": old_run, "old_grid": old_grid}


@pytest.mark.parametrize("name", ["run", "old_run"])
def test_a_crane_run_csv_is_refused_naming_its_columns_and_the_fittable_command(
    crane_files: dict[str, Path], name: str
) -> None:
    with pytest.raises(pl.InvalidInputError) as e:
        read_table(crane_files[name])
    text = str(e.value)
    assert e.value.key == "data_crane_run"  # type: ignore[attr-defined]
    said = f"{name}.csv: a crane run (pendulab crane run --out) with the columns ['t [s]', 'pivot_x [m]'"
    assert said in text
    assert "'payload_x [m]'" in text and "moving trolley" in text and "a fit needs t and x, y, z" in text
    assert MAKES_FITTABLE == "pendulab run SCENARIO.toml --out FILE.csv" and MAKES_FITTABLE in text
    assert "(payload_x - pivot_x, payload_y - pivot_y) as t,x,y" in text


@pytest.mark.parametrize("name", ["grid", "old_grid"])
def test_a_crane_grid_csv_is_refused_as_no_time_series(crane_files: dict[str, Path], name: str) -> None:
    with pytest.raises(pl.InvalidInputError) as e:
        read_table(crane_files[name])
    assert e.value.key == "data_crane_grid"  # type: ignore[attr-defined]
    assert str(e.value).startswith(
        f"{crane_files[name]}: a crane grid (pendulab crane grid --out): one row per case with the "
        "columns ['shaper', 'rope [m]', 'ratio', 'sway [m]'], no time series; a fit needs t and x, y, z"
    )
    assert MAKES_FITTABLE in str(e.value)


def test_pendulab_fit_says_it_and_named_columns_are_refused_the_same_way(
    crane_files: dict[str, Path],
) -> None:
    """``pendulab fit`` prints the refusal as one error line; naming the columns (``--columns``, here the
    payload's absolute x, y, z as positions) was let through before, and fitted a moving trolley's payload
    as a bob about a fixed pivot: it is refused in the same words."""
    assert_user_error(*invoke("fit", str(crane_files["run"])), "a crane run", MAKES_FITTABLE)
    assert_user_error(*invoke("fit", str(crane_files["grid"])), "a crane grid", MAKES_FITTABLE)
    header = crane_files["old_run"].read_text().split("\n", 1)[0].split(",")
    columns = ["t"] + ["-"] * 6 + ["x", "y", "z"] + ["-"] * (len(header) - 10)
    for name in ("run", "old_run"):
        with pytest.raises(pl.InvalidInputError) as e:
            read_table(crane_files[name], columns)
        assert e.value.key == "data_crane_run"  # type: ignore[attr-defined]
        code, out, err = invoke("fit", str(crane_files[name]), "--columns", ",".join(columns))
        assert_user_error(code, out, err, "a crane run", MAKES_FITTABLE)
    with pytest.raises(pl.InvalidInputError, match="a crane grid"):
        read_table(crane_files["grid"], ["-", "t", "-", "x"])


def test_a_pendulab_trajectory_csv_still_reads(tmp_path: Path) -> None:
    p = pl.Pendulum()
    tr = pl.simulate(p, p.state_from_angles(theta=0.5), 1.0, method="dop853")
    got = read_table(tr.to_csv(tmp_path / "swing.csv"))
    assert (got["t"] == tr.t).all() and (got["positions"] == tr.x).all()
    assert parse_table("t,x,y,z\n0,0.1,0,-1\n0.1,0.2,0,-1\n")["positions"].shape == (2, 3)


def test_the_lab_words_the_refusal_by_its_key(crane_files: dict[str, Path]) -> None:
    pytest.importorskip("fastapi")
    from ws_session import LabClient

    from pendulab.server import create_app
    from pendulab.server.notices import message

    client = LabClient(create_app("rosette"))
    for name, key in (("run", "data_crane_run"), ("grid", "data_crane_grid")):
        body = json.dumps({"csv": crane_files[name].read_text(), "name": f"{name}.csv"})
        r = client.post("/api/fit", content=body, headers={"content-type": "application/json"})
        answer = r.json()
        assert r.status_code == 422 and answer["key"] == key, answer
        assert answer["values"]["command"] == MAKES_FITTABLE
        assert ("'shaper'" if name == "grid" else "'pivot_x [m]'") in answer["values"]["columns"]
        worded = message(key, **answer["values"])
        assert "{" not in worded and worded.startswith(f"{name}.csv: a crane ")
