"""The settings of :func:`pendulab.fit` before any search: the search settings checked, the unknowns
named (``fit=``, the start unless ``state0`` is given, the pivot when positions do not hang from the
origin, φ₀ and φ̇₀ held for a hinge), every parameter's value before the search, and the refusal of
data that show no motion above their noise floor (noise.py); SciPy (the ``fit`` extra) required with a
clear error. Units: SI (docs/fit.md).
"""

from __future__ import annotations

import importlib.util
import math
from collections.abc import Mapping
from typing import Any

import numpy as np

from .._core import InvalidInputError
from ..model import Pendulum, State
from ..variants.spring import SwingingSpring
from .data import KINDS, Observations
from .keyed import KeyedInputError
from .problem import (
    OFFSET_NAMES,
    PIVOT_NAMES,
    STATE_NAMES,
    SYSTEMATIC_NAMES,
    check_model,
    model_params,
)
from .spring_model import SPRING_STATE

MAX_EVALUATIONS = 20_000
#: A kind shows motion when its spread exceeds this multiple of its noise floor.
MOTION = 3.0


def angles_of(state: State) -> dict[str, float]:
    """θ, φ [rad] and θ̇, φ̇ [rad/s] of a state (φ̇ = 0 at a pole, where φ means nothing), with the
    length r₀ = |x| [m] and its rate ṙ₀ [m/s] (used by the spring; r₀ = l on a rod)."""
    x, v = np.asarray(state.x), np.asarray(state.v)
    theta, phi = state.angles()
    ell = float(np.linalg.norm(x))
    e_theta = np.array([math.cos(theta) * math.cos(phi), math.cos(theta) * math.sin(phi), math.sin(theta)])
    e_phi = np.array([-math.sin(phi), math.cos(phi), 0.0])
    rho = math.hypot(x[0], x[1])
    return {
        "theta0": theta,
        "phi0": phi,
        "theta_dot0": float(v @ e_theta) / ell,
        "phi_dot0": float(v @ e_phi) / rho if rho > 1e-12 * ell else 0.0,
        "r0": ell,
        "r_dot0": float(v @ x) / ell,
    }


def fit_list(fit: Any) -> list[Any]:
    if isinstance(fit, str):
        return [s.strip() for s in fit.split(",") if s.strip()]
    return list(fit)


def pivot_names(columns: Mapping[str, int]) -> list[str]:
    if "horizontal" in columns:
        return ["pivot_x", "pivot_y"]
    return list(PIVOT_NAMES) if columns.get("positions", 3) == 3 else ["pivot_x", "pivot_z"]


def free_names(
    fit: Any, model: str, state_given: bool, columns: Mapping[str, int], planar: bool
) -> list[str]:
    fit = fit_list(fit)
    names: list[str] = []
    own = list(model_params(model))
    state = [*STATE_NAMES, *(SPRING_STATE if model == "spring" else ())]
    if planar:
        state = [n for n in state if n not in ("phi0", "phi_dot0")]
    pivot = pivot_names(columns)
    allowed = (
        own + state + list(PIVOT_NAMES) + list(OFFSET_NAMES) + list(SYSTEMATIC_NAMES) + ["state", "pivot"]
    )
    if planar and {"phi0", "phi_dot0"} & set(fit):
        raise KeyedInputError(
            "planar=True holds phi0 = phi_dot0 = 0 (a hinge): do not fit them, or pass planar=False",
            "fit_planar_phi",
        )
    for name in fit:
        if not isinstance(name, str) or name not in allowed:
            raise KeyedInputError(
                f"cannot fit {name!r} for the {model!r} model; choose from {', '.join(allowed)}",
                "fit_cannot_fit",
                param=str(name)[:80],
                model=model,
                allowed=", ".join(allowed),
            )
        expanded = state if name == "state" else pivot if name == "pivot" else [name]
        names += [n for n in expanded if n not in names]
    if not state_given:
        names += [n for n in state if n not in names]
    if set(PIVOT_NAMES) & set(names) and not {"positions", "horizontal"} & set(columns):
        raise KeyedInputError(
            "the pivot position is fitted from positions only; give positions=", "fit_pivot_needs_positions"
        )
    if "t_offset" in names and model != "ideal":
        raise KeyedInputError(
            "t_offset is fitted for the ideal pendulum only (the exact solution runs backward)",
            "fit_t_offset_ideal",
        )
    if not names:
        raise InvalidInputError("nothing to fit: give fit=[...] or leave state0 unset")
    return names


def need_scipy() -> None:
    """SciPy (``least_squares``, the χ² tails) is the ``fit`` extra, not a base dependency: without it
    :func:`pendulab.fit` raises an ImportError naming the package and the extra, before any work. Only
    looked up, not imported here: the search imports it within the fit's time limit, as before."""
    if importlib.util.find_spec("scipy") is None:
        raise ImportError("pl.fit needs SciPy: pip install 'pendulab[fit]' (or scipy>=1.11)", name="scipy")


