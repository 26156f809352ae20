"""The panels a movie can show, by name, and where each goes in the frame.

``3d`` (sphere, rod, bob, trail), ``top`` (the rosette), ``z`` (z(t)), ``reduced`` (Holm's reduced
orbit), ``veff`` (the effective potential with the energy line). With the 3-D panel and others, the
3-D panel fills the left part of the frame (a square, at most 60 % of the width) and the others
share the right part (in a column, or a 2 × 2 grid for four); without it the panels share the frame in
a grid.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

from .._core import InvalidInputError
from .canvas import Box
from .panel_3d import Panel3D
from .panel_reduced import ReducedPanel
from .panels_2d import HeightPanel, PotentialPanel, TopPanel
from .scene import Panel

MIN_PANEL = (100, 80)
"""Smallest box (width, height) [px] a panel other than a lone one may get."""

PANELS: dict[str, type[Panel]] = {
    cls.name: cls for cls in (Panel3D, TopPanel, HeightPanel, ReducedPanel, PotentialPanel)
}
"""Panel classes by name."""


def panel_names(panels: str | Sequence[str], bobs: int) -> list[str]:
    """Checked panel names from a list or a comma-separated string ("3d,top,z")."""
    names = [p.strip().lower() for p in (panels.split(",") if isinstance(panels, str) else panels)]
    names = [p for p in names if p]
    if not names:
        raise InvalidInputError(f"panels = {panels!r}: give at least one of {', '.join(PANELS)}")
    for p in names:
        if p not in PANELS:
            raise InvalidInputError(
                f"unknown panel {p!r} in panels = {panels!r}; allowed: {', '.join(PANELS)}"
            )
        if bobs > 1 and PANELS[p].single_bob:
            allowed = ", ".join(n for n, c in PANELS.items() if not c.single_bob)
            raise InvalidInputError(
                f"panel {p!r} shows the invariants of one orbit; an ensemble of {bobs} bobs takes {allowed}"
            )
    if len(set(names)) != len(names):
        raise InvalidInputError(f"panels = {panels!r} names a panel twice")
    return names


def boxes(names: Sequence[str], width: int, height: int) -> list[Box]:
    """A box per panel (module doc)."""
    n = len(names)
    if n == 1:
        return [Box(0, 0, width, height)]
    out: list[Box | None] = [None] * n
    rest = list(range(n))
    left = 0
    if "3d" in names:
        i = names.index("3d")
        w3 = min(height, int(0.6 * width))
        out[i] = Box(0, 0, w3, height)
        rest.remove(i)
        left = w3
        cols = 2 if len(rest) >= 4 else 1
        rows = math.ceil(len(rest) / cols)
    else:
        cols = math.ceil(math.sqrt(n))
        rows = math.ceil(n / cols)
    cw, rh = (width - left) // cols, height // rows
    if rest and (cw < MIN_PANEL[0] or rh < MIN_PANEL[1]):
        raise InvalidInputError(
            f"size = {width}x{height} pixels is too small for the panels {', '.join(names)}: each would be "
            f"{cw}x{rh}, and a panel needs at least {MIN_PANEL[0]}x{MIN_PANEL[1]}; make the movie larger or "
            "show fewer panels"
        )
    for j, i in enumerate(rest):
        r, c = divmod(j, cols)
        out[i] = Box(left + c * cw, r * rh, cw, rh)
    return [b for b in out if b is not None]
