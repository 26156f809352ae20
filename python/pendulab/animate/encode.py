"""Encoders: frames (RGB Pillow images) into a movie file, chosen by the file's suffix.

========= =========================================================================================
``.mp4``  H.264 (libx264, yuv420p, CRF 23, ``+faststart``) through ffmpeg — the binary that the
          ``imageio-ffmpeg`` package brings along, fed raw RGB frames through a pipe
``.webm`` VP9 (libvpx-vp9, CRF 33, realtime deadline) through the same ffmpeg
``.gif``  Pillow: every frame mapped onto one fixed palette (the theme's colours and their fades);
          delays are whole centiseconds, so the frame rate is 100/n (30 → 33.3 frames/s)
========= =========================================================================================

Sizes are checked before anything is drawn (:func:`check_size`): at least :data:`MIN_SIDE` and at
most :data:`MAX_WIDTH` × :data:`MAX_HEIGHT` pixels, even for MP4 and WebM (4:2:0 chroma halves
each side); a GIF holds all its frames in memory until written, so frames × pixels is capped at
:data:`MAX_GIF_PIXELS`. Encoders write to the path they are given (a temporary file; the driver
renames it), never guessing the container from its name.
"""

from __future__ import annotations

import contextlib
import math
import os
import subprocess
import tempfile
from pathlib import Path
from typing import Any, Protocol

from PIL import Image

from .._core import InvalidInputError
from .canvas import RGB, Theme, blend

FORMATS = {".mp4": "mp4", ".webm": "webm", ".gif": "gif"}
"""Movie formats by file suffix."""

MIN_SIDE = 64
MAX_WIDTH, MAX_HEIGHT = 3840, 2160
MAX_GIF_PIXELS = 400_000_000
"""Frames × pixels a GIF may have (Pillow keeps every frame, one byte per pixel, until it writes)."""
MAX_GIF_FPS = 50.0
"""GIF delays below 2 cs are played as 10 cs by browsers: the GIF frame rate is at most 50/s."""

_FFMPEG = {
    "mp4": ("libx264", ["-crf", "23", "-preset", "veryfast", "-movflags", "+faststart", "-f", "mp4"]),
    "webm": (
        "libvpx-vp9",
        ["-crf", "33", "-b:v", "0", "-deadline", "realtime", "-cpu-used", "8", "-f", "webm"],
    ),
}


def format_of(path: str | os.PathLike[str]) -> str:
    """The movie format from the suffix of ``path``; an error naming it otherwise."""
    suffix = Path(path).suffix.lower()
    if suffix not in FORMATS:
        raise InvalidInputError(
            f"unknown movie format {suffix or '(no suffix)'!r} in {str(path)!r}; "
            f"use one of {', '.join(FORMATS)}"
        )
    return FORMATS[suffix]


def parse_size(size: Any) -> tuple[int, int]:
    """(width, height) in pixels from a pair or a string "1280x720"."""
    if isinstance(size, str):
        parts = size.lower().replace("×", "x").split("x")
        if len(parts) == 2 and all(p.strip().isdigit() for p in parts):
            return int(parts[0]), int(parts[1])
        raise InvalidInputError(f"size = {size!r}: write it as WIDTHxHEIGHT in pixels, e.g. 1280x720")
    try:
        w, h = size
        if int(w) != w or int(h) != h:
            raise ValueError
        return int(w), int(h)
    except (TypeError, ValueError):
        raise InvalidInputError(
            f"size = {size!r}: give (width, height) in whole pixels, e.g. (1280, 720)"
        ) from None


def check_size(fmt: str, size: tuple[int, int]) -> None:
    """Refuses sizes that cannot be encoded (module doc)."""
    w, h = size
    if not (MIN_SIDE <= w <= MAX_WIDTH and MIN_SIDE <= h <= MAX_HEIGHT):
        raise InvalidInputError(
            f"size = {w}x{h} pixels: width must be {MIN_SIDE}..{MAX_WIDTH} and height "
            f"{MIN_SIDE}..{MAX_HEIGHT}"
        )
    if fmt in _FFMPEG and (w % 2 or h % 2):
        raise InvalidInputError(f"size = {w}x{h} pixels: {fmt} (4:2:0 video) needs an even width and height")


