"""Drawing on a frame: colours, fonts, rectangles, the 3-D camera and 2-D axes (Pillow, no matplotlib).

Frames are RGB images drawn with Pillow's ``ImageDraw`` (C code: lines, polylines and discs cost a
few microseconds each), which is what makes 1280×720 movies render at tens of frames per second on
one core.

The camera (:class:`Camera`) looks at the pivot from azimuth α and elevation β with a mild
perspective. For a point p [m] (pivot at the origin, z up) with the camera's unit vectors

    right = (−sin α, cos α, 0),  up = (−sin β cos α, −sin β sin α, cos β),
    toward = (cos β cos α, cos β sin α, sin β)                        (towards the viewer),

the depth is d = p·toward and the pixel is

    (u, w) = centre + scale · D/(D − d) · (p·right, −p·up),   D = 4 R (R: the radius of the scene),

so nearer points (d > 0) are drawn larger. :meth:`Camera.project` is the one place this is done;
the tests use it to check that the bob's pixels follow the trajectory.
"""

from __future__ import annotations

import importlib.util
import math
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

import numpy as np
from PIL import ImageDraw, ImageFont

from ..model import FloatArray

RGB = tuple[int, int, int]

GRADIENT_STEPS = 32


@dataclass(frozen=True)
class Theme:
    """The colours of a movie (RGB)."""

    background: RGB = (255, 255, 255)
    wire_back: RGB = (222, 226, 232)
    wire_front: RGB = (190, 197, 207)
    rod: RGB = (60, 60, 60)
    bob: RGB = (214, 39, 40)
    trail: RGB = (31, 119, 180)
    vector: RGB = (44, 160, 44)
    text: RGB = (30, 30, 30)
    axes: RGB = (120, 120, 120)
    faint: RGB = (200, 214, 230)
    energy: RGB = (255, 127, 14)
    pivot: RGB = (148, 103, 189)
    """A moving pivot's path (whole: faint; recent: a fading trail) and the pivot itself."""
    floor: RGB = (232, 235, 240)
    ensemble: tuple[RGB, ...] = ((68, 1, 84), (59, 82, 139), (33, 145, 140), (94, 201, 98), (253, 200, 37))
    """The ensemble's bobs are coloured along this gradient in the order of their rows."""

    def colours(self) -> list[RGB]:
        """Every colour drawn (for a GIF palette)."""
        named = [
            self.wire_back,
            self.wire_front,
            self.rod,
            self.bob,
            self.trail,
            self.vector,
            self.text,
            self.axes,
            self.faint,
            self.energy,
            self.pivot,
            self.floor,
        ]
        return named + [self.gradient(i, GRADIENT_STEPS) for i in range(GRADIENT_STEPS)]

    def gradient(self, i: int, n: int) -> RGB:
        """The colour of bob i of n: one of :data:`GRADIENT_STEPS` steps along ``ensemble``."""
        if n <= 1:
            return self.bob
        f = round((GRADIENT_STEPS - 1) * i / (n - 1)) / (GRADIENT_STEPS - 1) * (len(self.ensemble) - 1)
        j = min(int(f), len(self.ensemble) - 2)
        return blend(self.ensemble[j], self.ensemble[j + 1], f - j)


def blend(a: RGB, b: RGB, f: float) -> RGB:
    """(1 − f)·a + f·b, rounded: f = 0 gives a, f = 1 gives b."""
    return (
        round(a[0] + (b[0] - a[0]) * f),
        round(a[1] + (b[1] - a[1]) * f),
        round(a[2] + (b[2] - a[2]) * f),
    )


@dataclass(frozen=True)
class Box:
    """A rectangle of the frame in pixels: left, top, width, height."""

    left: int
    top: int
    width: int
    height: int

    @property
    def centre(self) -> tuple[float, float]:
        return (self.left + self.width / 2.0, self.top + self.height / 2.0)

    def inset(self, left: int, top: int, right: int, bottom: int) -> Box:
        return Box(self.left + left, self.top + top, self.width - left - right, self.height - top - bottom)


@lru_cache(maxsize=16)
def font(size: int) -> ImageFont.FreeTypeFont | ImageFont.ImageFont:
    """DejaVu Sans (has Greek letters and subscripts) from matplotlib's data if installed, else the
    font built into Pillow."""
    spec = importlib.util.find_spec("matplotlib")
    if spec is not None and spec.origin is not None:
        path = Path(spec.origin).parent / "mpl-data" / "fonts" / "ttf" / "DejaVuSans.ttf"
        if path.exists():
            return ImageFont.truetype(str(path), size)
    return ImageFont.load_default(size=size)


