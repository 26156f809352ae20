"""The reduced panel: the orbit in Holm's space of S¹-invariants, on the orbit manifold (Figure 2).

In unit-length variables (docs/theory.md §3, as ``pl.reduce`` computes them) the invariants

    σ₁ = z/l,  σ₂ = ż/l [1/s],  σ₃ = |v|²/l² [1/s²],  σ₆ = J₃/(m l²) [1/s]        (T-3.1)

of a motion lie on the orbit manifold C = 0, the surface

    σ₃ = (σ₂² + σ₆²)/(1 − σ₁²)                                              (T-3.3)

and on the Hamiltonian plane σ₃ = 2(H − γσ₁), H = E/(m l²), γ = g/l (H1.18): the motion is the
closed curve where they meet. The panel draws the surface (for the start's J₃) as a wireframe, the
plane's outline, the whole curve faint, the part already shown over it, and the current point,
each axis scaled to the curve's range; with damping the curve leaves both (J₃ and E change).
"""

from __future__ import annotations

import numpy as np
from PIL import ImageDraw

from ..model import FloatArray
from .canvas import Box, Camera, disc, font, polyline
from .scene import Panel, Scene

GRID_LINES = 9
GRID_POINTS = 60


class ReducedPanel(Panel):
    """σ-space (module doc)."""

    name = "reduced"
    single_bob = True

    def __init__(self, scene: Scene, box: Box) -> None:
        super().__init__(scene, box)
        m = scene.motion
        x, v = scene.x[:, 0], scene.v[:, 0]
        length = m.length
        self.sigma = np.stack(
            [x[:, 2] / length, v[:, 2] / length, np.einsum("ij,ij->i", v, v) / length**2], axis=-1
        )
        self.s6 = float((x[0, 0] * v[0, 1] - x[0, 1] * v[0, 0]) / length**2)
        self.gamma = m.g / length
        self.h = float(0.5 * self.sigma[0, 2] + self.gamma * self.sigma[0, 0])
        w0 = np.sqrt(abs(self.gamma)) if self.gamma != 0 else 1.0
        scales = np.array([1.0, w0, w0 * w0])
        lo, hi = np.nanmin(self.sigma, axis=0), np.nanmax(self.sigma, axis=0)
        half = np.maximum(0.6 * (hi - lo), 0.08 * scales)
        self.centre, self.half = (lo + hi) / 2.0, half
        self.camera = Camera(box.inset(6, 40, 6, 0), 1.7, azimuth_deg=-55.0, elevation_deg=22.0)
        self.pixels = self.camera.project(self._unit(self.sigma))

    def _unit(self, sigma: FloatArray) -> FloatArray:
        """σ scaled so that the box of the curve is [−1, 1]³ (NaN outside [−1.2, 1.2]³)."""
        u = (sigma - self.centre) / self.half
        return np.where((np.abs(u) <= 1.2).all(axis=-1, keepdims=True), u, np.nan)

    def _surface(self, s1: FloatArray, s2: FloatArray) -> FloatArray:
        return np.stack([s1, s2, (s2 * s2 + self.s6 * self.s6) / (1.0 - s1 * s1)], axis=-1)

    def background(self, draw: ImageDraw.ImageDraw) -> None:
        theme = self.theme
        (c1, c2, _), (h1, h2, _) = self.centre, self.half
        s1_lines = np.clip(c1 + h1 * np.linspace(-1.2, 1.2, GRID_LINES), -0.999, 0.999)
        s2_lines = c2 + h2 * np.linspace(-1.2, 1.2, GRID_LINES)
        s1_run = np.clip(c1 + h1 * np.linspace(-1.2, 1.2, GRID_POINTS), -0.999, 0.999)
        s2_run = c2 + h2 * np.linspace(-1.2, 1.2, GRID_POINTS)
        for a in s1_lines:
            polyline(
                draw,
                self.camera.project(self._unit(self._surface(np.full_like(s2_run, a), s2_run))),
                theme.wire_front,
            )
        for b in s2_lines:
            polyline(
                draw,
                self.camera.project(self._unit(self._surface(s1_run, np.full_like(s1_run, b)))),
                theme.wire_front,
            )
        for b in (c2 - 1.2 * h2, c2 + 1.2 * h2):  # the plane H = ½σ₃ + γσ₁ along its two σ₂ edges
            plane = np.stack([s1_run, np.full_like(s1_run, b), 2.0 * (self.h - self.gamma * s1_run)], axis=-1)
            polyline(draw, self.camera.project(self._unit(plane)), theme.energy)
        polyline(draw, self.pixels, theme.faint, width=2)
        small = font(13)
        for axis, label in enumerate(("σ₁", "σ₂", "σ₃")):
            end = np.zeros(3)
            end[axis] = 1.35
            start = -end
            start[(axis + 1) % 3] = end[(axis + 1) % 3] = -1.2
            start[(axis + 2) % 3] = end[(axis + 2) % 3] = -1.2
            a, b = self.camera.project(start), self.camera.project(end)
            draw.line((*a, *b), fill=theme.axes)
            draw.text(tuple(b), label, fill=theme.text, font=small)
        draw.text(
            (self.box.left + 6, self.box.top + 4),
            "reduced orbit (Holm, Fig. 2)",
            fill=theme.text,
            font=font(14),
        )
        draw.text(
            (self.box.left + 6, self.box.top + 22),
            "σ₁ = z/l, σ₂ = ż/l, σ₃ = |v|²/l²",
            fill=theme.axes,
            font=small,
        )

    def accumulate(self, draw: ImageDraw.ImageDraw, k: int) -> None:
        if k == 0:
            return
        i = self.scene.dense_index(k)
        polyline(draw, self.pixels[i - self.scene.step : i + 1], self.theme.trail, width=2)

    def overlay(self, draw: ImageDraw.ImageDraw, k: int) -> None:
        p = self.pixels[self.scene.dense_index(k)]
        if np.isfinite(p).all():
            disc(draw, p, 5.0, self.theme.bob)
