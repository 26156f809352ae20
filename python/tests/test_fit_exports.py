"""Data files as lab programs export them (python/tests/data/exports/README.md says where each format
comes from): read as the data kinds of pl.fit with the values of the pendulum that made them
(make_exports.py: the exact solution, rounded as the program rounds), and fitted end to end by
``pendulab fit`` to the length that made them. Hostile and extreme files are one clear error line
(exit code 2), never a traceback; ``--sigma`` per data kind."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from test_cli import assert_user_error, invoke

import pendulab as pl
from pendulab.fitting.table import parse_table_notes, read_table, read_table_notes

EXPORTS = Path(__file__).resolve().parent / "data" / "exports"
G = 9.81


def _exact(length: float, theta: float, phi_dot: float, t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    p = pl.Pendulum(length=length, g=G)
    return pl.exact(p, p.state_from_angles(theta, 0.0, 0.0, phi_dot)).state(t)


def test_tracker_export_track_name_line_and_a_missed_mark() -> None:
    data, notes = read_table_notes(EXPORTS / "tracker_mass_A.txt")
    assert set(data) == {"t", "positions"}  # the camera's (x across, y up) are the fit's x, z
    t, xz = data["t"], data["positions"]
    assert xz.shape == (90, 2) and np.isnan(xz[17]).all()
    frames = np.arange(90) / 30.0  # 30 frames/s, written with 4 decimals
    np.testing.assert_allclose(t, frames, atol=5e-5)
    x, _ = _exact(0.60, 0.35, 0.0, frames)
    keep = np.isfinite(xz[:, 0])
    np.testing.assert_allclose(xz[keep], x[keep][:, [0, 2]], atol=6e-5)
    assert any("mass A" in n for n in notes) and any("Tracker" in n for n in notes)


def test_logger_pro_run_names_before_header_cells() -> None:
    data, notes = read_table_notes(EXPORTS / "loggerpro_video.csv")
    assert set(data) == {"t", "positions"}  # the velocity columns are not data kinds: ignored
    x, _ = _exact(0.45, 0.30, 0.0, data["t"])
    np.testing.assert_allclose(data["positions"], x[:, [0, 2]], atol=6e-6)
    assert any("Logger Pro" in n for n in notes)


def test_vernier_run_name_line_and_angle_in_degrees() -> None:
    data = read_table(EXPORTS / "vernier_rotary_run1.txt")
    x, _ = _exact(0.80, 0.25, 0.0, data["t"])
    np.testing.assert_allclose(
        data["planar_angle"], np.arctan2(x[:, 0], -x[:, 2]), atol=0.006 * math.pi / 180
    )


def test_vernier_format_names_short_names_and_units_lines() -> None:
    data, notes = read_table_notes(EXPORTS / "vernier_format2.txt")
    assert set(data) == {"t", "positions"}  # Logger Pro's video analysis: X, Y of the image plane
    x, _ = _exact(0.65, 0.30, 0.0, data["t"])
    np.testing.assert_allclose(data["t"], np.arange(60) / 20.0, atol=1e-12)
    np.testing.assert_allclose(data["positions"], x[:, [0, 2]], atol=6e-6)
    assert any("Logger Pro" in n for n in notes)


def test_phyphox_accelerometer_and_semicolon_decimal_comma_gyroscope() -> None:
    acc = read_table(EXPORTS / "phyphox_acceleration.csv")
    x, v = _exact(0.70, 0.40, 0.0, acc["t"])
    np.testing.assert_allclose(acc["specific_force"], (np.sum(v**2, axis=1) - G * x[:, 2]) / 0.70, rtol=1e-9)
    gyro, notes = read_table_notes(EXPORTS / "phyphox_gyroscope_semicolon.csv")
    assert set(gyro) == {"t", "angular_speed"} and "read decimal commas" in notes
    np.testing.assert_allclose(gyro["t"], acc["t"], rtol=1e-12)
    omega = np.linalg.norm(np.cross(x, v), axis=1) / 0.70**2
    np.testing.assert_allclose(gyro["angular_speed"], omega, rtol=1e-9, atol=1e-12)


def test_cassy_quantity_slash_unit_headers_tabs_and_decimal_commas() -> None:
    data = read_table(EXPORTS / "cassy_angle.txt")
    x, _ = _exact(0.55, 0.30, 0.0, data["t"])
    np.testing.assert_allclose(data["t"], np.arange(100) / 40.0, atol=5e-4)
    np.testing.assert_allclose(data["planar_angle"], np.arctan2(x[:, 0], -x[:, 2]), atol=6e-4 * math.pi / 180)


@pytest.mark.parametrize("name", ["excel_utf8_bom.csv", "excel_semicolon_decimal_comma.csv"])
def test_excel_byte_order_mark_crlf_and_german_locale(name: str) -> None:
    data = read_table(EXPORTS / name)
    assert set(data) == {"t", "positions"}
    x, _ = _exact(0.50, 0.30, 0.0, data["t"])
    np.testing.assert_allclose(data["positions"], x[:, [0, 2]], atol=6e-7)


def test_old_mac_line_ends() -> None:
    """Excel for Mac's "CSV (Macintosh)" ends lines with CR alone."""
    data = parse_table_notes("t,x,z\r0,0.1,-0.5\r0.1,0.2,-0.4\r")[0]
    np.testing.assert_allclose(data["positions"], [[0.1, -0.5], [0.2, -0.4]])


