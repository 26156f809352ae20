"""Error messages of scenario files: what is wrong, where, and what is allowed.

Holds :class:`ScenarioError` (the one exception of scenario files: the file, the line of a TOML
syntax error, one message per problem) and the machinery turning pydantic's validation errors and
tomllib's syntax errors into those messages: the dotted key as written in the file, the bad value
as TOML shows it, and the allowed values with their units (SI: m, kg, s, rad; ``*_deg`` keys in
degrees), taken from the field descriptions of :mod:`pendulab.scenario.schema` and, for a model's
own parameters, from the core's model registry.
"""

from __future__ import annotations

import re
import tomllib
import typing
from collections.abc import Callable
from typing import Any

from pydantic import AliasChoices, BaseModel
from pydantic.fields import FieldInfo
from pydantic_core import ErrorDetails

from .._numbers import shown
from ..model.registry import elsewhere
from ..validate import abbreviate, did_you_mean, nearest
from .schema import (
    _COMMON_KEYS,
    MODELS,
    SECTIONS,
    ScenarioSpec,
    _degree_keys,
    _file_keys,
    _model_keys,
    _own_params,
    _show,
)

MOST_SHOWN = 5
"""The most problems the message of a scenario file's error shows (:class:`ScenarioError`, and a crane
file's ``pendulab.crane.CraneFileError``); the error's ``problems`` keeps them all."""


def describe(problems: list[str], most: int = MOST_SHOWN) -> str:
    """The problems of a file as one message: at most ``most`` of them, numbered when several, with
    how many more there are: ``7 problems: (1) … (5) … (and 2 more)``."""
    if len(problems) == 1:
        return problems[0]
    more = f" (and {len(problems) - most} more)" if len(problems) > most else ""
    shown = " ".join(f"({k}) {p}" for k, p in enumerate(problems[:most], 1))
    return f"{len(problems)} problems: {shown}{more}"


class ScenarioError(ValueError):
    """A scenario file (or string) cannot be used.

    ``source`` names the file, ``line`` the line of a TOML syntax error (else ``None``) and
    ``problems`` lists one readable message per problem (all of them), each naming the key, the bad
    value and what is allowed. ``str(error)`` is a single line: ``"<source>: <problem>"``, or with
    several the first :data:`MOST_SHOWN` numbered and how many more there are (:func:`describe`;
    ``pendulab validate`` prints every one).
    """

    def __init__(self, source: str, problems: str | list[str], line: int | None = None) -> None:
        self.source = source
        self.line = line
        self.problems = [problems] if isinstance(problems, str) else list(problems)
        super().__init__(f"{self.location}: {describe(self.problems)}")

    @property
    def location(self) -> str:
        """The file name, with the line number for TOML syntax errors."""
        return self.source if self.line is None else f"{self.source}, line {self.line}"


_TYPE_PROBLEMS = {
    "float_type": "is not a number",
    "int_type": "is not an integer",
    "string_type": "is not a string",
    "bool_type": "is not true or false",
    "list_type": "is not an array",
    "model_type": "is not a table",
    "dict_type": "is not a table",
    "finite_number": "is not a finite number (nan and inf are not allowed)",
}


_BOUNDS = {
    "greater_than": ("gt", ">"),
    "greater_than_equal": ("ge", ">="),
    "less_than": ("lt", "<"),
    "less_than_equal": ("le", "<="),
}


def _model_at(loc: tuple[int | str, ...], root: type[BaseModel] = ScenarioSpec) -> type[BaseModel] | None:
    """The pydantic model holding the key at ``loc`` (None if there is none), from ``root`` (the
    pendulum's :class:`ScenarioSpec` or the crane's ``CraneSpec``); an optional table counts."""
    model: type[BaseModel] = root
    for part in loc[:-1]:
        if not isinstance(part, str):
            return None
        info = model.model_fields.get(part)
        sub = info.annotation if info is not None else None
        options = typing.get_args(sub) if typing.get_args(sub) else (sub,)
        tables = [o for o in options if isinstance(o, type) and issubclass(o, BaseModel)]
        if not tables:
            return None
        model = tables[0]
    return model


def _allowed(loc: tuple[int | str, ...], root: type[BaseModel] = ScenarioSpec) -> str | None:
    keys = tuple(p for p in loc if isinstance(p, str))
    model = _model_at(keys, root)
    if model is None or not keys:
        return None
    info = model.model_fields.get(keys[-1])
    if info is None:  # a key read under an older name (a crane's [simulation] dt: output_spacing)
        info = next((f for f in model.model_fields.values() if _older_name(f, keys[-1])), None)
    return None if info is None else info.description


