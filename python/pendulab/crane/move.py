"""Point-to-point moves of a crane axis: acceleration- or jerk-limited profiles, shaped by convolution
(docs/cranes.md, docs/theory.md T-11.3). A profile is written as steps of its highest derivative: with
n = 2 (acceleration-limited, steps c_k of acceleration [m/s²]) or n = 3 (jerk-limited, steps c_k of
jerk [m/s³]) at times τ_k,

    s(t) = Σ_k c_k (t − τ_k)₊ⁿ / n!,   ṡ = Σ c_k (t − τ_k)₊ⁿ⁻¹/(n − 1)!,   s̈ = Σ c_k (t − τ_k)₊ⁿ⁻²/(n − 2)!

(T-11.3; x₊ = max(x, 0), x₊⁰ = H(x)), so the position, velocity and acceleration are analytic. A shaper
(A_i, t_i) turns every step into steps A_i c_k at τ_k + t_i: the shaped move is the unshaped one
convolved with the impulse train, covers the same distance and ends t_N later.

Acceleration-limited (trapezoid): t_a = v/a, cruising D/v − v/a (triangle with v = √(aD) when
D < v_max²/a_max). Jerk-limited (S-curve): speeding up to v takes T₁ = v/a + a/j if v ≥ a²/j, else
T₁ = 2√(v/j) with peak acceleration √(vj); the distance while speeding up and slowing down is v T₁, so
v = v_max if D ≥ v_max T₁(v_max), else the root of v T₁(v) = D. Units: m, s, m/s, m/s², m/s³.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from scipy.optimize import brentq

from ._checks import number, positive, real, time, times
from ._display import Row, Shown, profile_kind, profile_rows
from .shaper import FloatArray, Shaper, check_shaper


@dataclass(frozen=True, repr=False)
class Profile(Shown):
    """A scalar motion s(t) [m] (or [rad] for a slew) made of steps ``coeffs`` c_k at ``knots`` τ_k [s]
    of its ``order``-th derivative (2: acceleration, 3: jerk); see the module doc. ``start`` is s at
    t → −∞ (the axis's start value)."""

    knots: FloatArray
    coeffs: FloatArray
    order: int
    start: float = 0.0
    shaper: Shaper | None = field(default=None, compare=False)

    def _rows(self) -> list[Row]:
        return profile_rows(self)

    def _eval(self, t: Any, deriv: int, left: bool = False) -> FloatArray:
        ts = np.asarray(t, dtype=np.float64)
        d = ts[..., None] - self.knots
        n = self.order - deriv
        plus = np.where(d > 0, d, 0.0)
        step = (d > 0) if left else (d >= 0)
        basis = step.astype(float) if n == 0 else plus**n / math.factorial(n)
        out = basis @ self.coeffs
        return np.asarray(out + (self.start if deriv == 0 else 0.0), dtype=np.float64)

    def position(self, t: Any) -> FloatArray:
        """s(t) [m]."""
        return self._eval(times("t", t), 0)

    def velocity(self, t: Any) -> FloatArray:
        """ṡ(t) [m/s]."""
        return self._eval(times("t", t), 1)

    def acceleration(self, t: Any, left: bool = False) -> FloatArray:
        """s̈(t) [m/s²]: right-continuous at the steps of an acceleration-limited move (the left
        limits with ``left=True``)."""
        return self._eval(times("t", t), 2, left)

    @property
    def t_end(self) -> float:
        """The time [s] the move has stopped (its last knot)."""
        return float(self.knots.max()) if self.knots.size else 0.0

    @property
    def distance(self) -> float:
        """The distance covered [m]."""
        return float(self.position(self.t_end + 1.0) - self.start)

    def shaped(self, s: Shaper) -> Profile:
        """This profile convolved with the shaper ``s`` (T-11.3)."""
        check_shaper("s", s)
        knots = (self.knots[:, None] + s.times[None, :]).ravel()
        coeffs = (self.coeffs[:, None] * s.amplitudes[None, :]).ravel()
        order = np.argsort(knots, kind="stable")
        return Profile(knots[order], coeffs[order], self.order, self.start, s)

    def __add__(self, other: object) -> Profile:
        """Two moves of the same axis one after the other (or overlapping): their sum; both of one kind
        (acceleration-limited, or jerk-limited: ``profile(..., j_max=...)``), else a TypeError."""
        if not isinstance(other, Profile):
            return NotImplemented
        if other.order != self.order:
            kinds = f"{profile_kind(self.order)} + {profile_kind(other.order)}"
            raise TypeError(
                f"cannot add profiles of two kinds, {kinds}; "
                "allowed: two profiles of one kind (both acceleration-limited, or both jerk-limited: "
                "give both or neither j_max)"
            )
        knots = np.concatenate([self.knots, other.knots])
        coeffs = np.concatenate([self.coeffs, other.coeffs])
        order = np.argsort(knots, kind="stable")
        return Profile(knots[order], coeffs[order], self.order, self.start + other.start)


def _speed_up_time(v: float, a: float, j: float | None) -> float:
    if j is None:
        return v / a
    return v / a + a / j if v >= a * a / j else 2.0 * math.sqrt(v / j)


def profile(
    distance: float,
    v_max: float,
    a_max: float,
    j_max: float | None = None,
    shaper: Shaper | None = None,
    t_start: float = 0.0,
    start: float = 0.0,
) -> Profile:
    """The fastest rest-to-rest move over ``distance`` [m] (sign: direction) within the speed
    ``v_max`` [m/s], acceleration ``a_max`` [m/s²] and, if given, jerk ``j_max`` [m/s³] limits,
    starting at ``t_start`` [s] from ``start`` [m], convolved with ``shaper`` if given (module doc)."""
    dist = real("distance", distance, "a finite, nonzero distance in m", lambda x: x != 0.0)
    v = positive("v_max", v_max, "m/s")
    a = positive("a_max", a_max, "m/s²")
    j = None if j_max is None else positive("j_max", j_max, "m/s³")
    t0 = time("t_start", t_start)
    start = number("start", start, "m (or rad)")
    check_shaper("shaper", shaper, none_ok=True)
    d = abs(dist)
    if v * _speed_up_time(v, a, j) > d:  # never reaches v_max: v T₁(v) = D
        v = brentq(lambda u: u * _speed_up_time(u, a, j) - d, 0.0, v, xtol=1e-15 * max(v, 1.0), rtol=1e-15)
    t1 = _speed_up_time(v, a, j)
    cruise = max(d / v - t1, 0.0)
    if j is None:
        up_k, up_c = [0.0, t1], [a, -a]
    elif v >= a * a / j:
        up_k, up_c = [0.0, a / j, v / a, v / a + a / j], [j, -j, -j, j]
    else:
        up_k, up_c = [0.0, t1 / 2.0, t1], [j, -2.0 * j, j]
    down_k = [t1 + cruise + k for k in up_k]
    knots = np.array(up_k + down_k) + t0
    coeffs = math.copysign(1.0, dist) * np.array(up_c + [-c for c in up_c])
    p = Profile(knots, coeffs, 2 if j is None else 3, float(start))
    return p.shaped(shaper) if shaper is not None else p
