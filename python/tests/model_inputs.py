"""Shared inputs of the model tests (test_models*.py): the rosette start and a forced, damped pendulum.
Units: angles in rad, angular rates in rad/s, damping c in 1/s, drag c_q in 1/m, a force per unit
mass in m/s² at an angular frequency in rad/s."""

from __future__ import annotations

import math

ROSETTE = (math.radians(60.0), 0.0, 0.0, 2.0)  # θ₀ [rad], φ₀ [rad], θ̇₀, φ̇₀ [rad/s]
# damping c [1/s], drag c_q [1/m], a force per unit mass 0.8 m/s² cos(2.7 rad/s · t) along e_y
FORCED = {
    "damping": 0.05,
    "drag": 0.02,
    "forcing_amplitude": 0.8,
    "forcing_omega": 2.7,
    "forcing_x": 0.0,
    "forcing_y": 1.0,
}
