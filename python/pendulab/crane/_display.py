"""How the crane's objects show themselves (``Shaper``, ``Profile``, ``CraneRun``, ``GridResult``, ``LQR``,
``LQRRun``, ``Gantry``, ``Tower``, ``Crane``, ``Hoist``, ``Wind``): a
one-line ``repr`` of the key numbers and, in notebooks, a small HTML table of them with their SI units
(:func:`pendulab.display.html_table`), like the package's other results; never the arrays."""

from __future__ import annotations

import dataclasses
from typing import Any

import numpy as np

from ..display import Row, html_table, number, vector, with_unit


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


def _range(lo: float, hi: float) -> str:
    """A length range ``lo … hi`` (one number when they are equal)."""
    return number(lo) if lo == hi else _span(lo, hi)


def run_rows(r: Any) -> list[Row]:
    """samples, the time span, steps, the largest rope sway θ and the rope's length range (the hoist's
    true range over the run, ``r.rope_range``, where known; else the saved samples')."""
    n = int(r.t.shape[0])
    rows: list[Row] = [("samples", n, "")]
    if n:
        rows.append(("t", f"{number(r.t[0])} … {number(r.t[-1])}", "s"))
        rows.append(("max_sway", _largest(r.sway[:, 0]), "rad"))
        lo, hi = r.rope_range if r.rope_range is not None else (float(np.min(r.rope)), float(np.max(r.rope)))
        rows.append(("rope", _range(lo, hi), "m"))
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


def _span(a: float, b: float) -> str:
    return f"{number(a)} … {number(b)}"


def lqr_rows(c: Any) -> list[Row]:
    """rope, the poles' count and the slowest (least damped: smallest |Re p|), a_max where finite."""
    poles = np.asarray(c.poles)
    rows: list[Row] = [("rope", c.rope, "m"), ("poles", int(poles.size), "")]
    if poles.size:
        p = complex(poles[np.argmin(np.abs(poles.real))])
        text = number(p.real, 4) + (f" ± {number(abs(p.imag), 4)}j" if p.imag != 0 else "")
        rows.append(("slowest_pole", text, "1/s"))
    if np.isfinite(c.a_max):
        rows.append(("a_max", c.a_max, "m/s²"))
    return rows


def lqr_run_rows(r: Any) -> list[Row]:
    """distance, the time span, the limit's switches, the interruption."""
    rows: list[Row] = [
        ("distance", r.distance, "m"),
        ("t", _span(*r.span), "s"),
        ("switches", int(r.switches.size), ""),
    ]
    if r.interrupted:
        rows.append(("interrupted", True, ""))
    return rows


def gantry_rows(g: Any) -> list[Row]:
    """each axis's travel (its profile's distance) and t_end; origin and axes only where not the default."""
    rows: list[Row] = []
    for name, default in (("trolley", (1.0, 0.0, 0.0)), ("bridge", (0.0, 1.0, 0.0))):
        prof, axis = getattr(g, name), getattr(g, f"{name}_axis")
        rows.append((name, "—" if prof is None else number(prof.distance, 4), "" if prof is None else "m"))
        if tuple(float(v) for v in axis) != default:
            rows.append((f"{name}_axis", vector(axis, 4), ""))
    if any(float(v) != 0.0 for v in g.origin):
        rows.append(("origin", vector(g.origin, 4), "m"))
    rows.append(("t_end", g.t_end, "s"))
    return rows


def _axis(value: Any) -> str:
    """A tower's axis: a constant, or a profile's start … end (its start plus its distance)."""
    if not hasattr(value, "distance"):
        return number(float(value), 4)
    return _range(value.start, value.start + value.distance)


def tower_rows(w: Any) -> list[Row]:
    """slew [rad]; the radius [m], or on a luffing tower the luff [rad] and the boom [m]; height [m];
    t_end [s]: a profile as its start … end value, a constant as itself."""
    rows: list[Row] = [("slew", _axis(w.slew), "rad")]
    if w.luff is not None:
        rows += [("luff", _axis(w.luff), "rad"), ("boom", w.boom, "m")]
    else:
        rows.append(("radius", _axis(w.radius), "m"))
    return [*rows, ("height", w.height, "m"), ("t_end", w.t_end, "s")]


def crane_rows(c: Any, default_wind: Any) -> list[Row]:
    """rope (its range when hoisted: the spline's true least and largest length, which may lie between
    its samples), payload, hook and rigging, damping, wind, g where not 9.81, pivot."""
    rows: list[Row] = [
        ("rope", _range(*c.hoist.length_range()), "m"),
        ("payload_mass", c.payload_mass, "kg"),
    ]
    if c.hook_mass is not None:
        rows += [("hook_mass", c.hook_mass, "kg"), ("rigging", c.rigging, "m")]
    if c.damping:
        rows.append(("damping", c.damping, "1/s"))
    if c.wind != default_wind:
        rows.append(("wind", True, ""))
    if c.g != 9.81:
        rows.append(("g", c.g, "m/s²"))
    rows.append(("pivot", type(c.pivot).__name__, ""))
    return rows


def hoist_rows(h: Any) -> list[Row]:
    """the samples' count and time span, and the rope's true length range (the spline's extremes)."""
    return [
        ("samples", int(h.nodes.size), ""),
        ("t", _span(*h.span), "s"),
        ("length", _range(*h.length_range()), "m"),
    ]


_WIND_UNITS = {
    "area": "m²",
    "air_density": "kg/m³",
    "gust_start": "s",
    "gust_duration": "s",
    "hook_area": "m²",
    "turbulence": "m/s",
    "turbulence_scale": "m",
}
"""The units of the :class:`~pendulab.crane.Wind` fields shown as numbers (the others: none)."""


def wind_rows(w: Any) -> list[Row]:
    """the steady velocity [m/s], then the fields that differ from their defaults; a gust with its
    start and duration, turbulence with its scale and seed (and these only with a gust, turbulence)."""
    rows: list[Row] = [("velocity", vector(w.velocity, 4), "m/s")]
    gust = any(float(v) != 0.0 for v in w.gust)
    for f in dataclasses.fields(w):
        value = getattr(w, f.name)
        hidden = (f.name.startswith("gust") and not gust) or (
            f.name in ("turbulence_scale", "turbulence_modes", "seed") and not w.turbulence
        )
        shown = (gust and f.name.startswith("gust")) or (
            bool(w.turbulence) and f.name in ("turbulence_scale", "seed")
        )
        if f.name == "velocity" or hidden or (not shown and value == f.default):
            continue
        if f.name == "gust":
            rows.append(("gust", vector(value, 4), "m/s"))
        else:
            rows.append((f.name, value, _WIND_UNITS.get(f.name, "")))
    return rows
