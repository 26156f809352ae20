"""The commands of the exact solution: ``exact``, ``phases``, ``em-map``, ``reduced`` write their files and
print their numbers (exit 0); bad input gives one ``error: …`` line and exit code 2."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from conftest import SCENARIOS
from test_cli import assert_user_error, invoke, read_table

import pendulab as pl

ROSETTE = str(SCENARIOS / "rosette.toml")
PLANAR = str(SCENARIOS / "planar_large.toml")


@pytest.mark.parametrize("suffix", [".csv", ".nc"])
def test_exact_writes_the_states(suffix: str, tmp_path: Path) -> None:
    """exact --t 0:2:0.01 writes 201 exact states (equal to pl.exact's) and prints the kind, turning
    heights, period and Δφ."""
    out = tmp_path / f"exact{suffix}"
    code, stdout, stderr = invoke("exact", ROSETTE, "--t", "0:2:0.01", "--out", str(out))
    assert code == 0, stderr
    for needle in (
        "kind:     generic",
        "heights:",
        "period:   T_z = ",
        "dphi = ",
        f"wrote {out} (201 samples)",
    ):
        assert needle in stdout, (needle, stdout)
    cols = read_table(out)
    assert len(cols["t"]) == 201 and cols["t"][-1] == pytest.approx(2.0)
    sc = pl.load_scenario(ROSETTE)
    x, _ = pl.exact(sc.pendulum(), sc.initial_state()).state(cols["t"])
    assert np.allclose(cols["z"], x[:, 2], rtol=0, atol=1e-15)


def test_exact_negative_times_and_default_span() -> None:
    """A negative step runs backwards in time; without --t the scenario's span is used (1001 times)."""
    code, stdout, _ = invoke("exact", ROSETTE, "--t", "0:-1:-0.5")
    assert code == 0 and "t = 0 .. -1 s, 3 times" in stdout
    code, stdout, _ = invoke("exact", ROSETTE, "-q")
    assert code == 0 and stdout == ""
    code, stdout, _ = invoke("exact", ROSETTE)
    assert "t = 0 .. 100 s, 1001 times" in stdout


def test_phases_prints_the_split_and_the_measurement() -> None:
    """phases: T-4.5, its dynamic and geometric parts, their sum, the difference, and the RATTLE8 measurement
    within 1e-6 rad."""
    code, stdout, stderr = invoke("phases", ROSETTE, "--periods", "3")
    assert code == 0, stderr
    values = {}
    for line in stdout.splitlines()[1:]:
        name, _, rest = line.strip().partition(": ")
        values[name] = float(rest.split()[0])
    total = values["dphi (T-4.5)"]
    assert total == pytest.approx(3.8311623896149762, rel=1e-12)
    assert values["dphi_dyn = 2 T_z <K>/J3 (T-5.1)"] + values[
        "dphi_geom = -area/J3 (T-5.1)"
    ] == pytest.approx(total, abs=1e-10)
    assert values["dphi_dyn + dphi_geom"] == pytest.approx(total, abs=1e-10)
    assert abs(values["dphi - (dphi_dyn + dphi_geom)"]) <= 1e-10
    measured = values["measured (rattle8, dt 0.002 s, 3 periods)"]
    assert abs(measured - total) <= 1e-6 and abs(values["measured - dphi"]) <= 1e-6


def test_em_map_image_and_data(tmp_path: Path) -> None:
    """em-map writes a PNG, or the grid as .nc/.csv, and reports the monodromy ±1."""
    png = tmp_path / "em.png"
    code, stdout, stderr = invoke("em-map", "--grid", "40x30", "--out", str(png))
    assert code == 0, stderr
    assert png.stat().st_size > 10_000
    assert "changes by -1.0000" in stdout or "changes by +1.0000" in stdout
    csv = tmp_path / "em.csv"
    code, _, stderr = invoke(
        "em-map", "--grid", "20x10", "--length", "2", "--g", "3", "--mass", "0.5", "-o", str(csv)
    )
    assert code == 0, stderr
    assert len(csv.read_text().splitlines()) == 2 + 200


def test_reduced_writes_the_figure(tmp_path: Path) -> None:
    """reduced SCENARIO --out fig.png draws Holm's Figure 2 for the scenario's orbit."""
    out = tmp_path / "fig.png"
    code, stdout, stderr = invoke("reduced", ROSETTE, "--out", str(out))
    assert code == 0, stderr
    assert out.read_bytes()[:4] == b"\x89PNG" and "generic" in stdout


@pytest.mark.parametrize(
    ("args", "needles"),
    [
        (("exact", ROSETTE, "--t", "0:10"), ("--t", "START:STOP:STEP")),
        (("exact", ROSETTE, "--t", "0:10:-1"), ("STEP",)),
        (("exact", ROSETTE, "--t", "0:1:1e-9"), ("at most",)),
        (("exact", ROSETTE, "--out", "x.xlsx"), (".xlsx",)),
        (("phases", PLANAR), ("planar", "J3")),
        (("em-map", "--g", "0", "--out", "em.png"), ("g = 0",)),
        (("em-map", "--grid", "40", "--out", "em.png"), ("--grid", "400x400")),
        (("em-map", "--out", "em.xlsx"), (".xlsx",)),
        (("em-map", "--e-range", "3:1", "--out", "em.png"), ("e_range",)),
        (("reduced", ROSETTE, "--out", "fig.txt"), (".txt",)),
        (("exact", "missing.toml"), ("missing.toml",)),
    ],
)
def test_bad_input(
    args: tuple[str, ...], needles: tuple[str, ...], tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """One `error: …` line naming the bad value, exit code 2, nothing written."""
    monkeypatch.chdir(tmp_path)
    assert_user_error(*invoke(*args), *needles)
    assert list(tmp_path.iterdir()) == []
