"""``pendulab crane`` (python/pendulab/cli/crane.py, docs/cli.md): the shaper table, the sensitivity
table and plot, a move's residual sway; user errors as one ``error:`` line with exit code 2."""

from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np
import pytest
from test_cli import assert_user_error, invoke

from pendulab import crane


def test_shaper_table_matches_the_library() -> None:
    code, out, _ = invoke("crane", "shaper", "zvd", "--rope", "10")
    assert code == 0
    s = crane.shaper("zvd", omega=math.sqrt(9.81 / 10))
    rows = [line.split() for line in out.splitlines() if re.match(r"^\s+\d+\s", line)]
    np.testing.assert_allclose([(float(r[1]), float(r[2])) for r in rows], s.table(), atol=1e-6)
    assert "insensitivity (V ≤ 5 %) 0.2871" in out


def test_sensitivity_table_and_plot(tmp_path: Path) -> None:
    png = tmp_path / "v.png"
    code, out, _ = invoke("crane", "sensitivity", "zv", "ei", "--points", "3", "--plot", str(png))
    assert code == 0 and png.stat().st_size > 1000
    row = next(line for line in out.splitlines() if line.startswith("1.0000"))
    assert [float(v) for v in row.split()[1:]] == pytest.approx([0.0, 5.0], abs=1e-9)


def test_residual_reports_the_shapers_ratio() -> None:
    code, out, _ = invoke("crane", "residual", "--shaper", "zv", "--design-rope", "12", "--settle", "15")
    assert code == 0, out
    m = re.search(r"ratio ([\d.e-]+) \(the shaper's V at ω = [\d.]+ rad/s: ([\d.e-]+)\)", out)
    assert m is not None, out
    assert float(m.group(1)) == pytest.approx(float(m.group(2)), rel=0.03)


@pytest.mark.parametrize(
    ("args", "needle"),
    [
        (("crane", "shaper", "zq", "--omega", "1"), "zq"),
        (("crane", "shaper", "zv"), "--omega"),
        (("crane", "shaper", "zv", "--omega", "-2"), "omega"),
        (("crane", "sensitivity", "zv", "--plot", "x.gif"), ".gif"),
        (("crane", "residual", "--a-max", "0"), "a_max"),
        (("crane", "residual", "--hook-mass", "100"), "rigging"),
    ],
)
def test_user_errors(args: tuple[str, ...], needle: str) -> None:
    assert_user_error(*invoke(*args), needle)


def test_grid_command_writes_every_case(tmp_path: Path) -> None:
    out = tmp_path / "grid.csv"
    code, text, err = invoke(
        "crane",
        "grid",
        "--ropes",
        "6:10:2",
        "--ratios",
        "2:8:2",
        "--shapers",
        "none,zvd",
        "--settle",
        "5",
        "--out",
        str(out),
    )
    assert code == 0, err
    rows = [line.split(",") for line in out.read_text().splitlines()[2:]]
    assert len(rows) == 8 and {r[0] for r in rows} == {"unshaped", "zvd"}
    res = crane.residual_grid([6.0, 10.0], [2.0, 8.0], [None], settle=5.0)
    np.testing.assert_allclose([float(r[3]) for r in rows[:4]], res.sway[0].ravel(), rtol=1e-12)
    assert "8 runs in" in text
    assert_user_error(*invoke("crane", "grid", "--ropes", "5:1:3"), "--ropes")


