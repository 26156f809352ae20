"""The ideal spherical pendulum and its states on TS² (THEORY.md §1–2).

Units: length l [m], mass m [kg], gravity g [m/s²] (any sign; g > 0 pulls along −z), position x [m],
velocity v [m/s], angles [rad], energy [J], J₃ [kg m²/s], tension [N].
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np
import numpy.typing as npt

from . import _core

FloatArray = npt.NDArray[np.float64]


def _vec3(name: str, a: Any) -> FloatArray:
    arr = np.asarray(a, dtype=np.float64)
    if arr.shape != (3,):
        raise _core.InvalidInputError(f"{name} must be a vector of 3 numbers, got shape {arr.shape}")
    return np.ascontiguousarray(arr)


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

    def angles(self) -> tuple[float, float]:
        """Polar angle θ from the downward vertical and azimuth φ = atan2(y, x) [rad]."""
        rho = float(np.hypot(self.x[0], self.x[1]))
        return float(np.arctan2(rho, -self.x[2])), float(np.arctan2(self.x[1], self.x[0]))

    def as_array(self) -> FloatArray:
        """The state as one array (x₁, x₂, x₃, v₁, v₂, v₃) [m, m/s]."""
        return np.concatenate([self.x, self.v])


class Pendulum:
    """The ideal spherical pendulum: a mass on a rigid massless rod under uniform gravity.

    Parameters
    ----------
    length : rod length l [m], > 0.
    g : gravitational acceleration [m/s²], any finite value; g > 0 pulls along −z, g < 0 along +z,
        g = 0 leaves only the rod (great circles).
    mass : bob mass m [kg], > 0.

    Raises ``InvalidInputError`` (a ``ValueError``) naming the bad value and the allowed range.
    """

    model = "ideal"

    def __init__(self, length: float = 1.0, g: float = 9.81, mass: float = 1.0) -> None:
        _core.check_params(float(length), float(mass), float(g))
        self._length = float(length)
        self._g = float(g)
        self._mass = float(mass)

    @property
    def length(self) -> float:
        """Rod length l [m]."""
        return self._length

    @property
    def g(self) -> float:
        """Gravity g [m/s²] along −z."""
        return self._g

    @property
    def mass(self) -> float:
        """Bob mass m [kg]."""
        return self._mass

    @property
    def omega0(self) -> float:
        """Small-oscillation angular frequency ω₀ = √(|g|/l) [rad/s]."""
        return float(np.sqrt(abs(self._g) / self._length))

    def params(self) -> dict[str, float | str]:
        """Model name and parameters with SI values (length [m], mass [kg], g [m/s²])."""
        return {"model": self.model, "length": self._length, "mass": self._mass, "g": self._g}

    def _core_args(self) -> tuple[float, float, float]:
        return self._length, self._mass, self._g

    def __repr__(self) -> str:
        return f"Pendulum(length={self._length!r}, g={self._g!r}, mass={self._mass!r})"

    def state(self, x: Any, v: Any, *, project: bool = False) -> State:
        """State from Cartesian position x [m] and velocity v [m/s] (3 numbers each).

        Without ``project`` the state must lie on TS² (|x| = l and x·v = 0 to 1e-9 relative);
        with ``project=True`` it is moved there (x ← l x/|x|, v ← its tangential part) and
        ``State.projection`` says by how much.
        """
        xa, va = _vec3("x", x), _vec3("v", v)
        if project:
            (xp, vp), dx, dv = _core.project_state(*self._core_args(), xa, va)
            return State(_frozen(xp), _frozen(vp), (dx, dv))
        xs, vs = _core.state_on_ts2(*self._core_args(), xa, va)
        return State(_frozen(xs), _frozen(vs))

    def state_from_angles(
        self, theta: float, phi: float = 0.0, theta_dot: float = 0.0, phi_dot: float = 0.0
    ) -> State:
        """State at polar angle θ [rad] from the downward vertical, azimuth φ [rad], rates θ̇, φ̇ [rad/s]."""
        x, v = _core.state_from_angles(
            *self._core_args(), float(theta), float(phi), float(theta_dot), float(phi_dot)
        )
        return State(_frozen(x), _frozen(v))

    def diagnostics(self, x: Any, v: Any) -> dict[str, FloatArray]:
        """Energy [J], j3 [kg m²/s], tension [N], radius_error |x| − l [m], tangency x·v [m²/s]
        for arrays x, v of shape (N, 3) or (3,)."""
        xa = np.ascontiguousarray(np.atleast_2d(np.asarray(x, dtype=np.float64)))
        va = np.ascontiguousarray(np.atleast_2d(np.asarray(v, dtype=np.float64)))
        return _core.diagnostics(*self._core_args(), xa, va)

    def energy(self, state: State) -> float:
        """Total energy E = m(½|v|² + g z) [J] (T-2.6)."""
        return float(self.diagnostics(state.x, state.v)["energy"][0])

    def j3(self, state: State) -> float:
        """Vertical angular momentum J₃ = m (x × v)·e₃ [kg m²/s] (T-2.6)."""
        return float(self.diagnostics(state.x, state.v)["j3"][0])

    def tension(self, state: State) -> float:
        """Rod tension T = m(|v|² − g z)/l [N] (T-2.3); negative means the rod pushes."""
        return float(self.diagnostics(state.x, state.v)["tension"][0])
