"""What a movie shows: one or many bobs, their positions x [m] and velocities v [m/s] at any time.

A :class:`Motion` is a function from times to states plus what the panels need to draw them: the
sphere's radius (the rod length l [m]), gravity g [m/s²], the mass m [kg] and the time span of the
data. Three sources:

- :func:`from_function` — a function giving the states at any times, used for the exact solution
  (``ExactSolution.state``): every frame is exact (docs/theory.md T-4.2 … T-4.4), nothing is integrated.
- :func:`from_samples` — saved samples of a trajectory or an ensemble, between which the states
  are the cubic Hermite interpolant of (x, v): on [t_i, t_i + h], with s = (t − t_i)/h,

      x(t) = h₀₀(s) x_i + h h₁₀(s) v_i + h₀₁(s) x_{i+1} + h h₁₁(s) v_{i+1},
      h₀₀ = 2s³ − 3s² + 1, h₁₀ = s³ − 2s² + s, h₀₁ = −2s³ + 3s², h₁₁ = s³ − s²,

  whose error is O(h⁴) (the velocity: the derivative of the same cubic, O(h³)). A frame between
  samples is therefore as accurate as the samples allow, not a straight-line blend.

The states come as arrays of shape (n_times, n_bobs, 3). Bobs whose samples are not finite (the
invalid start rows of an ensemble) stay NaN and are not drawn.

A moving pivot (models ``slewing``, ``vibrating``, ``sampled_pivot``) is given as its positions
p(t_i) [m] at the samples; between them p(t) is the same cubic Hermite interpolant, with the
velocities ṗ(t_i) estimated by second-order finite differences (:func:`numpy.gradient`; error
O(h³)). The bob is then at p(t) + x(t) in the inertial frame; the 3-D panel draws the rod from p(t)
and the pivot's path. A swinging spring (``spring=True``) is drawn with a coil whose length |x|
varies instead of a rod.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from .._core import InvalidInputError
from ..model import FloatArray

StateFunction = Callable[[FloatArray], tuple[FloatArray, FloatArray]]
"""times (n,) [s] → (x, v), each (n, n_bobs, 3) [m], [m/s]."""

PivotFunction = Callable[[FloatArray], FloatArray]
"""times (n,) [s] → the pivot's position p (n, 3) [m] in the inertial frame."""


@dataclass(frozen=True)
class Motion:
    """Bobs to draw: ``states(times)`` gives x [m] and v [m/s] of shape (n, bobs, 3).

    ``length`` [m] is the radius of the sphere drawn (the rod length; the largest for an ensemble),
    ``g`` [m/s²] and ``mass`` [kg] enter the energy panels, ``span`` [s] is the time range with data
    (``None`` at either end: unbounded, as for the exact solution), ``label`` names the source in the
    movie ("exact", "rattle", …). ``pivot`` gives a moving pivot's position p(t) [m] (``None``: fixed
    at the origin), and x is relative to it; ``spring``: draw a coil of varying length, not a rod."""

    states: StateFunction
    bobs: int
    length: float
    g: float
    mass: float
    span: tuple[float, float]
    label: str
    pivot: PivotFunction | None = None
    spring: bool = False

    @property
    def small_period(self) -> float:
        """2π √(l/|g|) [s], the small-oscillation period (2π s when g = 0): the time scale of trails."""
        return 2.0 * math.pi * math.sqrt(self.length / abs(self.g)) if self.g != 0.0 else 2.0 * math.pi


def from_function(
    states: StateFunction, *, length: float, g: float, mass: float, span: tuple[float, float], label: str
) -> Motion:
    """A motion given by a function of time (one bob unless it returns more)."""
    probe_x, _ = states(np.array([span[0]]))
    return Motion(states, int(probe_x.shape[1]), float(length), float(g), float(mass), span, label)