def test_crane_grid_csv_has_the_metadata_line_of_every_pendulab_csv(tmp_path: Path) -> None:
    """``pendulab crane grid --out`` starts like every Pendulab CSV: ``# pendulab crane grid; metadata
    (JSON): …`` (the command's settings, the design ω, each shaper's impulses, units), then the names
    with units; NumPy reads it as a trajectory's (skiprows=2 for the numbers, skip_header=1 with names)."""
    import json

    out = tmp_path / "grid.csv"
    args = ("--ropes", "6:10:2", "--ratios", "2:8:2", "--shapers", "none,zv", "--settle", "5")
    code, _, err = invoke("crane", "grid", *args, "--hook-mass", "50", "--out", str(out))
    assert code == 0, err
    first, names = out.read_text().splitlines()[:2]
    assert first.startswith("# pendulab crane grid; metadata (JSON): {")
    meta = json.loads(first.split("metadata (JSON): ", 1)[1])
    settings = meta["settings"]
    assert (settings["ropes"], settings["ratios"], settings["shapers"]) == ("6:10:2", "2:8:2", ["none", "zv"])
    assert settings["hook_mass"] == 50.0 and settings["settle"] == 5.0 and settings["design_rope"] == 8.0
    # designed for the middle rope and the median ratio (2 and 8: 5)
    probe = crane.Crane(rope=8.0, payload_mass=50.0 * 5.0, hook_mass=50.0, rigging=2.0, g=9.81)
    assert meta["design_omega"] == pytest.approx(float(probe.modes()[0]), rel=1e-12)
    zv = crane.shaper("zv", omega=meta["design_omega"])
    assert meta["shapers"]["zv"] == {"times": zv.times.tolist(), "amplitudes": [0.5, 0.5]}
    assert meta["cases"] == 8 and meta["units"]["sway"] == "m" and meta["units"]["settle"] == "s"
    assert names == "shaper,rope [m],ratio,sway [m]"
    table = np.genfromtxt(out, delimiter=",", skip_header=1, names=True, dtype=None, encoding="utf-8")
    assert list(table["shaper"]) == ["unshaped"] * 4 + ["zv"] * 4 and list(table["rope_m"][:2]) == [6.0, 6.0]
    rows = np.loadtxt(out, delimiter=",", skiprows=2, usecols=(1, 2, 3))
    assert rows.shape == (8, 3) and np.array_equal(rows[:, 2], table["sway_m"])


def test_crane_run_csv_reads_back_bit_for_bit(tmp_path: Path) -> None:
    """``pendulab crane run --out`` writes every number in the shortest text that reads back as the
    same float (t = 0.1 s as ``0.1``, not ``0.10000000000000001``); the grid's numbers too."""
    from pendulab.crane.scenario import load

    example = Path(__file__).resolve().parents[2] / "examples" / "cranes" / "gantry_zvd.toml"
    out = tmp_path / "run.csv"
    code, _, err = invoke("crane", "run", str(example), "--out", str(out))
    assert code == 0, err
    lines = out.read_text().splitlines()
    names = next(line for line in lines if line.startswith("t [s],")).split(",")
    data = np.loadtxt(out, delimiter=",", comments="#", skiprows=lines.index(",".join(names)) + 1)
    run = load(example).run()
    assert [row.split(",", 1)[0] for row in lines[-len(run.t) :][:3]] == ["0", "0.05", "0.1"]
    expected = {"t [s]": run.t, "payload_x [m]": run.payload[:, 0], "rope [m]": run.rope}
    expected |= {"energy [J]": run.energy, "tension_rope [N]": run.tension[:, 0]}
    for name, values in expected.items():
        column = data[:, names.index(name)]
        assert np.array_equal(column.view(np.uint64), values.view(np.uint64)), name
    grid = tmp_path / "grid.csv"
    args = ("--ropes", "6:10:2", "--ratios", "2:8:2", "--shapers", "none", "--settle", "5")
    assert invoke("crane", "grid", *args, "--out", str(grid))[0] == 0
    rows = [line.split(",") for line in grid.read_text().splitlines()[2:]]
    res = crane.residual_grid([6.0, 10.0], [2.0, 8.0], [None], settle=5.0)
    assert [r[1] for r in rows] == ["6", "6", "10", "10"]
    assert np.array_equal([float(r[3]) for r in rows], res.sway[0].ravel())


