"""Sweeps (``docs/sweeps.md``): a quantity at every point of a design, in chunks, on threads or a Dask
cluster, resumable. ``run`` holds ``pl.sweep``; ``compute`` one chunk and the quantities; ``design``
the grids and random designs (``pl.sweep_design``); ``file`` sweep files (TOML); ``results`` the
Parquet output and ``SweepResult``; ``backends`` the thread pool and Dask. SI units throughout."""

from . import design
from .results import SweepResult, read_sweep
from .run import sweep

__all__ = ["SweepResult", "design", "read_sweep", "sweep"]
