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
from .shaper import Shaper, residual_vibration, shaper

ORDER = ("zv", "zvd", "ei", "zvdd", "2hump_ei")
"""Kinds tried without a ``kind``, shortest first (ZVD and EI have the same length; EI is more robust)."""


def worst_vibration(s: Shaper, omega_min: float, omega_max: float, damping: float = 0.0) -> float:
    """The largest V(ω, ζ) of ``s`` over [omega_min, omega_max] [rad/s] (a fine grid, 2001 points)."""
    grid = np.linspace(omega_min, omega_max, 2001)
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
    lo, hi = float(omega_min), float(omega_max)
    if not (math.isfinite(lo) and math.isfinite(hi) and 0 < lo <= hi):
        raise InvalidInputError(f"need 0 < omega_min <= omega_max (rad/s), got {omega_min!r}, {omega_max!r}")
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
    ``rope_max`` [m]."""
    a, b, gg = float(rope_min), float(rope_max), float(g)
    if not (math.isfinite(a) and math.isfinite(b) and 0 < a <= b and math.isfinite(gg) and gg > 0):
        raise InvalidInputError(
            f"need 0 < rope_min <= rope_max (m) and g > 0, got {rope_min!r}, {rope_max!r}, {g!r}"
        )
    return math.sqrt(gg / b), math.sqrt(gg / a)
