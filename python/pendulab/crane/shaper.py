"""Command (input) shapers and their residual vibration (docs/cranes.md, docs/theory.md T-11.1, T-11.2).

A shaper is a train of impulses A_i at times t_i (t_1 = 0, Σ A_i = 1); a command convolved with it
moves the same distance but, for a lightly damped mode of angular frequency ω and damping ratio ζ,
leaves the *percentage residual vibration* (Singer & Seering 1990, eq. 4; Singhose 2009)

    V(ω, ζ) = e^{−ζω t_N} √(C² + S²),   C = Σ A_i e^{ζω t_i} cos(ω_d t_i),
                                        S = Σ A_i e^{ζω t_i} sin(ω_d t_i),   ω_d = ω √(1 − ζ²)   (T-11.1)

of what the unshaped command leaves. With K = exp(−ζπ/√(1 − ζ²)) and the damped half period
T_d/2 = π/ω_d (T-11.2):

- ZV:   A = (1, K)/(1 + K),              t = (0, T_d/2);
- ZVD:  A = (1, 2K, K²)/(1 + K)²,        t = (0, T_d/2, T_d);
- ZVDD: A = (1, 3K, 3K², K³)/(1 + K)³,   t = (0, T_d/2, T_d, 3T_d/2);
- EI (extra insensitive, tolerance V_tol; Singhose, Seering & Singer 1994): undamped
  A = ((1 + V)/4, (1 − V)/2, (1 + V)/4), t = (0, T/2, T): V(ω₀) = V_tol with a flat top there and
  exact zeros on either side;
- two-hump EI: undamped A₁ = A₄ = (3X² + 2X + 3V²)/(16X), A₂ = A₃ = 1/2 − A₁,
  X = (V²(√(1 − V²) + 1))^{1/3}, t = (0, T/2, T, 3T/2): V(ω₀) = 0 with two humps of height V_tol.

The damped EI and two-hump EI are solved numerically (SciPy ``fsolve``, continued from the undamped
closed form in ζ) from the same conditions: EI — zeros at two frequencies, V = V_tol and ∂V/∂ω = 0 at
ω₀; two-hump EI — zeros at ω₀ and at two more frequencies, V = V_tol and ∂V/∂ω = 0 at two hump
frequencies. Shapers for several modes are convolved (``s1 * s2``). Units: t in s, ω in rad/s.
"""

from __future__ import annotations

import math
import numbers as numbers_abc
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray
from scipy.optimize import fsolve

from .._core import InvalidInputError
from ..validate import invalid
from ._checks import numbers, positive, positives, real
from ._display import Row, Shown, shaper_rows

FloatArray = NDArray[np.float64]

KINDS = ("zv", "zvd", "zvdd", "ei", "2hump_ei")
_ALIASES = {"two_hump_ei": "2hump_ei", "2-hump-ei": "2hump_ei", "2hei": "2hump_ei", "ei2": "2hump_ei"}