def check_settings(pendulum: Any, time_limit: Any, loss: Any, max_evaluations: Any) -> str:
    """The model's name, after checking the search settings (clear errors naming the value)."""
    if not isinstance(pendulum, Pendulum | SwingingSpring):
        raise InvalidInputError(
            f"pendulum must be a pendulab.Pendulum or SwingingSpring, got {type(pendulum).__name__}"
        )
    model = check_model(pendulum)
    if time_limit is not None and not (
        isinstance(time_limit, int | float) and not isinstance(time_limit, bool) and 0.0 < time_limit < 1e9
    ):
        raise InvalidInputError(f"time_limit = {time_limit!r} must be a positive number of seconds or None")
    if loss not in ("linear", "soft_l1", "huber", "cauchy", "arctan"):
        raise InvalidInputError(f"loss = {loss!r}: use linear, soft_l1, huber, cauchy or arctan")
    if (
        isinstance(max_evaluations, bool)
        or not isinstance(max_evaluations, int)
        or not (10 <= max_evaluations <= MAX_EVALUATIONS)
    ):
        raise InvalidInputError(
            f"max_evaluations = {max_evaluations!r} must be an integer from 10 to {MAX_EVALUATIONS}"
        )
    return model


def is_planar(planar: Any, obs: Observations, fit: Any) -> bool:
    """A hinge unless asked otherwise: data of a planar angle alone (an encoder, a planar video) are
    fitted with φ₀ = φ̇₀ = 0 held, unless ``planar=False`` or φ₀/φ̇₀ are named in ``fit``."""
    if planar is not None:
        if not isinstance(planar, bool):
            raise InvalidInputError(f"planar = {planar!r} must be True, False or None")
        return planar
    named = {"phi0", "phi_dot0"} & set(fit_list(fit))
    return (
        "planar_angle" in obs.values
        and not ({"positions", "horizontal", "angles"} & set(obs.values))
        and not named
    )


def off_origin(obs: Observations, model: str) -> bool:
    """Positions that cannot hang from the origin: seen from above (x, y) a sway centred farther from
    it than a fifth of its width; seen from the side (x, z) all above it, as a
    pendulum under gravity never is (start.py, check_upright); in 3-D (a rod) a distance from it that
    varies by more than 5 %, as a rod's bob's never does."""
    h = obs.values.get("horizontal")
    if h is not None:  # seen from above: a sway centred away from the origin
        centre = h.mean(axis=0)
        return float(np.hypot(*centre)) > 0.2 * float(np.max(np.hypot(*(h - centre).T)))
    p = obs.values.get("positions")
    if p is None:
        return False
    if p.shape[1] == 2:
        return bool(np.all(p[:, 1] > 0.0))
    r = np.linalg.norm(p, axis=1)
    return model != "spring" and float(np.std(r)) > 0.05 * float(np.median(r))


def initial_values(
    pendulum: Pendulum | SwingingSpring, model: str, state0: State | None, pivot: Any
) -> dict[str, float]:
    """Every parameter's value before the search: the pendulum's, the registry's defaults, the given
    start and pivot, and the systematic terms at their neutral values."""
    values: dict[str, float] = {n: float(spec["default"]) for n, spec in model_params(model).items()}
    if isinstance(pendulum, SwingingSpring):
        values.update(
            length=pendulum.rest_length,
            g=pendulum.g,
            mass=pendulum.mass,
            stiffness=pendulum.k_over_m * pendulum.mass,
        )
        for name, spec in model_params(model).items():  # the registry's limits, as a Pendulum checks them
            v = values[name]
            if not (math.isfinite(v) and float(spec["min"]) <= v <= float(spec["max"])):
                raise InvalidInputError(
                    f"the spring's {name} = {v!r} {spec['unit']}: allowed is {spec['allowed']}"
                )
        values.update(r0=pendulum.equilibrium_length, r_dot0=0.0)
    else:
        values.update({k: float(v) for k, v in pendulum.params().items() if k != "model"})
        values.update({k: float(v) for k, v in pendulum.extra.items()})
    values.update(dict.fromkeys(STATE_NAMES, 0.0))
    if state0 is not None:
        values.update(angles_of(state0))
    try:
        given_pivot = (0.0, 0.0, 0.0) if pivot is None else tuple(float(c) for c in pivot)
    except (TypeError, ValueError) as e:
        raise InvalidInputError(f"pivot must be 3 finite numbers [m], got {pivot!r}") from e
    if len(given_pivot) != 3 or not all(math.isfinite(c) and abs(c) <= 1e12 for c in given_pivot):
        raise InvalidInputError(f"pivot must be 3 finite numbers [m], got {pivot!r}")
    values.update(dict(zip(PIVOT_NAMES, given_pivot, strict=True)))
    values.update(SYSTEMATIC_NAMES)
    values["t_offset"] = 0.0
    return values


def check_motion(
    floors: Mapping[str, float], spreads: Mapping[str, float], sizes: Mapping[str, float]
) -> None:
    """Refuses data in which no kind moves more than :data:`MOTION` times its noise floor (and more
    than 1e-9 of its values' size ``sizes``, the round-off of constant readings): a bob at rest,
    constant readings or pure noise determine no length, g or damping, and a search would only fit
    the noise."""
    if any(spreads[k] > max(MOTION * floors[k], 1e-9 * sizes[k], 1e-300) for k in spreads):
        return
    said = "; ".join(f"{k}: spread {spreads[k]:.3g}, noise floor {floors[k]:.3g} {KINDS[k]}" for k in spreads)
    raise InvalidInputError(
        f"the data show no motion above their noise ({said}): a pendulum at rest, constant readings "
        "or noise alone determine no length, g or damping. Record a swing (at least a few periods); "
        "for the length of a pendulum at rest, measure its distance from the pivot directly"
    )
