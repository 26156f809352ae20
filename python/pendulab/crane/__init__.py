"""Cranes as crane engineers meet them (docs/cranes.md, docs/theory.md §8): command shapers and their
residual vibration, acceleration- and jerk-limited moves shaped by convolution, crane kinematics
(gantry, tower, luffing boom) as pivot paths. SI units (m, s, rad, rad/s, kg, N).

    from pendulab import crane
    s = crane.shaper("zvd", omega=0.99)                  # .times [s], .amplitudes (sum 1)
    V = crane.residual_vibration(s, omega=np.linspace(0.5, 1.5, 201))
    path = crane.move(distance=5.0, v_max=0.5, a_max=0.5, shaper=s)
"""

from .move import Profile, profile
from .shaper import KINDS, Shaper, insensitivity, residual_vibration, shaper

__all__ = [
    "KINDS",
    "Profile",
    "Shaper",
    "insensitivity",
    "profile",
    "residual_vibration",
    "shaper",
]
