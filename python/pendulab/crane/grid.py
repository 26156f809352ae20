"""The residual sway of a move over a grid of rope lengths × payload ratios × shapers, each case a hook +
payload crane (T-11.5) simulated in the core in parallel (``pendulab_core::crane::grid``; docs/cranes.md
"A grid of cases", docs/performance.md). Units: m, kg, s, m/s, m/s², m/s³.

The grid runs in chunks (one shaper × a block of rope lengths, about :data:`CHUNK_CASES` cases each)
on the sweeps' driver (:func:`pendulab.sweeps.backends.drive` on its thread pool: the core releases the
GIL and runs each chunk's cases in parallel), with a progress bar and a clean stop on Ctrl-C after the
chunks in flight: the cases not computed are NaN and ``GridResult.interrupted`` is True.
"""

from __future__ import annotations

import threading
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from .._core import InvalidInputError, RunOptions, crane_residual_grid
from .._progress import tqdm
from .._warn import warn_user
from ..sweeps.backends import Threads, drive
from ..validate import flag, integer, invalid
from . import _spacing
from ._checks import number, positive, positives, real, tolerances
from ._checks import ropes as rope_lengths
from ._display import Row, Shown, grid_rows
from .paths import move
from .shaper import FloatArray, Shaper, check_shaper

MAX_CASES = 1_000_000
DEFAULT_SPACING = 0.05
"""The default ``output_spacing`` [s] of :func:`residual_grid` (its ``GridResult.output_spacing``)."""
_SAMPLED = "the time between the sway's samples in s, as residual_grid's output_spacing"
CHUNK_CASES = 200
"""Cases per chunk (one shaper, a block of rope lengths × every ratio): a few tenths of a second."""


@dataclass(frozen=True, init=False, repr=False)
class GridResult(Shown):
    """``sway`` [m] (n_shapers, n_ropes, n_ratios): the payload's largest horizontal distance from the
    pivot after the move; ``ropes`` [m], ``ratios`` (m₂/m₁), ``labels`` (one per shaper, "unshaped"
    for None); ``interrupted`` when Ctrl-C stopped the grid (the cases not computed are NaN);
    ``output_spacing`` [s], the interval at which the sway was sampled after the move (the
    ``output_spacing`` of :func:`residual_grid`), and the DOP853 tolerances ``rtol``, ``atol`` of the
    runs. ``sample_spacing`` is the deprecated older name of ``output_spacing``, read and (as a keyword)
    given with a DeprecationWarning."""

    sway: FloatArray
    ropes: FloatArray
    ratios: FloatArray
    labels: tuple[str, ...]
    interrupted: bool = False
    output_spacing: float = DEFAULT_SPACING
    rtol: float = 1e-8
    atol: float = 1e-8

    def __init__(
        self,
        sway: FloatArray,
        ropes: FloatArray,
        ratios: FloatArray,
        labels: tuple[str, ...],
        interrupted: bool = False,
        output_spacing: float | None = None,
        rtol: float = 1e-8,
        atol: float = 1e-8,
        *,
        sample_spacing: float | None = None,
    ) -> None:
        """The fields in order; ``output_spacing`` [s] defaults to :data:`DEFAULT_SPACING`.
        ``sample_spacing=`` is its deprecated older name (a DeprecationWarning at the caller's line;
        both given is an ``InvalidInputError`` naming both values)."""
        _, spacing = _spacing.spacing(
            "GridResult", output_spacing, sample_spacing, DEFAULT_SPACING, what=_SAMPLED, old="sample_spacing"
        )
        values = {"sway": sway, "ropes": ropes, "ratios": ratios, "labels": labels}
        values |= {"interrupted": interrupted, "output_spacing": spacing, "rtol": rtol, "atol": atol}
        for name, value in values.items():
            object.__setattr__(self, name, value)  # frozen: as the generated __init__ sets them

    def _rows(self) -> list[Row]:
        return grid_rows(self)

    @property
    def sample_spacing(self) -> float:
        """Deprecated: the older name of :attr:`output_spacing` [s] (a DeprecationWarning)."""
        warn_user(
            "GridResult.sample_spacing is deprecated: it is the older name of output_spacing (the time "
            "between the sway's samples in s, as residual_grid's output_spacing); read output_spacing",
            DeprecationWarning,
        )
        return self.output_spacing


