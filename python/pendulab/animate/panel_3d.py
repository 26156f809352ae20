"""The 3-D panel: the sphere |x| = l as a wireframe, the rod, the bob, a fading trail and optionally
the velocity vector, seen by the camera of :mod:`pendulab.animate.canvas`.

The pivot is at the origin (for a moving pivot the view moves with it: x is the bob's position
relative to the pivot). The trail shows the last ``trail`` seconds of the dense grid, fading
linearly with age to the background; it is drawn in :data:`FADE_STEPS` pieces of equal colour, so a
frame costs a few dozen Pillow calls whatever the trail's length. An ensemble draws each bob as a
disc coloured by its row, nearer bobs over farther ones; rods only for at most :data:`MAX_RODS`
bobs and trails for at most :data:`MAX_TRAILS`.
"""

from __future__ import annotations

import itertools
import math

import numpy as np
from PIL import ImageDraw

from .canvas import Box, Camera, blend, disc, font, polyline
from .scene import Panel, Scene

FADE_STEPS = 12
MAX_RODS = 20
MAX_TRAILS = 50
WIRE_POINTS = 73
AXIS_LENGTH = 0.35
"""Length of the x, y, z axes drawn at the pivot, as a fraction of l."""


class Panel3D(Panel):
    """Sphere, rod, bob, trail (module doc)."""

    name = "3d"

    def __init__(self, scene: Scene, box: Box) -> None:
        super().__init__(scene, box)
        opts = scene.options
        self.radius = scene.motion.length
        self.camera = Camera(box, self.radius, opts.azimuth, opts.elevation)
        # every dense point projected once: (n_dense, bobs, 2) pixels, (n_dense, bobs) magnification
        self.pixels = self.camera.project(scene.x)
        self.magnify = self.camera.magnification(scene.x)
        bobs = scene.bobs
        self.bob_radius = max(2.0, 0.045 * self.camera.scale * self.radius / (1.0 + math.log10(bobs)))
        self.colours = (
            [scene.theme.bob] if bobs == 1 else [scene.theme.gradient(i, bobs) for i in range(bobs)]
        )
        dt_dense = scene.clock.frame_dt / scene.step
        # at most the whole dense grid (a trail of 1e308 s is the whole path, not an overflow)
        points = min(opts.trail / dt_dense, float(len(scene.x))) if opts.trail > 0 else 0.0
        self.trail_points = 0 if bobs > MAX_TRAILS else round(points)
        speed = np.linalg.norm(scene.v, axis=-1)
        vmax = float(np.nanmax(speed)) if np.isfinite(speed).any() else 0.0
        self.vector_scale = 0.5 * self.radius / vmax if vmax > 0 else 0.0  # s: the fastest is l/2 long

    def background(self, draw: ImageDraw.ImageDraw) -> None:
        """The sphere of reach as a wireframe, x, y, z axes at the pivot and the title."""
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
            pts = self.camera.project(curve)
            front = self.camera.depth(curve) >= 0.0
            polyline(draw, np.where(front[:, None], np.nan, pts), theme.wire_back)
            polyline(draw, np.where(front[:, None], pts, np.nan), theme.wire_front)
        pivot = self.camera.project(np.zeros(3))
        for axis, name in zip(np.eye(3), "xyz", strict=True):  # short x, y, z axes at the pivot (z up)
            tip = self.camera.project(AXIS_LENGTH * r * axis)
            polyline(draw, np.array([pivot, tip]), theme.axes)
            draw.text(tuple(tip + 4.0), name, fill=theme.axes, font=font(13))
        disc(draw, pivot, 3.0, theme.rod)
        draw.text(
            (self.box.left + 8, self.box.top + 6), self.scene.motion.label, fill=theme.text, font=font(16)
        )

    def overlay(self, draw: ImageDraw.ImageDraw, k: int) -> None:
        scene, theme = self.scene, self.theme
        i = scene.dense_index(k)
        if self.trail_points > 1:
            for b in range(scene.bobs):
                self._trail(draw, i, b)
        pivot = self.camera.project(np.zeros(3))
        here = self.pixels[i]
        order = np.argsort(self.camera.depth(scene.x[i])) if scene.bobs > 1 else np.array([0])
        for b in order:
            p = here[b]
            if not np.isfinite(p).all():
                continue
            if scene.bobs <= MAX_RODS:
                draw.line((*pivot, *p), fill=theme.rod, width=2)
            if scene.options.vectors and self.vector_scale > 0:
                tip = self.camera.project(scene.x[i, b] + self.vector_scale * scene.v[i, b])
                _arrow(draw, p, tip, theme.vector)
            disc(draw, p, self.bob_radius * float(self.magnify[i, b]), self.colours[b])
        t = scene.t[i]
        draw.text((self.box.left + 8, self.box.top + 28), f"t = {t:.2f} s", fill=theme.text, font=font(16))

    def _trail(self, draw: ImageDraw.ImageDraw, i: int, b: int) -> None:
        start = max(0, i - self.trail_points)
        if i - start < 1:
            return
        pts = self.pixels[start : i + 1, b]
        colour = self.colours[b] if self.scene.bobs > 1 else self.theme.trail
        edges = np.linspace(0, len(pts) - 1, FADE_STEPS + 1).round().astype(int)
        full = self.trail_points
        for a, c in itertools.pairwise(edges):
            if c <= a:
                continue
            age = (i - (start + (a + c) / 2.0)) / full  # 0 at the bob, 1 at the trail's end
            polyline(draw, pts[a : c + 1], blend(colour, self.theme.background, min(0.92, age)), width=2)


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
