"""The checks of single values and arrays every public entry point calls: real numbers within a
limit of the table (:mod:`pendulab.validate.table`; SI units: positions [m], velocities [m/s], times
[s], …), finite numbers, integers in a range, flags, choices, float64 arrays within a limit and of a
shape, the planned steps (t_end − t₀)/dt of a fixed-step run (and of all the trajectories of an
ensemble or a sweep), and results that must be finite.

Every check raises :class:`pendulab.InvalidInputError` (a ``ValueError``) naming the value and what
is allowed (:func:`pendulab.validate.table.invalid`); a non-finite result is an
:class:`pendulab.IntegrationError`.
"""

from __future__ import annotations

import difflib
import math
import numbers
from collections.abc import Iterable
from typing import TYPE_CHECKING, Any

import numpy as np
import numpy.typing as npt

from .._core import IntegrationError, InvalidInputError
from .table import LIMITS, MAX_SAMPLES, MAX_STEPS, _spec, invalid, show

if TYPE_CHECKING:
    from .._core import ParamSpec

FloatArray = npt.NDArray[np.float64]


def _real(name: str, value: Any, allowed: str) -> float:
    """``value`` as a float when it is a real number (not a bool, a string or None)."""
    scalar_array = isinstance(value, np.ndarray) and value.ndim == 0 and value.dtype.kind in "iuf"
    if isinstance(value, bool | np.bool_) or not (isinstance(value, numbers.Real) or scalar_array):
        raise invalid(name, value, allowed)
    try:
        x = float(value)
    except (OverflowError, TypeError, ValueError):
        raise invalid(name, value, allowed) from None
    if not math.isfinite(x):
        raise invalid(name, value, allowed)
    return x


def number(name: str, value: Any, limit: str | ParamSpec, *, positive: bool = False) -> float:
    """A real number within ``limit`` (a name of :data:`LIMITS` or :data:`COMMON`, or a parameter
    spec); ``positive`` also refuses 0."""
    spec = _spec(limit)
    x = _real(name, value, spec["allowed"])
    if not (spec["min"] <= x <= spec["max"]) or (positive and x <= 0.0):
        raise invalid(name, value, spec["allowed"])
    return x


def finite(name: str, value: Any, allowed: str = "a finite number") -> float:
    """A finite real number (for settings whose range the core checks)."""
    return _real(name, value, allowed)


def integer(name: str, value: Any, lo: int, hi: int, allowed: str | None = None) -> int:
    """An integer in [lo, hi] (a float with an integer value is accepted; a bool is not)."""
    allowed = allowed or f"an integer in [{lo}, {hi}]"
    if isinstance(value, bool | np.bool_):
        raise invalid(name, value, allowed)
    if isinstance(value, numbers.Integral):
        n = int(value)
    elif isinstance(value, numbers.Real):
        x = float(value)
        if not (math.isfinite(x) and x == int(x)):
            raise invalid(name, value, allowed)
        n = int(x)
    else:
        raise invalid(name, value, allowed)
    if not lo <= n <= hi:
        raise invalid(name, value, allowed)
    return n


def flag(name: str, value: Any) -> bool:
    """A bool (True/False, or a numpy bool)."""
    if not isinstance(value, bool | np.bool_):
        raise invalid(name, value, "True or False")
    return bool(value)


def did_you_mean(value: Any, options: Iterable[str]) -> str:
    """`` (did you mean 'x'?)`` for the option nearest to the string ``value`` (:func:`nearest`), or
    ``""``. Only a hint: the wrong case is never accepted."""
    near = nearest(value, options)
    return f" (did you mean {near!r}?)" if near is not None else ""


def nearest(value: Any, options: Iterable[str]) -> str | None:
    """The option nearest to the string ``value``, or None: an option equal to it but for case first,
    else the closest by :func:`difflib.get_close_matches` (what :func:`did_you_mean` suggests)."""
    if not isinstance(value, str):
        return None
    opts = list(options)
    near = [o for o in opts if o.casefold() == value.casefold()]
    near = near or difflib.get_close_matches(value[:100], opts, n=1)
    return near[0] if near else None


def choice(name: str, value: Any, options: Iterable[str]) -> str:
    """One of ``options`` (strings); the error names the nearest option (:func:`did_you_mean`)."""
    opts = list(options)
    if not isinstance(value, str) or value not in opts:
        raise invalid(name, value, f"one of {', '.join(map(repr, opts))}{did_you_mean(value, opts)}")
    return value