def residual_grid(
    ropes: ArrayLike,
    ratios: ArrayLike,
    shapers: Sequence[Shaper | None],
    distance: float = 5.0,
    v_max: float = 0.5,
    a_max: float = 0.5,
    j_max: float | None = None,
    hook_mass: float = 100.0,
    rigging: float = 2.0,
    g: float = 9.81,
    settle: float = 20.0,
    output_spacing: float | None = None,
    rtol: float = 1e-8,
    atol: float = 1e-8,
    *,
    progress: bool | None = None,
    workers: int = 1,
    dt: float | None = None,
) -> GridResult:
    """Moves the pivot by ``distance`` along x (limits ``v_max``, ``a_max``, ``j_max``), once per shaper
    (None: unshaped), for every rope length [m] × payload ratio m₂/m₁ (hook ``hook_mass`` [kg],
    ``rigging`` [m]); the residual sway is sampled every ``output_spacing`` [s] (default 0.05 s; the
    result's ``output_spacing``) for ``settle`` [s] after the move. ``dt`` is the deprecated older name
    of ``output_spacing`` (a DeprecationWarning; both given is an error).
    Runs in chunks (module doc): ``progress`` shows a bar (default: for more than 1000 cases),
    ``workers`` chunks run at once (each already parallel in the core). Ctrl-C returns what is done
    (NaN elsewhere, ``interrupted`` True) with a RuntimeWarning."""
    name, given = _spacing.spacing("residual_grid", output_spacing, dt, DEFAULT_SPACING)
    lr = rope_lengths("ropes", ropes).ravel()
    rr = positives("ratios", ratios, "(m₂/m₁)").ravel()
    if isinstance(shapers, str | bytes) or not isinstance(shapers, Sequence):
        raise invalid("shapers", shapers, "a list of crane.Shaper or None (unshaped)")
    for i, s in enumerate(shapers):
        check_shaper(f"shapers[{i}]", s, none_ok=True)
    settle = real("settle", settle, "a finite time in (0, 3600] s", lambda x: 0 < x <= 3600)
    spacing = real(
        name, given, f"a finite number > 0 s, at most settle = {settle!r} s", lambda x: 0 < x <= settle
    )
    crane = (
        positive("hook_mass", hook_mass, "kg"),
        positive("rigging", rigging, "m"),
        number("g", g, "m/s²"),
    )
    rtol, atol = tolerances(rtol, atol)
    if progress is not None:
        flag("progress", progress)
    workers = integer("workers", workers, 1, 64)
    n = len(shapers) * lr.size * rr.size
    if n == 0:
        raise InvalidInputError("give at least one rope length, one ratio and one shaper (None: unshaped)")
    if n > MAX_CASES:
        raise InvalidInputError(f"{n} cases exceed {MAX_CASES}; use a coarser grid")
    # every value checked once, up front, by the core (a bad rope or ratio fails before any work)
    crane_residual_grid(
        [], lr.tolist(), rr.tolist(), crane, settle, RunOptions(dt=spacing, rtol=rtol, atol=atol, max_steps=1)
    )
    moves: list[Any] = []
    labels = []
    for s in shapers:
        path = move(distance, v_max, a_max, j_max=j_max, shaper=s, t_start=0.0)
        moves.append((path.knots(-1.0, path.t_end + settle + 1.0), path.t_end))
        labels.append("unshaped" if s is None else s.kind)
    sway = np.full((len(shapers), lr.size, rr.size), np.nan)
    block = max(1, CHUNK_CASES // rr.size)
    chunks = [(i, j) for i in range(len(shapers)) for j in range(0, lr.size, block)]

    def work(chunk: tuple[int, int], cancel: threading.Event) -> Any:
        i, j = chunk
        if cancel.is_set():
            return None
        ropes_block = lr[j : j + block].tolist()
        options = RunOptions(dt=spacing, rtol=rtol, atol=atol, max_steps=10_000_000)
        return crane_residual_grid([moves[i]], ropes_block, rr.tolist(), crane, settle, options)

    def done(k: int, values: Any) -> None:
        i, j = chunks[k]
        if values is not None:
            sway[i, j : j + block] = np.asarray(values).reshape(-1, rr.size)

    show = n > 1000 if progress is None else progress
    bar = tqdm(total=len(chunks), unit="chunk", desc="crane grid", leave=False, disable=not show)
    interrupted = False
    with bar:
        try:
            drive(Threads(workers), work, list(range(len(chunks))), lambda k: chunks[k], done, bar)
        except KeyboardInterrupt:
            interrupted = True
            left = int(np.isnan(sway).sum())
            warn_user(
                f"crane grid interrupted: {n - left} of {n} cases computed, the rest are NaN", RuntimeWarning
            )
    return GridResult(sway, lr, rr, tuple(labels), interrupted, float(spacing), float(rtol), float(atol))
