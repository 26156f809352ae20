"""Measured data for :func:`pendulab.fit`: what a real pendulum gives and how the model predicts it.

Kinds (docs/fit.md; equation numbers of docs/theory.md):

================== ============ =================================================================
``positions``      m            the bob relative to the pivot, (N, 3) x, y, z; or (N, 2) from a
                                camera looking along y: (horizontal x, vertical z). With an
                                unknown pivot (``pivot_x``, ``pivot_y``, ``pivot_z`` fitted) the
                                positions may be in any frame parallel to ours.
``angles``         rad          (θ, φ): polar angle from the downward vertical and azimuth; the
                                residual is (Δθ, sin θ · Δφ) with Δφ wrapped to (−π, π], so that
                                φ's meaninglessness at the bottom costs nothing.
``horizontal``     m            the bob's horizontal position (x, y) (N, 2), seen from above (a crane
                                hook's sway log, a camera under the ceiling); with ``pivot_x``,
                                ``pivot_y`` fitted, in any frame parallel to ours.
``planar_angle``   rad          the signed angle of a swing in the x–z plane, atan2(x, −z).
``specific_force`` m/s²         |ẍ − g⃗|: what an accelerometer riding on the bob reads, the rod's
                                pull per mass T/m for the ideal pendulum (T-2.3) — frame-free.
``angular_speed``  rad/s        |ω| = |x × v| / l²: what a gyroscope on the rod reads — frame-free.
================== ============ =================================================================

Times t [s] may be uneven and have gaps. Rows with NaN anywhere are dropped and counted; times must be
distinct; unsorted rows are sorted (with a warning). Values beyond |v| = 1e12 (SI units), a record
longer than 1e9 s or shorter than 1e-6 s, and samples closer than 1e-12 of the record's span are
refused with the row named: no measurement is like that, and the fit's arithmetic would overflow or
underflow on them.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np

from .._core import InvalidInputError
from .._numbers import shown
from .._warn import warn_user
from ..model import FloatArray
from .keyed import KeyedInputError

KINDS: dict[str, str] = {
    "positions": "m",
    "horizontal": "m",
    "angles": "rad",
    "planar_angle": "rad",
    "specific_force": "m/s^2",
    "angular_speed": "rad/s",
}
"""Data kind → unit of its values (and of its ``sigma``)."""

MIN_SAMPLES = 8
MAX_SAMPLES = 10_000_000
MAX_VALUE = 1e12
"""Largest |value| of any data kind in SI units (m, rad, m/s², rad/s) and of any time [s]."""
SPAN = (1e-6, 1e9)
"""Shortest and longest record [s]."""
MIN_SPACING = 1e-12
"""Smallest spacing of two samples, as a fraction of the record's span."""
MIN_SIGMA = 1e-15
"""Smallest noise ``sigma`` of one value (its kind's SI unit): below the float64 resolution of a
metre-sized value, and a residual of up to :data:`MAX_VALUE` over a smaller one would overflow χ²
(``sigma = 1e-300`` ended in a ValueError from the solver, "array must not contain infs or NaNs")."""


def _show(value: Any) -> str:
    """``value`` in a message, at most 80 characters; a number or a list of numbers as the user writes
    them (:func:`pendulab._numbers.shown`: ``[1e308, -0.5]``, not ``[1e+308, -0.5]``)."""
    if isinstance(value, float):
        text = shown(value)
    elif isinstance(value, list) and all(isinstance(v, float) for v in value):
        text = "[" + ", ".join(map(shown, value)) + "]"
    else:
        text = repr(value)
    return text if len(text) <= 80 else text[:77] + "..."


@dataclass(frozen=True)
class Observations:
    """Cleaned data: times ``t`` [s] (sorted, distinct), and per kind its values (N, k) in SI units
    with the noise ``sigma`` (one value per kind, same unit; None: estimated from the residual)."""

    t: FloatArray
    values: dict[str, FloatArray]
    sigma: dict[str, float | None]
    dropped: int
    columns: dict[str, int]

    def __len__(self) -> int:
        return int(self.t.shape[0])

    @property
    def n_residuals(self) -> int:
        return int(sum(v.size for v in self.values.values()))


