"""Many trajectories at once (the core's ensemble kernel): ``simulate_ensemble``, its result
``EnsembleResult`` with the NetCDF/Zarr writers, and ``Save`` (what to keep). SI units."""

from .result import EnsembleResult
from .run import max_sway, model_damping, simulate_ensemble, states_from_angles
from .save import Save

__all__ = ["EnsembleResult", "Save", "max_sway", "model_damping", "simulate_ensemble", "states_from_angles"]
