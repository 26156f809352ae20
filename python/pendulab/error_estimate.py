"""The error record a trajectory carries: position [m] and velocity [m/s] errors at every sample.

``Trajectory.error_estimate`` is an *estimate* of the global error (how it was made: ``how`` and
``reference``); ``Trajectory.error`` is the *true* error against the exact solution (ideal pendulum
only, T-4.x; ``how = "exact"``). Both are |x_computed − x_reference| [m] and |v − v_reference| [m/s]
per saved sample, so they can be compared with each other and with a requested accuracy (relative to
the length l).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np
import numpy.typing as npt

from .display import Row, html_table, number


@dataclass(frozen=True)
class ErrorEstimate:
    """Global errors at the saved samples.

    ``position`` (N,) [m] and ``velocity`` (N,) [m/s]; ``how``: ``"richardson"`` (fixed-step methods, p
    the method's order: the run against one at twice the step, divided by 2^p − 1, or — when that coarse
    run is ruled out — against one at half the step, scaled by 2^p/(2^p − 1); ``reference["companion"]``
    is ``"2dt"`` or ``"dt/2"``, ``reference["why"]`` says why the coarse run was ruled out; on a sampled
    pivot ``reference["halved"]``: the dt/2 companion is the plain run with each (sub-)step taken as two
    halves), ``"companion"`` (DOP853: against a run at a 10× tighter tolerance, or a 10× looser one at
    the tightest tolerance allowed) or ``"exact"`` (the true error against the exact solution);
    ``reference`` the settings of the reference run; ``cost`` the work of the reference runs relative to
    the plain run (right-hand side evaluations; 0.5 for "2dt", 2.5 for a "dt/2" after a rejected 2dt
    run, 2 when the save times ruled 2dt out, ≈ 1.3 for DOP853).
    """

    position: npt.NDArray[np.float64]
    velocity: npt.NDArray[np.float64]
    how: str
    reference: dict[str, Any] = field(default_factory=dict)
    cost: float = 0.0

    def __repr__(self) -> str:
        return (
            f"ErrorEstimate({self.how}, {len(self.position)} samples, max position error "
            f"{number(np.max(self.position, initial=0.0), 3)} m, max velocity error "
            f"{number(np.max(self.velocity, initial=0.0), 3)} m/s, cost {number(self.cost, 3)})"
        )

    def _repr_html_(self) -> str:
        rows: list[Row] = [
            ("how", self.how, ""),
            ("max position error", float(np.max(self.position, initial=0.0)), "m"),
            ("max velocity error", float(np.max(self.velocity, initial=0.0)), "m/s"),
            ("work of the reference run(s) / plain run", self.cost, ""),
        ]
        return html_table("Estimated global error", rows)

    @property
    def max_position(self) -> float:
        """Largest position error over the run [m]."""
        return float(np.max(self.position, initial=0.0))

    @property
    def max_velocity(self) -> float:
        """Largest velocity error over the run [m/s]."""
        return float(np.max(self.velocity, initial=0.0))

    def describe(self) -> dict[str, Any]:
        """JSON-ready summary (file metadata): how, reference, cost, the largest errors."""
        return {
            "how": self.how,
            "reference": self.reference,
            "cost": self.cost,
            "max_position_m": self.max_position,
            "max_velocity_m_per_s": self.max_velocity,
        }
