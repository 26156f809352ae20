"""How Pendulab's objects show themselves: a short one-line ``repr`` and, in notebooks, a small HTML
table (``_repr_html_``) of the key numbers with their SI units.

Every result class (``Pendulum``, ``State``, ``Trajectory``, ``ExactSolution``, ``EnsembleResult``,
``SweepResult``, ``SpringTrajectory``) builds its display from :func:`html_table` and :func:`number`;
this module depends on nothing else in the package, so the trunk can use it.
"""

from __future__ import annotations

import html
import math
from collections.abc import Iterable, Sequence
from typing import Any

import numpy as np

Row = tuple[str, Any, str]
"""A table row: (quantity, value, unit); a value that is not a str is formatted by :func:`number`."""


def number(value: Any, digits: int = 6) -> str:
    """A number as a person reads it: ``digits`` significant digits, no trailing noise; ``None`` as
    "—"; non-finite values as ``nan`` / ``inf``; integers as they are."""
    if value is None:
        return "—"
    if isinstance(value, bool):
        return "yes" if value else "no"
    if isinstance(value, int):
        return str(value)
    try:
        x = float(value)
    except (TypeError, ValueError):
        return str(value)
    if not math.isfinite(x):
        return str(x)
    return f"{x:.{digits}g}"


def vector(values: Iterable[float], digits: int = 6) -> str:
    """A 3-vector as ``[a, b, c]`` with :func:`number`'s formatting."""
    return "[" + ", ".join(number(v, digits) for v in values) + "]"


def with_unit(value: Any, unit: str, digits: int = 6) -> str:
    """``value unit`` (no unit for dimensionless "1" or "")."""
    text = value if isinstance(value, str) else number(value, digits)
    return text if unit in ("", "1") else f"{text} {unit}"


def html_table(title: str, rows: Sequence[Row], note: str | None = None) -> str:
    """A small HTML table: a bold title, then one row per (quantity, value, unit), escaped."""
    cells = "".join(
        "<tr><th style='text-align:left;padding-right:1em'>{}</th>"
        "<td style='text-align:right'>{}</td><td style='text-align:left'>{}</td></tr>".format(
            html.escape(name),
            html.escape(value if isinstance(value, str) else number(value)),
            html.escape(unit if unit not in ("1",) else ""),
        )
        for name, value, unit in rows
    )
    foot = f"<div style='font-size:smaller'>{html.escape(note)}</div>" if note else ""
    return (
        f"<div class='pendulab'><b>{html.escape(title)}</b>"
        f"<table style='border-collapse:collapse'>{cells}</table>{foot}</div>"
    )


def relative_drift(values: Any, scale: float) -> float:
    """max |q − q₀| / scale over a series (0 for fewer than two values; nan when scale is 0)."""
    a = np.asarray(values, dtype=np.float64).ravel()
    if a.size < 2:
        return 0.0
    if scale == 0.0:
        return math.nan
    return float(np.max(np.abs(a - a[0])) / scale)