@dataclass(frozen=True, repr=False)
class Shaper(Shown):
    """Impulse ``times`` [s] (t₁ = 0, increasing) and ``amplitudes`` (sum 1); ``kind`` and the design
    ``omega`` [rad/s], ``damping`` ζ (NaN for convolved shapers) and ``tolerance`` V_tol (NaN but for the
    EI kinds, which alone are designed to one)."""

    times: FloatArray
    amplitudes: FloatArray
    kind: str = "custom"
    omega: float = math.nan
    damping: float = math.nan
    tolerance: float = math.nan

    def _rows(self) -> list[Row]:
        return shaper_rows(self)

    def __post_init__(self) -> None:
        """Checks the impulses (``times`` increasing from ≥ 0 s, as many finite ``amplitudes``) and keeps
        them as float64 arrays; the design fields are numbers or NaN (a convolved shaper's)."""
        t = numbers("times", self.times, "s")
        a = numbers("amplitudes", self.amplitudes, "")
        if t.ndim != 1 or t.size == 0 or a.shape != t.shape or t[0] < 0 or np.any(np.diff(t) <= 0):
            raise invalid(
                "times", self.times, f"n >= 1 increasing times >= 0 s and as many amplitudes (got {a.shape})"
            )
        object.__setattr__(self, "times", t)
        object.__setattr__(self, "amplitudes", a)
        for name in ("omega", "damping", "tolerance"):
            value = getattr(self, name)
            if not (isinstance(value, numbers_abc.Real) and not isinstance(value, bool | np.bool_)):
                raise invalid(name, value, "a number (NaN: none, for a convolved shaper)")
            object.__setattr__(self, name, float(value))

    @property
    def duration(self) -> float:
        """The shaper's length t_N [s]: the delay it adds to a move."""
        return float(self.times[-1])

    def __mul__(self, other: object) -> Shaper:
        """The convolution: impulses A_i B_j at t_i + s_j (equal times merged); cancels both modes."""
        if not isinstance(other, Shaper):
            return NotImplemented
        t = (self.times[:, None] + other.times[None, :]).ravel()
        a = (self.amplitudes[:, None] * other.amplitudes[None, :]).ravel()
        order = np.argsort(t, kind="stable")
        t, a = t[order], a[order]
        scale = max(float(t[-1]), 1.0)
        keep_t: list[float] = []
        keep_a: list[float] = []
        for ti, ai in zip(t, a, strict=True):
            if keep_t and ti - keep_t[-1] <= 1e-12 * scale:
                keep_a[-1] += float(ai)
            else:
                keep_t.append(float(ti))
                keep_a.append(float(ai))
        return Shaper(np.array(keep_t), np.array(keep_a), f"{self.kind}*{other.kind}")

    def table(self) -> list[tuple[float, float]]:
        """Rows (t_i [s], A_i)."""
        return [(float(t), float(a)) for t, a in zip(self.times, self.amplitudes, strict=True)]


def check_shaper(name: str, value: Any, none_ok: bool = False) -> None:
    """Refuses anything but a :class:`Shaper` (or None when ``none_ok``), naming ``name``."""
    if not (isinstance(value, Shaper) or (none_ok and value is None)):
        allowed = "a crane.Shaper (crane.shaper(...))" + (" or None (unshaped)" if none_ok else "")
        raise invalid(name, value, allowed)


def _ratio(name: str, value: Any) -> float:
    """A damping ratio ζ in [0, 1)."""
    return real(name, value, "a damping ratio 0 <= ζ < 1", lambda x: 0.0 <= x < 1.0)


def _closed_form(kind: str, w: float, z: float, vtol: float) -> tuple[FloatArray, FloatArray]:
    wd = w * math.sqrt(1.0 - z * z)
    half = math.pi / wd
    k = math.exp(-z * math.pi / math.sqrt(1.0 - z * z))
    if kind in ("zv", "zvd", "zvdd"):
        n = {"zv": 1, "zvd": 2, "zvdd": 3}[kind]
        amps = np.array([math.comb(n, i) * k**i for i in range(n + 1)]) / (1.0 + k) ** n
        return half * np.arange(n + 1, dtype=float), amps
    if kind == "ei":
        a1 = (1.0 + vtol) / 4.0
        return half * np.arange(3.0), np.array([a1, 1.0 - 2.0 * a1, a1])
    x = (vtol * vtol * (math.sqrt(1.0 - vtol * vtol) + 1.0)) ** (1.0 / 3.0)
    a1 = (3.0 * x * x + 2.0 * x + 3.0 * vtol * vtol) / (16.0 * x)
    return half * np.arange(4.0), np.array([a1, 0.5 - a1, 0.5 - a1, a1])


def _sums(times: FloatArray, amps: FloatArray, w: FloatArray, z: float) -> tuple[Any, Any]:
    """Complex Σ A_i e^{(ζω + iω_d) t_i} e^{−ζω t_N} and its ω-derivative, for arrays w."""
    wd = w * math.sqrt(1.0 - z * z)
    s = z * w[..., None] + 1j * wd[..., None]  # (…, 1)
    ds = z + 1j * math.sqrt(1.0 - z * z)
    e = amps * np.exp(s * (times - times[-1]))
    total = e.sum(axis=-1)
    d_total = (e * ds * (times - times[-1])).sum(axis=-1)
    return total, d_total


