"""How the crane's results show themselves (``Shaper``, ``Profile``, ``CraneRun``, ``GridResult``): a
one-line ``repr`` of the key numbers and, in notebooks, a small HTML table of them with their SI units
(:func:`pendulab.display.html_table`), like the package's other results; never the arrays."""

from __future__ import annotations

from typing import Any

import numpy as np

from ..display import Row, html_table, number, with_unit


class Shown:
    """A mixin: ``__repr__`` and ``_repr_html_`` from the class's ``_rows()`` (quantity, value, unit);
    the dataclasses using it are declared with ``repr=False`` (else the dataclass's repr wins)."""

    def _rows(self) -> list[Row]:
        raise NotImplementedError

    def __repr__(self) -> str:
        inner = ", ".join(f"{name}={with_unit(value, unit, 4)}" for name, value, unit in self._rows())
        return f"{type(self).__name__}({inner})"

    def _repr_html_(self) -> str:
        return html_table(type(self).__name__, self._rows())


def _largest(a: Any) -> float | None:
    """The largest finite value of ``a`` (None when there is none)."""
    values = np.asarray(a, dtype=np.float64)
    finite = values[np.isfinite(values)]
    return float(finite.max()) if finite.size else None


def shaper_rows(s: Any) -> list[Row]:
    """kind, impulses, duration; the design ω and ζ where it has them (a convolved or custom shaper
    has none) and V_tol only for the EI kinds (the others are not designed to a tolerance)."""
    rows: list[Row] = [
        ("kind", s.kind, ""),
        ("impulses", int(s.times.size), ""),
        ("duration", s.duration, "s"),
    ]
    rows += [(name, getattr(s, name), unit) for name, unit in (("omega", "rad/s"), ("damping", "")) if
             np.isfinite(getattr(s, name))]  # fmt: skip
    if np.isfinite(s.tolerance):
        rows.append(("tolerance", s.tolerance, ""))
    return rows


def profile_kind(order: int) -> str:
    """A profile's kind by the derivative that steps: 2 acceleration-limited, 3 jerk-limited."""
    return {2: "acceleration-limited", 3: "jerk-limited"}.get(order, f"order-{order}")


def profile_rows(p: Any) -> list[Row]:
    """kind (acceleration- or jerk-limited), distance, t_end, knots (its steps), start; the shaper's kind."""
    rows: list[Row] = [
        ("kind", profile_kind(p.order), ""),
        ("distance", p.distance, ""),  # m, or rad for a slew: the profile does not know
        ("t_end", p.t_end, "s"),
        ("knots", int(p.knots.size), ""),
    ]
    if p.start != 0.0:
        rows.append(("start", p.start, ""))
    if p.shaper is not None:
        rows.append(("shaper", p.shaper.kind, ""))
    return rows


def run_rows(r: Any) -> list[Row]:
    """samples, the time span, steps, the largest rope sway θ and the rope's length range."""
    n = int(r.t.shape[0])
    rows: list[Row] = [("samples", n, "")]
    if n:
        rows.append(("t", f"{number(r.t[0])} … {number(r.t[-1])}", "s"))
        rows.append(("max_sway", _largest(r.sway[:, 0]), "rad"))
        lo, hi = float(np.min(r.rope)), float(np.max(r.rope))
        rows.append(("rope", number(lo) if lo == hi else f"{number(lo)} … {number(hi)}", "m"))
    rows += [("hook", r.rigging_sway is not None, ""), ("steps", int(r.steps), "")]
    return rows


def grid_rows(g: Any) -> list[Row]:
    """the grid's shape, the shapers' labels (the first few), the largest sway, the interruption."""
    n_s, n_r, n_q = g.sway.shape
    labels = "[" + ", ".join(g.labels[:4]) + (f", … ({len(g.labels)} in all)]" if len(g.labels) > 4 else "]")
    rows: list[Row] = [
        ("shape", f"{n_s}×{n_r}×{n_q} (shapers × ropes × ratios)", ""),
        ("shapers", labels, ""),
        ("max_sway", _largest(g.sway), "m"),
    ]
    if g.interrupted:
        rows.append(("interrupted", True, ""))
    return rows
