"""The table of limits every check reads, and the error every check raises.

The table comes from the core's registry (``crates/pendulab-core/src/limits.rs``, re-exported by
``model/registry.rs``): the shared model parameters length l [m], mass m [kg], gravity g [m/s²] and
each model's own parameters (:func:`pendulab.models`), and the bounds of everything else a run is made
of (:func:`limits`): positions [m], velocities [m/s], angles [rad], angle rates [rad/s], times [s],
step sizes [s], the planned number of steps, saved samples, bytes of saved samples, and the size [B]
and nesting of scenario and sweep files (``docs/limits.md`` gives the reason for each). An error is
``invalid <name> = <value>: <allowed>`` with the value abbreviated to at most :data:`SHOW_CHARS`
characters (:func:`invalid`).
"""

from __future__ import annotations

from collections.abc import Mapping
from functools import cache
from types import MappingProxyType
from typing import TYPE_CHECKING, Any

import numpy as np

from .._core import InvalidInputError
from .._core import limits as _core_limits
from .._core import models as _models

if TYPE_CHECKING:
    from .._core import ModelInfo, ParamSpec

SHOW_CHARS = 80
"""The longest a bad value is echoed in an error message (characters)."""

LIMITS: dict[str, ParamSpec] = {p["name"]: p for p in _core_limits()}
"""The core's limits by name: position, velocity, angle, angle_rate, time, dt, steps, samples,
saved_bytes, file_bytes, file_nesting (each with unit, min, max, description = the reason, allowed)."""


@cache
def model_table() -> tuple[ModelInfo, ...]:
    """The core's model registry (:func:`pendulab.models`), fetched once: it is compiled into the core,
    and a fit builds a model for every residual (each build checks its keywords against the table).
    Shared, so only read it; ``pendulab.models()`` gives a caller a fresh copy to keep."""
    return tuple(_models())


@cache
def model_params_of(model: str) -> Mapping[str, Mapping[str, Any]] | None:
    """The parameters of ``model`` by name (each spec with unit, default, min, max, allowed) from
    :func:`model_table`, read-only and built once per model; None for a name the registry lacks."""
    for m in model_table():
        if m["name"] == model:
            return MappingProxyType({p["name"]: MappingProxyType(dict(p)) for p in m["params"]})
    return None


COMMON: dict[str, ParamSpec] = {p["name"]: p for p in model_table()[0]["params"][:3]}
"""The parameters every model shares: length [m], mass [kg], g [m/s²] with their limits."""
SHORTEST = float(COMMON["length"]["min"])
"""The shortest pendulum, or crane rope [m]: ``pl.limits()`` ``length`` (1e-6 m; docs/limits.md)."""
LONGEST = float(COMMON["length"]["max"])
"""The longest pendulum, or crane rope [m]: ``pl.limits()`` ``length`` (1e4 m; docs/limits.md)."""
SHORTEST_TEXT = f"{SHORTEST:.0e}".replace("e-0", "e-")
""":data:`SHORTEST` as the messages write it (``1e-6``)."""
LONGEST_TEXT = f"{LONGEST:.0e}".replace("e+0", "e")
""":data:`LONGEST` as the messages write it (``1e4``)."""

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


def param_spec(model: str, name: str) -> ParamSpec:
    """The registry's spec of parameter ``name`` of ``model`` (units, limits)."""
    return next(p for m in model_table() if m["name"] == model for p in m["params"] if p["name"] == name)


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