def _older_name(info: FieldInfo, key: str) -> bool:
    """True when ``key`` is one of the names a field is also read under (its ``validation_alias``)."""
    alias = info.validation_alias
    return isinstance(alias, AliasChoices) and key in alias.choices


def _key(loc: tuple[int | str, ...]) -> str:
    out = ""
    for part in loc:
        out += f"[{part}]" if isinstance(part, int) else (f".{part}" if out else part)
    return out


def _pendulum_model(data: Any) -> str:
    """The model named in the raw ``[pendulum]`` table (``"ideal"`` when absent or not a string)."""
    table = data.get("pendulum") if isinstance(data, dict) else None
    model = table.get("model", "ideal") if isinstance(table, dict) else "ideal"
    return model if isinstance(model, str) else "ideal"


def _unknown_pendulum_key(name: str, value: Any, model: str) -> str:
    """An unknown key of ``[pendulum]``: the nearest key of the chosen model, else the models whose key it
    is in the words of ``pl.Pendulum`` (:func:`pendulab.model.registry.elsewhere`), and the model's keys."""
    keys = _file_keys(model)
    text = f"unknown key pendulum.{abbreviate(name)} = {_show(value)}"
    other = elsewhere(model, name, keys, {m: _model_keys(m)[len(_COMMON_KEYS) :] for m in MODELS})
    text += f": {other}" if other is not None else did_you_mean(name, keys)
    return text + f"; allowed keys in [pendulum] for model {model!r}: {', '.join(keys)}"


def _shown_loc(loc: tuple[int | str, ...]) -> tuple[int | str, ...]:
    """``loc`` as a line shows it: a model parameter ``("pendulum", "params", name)`` as written in the
    file, ``("pendulum", name)``."""
    return ("pendulum", str(loc[2])) if loc[:2] == ("pendulum", "params") and len(loc) == 3 else loc


def _is_table(loc: tuple[int | str, ...], root: type[BaseModel]) -> bool:
    """Whether ``loc`` (as shown) is a whole table of the file (``[pendulum]``, ``[crane]``, …)."""
    return len(loc) == 1 and (loc[0] in SECTIONS or loc[0] in root.model_fields)


def _missing_name(loc: tuple[int | str, ...], root: type[BaseModel]) -> str:
    """How :func:`_problem` names a missing key: ``table [simulation]`` or the dotted key
    (``pendulum.length``)."""
    shown_loc = _shown_loc(loc)
    key = abbreviate(_key(shown_loc))
    return f"table [{key}]" if _is_table(shown_loc, root) else key


def _problem(err: ErrorDetails, data: Any = None, root: type[BaseModel] = ScenarioSpec) -> str:
    """One readable line for one pydantic error: the dotted key, the bad value, what is allowed.
    ``data`` is the raw input (it names the model whose keys ``[pendulum]`` takes); ``root`` the
    file's schema (the crane's ``CraneSpec`` for a file with ``[crane]``)."""
    loc = tuple(err["loc"])
    kind, value = err["type"], err.get("input")
    if kind == "extra_forbidden" and len(loc) == 2 and loc[0] == "pendulum" and root is ScenarioSpec:
        return _unknown_pendulum_key(str(loc[1]), value, _pendulum_model(data))
    allowed = _allowed(loc, root)
    if loc[:2] == ("pendulum", "params") and len(loc) == 3:  # a model parameter: shown as written
        model = _pendulum_model(data)
        name = str(loc[2])
        spec = _own_params(model).get(_degree_keys(model).get(name, name))
        if spec is not None:
            unit = "degrees" if name.endswith("_deg") else spec["unit"]
            allowed = f"{spec['allowed']} (in {unit}; {spec['description']})"
    loc = _shown_loc(loc)
    key = abbreviate(_key(loc))
    if kind == "missing" and _is_table(loc, root):
        return f"the table [{key}] is missing"
    if kind == "missing":
        return f"{key} is missing; expected {allowed}" if allowed else f"{key} is missing"
    if kind == "extra_forbidden":
        parent = _model_at(loc, root)
        names = list(parent.model_fields) if parent is not None else []
        section = f"[{_key(loc[:-1])}]" if len(loc) > 1 else "the top level"
        hint = did_you_mean(str(loc[-1]), names)
        return f"unknown key {key} = {_show(value)}{hint}; allowed keys in {section}: {', '.join(names)}"
    if kind == "value_error":
        reason = str(err.get("ctx", {}).get("error", err["msg"]))
        return f"[{key}] {reason}" if key and isinstance(value, dict) else f"{key} = {_show(value)}: {reason}"
    ctx = err.get("ctx", {})
    if kind in _TYPE_PROBLEMS:
        reason = _TYPE_PROBLEMS[kind]
    elif kind in ("too_short", "too_long") and ctx.get("min_length") == ctx.get("max_length") is not None:
        reason = f"must have exactly {ctx['min_length']} items, not {ctx.get('actual_length')}"
    elif kind in ("too_short", "too_long"):
        reason = err["msg"].replace("List should", "must").replace(" after validation", "")
    elif kind in _BOUNDS:
        bound = ctx[_BOUNDS[kind][0]]
        number = isinstance(bound, int | float) and not isinstance(bound, bool)
        reason = f"must be {_BOUNDS[kind][1]} {shown(bound) if number else repr(bound)}"
    else:  # anything else: pydantic says "Input should be …"
        reason = re.sub(r"^(Input|Value|List) should", "must", err["msg"])
    text = (
        f"{key} = {_show(value)} {reason}" if kind in _TYPE_PROBLEMS else f"{key} = {_show(value)}: {reason}"
    )
    return f"{text}; allowed: {allowed}" if allowed else text


