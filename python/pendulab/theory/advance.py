"""Measuring the azimuthal advance per z-period Δφ [rad] from the samples of any trajectory
(docs/theory.md T-4.5, T-5.1), so that the exact Δφ, its dynamic + geometric split and a simulation can
be compared.

The height z oscillates with period T_z while the azimuth φ advances; between two successive
events of the same phase of the z-oscillation — two lowest points, or two upward crossings of the
mid height — φ advances by exactly Δφ. The events are located inside their sampling intervals by
cubic Hermite interpolation (values and exact derivatives from the state), and φ there likewise, so
the measurement error is O(h⁴) in the sample spacing h, well below the integrators' own error.

φ is unwrapped using the physics: φ̇ = J₃/(m ρ²) never changes sign (ρ the distance from the vertical
axis), so a sample-to-sample change of about ±π, as when the bob passes close to a pole, is resolved
in the direction of J₃ instead of by the usual nearest-branch rule.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Literal

import numpy as np

from .._core import InvalidInputError
from ..display import Row, html_table, number
from ..model import FloatArray
from ..trajectory import Trajectory

REFERENCES = ("mid", "lowest")


@dataclass(frozen=True)
class MeasuredAdvance:
    """Δφ per z-period measured from a trajectory (see :func:`measured_azimuth_advance`).

    ``times`` [s] and ``azimuths`` [rad, continuous]: the successive events (upward crossings of the
    mid height, or lowest points — highest for g < 0, the lowest in the mirrored frame);
    ``per_period`` [rad]: their differences; ``delta_phi`` [rad]: the mean advance
    (φ_last − φ_first)/(number of periods); ``period_z`` [s]: the mean time between events;
    ``reference``: which events.
    """

    times: FloatArray
    azimuths: FloatArray
    per_period: FloatArray
    delta_phi: float
    period_z: float
    reference: str

    def __repr__(self) -> str:
        return (
            f"MeasuredAdvance(Δφ = {number(self.delta_phi, 10)} rad per z-period over {len(self.per_period)} "
            f"periods, T_z = {number(self.period_z, 10)} s, {self.reference})"
        )

    def _repr_html_(self) -> str:
        rows: list[Row] = [
            ("Δφ per z-period (mean)", self.delta_phi, "rad"),
            ("z-periods measured", len(self.per_period), ""),
            ("T_z (mean)", self.period_z, "s"),
            ("events", self.reference, ""),
        ]
        return html_table("Measured azimuthal advance", rows)


def _hermite(
    y0: FloatArray, y1: FloatArray, d0: FloatArray, d1: FloatArray, h: FloatArray, s: FloatArray
) -> tuple[FloatArray, FloatArray]:
    """Cubic Hermite interpolant through (0, y0), (h, y1) with slopes d0, d1, and its slope, at s ∈ [0, h]."""
    u = s / h
    value = (2 * u**3 - 3 * u**2 + 1) * y0 + (u**3 - 2 * u**2 + u) * h * d0
    value += (-2 * u**3 + 3 * u**2) * y1 + (u**3 - u**2) * h * d1
    slope = ((6 * u**2 - 6 * u) * y0 + (-6 * u**2 + 6 * u) * y1) / h
    slope += (3 * u**2 - 4 * u + 1) * d0 + (3 * u**2 - 2 * u) * d1
    return value, slope


def _hermite_root(
    y0: FloatArray, y1: FloatArray, d0: FloatArray, d1: FloatArray, h: FloatArray
) -> FloatArray:
    """The root in [0, h] of the Hermite cubic of y (y0 < 0 ≤ y1): secant start, safeguarded Newton."""
    s = h * (-y0) / (y1 - y0)
    for _ in range(60):
        val, slope = _hermite(y0, y1, d0, d1, h, s)
        safe = np.where(slope != 0, slope, 1.0)
        s_new = np.clip(s - np.where(slope != 0, val / safe, 0.0), 0.0, h)
        done = np.all(np.abs(s_new - s) <= 1e-15 * h)
        s = s_new
        if done:
            break
    return s


def monotone_azimuth(x: FloatArray, sign: float) -> FloatArray:
    """The continuous azimuth atan2(y, x) [rad] of positions x (N, 3) for motion with sign(J₃) = ``sign``:
    a step that would go backwards by more than 1e-9 rad is taken forwards (+2π·sign) instead."""
    raw = np.arctan2(x[:, 1], x[:, 0])
    d = np.angle(np.exp(1j * np.diff(raw)))  # principal value in (−π, π]
    d = np.where(sign * d < -1e-9, d + sign * 2 * math.pi, d)
    return np.concatenate([[raw[0]], raw[0] + np.cumsum(d)])


def measured_azimuth_advance(
    traj: Trajectory, reference: Literal["mid", "lowest"] = "mid"
) -> MeasuredAdvance:
    """Δφ per z-period [rad] and the z-period [s] measured from the samples of ``traj`` (any method).

    ``reference="mid"`` (default) measures between upward crossings of the mid height
    (z_min + z_max)/2 of the samples, where φ changes gently even for orbits that pass close to a
    pole; ``"lowest"`` between lowest points (highest for g < 0), where ż turns from negative to
    positive — the apsides, but there φ̇ is largest and, near a pole, too fast to interpolate.
    Needs J₃ ≠ 0, a height that varies, samples at increasing times fine enough to resolve the
    z-oscillation, and at least two events; otherwise :class:`pendulab.InvalidInputError`.

    Examples
    --------
    >>> import numpy as np
    >>> import pendulab as pl
    >>> p = pl.Pendulum()
    >>> s0 = p.state_from_angles(theta=np.radians(60), phi_dot=2.0)
    >>> m = pl.measured_azimuth_advance(pl.simulate(p, s0, t_end=5.0, method='rattle8'))
    >>> round(m.delta_phi, 6), round(pl.exact(p, s0).azimuth_advance, 6)
    (3.831162, 3.831162)
    """
    if reference not in REFERENCES:
        raise InvalidInputError(f"reference = {reference!r}; allowed: {', '.join(map(repr, REFERENCES))}")
    p = traj.pendulum
    t, x, v = traj.t, traj.x, traj.v
    if len(t) < 3 or np.any(np.diff(t) <= 0):
        raise InvalidInputError("the trajectory needs at least 3 samples at increasing times")
    length, g = p.length, p.g
    j3 = float(np.mean(traj.j3))
    if abs(j3) <= 1e-12 * p.mass * length * max(float(np.max(np.linalg.norm(v, axis=1))), 1e-300):
        raise InvalidInputError(
            "J3 = 0: a planar orbit passes through the pole, where the azimuth jumps by pi; "
            "the azimuthal advance per z-period is defined only for J3 != 0"
        )
    mirror = -1.0 if g < 0 else 1.0
    z, w = mirror * x[:, 2], mirror * v[:, 2]  # height and its rate in the frame where gravity pulls down
    if np.ptp(z) <= 1e-12 * length:
        raise InvalidInputError(
            f"the height stays constant to {np.ptp(z):.3g} m (a conical orbit): it has no z-period "
            "to measure the advance over; use pl.exact(...).azimuth_advance"
        )
    if reference == "lowest":
        lam = (g * x[:, 2] - np.einsum("ij,ij->i", v, v)) / length**2  # T-2.2
        y, dy = w, mirror * (-g + lam * x[:, 2])
    else:
        y, dy = z - 0.5 * (z.min() + z.max()), w
    idx = np.nonzero((y[:-1] < 0) & (y[1:] >= 0))[0]
    if len(idx) < 2:
        raise InvalidInputError(
            f"found {len(idx)} event(s) ({reference} reference) between t = {t[0]:g} and {t[-1]:g} s; "
            "the trajectory must span more than one z-period"
        )
    h = t[idx + 1] - t[idx]
    s = _hermite_root(y[idx], y[idx + 1], dy[idx], dy[idx + 1], h)
    phi = monotone_azimuth(x, math.copysign(1.0, j3))
    phidot = (x[:, 0] * v[:, 1] - x[:, 1] * v[:, 0]) / (x[:, 0] ** 2 + x[:, 1] ** 2)
    phi_ev, _ = _hermite(phi[idx], phi[idx + 1], phidot[idx], phidot[idx + 1], h, s)
    t_ev = t[idx] + s
    periods = len(idx) - 1
    return MeasuredAdvance(
        times=t_ev,
        azimuths=phi_ev,
        per_period=np.diff(phi_ev),
        delta_phi=float((phi_ev[-1] - phi_ev[0]) / periods),
        period_z=float((t_ev[-1] - t_ev[0]) / periods),
        reference=reference,
    )
