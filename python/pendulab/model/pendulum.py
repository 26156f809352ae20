"""The spherical pendulum: a mass m [kg] on a rigid massless rod of length l [m] under gravity g
[m/s²] (docs/theory.md §1–2: the constrained equations T-2.2, tension T-2.3, energy and J₃ T-2.6) and,
optionally, the forces of the real-pendulum models of the core's registry (§7, T-7.1: damping, drag,
forcing, any gravity direction, rotating frame, moving pivot) or a user force [N] (the slow path).

:class:`Pendulum` is built once and checked once in the core (its ``ModelSpec``, what every run
hands over); it makes states (:mod:`pendulab.model.state`) and computes diagnostics along arrays.
Units: l [m], m [kg], g [m/s²], x [m], v [m/s], t [s], energy [J], J₃ [kg m²/s], tension [N],
power [W].
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np

from .._core import InvalidInputError, ModelSpec
from .._core import diagnostics as _diagnostics
from .._warn import warn_user
from ..display import Row, html_table
from ..validate import COMMON, array, invalid, model_table
from ..validate import number as checked
from .registry import _infer_model, check_model_keywords, infer_model
from .state import (
    FloatArray,
    State,
    _frozen,
    angles_in_radians,
    state_from_angle_values,
    state_from_cartesian,
)


class Pendulum:
    """A spherical pendulum: a mass on a rigid massless rod, under gravity and, optionally, the forces
    of the real-pendulum models (docs/theory.md §7; ``pendulab.models()`` lists them with units).

    Parameters
    ----------
    length : rod length l [m], > 0.
    g : gravitational acceleration [m/s²], any finite value; g > 0 pulls along −z (or along
        ``gravity_direction``), g < 0 the other way, g = 0 leaves only the rod (great circles).
    mass : bob mass m [kg], > 0.
    model : registry name: ``"ideal"`` (default), ``"damped"`` (damping [1/s], drag [1/m], a periodic
        force forcing_amplitude [m/s²], forcing_omega [rad/s], forcing_phase [rad], forcing_x/y/z,
        and the gravity direction gravity_x/y/z), ``"rotating"`` (frame_rate [rad/s], latitude
        [rad], damping [1/s]), ``"slewing"`` and ``"vibrating"`` (moving pivots). When omitted it is
        inferred from the keywords: the first model of :func:`models` that has all of them (so
        ``damping`` alone → ``"damped"``, ``frame_rate``/``latitude`` → ``"rotating"``); a keyword
        no model has, or keywords no one model has together, is an error naming them.
    pivot_samples : ``(times, positions)``, times [s] (n,) strictly increasing, positions [m] (n, 3),
        n ≥ 4: the pivot moves along the C² (not-a-knot) cubic spline through them, whose second
        derivative is the pivot acceleration p̈ of T-7.2 (model ``"sampled_pivot"``, inferred when
        given; its only parameter is ``damping`` [1/s]). Runs must stay within [times[0], times[-1]].
    force : a user force ``force(t, x, v) -> (3,)`` [N] of time t [s], position x [m] and velocity v
        [m/s] (pivot-relative, as numpy-free lists of 3 floats), added to the model's forces (T-7.1:
        only its tangential part acts). **The slow path**: every evaluation calls Python (a few µs,
        ~10⁵ calls per simulated second at DOP853's usual steps). Simulated with ``dop853`` (the
        default then, with projection onto TS²), ``rkmk4`` or ``rk4`` — not the RATTLE family, whose
        kicks leave out velocity dependence; ``power`` and the power balance include F·v. An exception
        raised by the callable propagates unchanged; a result that is not 3 finite numbers is an
        ``InvalidInputError`` naming the value.
    **extra : the model's parameters, e.g. ``Pendulum(length=1.0, g=9.81, mass=1.0, damping=0.003)``.

    Raises ``InvalidInputError`` (a ``ValueError``) naming the bad value and the allowed range.

    Examples
    --------
    >>> import numpy as np
    >>> import pendulab as pl
    >>> p = pl.Pendulum(length=1.0, g=9.81, mass=1.0)
    >>> p
    Pendulum(length=1.0, g=9.81, mass=1.0)
    >>> pl.Pendulum(damping=0.003).model
    'damped'
    """

    def __init__(
        self,
        length: float = 1.0,
        g: float = 9.81,
        mass: float = 1.0,
        *,
        model: str | None = None,
        pivot_samples: tuple[Any, Any] | None = None,
        force: Callable[[float, Any, Any], Any] | None = None,
        **extra: float,
    ) -> None:
        length = checked("length", length, COMMON["length"])
        g = checked("g", g, COMMON["g"])
        mass = checked("mass", mass, COMMON["mass"])
        check_model_keywords(model, extra)
        if force is not None and not callable(force):
            raise InvalidInputError(
                f"force = {force!r} is not callable: give a function force(t, x, v) -> 3 numbers in N"
            )
        self._force = force
        if model is None:
            model = "sampled_pivot" if pivot_samples is not None else infer_model(extra)
        self._extra = {str(k): float(v) for k, v in extra.items()}
        self._pivot: tuple[FloatArray, FloatArray] | None = None
        if pivot_samples is not None:
            if not isinstance(pivot_samples, tuple | list) or len(pivot_samples) != 2:
                raise invalid("pivot_samples", pivot_samples, "a pair (times [s] (n,), positions [m] (n, 3))")
            times, positions = pivot_samples
            self._pivot = (
                _frozen(array("pivot_samples times", times, "time").ravel()),
                _frozen(array("pivot_samples positions", positions, "position")),
            )
        # validates everything (names, ranges, pivot samples) once, in the core, and keeps the model
        # built there: every run takes this spec (python/rust/spec.rs)
        self._spec = ModelSpec(
            float(length), float(mass), float(g), model, list(self._extra.items()), self._pivot
        )
        self.model = model
        self._length = float(length)
        self._g = float(g)
        self._mass = float(mass)

    @property
    def extra(self) -> dict[str, float]:
        """The model's own parameters as given (SI units; see ``pendulab.models()``)."""
        return dict(self._extra)

    @property
    def force(self) -> Callable[[float, Any, Any], Any] | None:
        """The user force ``force(t, x, v)`` [N], if any (the slow path; see the class doc)."""
        return self._force

    def force_at(self, t: Any, x: Any, v: Any) -> FloatArray:
        """The user force [N] at times t [s] (N,) and states x [m], v [m/s] (N, 3): (N, 3), zeros
        without one. Calls the callable once per sample; non-finite or malformed results are errors."""
        xa, va = (
            np.atleast_2d(np.asarray(x, dtype=np.float64)),
            np.atleast_2d(np.asarray(v, dtype=np.float64)),
        )
        ta = np.broadcast_to(np.asarray(0.0 if t is None else t, dtype=np.float64), (xa.shape[0],))
        out = np.zeros_like(xa)
        if self._force is None:
            return out
        for i in range(xa.shape[0]):
            f = np.asarray(self._force(float(ta[i]), xa[i].tolist(), va[i].tolist()), dtype=np.float64)
            if f.shape != (3,) or not np.all(np.isfinite(f)):
                raise InvalidInputError(
                    f"the force callable returned {f.tolist()!r} N at t = {float(ta[i])!r} s; "
                    "it must return 3 finite numbers"
                )
            out[i] = f
        return out

    @property
    def pivot_samples(self) -> tuple[FloatArray, FloatArray] | None:
        """The ``sampled_pivot`` model's samples: times [s] (n,) and positions [m] (n, 3); else None."""
        return self._pivot

    @property
    def length(self) -> float:
        """Rod length l [m]."""
        return self._length

    @property
    def g(self) -> float:
        """Gravity g [m/s²], along −z (or the model's gravity_x/y/z direction) for g > 0."""
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
        """Model name and parameters with SI values (length [m], mass [kg], g [m/s²], extras)."""
        out: dict[str, float | str] = {
            "model": self.model,
            "length": self._length,
            "mass": self._mass,
            "g": self._g,
            **self._extra,
        }
        if self._force is not None:
            out["force"] = f"python callable {getattr(self._force, '__qualname__', repr(self._force))}"
        return out

    @property
    def is_ideal(self) -> bool:
        """True for the ideal pendulum (the exact solution and the angle method need it)."""
        return self.model == "ideal" and self._force is None

    @property
    def spec(self) -> ModelSpec:
        """The model as the core built and checked it (``pendulab._core.ModelSpec``): what every run
        of this pendulum hands to the core, with a run's ``RunOptions`` and its start state."""
        return self._spec

    def __repr__(self) -> str:
        extras = "".join(f", {k}={v!r}" for k, v in self._extra.items())
        model = "" if _infer_model(set(self._extra)) == self.model else f", model={self.model!r}"
        if self._pivot is not None:
            model = f", pivot_samples=<{len(self._pivot[0])} samples>"
        if self._force is not None:
            model += f", force={self._force!r}"
        return f"Pendulum(length={self._length!r}, g={self._g!r}, mass={self._mass!r}{model}{extras})"

    def _repr_html_(self) -> str:
        rows: list[Row] = [
            ("model", self.model, ""),
            ("length l", self._length, "m"),
            ("gravity g", self._g, "m/s²"),
            ("mass m", self._mass, "kg"),
        ]
        units = {p["name"]: p["unit"] for m in model_table() if m["name"] == self.model for p in m["params"]}
        rows += [(k, v, units.get(k, "")) for k, v in self._extra.items()]
        if self._g != 0.0:
            omega0 = math.sqrt(abs(self._g) / self._length)
            rows += [
                ("ω₀ = √(|g|/l)", omega0, "rad/s"),
                ("small-swing period 2π/ω₀", 2.0 * math.pi / omega0, "s"),
            ]
        if self._pivot is not None:
            rows.append(("pivot samples", len(self._pivot[0]), ""))
        if self._force is not None:
            rows.append(("user force", repr(self._force), "N"))
        return html_table("Pendulum", rows)

    def state(self, x: Any, v: Any, *, project: bool = False) -> State:
        """State from Cartesian position x [m] and velocity v [m/s] (3 numbers each).

        Without ``project`` the state must lie on TS² (|x| = l and x·v = 0 to 1e-9 relative);
        with ``project=True`` it is moved there (x ← l x/|x|, v ← its tangential part) and
        ``State.projection`` says by how much.

        Examples
        --------
        >>> import numpy as np
        >>> import pendulab as pl
        >>> p = pl.Pendulum(length=2.0)
        >>> p.state([0.0, 0.0, -2.0], [1.0, 0.0, 0.0])
        State(x=[0, 0, -2] m, v=[1, 0, 0] m/s; θ=0°, φ=0°)
        >>> p.state([0.0, 0.0, -2.1], [1.0, 0.0, 0.0], project=True).projection
        (0.10000000000000009, 0.0)
        """
        return state_from_cartesian(self._spec, self._length, x, v, project)

    def state_from_angles(
        self,
        theta: float | None = None,
        phi: float | None = None,
        theta_dot: float | None = None,
        phi_dot: float | None = None,
        *,
        theta_deg: float | None = None,
        phi_deg: float | None = None,
        theta_dot_deg: float | None = None,
        phi_dot_deg: float | None = None,
    ) -> State:
        """State at polar angle θ [rad] from the downward vertical, azimuth φ [rad], rates θ̇, φ̇ [rad/s].

        Radians are the default; each angle may be given in degrees instead (``theta_deg`` [°],
        ``phi_deg`` [°], ``theta_dot_deg``, ``phi_dot_deg`` [°/s]), never both ways. θ (or θ in degrees)
        is required; the others default to 0. Angles are limited to ±1e6 (rad or degrees), rates to
        ±1e9 (rad/s or °/s), and the velocity they give to 1e7 m/s (docs/limits.md). A θ beyond 2π rad
        is allowed but warned about, since it is most often meant in degrees (``theta=60`` is 60 rad,
        not 60°).

        Examples
        --------
        >>> import numpy as np
        >>> import pendulab as pl
        >>> p = pl.Pendulum()
        >>> s = p.state_from_angles(theta=np.radians(60), phi_dot=2.0)
        >>> s
        State(x=[0.866025, 0, -0.5] m, v=[0, 1.73205, 0] m/s; θ=60°, φ=0°)
        >>> p.state_from_angles(theta_deg=90).x
        array([ 1.000000e+00,  0.000000e+00, -6.123234e-17])
        """
        values = angles_in_radians(
            (
                ("theta", theta, theta_deg),
                ("phi", phi, phi_deg),
                ("theta_dot", theta_dot, theta_dot_deg),
                ("phi_dot", phi_dot, phi_dot_deg),
            )
        )
        if theta is not None and abs(values[0]) > 2.0 * math.pi:
            warn_user(
                f"theta = {theta!r} rad is more than 2π; angles are in radians (use theta_deg={theta!r} "
                "for degrees)",
                UserWarning,
            )
        return state_from_angle_values(self._spec, values)

    def diagnostics(self, x: Any, v: Any, t: Any = None) -> dict[str, FloatArray]:
        """Diagnostics along arrays x [m], v [m/s] of shape (N, 3) or (3,), at times t [s] (N values or
        a scalar; default 0 — give them for time-dependent models, whose forcing, pivot and tension
        depend on t): ``energy`` [J] (including the model's potential, T-2.6), ``j3`` [kg m²/s],
        ``tension`` [N] (T-2.3), ``radius_error`` |x| − l [m], ``tangency`` x·v [m²/s], ``power`` [W]
        = dE/dt of the non-conservative forces (T-7.1; 0 for the ideal pendulum), ``acceleration``
        (N, 3) [m/s²] ẍ = f + λx of T-2.2 (relative to the pivot, the user force included) and, for a
        moving pivot when t is given, ``pivot`` (N, 3) [m]."""
        xa = np.ascontiguousarray(np.atleast_2d(array("x", x, "position")))
        va = np.ascontiguousarray(np.atleast_2d(array("v", v, "velocity")))
        ta = None
        if t is not None:
            ta = array("t", t, "time")
            if ta.ndim == 0:
                ta = np.full(xa.shape[0], float(ta))
            ta = np.ascontiguousarray(ta.ravel())
        d = _diagnostics(self._spec, xa, va, ta)
        if self._force is not None:
            # the user force: its power F·v, its share x·F/l of the tension, and its tangential part
            # (F − x (x·F)/l²)/m of the acceleration (the rod takes the radial part, T-2.2)
            f = self.force_at(ta, xa, va)
            radial = np.einsum("ij,ij->i", f, xa)
            d["power"] = d["power"] + np.einsum("ij,ij->i", f, va)
            d["tension"] = d["tension"] + radial / self._length
            tangential = f - xa * (radial / self._length**2)[:, None]
            d["acceleration"] = d["acceleration"] + tangential / self._mass
        return d

    def energy(self, state: State) -> float:
        """Total energy E = m(½|v|² + V(x)) [J] (T-2.6); V = g z for the ideal pendulum, plus the
        model's potential (tilted gravity, centrifugal) otherwise."""
        return float(self.diagnostics(state.x, state.v)["energy"][0])

    def j3(self, state: State) -> float:
        """Vertical angular momentum J₃ = m (x × v)·e₃ [kg m²/s] (T-2.6)."""
        return float(self.diagnostics(state.x, state.v)["j3"][0])

    def tension(self, state: State, t: float = 0.0) -> float:
        """Rod tension T = m(|v|² + x·f)/l [N] at time t [s] (T-2.3; f the applied force per unit
        mass, −g e₃ for the ideal pendulum); negative means the rod pushes."""
        return float(self.diagnostics(state.x, state.v, t)["tension"][0])

    def power(self, state: State, t: float = 0.0) -> float:
        """Power of the non-conservative forces at time t [s], dE/dt = m P [W] (T-7.1): forcing,
        damping and drag, or the moving pivot's inertial force; 0 for conservative models."""
        return float(self.diagnostics(state.x, state.v, t)["power"][0])


def check_pendulum_state(pendulum: Any, state: Any) -> None:
    """``pendulum`` is a :class:`Pendulum` and ``state`` a :class:`State` (named errors otherwise)."""
    if not isinstance(pendulum, Pendulum):
        raise invalid("pendulum", pendulum, "a pendulab.Pendulum")
    if not isinstance(state, State):
        raise invalid("state", state, "a pendulab.State (from Pendulum.state or Pendulum.state_from_angles)")
    for name, value, unit in (("state.x", state.x, "m"), ("state.v", state.v, "m/s")):
        # a State built by hand may hold complex numbers or strings: refused by name, not cast or
        # handed to the core (a TypeError about 'PyArray<T, D>' before)
        try:
            a = np.asarray(value)
        except (TypeError, ValueError):  # ragged
            a = np.asarray(None)
        if a.dtype.kind not in "fiu" or a.shape != (3,):
            raise invalid(name, value, f"3 real numbers [{unit}] (a float64 array of shape (3,))")
