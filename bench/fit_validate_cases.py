"""The cases of ``bench/fit_validate.py``: data from the independent integrator
(``testdata/generate/independent_pendulum.py``, SciPy DOP853 of a hand-written Cartesian model — no
Pendulab code), fitted with ``pl.fit`` as a user calls it: ``sigma`` left out, the documented default
starting pendulum, the default loss unless the case says otherwise.

Three sorts of case (docs/fit.md, "Validation"):

- ``right``: the model fitted is the one that made the data (white or AR(1) noise, quantisation,
  outliers with a robust loss, mid-swing starts, elliptical swings seen from the side, a pivot off the
  origin; cases 22–24: the sensor's offset, bias or scale fitted as a systematic term; 25: dry
  friction fitted; 26: a swing that starts on the negative side; 27: a swing released in the x–z
  plane, fitted as a spherical one; 28: case 1 with the start's truth; 29, 30: a turntable's rotating
  frame and a slewing boom's pivot, x, z seen from the side: fit_validate_frames.py). Measured: how
  often each true parameter lies within ±2 stderr (target 90–98 %) and how often a warning is raised
  anyway (false alarms).
- ``wrong``: the data contain physics or sensor effects the fitted model lacks (wind, dry pivot
  friction, a wrong damping law, an accelerometer bias, an encoder zero offset, a camera scale error
  with g fixed, outliers with the plain loss). Measured: how often the fit warns (target ≥ 95 %).
  ``detectability``: the rms of the noise-free misfit over the noise σ, from one noise-free fit — a
  mismatch far below the noise cannot be detected by any fit and is not counted against it.
- ``degenerate``: constant positions, a bob at rest, pure noise as a planar angle, a fraction of a
  swing. Required: a clear ``InvalidInputError`` or a warning or a parameter reported not determined,
  or (when a truth exists) the truth within 3 stderr — within the time limit; never another
  exception, a hang, or a confident wrong value.

Units: SI (m, s, rad, m/s²); the ``units`` case fits the same swing in m and in mm. The data makers
(video, encoder, phone, ...) are in ``bench/fit_validate_data.py``.
"""

from __future__ import annotations

import sys
from pathlib import Path
from typing import Any

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "testdata" / "generate"))
import independent_pendulum as ip
from fit_validate_data import Case, also, angles, constant, encoder, phone, pure_noise, video
from fit_validate_frames import slewing, turning

VIDEO = ip.Truth(length=0.6, g=9.81, damping=0.010)
VIDEO_FIT = ["length", "g", "damping", "pivot"]
DAMPED: dict[str, Any] = {"model": "damped"}


