"""The core's model registry as the Python side sees it (docs/theory.md §7): the models by name —
ideal, damped (damping, drag, dry friction, periodic forcing, any gravity direction), rotating frame,
moving pivots, string, swinging spring, hoisted rope — each with its parameters (SI unit, default,
limits, what is allowed); which model a set of keyword parameters names; and the check of a model's
keyword parameters before the core builds it.

Length l [m], mass m [kg] and g [m/s²] come first in every model; the rest are each model's own
(units as :func:`models` lists them).
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from .._core import InvalidInputError
from .._core import models as _models
from ..validate import choice, did_you_mean, finite, invalid, model_params_of, model_table, show

if TYPE_CHECKING:
    from .._core import ModelInfo


def models() -> list[ModelInfo]:
    """The model registry (docs/theory.md §7): one dict per model with ``name``, ``summary``,
    ``interactive`` (runs with the incremental :class:`pendulab.Stepper`; False for ``string``,
    ``spring`` and ``sampled_pivot``, which run with ``pl.simulate`` / ``pendulab run`` — the web lab
    runs the string and the spring too, with their own core steppers) and
    ``params``,
    a list of dicts ``name``, ``unit`` (SI), ``default``, ``min``, ``max`` (±inf for none),
    ``description`` and ``allowed`` (in words). Length [m], mass [kg] and g [m/s²] come first in every
    model; the rest are the model's own keywords of :class:`Pendulum` and keys of scenario files.
    ``pendulab models`` prints the same table.

    Examples
    --------
    >>> import numpy as np
    >>> import pendulab as pl
    >>> [m['name'] for m in pl.models()][:3]
    ['ideal', 'damped', 'rotating']
    >>> damped = next(m for m in pl.models() if m['name'] == 'damped')
    >>> [(q['name'], q['unit']) for q in damped['params']][3:5]
    [('damping', '1/s'), ('drag', '1/m')]
    """
    return _models()


def _infer_model(keys: set[str]) -> str:
    """The first registered model whose parameters include all of ``keys`` (``"ideal"`` for none);
    ``"damped"`` when none has them all (the core then names the parameter it does not know)."""
    if not keys:
        return "ideal"
    for m in model_table():
        if keys <= {p["name"] for p in m["params"]}:
            return m["name"]
    return "damped"


def infer_model(extra: dict[str, float]) -> str:
    """The model ``Pendulum(**extra)`` without ``model=`` names (:func:`_infer_model`); a keyword that
    no model has, or keywords that no one model has together, is an :class:`InvalidInputError` naming
    them (with the nearest name, or the models that have each) — not "the 'damped' model has no
    parameter", a model the caller never named."""
    owners: dict[str, list[str]] = {p["name"]: [] for m in model_table() for p in m["params"]}
    for m in model_table():
        for q in m["params"]:
            owners[q["name"]].append(m["name"])
    unknown = {k: v for k, v in extra.items() if k not in owners}
    if unknown:
        each = "; ".join(
            f"no model has a parameter {k!r}{did_you_mean(k, [*owners, 'model', 'pivot_samples', 'force'])}"
            for k in unknown
        )
        takes = "Pendulum takes length, g, mass, model, pivot_samples, force and the models' own parameters"
        raise refused(unknown, f"{each}; {takes} (pendulab.models(), `pendulab models`)")
    model = _infer_model(set(extra))
    if not set(extra) <= {p["name"] for m in model_table() if m["name"] == model for p in m["params"]}:
        given = ", ".join(f"{k} = {show(v)}" for k, v in extra.items())
        which = "; ".join(f"{k}: {', '.join(owners[k])}" for k in extra)
        raise InvalidInputError(
            f"invalid parameters {given}: no one model has all of them (the models of each: {which}); "
            "give model='…' and that model's parameters (pendulab.models(), `pendulab models`)"
        )
    return model


