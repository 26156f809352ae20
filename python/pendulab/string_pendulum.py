"""The pendulum on a string (model ``"string"``): a rope that can pull but not push. While the string
is taut the bob moves as on a rod (THEORY.md §2); where the tension T = m(|v|² − g z)/l (T-2.3) would
turn negative — for the ideal pendulum at the height z* = 2E/(3 m g) — the string goes slack and the
bob flies freely on the exact parabola x_e + v_e τ − ½ g τ² e₃ until |x| = l again, when the string
snaps taut: the outward radial velocity u is removed (``restitution`` e = 0, inelastic, the default;
½ m |u|² is lost) or reflected (e = 1, elastic, E kept), in general v ← v − (1 + e)u.

The run is hybrid and done in the core in one call (GIL released; no progress bar and no Ctrl-C
inside it): the leave and snap events are located to round-off (bisection of the step length on T,
closed form or bisection of |x|² − l² on the parabola). Units: SI (m, kg, s, J).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from . import _core
from .model import Pendulum, State
from .trajectory import Trajectory

STRING_METHODS = ("rattle", "rattle4", "rattle6", "rattle8", "rkmk4")
"""Methods for the taut phases: fixed step and keeping TS² (the leave is found by shortening a step)."""


def check_string_settings(method: str, save_at: Any = None, conserve: bool = False) -> None:
    """Refuses what the hybrid string run cannot do, naming the alternative."""
    if method not in STRING_METHODS:
        raise _core.InvalidInputError(
            f"method {method!r} cannot integrate the 'string' model: its taut phases need a fixed-step "
            f"method that keeps TS² (the leave is found by shortening a step); use one of "
            f"{', '.join(STRING_METHODS)}"
        )
    if save_at is not None:
        raise _core.InvalidInputError(
            "save_at is not available for the 'string' model: it saves every save_every-th step of its "
            "grid t0 + k·dt and every event"
        )
    if conserve:
        raise _core.InvalidInputError(
            "conserve=True is for dop853; the 'string' model's taut phases use the RATTLE family or rkmk4"
        )


def simulate_string(
    pendulum: Pendulum,
    state: State,
    t_end: float,
    *,
    method: str = "rattle",
    dt: float | None = None,
    save_every: int | None = None,
    t0: float = 0.0,
    max_saved_bytes: int | None = None,
) -> Trajectory:
    """Simulates a ``model="string"`` pendulum (called by :func:`pendulab.simulate`): samples every
    ``save_every``-th step of the grid t0 + k·dt [s] (default dt 1e-3 s), every event (the state after
    it) and t_end; ``Trajectory.taut`` flags the samples, ``Trajectory.events`` lists the events."""
    check_string_settings(method)
    dt = 1e-3 if dt is None else float(dt)
    out = _core.string_simulate(
        *pendulum._core_args(),
        float(pendulum.extra.get("restitution", 0.0)),
        np.ascontiguousarray(state.x),
        np.ascontiguousarray(state.v),
        float(t0),
        float(t_end),
        method,
        dt,
        1 if save_every is None else int(save_every),
        max_saved_bytes,
    )
    options: dict[str, Any] = {"dt": dt, "t0": t0, "t_end": t_end}
    if save_every is not None:
        options["save_every"] = int(save_every)
    return Trajectory(
        pendulum,
        out["t"],
        out["x"],
        out["v"],
        method,
        options,
        dict(out["stats"]),
        taut=out["taut"],
        events=dict(out["events"]),
    )
