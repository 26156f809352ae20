"""The core's model registry as the Python side sees it (docs/theory.md §7): the models by name —
ideal, damped (damping, drag, dry friction, periodic forcing, any gravity direction), rotating frame,
moving pivots, string, swinging spring, hoisted rope — each with its parameters (SI unit, default,
limits, what is allowed); which model a set of keyword parameters names; and the check of a model's
keyword parameters before the core builds it.

Length l [m], mass m [kg] and g [m/s²] come first in every model; the rest are each model's own
(units as :func:`models` lists them).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from .._core import models as _models
from ..validate import choice, finite, invalid

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
    for m in _models():
        if keys <= {p["name"] for p in m["params"]}:
            return m["name"]
    return "damped"


def check_model_keywords(model: str | None, extra: dict[str, float]) -> None:
    """``model`` (when given) is a registered name, and each keyword parameter a short name with a
    finite value (within the model's limits when it is one of ``model``'s parameters; the core then
    checks names and ranges against the model inferred or given)."""
    if model is not None:
        choice("model", model, [m["name"] for m in _models()])
    for key, value in extra.items():
        if len(key) > 64:
            raise invalid("parameter name", key, "a parameter of the model (pendulab.models())")
        own = {p["name"]: p for m in _models() if m["name"] == model for p in m["params"]}
        finite(
            str(key),
            value,
            own[key]["allowed"] if key in own else f"a finite number (pendulab.models() lists {key!r})",
        )