EMPTY_FILE = (
    "nothing in it (an empty file, or only comments): a scenario file has the tables [pendulum], [initial] "
    "and [simulation], a crane file [crane] and [simulation] (docs/scenarios.md; `pendulab scenarios` "
    "lists the examples)"
)
"""The problem of a scenario or crane file without a key: what such a file holds, not each missing table."""


def file_problems(
    errors: list[ErrorDetails], data: Any = None, root: type[BaseModel] = ScenarioSpec
) -> list[str]:
    """One readable line per problem of a file (:func:`_problem`), unknown keys first, a typo of a
    required key one problem (:func:`merge_typos`: ``unknown key pendulum.lenght = 2 (did you mean
    'length'? so the required pendulum.length is missing)``)."""
    return merge_typos(
        errors,
        problem=lambda err: _problem(err, data, root),
        keys_of=lambda table: _keys_of(table, data, root),
        missing_name=lambda err: _missing_name(tuple(err["loc"]), root),
    )


def merge_typos(
    errors: list[ErrorDetails],
    problem: Callable[[ErrorDetails], str],
    keys_of: Callable[[tuple[int | str, ...]], list[str]],
    missing_name: Callable[[ErrorDetails], str],
) -> list[str]:
    """``problem(err)`` for each error, unknown keys first. A typo of a required key is one problem, not
    two: when an unknown key's did-you-mean (among ``keys_of(its table)``) is a key or table that is
    missing in the same table, the unknown key's line says so (``... (did you mean 'length'? so the
    required <missing_name(the missing key's error)> is missing)``) and the missing key is not listed
    again. Scenario, crane and sweep files share this rule."""
    ordered = sorted(errors, key=lambda err: err["type"] != "extra_forbidden")
    missing = {tuple(err["loc"]): err for err in ordered if err["type"] == "missing"}
    said: set[tuple[int | str, ...]] = set()
    out: list[str] = []
    for err in ordered:
        loc = tuple(err["loc"])
        if err["type"] == "missing" and loc in said:
            continue
        text = problem(err)
        if err["type"] == "extra_forbidden" and loc and isinstance(loc[-1], str):
            near = nearest(loc[-1], keys_of(loc[:-1]))
            lost = (*loc[:-1], near or "")
            hint = did_you_mean(loc[-1], [near or ""])
            if near is not None and lost in missing and lost not in said and hint in text:
                said.add(lost)
                required = f"{hint[:-2]}? so the required {missing_name(missing[lost])} is missing)"
                text = text.replace(hint, required, 1)
        out.append(text)
    return out


def _keys_of(table: tuple[int | str, ...], data: Any, root: type[BaseModel]) -> list[str]:
    """The keys the table at ``table`` takes (the top level for ``()``), as its unknown keys' did-you-mean
    chooses among them (``[pendulum]``: the keys of the file's model)."""
    if table == ("pendulum",) and root is ScenarioSpec:
        return _file_keys(_pendulum_model(data))
    model = _model_at((*table, ""), root)
    return list(model.model_fields) if model is not None else []


def _syntax_error(source: str, text: str, err: tomllib.TOMLDecodeError) -> ScenarioError:
    message = str(err)
    line: int | None = getattr(err, "lineno", None)
    column: int | None = getattr(err, "colno", None)
    if m := re.search(r"\s*\(at line (\d+), column (\d+)\)$", message):
        line, column = int(m.group(1)), int(m.group(2))
        message = message[: m.start()]
    elif m := re.search(r"\s*\(at end of document\)$", message):
        line = text.count("\n") + 1
        message = message[: m.start()] + " at the end of the file"
    where = f" (column {column})" if column else ""
    return ScenarioError(source, f"invalid TOML: {message[:1].lower()}{message[1:]}{where}", line=line)
