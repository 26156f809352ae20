"""The 3-D panel: the sphere |x| = l as a wireframe, the rod, the bob, a fading trail, a faint floor
grid and optionally the velocity vector, seen by the camera of :mod:`pendulab.animate.canvas`.

Everything is drawn in the inertial frame: the bob at p(t) + x(t), p the pivot (the origin unless it
moves). A moving pivot (slewing crane, vibrating or sampled pivot) has its whole path drawn faintly,
its recent path as a fading trail of its own colour, the rod from where it is and the sphere of reach
around it; the camera looks at the middle of the pivot's path and fits R = l + the path's largest
distance from it [m]. A swinging spring is drawn as a coil from the pivot to the bob whose length
|x| [m] varies (no sphere: the bob leaves it). The floor grid lies in the plane z = min p_z − R_b
[m] (R_b: l, or the spring's largest length), below every position the bob reaches, with
:data:`FLOOR_LINES` lines each way across 2R. The trail shows the last ``trail`` seconds of the
dense grid, fading linearly with age to the background; it is drawn in :data:`FADE_STEPS` pieces
of equal colour, so a frame costs a few dozen Pillow calls whatever the trail's length. An
ensemble draws each bob as a disc coloured by its row, nearer bobs over farther ones; rods only for
at most :data:`MAX_RODS` bobs and trails for at most :data:`MAX_TRAILS`.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Sequence
from functools import lru_cache

import numpy as np
from PIL import ImageDraw

from .canvas import RGB, Box, Camera, blend, disc, font, polyline
from .scene import Panel, Scene

FADE_STEPS = 12
MAX_RODS = 20
MAX_TRAILS = 50
WIRE_POINTS = 73
FLOOR_LINES = 9
"""Lines of the floor grid in each direction."""
COILS = 10
"""Zigzags of a swinging spring's coil."""
AXIS_LENGTH = 0.35
"""Length of the x, y, z axes drawn at the pivot, as a fraction of l."""


