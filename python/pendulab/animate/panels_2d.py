"""The plot panels: the top view (the rosette), z(t), and the effective potential with the energy line.

- ``top``: the bob seen from above, (x, y) [m] inside the circle ρ = l; the path grows as the movie
  plays (the rosette of a generic orbit, docs/theory.md T-4.4). An ensemble shows every bob as a dot.
- ``z``: the height z(t) [m] over the movie's time span, the whole curve faint and the part already
  shown drawn over it; z stays between the turning heights z₁ ≤ z ≤ z₂ (T-4.1).
- ``veff``: the effective potential of the polar angle (T-2.5)

      V_eff(θ) = −m g l cos θ + J₃² / (2 m l² sin² θ)   [J],

  the energy line E (T-2.6), and the bob at (θ, V_eff(θ)) with a vertical bar up to E: its length
  is the kinetic energy of the polar motion ½ m l² θ̇², zero at the turning angles where the line
  meets the curve. When E or J₃ change (damping, forcing) the line and the curve move with them.
"""

from __future__ import annotations

import numpy as np
from PIL import ImageDraw

from ..model import FloatArray
from .canvas import Axes, Box, blend, disc, polyline
from .scene import Panel, Scene

VEFF_POINTS = 240


def _padded(lo: float, hi: float, pad: float = 0.06) -> tuple[float, float]:
    span = hi - lo if hi > lo else max(abs(hi), 1e-3)
    return lo - pad * span, hi + pad * span


class TopPanel(Panel):
    """The view from above (module doc)."""

    name = "top"

    def __init__(self, scene: Scene, box: Box) -> None:
        super().__init__(scene, box)
        r = scene.motion.length
        self.axes = Axes(box, (-1.05 * r, 1.05 * r), (-1.05 * r, 1.05 * r), equal=True)
        self.pixels = self.axes.to_pixels(scene.x[..., 0], scene.x[..., 1])  # (n_dense, bobs, 2)
        bobs = scene.bobs
        self.colours = (
            [scene.theme.bob] if bobs == 1 else [scene.theme.gradient(i, bobs) for i in range(bobs)]
        )

    def background(self, draw: ImageDraw.ImageDraw) -> None:
        self.axes.frame(draw, self.theme, "top view (rosette)", "x [m]", "y [m]")
        s = np.linspace(0, 2 * np.pi, 121)
        r = self.scene.motion.length
        polyline(draw, self.axes.to_pixels(r * np.cos(s), r * np.sin(s)), self.theme.wire_front)
        disc(draw, self.axes.to_pixels(np.array(0.0), np.array(0.0)), 2.0, self.theme.axes)

    def accumulate(self, draw: ImageDraw.ImageDraw, k: int) -> None:
        if self.scene.bobs != 1 or k == 0:
            return
        i = self.scene.dense_index(k)
        polyline(draw, self.pixels[i - self.scene.step : i + 1, 0], self.theme.trail)

    def overlay(self, draw: ImageDraw.ImageDraw, k: int) -> None:
        i = self.scene.dense_index(k)
        radius = 5.0 if self.scene.bobs == 1 else 2.5
        for b in range(self.scene.bobs):
            p = self.pixels[i, b]
            if np.isfinite(p).all():
                disc(draw, p, radius, self.colours[b])


class HeightPanel(Panel):
    """z(t) (module doc)."""

    name = "z"
    single_bob = True

    def __init__(self, scene: Scene, box: Box) -> None:
        super().__init__(scene, box)
        z = scene.x[:, 0, 2]
        self.axes = Axes(box, (scene.t[0], scene.t[-1]), _padded(float(np.min(z)), float(np.max(z))))
        self.pixels = self.axes.to_pixels(scene.t, z)

    def background(self, draw: ImageDraw.ImageDraw) -> None:
        self.axes.frame(draw, self.theme, "height z(t)", "t [s]", "z [m]")
        polyline(draw, self.pixels, self.theme.faint)

    def accumulate(self, draw: ImageDraw.ImageDraw, k: int) -> None:
        if k == 0:
            return
        i = self.scene.dense_index(k)
        polyline(draw, self.pixels[i - self.scene.step : i + 1], self.theme.trail, width=2)

    def overlay(self, draw: ImageDraw.ImageDraw, k: int) -> None:
        disc(draw, self.pixels[self.scene.dense_index(k)], 4.0, self.theme.bob)


