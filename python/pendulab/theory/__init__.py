"""The ideal pendulum's theory, computed: the exact solution by elliptic functions (T-4.x) and its
phases (T-5.1), the S¹ reduction to σ-invariants and the Nambu flow (T-3.x), the azimuthal advance
measured from a trajectory, and the energy–momentum map with rotation number and monodromy (T-6.x).
SI units throughout."""

from .advance import MeasuredAdvance, measured_azimuth_advance
from .em_map import EMMap, em_map
from .exact import ExactSolution, Phases, exact
from .phase_orbit import PhaseOrbit, phase_orbit
from .reduce import Reduced, ReducedSurfaces, reduce, reduced_flow, reduced_surfaces

__all__ = [
    "EMMap",
    "ExactSolution",
    "MeasuredAdvance",
    "PhaseOrbit",
    "Phases",
    "Reduced",
    "ReducedSurfaces",
    "em_map",
    "exact",
    "measured_azimuth_advance",
    "phase_orbit",
    "reduce",
    "reduced_flow",
    "reduced_surfaces",
]