class Panel3D(Panel):
    """Sphere, rod, bob, trail (module doc)."""

    name = "3d"

    def __init__(self, scene: Scene, box: Box) -> None:
        super().__init__(scene, box)
        opts = scene.options
        self.spring = scene.motion.spring
        reach = float(np.nanmax(np.linalg.norm(scene.x, axis=-1))) if self.spring else 0.0
        self.radius = max(scene.motion.length, reach if math.isfinite(reach) else 0.0)
        path = scene.pivot
        self.path = np.zeros((len(scene.t), 3)) if path is None else path
        self.centre = 0.5 * (self.path.min(axis=0) + self.path.max(axis=0))
        self.span = float(np.linalg.norm(self.path - self.centre, axis=-1).max())
        self.camera = Camera(box, self.radius + self.span, opts.azimuth, opts.elevation)
        world = scene.x + self.path[:, None, :] - self.centre  # relative to the view's centre
        # every dense point projected once: (n_dense, bobs, 2) pixels, (n_dense, bobs) magnification
        self.pixels = self.camera.project(world)
        self.magnify = self.camera.magnification(world)
        self.depths = self.camera.depth(world)
        self.pivot_pixels = self.camera.project(self.path - self.centre)
        bobs = scene.bobs
        self.bob_radius = max(2.0, 0.045 * self.camera.scale * self.radius / (1.0 + math.log10(bobs)))
        self.colours = (
            [scene.theme.bob] if bobs == 1 else [scene.theme.gradient(i, bobs) for i in range(bobs)]
        )
        self.trail_colours = self.colours if bobs > 1 else [scene.theme.trail]
        dt_dense = scene.clock.frame_dt / scene.step
        # at most the whole dense grid (a trail of 1e308 s is the whole path, not an overflow)
        points = min(opts.trail / dt_dense, float(len(scene.x))) if opts.trail > 0 else 0.0
        self.trail_points = 0 if bobs > MAX_TRAILS else round(points)
        speed = np.linalg.norm(scene.v, axis=-1)
        vmax = float(np.nanmax(speed)) if np.isfinite(speed).any() else 0.0
        self.vector_scale = 0.5 * self.radius / vmax if vmax > 0 else 0.0  # s: the fastest is l/2 long

    @property
    def moving(self) -> bool:
        return self.scene.pivot is not None

    def background(self, draw: ImageDraw.ImageDraw) -> None:
        """The floor grid, the sphere of reach (fixed pivot), the pivot's whole path (moving pivot),
        x, y, z axes at the centre of the view and the title."""
        theme, r = self.theme, self.radius
        self._floor(draw)
        if not (self.moving or self.spring):
            self._sphere(draw, np.zeros(3))
        if self.moving:
            polyline(draw, self.pivot_pixels, blend(theme.pivot, theme.background, 0.75), width=1)
        origin = self.camera.project(np.zeros(3))
        for axis, name in zip(np.eye(3), "xyz", strict=True):  # short x, y, z axes at the centre (z up)
            tip = self.camera.project(AXIS_LENGTH * r * axis)
            polyline(draw, np.array([origin, tip]), theme.axes)
            draw.text(tuple(tip + 4.0), name, fill=theme.axes, font=font(13))
        if not self.moving:
            disc(draw, origin, 3.0, theme.rod)
        draw.text(
            (self.box.left + 8, self.box.top + 6), self.scene.motion.label, fill=theme.text, font=font(16)
        )

    def _floor(self, draw: ImageDraw.ImageDraw) -> None:
        """The floor grid (module doc), in the view's coordinates."""
        half = self.radius + self.span
        z = float(self.path[:, 2].min() - self.centre[2]) - self.radius
        ticks = np.linspace(-half, half, FLOOR_LINES)
        for a in ticks:
            for line in (((a, -half, z), (a, half, z)), ((-half, a, z), (half, a, z))):
                polyline(draw, self.camera.project(np.array(line)), self.theme.floor)

    def _sphere(self, draw: ImageDraw.ImageDraw, centre: np.ndarray) -> None:
        """The sphere of reach |x| = l around ``centre`` [m] (view coordinates) as a wireframe."""
        theme, r = self.theme, self.radius
        s = np.linspace(0.0, 2.0 * np.pi, WIRE_POINTS)
        curves = []
        for lon in np.radians(np.arange(0, 180, 30)):  # great circles through the poles
            curves.append(
                np.stack([r * np.sin(s) * np.cos(lon), r * np.sin(s) * np.sin(lon), r * np.cos(s)], -1)
            )
        for lat in np.radians([-60, -30, 0, 30, 60]):
            rho = r * np.cos(lat)
            curves.append(np.stack([rho * np.cos(s), rho * np.sin(s), np.full_like(s, r * np.sin(lat))], -1))
        for curve in curves:
            pts = self.camera.project(curve + centre)
            front = self.camera.depth(curve) >= 0.0
            polyline(draw, np.where(front[:, None], np.nan, pts), theme.wire_back)
            polyline(draw, np.where(front[:, None], pts, np.nan), theme.wire_front)

    def overlay(self, draw: ImageDraw.ImageDraw, k: int) -> None:
        scene, theme = self.scene, self.theme
        i = scene.dense_index(k)
        if self.moving:
            self._sphere(draw, self.path[i] - self.centre)
            if self.trail_points > 1:
                self._fading(draw, self.pivot_pixels[:, None, :], i, (theme.pivot,))
        if self.trail_points > 1:
            self._fading(draw, self.pixels, i, self.trail_colours)
        pivot = self.pivot_pixels[i]
        here = self.pixels[i]
        order = np.argsort(self.depths[i]) if scene.bobs > 1 else np.array([0])
        for b in order:
            p = here[b]
            if not np.isfinite(p).all():
                continue
            if self.spring:
                _coil(draw, pivot, p, 0.03 * self.camera.scale * self.radius, theme.rod)
            elif scene.bobs <= MAX_RODS:
                draw.line((*pivot, *p), fill=theme.rod, width=2)
            if scene.options.vectors and self.vector_scale > 0:
                here_m = scene.x[i, b] + self.path[i] - self.centre
                tip = self.camera.project(here_m + self.vector_scale * scene.v[i, b])
                _arrow(draw, p, tip, theme.vector)
            disc(draw, p, self.bob_radius * float(self.magnify[i, b]), self.colours[b])
        if self.moving:  # over the rod hanging from it
            disc(draw, pivot, 4.0, theme.pivot)
        t = scene.t[i]
        draw.text((self.box.left + 8, self.box.top + 28), f"t = {t:.2f} s", fill=theme.text, font=font(16))

    def _fading(self, draw: ImageDraw.ImageDraw, pixels: np.ndarray, i: int, colours: Sequence[RGB]) -> None:
        """The last ``trail_points`` of each curve of ``pixels`` (n_dense, curves, 2) up to dense index
        i, fading with age, curve after curve: :data:`FADE_STEPS` pieces of one colour each. The pieces
        and their shades are the same for every curve of a frame (:func:`_pieces`, :func:`_shades`,
        cached), and the window's pixels become Python numbers in one call, so a piece costs one
        Pillow call; a curve with a non-finite pixel in the window is drawn with breaks there."""
        start = max(0, i - self.trail_points)
        if i - start < 1:
            return
        pieces = _pieces(i - start, self.trail_points)
        window = pixels[start : i + 1]
        finite = np.isfinite(window).all(axis=(0, 2))
        flat = window.transpose(1, 0, 2).reshape(len(colours), -1).tolist()
        background = self.theme.background
        for curve, colour in enumerate(colours):
            shades = _shades(colour, background, pieces)
            if finite[curve]:
                xy = flat[curve]
                for (a, c, _), shade in zip(pieces, shades, strict=True):
                    draw.line(xy[2 * a : 2 * c + 2], fill=shade, width=2)
            else:
                for (a, c, _), shade in zip(pieces, shades, strict=True):
                    polyline(draw, window[a : c + 1, curve], shade, width=2)


