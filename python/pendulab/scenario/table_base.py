"""What every table of a scenario file shares: strict pydantic models (unknown keys are errors, no
type coercion, no NaN or inf), bounds taken from the table of limits (:mod:`pendulab.validate`:
positions [m], velocities [m/s], times [s]), text that is printable (no control characters), and a
value shown as the user wrote it in TOML for error messages. The tables themselves:
:mod:`pendulab.scenario.pendulum_table`, :mod:`pendulab.scenario.initial_table`,
:mod:`pendulab.scenario.simulation_table`; the whole file: :mod:`pendulab.scenario.schema`.
Units: SI (m, m/s, s; angles in rad, or in degrees where a key ends in ``_deg``: ``_DEG`` rad per degree).
"""

from __future__ import annotations

import math
from typing import Annotated, Any, TypedDict

from pydantic import BaseModel, ConfigDict, Field

from ..validate import COMMON, LIMITS, abbreviate

#: Radians per degree (keys ending in ``_deg``).
_DEG = math.pi / 180


class _Section(BaseModel):
    """Common settings: unknown keys are errors, no type coercion (a string is not a number), no NaN/inf."""

    model_config = ConfigDict(extra="forbid", strict=True, allow_inf_nan=False, frozen=True)


class _Length(TypedDict):
    """pydantic's bounds of a list's length (``Field(**_VEC3)``)."""

    min_length: int
    max_length: int


class _Bounds(TypedDict):
    """pydantic's bounds of a number (``Field(**_lim(name))``)."""

    ge: float
    le: float


_VEC3: _Length = {"min_length": 3, "max_length": 3}


def _lim(name: str) -> _Bounds:
    """pydantic bounds of entry ``name`` of the table of limits (:mod:`pendulab.validate`)."""
    spec = COMMON[name] if name in COMMON else LIMITS[name]
    return {"ge": spec["min"], "le": spec["max"]}


_Position = Annotated[float, Field(**_lim("position"))]
_Velocity = Annotated[float, Field(**_lim("velocity"))]
_Time = Annotated[float, Field(**_lim("time"))]


def printable(value: str, what: str, *, one_line: bool) -> str:
    """``value`` when it has no control characters (an ANSI escape sequence in a title would
    recolour, move or retitle the terminal that prints it); a description may have line breaks and
    tabs. A ``ValueError`` naming the character and its position otherwise."""
    allowed = "" if one_line else "\n\t"
    bad = next((c for c in value if _is_control(c) and c not in allowed), None)
    if bad is not None:
        raise ValueError(
            f"has the control character {bad!r} at character {value.index(bad) + 1}: a {what} is "
            f"printable text{' on one line' if one_line else ''} (no escape sequences)"
        )
    return value


def _is_control(c: str) -> bool:
    """A C0 or C1 control character or DEL (ESC starts ANSI sequences; U+009B is a one-character CSI)."""
    o = ord(c)
    return o < 0x20 or 0x7F <= o <= 0x9F


def _show(value: Any) -> str:
    """A value as the user would recognise it from the TOML file, abbreviated to 80 characters."""
    return abbreviate(_toml_like(value))


def _toml_like(value: Any) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, dict):
        return "{" + ", ".join(f"{k} = {_toml_like(v)}" for k, v in list(value.items())[:20]) + "}"
    if isinstance(value, list | tuple):
        return "[" + ", ".join(_toml_like(v) for v in value[:20]) + (", ..." if len(value) > 20 else "") + "]"
    return repr(value)