def cases() -> list[Case]:
    """All cases, in the order of the report."""
    enc_truth = ip.Truth(length=0.5, g=9.81, damping=0.02, drag=0.05)
    phone_truth = ip.Truth(length=0.9, g=9.81, damping=0.03)
    coulomb = ip.Truth(length=0.55, g=9.80, damping=0.004, coulomb=0.012, coulomb_speed=2e-3)
    return [
        # --- the model is right ---------------------------------------------------------------
        Case(
            "video x,z, ellipse, mid-swing, pivot off origin",
            "right",
            VIDEO_FIT,
            DAMPED,
            video(VIDEO),
            "issue 23: l 0.6 m, c 0.010 1/s, φ̇ 0.8 rad/s at release, filmed from 1.3 s, 30 fps, σ 1.5 mm",
        ),
        Case(
            "3-D positions, ellipse, mid-swing, pivot off origin",
            "right",
            VIDEO_FIT,
            DAMPED,
            video(
                ip.Truth(length=0.8, damping=0.02),
                start=(0.4, 0.3, 0.2, 1.0),
                t_from=0.9,
                duration=12.0,
                fps=25.0,
                pivot=(0.1, -0.2, 0.9),
                sigma=1e-3,
                columns=(0, 1, 2),
            ),
            "motion capture, 25 fps, σ 1 mm",
        ),
        Case(
            "encoder, viscous + quadratic drag (l known)",
            "right",
            ["g", "damping", "drag"],
            {"model": "damped", "length": 0.5},
            encoder(enc_truth, amplitude=1.2, t_from=0.37, duration=15.0, rate=50.0, sigma=2e-3),
            "planar, 50 Hz, 15 s, white σ 2 mrad then 2400 steps/turn",
        ),
        Case(
            "phone (specific force, angular speed), ellipse, mid-swing",
            "right",
            ["length", "g", "damping"],
            DAMPED,
            phone(phone_truth),
            "100 Hz, 15 s, σ 0.03 m/s² and 0.005 rad/s",
        ),
        Case(
            "angles (theta, phi), ideal, l known",
            "right",
            ["g"],
            {"length": 1.0},
            angles(ip.Truth(length=1.0)),
            "20 Hz, 20 s, σ 2 mrad",
        ),
        Case(
            "video x,z, damping + drag both fitted",
            "right",
            [*VIDEO_FIT, "drag"],
            DAMPED,
            video(ip.Truth(length=0.6, damping=0.01, drag=0.08), start=(0.8, 0.0, 0.0, 0.5)),
            "issue 23: damping + drag on drag data gave LinAlgError",
        ),
        Case(
            "video x,z, 10 % outliers, loss=soft_l1",
            "right",
            VIDEO_FIT,
            DAMPED,
            video(VIDEO, outliers=0.1),
            "outliers ±(10…30) σ in 10 % of frames; robust loss, σ left out",
            loss="soft_l1",
        ),
        Case(
            "video x,z, AR(1) noise rho 0.8",
            "right",
            VIDEO_FIT,
            DAMPED,
            video(VIDEO, rho=0.8),
            "correlated noise: error bars must account for it (or a warning)",
        ),
        # --- the model is wrong ---------------------------------------------------------------
        Case(
            "video x,z, steady wind 0.4 m/s^2",
            "wrong",
            VIDEO_FIT,
            DAMPED,
            video(ip.Truth(length=0.6, damping=0.01, wind=(0.4, 0.0, 0.0))),
            "a tilted equilibrium (2.3°)",
        ),
        Case(
            "video x,z, quadratic drag fitted as viscous",
            "wrong",
            VIDEO_FIT,
            DAMPED,
            video(ip.Truth(length=0.6, drag=0.3), start=(0.9, 0.0, 0.0, 0.3)),
            "the wrong damping law",
        ),
        Case(
            "encoder, dry pivot friction (90 deg release)",
            "wrong",
            ["length", "damping", "drag"],
            {"model": "damped", "g": 9.80, "damping": 0.01},
            encoder(coulomb, amplitude=1.5, t_from=0.4, duration=30.0, rate=50.0, sigma=3e-4),
            "issue 24: Coulomb μ 0.012 m/s² + c 0.004 1/s, 2400 steps/turn",
        ),
        Case(
            "encoder, zero offset 0.03 rad",
            "wrong",
            ["g", "damping"],
            {"model": "damped", "length": 0.5},
            encoder(enc_truth, amplitude=0.6, t_from=0.2, duration=20.0, rate=50.0, sigma=2e-3, offset=0.03),
            "the encoder's zero is not the vertical",
        ),
        Case(
            "phone, accelerometer bias 0.05 m/s^2",
            "wrong",
            ["length", "g", "damping"],
            DAMPED,
            phone(phone_truth, bias=0.05),
            "issue 23: g 150 stderr off, no word",
        ),
        Case(
            "video x,z, scale error 5 %, g fixed",
            "wrong",
            ["length", "damping", "pivot"],
            {"model": "damped", "g": 9.81},
            video(VIDEO, scale=1.05),
            "a wrong ruler in the video",
        ),
        Case(
            "video x,z, 10 % outliers, plain loss",
            "wrong",
            VIDEO_FIT,
            DAMPED,
            video(VIDEO, outliers=0.1),
            "outliers with the default loss: must say so",
        ),
        # --- degenerate data --------------------------------------------------------------------
        Case(
            "constant positions + noise",
            "degenerate",
            ["length", "g"],
            {},
            constant((0.0, 0.0, -1.0), 1e-3),
            "issue 23: LinAlgError after 91 s",
            key=["length", "g"],
        ),
        Case(
            "constant positions, no noise",
            "degenerate",
            ["length", "g"],
            {},
            constant((0.0, 0.0, -1.0), 0.0),
            "issue 23: l = start ± 2.6e-17 'determined'",
            key=["length", "g"],
        ),
        Case(
            "bob at rest, video x,z, pivot unknown",
            "degenerate",
            VIDEO_FIT,
            DAMPED,
            constant((0.31, 1.25 - 0.6), 1.5e-3),
            "issue 23: g = 467 ± 8.5",
            key=["length", "g"],
        ),
        Case(
            "pure noise as planar angle",
            "degenerate",
            ["g", "damping"],
            {"model": "damped", "length": 0.5},
            pure_noise(),
            "issue 23: g = 369 ± 3.5",
            key=["g"],
        ),
        Case(
            "a third of a swing",
            "degenerate",
            VIDEO_FIT,
            DAMPED,
            video(VIDEO, t_from=0.0, duration=0.5, start_truth=True),
            "too few swings: honest bars or not determined (the start's too)",
            key=["length", "g"],
        ),
        # --- units ------------------------------------------------------------------------------
        Case(
            "units: same swing in m and in mm",
            "units",
            VIDEO_FIT,
            DAMPED,
            video(VIDEO),
            "the fit must not depend on the unit of the numbers",
        ),
        # --- the systematic terms fitted (the model is right again) -----------------------------
        Case(
            "encoder, zero offset 0.03 rad, angle_offset fitted",
            "right",
            ["g", "damping", "drag", "angle_offset"],
            {"model": "damped", "length": 0.5},
            also(
                encoder(
                    enc_truth, amplitude=0.6, t_from=0.2, duration=20.0, rate=50.0, sigma=2e-3, offset=0.03
                ),
                angle_offset=0.03,
            ),
            "case 12 with the encoder's zero fitted",
        ),
        Case(
            "phone, accelerometer bias, force_bias fitted",
            "right",
            ["length", "g", "damping", "force_bias"],
            DAMPED,
            also(phone(phone_truth, bias=0.05), force_bias=0.05),
            "case 13 with the bias fitted",
        ),
        Case(
            "video x,z, scale error 5 %, g fixed, scale fitted",
            "right",
            ["length", "damping", "pivot", "scale"],
            {"model": "damped", "g": 9.81},
            also(video(VIDEO, scale=1.05), scale=1.05),
            "case 14 with the scale bar fitted (g known)",
        ),
        Case(
            "encoder, dry pivot friction fitted (friction)",
            "right",
            ["length", "damping", "friction"],
            {
                "model": "damped",
                "g": 9.80,
                "damping": 0.01,
                "friction_speed": coulomb.coulomb_speed / coulomb.length,  # ω_ε = v_ε/l (T-7.6)
            },
            also(
                encoder(coulomb, amplitude=1.5, t_from=0.4, duration=30.0, rate=50.0, sigma=3e-4),
                friction=coulomb.coulomb / coulomb.length,  # ε_f = μ/l [rad/s²]
            ),
            "case 11 with the damped model's dry friction fitted",
        ),
        Case(
            "encoder, viscous + drag, released on the negative side",
            "right",
            ["g", "damping", "drag"],
            {"model": "damped", "length": 0.5},
            encoder(enc_truth, amplitude=-1.2, t_from=0.1, duration=15.0, rate=50.0, sigma=2e-3),
            "case 3 mirrored: the first sample at a negative angle",
        ),
        Case(
            "video x,z, a planar swing fitted as a spherical one",
            "right",
            VIDEO_FIT,
            DAMPED,
            video(VIDEO, start=(0.5, 0.0, 0.0, 0.0), start_truth=True),
            "case 1 released in the x–z plane (φ₀ = φ̇₀ = 0), planar=False: the sideways motion seen at "
            "second order",
        ),
        Case(
            "video x,z, ellipse, the start's truth",
            "right",
            VIDEO_FIT,
            DAMPED,
            video(VIDEO, start_truth=True),
            "case 1 with the start at the first sample in the truth: φ̇₀ clearly nonzero",
        ),
        # --- a rotating frame and a slewing pivot, filmed as x, z (fit_validate_frames.py) -------
        Case(
            "turntable x,z, Omega 0.4 rad/s at latitude 0.9, damped",
            "right",
            VIDEO_FIT,
            {"model": "rotating", "frame_rate": 0.4, "latitude": 0.9},
            turning(),
            "Ω_z = 0.31 rad/s: Coriolis shows the sideways motion at first order (not mirror-blind)",
        ),
        Case(
            "slewing boom x,z, R 0.3 m, omega 0.5 rad/s",
            "right",
            ["length", "g", "pivot"],
            {"model": "slewing", "radius": 0.3, "rate": 0.5, "height": 0.0},
            slewing(),
            "the pivot moves along y: the camera sees p(t) + x, p from the record's first frame",
        ),
    ]


#: How each fitted name scales when positions are given in mm instead of m.
MM_SCALE = {
    "length": 1e3,
    "g": 1e3,
    "damping": 1.0,
    "drag": 1e-3,
    "pivot_x": 1e3,
    "pivot_y": 1e3,
    "pivot_z": 1e3,
}
