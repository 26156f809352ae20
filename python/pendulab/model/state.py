"""States on TS² (docs/theory.md §1–2): :class:`State`, a point (x, v) with |x| = l and x·v = 0,
and how one is made — from Cartesian position x [m] and velocity v [m/s], on TS² already or projected
onto it (x ← l x/|x|, v ← its tangential part), or from the angles of T-1.1: polar angle θ from the
downward vertical and azimuth φ [rad] with their rates θ̇, φ̇ [rad/s] (or in degrees, [°] and [°/s]).

The core does the geometry (``pendulab._core.state_on_ts2``, ``project_state``,
``state_from_angles``, for the pendulum's ``ModelSpec``); this module checks the input against the
limits of :mod:`pendulab.validate` and keeps the arrays read-only. Units: x [m], v [m/s], angles
[rad] (or [°] where named ``_deg``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np
import numpy.typing as npt

from .._core import InvalidInputError, project_state, state_on_ts2
from .._core import state_from_angles as _state_from_angles
from ..display import Row, html_table, number, vector
from ..validate import LIMITS, array, flag, invalid, spec
from ..validate import number as checked

if TYPE_CHECKING:
    from .._core import ModelSpec, ParamSpec

FloatArray = npt.NDArray[np.float64]


_SPEED: ParamSpec = {
    **LIMITS["velocity"],
    "allowed": f"{LIMITS['velocity']['allowed']} (the speed bound of a start)",
}


def _vec3(name: str, a: Any, limit: str = "position") -> FloatArray:
    """3 real numbers within the ``limit`` of :mod:`pendulab.validate` (position [m] or velocity [m/s])."""
    return array(name, a, limit, shape=(3,))


def _check_speed(v: FloatArray, given: str) -> None:
    """A velocity built from angle rates must respect the velocity limit too (|v_i| ≤ 10⁸ m/s)."""
    lim = LIMITS["velocity"]
    if not np.all(np.isfinite(v) & (np.abs(v) <= lim["max"])):
        raise invalid(
            given, f"a velocity {v.tolist()!r} m/s", f"the velocity it gives must be {lim['allowed']}"
        )


def _frozen(a: FloatArray) -> FloatArray:
    a = np.array(a, dtype=np.float64)
    a.flags.writeable = False
    return a


@dataclass(frozen=True)
class State:
    """A point (x, v) of TS²: position x [m] relative to the pivot, velocity v [m/s].

    ``projection`` is ``(|Δx| [m], |Δv| [m/s])`` when the state was moved onto TS² with
    ``project=True``, else ``None``.
    """

    x: FloatArray
    v: FloatArray
    projection: tuple[float, float] | None = field(default=None, compare=False)

    def __post_init__(self) -> None:
        # a State built by hand from integers, float32 or lists holds float64 arrays like one from
        # Pendulum.state (integer arrays reached the core as 'PyArray<T, D>' TypeErrors); anything
        # else (complex, text, a wrong shape) is kept as given and refused by name where it is used
        for name in ("x", "v"):
            given = getattr(self, name)
            try:
                a = np.asarray(given)
            except (TypeError, ValueError):  # ragged
                continue
            if a.dtype.kind in "fiu" and not (isinstance(given, np.ndarray) and a.dtype == np.float64):
                object.__setattr__(self, name, _frozen(a))

    def angles(self) -> tuple[float, float]:
        """Polar angle θ from the downward vertical and azimuth φ = atan2(y, x) [rad]."""
        rho = float(np.hypot(self.x[0], self.x[1]))
        return float(np.arctan2(rho, -self.x[2])), float(np.arctan2(self.x[1], self.x[0]))

    @property
    def pair(self) -> tuple[FloatArray, FloatArray]:
        """(x [m], v [m/s]) as contiguous arrays: the state a core class takes with a spec and options."""
        return np.ascontiguousarray(self.x), np.ascontiguousarray(self.v)

    def as_array(self) -> FloatArray:
        """The state as one array (x₁, x₂, x₃, v₁, v₂, v₃) [m, m/s]."""
        return np.concatenate([self.x, self.v])

    def angles_deg(self) -> tuple[float, float]:
        """θ and φ of :meth:`angles` in degrees."""
        theta, phi = self.angles()
        return math.degrees(theta), math.degrees(phi)

    def __repr__(self) -> str:
        theta, phi = self.angles_deg()
        moved = "" if self.projection is None else f", projected by {number(self.projection[0], 3)} m"
        return (
            f"State(x={vector(self.x)} m, v={vector(self.v)} m/s; "
            f"θ={number(theta, 6)}°, φ={number(phi, 6)}°{moved})"
        )

    def _repr_html_(self) -> str:
        theta, phi = self.angles_deg()
        rows: list[Row] = [
            ("position x", vector(self.x), "m"),
            ("velocity v", vector(self.v), "m/s"),
            ("polar angle θ (from the downward vertical)", theta, "°"),
            ("azimuth φ", phi, "°"),
        ]
        if self.projection is not None:
            rows.append(("moved onto TS² by |Δx|, |Δv|", vector(self.projection, 3), "m, m/s"))
        return html_table("State on TS²", rows)


def state_from_cartesian(model: ModelSpec, length: float, x: Any, v: Any, project: Any) -> State:
    """The state of :meth:`pendulab.Pendulum.state`: position x [m] and velocity v [m/s] (3 numbers
    each) of the pendulum ``model`` with rod length ``length`` [m], on TS² to 1e-9 relative, or moved
    there when ``project`` is True (``State.projection`` says by how much)."""
    xa, va = _vec3("x", x), array("v", v, _SPEED, shape=(3,))
    if flag("project", project):
        if 0.0 < np.linalg.norm(xa) < 1e-9 * length:  # its direction is lost to rounding
            raise invalid(
                "x", xa.tolist(), f"a position at least 1e-9 l = {1e-9 * length:g} m from the pivot"
            )
        (xp, vp), dx, dv = project_state(model, xa, va)
        return State(_frozen(xp), _frozen(vp), (dx, dv))
    xs, vs = state_on_ts2(model, xa, va)
    return State(_frozen(xs), _frozen(vs))


def angles_in_radians(given: tuple[tuple[str, float | None, float | None], ...]) -> list[float]:
    """θ, φ [rad] and θ̇, φ̇ [rad/s] from ``(name, in radians, in degrees)`` for ``theta``, ``phi``,
    ``theta_dot``, ``phi_dot`` (the keywords of :meth:`pendulab.Pendulum.state_from_angles`): each
    given one way at most, within the limits ``angle`` and ``angle_rate`` (in radians or degrees);
    θ is required, the others default to 0."""
    values = []
    for name, rad, deg in given:
        limit = "angle_rate" if name.endswith("_dot") else "angle"
        if rad is not None and deg is not None:
            raise InvalidInputError(
                f"give {name} either in radians ({name}={rad!r}) or in degrees ({name}_deg={deg!r}), not both"
            )
        if deg is not None:
            lim = LIMITS[limit]
            unit = "degrees/s" if name.endswith("_dot") else "degrees"
            in_degrees = spec(
                f"{name}_deg", unit, lim["min"], lim["max"], f"{lim['allowed'].rsplit(' ', 1)[0]} {unit}"
            )
            values.append(math.radians(checked(f"{name}_deg", deg, in_degrees)))
        elif rad is not None:
            values.append(checked(name, rad, limit))
        elif name == "theta":
            raise InvalidInputError("give the polar angle: theta [rad] or theta_deg [°]")
        else:
            values.append(0.0)
    return values


def state_from_angle_values(model: ModelSpec, values: list[float]) -> State:
    """The state on TS² of the pendulum ``model`` at θ, φ [rad], θ̇, φ̇ [rad/s] (T-1.1), refused when
    the velocity it gives exceeds the velocity limit."""
    x, v = _state_from_angles(model, values)
    _check_speed(np.asarray(v), f"(theta_dot, phi_dot) = ({values[2]!r}, {values[3]!r}) rad/s")
    return State(_frozen(x), _frozen(v))
