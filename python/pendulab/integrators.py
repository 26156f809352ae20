"""The core's integrators by name (``methods``, ``method_names``) and the run settings that
:func:`pendulab.simulate` and :class:`pendulab.Stepper` share, checked once (``check_settings``: method,
dt [s], rtol, atol [m and m/s], project, conserve, t0 [s]; ``DEFAULTS``)."""

from __future__ import annotations

import functools
from typing import TYPE_CHECKING, Any

from ._core import InvalidInputError, fused_is_fast
from ._core import methods as _methods
from .model import Pendulum
from .validate import LIMITS, abbreviate, choice, did_you_mean, finite, flag, nearest, number, show

if TYPE_CHECKING:
    from ._core import MethodInfo, ParamSpec

_U64 = 2**63 - 1
"""The largest count the core's unsigned 64-bit step counters take from Python (signed range)."""

_ARITHMETICS = ("auto", "unfused", "fused")
"""The RATTLE family's arithmetic of a·b + c: two roundings (``"unfused"``), one (``"fused"``,
``f64::mul_add``), or ``"auto"`` (the default): fused where the CPU does it in one instruction."""
_FUSED_METHODS = ("rattle", "rattle4", "rattle6", "rattle8")
"""The methods that have ``arithmetic="fused"``."""

DEFAULTS: dict[str, Any] = {"method": "rattle", "dt": 1e-3, "rtol": 1e-10, "atol": 1e-12, "project": True}


def _check_conserve(pendulum: Pendulum, conserve: bool) -> None:
    """``conserve`` holds E (conservative models) and J₃ (axisymmetric ones) at their initial values;
    damping or drag make both decay (J₃(t) = J₃(0) e^{−ct} for linear damping, T-7.1), so holding them
    would be wrong physics: refused with the reason."""
    lossy = {k: v for k, v in pendulum.extra.items() if k in ("damping", "drag") and v != 0.0}
    if conserve and lossy:
        given = ", ".join(f"{k} = {v!r}" for k, v in lossy.items())
        raise InvalidInputError(
            f"conserve=True would hold E and J₃ at their initial values, but they decay with {given} "
            "(J₃(t) = J₃(0)·e^(−c t)); run without conserve (DOP853 then follows the decay to its "
            "tolerance) or with a RATTLE method, whose exact damping flow keeps the decay of J₃ exactly"
        )


def check_settings(
    *,
    method: Any,
    dt: Any,
    rtol: Any,
    atol: Any,
    project: Any,
    conserve: Any,
    t0: Any,
) -> tuple[str, float | None, float, float, bool, bool, float]:
    """The shared settings of :func:`simulate` and :class:`Stepper` checked against :mod:`pendulab.validate`:
    method (a registered name; any other value is refused with :func:`unknown_method`'s message, as at
    every entry point), dt [s] (None or the dt limit, for every method: an adaptive method's first step,
    never 0; None lets it choose), rtol, atol (finite; the core checks their ranges), project and
    conserve (bools), t0 [s] (the time limit)."""
    if not isinstance(method, str) or method not in method_names():  # the message of every entry point
        raise InvalidInputError(unknown_method(method))
    if dt is not None:
        dt = number("dt", dt, _dt_limit(method))
    rtol = finite("rtol", rtol, "a finite relative tolerance (dop853)")
    atol = finite("atol", atol, "a finite absolute tolerance in m and m/s (dop853)")
    return (
        method,
        dt,
        rtol,
        atol,
        flag("project", project),
        flag("conserve", conserve),
        number("t0", t0, "time"),
    )


def _dt_limit(method: str) -> ParamSpec:
    """The dt limit as :data:`pendulab.validate.LIMITS` has it, in words naming the method: a fixed-step
    method's step, None (leaving it out) for the default 1 ms; an adaptive method's first step, None
    to let the method choose it."""
    spec = LIMITS["dt"]
    if _method_table()[method]["adaptive"]:
        allowed = f"{spec['allowed']} (the first step of {method}), or None to let {method} choose it"
    else:
        allowed = f"{spec['allowed']} (the step of {method}), or None for {DEFAULTS['dt']:g} s"
    return spec | {"allowed": allowed}


