"""The one validation layer: the table of limits and the checks every public entry point calls.

The table comes from the core's registry (``crates/pendulab-core/src/model/registry.rs``): the
shared model parameters length l [m], mass m [kg], gravity g [m/s²] and each model's own parameters
(:func:`pendulab.models`), and the bounds of everything else a run is made of (:func:`limits`):
positions [m], velocities [m/s], angles [rad], angle rates [rad/s], times [s], step sizes [s], the
planned number of steps (t_end − t₀)/dt, saved samples, bytes of saved samples, and the size [B]
and nesting of scenario and sweep files. The bounds are chosen so that every derived quantity
(energy m(½|v|² + g z) [J], tension m(|v|² + x·f)/l [N], J₃ [kg m²/s]) is finite and every amount
of work and memory is bounded before it starts; ``docs/limits.md`` gives the reason for each.

Every check raises :class:`pendulab.InvalidInputError` (a ``ValueError``) as
``invalid <name> = <value>: <allowed>`` with the value abbreviated to at most 80 characters.
"""

from __future__ import annotations

import math
import numbers
import os
import re
import sys
import tomllib
from collections.abc import Iterable
from typing import TYPE_CHECKING, Any

import numpy as np
import numpy.typing as npt

from ._core import IntegrationError, InvalidInputError
from ._core import limits as _core_limits
from ._core import models as _models

if TYPE_CHECKING:
    from ._core import ParamSpec

FloatArray = npt.NDArray[np.float64]

SHOW_CHARS = 80
"""The longest a bad value is echoed in an error message (characters)."""

LIMITS: dict[str, ParamSpec] = {p["name"]: p for p in _core_limits()}
"""The core's limits by name: position, velocity, angle, angle_rate, time, dt, steps, samples,
saved_bytes, file_bytes, file_nesting (each with unit, min, max, description = the reason, allowed)."""

COMMON: dict[str, ParamSpec] = {p["name"]: p for p in _models()[0]["params"][:3]}
"""The parameters every model shares: length [m], mass [kg], g [m/s²] with their limits."""

FILE_BYTES = int(LIMITS["file_bytes"]["max"])
"""The largest scenario or sweep file read [B] (checked before parsing)."""
FILE_NESTING = int(LIMITS["file_nesting"]["max"])
"""The deepest nesting of arrays and tables a scenario or sweep file may have (checked before parsing)."""
MAX_STEPS = LIMITS["steps"]["max"]
"""The most steps (t_end − t₀)/dt a fixed-step run may plan."""
MAX_SAMPLES = int(LIMITS["samples"]["max"])
"""The most samples a call may ask for (save times, evaluation times, sweep points, trajectories)."""


def limits() -> list[ParamSpec]:
    """Every limit: the shared model parameters (length [m], mass [kg], g [m/s²]) and the bounds of
    states, times, steps, samples, bytes and files, each a dict ``name``, ``unit``, ``default``,
    ``min``, ``max``, ``description`` (the reason for the bound) and ``allowed`` (in words). The
    models' own parameters and their limits: :func:`pendulab.models`. ``docs/limits.md`` lists both.

    Examples
    --------
    >>> import numpy as np
    >>> import pendulab as pl
    >>> lim = {row['name']: row for row in pl.limits()}
    >>> lim['length']['min'], lim['length']['max'], lim['length']['unit']
    (1e-06, 10000.0, 'm')
    """
    return [*COMMON.values(), *LIMITS.values()]


def show(value: Any) -> str:
    """``repr(value)`` abbreviated to at most :data:`SHOW_CHARS` characters (the middle elided)."""
    if isinstance(value, np.generic):  # np.float64(nan) -> nan
        value = value.item()
    try:
        text = repr(value)
    except Exception:  # a hostile __repr__ (or a value too large to print)
        text = f"<{type(value).__name__}>"
    return abbreviate(text)


def abbreviate(text: str) -> str:
    """``text`` shortened to at most :data:`SHOW_CHARS` characters, the middle elided as `` ... ``."""
    if len(text) <= SHOW_CHARS:
        return text
    half = (SHOW_CHARS - 5) // 2
    return f"{text[:half]} ... {text[-half:]}"


def invalid(name: str, value: Any, allowed: str) -> InvalidInputError:
    """The error for ``name = value`` (abbreviated) with what is allowed."""
    return InvalidInputError(f"invalid {name} = {show(value)}: {allowed}")


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


