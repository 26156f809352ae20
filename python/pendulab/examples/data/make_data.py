#!/usr/bin/env python3
"""Makes the example data sets of ``pendulab fit`` (docs/fit.md) — synthetic measurements of known
pendulums with realistic noise, so that the fit's answer can be checked against the truth:

- ``filmed_swing.csv`` — a planar swing filmed side-on at 30 frames/s for 20 s and digitised by a
  video-analysis tool: columns t [s], x, z [m] (horizontal, vertical in the camera's frame, whose
  origin is NOT the pivot: the pivot is at (0.312, 1.250) m there), 1.5 mm noise per coordinate.
  Truth: l = 0.620 m, g = 9.81 m/s², damping c = 0.020 1/s, released from rest at 25°.
- ``phone_pendulum.csv`` — a phone hung as the bob on a 0.90 m cord, its sensor app logging at
  100 Hz for 30 s: t [s], specific_force |a − g⃗| [m/s²] (accelerometer, noise 0.03 m/s²),
  angular_speed |ω| [rad/s] (gyroscope, noise 0.005 rad/s), with 12 dropped rows (NaN).
  Truth: l = 0.90 m, g = 9.81 m/s², c = 0.030 1/s, from 35° with a little sideways speed.
- ``crane_sway.csv`` — a crane's payload sway logged at 10 Hz for 120 s: t [s], angle [rad] (the
  sway in the boom's plane, noise 0.004 rad). Truth: rope l = 12.0 m, g = 9.81 m/s² (known),
  c = 0.012 1/s, from 6° at rest.

The motions are computed by DOP853 at rtol 1e-13 (damped model, docs/theory.md T-7.1); the noise is
Gaussian from NumPy's default_rng with the seeds below. Run from the repository root:
``.venv/bin/python examples/data/make_data.py`` (writes the three files beside this script).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

import pendulab as pl

HERE = Path(__file__).resolve().parent


def _motion(length: float, damping: float, theta: float, phi_dot: float, t: np.ndarray) -> pl.Trajectory:
    p = pl.Pendulum(length=length, g=9.81, damping=damping)
    s = p.state_from_angles(theta, 0.0, 0.0, phi_dot)
    return pl.simulate(p, s, float(t[-1]), method="dop853", rtol=1e-13, atol=1e-15, save_at=t)


def _write(name: str, header: str, columns: list[np.ndarray], comment: str) -> None:
    rows = np.column_stack(columns)
    lines = [f"# {line}" for line in comment.strip().splitlines()] + [header]
    lines += [",".join("nan" if not np.isfinite(v) else f"{v:.9g}" for v in row) for row in rows]
    (HERE / name).write_text("\n".join(lines) + "\n", encoding="utf-8")


def main() -> None:
    rng = np.random.default_rng(20261125)
    t = np.arange(0.0, 20.0, 1 / 30)
    tr = _motion(0.62, 0.020, np.radians(25.0), 0.0, t)
    x = tr.x[:, 0] + 0.312 + 0.0015 * rng.standard_normal(len(t))
    z = tr.x[:, 2] + 1.250 + 0.0015 * rng.standard_normal(len(t))
    _write("filmed_swing.csv", "t,x,z", [t, x, z], "a filmed planar swing (make_data.py); SI units")

    t = np.arange(0.0, 30.0, 0.01)
    tr = _motion(0.90, 0.030, np.radians(35.0), 0.15, t)
    acc = tr.pendulum.diagnostics(tr.x, tr.v, t)["acceleration"]
    f = np.linalg.norm(acc + np.array([0.0, 0.0, 9.81]), axis=1) + 0.03 * rng.standard_normal(len(t))
    w = np.linalg.norm(np.cross(tr.x, tr.v), axis=1) / 0.90**2 + 0.005 * rng.standard_normal(len(t))
    lost = rng.choice(len(t), 12, replace=False)
    f[lost] = np.nan
    _write(
        "phone_pendulum.csv",
        "t,specific_force,angular_speed",
        [t, f, w],
        "a phone as the bob: accelerometer |a - g| [m/s^2], gyroscope |w| [rad/s] (make_data.py)",
    )

    t = np.arange(0.0, 120.0, 0.1)
    tr = _motion(12.0, 0.012, np.radians(6.0), 0.0, t)
    angle = np.arctan2(tr.x[:, 0], -tr.x[:, 2]) + 0.004 * rng.standard_normal(len(t))
    _write("crane_sway.csv", "t,angle", [t, angle], "a crane payload's sway angle [rad] (make_data.py)")


if __name__ == "__main__":
    main()