@functools.cache
def _method_table() -> dict[str, MethodInfo]:
    """The core's integrators by name (fixed for the life of the process)."""
    return {m["name"]: m for m in _methods()}


def methods() -> list[MethodInfo]:
    """The registered integrators: name, order, symplectic, preserves_ts2, preserves_j3, adaptive, …

    Examples
    --------
    >>> import numpy as np
    >>> import pendulab as pl
    >>> [m['name'] for m in pl.methods()][:3]
    ['rattle', 'rattle4', 'rattle6']
    >>> pl.methods()[0]['order']
    2
    """
    return _methods()


def method_names() -> list[str]:
    """Names of the registered integrators.

    Examples
    --------
    >>> import numpy as np
    >>> import pendulab as pl
    >>> pl.method_names()
    ['rattle', 'rattle4', 'rattle6', 'rattle8', 'dop853', 'rkmk4', 'rk4', 'rk4_angles']
    """
    return [m["name"] for m in _methods()]


def unknown_method(name: Any) -> str:
    """The message refusing a method ``name`` that is not registered (or not a string): the nearest
    name (the same but for case first; :func:`pendulab.validate.did_you_mean`) and the available ones."""
    names = method_names()
    hint = did_you_mean(name, names)
    return f"unknown method {show(name)}{hint}; available: {', '.join(names)}"


def unknown_method_key(name: str) -> tuple[str, dict[str, str]]:
    """The message key and values of :func:`unknown_method` for a page that words it in its language
    (``pendulab/server/messages.json``; the core's lab engine keys it alike, ``live::wire::unknown_method``):
    ``unknown_method`` (method: the name, abbreviated; available) or, with the nearest name,
    ``unknown_method_hint`` (the same and nearest)."""
    names = method_names()
    values = {"method": abbreviate(name), "available": ", ".join(names)}
    near = nearest(name, names)
    return ("unknown_method", values) if near is None else ("unknown_method_hint", values | {"nearest": near})


def check_arithmetic(arithmetic: Any, method: str, model: str | None = None) -> str:
    """``arithmetic`` checked and resolved: ``"unfused"`` (every method), ``"fused"`` (the RATTLE family)
    or ``"auto"``, which is ``"fused"`` for the RATTLE family (but the ``"string"`` model, whose stepper
    is unfused) where the CPU does a fused multiply-add in one instruction (x86-64-v3/v4, aarch64:
    ``_core.fused_is_fast()``) and ``"unfused"`` otherwise (docs/performance.md, "No CPU left behind")."""
    resolved = choice("arithmetic", arithmetic, _ARITHMETICS)
    if resolved == "auto":
        fused = method in _FUSED_METHODS and model != "string" and fused_is_fast()
        return "fused" if fused else "unfused"
    if resolved == "fused" and method not in _FUSED_METHODS:
        raise InvalidInputError(
            f"arithmetic='fused' applies to the RATTLE family ({', '.join(_FUSED_METHODS)}), "
            f"not to method {method!r}"
        )
    return resolved


def check_steps_on_samples(steps_on_samples: Any, pendulum: Pendulum) -> bool:
    """``steps_on_samples`` checked (a bool) for ``simulate`` and ``Stepper``: True only with a sampled
    pivot (``Pendulum(pivot_samples=...)``), whose samples the fixed steps then land on; without samples
    there is nothing to land on, so it is refused rather than ignored (docs/integrators.md, "Sampled
    pivot"). ``dop853`` takes it and steps as before (its steps end on the samples anyway)."""
    on = flag("steps_on_samples", steps_on_samples)
    if on and pendulum.pivot_samples is None:
        raise InvalidInputError(
            f"steps_on_samples=True lands the fixed steps on a sampled pivot's samples, but this "
            f"{pendulum.model!r} pendulum has no pivot_samples; give Pendulum(pivot_samples=(times, "
            "positions)) or leave steps_on_samples=False"
        )
    return on
