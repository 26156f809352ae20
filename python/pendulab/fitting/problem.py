"""The unknowns of a fit and the forward model: a vector of parameter values → the pendulum, its state
at the first sample time and the offsets → the predicted data.

Parameter names (SI units):

- the model's own parameters, as ``pl.models()`` lists them: ``length`` [m], ``g`` [m/s²], ``mass``
  [kg], and per model e.g. ``damping`` [1/s], ``drag`` [1/m], ``frame_rate`` [rad/s];
- the start at the first sample time t₀: ``theta0``, ``phi0`` [rad], ``theta_dot0``, ``phi_dot0``
  [rad/s] (θ from the downward vertical, T-1.2);
- ``pivot_x``, ``pivot_y``, ``pivot_z`` [m]: where the pivot is in the frame of measured positions;
- ``t_offset`` [s]: the model's clock runs from t₀ + t_offset (ideal pendulum only: the exact solution
  runs backward in time as well);
- systematic terms of the measurement (:data:`SYSTEMATIC_NAMES`, neutral by default): ``scale`` [1]
  multiplies the positions about the pivot (a camera's scale bar: measured = pivot + scale·x) and the
  ``horizontal`` ones, the kinds that are lengths (:data:`LENGTH_KINDS`), no other kind;
  ``angle_offset`` [rad] is added to a planar angle and to θ (an encoder's zero); ``force_bias``
  [m/s²] to the specific force and ``rate_bias`` [rad/s] to the angular speed (a sensor's bias);
  ``perspective`` κ = 1/D [1/m] is a camera at distance D in front of the pivot looking along +y, which
  sees the bob's offset from the pivot shrunk by 1/(1 + κ y) (a pinhole; 0: the far-away camera; it acts
  on ``positions`` only, no other data kind is seen through a camera). A
  clock rate is not among them: a clock running fast by a factor κ is indistinguishable from g/l
  larger by κ², so only an independent time reference could tell.
- the swinging spring (``model = "spring"``, a :class:`pendulab.SwingingSpring`): ``length`` is its
  rest length l₀, ``stiffness`` k [N/m], and the start has also ``r0`` [m], ``r_dot0`` [m/s]
  (spring_model.py).

The forward model is the exact solution (T-4.x) for the ideal pendulum and DOP853 at rtol 1e-12 with
dense output at the sample times otherwise, so that its own error (≲ 1e-10 relative) stays far below
any measurement noise and noise-free data are recovered to about 1e-8; the spring's is its own
(spring_model.py).
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np

from .._core import IntegrationError, InvalidInputError
from ..model import FloatArray, Pendulum, State
from ..simulation import simulate
from ..theory.exact import exact
from ..validate import model_params_of
from ..variants.spring import SwingingSpring
from . import spring_model
from .data import Observations, predict, residual

STATE_NAMES = ("theta0", "phi0", "theta_dot0", "phi_dot0")
PIVOT_NAMES = ("pivot_x", "pivot_y", "pivot_z")
OFFSET_NAMES = ("t_offset",)
POSITIVE = {"length", "mass", "g", "damping", "drag", "stiffness", "r0", "scale"}
"""Parameters that are positive by nature: the search and the error analysis work in ln p for them."""
SYSTEMATIC_NAMES = {
    "scale": 1.0,
    "angle_offset": 0.0,
    "force_bias": 0.0,
    "rate_bias": 0.0,
    "perspective": 0.0,
}
"""The systematic terms of the measurement and their neutral values (module doc)."""
ROD_MODELS = ("ideal", "damped", "rotating", "slewing", "vibrating")
FITTABLE_MODELS = (*ROD_MODELS, "spring")
UNITS_EXTRA = {
    "theta0": "rad",
    "phi0": "rad",
    "theta_dot0": "rad/s",
    "phi_dot0": "rad/s",
    "pivot_x": "m",
    "pivot_y": "m",
    "pivot_z": "m",
    "t_offset": "s",
    "scale": "1",
    "angle_offset": "rad",
    "force_bias": "m/s^2",
    "rate_bias": "rad/s",
    "perspective": "1/m",
    "r0": "m",
    "r_dot0": "m/s",
}
LENGTH_KINDS = ("positions", "horizontal")
"""The data kinds that are lengths read off a scale (a camera's, a ruler's): ``scale`` multiplies
these only. Angles are the same for a scaled x; a phone's |ω| = |x × v|/l² and |a − g⃗| are not
measured against any scale bar."""
RTOL = 1e-12
ATOL = 1e-14
BUILT_KEPT = 64
"""The pendulums a :class:`Problem` keeps built (:meth:`Problem.pendulum`)."""


def model_params(model: str) -> Mapping[str, Mapping[str, Any]]:
    """The registry's parameters of ``model`` (name → spec with unit, default, min, max), read-only
    and shared (:func:`pendulab.validate.model_params_of`): a fit asks for them for every residual
    (about 1850 times in the tour's encoder-decay fit)."""
    table = model_params_of(model)
    if table is None:
        raise InvalidInputError(f"unknown model {model!r}: use one of {', '.join(FITTABLE_MODELS)}")
    return table


Motion = tuple[Pendulum | SwingingSpring, FloatArray, FloatArray, FloatArray]
"""A pendulum and its x [m], v [m/s] at the sample times, with the model times τ [s]."""


@dataclass
class Problem:
    """Everything a fit evaluates: the model, all parameter values (the free ones are overwritten by
    the optimizer), which are free, the data, and the first sample time t₀ [s]."""

    model: str
    values: dict[str, float]
    free: list[str]
    obs: Observations
    evaluations: int = 0
    built: dict[tuple[float, ...], Pendulum | SwingingSpring] = field(
        default_factory=dict, init=False, repr=False, compare=False
    )
    """The pendulums built, by their parameter values (:meth:`pendulum`; at most :data:`BUILT_KEPT`);
    a copy (``dataclasses.replace``, :meth:`restricted`) starts with none."""

    @property
    def t0(self) -> float:
        return float(self.obs.t[0])

    def restricted(self, n: int) -> Problem:
        """The same problem on the first ``n`` samples only (same t₀)."""
        obs = self.obs
        part = replace(obs, t=obs.t[:n], values={k: v[:n] for k, v in obs.values.items()})
        return Problem(self.model, self.values, self.free, part)

    def with_free(self, u: Iterable[float]) -> dict[str, float]:
        """All values, the free ones taken from ``u`` (same order as ``free``)."""
        out = dict(self.values)
        out.update({name: float(x) for name, x in zip(self.free, u, strict=True)})
        return out

    def pendulum(self, values: Mapping[str, float]) -> Pendulum | SwingingSpring:
        """The model with ``values`` (SI units). A fit asks for the same one many times (every column
        of the exact Jacobian whose parameter does not move the motion, a refit's start), and a
        pendulum is immutable, so each is built once and kept (the last :data:`BUILT_KEPT`)."""
        key = tuple(float(values[k]) for k in model_params(self.model))
        made = self.built.get(key)
        if made is None:
            if len(self.built) >= BUILT_KEPT:
                self.built.clear()
            made = self.built[key] = self._build(values)
        return made

    def _build(self, values: Mapping[str, float]) -> Pendulum | SwingingSpring:
        if self.model == "spring":
            return SwingingSpring(
                values["stiffness"] / values["mass"], values["length"], values["g"], values["mass"]
            )
        own = model_params(self.model)
        extra = {
            k: values[k]
            for k, spec in own.items()
            if k not in ("length", "g", "mass") and values[k] != spec["default"]
        }
        # **extra holds only the model's own float parameters by name (never model/force/pivot_samples)
        return Pendulum(values["length"], values["g"], values["mass"], model=self.model, **extra)  # type: ignore[arg-type]

    def state0(self, pendulum: Pendulum | SwingingSpring, values: Mapping[str, float]) -> State:
        if isinstance(pendulum, SwingingSpring):
            return State(*spring_model.start_vectors(values))
        theta, phi, theta_dot, phi_dot = (values[k] for k in STATE_NAMES)
        if theta < 0.0:  # a signed θ₀ (a hinge's swing through the bottom): (−θ, φ) is (θ, φ + π), θ̇ → −θ̇
            theta, phi, theta_dot = -theta, phi + math.pi, -theta_dot
        return pendulum.state_from_angles(theta, phi, theta_dot, phi_dot)

    def motion(self, values: Mapping[str, float]) -> Motion:
        """The pendulum and its x [m], v [m/s] at the sample times, with the model times τ [s]."""
        p = self.pendulum(values)
        tau = self.obs.t - self.t0 - values.get("t_offset", 0.0)
        if isinstance(p, SwingingSpring):
            x, v = spring_model.motion(values, tau)
            return p, x, v, tau
        s = self.state0(p, values)
        if p.is_ideal:
            x, v = exact(p, s).state(tau)
            return p, x, v, tau
        if tau[0] != 0.0:  # pragma: no cover - t_offset is refused for these models up front
            raise InvalidInputError("t_offset is fitted for the ideal pendulum only")
        tr = simulate(p, s, float(tau[-1]), method="dop853", rtol=RTOL, atol=ATOL * p.length, save_at=tau)
        return p, tr.x, tr.v, tau

    def predictions(self, values: Mapping[str, float], motion: Motion | None = None) -> dict[str, FloatArray]:
        """Each data kind as the model with ``values`` predicts it (from ``motion``, the result of
        :meth:`motion`, when given: the exact Jacobian of sensitivity.py moves it by its derivatives)."""
        p, x, v, tau = motion if motion is not None else self.motion(values)
        accel = None
        if "specific_force" in self.obs.values:
            accel = (
                spring_model.acceleration(x, p.k_over_m, p.rest_length, p.g)
                if isinstance(p, SwingingSpring)
                else p.diagnostics(x, v, tau)["acceleration"]
            )
        gdir = np.array([0.0, 0.0, -1.0])
        if self.model == "damped":
            gdir = np.array(
                [values.get(f"gravity_{a}", d) for a, d in zip("xyz", (0.0, 0.0, -1.0), strict=True)]
            )
            gdir = gdir / np.linalg.norm(gdir)
        gravity = values["g"] * gdir
        pivot = np.array([values.get(k, 0.0) for k in PIVOT_NAMES])
        if self.model in ("slewing", "vibrating") and {"positions", "horizontal"} & set(self.obs.values):
            assert isinstance(p, Pendulum)
            pivot = pivot + p.diagnostics(x, v, tau)["pivot"]
        scale = values.get("scale", 1.0)
        seen = x if scale == 1.0 else scale * x  # lengths on a scale bar: LENGTH_KINDS only
        kappa = values.get("perspective", 0.0)
        camera = seen  # the positions (x, z) a camera sees; no other kind is seen through it
        if kappa != 0.0 and "positions" in self.obs.values:  # a pinhole at 1/κ before the pivot, along +y
            depth = 1.0 + kappa * x[:, 1]
            if not np.all(depth > 0.0):
                raise InvalidInputError(f"perspective = {kappa!r} 1/m puts the bob behind the camera")
            camera = seen / depth[:, None]
        out = {}
        for kind in self.obs.values:
            shown = camera if kind == "positions" else seen if kind in LENGTH_KINDS else x
            out[kind] = predict(kind, self.obs.columns[kind], shown, v, accel, gravity, pivot)
        return _with_offsets(out, values)

    def residuals(
        self, values: Mapping[str, float], sigma: Mapping[str, float], motion: Motion | None = None
    ) -> FloatArray:
        """(measured − predicted)/σ for every value of every kind, as one vector (``motion``: as in
        :meth:`predictions`)."""
        self.evaluations += 1
        pred = self.predictions(values, motion)
        parts = [
            (residual(kind, self.obs.values[kind], pred[kind]) / sigma[kind]).ravel()
            for kind in self.obs.values
        ]
        return np.concatenate(parts)

    def penalty(self, sigma: Mapping[str, float]) -> float:
        """A residual larger than any the data can give [units of σ]: what a model that cannot be
        evaluated costs, 10³ times the largest |value| over its σ (at least 10⁶)."""
        return max(
            1e6, *(1e3 * float(np.max(np.abs(v))) / sigma[k] for k, v in self.obs.values.items() if v.size)
        )

    def safe_residuals(self, u: Iterable[float], sigma: Mapping[str, float]) -> FloatArray:
        """:meth:`residuals` for the optimizer: a model that cannot be evaluated there (a start off the
        registry's limits, a run that diverged) gives a large finite residual (:meth:`penalty`) instead
        of an exception."""
        try:
            r = self.residuals(self.with_free(u), sigma)
        except (InvalidInputError, IntegrationError, OverflowError, ZeroDivisionError):
            return np.full(self.obs.n_residuals, self.penalty(sigma))
        finite = np.isfinite(r)
        return r if finite.all() else np.where(finite, r, self.penalty(sigma))


def _with_offsets(pred: dict[str, FloatArray], values: Mapping[str, float]) -> dict[str, FloatArray]:
    """The systematic terms added to the predictions (module doc); neutral ones cost nothing."""
    offset = values.get("angle_offset", 0.0)
    if offset != 0.0:
        if "planar_angle" in pred:
            pred["planar_angle"] = pred["planar_angle"] + offset
        if "angles" in pred:
            pred["angles"] = pred["angles"] + np.array([offset, 0.0])
    for name, kind in (("force_bias", "specific_force"), ("rate_bias", "angular_speed")):
        bias = values.get(name, 0.0)
        if bias != 0.0 and kind in pred:
            pred[kind] = pred[kind] + bias
    return pred


def check_model(pendulum: Pendulum | SwingingSpring) -> str:
    """The model name, if the fit can handle it; a clear error otherwise."""
    if isinstance(pendulum, SwingingSpring):
        return "spring"
    if pendulum.force is not None or pendulum.pivot_samples is not None:
        raise InvalidInputError("fit takes a registry model, not a user force or a sampled pivot path")
    if pendulum.model not in FITTABLE_MODELS:
        raise InvalidInputError(
            f"fit works with the models {', '.join(FITTABLE_MODELS)} (the spring as a pl.SwingingSpring); "
            f"{pendulum.model!r} is not supported yet"
        )
    return pendulum.model


def unit_of(model: str, name: str) -> str:
    if name in UNITS_EXTRA:
        return UNITS_EXTRA[name]
    return str(model_params(model)[name]["unit"])


def bounds_of(model: str, name: str, value: float) -> tuple[float, float]:
    """Where the optimizer may go for ``name`` (the registry's limits; θ₀ in [0, π])."""
    if name == "theta0":  # signed: a swing crosses the bottom smoothly (state0: (−θ, φ) = (θ, φ + π))
        return -math.pi, math.pi
    if name == "r0":
        return 1e-9 * abs(value), math.inf
    if name == "scale":
        return 1e-6, 1e6
    if name in UNITS_EXTRA:
        return -math.inf, math.inf
    spec = model_params(model)[name]
    lo, hi = float(spec["min"]), float(spec["max"])
    if name in ("length", "mass"):
        lo = max(lo, 1e-9 * abs(value))
    return lo, hi


def scale_of(name: str, value: float, length: float, period: float) -> float:
    """A typical size of ``name`` near ``value``: the optimizer moves in units of it."""
    if name in ("theta0", "phi0"):
        return 1.0
    if name in ("theta_dot0", "phi_dot0"):
        return max(abs(value), 2.0 * math.pi / period)
    if name in (*PIVOT_NAMES, "r0"):
        return length
    if name == "r_dot0":
        return max(abs(value), length * 2.0 * math.pi / period)
    if name == "t_offset":
        return period / 10.0
    if name == "scale":
        return 0.1
    if name == "angle_offset":
        return 0.01
    if name == "perspective":
        return 0.1 / length
    return max(abs(value), 1e-3 if name != "g" else 1e-2)
