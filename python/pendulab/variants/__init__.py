"""The real variants beyond the rigid rod on a fixed pivot that have drivers of their own: the slewing
crane's closed-form small sway, the compound pendulum as its equivalent point pendulum, the swinging
spring (an elastic rod) and the string that can go slack. SI units throughout."""

from .compound import CompoundPendulum, Part
from .crane import SlewingSway, slewing_sway
from .spring import SpringTrajectory, SwingingSpring, simulate_spring

__all__ = [
    "CompoundPendulum",
    "Part",
    "SlewingSway",
    "SpringTrajectory",
    "SwingingSpring",
    "simulate_spring",
    "slewing_sway",
]
