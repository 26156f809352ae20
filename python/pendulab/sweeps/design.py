"""Designs of a sweep (:func:`pendulab.sweep`): which points to compute.

A point is a start of the ideal pendulum given by up to six numbers, the **axes** (SI units):

============== ======= =================================================================
axis           unit    meaning (default when the design does not vary it)
============== ======= =================================================================
``theta0``     rad     polar angle from the downward vertical at t = 0 (0)
``phi0``       rad     azimuth at t = 0 (0)
``theta_dot0`` rad/s   dθ/dt at t = 0 (0)
``phi_dot0``   rad/s   dφ/dt at t = 0 (0)
``length``     m       rod length l, > 0 (the pendulum's)
``g``          m/s²    gravity, any finite value (the pendulum's)
``damping``    1/s     linear damping c ≥ 0, force −m c v (the pendulum's; simulated only)
============== ======= =================================================================

Three kinds of design, all with points numbered 0 … n − 1 (the ``point`` column of the results):

* :func:`grid` — full factorial over 1-D arrays, C order (the last axis varies fastest); the
  points are generated chunk by chunk, never all at once.
* :func:`random` — ``n`` points drawn uniformly (or by Latin hypercube) in ranges, reproducible from
  ``seed`` (NumPy's PCG64).
* :func:`points` — explicit columns of equal length (one row per point).
"""

from __future__ import annotations

import hashlib
import json
import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, Literal

import numpy as np

from .. import validate as limits
from .._core import InvalidInputError
from ..memory import check_memory
from ..model import FloatArray

if TYPE_CHECKING:
    from .._core import ParamSpec

AXES: dict[str, str] = {
    "theta0": "rad",
    "phi0": "rad",
    "theta_dot0": "rad/s",
    "phi_dot0": "rad/s",
    "length": "m",
    "g": "m/s^2",
    "damping": "1/s",
}
"""The axes a design may vary, with their SI units."""

AXIS_LIMITS: dict[str, str | ParamSpec] = {
    "theta0": "angle",
    "phi0": "angle",
    "theta_dot0": "angle_rate",
    "phi_dot0": "angle_rate",
    "length": limits.COMMON["length"],
    "g": limits.COMMON["g"],
    "damping": limits.param_spec("damped", "damping"),
}
"""Each axis's entry of the table of limits (:mod:`pendulab.validate`, docs/limits.md)."""

INITIAL_AXES = ("theta0", "phi0", "theta_dot0", "phi_dot0")
"""The axes that set the start (the others, ``length``, ``g`` and ``damping``, are the pendulum's
parameters)."""

RANDOM_METHODS = ("uniform", "lhs")
"""How :func:`random` draws: independent uniform values, or a Latin hypercube (one point per 1/n slice
of every range)."""

MAX_POINTS = 2**40
"""Most points a design may have (far beyond what memory or disk allow; those are checked per sweep)."""


def _bad(message: str) -> InvalidInputError:
    return InvalidInputError(message)


def check_axis_name(name: Any, where: str = "axis") -> str:
    """``name`` if it is one of :data:`AXES`; otherwise a clear error with the closest name."""
    if not isinstance(name, str) or name not in AXES:
        did = limits.did_you_mean(name, AXES)
        raise _bad(f"unknown {where} {limits.show(name)}{did}; the axes are {', '.join(AXES)}")
    return name


def check_values(name: str, values: Any) -> FloatArray:
    """The values of axis ``name`` as a contiguous float64 1-D array: non-empty, finite, and > 0 for
    ``length``, >= 0 for ``damping``; an error naming the axis and the bad value otherwise."""
    check_axis_name(name)
    a = limits.array(f"axis {limits.show(name)} values", values, AXIS_LIMITS[name])
    if a.ndim != 1:
        raise _bad(f"axis {limits.show(name)}: values must be a 1-D array, got shape {a.shape}")
    if a.size == 0:
        raise _bad(f"axis {limits.show(name)} is empty: give at least one value (in {AXES[name]})")
    return np.ascontiguousarray(a)


