"""A shaper for a range of sway frequencies, e.g. a rope hoisted between two lengths while the trolley
moves (docs/cranes.md, docs/theory.md T-11.2). For the undamped shapers V depends on ω/ω₀ only and is
symmetric about ω/ω₀ = 1 in the neighbourhood that matters (ZV: V = |cos(πω/2ω₀)|, ZVD: its square;
EI: the same symmetric form), so the design frequency that makes the largest V over [ω_lo, ω_hi]
smallest is the midpoint ω₀ = (ω_lo + ω_hi)/2, where V is equal at both ends. Without a kind, the
shortest of ZV, ZVD, EI, ZVDD, two-hump EI whose largest V over the range is ≤ the tolerance is
chosen; if none is, the shortest product of n ZV (or ZVD) shapers designed at n frequencies spread
evenly over the range (ZV n = 2 … 8, ZVD n = 2 … 5: at most 256 impulses; each factor puts a zero
of V at its frequency). Units: rad/s, m,
m/s².
"""

from __future__ import annotations

import math

import numpy as np

from .._core import InvalidInputError
from ..validate import invalid
from ._checks import positive, real, rope
from .shaper import Shaper, residual_vibration, shaper

ORDER = ("zv", "zvd", "ei", "zvdd", "2hump_ei")
"""Kinds tried without a ``kind``, shortest first (ZVD and EI have the same length; EI is more robust)."""


def worst_vibration(s: Shaper, omega_min: float, omega_max: float, damping: float = 0.0) -> float:
    """The largest V(ω, ζ) of ``s`` over [omega_min, omega_max] [rad/s] (a fine grid, 2001 points)."""
    lo, hi = _band("omega_min", omega_min, "omega_max", omega_max, "rad/s")
    grid = np.linspace(lo, hi, 2001)
    return float(residual_vibration(s, grid, damping).max())


def shaper_for_range(
    omega_min: float,
    omega_max: float,
    kind: str | None = None,
    tolerance: float = 0.05,
    ei_tolerance: float = 0.05,
) -> Shaper:
    """The shaper for sway frequencies anywhere in [``omega_min``, ``omega_max``] [rad/s] (0 < min ≤
    max), designed at their midpoint (module doc): of ``kind`` if given, else the shortest kind whose
    largest V over the range is ≤ ``tolerance`` (a fraction). ``ei_tolerance`` is the EI kinds' V_tol.
    Without a kind and when no single kind meets the tolerance, the shortest product of 2 … 8 ZV or
    ZVD shapers spread over the range (module doc); ``InvalidInputError`` when none does."""
    lo, hi = _band("omega_min", omega_min, "omega_max", omega_max, "rad/s")
    tolerance = real("tolerance", tolerance, "a fraction 0 < V < 1", lambda x: 0.0 < x < 1.0)
    ei_tolerance = real("ei_tolerance", ei_tolerance, "a fraction 0 < V_tol < 1", lambda x: 0.0 < x < 1.0)
    mid = 0.5 * (lo + hi)
    if kind is not None:
        return shaper(kind, omega=mid, tolerance=ei_tolerance)
    worst = {}
    for k in ORDER:
        s = shaper(k, omega=mid, tolerance=ei_tolerance)
        worst[k] = worst_vibration(s, lo, hi)
        if worst[k] <= tolerance:
            return s
    products = []
    for n in range(2, 9):
        freqs = lo + (hi - lo) * (np.arange(n) + 0.5) / n
        for k in ("zv", "zvd") if n <= 5 else ("zv",):  # at most 256 impulses
            prod = shaper(k, omega=float(freqs[0]))
            for f in freqs[1:]:
                prod = prod * shaper(k, omega=float(f))
            if worst_vibration(prod, lo, hi) <= tolerance:
                products.append(prod)
        if products:
            best = min(products, key=lambda p: p.duration)
            return Shaper(best.times, best.amplitudes, f"{best.kind}", mid, 0.0, math.nan)
    summary = ", ".join(f"{k} {100 * v:.1f} %" for k, v in worst.items())
    raise InvalidInputError(
        f"no single shaper keeps V <= {100 * tolerance:g} % over {lo:g}…{hi:g} rad/s (worst: {summary}); "
        "nor a product of up to 8 ZV/ZVD shapers across it; narrow the range"
    )


def rope_range(rope_min: float, rope_max: float, g: float = 9.81) -> tuple[float, float]:
    """The sway frequencies (√(g/l_max), √(g/l_min)) [rad/s] of a rope between ``rope_min`` and
    ``rope_max`` [m], each a rope length (in [1e-6, 1e4] m, a pendulum's, ``pl.limits()``)."""
    a, b = rope("rope_min", rope_min), rope("rope_max", rope_max)
    if not a <= b:
        raise invalid("rope_max", rope_max, f"a finite number >= rope_min = {a!r} m")
    gg = positive("g", g, "m/s²")
    return math.sqrt(gg / b), math.sqrt(gg / a)


def _band(lo_name: str, lo: object, hi_name: str, hi: object, unit: str) -> tuple[float, float]:
    """``(lo, hi)``, finite numbers with 0 < lo <= hi [``unit``]; each bad one is named."""
    a = positive(lo_name, lo, unit)
    b = positive(hi_name, hi, unit)
    if not a <= b:
        raise invalid(hi_name, hi, f"a finite number >= {lo_name} = {a!r} {unit}")
    return a, b