def test_x_y_without_z_are_horizontal_positions_not_a_rename() -> None:
    data, notes = read_table_notes(EXPORTS / "crane_hook_xy.csv")
    assert set(data) == {"t", "horizontal"}
    x, _ = _exact(25.0, 0.06, 0.02, data["t"])
    np.testing.assert_allclose(data["horizontal"], x[:, :2], atol=6e-5)
    assert any("horizontal" in n for n in notes) and not any("rename" in n for n in notes)
    again, _ = parse_table_notes("mass A\nt,x,y\n0,0.1,-0.5\n", ["t", "x", "y"])  # named: horizontal
    assert set(again) == {"t", "horizontal"}


@pytest.mark.parametrize(
    ("name", "fit", "length"),
    [
        ("tracker_mass_A.txt", "length,g", 0.60),
        ("excel_utf8_bom.csv", "length,g", 0.50),
        ("cassy_angle.txt", "length", 0.55),  # an angle alone gives g/l: g known (9.81)
        ("vernier_rotary_run1.txt", "length", 0.80),
    ],
)
def test_pendulab_fit_finds_the_length_that_made_the_export(
    name: str, fit: str, length: float, tmp_path: Path
) -> None:
    out = tmp_path / "fitted.toml"
    code, stdout, err = invoke("fit", str(EXPORTS / name), "--fit", fit, "--out", str(out))
    assert code == 0, (stdout, err)
    # the rounding of the export (4 digits of 0.2 m; 0.001°) is the only error
    assert pl.load_scenario(out).pendulum().length == pytest.approx(length, rel=2e-3)


def test_the_crane_hook_log_fits_the_rope_length(tmp_path: Path) -> None:
    """x, y seen from above give g/l through the period (g known: the length); read as x, z (the
    rename the reader once suggested) they gave l = 0.354 m for a 25 m rope. The start: the rope's
    length as the crane's operator knows it, 20 m (from the default 1 m the search stays near 0.1 m)."""
    out = tmp_path / "hook.toml"
    hook = str(EXPORTS / "crane_hook_xy.csv")
    code, stdout, err = invoke("fit", hook, "--fit", "length", "--param", "length=20", "--out", str(out))
    assert code == 0, (stdout, err)
    assert "horizontal" in err  # the note saying how x, y were taken
    assert pl.load_scenario(out).pendulum().length == pytest.approx(25.0, rel=2e-3)


def test_sigma_per_data_kind(tmp_path: Path) -> None:
    data = tmp_path / "both.csv"
    t = np.arange(300) / 50.0
    x, _ = _exact(0.8, 0.3, 0.0, t)
    angle = np.arctan2(x[:, 0], -x[:, 2])
    np.savetxt(
        data, np.column_stack([t, x[:, 0], x[:, 2], angle]), delimiter=",", header="t,x,z,angle", comments=""
    )
    code, out, err = invoke("fit", str(data), "--sigma", "positions=0.002", "--sigma", "angle=0.01")
    assert code == 0, (out, err)
    assert "0.002" in out and "0.01" in out  # the given sigmas are reported
    assert_user_error(*invoke("fit", str(data), "--sigma", "colour=1"), "KIND=VALUE", "positions")
    assert_user_error(*invoke("fit", str(data), "--sigma", "angles=1"), "no angles data")
    assert_user_error(*invoke("fit", str(data), "--sigma", "positions=-1"), "positive")
    assert_user_error(*invoke("fit", str(data), "--sigma", "1e-300"), "positive number in [1e-100, 1e100]")
    assert_user_error(*invoke("fit", str(data), "--sigma", "positions=1", "--sigma", "positions=2"), "twice")


ROWS = "".join(f"{i / 30:.4f},{0.1 * math.sin(i / 5):.5f},-0.5\n" for i in range(40))


@pytest.mark.parametrize(
    ("body", "said"),
    [
        (ROWS + "2.0,inf,-0.5\n", "row 41 (line 42), column 'x': 'inf' is infinite"),
        (ROWS + "2.0,1e400,-0.5\n", "is infinite"),
        (ROWS + "2.0,1e308,-0.5\n", "'1e308' is beyond ±1e9 m"),
        (ROWS + "2.0,5e-324,-0.5\n", "'5e-324' is subnormal"),
        (ROWS + "1e300,0.1,-0.5\n", "column 't': '1e300' is beyond ±1e12 s"),
        ("".join(f"{i}e-300,0.1,-0.5\n" for i in range(20)), "cannot be told apart"),
        (ROWS + "2.0," + "1" * 200_000 + ",-0.5\n", "is infinite"),
        (ROWS + "2.0," + "x" * 200_000 + ",-0.5\n", "line 42"),
        (ROWS + "2.0,0.1\n", "row 41 (line 42) has 2 values"),
        (ROWS + "2.0,0.1,abc\n", "column 'z': 'abc' is not a number"),
    ],
)
def test_extreme_data_files_are_one_clear_error(body: str, said: str, tmp_path: Path) -> None:
    data = tmp_path / "bad.csv"
    data.write_text("t,x,z\n" + body)
    assert_user_error(*invoke("fit", str(data)), "bad.csv", said)


def test_a_huge_header_cell_is_one_clear_error(tmp_path: Path) -> None:
    data = tmp_path / "wide.csv"
    data.write_text("t,x," + "(" * 200_000 + "\n" + ROWS)
    assert_user_error(*invoke("fit", str(data)), "characters long", "header row may have at most")


def test_a_numerical_failure_inside_the_fit_is_one_error_line(monkeypatch: pytest.MonkeyPatch) -> None:
    from pendulab.cli import fit as fit_cli

    def broken(**_: object) -> None:
        raise np.linalg.LinAlgError("SVD did not converge")

    monkeypatch.setattr(fit_cli, "fit", broken)
    code, out, err = invoke("fit", str(EXPORTS / "excel_utf8_bom.csv"))
    assert_user_error(code, out, err, "the fit failed on these data", "SVD did not converge", "--fit")