def array(
    name: str,
    value: Any,
    limit: str | ParamSpec,
    *,
    shape: tuple[int, ...] | None = None,
    max_size: int | None = None,
) -> FloatArray:
    """A float64 array of real numbers within ``limit`` (contiguous); ``shape`` (None: any) and at
    most ``max_size`` (default :data:`MAX_SAMPLES`) entries."""
    spec = _spec(limit)
    max_size = MAX_SAMPLES if max_size is None else max_size
    if isinstance(value, str | bytes | dict) or value is None:
        raise invalid(name, value, _what(spec, shape))
    try:
        size = np.size(value) if isinstance(value, np.ndarray) else None
        if size is not None and size > max_size:
            raise invalid(name, f"<array of {size} values>", f"at most {max_size} values")
        arr = np.asarray(value)
    except InvalidInputError:
        raise
    except (TypeError, ValueError, OverflowError, RecursionError, MemoryError):
        raise invalid(name, value, _what(spec, shape)) from None
    if arr.dtype.kind not in "iuf" and not (arr.dtype == object and _all_real(arr)):
        raise invalid(name, value, _what(spec, shape))
    if arr.size > max_size:
        raise invalid(name, f"<array of {arr.size} values>", f"at most {max_size} values")
    try:
        out = np.asarray(arr, dtype=np.float64)
        out = np.ascontiguousarray(out) if out.ndim else out.copy()
    except (TypeError, ValueError, OverflowError):
        raise invalid(name, value, _what(spec, shape)) from None
    if shape is not None and out.shape != shape:
        raise invalid(name, value, f"{_what(spec, shape)} (got shape {out.shape})")
    if out.size and _within(out, spec["min"], spec["max"]):
        return out  # the usual case, told by two reductions; else the entry to name is looked for
    bad = ~(np.isfinite(out) & (out >= spec["min"]) & (out <= spec["max"]))
    if bad.any():
        i = np.unravel_index(int(np.argmax(bad)), out.shape) if out.ndim else ()
        where = "".join(f"[{k}]" for k in i)
        raise invalid(f"{name}{where}", arr[i] if out.ndim else arr.item(), spec["allowed"])
    return out


def _what(spec: ParamSpec, shape: tuple[int, ...] | None) -> str:
    """What :func:`array` allows, for its error messages: the numbers and units, and the shape."""
    span = f"numbers in [{spec['min']:g}, {spec['max']:g}] {spec['unit']}".rstrip()
    if shape is None:
        return f"an array of {span}"
    return f"{math.prod(shape)} {span}" if len(shape) == 1 else f"an array of shape {shape} of {span}"


def _within(a: FloatArray, lo: float, hi: float) -> bool:
    """Every entry of the non-empty float64 array ``a`` finite and in [lo, hi]: its least and largest
    entry (a NaN makes both NaN, so false), no temporary array."""
    least, largest = float(a.min()), float(a.max())
    return math.isfinite(least) and math.isfinite(largest) and lo <= least and largest <= hi


def _all_real(arr: np.ndarray) -> bool:
    return all(isinstance(v, numbers.Real) and not isinstance(v, bool | np.bool_) for v in arr.flat)


def planned_steps(t0: float, t_end: float, dt: float, name: str = "t_end") -> float:
    """Refuses a fixed-step run of more than :data:`MAX_STEPS` steps (t_end − t₀)/dt before it starts."""
    steps = (t_end - t0) / dt
    if not steps <= MAX_STEPS:
        raise InvalidInputError(
            f"invalid {name} = {show(t_end)} with dt = {show(dt)} (t0 = {show(t0)}): (t_end - t0)/dt = "
            f"{steps:.3g} steps; {LIMITS['steps']['allowed']}"
        )
    return steps


def _count(x: float) -> str:
    """A count in 3 significant digits, exponents without sign or zeros: 48, 2.5e4, 1.2e11."""
    mantissa, _, exponent = f"{x:.3g}".partition("e")
    return mantissa if not exponent else f"{mantissa}e{int(exponent)}"


def planned_work(t_end: float, dt: float, count: int, unit: str, method: str, substeps: int) -> float:
    """Refuses, before it starts, a fixed-step run of ``count`` trajectories (``unit``: "trajectory",
    "point") whose RATTLE steps in all — count × t_end/dt steps × ``substeps`` RATTLE sub-steps per step
    of ``method`` (1 for RATTLE, 3, 7, 15 for its compositions) — exceed :data:`MAX_STEPS`; the
    message names that product and each factor with the caller's values (t_end, dt [s]), the limit and
    what lowers it. Returns the product."""
    steps = t_end / dt
    work = count * steps * substeps
    if not work <= MAX_STEPS:
        units = unit if count == 1 else ("trajectories" if unit == "trajectory" else unit + "s")
        sub = "" if substeps == 1 else f" × {substeps} RATTLE sub-steps per step of {method}"
        fixes = ["lower t_end", "raise dt"]
        fixes += [f"use fewer {units}"] if count > 1 else []
        fixes += ["use a method of fewer sub-steps"] if substeps > 1 else []
        raise InvalidInputError(
            f"{'the run' if count > 1 else 'one ' + unit} would take {_count(work)} RATTLE steps "
            f"({'' if count == 1 else f'{count} {units} × '}t_end/dt = {show(t_end)} s / {show(dt)} s = "
            f"{_count(steps)} steps{sub}), more than the limit of {_count(MAX_STEPS)}: "
            f"{', '.join(fixes[:-1])} or {fixes[-1]}"
        )
    return work


def require_finite_result(what: str, inputs: str, *arrays: Any) -> None:
    """Raises :class:`pendulab.IntegrationError` naming ``inputs`` when any of ``arrays`` holds a
    NaN or an infinity (so that no non-finite number leaves a call silently)."""
    for a in arrays:
        if a is not None and not np.all(np.isfinite(np.asarray(a, dtype=np.float64))):
            raise IntegrationError(
                f"{what} is not finite for {inputs}; this input is beyond what can be computed"
            )