def gif_fps(fps: float) -> float:
    """The frame rate a GIF can play: 100/n frames/s for a delay of n whole centiseconds."""
    if fps > MAX_GIF_FPS:
        raise InvalidInputError(
            f"fps = {fps:g}: a GIF plays at most {MAX_GIF_FPS:g} frames/s (delays >= 2 cs)"
        )
    return 100.0 / max(2, round(100.0 / fps))


def check_work(fmt: str, size: tuple[int, int], frames: int) -> None:
    """Refuses a GIF that would not fit in memory (module doc)."""
    if fmt == "gif" and frames * size[0] * size[1] > MAX_GIF_PIXELS:
        raise InvalidInputError(
            f"a GIF of {frames} frames at {size[0]}x{size[1]} is {frames * size[0] * size[1]:.3g} pixels, "
            f"more than the {MAX_GIF_PIXELS:.3g} a GIF may hold: make it smaller, shorter or slower (fps), "
            "or write .mp4"
        )


GIF_SIZE = (640, 360)
"""A GIF's frame size when none is given (``pendulab animate``): a quarter of 720p."""
GIF_FPS = 20.0
"""A GIF's frame rate when none is given (``pendulab animate``)."""
MIN_GIF_FPS = 10.0
"""The lowest frame rate chosen for a GIF (below, a faster speed is chosen instead)."""


def fit_gif(
    span: float, size: tuple[int, int] | None, fps: float | None, speed: float
) -> tuple[tuple[int, int], float, float]:
    """Size, frame rate and speed of a GIF of ``span`` simulated seconds that fits
    :data:`MAX_GIF_PIXELS`: what is given is kept; a size not given is :data:`GIF_SIZE`, a frame rate
    not given is :data:`GIF_FPS` or lower (down to :data:`MIN_GIF_FPS`); when that is not enough and
    neither was given, the speed [simulated s per s of video] is raised until the frames fit.

    Examples
    --------
    >>> size, fps, speed = fit_gif(100.0, None, None, 1.0)  # rosette: 100 s of motion
    >>> size, round(fps, 2), speed  # 1668 frames of 640x360: 3.8e8 pixels
    ((640, 360), 16.67, 1.0)
    >>> fit_gif(1000.0, None, None, 1.0)  # 1000 s: at 10 frames/s and 5.77x speed, 1734 frames
    ((640, 360), 10.0, 5.77)
    >>> fit_gif(10.0, (1280, 720), 30.0, 1.0)  # given: kept (check_work refuses what does not fit)
    ((1280, 720), 30.0, 1.0)
    """
    w, h = size if size is not None else GIF_SIZE
    frames_cap = MAX_GIF_PIXELS // (w * h)
    if fps is not None:
        return (w, h), fps, speed
    if not (math.isfinite(span) and span >= 0.0 and math.isfinite(speed) and speed > 0.0):
        return (w, h), gif_fps(GIF_FPS), speed
    rate = gif_fps(GIF_FPS)
    while rate > MIN_GIF_FPS and span / speed * rate + 1 > frames_cap:
        rate = gif_fps(100.0 / (round(100.0 / rate) + 1))
    if size is None and span / speed * rate + 1 > frames_cap:
        speed = math.ceil(100.0 * span * rate / (frames_cap - 2)) / 100.0  # 2 frames to spare
    return (w, h), rate, speed


class Encoder(Protocol):
    """Takes frames one at a time; ``close`` finishes the file, ``abort`` stops without finishing."""

    def write(self, frame: Image.Image) -> None: ...
    def close(self) -> None: ...
    def abort(self) -> None: ...


