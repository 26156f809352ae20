"""A CSV the lab exported (docs/web.md, "Share and export") is read as every Pendulab CSV is (README,
"Reading a CSV back": ``pendulab.io.read_metadata``, the JSON after ``metadata (JSON): ``, pandas
``comment="#"``, NumPy ``skiprows=2``) and replays its run: ``pl.simulate`` from the header's start,
pendulum, method, dt and arithmetic gives its states bit for bit (``tools/replay_lab_csv.py``, which
``make test-lab-html`` runs on fresh downloads of the one-file lab; here on ones kept in
``python/tests/data/lab/``).
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from conftest import load_tool

import pendulab as pl
from pendulab.io import read_metadata

DATA = Path(__file__).parent / "data" / "lab"
FILES = sorted(DATA.glob("lab-*.csv"))


replay_lab_csv = load_tool("replay_lab_csv")
COLUMNS_LAB = replay_lab_csv.COLUMNS


def _with_meta(src: Path, dst: Path, **change: object) -> Path:
    """``src`` with its metadata's keys (``options`` merged) replaced by ``change``."""
    first, rest = src.read_text(encoding="utf-8").split("\n", 1)
    prefix, text = first.split("metadata (JSON): ", 1)
    meta = json.loads(text)
    meta["options"] |= change.pop("options", {})  # type: ignore[operator]
    meta |= change
    dst.write_text(f"{prefix}metadata (JSON): {json.dumps(meta, sort_keys=True)}\n{rest}", encoding="utf-8")
    return dst


def test_the_kept_downloads_are_there() -> None:
    assert [f.name for f in FILES] == ["lab-damped.csv", "lab-rosette.csv"]


@pytest.mark.parametrize("path", FILES, ids=lambda p: p.stem)
def test_a_lab_csv_reads_as_every_pendulab_csv(path: Path) -> None:
    with open(path, encoding="utf-8") as f:
        first = f.readline()
        meta = json.loads(first.split("metadata (JSON): ", 1)[1])
    assert first.startswith("# pendulab lab trajectory; metadata (JSON): {")
    assert read_metadata(path) == meta
    assert meta["options"]["arithmetic"] == "unfused" and meta["software"] == "pendulab"
    assert list(meta) == sorted(meta)  # as json.dumps(sort_keys=True) writes the CLI's line
    df = pd.read_csv(path, comment="#")
    a = np.loadtxt(path, delimiter=",", skiprows=2)
    assert list(df.columns[:4]) == ["t [s]", "x1 [m]", "x2 [m]", "x3 [m]"] and df.shape == a.shape == (40, 19)
    assert np.array_equal(df.to_numpy(), a)
    # the start is the first row's state (the damped file's run began mid-way, at the change of model)
    assert [meta["start"]["t"], *meta["start"]["x"], *meta["start"]["v"]] == a[0, :7].tolist()


@pytest.mark.parametrize("path", FILES, ids=lambda p: p.stem)
def test_a_lab_csv_replays_bit_for_bit_with_its_arithmetic(path: Path) -> None:
    got = replay_lab_csv.replay(path)
    assert got["rows"] == 40 and got["differ"] == 0 and got["largest"] == 0.0
    # the arithmetic matters: fused multiply-adds give other last bits in most rows
    assert replay_lab_csv.replay(path, "fused")["differ"] > 10
    assert replay_lab_csv.main([str(path)]) == 0


def test_a_header_that_does_not_say_the_run_is_not_replayed(tmp_path: Path) -> None:
    rosette = DATA / "lab-rosette.csv"
    fused = _with_meta(rosette, tmp_path / "fused.csv", options={"arithmetic": "fused"})
    assert replay_lab_csv.replay(fused)["differ"] > 10
    assert replay_lab_csv.main([str(fused)]) == 1
    change = [{"t": 1.5, "method": "rk4", "dt": 0.01}]
    changed = _with_meta(rosette, tmp_path / "changed.csv", method_changes=change)
    with pytest.raises(ValueError, match=r"method changed at t = 1.5 s to rk4 \(dt = 0.01 s\)"):
        replay_lab_csv.replay(changed)
    old = tmp_path / "old.csv"  # the lab's line before it said the arithmetic and the start
    rows = rosette.read_text().split("\n", 1)[1]
    old.write_text('# {"source": "pendulab lab", "method": "rattle"}\n' + rows)
    with pytest.raises(ValueError, match="is not the lab's metadata line"):
        replay_lab_csv.replay(old)


def test_a_file_the_tool_cannot_replay_is_one_error_line_with_exit_code_2(tmp_path: Path, capsys) -> None:
    """A wrong file was answered with a Python traceback (KeyError, FileNotFoundError, ...): now one line
    ``error: FILE: ...`` saying what is wrong, exit code 2 (1 stays "rows differ")."""
    rosette = DATA / "lab-rosette.csv"
    p = pl.Pendulum()
    trajectory = pl.simulate(p, p.state_from_angles(0.5), 0.1).to_csv(tmp_path / "cli.csv")
    no_start = tmp_path / "no_start.csv"
    first, rest = rosette.read_text(encoding="utf-8").split("\n", 1)
    meta = json.loads(first.split("metadata (JSON): ", 1)[1])
    del meta["start"], meta["options"]["t0"]
    no_start.write_text(f"{first.split('{', 1)[0]}{json.dumps(meta)}\n{rest}", encoding="utf-8")
    binary = tmp_path / "binary.csv"
    binary.write_bytes(b"\xff\xfe\x00garbage")
    words = tmp_path / "words.csv"
    words.write_text(
        f"{rosette.read_text(encoding='utf-8').split(chr(10), 2)[0]}\n{','.join(COLUMNS_LAB)}\na,b\n"
    )
    adaptive = _with_meta(rosette, tmp_path / "adaptive.csv", adaptive=True, method="dop853")
    cases = {
        tmp_path / "missing.csv": "cannot read",
        tmp_path: "cannot read",
        trajectory: "is not the lab's metadata line",
        no_start: "the metadata lack what a replay needs: start, options.t0",
        binary: "",
        words: "the rows are not numbers",
        adaptive: "method 'dop853' is adaptive",
    }
    for path, needle in cases.items():
        assert replay_lab_csv.main([str(path)]) == 2, path
        err = capsys.readouterr().err
        assert err.startswith(f"error: {path}: ") and err.count("\n") == 1 and needle in err, err
        assert "Traceback" not in err
