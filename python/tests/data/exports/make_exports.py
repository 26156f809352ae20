"""Writes the example exports of lab programs in this directory (README.md says where each format
comes from): the motion of known pendulums (the exact solution, ``pl.exact``) written as Tracker,
Logger Pro / Graphical Analysis, phyphox, Cassy and Excel write it, so that test_fit_exports.py can
check both the reading and, end to end, the fitted length. SI units unless a header says otherwise.

    .venv/bin/python python/tests/data/exports/make_exports.py
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

import pendulab as pl

HERE = Path(__file__).resolve().parent
G = 9.81  # [m/s²]


def _swing(length: float, theta: float, phi_dot: float, t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Positions (N, 3) [m] and velocities (N, 3) [m/s] of an ideal pendulum released at θ (rad)."""
    p = pl.Pendulum(length=length, g=G)
    x, v = pl.exact(p, p.state_from_angles(theta, 0.0, 0.0, phi_dot)).state(t)
    return x, v


def _write(name: str, text: str, *, bom: bool = False, crlf: bool = False) -> None:
    if crlf:
        text = text.replace("\n", "\r\n")
    (HERE / name).write_bytes(("\ufeff" if bom else "").encode() + text.encode("utf-8"))


def _sci(v: float) -> str:
    """phyphox' number format: 9 decimals, exponent without padding (``1.234567890E-1``)."""
    mantissa, exponent = f"{v:.9E}".split("E")
    return f"{mantissa}E{int(exponent)}"


def tracker() -> None:
    """Tracker (physlets.org/tracker), File > Export > Data, tab delimited: the track's name on the
    first line, then t, x, y of the point mass in the image plane (x across, y up), a missed mark
    left empty. Origin at the pivot, l = 0.60 m, 30 frames/s."""
    t = np.arange(90) / 30.0
    x, _ = _swing(0.60, 0.35, 0.0, t)
    lines = ["mass A", "t\tx\ty"]
    for i, ti in enumerate(t):
        cells = ("", "") if i == 17 else (f"{x[i, 0]:.4f}", f"{x[i, 2]:.4f}")
        lines.append(f"{ti:.4f}\t" + "\t".join(cells))
    _write("tracker_mass_A.txt", "\n".join(lines) + "\n")


def logger_pro_video() -> None:
    """Logger Pro 3 video analysis, File > Export As > CSV: every header cell prefixed by the data
    set's name (``Latest:``), X and Y in the image plane (Y up), velocities after them."""
    t = np.arange(75) / 25.0
    x, v = _swing(0.45, 0.30, 0.0, t)
    lines = [
        '"Latest: Time (s)","Latest: X (m)","Latest: Y (m)",'
        '"Latest: X Velocity (m/s)","Latest: Y Velocity (m/s)"'
    ]
    for i, ti in enumerate(t):
        lines.append(f"{ti:.2f},{x[i, 0]:.5f},{x[i, 2]:.5f},{v[i, 0]:.4f},{v[i, 2]:.4f}")
    _write("loggerpro_video.csv", "\n".join(lines) + "\n")


def vernier_rotary() -> None:
    """Graphical Analysis / Logger Pro text export of a Rotary Motion Sensor run: the run's name on
    its own line, then Time (s) and Angle (°), tab separated."""
    t = np.arange(100) / 50.0
    x, _ = _swing(0.80, 0.25, 0.0, t)
    angle = np.degrees(np.arctan2(x[:, 0], -x[:, 2]))
    lines = ["Run 1", "Time (s)\tAngle (°)"]
    lines += [f"{ti:.2f}\t{a:.2f}" for ti, a in zip(t, angle, strict=True)]
    _write("vernier_rotary_run1.txt", "\n".join(lines) + "\n")


def vernier_format() -> None:
    """Logger Pro 3, File > Export As > Text (Vernier Format 2, tab delimited): the format line, the
    source file and date, the data set's name, then lines of long names, short names and units, a
    blank line, the data. Video analysis: X across, Y up (the image plane)."""
    t = np.arange(60) / 20.0
    x, _ = _swing(0.65, 0.30, 0.0, t)
    lines = [
        "Vernier Format 2",
        "pendulum.cmbl 11/26/2026 16:00:00 .",
        "Latest",
        "Time\tX\tY",
        "t\tX\tY",
        "s\tm\tm",
        "",
    ]
    lines += [f"{ti:.2f}\t{x[i, 0]:.5f}\t{x[i, 2]:.5f}" for i, ti in enumerate(t)]
    _write("vernier_format2.txt", "\n".join(lines) + "\n", crlf=True)