class Camera:
    """Projection of 3-D points [m] onto a box of the frame (module doc): azimuth and elevation in
    degrees, ``radius`` [m] the size of the scene that must fit."""

    def __init__(
        self, box: Box, radius: float, azimuth_deg: float = 35.0, elevation_deg: float = 18.0
    ) -> None:
        a, b = math.radians(azimuth_deg), math.radians(elevation_deg)
        self.right = np.array([-math.sin(a), math.cos(a), 0.0], dtype=np.float64)
        self.up = np.array(
            [-math.sin(b) * math.cos(a), -math.sin(b) * math.sin(a), math.cos(b)], dtype=np.float64
        )
        self.toward = np.array(
            [math.cos(b) * math.cos(a), math.cos(b) * math.sin(a), math.sin(b)], dtype=np.float64
        )
        self.distance = 4.0 * radius
        # the nearest point of the sphere is magnified by D/(D − R) = 4/3: leave room for it
        self.scale = 0.46 * min(box.width, box.height) / (radius * 4.0 / 3.0)
        self.cx, self.cy = box.centre

    def depth(self, p: FloatArray) -> FloatArray:
        """p·toward [m]: > 0 in front of the pivot."""
        return np.asarray(p) @ self.toward

    def project(self, p: FloatArray) -> FloatArray:
        """Pixel coordinates (…, 2) of points p (…, 3) [m]."""
        p = np.asarray(p, dtype=np.float64)
        f = self.scale * self.distance / (self.distance - p @ self.toward)
        return np.stack([self.cx + f * (p @ self.right), self.cy - f * (p @ self.up)], axis=-1)

    def magnification(self, p: FloatArray) -> FloatArray:
        """D/(D − d): how much larger than at the pivot's depth a thing at p is drawn."""
        return self.distance / (self.distance - np.asarray(p) @ self.toward)


def polyline(draw: ImageDraw.ImageDraw, pts: FloatArray, fill: RGB, width: int = 1) -> None:
    """A polyline through pixel points (n, 2); NaN points break it."""
    ok = np.isfinite(pts).all(axis=1)
    if ok.all():
        if len(pts) >= 2:
            draw.line(pts.ravel().tolist(), fill=fill, width=width)
        return
    edges = np.flatnonzero(np.diff(np.concatenate([[0], ok.astype(np.int8), [0]])))
    for a, b in zip(edges[::2], edges[1::2], strict=True):
        if b - a >= 2:
            draw.line(pts[a:b].ravel().tolist(), fill=fill, width=width)


def disc(
    draw: ImageDraw.ImageDraw, centre: FloatArray, radius: float, fill: RGB, outline: RGB | None = None
) -> None:
    """A filled circle of ``radius`` pixels at ``centre`` (u, w)."""
    u, w = float(centre[0]), float(centre[1])
    draw.ellipse((u - radius, w - radius, u + radius, w + radius), fill=fill, outline=outline)


class Axes:
    """A 2-D plot inside a box: data (x, y) → pixels, with a frame, a title, axis labels and the data
    range written at the ends of each axis."""

    def __init__(
        self, box: Box, xlim: tuple[float, float], ylim: tuple[float, float], *, equal: bool = False
    ) -> None:
        self.outer = box
        self.inner = box.inset(46, 24, 12, 26)
        x0, x1 = xlim
        y0, y1 = ylim
        if not x1 > x0:
            x0, x1 = x0 - 1.0, x0 + 1.0
        if not y1 > y0:
            y0, y1 = y0 - 1.0, y0 + 1.0
        sx = self.inner.width / (x1 - x0)
        sy = self.inner.height / (y1 - y0)
        if equal:  # one scale for both axes: the plot area shrinks to the data's shape, centred
            sx = sy = min(sx, sy)
            w, h = round((x1 - x0) * sx), round((y1 - y0) * sy)
            i = self.inner
            self.inner = Box(i.left + (i.width - w) // 2, i.top + (i.height - h) // 2, w, h)
        self.xlim, self.ylim, self.sx, self.sy = (x0, x1), (y0, y1), sx, sy

    def to_pixels(self, x: FloatArray, y: FloatArray) -> FloatArray:
        """Pixels (n, 2) of data points; NaN for points outside the axes' ranges (breaks in polylines)."""
        x = np.asarray(x, dtype=np.float64)
        y = np.asarray(y, dtype=np.float64)
        tol_x, tol_y = 1e-9 * (self.xlim[1] - self.xlim[0]), 1e-9 * (self.ylim[1] - self.ylim[0])
        inside = (x >= self.xlim[0] - tol_x) & (x <= self.xlim[1] + tol_x)
        inside &= (y >= self.ylim[0] - tol_y) & (y <= self.ylim[1] + tol_y)
        x, y = np.where(inside, x, np.nan), np.where(inside, y, np.nan)
        u = self.inner.left + (x - self.xlim[0]) * self.sx
        w = self.inner.top + self.inner.height - (y - self.ylim[0]) * self.sy
        return np.stack([u, w], axis=-1)

    def frame(self, draw: ImageDraw.ImageDraw, theme: Theme, title: str, xlabel: str, ylabel: str) -> None:
        """The box, title, labels and the range at the ends of each axis."""
        b, small = self.inner, font(12)
        draw.rectangle((b.left, b.top, b.left + b.width, b.top + b.height), outline=theme.axes)
        draw.text((self.outer.left + 6, self.outer.top + 4), title, fill=theme.text, font=font(14))
        bottom = b.top + b.height + 4
        draw.text((b.left, bottom), f"{self.xlim[0]:.3g}", fill=theme.axes, font=small)
        draw.text((b.left + b.width, bottom), f"{self.xlim[1]:.3g}", fill=theme.axes, font=small, anchor="ra")
        draw.text((b.left + b.width / 2, bottom), xlabel, fill=theme.text, font=small, anchor="ma")
        draw.text(
            (b.left - 4, b.top + b.height), f"{self.ylim[0]:.3g}", fill=theme.axes, font=small, anchor="rb"
        )
        draw.text((b.left - 4, b.top), f"{self.ylim[1]:.3g}", fill=theme.axes, font=small, anchor="rt")
        draw.text((b.left - 4, b.top + b.height / 2), ylabel, fill=theme.text, font=small, anchor="rm")
