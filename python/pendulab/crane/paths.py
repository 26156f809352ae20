"""Crane kinematics as pivot paths P(t) with analytic Ṗ, P̈ (docs/cranes.md, docs/theory.md T-11.3):

- gantry / overhead crane: P = P₀ + s_trolley(t) e_trolley + s_bridge(t) e_bridge (straight axes);
- tower crane: slew angle θ(t) [rad], trolley radius r(t) [m], jib height h [m]:
  P = (r cos θ, r sin θ, h),  Ṗ = ṙ e_r + r θ̇ e_θ,  P̈ = (r̈ − r θ̇²) e_r + (r θ̈ + 2 ṙ θ̇) e_θ;
- luffing boom: slew θ(t), luff angle β(t) [rad] above the horizontal, boom length L [m], foot
  height h [m]: the tip at radius ρ = L cos β and height z = h + L sin β, so
  ρ̇ = −L sin β β̇, ρ̈ = −L (cos β β̇² + sin β β̈), ż = L cos β β̇, z̈ = L (cos β β̈ − sin β β̇²),
  and the horizontal part as for the tower crane with r = ρ;
- samples (t_i, P_i), e.g. a measured path from a CSV file: the C² not-a-knot cubic spline (SciPy).

Every path gives ``position/velocity/acceleration(t)`` (arrays (N, 3), m, m/s, m/s²), its jump times
``breaks`` (where P̈ may step) and ``pivot_samples(t_end, spacing)`` for
``pendulab.Pendulum(pivot_samples=...)`` (the existing moving-pivot model, T-7.2), and ``knots`` for
the crane dynamics (T-11.4).
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
from scipy.interpolate import CubicSpline

from .._core import InvalidInputError
from ..validate import integer, invalid, show
from . import _spacing
from ._checks import count, later, numbers, positive, time
from ._checks import times as time_array
from ._display import Row, Shown, gantry_rows, tower_rows
from .move import Profile, profile
from .shaper import FloatArray, Shaper

Knots = tuple[FloatArray, FloatArray, FloatArray, FloatArray]
SAMPLE_SPACING = 0.01
"""The default ``spacing`` [s] of :meth:`Path.pivot_samples`."""
RETURNED = "the time between the returned samples in s"
"""What ``spacing`` of :meth:`Path.pivot_samples` is, in the messages."""
TOWER_RADIUS = 10.0
"""The default ``radius`` [m] of a :class:`Tower` without a luffing boom."""
KNOT_SPACING = 0.05
"""The default ``spacing`` [s] of :meth:`Path.knots`."""
BETWEEN_KNOTS = "the most time between two knots in s"
"""What ``spacing`` of :meth:`Path.knots` is, in the messages."""


def _unit(direction: Sequence[float], name: str = "direction") -> FloatArray:
    d = numbers(name, direction, "", shape=(3,))
    n = float(np.linalg.norm(d))
    if not (math.isfinite(n) and n > 0):
        raise invalid(name, direction, "three finite numbers, not all 0")
    return d / n


def _profile_or_number(name: str, value: Any, unit: str) -> None:
    """A :class:`Profile` or a constant (a finite number [``unit``])."""
    if not isinstance(value, Profile):
        numbers(name, value, unit, shape=())


class Path:
    """A pivot path (see the module doc). Subclasses define ``_pva(t)``, ``breaks`` and, for a spline,
    ``nodes``."""

    breaks: FloatArray = np.zeros(0)
    # where a spline's cubic pieces join (P and its first two derivatives continuous, P⃛ steps): knots
    # of the core's interpolant, so that it is the spline itself, and steps of its integrator (T-11.4)
    nodes: FloatArray = np.zeros(0)
    t_end: float = 0.0

    def _pva(self, t: FloatArray, left: bool = False) -> tuple[FloatArray, FloatArray, FloatArray]:
        raise NotImplementedError

    def position(self, t: Any) -> FloatArray:
        """P(t) [m], shape (N, 3) for N times [s]."""
        return self._pva(np.atleast_1d(time_array("t", t)))[0]

    def velocity(self, t: Any) -> FloatArray:
        """Ṗ(t) [m/s], shape (N, 3)."""
        return self._pva(np.atleast_1d(time_array("t", t)))[1]

    def acceleration(self, t: Any) -> FloatArray:
        """P̈(t) [m/s²], shape (N, 3) (right-continuous at the breaks)."""
        return self._pva(np.atleast_1d(time_array("t", t)))[2]

    def check_run(self, t_start: float, t_end: float) -> None:
        """Refuses (``InvalidInputError``) a run over [t_start, t_end] [s] the path does not define;
        the moves define all times (at rest outside their motion); :class:`Sampled` refuses times
        outside its samples, an ``LQRRun`` times after its loop's end."""

    def knots(self, t0: float, t1: float, spacing: float | None = None, *, dt: float | None = None) -> Knots:
        """Knots (t, P, Ṗ, P̈) on [t0, t1] [s] every ≤ ``spacing`` [s] (default 0.05 s), and at every
        break and every node of a spline twice (the values before and after), so that the quintic
        Hermite interpolant of the core (T-11.4) steps there and its integrator ends a step there rather
        than crossing a jump of P̈ or a kink (a node: P̈ continuous, P⃛ steps); between two knots the
        path is one cubic, which that interpolant is. ``dt`` is the deprecated older name of ``spacing``
        (a DeprecationWarning; both given is an error)."""
        name, given = _spacing.spacing("Path.knots", spacing, dt, KNOT_SPACING, "spacing", BETWEEN_KNOTS)
        return self._knots(t0, t1, name, given)

    def _knots(self, t0: Any, t1: Any, name: str, given: object) -> Knots:
        t0 = time("t0", t0)
        t1 = later("t1", t1, t0, "t0")
        step = positive(name, given, "s")
        count(name, t1 - t0, step)
        jumps = np.union1d(self.breaks, self.nodes)
        inner = jumps[(jumps > t0) & (jumps < t1)]
        grid = np.union1d(np.linspace(t0, t1, max(2, math.ceil((t1 - t0) / step) + 1)), inner)
        p, v, a = self._pva(grid)
        if inner.size == 0:
            return grid, p, v, a
        idx = np.searchsorted(grid, inner)
        _, v_left, a_left = self._pva(inner, left=True)
        t_all = np.insert(grid, idx, inner)
        p_all = np.insert(p, idx, p[idx], axis=0)
        v_all = np.insert(v, idx, v_left, axis=0)
        a_all = np.insert(a, idx, a_left, axis=0)
        return t_all, p_all, v_all, a_all

    def pivot_samples(
        self, t_end: float, spacing: float | None = None, t_start: float = 0.0, *, dt: float | None = None
    ) -> tuple[FloatArray, FloatArray]:
        """(times [s], positions [m] (n, 3)) on [t_start, t_end], ``spacing`` [s] apart at most
        (default 0.01 s; the time between the returned samples), for
        ``pendulab.Pendulum(pivot_samples=...)``: the moving-pivot model then uses the cubic spline
        through them (T-7.2), which smooths P̈'s steps over ~spacing. ``dt`` is the deprecated older
        name of ``spacing`` (a DeprecationWarning; both given is an error)."""
        name, given = _spacing.spacing("Path.pivot_samples", spacing, dt, SAMPLE_SPACING, "spacing", RETURNED)
        t0 = time("t_start", t_start)
        t1 = later("t_end", t_end, t0)
        n = count(name, t1 - t0, positive(name, given, "s"))
        t = np.linspace(t0, t1, n)
        return t, self.position(t)