def _vib(times: FloatArray, amps: FloatArray, w: float, z: float) -> tuple[float, float]:
    """V and ∂V/∂ω at one frequency."""
    c, dc = _sums(times, amps, np.array([w]), z)
    v = abs(c[0])
    dv = float((c[0].conjugate() * dc[0]).real / v) if v > 0 else 0.0
    return float(v), dv


def _solve_damped(kind: str, w: float, z: float, vtol: float) -> tuple[FloatArray, FloatArray]:
    """EI / two-hump EI for ζ > 0: continuation in ζ from the closed form (module doc)."""
    t0, a0 = _closed_form(kind, w, 0.0, vtol)
    scale = 2.0 * math.pi / w
    if kind == "ei":
        xz = math.acos((2 * a0[0] - 1) / (2 * a0[0])) / math.pi  # zeros of the undamped EI, in ω/ω₀
        guess = np.array([a0[0], a0[1], t0[1] / scale, t0[2] / scale, xz, 2.0 - xz])
    else:
        grid = np.linspace(0.3, 1.7, 2801)
        vv = np.abs(_sums(t0, a0, w * grid, 0.0)[0])
        inner = (grid > 0.35) & (grid < 1.65)
        mins = [i for i in range(1, len(grid) - 1) if inner[i] and vv[i] <= vv[i - 1] and vv[i] <= vv[i + 1]]
        maxs = [i for i in range(1, len(grid) - 1) if inner[i] and vv[i] >= vv[i - 1] and vv[i] >= vv[i + 1]]
        zs = [grid[i] for i in mins if abs(grid[i] - 1) > 0.05][:2]
        hs = [grid[i] for i in maxs][:2]
        guess = np.array([a0[0], a0[1], a0[2], t0[1] / scale, t0[2] / scale, t0[3] / scale, *zs, *hs])

    def unpack(p: FloatArray) -> tuple[FloatArray, FloatArray]:
        if kind == "ei":
            amps = np.array([p[0], p[1], 1.0 - p[0] - p[1]])
            times = np.array([0.0, p[2], p[3]]) * scale
        else:
            amps = np.array([p[0], p[1], p[2], 1.0 - p[0] - p[1] - p[2]])
            times = np.array([0.0, p[3], p[4], p[5]]) * scale
        return times, amps

    def equations(p: FloatArray, zeta: float) -> FloatArray:
        times, amps = unpack(p)
        out: list[float] = []
        zero_at = [p[4], p[5]] if kind == "ei" else [1.0, p[6], p[7]]
        for x in zero_at:
            c = _sums(times, amps, np.array([w * x]), zeta)[0][0]
            out += [c.real, c.imag]
        for x in [1.0] if kind == "ei" else [p[8], p[9]]:
            v, dv = _vib(times, amps, w * x, zeta)
            out += [v - vtol, dv * w]
        return np.array(out)

    p = guess
    steps = max(1, math.ceil(z / 0.02))
    for zeta in np.linspace(0.0, z, steps + 1)[1:]:
        p, _, ok, msg = fsolve(equations, p, args=(float(zeta),), full_output=True, xtol=1e-13)
        if ok != 1 or np.max(np.abs(equations(p, float(zeta)))) > 1e-9:
            raise InvalidInputError(
                f"no damped {kind} shaper for damping = {z!r} and tolerance = {vtol!r} (the solve stopped "
                f"at damping {float(zeta):.3g}: {msg}); use a smaller damping or a ZV/ZVD/ZVDD shaper"
            )
    times, amps = unpack(p)
    if np.any(np.diff(times) <= 0) or np.any(amps <= 0):
        raise InvalidInputError(
            f"the damped {kind} shaper for damping = {z!r}, tolerance = {vtol!r} has no increasing "
            "times and positive impulses; use a smaller damping or a ZV/ZVD/ZVDD shaper"
        )
    return times, amps