def hermite(t: FloatArray, x: FloatArray, v: FloatArray, times: FloatArray) -> tuple[FloatArray, FloatArray]:
    """Cubic Hermite interpolation of samples ``x``, ``v`` (n, bobs, 3) at ``t`` (n,) [s], increasing,
    evaluated at ``times`` (m,) within [t₀, t_{n−1}]; returns x, v of shape (m, bobs, 3)."""
    if len(t) == 1:
        return np.repeat(x[:1], len(times), axis=0), np.repeat(v[:1], len(times), axis=0)
    i = np.clip(np.searchsorted(t, times, side="right") - 1, 0, len(t) - 2)
    h = (t[i + 1] - t[i])[:, None, None]
    s = ((times - t[i]) / (t[i + 1] - t[i]))[:, None, None]
    s2, s3 = s * s, s * s * s
    x0, x1, v0, v1 = x[i], x[i + 1], v[i], v[i + 1]
    pos = (
        (2 * s3 - 3 * s2 + 1) * x0 + (s3 - 2 * s2 + s) * h * v0 + (-2 * s3 + 3 * s2) * x1 + (s3 - s2) * h * v1
    )
    vel = ((6 * s2 - 6 * s) * (x0 - x1)) / h + (3 * s2 - 4 * s + 1) * v0 + (3 * s2 - 2 * s) * v1
    return pos, vel


def from_samples(
    t: FloatArray,
    x: FloatArray,
    v: FloatArray,
    *,
    length: float,
    g: float,
    mass: float,
    label: str,
    pivot: FloatArray | None = None,
    spring: bool = False,
) -> Motion:
    """A motion from saved samples: ``t`` (n,) [s] increasing, ``x`` and ``v`` of shape (n, 3) for one
    bob or (bobs, n, 3) for an ensemble [m], [m/s]; states between samples by :func:`hermite`.
    ``pivot`` (n, 3) [m]: a moving pivot's positions at the samples (module doc); ``spring``: a
    swinging spring (module doc)."""
    t = np.asarray(t, dtype=np.float64)
    x = np.asarray(x, dtype=np.float64)
    v = np.asarray(v, dtype=np.float64)
    if x.ndim == 2:
        x, v = x[None], v[None]
    if x.ndim != 3 or x.shape[2] != 3 or v.shape != x.shape or t.shape != (x.shape[1],):
        raise InvalidInputError(
            "samples must be t (n,) with x and v (n, 3) or (bobs, n, 3); "
            f"got t {t.shape}, x {x.shape}, v {v.shape}"
        )
    if len(t) == 0:
        raise InvalidInputError("there are no samples to animate (0 saved times)")
    if len(t) > 1 and not np.all(np.diff(t) > 0):
        raise InvalidInputError("the sample times must increase strictly to be animated")
    xs = np.ascontiguousarray(np.swapaxes(x, 0, 1))  # (n, bobs, 3)
    vs = np.ascontiguousarray(np.swapaxes(v, 0, 1))

    def states(times: FloatArray) -> tuple[FloatArray, FloatArray]:
        return hermite(t, xs, vs, np.asarray(times, dtype=np.float64))

    span = (float(t[0]), float(t[-1]))
    return Motion(
        states,
        int(xs.shape[1]),
        float(length),
        float(g),
        float(mass),
        span,
        label,
        _pivot_function(t, pivot),
        bool(spring),
    )


def _pivot_function(t: FloatArray, pivot: FloatArray | None) -> PivotFunction | None:
    """p(t) through the pivot's samples (module doc); ``None`` if there is none or it never moves."""
    if pivot is None:
        return None
    p = np.asarray(pivot, dtype=np.float64)
    if p.shape != (len(t), 3):
        raise InvalidInputError(f"pivot positions must be (n, 3) = ({len(t)}, 3) [m]; got {p.shape}")
    if not np.isfinite(p).all():
        raise InvalidInputError("the pivot positions must be finite to be animated")
    if len(t) == 1 or np.all(p == p[0]):
        p0 = p[0].copy()
        if not p0.any():
            return None
        return lambda times: np.repeat(p0[None], len(np.atleast_1d(times)), axis=0)
    pv = np.gradient(p, t, axis=0, edge_order=2 if len(t) > 2 else 1)
    return lambda times: hermite(t, p[:, None], pv[:, None], np.asarray(times, dtype=np.float64))[0][:, 0]