class PotentialPanel(Panel):
    """V_eff(θ) with the energy line (module doc)."""

    name = "veff"
    single_bob = True

    def __init__(self, scene: Scene, box: Box) -> None:
        super().__init__(scene, box)
        m = scene.motion
        self.energy = scene.energy()[:, 0]
        self.j3 = scene.j3()[:, 0]
        x = scene.x[:, 0]
        self.theta = np.arctan2(np.hypot(x[:, 0], x[:, 1]), -x[:, 2])
        grid = np.linspace(1e-3, np.pi - 1e-3, VEFF_POINTS)
        self.grid = grid
        lowest = min(
            float(np.min(self.veff(grid, j))) for j in (np.min(np.abs(self.j3)), np.max(np.abs(self.j3)))
        )
        e_hi = float(np.max(self.energy))
        scale = max(e_hi - lowest, 0.05 * m.mass * max(abs(m.g), 1e-9) * m.length)
        y_lim = (lowest - 0.08 * scale, e_hi + 0.45 * scale)
        inside = grid[self.veff(grid, float(np.min(np.abs(self.j3)))) <= y_lim[1]]
        x_lim = (0.0, np.pi) if inside.size == 0 else _padded(float(inside[0]), float(inside[-1]), 0.05)
        self.axes = Axes(box, (max(0.0, x_lim[0]), min(np.pi, x_lim[1])), y_lim)
        self.constant = bool(np.ptp(self.j3) <= 1e-9 * max(1e-300, float(np.max(np.abs(self.j3)))))

    def veff(self, theta: FloatArray, j3: float) -> FloatArray:
        """V_eff(θ) [J] for the vertical angular momentum ``j3`` [kg m²/s] (T-2.5)."""
        m = self.scene.motion
        s = np.sin(theta)
        with np.errstate(divide="ignore", invalid="ignore"):  # at a pole: 0 for J₃ = 0, else +inf
            spin = np.where(j3 == 0.0, 0.0, j3 * j3 / (2.0 * m.mass * m.length**2 * s * s))
        return -m.mass * m.g * m.length * np.cos(theta) + spin

    def background(self, draw: ImageDraw.ImageDraw) -> None:
        self.axes.frame(draw, self.theme, "effective potential and energy", "θ [rad]", "V [J]")
        if self.constant:
            self._curve(draw, float(self.j3[0]))

    def _curve(self, draw: ImageDraw.ImageDraw, j3: float) -> None:
        polyline(draw, self.axes.to_pixels(self.grid, self.veff(self.grid, j3)), self.theme.rod, width=2)

    def overlay(self, draw: ImageDraw.ImageDraw, k: int) -> None:
        i = self.scene.dense_index(k)
        if not self.constant:
            self._curve(draw, float(self.j3[i]))
        e, th = float(self.energy[i]), float(self.theta[i])
        left, right = self.axes.to_pixels(np.array(self.axes.xlim), np.array([e, e]))
        draw.line((*left, *right), fill=self.theme.energy, width=2)
        on_curve = self.axes.to_pixels(np.array(th), self.veff(np.array(th), float(self.j3[i])))
        at_line = self.axes.to_pixels(np.array(th), np.array(e))
        draw.line((*on_curve, *at_line), fill=blend(self.theme.energy, self.theme.background, 0.4), width=2)
        disc(draw, on_curve, 5.0, self.theme.bob)
