"""A computed trajectory: saved times and states plus the diagnostics that prove it right.

Arrays (N samples): ``t`` [s], ``x`` [m] (N, 3), ``v`` [m/s] (N, 3); derived on first use:
``energy`` [J], ``j3`` [kg m²/s], ``tension`` [N] (T-2.3, T-2.6), ``radius_error`` = |x| − l [m],
``constraint_error`` = (|x| − l)/l (dimensionless), ``tangency`` = x·v [m²/s], ``theta``, ``phi`` [rad],
and for the real-pendulum models (docs/theory.md §7) ``power`` [W] of the non-conservative forces,
``power_balance_residual`` E(t) − E(0) − ∫P dt [J] (the check of T-7.1) and ``pivot`` [m] (moving pivot).

The modules: :mod:`~pendulab.trajectory.result` (``Trajectory``), :mod:`~pendulab.trajectory.tables`
(columns with units, metadata, the xarray Dataset), :mod:`~pendulab.trajectory.report` (``repr`` and
``summary``). This package only re-exports them.
"""

from .result import Trajectory
from .tables import UNITS

__all__ = ["UNITS", "Trajectory"]
