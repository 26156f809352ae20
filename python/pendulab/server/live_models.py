"""The pendulum a scenario gives the lab, as the server describes it to the core's live session
(``GET /api/scenarios``, :func:`pendulab.server.session.describe`): a :class:`pendulab.Pendulum` of any
lab model, or the swinging spring (:class:`SpringPendulum`: an elastic rod, T-7.4, whose state is
(r, v) ∈ R³ × R³ off the sphere). The stepping of every model — the rod models, the spring in whole
steps of Störmer–Verlet or its triple jump, the string on the grid t₀ + k·dt with its taut/slack mode —
is the core's live session's (``crates/pendulab-core/src/live/pendulum.rs``, ``LiveStepper``).
SI units throughout.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from .._core import InvalidInputError
from ..model import Pendulum
from ..scenario import Scenario
from .crane_setup import CranePendulum

OWN_STEPPER_MODELS = ("spring", "string")
"""Models of the registry that the lab runs with their own core steppers instead of ``pendulab.Stepper``."""


@dataclass(frozen=True)
class SpringPendulum:
    """The swinging spring as a scenario gives it to the lab, in the place of a :class:`pendulab.Pendulum`:
    ``length`` is the rest length l₀ [m], ``stiffness`` k [N/m], ``mass`` [kg], ``g`` [m/s²] along −z.
    The bob hangs at rest at the equilibrium length l₀ + m |g|/k (above the pivot for g < 0)."""

    length: float
    g: float
    mass: float
    stiffness: float
    model: str = "spring"

    def __post_init__(self) -> None:
        for name, value in (("length", self.length), ("mass", self.mass), ("stiffness", self.stiffness)):
            if not (math.isfinite(value) and value > 0):
                unit = {"length": "m", "mass": "kg", "stiffness": "N/m"}[name]
                raise InvalidInputError(f"invalid {name} = {value!r}: a finite number > 0 ({unit})")
        if not math.isfinite(self.g):
            raise InvalidInputError(f"invalid g = {self.g!r}: a finite number (m/s²)")

    @property
    def extra(self) -> dict[str, float]:
        """The model's own parameters (SI)."""
        return {"stiffness": self.stiffness}


LabPendulum = Pendulum | SpringPendulum | CranePendulum
"""What a scenario gives the lab: a pendulum of a registry model, the swinging spring, or the crane mode's
load (a crane file, :mod:`.crane_setup`)."""


def scenario_pendulum(sc: Scenario) -> LabPendulum:
    """The lab's pendulum of a scenario (the spring's from ``Scenario.spring()``)."""
    spring = sc.spring()
    if spring is not None:
        return SpringPendulum(spring.rest_length, spring.g, spring.mass, spring.k_over_m * spring.mass)
    return sc.pendulum()
