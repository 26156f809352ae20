"""Measured-data files as real tools write them (pendulab/fitting/table.py, columns.py): units in the
header converted to SI, sensor components combined into the magnitudes the fit uses, decimal commas,
and clear errors for pixels, a phone's linear acceleration, wrong units and missing components."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

import pendulab as pl
from pendulab.fitting.table import parse_table, read_table

EXAMPLES = Path(__file__).resolve().parents[2] / "examples" / "data"
G0 = 9.80665  # standard gravity [m/s²], the unit "g" of phone apps


def test_units_in_the_header_are_converted_to_si() -> None:
    got = parse_table("t [ms],x (cm),z (mm)\n0,10,-500\n10,11,-490\n")
    np.testing.assert_allclose(got["t"], [0.0, 0.01])
    np.testing.assert_allclose(got["positions"], [[0.10, -0.50], [0.11, -0.49]])
    got = parse_table("Time (s),theta (deg),phi (°)\n0,90,180\n1,45,0\n")
    np.testing.assert_allclose(got["angles"], [[math.pi / 2, math.pi], [math.pi / 4, 0.0]])


def test_phyphox_style_components_become_the_magnitudes() -> None:
    text = (
        '"Time (s)";"Acceleration x (m/s^2)";"Acceleration y (m/s^2)";"Acceleration z (m/s^2)";'
        '"Gyroscope x (rad/s)";"Gyroscope y (rad/s)";"Gyroscope z (rad/s)"\n'
        "0,00;3,0;4,0;0,0;0;0;2\n0,01;0;0;9,81;1;2;2\n"
    )
    got = parse_table(text)
    np.testing.assert_allclose(got["t"], [0.0, 0.01])
    np.testing.assert_allclose(got["specific_force"], [5.0, 9.81])
    np.testing.assert_allclose(got["angular_speed"], [2.0, 3.0])


def test_physics_toolbox_g_force_columns_are_in_units_of_g() -> None:
    got = parse_table("time,gFx,gFy,gFz\n0,0.6,0.8,0\n1,0,0,2\n")
    np.testing.assert_allclose(got["specific_force"], [G0, 2.0 * G0])
    got = parse_table("time,gFx,gFy,gFz,TgF\n0,0.6,0.8,0,1.0\n")  # the total wins over the components
    np.testing.assert_allclose(got["specific_force"], [G0])


def test_the_phone_example_read_from_components_fits_as_from_magnitudes(tmp_path: Path) -> None:
    data = read_table(EXAMPLES / "phone_pendulum.csv")
    rng = np.random.default_rng(3)
    f, w = data["specific_force"], data["angular_speed"]
    fu = rng.normal(size=(len(f), 3))
    fu /= np.linalg.norm(fu, axis=1)[:, None]
    wu = rng.normal(size=(len(w), 3))
    wu /= np.linalg.norm(wu, axis=1)[:, None]
    cols = np.column_stack([data["t"], f[:, None] * fu / G0, w[:, None] * wu * 180.0 / math.pi])
    path = tmp_path / "phone.csv"
    header = "t,gFx,gFy,gFz,wx (deg/s),wy (deg/s),wz (deg/s)"
    np.savetxt(path, cols, delimiter=",", header=header, comments="")
    again = read_table(path)
    np.testing.assert_allclose(again["specific_force"], f, rtol=1e-12)
    np.testing.assert_allclose(again["angular_speed"], w, rtol=1e-12)


@pytest.mark.parametrize(
    ("text", "said"),
    [
        ("t,x (px),z (px)\n0,1,2\n", "pixels"),
        ("t,Linear Acceleration x (m/s^2)\n0,1\n", "linear acceleration"),
        ("t,x (kg),z\n0,1,2\n", "'kg'"),
        ("t,ax,ay\n0,1,2\n", "all three components"),
        ("t,x,x,z\n0,1,2,3\n", "more than once"),
        ("t (furlong),x,z\n0,1,2\n", "'furlong'"),
    ],
)
def test_bad_headers_are_clear_errors(text: str, said: str) -> None:
    with pytest.raises(pl.InvalidInputError, match=said):
        parse_table(text)


def test_upside_down_video_is_an_error_naming_the_vertical_axis() -> None:
    """Image rows grow downward: x, z data with z pointing down never come below the pivot, which a
    pendulum under gravity (lower turning height u₁ < 0, start.py) cannot do."""
    p = pl.Pendulum(length=0.5, g=9.81)
    t = np.arange(0.0, 4.0, 1 / 30)
    x, _ = pl.exact(p, p.state_from_angles(0.5)).state(t)
    seen = np.column_stack([x[:, 0] + 0.3, 1.2 - x[:, 2]])
    with pytest.raises(pl.InvalidInputError, match="vertical axis point down"):
        pl.fit(t, positions=seen, pendulum=pl.Pendulum(model="damped"), fit="length,g,damping,pivot")
