"""The residual sway of a move over a grid of rope lengths × payload ratios × shapers, each case a hook +
payload crane (T-11.5) simulated in the core in parallel (``pendulab_core::crane::grid``; docs/cranes.md
"A grid of cases", docs/performance.md). Units: m, kg, s, m/s, m/s², m/s³.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from .._core import InvalidInputError, crane_residual_grid
from .paths import move
from .shaper import FloatArray, Shaper

MAX_CASES = 1_000_000


@dataclass(frozen=True)
class GridResult:
    """``sway`` [m] (n_shapers, n_ropes, n_ratios): the payload's largest horizontal distance from the
    pivot after the move; ``ropes`` [m], ``ratios`` (m₂/m₁), ``labels`` (one per shaper, "unshaped"
    for None)."""

    sway: FloatArray
    ropes: FloatArray
    ratios: FloatArray
    labels: tuple[str, ...]


def residual_grid(
    ropes: Sequence[float],
    ratios: Sequence[float],
    shapers: Sequence[Shaper | None],
    distance: float = 5.0,
    v_max: float = 0.5,
    a_max: float = 0.5,
    j_max: float | None = None,
    hook_mass: float = 100.0,
    rigging: float = 2.0,
    g: float = 9.81,
    settle: float = 20.0,
    dt: float = 0.05,
    rtol: float = 1e-8,
    atol: float = 1e-8,
) -> GridResult:
    """Moves the pivot by ``distance`` along x (limits ``v_max``, ``a_max``, ``j_max``), once per shaper
    (None: unshaped), for every rope length [m] × payload ratio m₂/m₁ (hook ``hook_mass`` [kg],
    ``rigging`` [m]); the residual sway is measured every ``dt`` [s] for ``settle`` [s] after the move."""
    lr = np.asarray(ropes, dtype=np.float64).ravel()
    rr = np.asarray(ratios, dtype=np.float64).ravel()
    n = len(shapers) * lr.size * rr.size
    if n == 0:
        raise InvalidInputError("give at least one rope length, one ratio and one shaper (None: unshaped)")
    if n > MAX_CASES:
        raise InvalidInputError(f"{n} cases exceed {MAX_CASES}; use a coarser grid")
    if not (math.isfinite(settle) and 0 < settle <= 3600 and math.isfinite(dt) and 0 < dt <= settle):
        raise InvalidInputError(f"need 0 < dt <= settle <= 3600 s, got dt = {dt!r}, settle = {settle!r}")
    moves: list[Any] = []
    labels = []
    for s in shapers:
        path = move(distance, v_max, a_max, j_max=j_max, shaper=s, t_start=0.0)
        moves.append((path.knots(-1.0, path.t_end + settle + 1.0), path.t_end))
        labels.append("unshaped" if s is None else s.kind)
    out = crane_residual_grid(
        moves, lr.tolist(), rr.tolist(), hook_mass, rigging, g, settle, dt, rtol, atol, 10_000_000
    )
    return GridResult(np.asarray(out).reshape(len(shapers), lr.size, rr.size), lr, rr, tuple(labels))
