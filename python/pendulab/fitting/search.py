"""The two stages around :func:`pendulab.fit`'s trust-region search (estimator.py): the continuation
over growing time windows, which keeps each stage's phase error small so that a long record does not
trap the search in the wrong number of swings, and the Gauss–Newton polish after it, which takes
noise-free data to the float64 floor (least squares, T-10.2; docs/fit.md, "How it works"). Units: SI.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from .._core import IntegrationError, InvalidInputError
from ..model import FloatArray
from .identify import jacobian

#: At most this many Gauss–Newton steps (see :func:`polish`).
POLISH_STEPS = 40


def windows_of(t: FloatArray, period: float) -> list[int]:
    """Sample counts of growing time windows [t₀, t₀ + 4T·2ᵏ) shorter than the data (T the estimated
    period): fitting them in turn keeps each stage's phase error small, so that a long record does
    not trap the search in the wrong number of swings."""
    span = float(t[-1] - t[0])
    out: list[int] = []
    width = 4.0 * period
    while width < 0.6 * span:
        n = int(np.searchsorted(t, t[0] + width))
        if n >= 16 and (not out or n > out[-1]):
            out.append(n)
        width *= 2.0
    return out


def polish(
    weighted: Any,
    u: FloatArray,
    r: FloatArray,
    jac: FloatArray,
    steps: FloatArray,
    positive: FloatArray,
    lo: FloatArray,
    hi: FloatArray,
) -> tuple[FloatArray, FloatArray, FloatArray]:
    """Gauss–Newton steps with central-difference Jacobians after the trust-region search: near the
    optimum its forward differences stall short of the float64 floor on noise-free data; these steps
    reach it (directions the data do not determine are left alone by the pseudo-inverse). Four steps,
    and more (up to POLISH_STEPS) while each still cuts the misfit by 4× or more: along a direction
    where the residual is quadratic (a planar swing seen along y: r ∝ φ̇₀²) Gauss–Newton only halves
    the distance per step."""
    for k in range(POLISH_STEPS):
        step = np.linalg.lstsq(jac, -r, rcond=1e-10)[0]
        trial = np.minimum(np.maximum(u + step, lo), hi)
        try:
            r_trial = weighted(trial)
        except (InvalidInputError, IntegrationError):  # a step into a state the model refuses
            break
        before, after = float(r @ r), float(r_trial @ r_trial)
        if not after < before or (k >= 4 and after > 0.25 * before):
            break
        small = np.all(np.abs(trial - u) <= 1e-13 * np.maximum(np.abs(u), 1.0))
        u, r = trial, r_trial
        jac = jacobian(weighted, u, steps, positive)
        if small:
            break
    return u, r, jac