@dataclass(frozen=True, eq=False, repr=False)
class Gantry(Path, Shown):
    """Overhead / gantry crane: trolley and bridge profiles [m] along their axes from ``origin`` [m]."""

    trolley: Profile | None = None
    bridge: Profile | None = None
    origin: tuple[float, float, float] = (0.0, 0.0, 0.0)
    trolley_axis: tuple[float, float, float] = (1.0, 0.0, 0.0)
    bridge_axis: tuple[float, float, float] = (0.0, 1.0, 0.0)

    def __post_init__(self) -> None:
        for name in ("trolley", "bridge"):
            if not isinstance(getattr(self, name), Profile | None):
                raise invalid(name, getattr(self, name), "a crane.Profile (crane.profile(...)) or None")
        numbers("origin", self.origin, "m", shape=(3,))
        _unit(self.trolley_axis, "trolley_axis")
        _unit(self.bridge_axis, "bridge_axis")

    def _rows(self) -> list[Row]:
        return gantry_rows(self)

    def _axes(self) -> list[tuple[Profile, FloatArray]]:
        out = []
        for prof, axis in ((self.trolley, self.trolley_axis), (self.bridge, self.bridge_axis)):
            if prof is not None:
                out.append((prof, _unit(axis, "axis")))
        return out

    def _pva(self, t: FloatArray, left: bool = False) -> tuple[FloatArray, FloatArray, FloatArray]:
        p = np.tile(np.asarray(self.origin, dtype=np.float64), (t.size, 1))
        v, a = np.zeros_like(p), np.zeros_like(p)
        for prof, e in self._axes():
            p += prof.position(t)[:, None] * e
            v += prof.velocity(t)[:, None] * e
            a += prof.acceleration(t, left)[:, None] * e
        return p, v, a

    @property
    def breaks(self) -> FloatArray:  # type: ignore[override]
        return np.unique(np.concatenate([np.zeros(0)] + [p.knots for p, _ in self._axes()]))

    @property
    def t_end(self) -> float:  # type: ignore[override]
        return max([0.0] + [p.t_end for p, _ in self._axes()])


