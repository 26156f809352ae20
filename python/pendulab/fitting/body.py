"""A fit of a physical (compound) pendulum whose geometry is known (docs/fit.md, "A physical (compound)
pendulum"; docs/theory.md T-7.7): ``pl.fit(..., body=pl.CompoundPendulum(...))``.

The body swings as the point pendulum of length l_eq = I_O/(M h) and mass M, with every pivot torque
divided by I_O (T-7.1, T-7.6):

- its length is l_eq from the geometry (held, so that a recording of the angle alone determines g —
  the physical pendulum as a gravimeter), unless ``length`` is fitted; then the fitted length is l_eq
  and :meth:`BodyFit.distance` turns it into the position d of one part, with
  σ_d = σ_l/|∂l_eq/∂d|, ∂l_eq/∂d = m (2d − l_eq)/(M h) for a part of mass m at d;
- a fitted ``damping`` c [1/s] is the viscous pivot torque coefficient b = c I_O [N m s];
- a fitted ``friction`` ε_f [rad/s²] is the dry pivot friction torque τ_f = ε_f I_O [N m].

Units: SI (m, kg, kg m², N m, N m s).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass

from .._core import InvalidInputError
from ..model import Pendulum
from ..variants.compound import CompoundPendulum

#: Fitted parameters → (torque name, unit) of the body's pivot: value × I_O.
TORQUES = {"damping": ("damping_torque", "N m s"), "friction": ("friction_torque", "N m")}


def pendulum_of(body: object, pendulum: object) -> Pendulum:
    """The point pendulum the fit runs: ``pendulum``'s model, g and laws with the body's l_eq and M."""
    if not isinstance(body, CompoundPendulum):
        raise InvalidInputError(f"body must be a pendulab.CompoundPendulum, got {type(body).__name__}")
    base = Pendulum() if pendulum is None else pendulum
    if not isinstance(base, Pendulum):
        raise InvalidInputError(
            f"body= needs a pendulab.Pendulum (its model, g, damping) as pendulum=, got {type(base).__name__}"
        )
    if base.force is not None or base.pivot_samples is not None:
        raise InvalidInputError("body= takes a pendulum on a fixed axis: no force= and no pivot_samples=")
    # **base.extra holds only the model's own float parameters by name (never model/force/pivot_samples)
    return Pendulum(body.equivalent_length, base.g, body.mass, model=base.model, **base.extra)  # type: ignore[arg-type]


@dataclass(frozen=True)
class BodyFit:
    """What a fit says about the body: its geometry, the fitted values converted to pivot torques
    (``torques``: name → (value, standard error) [N m or N m s]) and, when ``length`` was fitted, the
    equivalent length the data give (``length``: (value, standard error) [m])."""

    body: CompoundPendulum
    torques: dict[str, tuple[float, float]]
    length: tuple[float, float] | None

    @classmethod
    def of(cls, body: CompoundPendulum, params: Mapping[str, float], stderr: Mapping[str, float]) -> BodyFit:
        inertia = body.inertia
        torques = {
            TORQUES[name][0]: (params[name] * inertia, stderr[name] * inertia)
            for name in TORQUES
            if name in params
        }
        length = (params["length"], stderr["length"]) if "length" in params else None
        return cls(body, torques, length)

    def distance(self, index: int) -> tuple[float, float]:
        """The position d [m] of part ``index`` that makes the body's l_eq the fitted length, with its
        standard error (module doc). Needs ``length`` among the fitted parameters."""
        if self.length is None:
            raise InvalidInputError("the length was not fitted: fit=[..., 'length'] gives a part's position")
        fitted, err = self.length
        moved = self.body.solve_distance(index, fitted)
        part = moved.parts[index]
        slope = part.mass * (2.0 * part.distance - fitted) / (moved.mass * moved.centre)
        return part.distance, (abs(err / slope) if slope != 0.0 else math.inf)

    def report_lines(self) -> list[str]:
        b = self.body
        lines = [f"  compound pendulum: {b.formula} (I_O = {b.inertia:.6g} kg m², M = {b.mass:.6g} kg)"]
        if self.length is None:
            lines.append("  length held at the body's l_eq; fit 'length' to test the geometry")
        else:
            value, err = self.length
            off = (value - b.equivalent_length) / err if err > 0.0 and math.isfinite(err) else math.inf
            lines.append(
                f"  fitted length {value:.6g} ± {err:.2g} m is {off:+.2g} standard errors from the "
                "geometry's l_eq (res.body.distance(i): the part position it implies)"
            )
        units = dict(TORQUES.values())
        for name, (value, err) in self.torques.items():
            lines.append(f"  {name} = {value:.6g} ± {err:.2g} {units[name]} (fitted value × I_O)")
        return lines