def phyphox() -> None:
    """phyphox (phyphox.org), "Acceleration with g", export "CSV (Comma, decimal point)": quoted
    header cells with units in brackets, numbers in its 9-decimal E format, the magnitude last; and
    the gyroscope exported as "CSV (Semicolon, decimal comma)"."""
    t = np.arange(200) / 100.0
    x, v = _swing(0.70, 0.40, 0.0, t)
    # the specific force of the ideal pendulum is along the rod: |f| = T/m = (|v|² − g z)/l (T-2.3)
    mag = (np.sum(v**2, axis=1) - G * x[:, 2]) / 0.70
    along = np.array([0.08, 0.06, -1.0]) / math.sqrt(0.08**2 + 0.06**2 + 1.0)  # phone tilted on the rod
    comp = mag[:, None] * along[None, :]
    lines = [
        '"Time (s)","Acceleration x (m/s^2)","Acceleration y (m/s^2)","Acceleration z (m/s^2)",'
        '"Absolute acceleration (m/s^2)"'
    ]
    for i, ti in enumerate(t):
        lines.append(",".join(_sci(c) for c in (ti, *comp[i], mag[i])))
    _write("phyphox_acceleration.csv", "\n".join(lines) + "\n")
    omega = np.linalg.norm(np.cross(x, v), axis=1) / 0.70**2
    axis = np.array([0.0, 1.0, 0.0])
    lines = [
        '"Time (s)";"Gyroscope x (rad/s)";"Gyroscope y (rad/s)";"Gyroscope z (rad/s)";"Absolute (rad/s)"'
    ]
    for i, ti in enumerate(t):
        cells = (ti, *(omega[i] * axis), omega[i])
        lines.append(";".join(_sci(c).replace(".", ",") for c in cells))
    _write("phyphox_gyroscope_semicolon.csv", "\n".join(lines) + "\n")


def cassy() -> None:
    """CASSY Lab 2 (LD Didactic), table copied / exported as text in a German locale: ISO 80000
    headers ``quantity / unit``, tab separated, decimal commas; the angle in degrees (α)."""
    t = np.arange(100) / 40.0
    x, _ = _swing(0.55, 0.30, 0.0, t)
    angle = np.degrees(np.arctan2(x[:, 0], -x[:, 2]))
    lines = ["t / s\tα / °"]
    lines += [f"{ti:.3f}\t{a:.3f}".replace(".", ",") for ti, a in zip(t, angle, strict=True)]
    _write("cassy_angle.txt", "\n".join(lines) + "\n", crlf=True)


def excel() -> None:
    """Excel, Save As "CSV UTF-8 (Comma delimited)": a byte order mark, CRLF line ends; and Save As
    "CSV (Trennzeichen-getrennt)" in a German locale: semicolons and decimal commas."""
    t = np.arange(60) / 20.0
    x, _ = _swing(0.50, 0.30, 0.0, t)
    lines = ["t (s),x (m),z (m)"] + [f"{ti},{x[i, 0]:.6f},{x[i, 2]:.6f}" for i, ti in enumerate(t)]
    _write("excel_utf8_bom.csv", "\n".join(lines) + "\n", bom=True, crlf=True)
    lines = ["t;x;z"] + [f"{ti:.2f};{x[i, 0]:.6f};{x[i, 2]:.6f}".replace(".", ",") for i, ti in enumerate(t)]
    _write("excel_semicolon_decimal_comma.csv", "\n".join(lines) + "\n", crlf=True)


def crane() -> None:
    """A crane hook's sway logged from above (a camera or laser tracker on the trolley): x, y in the
    horizontal plane relative to the rope's suspension point, l = 25 m, an elliptical swing."""
    t = np.arange(0.0, 40.0, 0.5)
    x, _ = _swing(25.0, 0.06, 0.02, t)
    lines = ["# hook position seen from above [m], rope 25 m (make_exports.py)", "t,x,y"]
    lines += [f"{ti:.1f},{x[i, 0]:.4f},{x[i, 1]:.4f}" for i, ti in enumerate(t)]
    _write("crane_hook_xy.csv", "\n".join(lines) + "\n")


if __name__ == "__main__":
    tracker()
    logger_pro_video()
    vernier_rotary()
    vernier_format()
    phyphox()
    cassy()
    excel()
    crane()