@dataclass(frozen=True, eq=False)
class Design:
    """The points of a sweep (build it with :func:`grid`, :func:`random` or :func:`points`).

    ``kind`` is ``"grid"``, ``"random"`` or ``"points"``; ``names`` the axes varied, in order; ``n`` the
    number of points. A grid keeps only its ``axes`` (``shape`` = their lengths); the other kinds keep
    ``values`` (one column of n values per axis). ``info`` holds what made the design (seed, ranges).
    """

    kind: Literal["grid", "random", "points"]
    names: tuple[str, ...]
    n: int
    axes: dict[str, FloatArray] | None = None
    values: dict[str, FloatArray] | None = None
    info: dict[str, Any] = field(default_factory=dict)

    @property
    def shape(self) -> tuple[int, ...]:
        """The grid's shape (one length per axis, in order); ``(n,)`` for the other kinds."""
        if self.axes is not None:
            return tuple(len(a) for a in self.axes.values())
        return (self.n,)

    def __len__(self) -> int:
        return self.n

    def columns(self, start: int = 0, stop: int | None = None) -> dict[str, FloatArray]:
        """The axis values of points ``start`` … ``stop − 1``: one float64 array per axis."""
        stop = self.n if stop is None else stop
        if not 0 <= start <= stop <= self.n:
            raise _bad(f"points {start}..{stop} are outside the design's 0..{self.n}")
        if self.values is not None:
            return {k: v[start:stop].copy() for k, v in self.values.items()}
        assert self.axes is not None
        idx = np.unravel_index(np.arange(start, stop, dtype=np.int64), self.shape)
        return {k: a[i] for (k, a), i in zip(self.axes.items(), idx, strict=True)}

    def describe(self) -> dict[str, Any]:
        """A JSON-able description (the manifest's ``design``): kind, names, n, the grid's axes."""
        out: dict[str, Any] = {"kind": self.kind, "names": list(self.names), "n": self.n, **self.info}
        if self.axes is not None:
            out["axes"] = {k: v.tolist() for k, v in self.axes.items()}
        return out

    def fingerprint(self) -> str:
        """SHA-256 of the design's kind, names and values (bit for bit): equal designs, equal prints."""
        h = hashlib.sha256(json.dumps([self.kind, list(self.names), self.n]).encode())
        for arrays in (self.axes, self.values):
            for k, v in (arrays or {}).items():
                h.update(k.encode())
                h.update(np.ascontiguousarray(v, dtype="<f8").tobytes())
        return h.hexdigest()

    @staticmethod
    def from_description(desc: dict[str, Any], values: dict[str, FloatArray] | None = None) -> Design:
        """The design back from :meth:`describe` (and, for random and points designs, the values read
        from the results)."""
        if desc["kind"] == "grid":
            return grid({k: np.asarray(desc["axes"][k], dtype=np.float64) for k in desc["names"]})
        if values is None:
            raise _bad(f"a {desc['kind']!r} design needs its values")
        info = {k: v for k, v in desc.items() if k not in ("kind", "names", "n")}
        d = points({k: values[k] for k in desc["names"]})
        return Design(desc["kind"], d.names, d.n, values=d.values, info=info)


def _check_names(names: list[str]) -> None:
    if not names:
        raise _bad(f"a design needs at least one axis; the axes are {', '.join(AXES)}")
    for name in names:
        check_axis_name(name)


def grid(axes: Mapping[str, Any] | Design) -> Design:
    """The full factorial design over ``axes`` (axis name → 1-D array of values in the axis's unit),
    in C order: point k has the indices ``np.unravel_index(k, shape)``."""
    if isinstance(axes, Design):
        return axes
    if not isinstance(axes, Mapping):
        raise _bad(f"a grid is a dict of axis name -> 1-D array, got {type(axes).__name__}")
    _check_names(list(axes))
    arrays = {name: check_values(name, values) for name, values in axes.items()}
    n = math.prod(len(a) for a in arrays.values())
    if n > MAX_POINTS:
        sizes = " x ".join(str(len(a)) for a in arrays.values())
        raise _bad(f"the grid {sizes} has {n} points; at most 2^40")
    return Design("grid", tuple(arrays), n, axes=arrays)