def check_model_keywords(model: str | None, extra: dict[str, float]) -> None:
    """``model`` (when given) is a registered name, and each keyword parameter a short name with a
    finite value (within the model's limits when it is one of ``model``'s parameters; the core then
    checks names and ranges against the model inferred or given)."""
    own: Mapping[str, Mapping[str, Any]] = {}
    if model is not None:
        choice("model", model, [m["name"] for m in model_table()])
        own = model_params_of(model) or {}
        names = list(own)
        unknown = {k: v for k, v in extra.items() if k not in names}
        if unknown:
            raise refused(unknown, not_of_model(model, list(unknown), names))
    for key, value in extra.items():
        if len(key) > 64:
            raise invalid("parameter name", key, "a parameter of the model (pendulab.models())")
        finite(
            str(key),
            value,
            own[key]["allowed"] if key in own else f"a finite number (pendulab.models() lists {key!r})",
        )


@dataclass(frozen=True)
class Elsewhere:
    """A keyword ``key`` that ``model`` does not have but other models do, the same but for case:
    ``name`` the parameter's own name, ``owners`` the models whose parameter it is (the registry's
    order). ``str()`` is the one wording of it — ``pl.Pendulum``, scenario files and the lab's commands:
    ``damping is a parameter of model 'damped' (and 'rotating', …), not of 'ideal'``, after ``the 'ideal'
    model has no parameter 'DAMPING' (did you mean 'damping'?); `` for a key in another case."""

    model: str
    key: str
    name: str
    owners: tuple[str, ...]

    def __str__(self) -> str:
        also = f" (and {', '.join(map(repr, self.owners[1:]))})" if len(self.owners) > 1 else ""
        where = f"{self.name} is a parameter of model {self.owners[0]!r}{also}, not of {self.model!r}"
        if self.key != self.name:  # the wrong case: said first, the right name then placed
            hint = did_you_mean(self.key, [self.name])
            where = f"the {self.model!r} model has no parameter {self.key!r}{hint}; {where}"
        return where


def elsewhere(
    model: str, key: str, names: Iterable[str], params: Mapping[str, Iterable[str]] | None = None
) -> Elsewhere | None:
    """The other models whose parameter the keyword ``key`` is, which ``model`` (whose keys are
    ``names``) refuses — None when one of ``names`` is near ``key`` (:func:`pendulab.validate.did_you_mean`
    says that one) or no other model has it. ``params``: each model's keys by name where the caller
    takes other keys than the registry's parameters (a scenario file's ``<name>_deg``, the lab's
    models only); default every model's parameters (:func:`models`)."""
    if did_you_mean(key, names):
        return None
    if params is None:
        params = {m["name"]: [q["name"] for q in m["params"]] for m in model_table()}
    fold = str(key).casefold()
    name = next((q for qs in params.values() for q in qs if q.casefold() == fold), None)
    owners = tuple(m for m, qs in params.items() if m != model and name in set(qs))
    return Elsewhere(model, str(key), name, owners) if name is not None and owners else None


def not_of_model(model: str, keys: list[str], names: list[str]) -> str:
    """Why ``model`` (whose parameters are ``names``) refuses the keywords ``keys``: for each, the nearest
    of its own parameters (:func:`pendulab.validate.did_you_mean`), else the other models whose parameter
    it is, the same but for case (:func:`elsewhere`); then the model's parameters, once."""
    each = []
    for key in keys:
        other = elsewhere(model, key, names)
        each.append(
            str(other)
            if other is not None
            else f"the {model!r} model has no parameter {key!r}{did_you_mean(key, names)}"
        )
    return f"{'; '.join(each)}; its parameters: {', '.join(names)}"


def refused(unknown: Mapping[str, Any], why: str) -> InvalidInputError:
    """The refusal of the keywords ``unknown`` (name → value): ``invalid parameter foo = 1: <why>`` for
    one, ``invalid parameters foo = 1, bar = 2: <why>`` for several (``why`` words each of them)."""
    if len(unknown) == 1:
        ((key, value),) = unknown.items()
        return invalid("parameter " + key, value, why)
    given = ", ".join(f"{k} = {show(v)}" for k, v in unknown.items())
    return InvalidInputError(f"invalid parameters {given}: {why}")
