"""The lab's notices and refusals (docs/web.md, "Notices", "Languages"): the JSON ``error`` and
``event`` notices the server sends, the message keys a page translates (``messages.json`` beside this
file: key → English words with ``{placeholders}``), and the words of a refused command or request —
:class:`CommandError`, :func:`validation_problems` naming every problem of a pydantic error and
:func:`validation_key` the key of one the page translates. Numbers in SI units as the commands'.
"""

from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Any

from pydantic import ValidationError

from .._numbers import shown

#: the error notices a page translates: key -> English words with {placeholders} (``messages.json``)
MESSAGES: dict[str, str] = {
    k: v
    for k, v in json.loads(Path(__file__).with_name("messages.json").read_text(encoding="utf-8")).items()
    if not k.startswith("_")
}


class CommandError(ValueError):
    """A message that is not a valid command; ``command`` is its type when that could be read; ``key``
    and ``values`` name the message for a page that translates it (``messages.json``; None: not keyed)."""

    def __init__(
        self,
        message: str,
        command: str | None = None,
        key: str | None = None,
        values: dict[str, Any] | None = None,
    ) -> None:
        super().__init__(message)
        self.command = command
        self.key = key
        self.values = values or {}


class KeyedValueError(ValueError):
    """A command validator's refusal (its English words) with the message key and values a page words it
    by (``messages.json``: an unknown model or parameter); pydantic keeps it as the error's
    ``ctx["error"]``, where :func:`validation_key` finds it."""

    def __init__(self, words: str, key: str, **values: str) -> None:
        super().__init__(words)
        self.key = key
        self.values = values


def show_value(value: Any) -> str:
    """A value of a refused message as the user wrote it: a string quoted, a number by
    :func:`pendulab._numbers.shown` (``1e-9``, ``-1``; not ``1e-09``, ``-1.0``), else its JSON (``NaN``
    as JSON writes it); at most 80 characters."""
    if isinstance(value, str):
        text = repr(value)
    elif isinstance(value, float) and math.isfinite(value):
        text = shown(value)
    else:
        text = json.dumps(value, allow_nan=True)
    return text if len(text) <= 80 else text[:77] + "..."


def validation_problems(e: ValidationError, skip: int = 0) -> str:
    """One line naming every problem of a pydantic error (``skip`` leading location parts, e.g. the
    union tag)."""
    return "; ".join(_problem(err, skip) for err in e.errors())


def _problem(err: Any, skip: int) -> str:
    loc = [str(p) for p in err["loc"][skip:]]
    key = ".".join(loc)
    msg = str(err["msg"])
    if err["type"] == "value_error":
        msg = str(err.get("ctx", {}).get("error", msg))
        return f"{key}: {msg}" if key else msg
    if err["type"] == "extra_forbidden":
        return f"unknown key {key!r}"
    if err["type"] == "missing":
        return f"{key} is missing"
    if err["type"] in _BOUND_WORDS:  # pydantic writes the limit 1e-6 as 0.000001
        limit = err.get("ctx", {}).get(_KEYED[err["type"]][1])
        msg = f"input should be {_BOUND_WORDS[err['type']]} {show_value(limit)}"
    return f"{key} = {show_value(err.get('input'))}: {msg[:1].lower()}{msg[1:]}"


#: pydantic's error types the page translates: type -> (message key, the limit's name in ``ctx``)
_KEYED = {
    "greater_than_equal": ("too_small", "ge"),
    "greater_than": ("too_small_strict", "gt"),
    "less_than_equal": ("too_large", "le"),
    "less_than": ("too_large_strict", "lt"),
    "missing": ("missing", None),
    "extra_forbidden": ("unknown_key", None),
}


#: the words of pydantic's bounds, with the limit written by :func:`show_value`
_BOUND_WORDS = {
    "greater_than_equal": "greater than or equal to",
    "greater_than": "greater than",
    "less_than_equal": "less than or equal to",
    "less_than": "less than",
}


def validation_key(e: ValidationError, skip: int = 0) -> tuple[str | None, dict[str, Any]]:
    """The message key and values (``messages.json``) of a pydantic error with one problem of a kind the
    page translates; ``(None, {})`` otherwise (the page shows the English message)."""
    errors = e.errors()
    keyed = errors[0].get("ctx", {}).get("error") if len(errors) == 1 else None
    if isinstance(keyed, KeyedValueError):  # a validator's own refusal (an unknown model or parameter)
        return keyed.key, dict(keyed.values)
    if len(errors) != 1 or errors[0]["type"] not in _KEYED:
        return None, {}
    err = errors[0]
    key, limit = _KEYED[err["type"]]
    values: dict[str, Any] = {"name": ".".join(str(p) for p in err["loc"][skip:])}
    if limit is not None:
        values |= {"value": show_value(err.get("input")), "limit": show_value(err.get("ctx", {}).get(limit))}
    return key, values


def message(key: str, **values: Any) -> str:
    """The English words of message ``key`` (``messages.json``) with ``values`` filled in."""
    return MESSAGES[key].format(**values)


def keyed_body(key: str, **values: Any) -> dict[str, Any]:
    """The JSON body of an HTTP error answer of message ``key``: the English ``detail``, and for a page
    that translates it, ``key`` and ``values``."""
    return {"detail": message(key, **values), "key": key, "values": values}


def keyed_notice(key: str, command: str | None = None, **values: Any) -> dict[str, Any]:
    """An ``error`` notice of message ``key``: its English words, the key and the values."""
    return error_notice(message(key, **values), command, key, values)


def error_notice_of(e: CommandError) -> dict[str, Any]:
    """The ``error`` notice of a refused command (keyed when the error is)."""
    return error_notice(str(e), e.command, e.key, e.values)


def error_notice(
    message: str, command: str | None = None, key: str | None = None, values: dict[str, Any] | None = None
) -> dict[str, Any]:
    """The JSON ``error`` notice; with ``key`` (``messages.json``) and its ``values`` for a page that
    translates the message."""
    notice: dict[str, Any] = {"type": "error", "message": message, "command": command}
    if key is not None:
        notice |= {"key": key, "values": values or {}}
    return notice


def event_notice(event: dict[str, Any], epoch: int, skipped: int = 0) -> dict[str, Any]:
    """The JSON ``event`` notice of one of the string's events as the core reports it
    (``StringStepper.take_events()``): ``kind`` "slack" (the tension reached 0, the bob leaves the
    sphere) or "taut" (the string snaps taut again), the time ``t`` [s], ``energy_lost`` [J] (0 for a
    leave, ½m(1 − e²)u² for a snap), the bob's position ``x`` just after [m], the ``epoch`` it belongs
    to, and ``skipped``: how many earlier events of the same tick were not sent (see
    :data:`pendulab.server.session.MAX_EVENT_NOTICES`)."""
    return {
        "type": "event",
        "kind": str(event["kind"]),
        "t": float(event["t"]),
        "energy_lost": float(event["energy_lost"]),
        "x": [float(c) for c in event["x"]],
        "epoch": int(epoch),
        "skipped": int(skipped),
    }


def finite_or_none(value: float | None) -> float | None:
    """JSON has no inf/NaN: such values (and None) become null."""
    if value is None or not math.isfinite(value):
        return None
    return float(value)