def choice(name: str, value: Any, options: Iterable[str]) -> str:
    """One of ``options`` (strings)."""
    opts = list(options)
    if not isinstance(value, str) or value not in opts:
        raise invalid(name, value, f"one of {', '.join(map(repr, opts))}")
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
    span = f"numbers in [{spec['min']:g}, {spec['max']:g}] {spec['unit']}".rstrip()
    what = (
        f"an array of {span}"
        if shape is None
        else f"{math.prod(shape)} {span}"
        if len(shape) == 1
        else f"an array of shape {shape} of {span}"
    )
    if isinstance(value, str | bytes | dict) or value is None:
        raise invalid(name, value, what)
    try:
        size = np.size(value) if isinstance(value, np.ndarray) else None
        if size is not None and size > max_size:
            raise invalid(name, f"<array of {size} values>", f"at most {max_size} values")
        arr = np.asarray(value)
    except InvalidInputError:
        raise
    except (TypeError, ValueError, OverflowError, RecursionError, MemoryError):
        raise invalid(name, value, what) from None
    if arr.dtype.kind not in "iuf" and not (arr.dtype == object and _all_real(arr)):
        raise invalid(name, value, what)
    if arr.size > max_size:
        raise invalid(name, f"<array of {arr.size} values>", f"at most {max_size} values")
    try:
        out = np.asarray(arr, dtype=np.float64)
        out = np.ascontiguousarray(out) if out.ndim else out.copy()
    except (TypeError, ValueError, OverflowError):
        raise invalid(name, value, what) from None
    if shape is not None and out.shape != shape:
        raise invalid(name, value, f"{what} (got shape {out.shape})")
    bad = ~(np.isfinite(out) & (out >= spec["min"]) & (out <= spec["max"]))
    if bad.any():
        i = np.unravel_index(int(np.argmax(bad)), out.shape) if out.ndim else ()
        where = "".join(f"[{k}]" for k in i)
        raise invalid(f"{name}{where}", arr[i] if out.ndim else arr.item(), spec["allowed"])
    return out


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


def require_finite_result(what: str, inputs: str, *arrays: Any) -> None:
    """Raises :class:`pendulab.IntegrationError` naming ``inputs`` when any of ``arrays`` holds a
    NaN or an infinity (so that no non-finite number leaves a call silently)."""
    for a in arrays:
        if a is not None and not np.all(np.isfinite(np.asarray(a, dtype=np.float64))):
            raise IntegrationError(
                f"{what} is not finite for {inputs}; this input is beyond what can be computed"
            )


_TOML_INTERESTING = re.compile(r"[\"'#\[\]{}.]")
"""What the nesting check stops at: a string or comment start, a bracket or brace, a dot."""
_KEY_BREAK = re.compile(r"[=,\n]")
"""What ends a dotted key outside strings (besides brackets and braces)."""
_BASIC_STOP = re.compile(r'[\\"\n]')
"""Where a one-line basic string may end: an escape, its closing quote, or the end of the line."""
_MULTILINE_STOP = re.compile(r'\\.|"""', re.S)
"""Where a multi-line basic string may end: an escape (skipped) or its closing triple quote."""


def _skip_string(text: str, i: int) -> int:
    """The position after the TOML string starting at ``text[i]`` (a quote); an unterminated string
    ends at its line's end (the parser reports it). Each character is looked at a bounded number of
    times: linear in the string's length, whatever it holds."""
    n = len(text)
    if text.startswith('"""', i):
        pos = i + 3
        while (m := _MULTILINE_STOP.search(text, pos)) is not None:
            if m.group() == '"""':
                return m.end()
            pos = m.end()
        return n
    if text.startswith("'''", i):
        j = text.find("'''", i + 3)
        return n if j < 0 else j + 3
    if text[i] == "'":  # a literal string: no escapes, ends at the next quote on its line
        j = text.find("'", i + 1)
        stop = n if j < 0 else j
        nl = text.find("\n", i + 1, stop)
        return nl if nl >= 0 else (n if j < 0 else j + 1)
    pos = i + 1
    while (m := _BASIC_STOP.search(text, pos)) is not None:
        c = m.group()
        if c == "\\":
            pos = m.end() + 1  # the escaped character, whatever it is
        elif c == '"':
            return m.end()
        else:
            return m.start()  # unterminated on its line
    return n


def read_file_capped(path: str | os.PathLike[str]) -> str:
    """The UTF-8 text of a scenario or sweep file, refused before parsing when it is larger than
    :data:`FILE_BYTES` (1 MiB; ``/dev/zero`` returns at once) or nests arrays and tables deeper than
    :data:`FILE_NESTING`. Read errors are ``OSError`` naming the file; a refusal is an
    :class:`InvalidInputError` saying what is allowed (the caller adds the file name). A UTF-8 byte
    order mark (Windows editors write one) is dropped."""
    source = os.fspath(path)
    try:
        with open(path, "rb") as f:
            raw = f.read(FILE_BYTES + 1)
    except OSError as e:
        raise OSError(e.errno, e.strerror or str(e), source) from None
    if len(raw) > FILE_BYTES:
        raise InvalidInputError(
            f"the file is larger than {FILE_BYTES} bytes (1 MiB); {LIMITS['file_bytes']['allowed']}"
        )
    try:
        text = raw.decode("utf-8").removeprefix("\ufeff")
    except UnicodeDecodeError as e:
        raise InvalidInputError(f"not UTF-8 text (byte {e.start}): TOML files must be UTF-8") from None
    check_nesting(text)
    return text