@lru_cache(maxsize=64)
def _pieces(last: int, full: int) -> tuple[tuple[int, int, float], ...]:
    """The pieces (a, c, f) of a trail of points 0..last (the bob at ``last``): points a..c are drawn
    in one colour, blended towards the background by f = min(0.92, age) with age = (last − (a + c)/2)
    / ``full`` (0 at the bob, 1 at the end of a whole trail of ``full`` points)."""
    edges = np.linspace(0, last, FADE_STEPS + 1).round().astype(int).tolist()
    return tuple(
        (a, c, min(0.92, (last - (a + c) / 2.0) / full)) for a, c in itertools.pairwise(edges) if c > a
    )


@lru_cache(maxsize=4096)
def _shades(colour: RGB, background: RGB, pieces: tuple[tuple[int, int, float], ...]) -> tuple[RGB, ...]:
    """The colour of each of ``pieces`` (:func:`_pieces`) of a trail of ``colour``."""
    return tuple(blend(colour, background, f) for _, _, f in pieces)


def _coil(
    draw: ImageDraw.ImageDraw, a: np.ndarray, b: np.ndarray, width: float, colour: tuple[int, int, int]
) -> None:
    """A spring from pixel a to b: straight ends of 1/8 of its length each and :data:`COILS` zigzags
    of half-width ``width`` [px] across the line between them (its length follows |b − a|)."""
    d = b - a
    n = float(np.hypot(*d))
    if not (np.isfinite(n) and n >= 1.0):
        return
    side = np.array([-d[1], d[0]]) / n
    s = np.linspace(0.125, 0.875, 2 * COILS + 1)
    offset = np.where(np.arange(len(s)) % 2 == 1, width, 0.0) * np.where(
        np.arange(len(s)) % 4 == 1, 1.0, -1.0
    )
    pts = a + s[:, None] * d + offset[:, None] * side
    polyline(draw, np.vstack([a, pts, b]), colour, width=2)


def _arrow(draw: ImageDraw.ImageDraw, a: np.ndarray, b: np.ndarray, colour: tuple[int, int, int]) -> None:
    """A line from pixel a to b with a small head at b."""
    if not (np.isfinite(a).all() and np.isfinite(b).all()):
        return
    draw.line((*a, *b), fill=colour, width=2)
    d = b - a
    n = float(np.hypot(*d))
    if n < 4:
        return
    d = d / n
    side = np.array([-d[1], d[0]])
    head = min(10.0, 0.4 * n)
    draw.polygon(
        [tuple(b), tuple(b - head * d + 0.5 * head * side), tuple(b - head * d - 0.5 * head * side)],
        fill=colour,
    )