def _as_array(name: str, value: Any, n: int) -> FloatArray:
    if np.iscomplexobj(value):
        raise InvalidInputError(f"{name} must be real numbers, got complex values")
    try:
        a = np.asarray(value, dtype=np.float64)
    except (TypeError, ValueError) as e:
        raise InvalidInputError(f"{name} must be numbers (an array), got {_show(value)}") from e
    if name == "angles":
        if a.ndim == 2 and a.shape[0] == 2 and a.shape[1] == n and n != 2:
            a = a.T  # (theta, phi) given as two rows
        if a.ndim != 2 or a.shape[1] != 2:
            raise InvalidInputError(
                f"angles must be (theta, phi): two arrays of N values [rad], got shape {a.shape}"
            )
    elif name == "horizontal":
        if a.ndim != 2 or a.shape[1] != 2:
            raise InvalidInputError(
                f"horizontal must have shape (N, 2) [m] (x, y seen from above), got {a.shape}"
            )
    elif name == "positions":
        if a.ndim != 2 or a.shape[1] not in (2, 3):
            raise InvalidInputError(
                f"positions must have shape (N, 3) [m] (x, y, z) or (N, 2) (x, z seen along y), got {a.shape}"
            )
    else:
        if a.ndim != 1:
            raise InvalidInputError(f"{name} must be one value per time (N,), got shape {a.shape}")
        a = a[:, None]
    if a.shape[0] != n:
        raise InvalidInputError(f"{name} has {a.shape[0]} rows but t has {n} times: give one row per time")
    return a


def _sigma(kind: str, sigma: Any) -> float | None:
    value = sigma.get(kind) if isinstance(sigma, Mapping) else sigma
    if value is None:
        return None
    if isinstance(value, bool) or not isinstance(value, int | float | np.floating | np.integer):
        raise InvalidInputError(
            f"sigma for {kind} must be a positive number [{KINDS[kind]}], got {_show(value)}"
        )
    s = float(value)
    if not (math.isfinite(s) and s > 0.0):
        raise InvalidInputError(
            f"sigma = {s!r} for {kind} must be a positive finite number [{KINDS[kind]}] "
            "(the noise of one value)"
        )
    if s < MIN_SIGMA:
        raise InvalidInputError(
            f"sigma = {s!r} {KINDS[kind]} for {kind} is below {shown(MIN_SIGMA)} {KINDS[kind]}, finer than "
            "any measurement and than float64 resolves: give the noise of one value in SI units"
        )
    return s


def observations(t: Any, data: Mapping[str, Any], sigma: Any = None) -> Observations:
    """Checks and cleans the data (see the module doc). ``data``: kind → values; ``sigma``: one number
    for every kind, or kind → number, or None (estimated from the residual)."""
    given = {k: v for k, v in data.items() if v is not None}
    if not given:
        raise InvalidInputError(f"give some data: one or more of {', '.join(KINDS)}")
    for kind in given:
        if kind not in KINDS:
            raise InvalidInputError(f"unknown data kind {kind!r}; use {', '.join(KINDS)}")
    if isinstance(sigma, Mapping):
        for kind in sigma:
            if kind not in given:
                raise InvalidInputError(f"sigma given for {kind!r}, but there are no {kind} data")
    if np.iscomplexobj(t):
        raise InvalidInputError("t must be real times [s], got complex values")
    try:
        times = np.asarray(t, dtype=np.float64)
    except (TypeError, ValueError) as e:
        raise InvalidInputError(f"t must be an array of times [s], got {_show(t)}") from e
    if times.ndim != 1:
        raise InvalidInputError(f"t must be a 1-D array of times [s], got shape {times.shape}")
    n = times.shape[0]
    if n > MAX_SAMPLES:
        raise InvalidInputError(f"{n} samples: at most {MAX_SAMPLES} are fitted at once; thin the data")
    arrays = {k: _as_array(k, v, n) for k, v in given.items()}
    good = np.isfinite(times)
    for a in arrays.values():
        good &= np.all(np.isfinite(a), axis=1)
    dropped = int(n - np.count_nonzero(good))
    if dropped:
        warn_user(f"dropped {dropped} of {n} rows with NaN or inf (in t or the data)", UserWarning)
    times = times[good]
    arrays = {k: a[good] for k, a in arrays.items()}
    if len(times) < MIN_SAMPLES:
        raise KeyedInputError(
            f"only {len(times)} usable samples: a fit needs at least {MIN_SAMPLES}",
            "data_too_few",
            have=len(times),
            need=MIN_SAMPLES,
        )
    order = np.argsort(times, kind="stable")
    if np.any(order != np.arange(len(times))):
        warn_user("the times were not in increasing order: the rows were sorted", UserWarning)
        times = times[order]
        arrays = {k: a[order] for k, a in arrays.items()}
    same = np.flatnonzero(np.diff(times) == 0.0)
    if same.size:
        raise KeyedInputError(
            f"the time t = {float(times[same[0]])!r} s appears twice ({same.size} repeated time(s) in all): "
            "every sample needs its own time",
            "data_time_twice",
            t=repr(float(times[same[0]])),
        )
    if "angles" in arrays:
        theta = arrays["angles"][:, 0]
        # noise may push θ a little below 0 near the bottom; values far outside [0, π] are degrees
        if np.any(theta < -0.5) or np.any(theta > math.pi + 0.5):
            raise KeyedInputError(
                "angles: θ must lie in [0, π] rad (the polar angle from the downward vertical); "
                f"got values from {shown(theta.min(), 6)} to {shown(theta.max(), 6)} — degrees? use "
                "np.radians",
                "data_theta_range",
                lo=shown(theta.min(), 6),
                hi=shown(theta.max(), 6),
            )
    _check_ranges(times, arrays)
    sig = {k: _sigma(k, sigma) for k in arrays}
    columns = {k: int(a.shape[1]) for k, a in arrays.items()}
    return Observations(np.ascontiguousarray(times), arrays, sig, dropped, columns)


