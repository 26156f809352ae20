"""The lab's command limits are one table (``crates/pendulab-core/src/live/wire.rs``, ``LIMITS``; through
the bindings ``pendulab._core.LiveSession.limits()``): the server's pydantic command models take their
bounds from it, so the server's check, its API schema and the core's check (the page's engine's too)
cannot drift apart. SI units as in the table (l, m [m, kg], g [m/s²], dt [s], time scale [1], n [steps])."""

from __future__ import annotations

from typing import Any, get_args

import annotated_types
import pytest
from pydantic import BaseModel

from pendulab._core import LiveSession
from pendulab.server import commands
from pendulab.server.protocol import (
    COMMAND_TYPES,
    CORE_LIMITS,
    LIMITS,
    MAX_MESSAGE_BYTES,
    Command,
    ExactRequest,
    SetMethod,
    SetParams,
    SetTimeScale,
    Step,
)

#: every bounded number of the commands and requests: (model, field) -> the core's limit it must equal
BOUNDED: dict[tuple[type[BaseModel], str], str] = {
    (SetParams, "length"): "length",
    (SetParams, "mass"): "mass",
    (SetParams, "g"): "g",
    (ExactRequest, "length"): "length",
    (ExactRequest, "mass"): "mass",
    (ExactRequest, "g"): "g",
    (SetMethod, "dt"): "dt",
    (SetTimeScale, "time_scale"): "time_scale",
    (Step, "n"): "n",
}


def _bounds(model: type[BaseModel], field: str) -> tuple[Any, Any]:
    """The ``ge`` and ``le`` of one pydantic field (None where it has none)."""
    meta = model.model_fields[field].metadata
    ge = next((m.ge for m in meta if isinstance(m, annotated_types.Ge)), None)
    le = next((m.le for m in meta if isinstance(m, annotated_types.Le)), None)
    return ge, le


def test_the_core_exposes_its_table() -> None:
    limits = LiveSession.limits()
    assert set(limits) == {"length", "mass", "g", "dt", "time_scale", "n"}
    for lim in limits.values():
        assert lim["min"] < lim["max"] and isinstance(lim["unit"], str)
    assert limits["length"] == {"min": 1e-3, "max": 1e3, "unit": "m"}


@pytest.mark.parametrize(("model", "field"), sorted(BOUNDED, key=lambda k: (k[0].__name__, k[1])))
def test_every_bounded_field_takes_the_cores_bounds(model: type[BaseModel], field: str) -> None:
    core = CORE_LIMITS[BOUNDED[(model, field)]]
    assert _bounds(model, field) == (core["min"], core["max"])


def test_every_command_field_with_a_bound_is_in_the_table() -> None:
    """No bounded number of a command left out of the comparison above (a new field with its own
    literal bounds would be a second table again)."""
    models = [m for m in vars(commands).values() if isinstance(m, type) and issubclass(m, BaseModel)]
    bounded = {
        (m, name)
        for m in models
        if m.__module__ == commands.__name__
        for name in m.model_fields
        if _bounds(m, name) != (None, None)
    }
    assert bounded == set(BOUNDED)
    assert {BOUNDED[k] for k in BOUNDED} == set(CORE_LIMITS)  # every limit of the core is used


def test_the_controls_schema_has_the_cores_bounds() -> None:
    names = {"length": "length", "mass": "mass", "g": "g", "dt": "dt", "time_scale": "time_scale"}
    names["step_n"] = "n"
    assert set(LIMITS) == set(names)
    for name, core in names.items():
        assert (LIMITS[name]["min"], LIMITS[name]["max"]) == (
            CORE_LIMITS[core]["min"],
            CORE_LIMITS[core]["max"],
        )


def test_message_length_and_command_types_are_the_cores() -> None:
    """The core's command types are exactly the server's command models' ``type`` tags, in order."""
    assert MAX_MESSAGE_BYTES == LiveSession.MAX_MESSAGE_BYTES == 4096
    tags = tuple(get_args(m.model_fields["type"].annotation)[0] for m in get_args(Command))
    assert tags == COMMAND_TYPES