def shaper(kind: str, omega: float, damping: float = 0.0, tolerance: float = 0.05) -> Shaper:
    """The shaper ``kind`` ("zv", "zvd", "zvdd", "ei", "2hump_ei") for the mode of angular frequency
    ``omega`` [rad/s] (> 0) and damping ratio ``damping`` ζ (0 ≤ ζ < 1; EI kinds ζ ≤ 0.3); EI kinds
    hold the residual vibration at or below ``tolerance`` V_tol (0 < V_tol < 1, a fraction) around the
    design frequency. Formulas: module doc (T-11.2)."""
    key = _ALIASES.get(str(kind).lower(), str(kind).lower())
    if key not in KINDS:
        raise InvalidInputError(f"shaper kind {kind!r} is not known; allowed: {', '.join(KINDS)}")
    w = positive("omega", omega, "rad/s")
    z = _ratio("damping", damping)
    vtol = real("tolerance", tolerance, "a fraction 0 < V_tol < 1", lambda x: 0.0 < x < 1.0)
    if key in ("ei", "2hump_ei") and z > 0.3:
        raise invalid("damping", damping, f"0 <= ζ <= 0.3 for the {key} shaper")
    if key in ("ei", "2hump_ei") and z > 0.0:
        times, amps = _solve_damped(key, w, z, vtol)
    else:
        times, amps = _closed_form(key, w, z, vtol)
    return Shaper(times, amps / amps.sum(), key, w, z, vtol if key in ("ei", "2hump_ei") else math.nan)


def residual_vibration(s: Shaper, omega: Any, damping: float = 0.0) -> FloatArray:
    """V(ω, ζ) of T-11.1 at the angular frequencies ``omega`` [rad/s] (array, each > 0) for a mode of
    damping ratio ``damping`` (0 ≤ ζ < 1): the residual vibration with the shaper as a fraction of
    the unshaped command's (1 = no reduction)."""
    check_shaper("s", s)
    w = positives("omega", omega, "rad/s")
    z = _ratio("damping", damping)
    total, _ = _sums(s.times, s.amplitudes, np.atleast_1d(w), z)
    out = np.abs(total).reshape(w.shape)
    return np.asarray(out, dtype=np.float64)


def insensitivity(s: Shaper, level: float = 0.05, damping: float = 0.0) -> float:
    """The width of the frequency band around ``s.omega`` where V ≤ ``level``, as a fraction of the
    design frequency (Singhose 2009: ZV 0.0637, ZVD 0.2871, EI 0.3994 at 5 %)."""
    from scipy.optimize import brentq

    check_shaper("s", s)
    w0 = real(
        "s.omega", s.omega, "a design frequency > 0 rad/s (a shaper made by crane.shaper)", lambda x: x > 0
    )
    level = real("level", level, "a fraction 0 < level < 1", lambda x: 0.0 < x < 1.0)
    _ratio("damping", damping)
    grid = np.linspace(0.05, 1.95, 19001) * w0
    below = residual_vibration(s, grid, damping) <= level * (1 + 1e-9)
    i0 = int(np.argmin(np.abs(grid - w0)))
    if not below[i0]:
        return 0.0
    lo, hi = i0, i0
    while lo > 0 and below[lo - 1]:
        lo -= 1
    while hi < len(grid) - 1 and below[hi + 1]:
        hi += 1
    if lo == 0 or hi == len(grid) - 1:
        raise InvalidInputError(f"V stays below {level} beyond 0.05…1.95 ω₀; no finite width")

    def f(x: float) -> float:
        return float(residual_vibration(s, np.array([x]), damping)[0]) - level

    a = brentq(f, grid[lo - 1], grid[lo], xtol=1e-14)
    b = brentq(f, grid[hi], grid[hi + 1], xtol=1e-14)
    return float((b - a) / w0)
