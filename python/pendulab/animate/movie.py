"""The driver: a :class:`~pendulab.animate.motion.Motion` into a movie file, frame by frame.

Steps, all checks first: the format from the suffix, the size, the panels, the clock (frames,
speed, limits; :mod:`~pendulab.animate.clock`), the work a GIF may hold; then the states on the
clock's dense grid (one call: exact solution or Hermite interpolation), the panels' backgrounds, and
for every frame k the panels' growing curves, a copy of that layer and the overlay (bob, trail, time),
passed to the encoder (:mod:`~pendulab.animate.encode`). A tqdm bar counts frames for longer movies.

The file is written atomically: the encoder writes a temporary file beside the target, renamed
onto it only when the movie is complete. Ctrl-C (or any error) stops after the current frame,
removes the temporary file and re-raises: no half-written movie is ever left behind.
"""

from __future__ import annotations

import base64
import html
import math
import os
import time
from collections.abc import Iterator, Mapping, Sequence
from dataclasses import dataclass, fields, replace
from pathlib import Path
from typing import Any

from PIL import Image, ImageDraw

from .._core import InvalidInputError
from .._progress import tqdm
from ..io import atomic_path
from .canvas import Theme
from .clock import check_fps, make_clock
from .encode import check_size, check_work, format_of, gif_fps, open_encoder, parse_size
from .layout import PANELS, boxes, panel_names
from .motion import Motion
from .scene import Options, Panel, Scene

DENSE_PER_PERIOD = 80
"""Dense samples per small-oscillation period 2π√(l/g) at least (smooth trails and curves)."""

SPHERE_PANELS = ("reduced", "veff")
"""Panels of a pendulum on the sphere |x| = l, which a swinging spring does not take."""

PROGRESS_AFTER = 150
"""Movies with more frames than this show a progress bar unless ``progress=False``."""


@dataclass(frozen=True)
class Movie:
    """What was written: ``path``, ``format`` (mp4, webm, gif), ``frames``, ``fps`` [1/s] (a GIF's
    is rounded to 100/n), ``size`` (width, height) [px], ``t_start``, ``t_end`` [s] of simulated time
    in the first and last frame, ``speed`` [simulated s per s of video], ``seconds`` [s] of wall time
    spent rendering and encoding, ``bytes`` (the file's size)."""

    path: Path
    format: str
    frames: int
    fps: float
    size: tuple[int, int]
    t_start: float
    t_end: float
    speed: float
    seconds: float
    bytes: int

    @property
    def duration(self) -> float:
        """Length of the movie [s of video]."""
        return self.frames / self.fps

    @property
    def frames_per_second(self) -> float:
        """Frames rendered and encoded per second of wall time."""
        return self.frames / self.seconds if self.seconds > 0 else float("inf")

    def __repr__(self) -> str:
        w, h = self.size
        return (
            f"Movie({self.path.name}: {self.format}, {self.frames} frames, {self.duration:.3g} s at "
            f"{self.fps:.3g} frames/s, {w}x{h}, t = {self.t_start:g} .. {self.t_end:.6g} s, "
            f"{self.bytes / 1e6:.2f} MB)"
        )

    def _repr_html_(self) -> str:
        """The movie itself in a notebook: the file embedded as a data URI (a GIF as an image, MP4 and
        WebM as a looping video with controls), so that it plays in exported and rendered notebooks
        (the documentation site) with no file beside them; a movie larger than
        :data:`MAX_EMBED_BYTES` is shown by its description only."""
        label = html.escape(repr(self))
        try:
            data = self.path.read_bytes() if self.bytes <= MAX_EMBED_BYTES else None
        except OSError:
            data = None
        if data is None:
            return f"<p><code>{label}</code> (not embedded: larger than {MAX_EMBED_BYTES / 1e6:g} MB)</p>"
        b64 = base64.b64encode(data).decode("ascii")
        w, h = self.size
        if self.format == "gif":
            return f'<img src="data:image/gif;base64,{b64}" width="{w}" height="{h}" alt="{label}">'
        return (
            f'<video controls loop autoplay muted playsinline width="{w}" height="{h}" title="{label}">'
            f'<source src="data:video/{self.format};base64,{b64}" type="video/{self.format}"></video>'
        )


MAX_EMBED_BYTES = 8_000_000
"""Largest movie file [bytes] that :meth:`Movie._repr_html_` embeds into a notebook."""


def _finite(name: str, value: object, unit: str, lower: float = -math.inf, upper: float = math.inf) -> float:
    """``value`` as a finite float in [lower, upper]; an error naming it otherwise."""
    try:
        x = float(value)  # type: ignore[arg-type]
    except (TypeError, ValueError):
        raise InvalidInputError(f"{name} = {value!r} must be a number ({unit})") from None
    if not (math.isfinite(x) and lower <= x <= upper):
        raise InvalidInputError(
            f"{name} = {value!r} {unit}: must be finite and within [{lower:g}, {upper:g}]"
        )
    return x


