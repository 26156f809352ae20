"""What every part of the golden-state generator (``golden_states.py``) shares: the working
precision, output times and tolerances, the units of the JSON, the small vector helpers on mpf
triples, and the scenarios' float64 initial states. Equation numbers (T-x.y) refer to
docs/theory.md; units SI (m, kg, s, rad).

Initial state: the float64 (x0, v0) that Rust's ``State::from_angles`` builds from the
scenario's angles (theta from the downward vertical), taken as exact binary numbers and
projected onto TS^2 (x <- l x/|x|, v <- v - (x.v/l^2) x) at twice the working precision,
which the values keep (rounded to 40 digits, the start would move the nearly conical
orbit's u2 - u1 by 1e-24 relative). That moves them by < 1e-15 relative (checked), below
the conditioning floor; without it no solution on TS^2 would pass through the stored floats.
Scenario files of another model than "ideal" (damped, pivot, ...) and crane scenarios are skipped:
the exact solution exists for the ideal pendulum only.
"""

from __future__ import annotations

import math
import tomllib
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from mpmath import mp, mpf

REPO = Path(__file__).resolve().parents[2]
SCENARIO_DIR = REPO / "examples" / "scenarios"
OUTPUT = REPO / "testdata" / "golden_states.json"
GENERATOR = "testdata/generate/golden_states.py"

DPS = 40  # working precision [significant digits]
HIGH_DPS = 60  # precision of the self-consistency recomputation (check 5)
STR_DIGITS = 30  # digits of the stored strings
TIMES = (1.0, 10.0, 100.0, 1000.0, 10000.0)  # output times [s]
DIFF_TIMES = (0.37, *TIMES)  # times of check 3 [s]
TOL_STATE = mpf("1e-30")  # checks 1, 2
TOL_ODE = mpf("1e-25")  # checks 3, 4
TOL_HIGH = mpf("1e-32")  # check 5
TOL_FLOOR = mpf("1e-25")  # check 5, the orbits that set the floors
TOL_PHASE = mpf("1e-25")  # check 6
ODE_DPS = 30
ODE_T_END = 2.0  # [s]
FLOOR_REL = 2.0**-53

UNITS = {
    "length": "m",
    "mass": "kg",
    "g": "m/s^2",
    "t": "s",
    "x": "m",
    "v": "m/s",
    "energy": "J",
    "j3": "kg m^2/s",
    "period_z": "s",
    "delta_phi": "rad",
    "u1, u2, u3, m": "1 (u = z/l, or -z/l when g < 0; m is the elliptic parameter k^2)",
    "eps, j": "1 (eps = E/(m |g| l), j = J3/(m l^2 w0), of the g > 0 (mirrored) problem)",
    "z1, z2": "m (lowest and highest height of the bob, physical frame)",
    "phase_dynamic, phase_geometric": "rad",
    "*_str": "the same quantity as a decimal string with string_digits significant digits",
    "floor": "1 (relative, max(|dx|/l, |dv|/max(|v|, l w0)))",
}

Vec = list[Any]  # three mpf components
State = tuple[Vec, Vec]


class GoldenError(RuntimeError):
    """A case the generator cannot solve, or a failed verification."""


# --------------------------------------------------------------------------------------
# Small vector helpers (mpf lists of length 3)


def dot(a: Sequence[Any], b: Sequence[Any]) -> Any:
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def norm(a: Sequence[Any]) -> Any:
    return mp.sqrt(dot(a, a))


def sub(a: Sequence[Any], b: Sequence[Any]) -> Vec:
    return [a[i] - b[i] for i in range(3)]


def scale(c: Any, a: Sequence[Any]) -> Vec:
    return [c * a[i] for i in range(3)]


def mirror(a: Sequence[Any]) -> Vec:
    return [a[0], a[1], -a[2]]


def to_mp(a: Sequence[float]) -> Vec:
    return [mpf(c) for c in a]


# --------------------------------------------------------------------------------------
# Scenarios and the float64 initial state


@dataclass(frozen=True)
class Scenario:
    name: str
    path: str  # relative to the repository root
    length: float
    mass: float
    g: float
    x0: tuple[float, float, float]
    v0: tuple[float, float, float]


def float_initial_state(
    length: float, theta_deg: float, phi_deg: float, theta_dot: float, phi_dot: float
) -> tuple[tuple[float, float, float], tuple[float, float, float]]:
    """Float64 (x0, v0) exactly as Rust's `State::from_angles` with `to_radians()`."""
    theta = theta_deg * (math.pi / 180.0)  # Rust f64::to_radians
    phi = phi_deg * (math.pi / 180.0)
    st, ct = math.sin(theta), math.cos(theta)
    sp, cp = math.sin(phi), math.cos(phi)
    ell, thd, phd = length, theta_dot, phi_dot
    x = (ell * st * cp, ell * st * sp, -ell * ct)
    v = (
        ell * (thd * ct * cp - phd * st * sp),
        ell * (thd * ct * sp + phd * st * cp),
        ell * thd * st,
    )
    return x, v


def load_scenarios(directory: Path = SCENARIO_DIR) -> list[Scenario]:
    files = sorted(directory.glob("*.toml"))
    if not files:
        raise GoldenError(f"no scenario files in {directory}")
    out = []
    for f in files:
        with f.open("rb") as fh:
            doc = tomllib.load(fh)
        if "crane" in doc:
            continue  # a crane scenario (docs/cranes.md) describes no pendulum of its own
        try:
            pend, init = doc["pendulum"], doc["initial"]
            model = pend.get("model", "ideal")
            if model != "ideal":
                continue  # the exact solution exists for the ideal pendulum only (damped, pivot, ...)
            length, mass, g = (
                float(pend["length"]),
                float(pend["mass"]),
                float(pend["g"]),
            )
            angles = [float(init[k]) for k in ("theta_deg", "phi_deg", "theta_dot", "phi_dot")]
        except KeyError as e:
            raise GoldenError(f"{f.name}: missing key {e}") from e
        x0, v0 = float_initial_state(length, *angles)
        rel = f.relative_to(REPO).as_posix()
        out.append(Scenario(f.stem, rel, length, mass, g, x0, v0))
    return out


def project(length: Any, x: Sequence[Any], v: Sequence[Any]) -> State:
    """Projection onto TS^2 (working precision): x <- l x/|x|, v <- v - (x.v/l^2) x."""
    xp = scale(length / norm(x), x)
    vp = sub(v, scale(dot(xp, v) / length**2, xp))
    return xp, vp
