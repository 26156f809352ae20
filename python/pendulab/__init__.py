"""Pendulab: the spherical pendulum, simulated right.

SI units throughout (m, kg, s, rad); z axis up; gravity along −z for g > 0; the polar angle θ is
measured from the downward vertical. Quick start::

    import numpy as np, pendulab as pl
    p = pl.Pendulum(length=1.0, g=9.81, mass=1.0)
    s0 = p.state_from_angles(theta=np.radians(60), phi=0.0, theta_dot=0.0, phi_dot=2.0)
    tr = pl.simulate(p, s0, t_end=100.0, method="rattle", dt=1e-3, save_every=10)
    print(tr.summary())
    sol = pl.exact(p, s0)               # the exact solution (docs/theory.md §4): sol.state(t), sol.phases()
    pl.models()                         # the real-pendulum models (§7): damped, rotating, ... (SI units)

Plots (matplotlib, optional): ``pendulab.plot``.
"""

from ._core import IntegrationError, InvalidInputError, __version__
from .ensemble.run import EnsembleResult, simulate_ensemble, states_from_angles
from .ensemble.save import Save
from .error_estimate import ErrorEstimate
from .fitting import Comparison, FitResult, compare_fits, fit
from .integrators import method_names, methods
from .model import Pendulum, State, models
from .scenario import Scenario, ScenarioError, load_scenario
from .simulation import simulate
from .stepper import Stepper
from .sweeps import design as sweep_design
from .sweeps.results import SweepResult, read_sweep
from .sweeps.run import sweep
from .theory.advance import MeasuredAdvance, measured_azimuth_advance
from .theory.em_map import EMMap, em_map
from .theory.exact import ExactSolution, Phases, exact
from .theory.reduce import Reduced, reduce, reduced_flow
from .trajectory import Trajectory
from .validate import limits
from .variants.compound import CompoundPendulum, Part
from .variants.crane import SlewingSway, slewing_sway
from .variants.spring import SpringTrajectory, SwingingSpring, simulate_spring

__all__ = [
    "Comparison",
    "CompoundPendulum",
    "EMMap",
    "EnsembleResult",
    "ErrorEstimate",
    "ExactSolution",
    "FitResult",
    "IntegrationError",
    "InvalidInputError",
    "MeasuredAdvance",
    "Part",
    "Pendulum",
    "Phases",
    "Reduced",
    "Save",
    "Scenario",
    "ScenarioError",
    "SlewingSway",
    "SpringTrajectory",
    "State",
    "Stepper",
    "SweepResult",
    "SwingingSpring",
    "Trajectory",
    "__version__",
    "compare_fits",
    "em_map",
    "exact",
    "fit",
    "limits",
    "load_scenario",
    "measured_azimuth_advance",
    "method_names",
    "methods",
    "models",
    "read_sweep",
    "reduce",
    "reduced_flow",
    "simulate",
    "simulate_ensemble",
    "simulate_spring",
    "slewing_sway",
    "states_from_angles",
    "sweep",
    "sweep_design",
]