class FFmpegEncoder:
    """MP4 or WebM: raw RGB frames piped into the ffmpeg binary of imageio-ffmpeg (module doc).

    ffmpeg runs in its own session, so a Ctrl-C in the terminal reaches only Python, which then
    aborts the encoder (kills ffmpeg); its messages go to a temporary file and are quoted if it fails."""

    def __init__(self, path: Path, fmt: str, size: tuple[int, int], fps: float) -> None:
        try:
            import imageio_ffmpeg
        except ImportError as e:  # pragma: no cover - depends on the environment
            raise ImportError("writing .mp4 or .webm needs imageio-ffmpeg: pip install imageio-ffmpeg") from e
        codec, params = _FFMPEG[fmt]
        w, h = size
        cmd = [
            imageio_ffmpeg.get_ffmpeg_exe(),
            "-y",
            "-hide_banner",
            "-loglevel",
            "error",
            "-f",
            "rawvideo",
            "-pix_fmt",
            "rgb24",
            "-s",
            f"{w}x{h}",
            "-framerate",
            f"{fps:.12g}",
            "-i",
            "-",
            "-an",
            "-c:v",
            codec,
            "-pix_fmt",
            "yuv420p",
            *params,
            str(path),
        ]
        self._log = tempfile.TemporaryFile()  # noqa: SIM115 - open for the encoder's lifetime
        self._proc = subprocess.Popen(
            cmd, stdin=subprocess.PIPE, stdout=subprocess.DEVNULL, stderr=self._log, start_new_session=True
        )

    def _failed(self) -> RuntimeError:
        self._log.seek(0)
        text = self._log.read().decode("utf-8", "replace").strip()[-2000:]
        return RuntimeError(f"ffmpeg failed (exit code {self._proc.returncode}): {text or 'no message'}")

    def write(self, frame: Image.Image) -> None:
        assert self._proc.stdin is not None
        try:
            self._proc.stdin.write(frame.tobytes())
        except BrokenPipeError:
            self.abort()
            raise self._failed() from None

    def close(self) -> None:
        assert self._proc.stdin is not None
        with contextlib.suppress(BrokenPipeError):
            self._proc.stdin.close()
        code = self._proc.wait()
        try:
            if code != 0:
                raise self._failed()
        finally:
            self._log.close()

    def abort(self) -> None:
        if self._proc.poll() is None:
            self._proc.kill()
        with contextlib.suppress(BrokenPipeError, OSError):
            assert self._proc.stdin is not None
            self._proc.stdin.close()
        self._proc.wait()
        if not self._log.closed:
            self._log.close()


def palette(theme: Theme) -> Image.Image:
    """A "P" image whose palette holds the background, every theme colour and 15 fades of each to
    the background (at most 256 entries)."""
    colours: list[RGB] = [theme.background]
    for c in theme.colours():
        for f in range(16):
            colours.append(blend(c, theme.background, f / 16.0))
    unique = list(dict.fromkeys(colours))[:256]
    flat = [v for c in unique for v in c]
    img = Image.new("P", (1, 1))
    img.putpalette(flat + flat[-3:] * (256 - len(unique)))
    return img


class GifEncoder:
    """GIF through Pillow (module doc)."""

    def __init__(self, path: Path, size: tuple[int, int], fps: float, theme: Theme) -> None:
        self.path, self.delay_ms = path, 10 * max(2, round(100.0 / fps))
        self.palette = palette(theme)
        self.frames: list[Image.Image] = []

    def write(self, frame: Image.Image) -> None:
        self.frames.append(frame.quantize(palette=self.palette, dither=Image.Dither.NONE))

    def close(self) -> None:
        first, *rest = self.frames
        first.save(
            self.path,
            format="GIF",
            save_all=True,
            append_images=rest,
            duration=self.delay_ms,
            loop=0,
            optimize=False,
        )
        self.frames.clear()

    def abort(self) -> None:
        self.frames.clear()


def open_encoder(fmt: str, path: Path, size: tuple[int, int], fps: float, theme: Theme) -> Encoder:
    """The encoder for ``fmt`` writing to ``path``."""
    if fmt == "gif":
        return GifEncoder(path, size, fps, theme)
    if not math.isfinite(fps):
        raise InvalidInputError(f"fps = {fps!r} must be finite")
    return FFmpegEncoder(path, fmt, size, fps)
