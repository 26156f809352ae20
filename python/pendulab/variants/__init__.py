"""The real variants beyond the rigid rod on a fixed pivot that have drivers of their own: the slewing
crane's closed-form small sway, the swinging spring (an elastic rod) and the string that can go slack.
SI units throughout."""

from .crane import SlewingSway, slewing_sway
from .spring import SpringTrajectory, SwingingSpring, simulate_spring

__all__ = ["SlewingSway", "SpringTrajectory", "SwingingSpring", "simulate_spring", "slewing_sway"]
