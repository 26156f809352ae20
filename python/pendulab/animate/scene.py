"""The scene of a movie (the states at every frame, computed once) and the panel interface.

:class:`Scene` holds the dense grid of the movie clock (``clock.substeps`` samples per frame,
frame k at dense index k·substeps): times ``t`` [s], positions ``x`` [m] and velocities ``v``
[m/s] of shape (n_dense, bobs, 3) relative to the pivot (a moving pivot's position ``pivot`` [m],
(n_dense, 3)), and the conserved quantities per unit of what the panels need:

    E = m(½|v|² + g z)  [J],   J₃ = m (x × v)·e₃  [kg m²/s]          (T-2.6)

A :class:`Panel` draws one view of the scene into its box in three layers: ``background`` once
(axes, the sphere), ``accumulate`` onto a persistent layer (curves that grow as the movie plays:
drawn once, kept), and ``overlay`` on each frame's copy (the bob, the fading trail, markers).
Per frame the cost is one image copy plus the overlay, independent of the movie's length.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

import numpy as np
from PIL import ImageDraw

from ..model import FloatArray
from .canvas import Box, Theme
from .clock import Clock
from .motion import Motion


@dataclass(frozen=True)
class Options:
    """Drawing options: ``trail`` [s] of fading trail behind each bob (0: none), ``vectors`` (draw the
    velocity at the bob), ``azimuth``, ``elevation`` [deg] of the 3-D camera."""

    trail: float
    vectors: bool = False
    azimuth: float = 35.0
    elevation: float = 18.0


class Scene:
    """States on the dense grid of ``clock`` (module doc)."""

    def __init__(self, motion: Motion, clock: Clock, options: Options, theme: Theme) -> None:
        self.motion, self.clock, self.options, self.theme = motion, clock, options, theme
        self.t = clock.dense_times()
        self.x, self.v = motion.states(self.t)
        self.step = clock.substeps
        # a moving pivot's position p [m] (n_dense, 3) in the inertial frame; None when it is fixed
        self.pivot = None if motion.pivot is None else np.asarray(motion.pivot(self.t), dtype=np.float64)

    @property
    def bobs(self) -> int:
        return self.motion.bobs

    def dense_index(self, k: int) -> int:
        """The dense index of frame k."""
        return k * self.step

    def energy(self) -> FloatArray:
        """E [J] (n_dense, bobs)."""
        m, g = self.motion.mass, self.motion.g
        v2: FloatArray = np.einsum("...i,...i->...", self.v, self.v)  # |v|², Any in numpy's stubs
        return m * (0.5 * v2 + g * self.x[..., 2])

    def j3(self) -> FloatArray:
        """J₃ [kg m²/s] (n_dense, bobs)."""
        return self.motion.mass * (self.x[..., 0] * self.v[..., 1] - self.x[..., 1] * self.v[..., 0])


class Panel:
    """One view of the scene in ``box`` (module doc). Subclasses set ``name`` and ``single_bob``
    (True if the view shows one orbit's invariants and refuses an ensemble)."""

    name: ClassVar[str] = ""
    single_bob: ClassVar[bool] = False

    def __init__(self, scene: Scene, box: Box) -> None:
        self.scene, self.box, self.theme = scene, box, scene.theme

    def background(self, draw: ImageDraw.ImageDraw) -> None:
        """What never changes (drawn once)."""

    def accumulate(self, draw: ImageDraw.ImageDraw, k: int) -> None:
        """What frame k adds for good to the persistent layer (called for k = 0, 1, … in order)."""

    def overlay(self, draw: ImageDraw.ImageDraw, k: int) -> None:
        """What only frame k shows."""