@dataclass(frozen=True, eq=False, repr=False)
class Tower(Path, Shown):
    """Tower crane: ``slew`` θ(t) [rad] and trolley ``radius`` r(t) [m] profiles (a Profile, or a
    constant; default 10 m), jib ``height`` h [m]; boom luffing when ``boom`` L [m] and ``luff`` β(t)
    [rad] are given, which set the radius (L cos β: a ``radius`` given with them is refused, and the
    field stays None) (module doc). ``radius`` is the input (a Profile, a number or None): the radius
    in metres at any time, luffing or not, is :meth:`radius_at`."""

    slew: Profile | float = 0.0
    radius: Profile | float | None = None
    height: float = 0.0
    luff: Profile | float | None = None
    boom: float | None = None

    def __post_init__(self) -> None:
        _profile_or_number("slew", self.slew, "rad")
        if self.radius is not None:
            _profile_or_number("radius", self.radius, "m")
        numbers("height", self.height, "m", shape=())
        if self.luff is not None:
            _profile_or_number("luff", self.luff, "rad")
        if self.boom is not None:
            positive("boom", self.boom, "m")
        if (self.luff is None) != (self.boom is None):  # one alone would be ignored: the radius would rule
            given, missing = ("luff", "boom") if self.boom is None else ("boom", "luff")
            raise InvalidInputError(
                f"Tower: {given} = {show(getattr(self, given))} given without {missing}: a luffing boom "
                "needs both luff (its angle β [rad] above the horizontal) and boom (its length L [m]); "
                "give both, or neither for a trolley at radius"
            )
        if self.luff is not None and self.radius is not None:  # L cos β would silently rule
            raise InvalidInputError(
                f"Tower: radius = {show(self.radius)} given with luff = {show(self.luff)} and boom = "
                f"{show(self.boom)}: a luffing boom's tip is at radius boom·cos(luff), which they set; "
                "give radius for a trolley on a horizontal jib, or luff and boom for a luffing boom, "
                "not both"
            )
        if self.luff is None and self.radius is None:
            object.__setattr__(self, "radius", TOWER_RADIUS)

    def _rows(self) -> list[Row]:
        return tower_rows(self)

    def radius_at(self, t: Any) -> FloatArray:
        """The pivot's horizontal distance from the tower's axis r(t) [m], shape (N,) for N times t [s]:
        the ``radius`` (a profile or a constant), or on a luffing tower (``radius`` None) the boom
        tip's L cos β(t) (module doc); ``radius_at(0.0)[0]`` is the radius at the start."""
        ts = np.atleast_1d(time_array("t", t)).ravel()
        if self.luff is not None and self.boom is not None:
            return np.asarray(
                float(self.boom) * np.cos(self._eval(self.luff, ts, False)[0]), dtype=np.float64
            )
        return self._eval(TOWER_RADIUS if self.radius is None else self.radius, ts, False)[0]

    @staticmethod
    def _eval(prof: Profile | float, t: FloatArray, left: bool) -> tuple[FloatArray, FloatArray, FloatArray]:
        if isinstance(prof, Profile):
            return prof.position(t), prof.velocity(t), prof.acceleration(t, left)
        c = float(prof)
        return np.full(t.size, c), np.zeros(t.size), np.zeros(t.size)

    def _pva(self, t: FloatArray, left: bool = False) -> tuple[FloatArray, FloatArray, FloatArray]:
        th, dth, ddth = self._eval(self.slew, t, left)
        zero = np.zeros(t.size)
        if self.luff is not None and self.boom is not None:
            b, db, ddb = self._eval(self.luff, t, left)
            big_l = float(self.boom)
            r, dr = big_l * np.cos(b), -big_l * np.sin(b) * db
            ddr = -big_l * (np.cos(b) * db**2 + np.sin(b) * ddb)
            z, dz = self.height + big_l * np.sin(b), big_l * np.cos(b) * db
            ddz = big_l * (np.cos(b) * ddb - np.sin(b) * db**2)
        else:
            r, dr, ddr = self._eval(TOWER_RADIUS if self.radius is None else self.radius, t, left)
            z, dz, ddz = np.full(t.size, float(self.height)), zero, zero
        c, s = np.cos(th), np.sin(th)
        er = np.stack([c, s, zero], axis=1)
        et = np.stack([-s, c, zero], axis=1)
        ez = np.array([0.0, 0.0, 1.0])
        p = r[:, None] * er + z[:, None] * ez
        v = dr[:, None] * er + (r * dth)[:, None] * et + dz[:, None] * ez
        a = (ddr - r * dth**2)[:, None] * er + (r * ddth + 2 * dr * dth)[:, None] * et + ddz[:, None] * ez
        return p, v, a

    @property
    def breaks(self) -> FloatArray:  # type: ignore[override]
        ks = [p.knots for p in (self.slew, self.radius, self.luff) if isinstance(p, Profile)]
        return np.unique(np.concatenate([np.zeros(0), *ks]))

    @property
    def t_end(self) -> float:  # type: ignore[override]
        return max([0.0] + [p.t_end for p in (self.slew, self.radius, self.luff) if isinstance(p, Profile)])