def test_crane_run_csv_has_the_metadata_line_of_every_pendulab_csv(tmp_path: Path) -> None:
    """A crane run's CSV starts like a trajectory's: ``# pendulab crane run; metadata (JSON): …`` (the
    file's settings, the shaper's impulses, the sway modes, units), then the names with units; NumPy
    (skiprows=2, as for a trajectory) and Sampled.from_csv (its pivot) read it; ``pendulab run`` of a
    crane scenario writes the same."""
    import json

    example = Path(__file__).resolve().parents[2] / "examples" / "cranes" / "gantry_zvd.toml"
    out = tmp_path / "run.csv"
    assert invoke("crane", "run", str(example), "--out", str(out))[0] == 0
    first, names = out.read_text().splitlines()[:2]
    assert first.startswith("# pendulab crane run; metadata (JSON): {")
    meta = json.loads(first.split("metadata (JSON): ", 1)[1])
    assert meta["file"]["crane"]["rope"] == 10.0 and meta["file"]["move"]["distance"] == 5.0
    assert meta["shaper"]["kind"] == "zvd" and meta["shaper"]["amplitudes"] == [0.25, 0.5, 0.25]
    assert meta["modes"][0] == pytest.approx(0.91, abs=1e-4) and meta["units"]["tension_rope"] == "N"
    assert names.startswith("t [s],pivot_x [m],pivot_y [m],pivot_z [m],hook_x [m]")
    data = np.loadtxt(out, delimiter=",", skiprows=2)
    columns = [name.split(" [")[0] for name in names.split(",")]
    assert data.shape[1] == len(columns) and all(
        meta["units"][c] in name for c, name in zip(columns, names.split(","), strict=True)
    )
    path = crane.Sampled.from_csv(str(out))  # the crane's pivot, after the metadata line
    t = np.linspace(0.0, 40.0, 9)
    np.testing.assert_allclose(path.position(t)[:, 0], np.interp(t, data[:, 0], data[:, 1]), atol=1e-3)
    again = tmp_path / "again.csv"
    assert invoke("run", str(example), "--out", str(again))[0] == 0
    assert again.read_text() == out.read_text()


def test_crane_csvs_say_their_output_spacing_and_tolerances(tmp_path: Path) -> None:
    """A crane run's ``[simulation] output_spacing`` (``dt`` in older files) is the spacing of the rows of
    an adaptive (DOP853) run: its metadata says ``output_spacing`` (it said ``dt``, which elsewhere is a
    step; read_metadata reads the old form as the new). The grid's metadata said neither its sampling
    interval nor its tolerances."""
    import json

    from pendulab.io import read_metadata

    example = Path(__file__).resolve().parents[2] / "examples" / "cranes" / "gantry_zvd.toml"
    out = tmp_path / "run.csv"
    assert invoke("crane", "run", str(example), "--out", str(out))[0] == 0
    meta = read_metadata(out)
    sim = meta["file"]["simulation"]
    assert sim["output_spacing"] == 0.05 and "dt" not in sim and sim["rtol"] == 1e-10
    assert meta["units"]["file.simulation.output_spacing"] == "s"
    first, rest = out.read_text(encoding="utf-8").split("\n", 1)
    old = json.loads(first.split("metadata (JSON): ", 1)[1])
    old["file"]["simulation"] = {("dt" if k == "output_spacing" else k): v for k, v in sim.items()}
    older = tmp_path / "old.csv"
    older.write_text(f"# pendulab crane run; metadata (JSON): {json.dumps(old)}\n{rest}", encoding="utf-8")
    assert read_metadata(older)["file"] == meta["file"]
    grid = tmp_path / "grid.csv"
    args = ("--ropes", "6:10:2", "--ratios", "2:8:2", "--shapers", "none", "--settle", "5")
    assert invoke("crane", "grid", *args, "--out", str(grid))[0] == 0
    settings = read_metadata(grid)["settings"]
    assert (settings["sample_spacing"], settings["rtol"], settings["atol"]) == (0.05, 1e-8, 1e-8)
    assert read_metadata(grid)["units"]["sample_spacing"] == "s"
    res = crane.residual_grid([6.0], [2.0], [None], settle=5.0)
    assert (res.output_spacing, res.rtol, res.atol) == (0.05, 1e-8, 1e-8)