def _check_ranges(times: FloatArray, arrays: Mapping[str, FloatArray]) -> None:
    """The limits of the module doc, each violation named with its row."""
    for kind, a in [("t", times[:, None]), *arrays.items()]:
        big = np.flatnonzero(np.any(np.abs(a) > MAX_VALUE, axis=1))
        if big.size:
            i = int(big[0])
            raise KeyedInputError(
                f"{kind} in sorted row {i}: {_show(a[i].tolist())} is beyond ±{shown(MAX_VALUE)} (SI units); "
                "a measurement of a pendulum never is — check the file's units and columns",
                "data_value_beyond",
                kind=kind,
                row=i,
                value=_show(a[i].tolist()),
                limit=shown(MAX_VALUE),
            )
    span = float(times[-1] - times[0])
    if not SPAN[0] <= span <= SPAN[1]:
        raise KeyedInputError(
            f"the record spans {shown(span, 6)} s; a fit needs {shown(SPAN[0])} s to {shown(SPAN[1])} s "
            "(times in s?)",
            "data_span",
            span=shown(span, 6),
            least=shown(SPAN[0]),
            most=shown(SPAN[1]),
        )
    gap = np.diff(times)
    close = np.flatnonzero(gap < MIN_SPACING * span)
    if close.size:
        i = int(close[0])
        raise KeyedInputError(
            f"the times {shown(times[i])} s and {shown(times[i + 1])} s are {shown(gap[i], 3)} s apart, "
            "less than "
            f"{shown(MIN_SPACING)} of the record's span {shown(span, 6)} s: round-off, not a measurement",
            "data_spacing",
            t1=shown(times[i]),
            t2=shown(times[i + 1]),
            gap=shown(gap[i], 3),
        )


def wrap(angle: FloatArray) -> FloatArray:
    """An angle difference wrapped to (−π, π] [rad]."""
    return np.asarray(np.pi - np.mod(np.pi - angle, 2.0 * np.pi))


def predict(
    kind: str,
    columns: int,
    x: FloatArray,
    v: FloatArray,
    acceleration: FloatArray | None,
    gravity: FloatArray,
    pivot: FloatArray,
) -> FloatArray:
    """What the data of ``kind`` would read for the model's x [m], v [m/s] (N, 3), its acceleration
    ẍ [m/s²] (needed for specific_force), the gravity vector g⃗ [m/s²] and the pivot offset [m]."""
    if kind == "positions":
        p = x + pivot
        return p if columns == 3 else p[:, [0, 2]]
    if kind == "horizontal":
        return (x + pivot)[:, :2]
    if kind == "angles":
        rho = np.hypot(x[:, 0], x[:, 1])
        return np.column_stack([np.arctan2(rho, -x[:, 2]), np.arctan2(x[:, 1], x[:, 0])])
    if kind == "planar_angle":
        return np.arctan2(x[:, 0], -x[:, 2])[:, None]
    if kind == "specific_force":
        assert acceleration is not None
        # (N,): numpy's stubs type a norm along an axis as Any (a scalar or an array, by the shape)
        force: FloatArray = np.linalg.norm(acceleration - gravity, axis=1)
        return force[:, None]
    if kind == "angular_speed":
        ell2: FloatArray = np.einsum("ij,ij->i", x, x)  # |x|² (N,), Any in numpy's stubs
        h: FloatArray = np.linalg.norm(np.cross(x, v), axis=1)  # |x × v| (N,), Any in numpy's stubs
        return (h / ell2)[:, None]
    raise AssertionError(kind)


def residual(kind: str, measured: FloatArray, predicted: FloatArray) -> FloatArray:
    """measured − predicted, per value, in the data's unit (angles: (Δθ, sin θ · Δφ) wrapped)."""
    if kind == "angles":
        d_theta = measured[:, 0] - predicted[:, 0]
        d_phi = wrap(measured[:, 1] - predicted[:, 1]) * np.sin(predicted[:, 0])
        return np.column_stack([d_theta, d_phi])
    if kind == "planar_angle":
        return wrap(measured - predicted)
    return measured - predicted