def check_nesting(text: str) -> None:
    """Refuses TOML text whose arrays and inline tables nest deeper than :data:`FILE_NESTING` (before
    parsing: the parser recurses once per level). A scanner, not a backtracking regular expression:
    linear time in the text's length whatever it holds (unterminated strings, runs of escapes).

    Dotted keys (``a.b.c = 1``) nest too, and tomllib's work for one grows with the square of its
    parts (16 000 parts: 15 s): more than :data:`FILE_NESTING` dots between two of ``= , [ ] { }`` or
    line ends (outside strings and comments) are refused before parsing. A value has at most one dot
    (a float, a time's fraction of a second)."""
    depth = deepest = pos = dots = 0
    while (m := _TOML_INTERESTING.search(text, pos)) is not None:
        c, i = m.group(), m.start()
        if _KEY_BREAK.search(text, pos, i):  # text[pos:i] is outside strings: each part looked at once
            dots = 0
        if c in "\"'":
            pos = _skip_string(text, i)
            continue
        if c == "#":  # a comment runs to the end of its line
            nl = text.find("\n", i)
            pos = len(text) if nl < 0 else nl + 1
            dots = 0
            continue
        pos = i + 1
        if c == ".":
            dots += 1
            if dots > FILE_NESTING:
                line = text.count("\n", 0, i) + 1
                raise InvalidInputError(
                    f"a dotted key nests more than {FILE_NESTING} levels deep (line {line}); "
                    f"{LIMITS['file_nesting']['allowed']}"
                )
            continue
        dots = 0
        if c in "[{":
            depth += 1
            deepest = max(deepest, depth)
            if deepest > FILE_NESTING:
                line = text.count("\n", 0, i) + 1
                raise InvalidInputError(
                    f"arrays or tables nest more than {FILE_NESTING} levels deep (line {line}); "
                    f"{LIMITS['file_nesting']['allowed']}"
                )
        else:
            depth = max(depth - 1, 0)


def parse_toml(text: str) -> dict[str, Any]:
    """TOML text from outside, parsed with the checks every reader needs: a UTF-8 byte order mark
    dropped, the nesting checked before parsing (:func:`check_nesting`) and after
    (:func:`check_depth`), and an integer too long for Python to convert (more than
    ``sys.get_int_max_str_digits()``, 4300 digits: tomllib raised a bare ``ValueError``) refused as
    :class:`InvalidInputError`. Bad syntax raises ``tomllib.TOMLDecodeError`` (the caller names the
    file, line and column)."""
    text = text.removeprefix("\ufeff")
    check_nesting(text)
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError:
        raise
    except ValueError:
        raise InvalidInputError(
            f"a number with more than {sys.get_int_max_str_digits()} digits; numbers in a file are "
            "SI values of at most a few dozen digits"
        ) from None
    check_depth(data)
    return data


def check_depth(data: Any) -> None:
    """Refuses parsed data (dicts and lists) nested deeper than :data:`FILE_NESTING` levels (dotted
    keys such as ``a.b.c`` nest without brackets). Iterative: no recursion on hostile input."""
    stack = [(data, 0)]
    while stack:
        item, depth = stack.pop()
        if depth > FILE_NESTING:
            allowed = LIMITS["file_nesting"]["allowed"]
            raise InvalidInputError(
                f"keys, arrays or tables nest more than {FILE_NESTING} levels deep; {allowed}"
            )
        if isinstance(item, dict):
            stack.extend((v, depth + 1) for v in item.values())
        elif isinstance(item, list):
            stack.extend((v, depth + 1) for v in item)


def param_spec(model: str, name: str) -> ParamSpec:
    """The registry's spec of parameter ``name`` of ``model`` (units, limits)."""
    return next(p for m in _models() if m["name"] == model for p in m["params"] if p["name"] == name)


def spec(name: str, unit: str, lo: float, hi: float, allowed: str) -> ParamSpec:
    """A spec for a setting of one entry point (e.g. an angle in (0, π]) in the shape of the table's."""
    return {
        "name": name,
        "label": name,
        "unit": unit,
        "default": lo,
        "min": lo,
        "max": hi,
        "description": "",
        "allowed": allowed,
    }


def _spec(limit: str | ParamSpec) -> ParamSpec:
    if isinstance(limit, str):
        return LIMITS[limit] if limit in LIMITS else COMMON[limit]
    return limit