@dataclass(frozen=True)
class MovieSettings:
    """How a movie looks, named once for :func:`render`, :func:`frames` and every ``animate`` method
    (``Trajectory``, ``ExactSolution``, ``EnsembleResult``, ``SpringTrajectory``, ``pendulab
    animate``), each of which takes a ``MovieSettings`` and/or these fields as keywords.

    ``fps`` [frames/s of video]; ``speed`` [simulated s per s of video]; ``duration`` [s of video]
    (default: the whole span of the data); ``panels``: names from ``3d``, ``top``, ``z``,
    ``reduced``, ``veff`` (a list or "3d,top,z"); ``size``: (width, height) [px] or "1280x720";
    ``trail`` [s] of fading trail (default one small-oscillation period 2π√(l/g); 0: none);
    ``vectors``: draw the velocity; ``azimuth``, ``elevation`` [deg]: the 3-D camera; ``progress``:
    a bar over frames (default: for longer movies). Checked when the movie is planned.
    """

    fps: float = 30.0
    speed: float = 1.0
    duration: float | None = None
    panels: str | Sequence[str] = ("3d",)
    size: object = (1280, 720)
    trail: float | None = None
    vectors: bool = False
    azimuth: float = 35.0
    elevation: float = 18.0
    progress: bool | None = None


_SETTING_NAMES = frozenset(f.name for f in fields(MovieSettings))


def movie_settings(
    settings: MovieSettings | None = None, options: Mapping[str, Any] | None = None
) -> MovieSettings:
    """``settings`` (default: :class:`MovieSettings`'s defaults) with the keywords ``options`` put in;
    a keyword that is not a movie setting is a TypeError naming the ones there are."""
    options = dict(options or {})
    unknown = sorted(set(options) - _SETTING_NAMES)
    if unknown:
        raise TypeError(f"unknown movie setting(s) {unknown}; the settings are {sorted(_SETTING_NAMES)}")
    if settings is not None and not isinstance(settings, MovieSettings):
        raise TypeError(f"settings = {settings!r} must be a pendulab.animate.MovieSettings")
    return replace(settings or MovieSettings(), **options)


class _Plan:
    """Everything checked and computed before the first frame."""

    def __init__(self, motion: Motion, fmt: str, settings: MovieSettings) -> None:
        s = settings
        fps, speed, duration, trail, azimuth, elevation = (
            s.fps,
            s.speed,
            s.duration,
            s.trail,
            s.azimuth,
            s.elevation,
        )
        self.size = parse_size(s.size)
        check_size(fmt, self.size)
        self.names = panel_names(s.panels, motion.bobs)
        on_sphere = [n for n in self.names if n in SPHERE_PANELS]
        if motion.spring and on_sphere:
            raise InvalidInputError(
                f"panel {on_sphere[0]!r} shows a pendulum on the sphere; a swinging spring leaves it and "
                "takes 3d, top, z"
            )
        self.fps = gif_fps(check_fps(fps)) if fmt == "gif" else check_fps(fps)
        self.clock = make_clock(
            motion.span,
            fps=self.fps,
            speed=speed,
            duration=duration,
            bobs=motion.bobs,
            max_dense_dt=motion.small_period / DENSE_PER_PERIOD,
        )
        check_work(fmt, self.size, self.clock.frames)
        trail_s = motion.small_period if trail is None else _finite("trail", trail, "s", lower=0.0)
        view = (_finite("azimuth", azimuth, "deg"), _finite("elevation", elevation, "deg", -90.0, 90.0))
        options = Options(trail_s, bool(s.vectors), *view)
        self.theme = Theme()
        self.scene = Scene(motion, self.clock, options, self.theme)
        self.panels: list[Panel] = [
            PANELS[name](self.scene, box)
            for name, box in zip(self.names, boxes(self.names, *self.size), strict=True)
        ]

    def frames(self) -> Iterator[Image.Image]:
        base = Image.new("RGB", self.size, self.theme.background)
        layer = ImageDraw.Draw(base)
        for p in self.panels:
            p.background(layer)
        for k in range(self.clock.frames):
            for p in self.panels:
                p.accumulate(layer, k)
            frame = base.copy()
            draw = ImageDraw.Draw(frame)
            for p in self.panels:
                p.overlay(draw, k)
            yield frame


def frames(motion: Motion, settings: MovieSettings | None = None, **options: Any) -> Iterator[Image.Image]:
    """The frames of the movie :func:`render` would write, as RGB Pillow images (no file); the
    settings as for :func:`render`."""
    return _Plan(motion, "mp4", movie_settings(settings, options)).frames()


def render(
    motion: Motion, path: str | os.PathLike[str], settings: MovieSettings | None = None, **options: Any
) -> Movie:
    """Writes the movie of ``motion`` to ``path`` (.mp4, .webm or .gif) and describes it.

    ``settings``: a :class:`MovieSettings` (fps [frames/s of video], speed [simulated s per s of
    video], duration [s of video], panels, size [px], trail [s], vectors, azimuth, elevation [deg],
    progress); ``options``: any of its fields as keywords, over ``settings``. Raises
    :class:`~pendulab.InvalidInputError` naming the bad value before any work is done.
    """
    fmt = format_of(path)
    s = movie_settings(settings, options)
    plan = _Plan(motion, fmt, s)
    clock = plan.clock
    show = clock.frames > PROGRESS_AFTER if s.progress is None else bool(s.progress)
    target = Path(path)
    start = time.perf_counter()
    with atomic_path(target) as tmp:
        encoder = open_encoder(fmt, tmp, plan.size, plan.fps, plan.theme)
        try:
            bar = tqdm(total=clock.frames, unit="frame", desc=target.name, leave=False, disable=not show)
            with bar:
                for frame in plan.frames():
                    encoder.write(frame)
                    bar.update(1)
        except BaseException:
            encoder.abort()
            raise
        encoder.close()
    seconds = time.perf_counter() - start
    return Movie(
        target,
        fmt,
        clock.frames,
        plan.fps,
        plan.size,
        clock.t0,
        clock.t_last,
        clock.speed,
        seconds,
        target.stat().st_size,
    )
