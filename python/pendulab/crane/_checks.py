"""The checks of the crane's Python arguments, each a call of :mod:`pendulab.validate` (a real number, a
float64 array, an integer) with what the crane allows in words: a bad value — a string, None, a bool,
a complex number, an array where one number belongs, NaN, ±inf, a number out of range — is an
:class:`pendulab.InvalidInputError` ``invalid <name> = <value>: <allowed>`` (never a bare ValueError or
TypeError, never a NaN carried on). SI units: m, kg, s, rad, m/s, m/s², m/s³."""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np

from .. import memory
from ..validate import (
    LONGEST,
    LONGEST_TEXT,
    MAX_SAMPLES,
    SHORTEST,
    SHORTEST_TEXT,
    FloatArray,
    array,
    finite,
    invalid,
    spec,
)
from ..validate import number as number_within

ROPE_ALLOWED = f"in [{SHORTEST_TEXT}, {LONGEST_TEXT}] m (a pendulum's length, pl.limits() length)"
"""What a rope length [m] may be, in the messages (after "a finite number" or "finite numbers")."""


def real(name: str, value: Any, allowed: str, ok: Callable[[float], bool] = lambda _x: True) -> float:
    """A finite real number (not a bool, a string, None, a complex number or an array) for which
    ``ok`` holds; ``allowed`` says which, in words."""
    x = finite(name, value, allowed)
    if not ok(x):
        raise invalid(name, value, allowed)
    return x


def positive(name: str, value: Any, unit: str) -> float:
    """A finite number > 0 [``unit``]."""
    return real(name, value, f"a finite number > 0 {unit}".rstrip(), lambda x: x > 0)


def rope(name: str, value: Any) -> float:
    """A rope length: a finite number in [:data:`SHORTEST`, :data:`LONGEST`] [m]."""
    return real(name, value, f"a finite number {ROPE_ALLOWED}", lambda x: SHORTEST <= x <= LONGEST)


def ropes(name: str, value: Any) -> FloatArray:
    """Rope lengths (a hoist's samples): finite numbers in [:data:`SHORTEST`, :data:`LONGEST`] [m];
    the first bad entry is named."""
    allowed = f"finite numbers {ROPE_ALLOWED}"
    a = positives(name, value, "m", allowed)
    outside = (a < SHORTEST) | (a > LONGEST)
    if np.any(outside):
        i = np.unravel_index(int(np.argmax(outside)), a.shape) if a.ndim else ()
        raise invalid(name + "".join(f"[{k}]" for k in i), a[i] if a.ndim else a.item(), allowed)
    return a


def nonnegative(name: str, value: Any, unit: str) -> float:
    """A finite number ≥ 0 [``unit``]."""
    return real(name, value, f"a finite number >= 0 {unit}".rstrip(), lambda x: x >= 0)


def number(name: str, value: Any, unit: str) -> float:
    """Any finite number [``unit``] (a time, a position, a start value)."""
    return real(name, value, f"a finite number {unit}".rstrip())


def numbers(name: str, value: Any, unit: str, shape: tuple[int, ...] | None = None) -> FloatArray:
    """A float64 array of finite numbers [``unit``] (of ``shape`` if given)."""
    allowed = f"finite numbers {unit}".rstrip()
    return array(name, value, spec(name, unit, -np.inf, np.inf, allowed), shape=shape)


def positives(name: str, value: Any, unit: str, allowed: str | None = None) -> FloatArray:
    """A non-empty float64 array of finite numbers > 0 [``unit``]; the first bad entry is named with
    ``allowed`` (default "finite numbers > 0 ``unit``")."""
    allowed = allowed or f"finite numbers > 0 {unit}".rstrip()
    a = array(name, value, spec(name, unit, 0.0, np.inf, allowed))
    if a.size == 0:
        raise invalid(name, value, f"at least one of {allowed}")
    if np.any(a <= 0):
        i = np.unravel_index(int(np.argmax(a <= 0)), a.shape) if a.ndim else ()
        raise invalid(name + "".join(f"[{k}]" for k in i), a[i] if a.ndim else a.item(), allowed)
    return a


def time(name: str, value: Any) -> float:
    """A time [s] within the table's time limit (:data:`pendulab.validate.LIMITS` ``time``)."""
    return number_within(name, value, "time")


def times(name: str, value: Any) -> FloatArray:
    """Times [s] (a number or an array) within the time limit, as a float64 array of the same shape."""
    return array(name, value, "time")


def later(name: str, value: Any, start: float, start_name: str = "t_start") -> float:
    """A time [s] within the time limit and later than ``start`` (named ``start_name``)."""
    t = time(name, value)
    if not t > start:
        raise invalid(name, value, f"a time later than {start_name} = {start!r} s")
    return t


SAMPLE_BYTES = 30 * 8
"""Bytes one sample of a grid takes at the peak (:meth:`pendulab.crane.Path.knots`,
:meth:`~pendulab.crane.Path.pivot_samples`): its time, P, Ṗ, P̈ (10 float64) and the work arrays
beside them (about twice as many)."""


def count(name: str, span: float, spacing: float) -> int:
    """The samples ⌈span/spacing⌉ + 1 of a grid, refused (naming the spacing ``name``) when more than
    :data:`pendulab.validate.MAX_SAMPLES` or when their :data:`SAMPLE_BYTES` each exceed the memory
    budget of one call (:func:`pendulab.memory.check_memory`: 80 % of what this process can get)."""
    ratio = span / spacing  # may be inf for a tiny spacing
    if not ratio + 1 <= MAX_SAMPLES:
        raise invalid(
            name,
            spacing,
            f"at most {MAX_SAMPLES} samples over {span!r} s ({ratio:.3g} asked): a larger spacing",
        )
    n = math.ceil(ratio) + 1
    have = memory.available_bytes()
    if have is not None and n * SAMPLE_BYTES > memory.USABLE_FRACTION * have:
        most = int(memory.USABLE_FRACTION * have / SAMPLE_BYTES)
        raise invalid(
            name,
            spacing,
            f"at most {most} samples fit in the memory this process can get ({have / 2**30:.3g} GiB "
            f"available, {memory.USABLE_FRACTION:.0%} of it usable, {SAMPLE_BYTES} B a sample); {n} "
            f"asked over {span!r} s: a larger spacing or a shorter span",
        )
    return n


def tolerances(rtol: Any, atol: Any) -> tuple[float, float]:
    """DOP853's ``rtol`` (≥ 1e-14, as the core takes it) and ``atol`` (> 0)."""
    return real("rtol", rtol, "a finite number >= 1e-14", lambda x: x >= 1e-14), positive("atol", atol, "")
