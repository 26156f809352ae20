"""Helpers for the movie tests (test_animate*.py): find the bob in a decoded frame. Positions on
screen in pixels (u to the right, w down)."""

from __future__ import annotations

import numpy as np


def red_centroid(rgb: np.ndarray) -> np.ndarray:
    """Pixel centroid (u, w) of the bob's red disc in an (h, w, 3) frame."""
    r, g, b = (rgb[..., i].astype(int) for i in range(3))
    mask = (r > 150) & (g < 120) & (b < 120)
    assert mask.sum() >= 8, "no bob found in the frame"
    w, u = np.nonzero(mask)
    return np.array([u.mean(), w.mean()])