class Sampled(Path):
    """A measured path through samples (t_i [s], P_i [m] (n, 3), n ≥ 4): the not-a-knot cubic spline,
    defined on [t₀, t_n] only. A time outside it (``position``, ``pivot_samples``) and a crane run
    reaching outside it are refused, naming both: the samples say nothing there, and neither choice
    is right in general — the end cubic extrapolated runs away (t² sampled on [0, 2] s would be at
    100 m at 10 s), and held at rest the path would stop dead from its last velocity (an impulse the
    rope cannot take). If the crane stood still after the measurement, append samples at the last
    position (and likewise before the first). A :class:`~pendulab.crane.Hoist` holds its ends instead:
    its clamped spline ends at rest, so holding it is the same smooth motion."""

    def __init__(self, times: Any, positions: Any) -> None:
        t = time_array("times", times).ravel()
        p = numbers("positions", positions, "m")
        if t.size < 4 or p.shape != (t.size, 3):
            raise InvalidInputError(
                f"pivot samples need n >= 4 finite times [s] and positions (n, 3) [m], got {t.size} times "
                f"and positions of shape {p.shape}"
            )
        if np.any(np.diff(t) <= 0):
            raise InvalidInputError("pivot sample times must be strictly increasing")
        self._spline = CubicSpline(t, p, axis=0)
        self.breaks = np.zeros(0)
        self.nodes = t
        self.t_end = float(t[-1])

    @classmethod
    def from_csv(cls, path: str, columns: Sequence[int] = (0, 1, 2, 3), skip_header: int = 1) -> Sampled:
        """A measured path from a CSV file: the columns (t [s], x, y, z [m]) by index, after
        ``skip_header`` lines (comments starting with # are skipped, and not counted when they lead the
        file: a Pendulab CSV's metadata line; at most 10⁶ rows). The pivot of a crane run written by
        ``pendulab crane run --out`` is columns (0, 1, 2, 3)."""
        four = "four column indices >= 0 (t, x, y, z)"
        if isinstance(columns, str | bytes) or not isinstance(columns, Sequence) or len(columns) != 4:
            raise invalid("columns", columns, four)
        cols = tuple(integer(f"columns[{i}]", c, 0, 2**31 - 1, four) for i, c in enumerate(columns))
        skip_header = integer("skip_header", skip_header, 0, 2**31 - 1, "an integer >= 0 (lines)")
        try:
            with open(path, encoding="utf-8") as f:
                lines = itertools.dropwhile(lambda line: line.startswith("#"), f)
                data = np.genfromtxt(
                    lines, delimiter=",", skip_header=skip_header, usecols=cols, max_rows=1_000_001
                )
        except (ValueError, IndexError) as e:
            raise InvalidInputError(f"{path}: cannot read columns {cols} as numbers: {e}") from None
        data = np.atleast_2d(data)
        if data.shape[0] > 1_000_000:
            raise InvalidInputError(f"{path}: more than 10⁶ rows")
        if not np.all(np.isfinite(data)):
            bad = int(np.argwhere(~np.isfinite(data))[0, 0])
            raise InvalidInputError(f"{path}: row {bad + 1} of the data has an empty or non-numeric value")
        return cls(data[:, 0], data[:, 1:4])

    @property
    def span(self) -> tuple[float, float]:
        """The sampled interval [t₀, t_n] [s] on which the path is defined."""
        return float(self.nodes[0]), float(self.nodes[-1])

    def check_run(self, t_start: float, t_end: float) -> None:
        a, b = self.span
        if not (a <= t_start and t_end <= b):
            raise InvalidInputError(
                f"the measured pivot path's samples cover t = {a:.10g} … {b:.10g} s, but the run goes from "
                f"t_start = {t_start:.10g} s to t_end = {t_end:.10g} s: give samples over the whole run (a "
                "measured path is not extrapolated; if the crane stood still, repeat its last position "
                "at later times)"
            )

    def _knots(self, t0: Any, t1: Any, name: str, given: object) -> Knots:
        a, b = self.span
        t0 = time("t0", t0)
        return super()._knots(max(t0, a), min(later("t1", t1, t0, "t0"), b), name, given)

    def _pva(self, t: FloatArray, left: bool = False) -> tuple[FloatArray, FloatArray, FloatArray]:
        a, b = self.span
        outside = (t < a) | (t > b) | np.isnan(t)
        if np.any(outside):
            bad = float(t[np.argmax(outside)])
            if not np.isfinite(bad):
                raise InvalidInputError(
                    f"t = {bad} s is not a finite number: a time [s] in {a:.10g} … {b:.10g}"
                )
            raise InvalidInputError(
                f"t = {bad:.10g} s is outside the measured pivot path's samples, t = {a:.10g} … {b:.10g} "
                "s (a measured path is not extrapolated: give samples that cover it)"
            )
        s = self._spline
        return s(t), s(t, 1), s(t, 2)


def move(
    distance: float,
    v_max: float,
    a_max: float,
    j_max: float | None = None,
    shaper: Shaper | None = None,
    direction: Sequence[float] = (1.0, 0.0, 0.0),
    t_start: float = 0.0,
    origin: Sequence[float] = (0.0, 0.0, 0.0),
) -> Gantry:
    """A straight rest-to-rest move of the pivot over ``distance`` [m] along ``direction`` from
    ``origin`` [m], starting at ``t_start`` [s], within ``v_max`` [m/s], ``a_max`` [m/s²] and, if
    given, ``j_max`` [m/s³], convolved with ``shaper`` (T-11.3): a :class:`Gantry` path."""
    prof = profile(distance, v_max, a_max, j_max=j_max, shaper=shaper, t_start=t_start)
    o = numbers("origin", origin, "m", shape=(3,))
    e = _unit(direction)
    return Gantry(
        trolley=prof, origin=(float(o[0]), float(o[1]), float(o[2])), trolley_axis=(e[0], e[1], e[2])
    )