def random(
    n: int,
    ranges: Mapping[str, tuple[float, float]],
    seed: int = 0,
    method: Literal["uniform", "lhs"] = "uniform",
) -> Design:
    """``n`` points with each axis in its range [lo, hi] (unit of the axis): independent uniform draws
    (``method="uniform"``) or a Latin hypercube (``"lhs"``), from ``np.random.default_rng(seed)``.
    The same arguments give the same points on every machine. A design whose points would not fit in
    the memory this process can still get is refused before any is drawn
    (:func:`pendulab.memory.check_memory`)."""
    if isinstance(n, bool) or not isinstance(n, int | np.integer) or not 1 <= n <= MAX_POINTS:
        raise _bad(f"n = {limits.show(n)} must be an integer number of points >= 1")
    if method not in RANDOM_METHODS:
        raise _bad(f"method = {limits.show(method)}: use one of {', '.join(RANDOM_METHODS)}")
    if isinstance(seed, bool) or not isinstance(seed, int | np.integer) or seed < 0:
        raise _bad(f"seed = {limits.show(seed)} must be an integer >= 0")
    if not isinstance(ranges, Mapping):
        raise _bad(f"ranges is a dict of axis name -> (lo, hi), got {type(ranges).__name__}")
    _check_names(list(ranges))
    bounds: dict[str, tuple[float, float]] = {}
    for name, r in ranges.items():
        try:
            lo, hi = (float(v) for v in r)
        except (TypeError, ValueError):
            raise _bad(
                f"range of {limits.show(name)}: expected (lo, hi) in {AXES[name]}, got {limits.show(r)}"
            ) from None
        check_values(name, [lo, hi])
        if not lo <= hi:
            raise _bad(
                f"range of {limits.show(name)}: lo = {limits.show(lo)} must be <= "
                f"hi = {limits.show(hi)} ({AXES[name]})"
            )
        bounds[name] = (lo, hi)
    # its columns, one draw and (lhs) one permutation at once: refused before anything is drawn
    check_memory(f"a random design of {int(n)} points", 8.0 * int(n) * (len(bounds) + 3), "draw fewer points")
    rng = np.random.default_rng(int(seed))
    values: dict[str, FloatArray] = {}
    for name, (lo, hi) in bounds.items():
        u = rng.random(int(n))
        if method == "lhs":
            u = (rng.permutation(int(n)) + u) / int(n)
        values[name] = np.ascontiguousarray(lo + (hi - lo) * u)
    info = {"seed": int(seed), "method": method, "ranges": {k: list(v) for k, v in bounds.items()}}
    return Design("random", tuple(values), int(n), values=values, info=info)


def points(columns: Mapping[str, Any]) -> Design:
    """Explicit points: one 1-D array per axis, all of the same length (row k is point k)."""
    if not isinstance(columns, Mapping):
        raise _bad(f"points is a dict of axis name -> 1-D array, got {type(columns).__name__}")
    _check_names(list(columns))
    values = {name: check_values(name, v) for name, v in columns.items()}
    lengths = {name: len(v) for name, v in values.items()}
    if len(set(lengths.values())) != 1:
        raise _bad(f"point columns must have equal lengths, got {lengths}")
    return Design("points", tuple(values), next(iter(lengths.values())), values=values)


def as_design(design: Any) -> Design:
    """A :class:`Design` as is; a dict of axis name → 1-D array as a :func:`grid`."""
    if isinstance(design, Design):
        return design
    if isinstance(design, Mapping):
        return grid(design)
    raise _bad(
        f"a sweep needs a grid (dict of axis name -> 1-D array) or a design from pendulab.sweeps.design, "
        f"got {type(design).__name__}"
    )
