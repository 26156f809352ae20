"""The movie clock: which simulated time each frame shows, and the limits on the work a movie may ask.

A movie of ``frames`` frames at ``fps`` frames per second of video shows, in frame k (k = 0, 1, …),
the motion at the simulated time

    t_k = t₀ + speed · k / fps        [s]

so ``speed`` is simulated seconds per second of video (1.0: real time) and the movie lasts
``frames / fps`` seconds of video. ``duration`` [s of video] defaults to the whole span of the data
divided by the speed. Between two frames the trail is sampled ``substeps`` times (a dense grid of
spacing speed/(fps · substeps) [s]), fine enough to draw a smooth curve when the speed is high.

Everything is checked before any frame is drawn: fps, speed and duration must be finite and
positive, the frames must fit in the data's span, and the work is bounded (:data:`MAX_FRAMES`,
:data:`MAX_POSITIONS`) — a request past a limit is refused with an
:class:`~pendulab.InvalidInputError` that names the value and what is allowed.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import NoReturn

import numpy as np

from .._core import InvalidInputError
from ..model import FloatArray

MAX_FPS = 120.0
"""Largest frame rate [1/s] accepted."""

MAX_FRAMES = 100_000
"""Largest number of frames one movie may have (about 55 min at 30 fps)."""

MAX_POSITIONS = 5_000_000
"""Largest number of bob positions (dense samples × bobs) computed up front (x and v: 240 MB)."""

MAX_SUBSTEPS = 16
"""Most dense samples between two frames (for trails and curves at high speed)."""


@dataclass(frozen=True)
class Clock:
    """Frame times of one movie: ``t0`` [s] of frame 0, ``fps`` [frames per s of video], ``speed``
    [simulated s per s of video], ``frames`` (count) and ``substeps`` (dense samples per frame)."""

    t0: float
    fps: float
    speed: float
    frames: int
    substeps: int

    @property
    def frame_dt(self) -> float:
        """Simulated time between two frames [s]."""
        return self.speed / self.fps

    @property
    def duration(self) -> float:
        """Length of the movie [s of video]."""
        return self.frames / self.fps

    @property
    def t_last(self) -> float:
        """Simulated time of the last frame [s]."""
        return self.t0 + self.frame_dt * (self.frames - 1)

    def frame_times(self) -> FloatArray:
        """t_k [s] for every frame k."""
        return self.t0 + self.frame_dt * np.arange(self.frames, dtype=np.float64)

    def dense_times(self) -> FloatArray:
        """The dense grid [s]: ``substeps`` samples per frame interval; frame k is sample k·substeps."""
        n = (self.frames - 1) * self.substeps + 1
        return self.t0 + (self.frame_dt / self.substeps) * np.arange(n, dtype=np.float64)


def _positive(name: str, value: object, unit: str, upper: float | None = None) -> float:
    try:
        x = float(value)  # type: ignore[arg-type]
    except (TypeError, ValueError):
        raise InvalidInputError(f"{name} = {value!r} must be a number ({unit})") from None
    if not (math.isfinite(x) and x > 0.0) or (upper is not None and x > upper):
        allowed = f"finite and > 0{f', at most {upper:g}' if upper is not None else ''}"
        raise InvalidInputError(f"{name} = {value!r} {unit}: must be {allowed}")
    return x


def check_fps(fps: object) -> float:
    """``fps`` as a float, finite, > 0 and at most :data:`MAX_FPS`; an error naming it otherwise."""
    return _positive("fps", fps, "frames/s", MAX_FPS)


def _too_many(frames: float, fps: float, what: str) -> NoReturn:
    raise InvalidInputError(
        f"{frames:.4g} frames (fps = {fps:g}, {what}) exceed the limit of {MAX_FRAMES}: "
        "lower fps, raise speed or give a shorter duration"
    )


def make_clock(
    span: tuple[float, float],
    *,
    fps: float,
    speed: float,
    duration: float | None,
    bobs: int = 1,
    max_dense_dt: float | None = None,
    max_fps: float = MAX_FPS,
) -> Clock:
    """The clock for data covering ``span`` = (t_start, t_end) [s], checked and bounded.

    ``max_dense_dt`` [s]: the dense grid's spacing should not exceed it (trails stay smooth); it
    sets ``substeps`` (1 … :data:`MAX_SUBSTEPS`). ``bobs`` counts towards :data:`MAX_POSITIONS`.
    """
    fps = _positive("fps", fps, "frames/s", max_fps)
    speed = _positive("speed", speed, "simulated s per s of video")
    t_start, t_end = (float(span[0]), float(span[1]))
    if not (math.isfinite(t_start) and math.isfinite(t_end) and t_end >= t_start):
        raise InvalidInputError(f"the time span ({t_start!r}, {t_end!r}) s must be finite with end >= start")
    available = (t_end - t_start) / speed  # s of video the data can fill (inf for a tiny speed)
    if duration is None:
        wanted = available * fps * (1 + 1e-12)
        if not wanted < MAX_FRAMES:  # also inf: checked before it becomes an integer
            _too_many(wanted, fps, f"the span {t_end - t_start:g} s at speed = {speed:g}")
        frames = math.floor(wanted) + 1
    else:
        duration = _positive("duration", duration, "s of video")
        if not duration * fps <= MAX_FRAMES:
            _too_many(duration * fps, fps, f"duration = {duration:g} s")
        frames = max(1, round(duration * fps))
        shown = t_start + speed * (frames - 1) / fps
        if shown > t_end + 1e-9 * max(1.0, abs(t_end)):
            raise InvalidInputError(
                f"duration = {duration:g} s at speed = {speed:g} and fps = {fps:g} shows t up to "
                f"{shown:g} s, "
                f"past the end of the data at t = {t_end:g} s: at most {available + 1 / fps:g} s of video, "
                "or a lower speed"
            )
    if frames > MAX_FRAMES:
        _too_many(frames, fps, f"{frames / fps:g} s of video")
    substeps = 1
    if max_dense_dt is not None and max_dense_dt > 0 and frames > 1:
        substeps = int(min(MAX_SUBSTEPS, max(1, math.ceil(speed / fps / max_dense_dt))))
    positions = ((frames - 1) * substeps + 1) * max(1, bobs)
    if positions > MAX_POSITIONS:
        if (frames * max(1, bobs)) > MAX_POSITIONS:
            raise InvalidInputError(
                f"{frames} frames × {bobs} bobs = {frames * bobs} positions exceed the limit of "
                f"{MAX_POSITIONS}: fewer bobs, fewer frames (lower fps or a shorter duration)"
            )
        substeps = max(1, (MAX_POSITIONS // max(1, bobs) - 1) // max(1, frames - 1))
    return Clock(t_start, fps, speed, frames, substeps)
