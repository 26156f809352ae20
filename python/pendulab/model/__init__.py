"""The spherical pendulum and its states on TS² (docs/theory.md §1–2), with the real-pendulum models of
the core's registry (§7: damping, drag, forcing, any gravity direction, rotating frame, moving pivot).

Units: length l [m], mass m [kg], gravity g [m/s²] (any sign; g > 0 pulls along −z), position x [m],
velocity v [m/s], time t [s], angles [rad], energy [J], J₃ [kg m²/s], tension [N], power [W]; the
models' own parameters in the units :func:`models` lists.

The modules: :mod:`~pendulab.model.state` (``State`` on TS² and how one is made),
:mod:`~pendulab.model.registry` (``models()``: the registry's models and parameters),
:mod:`~pendulab.model.pendulum` (``Pendulum``). This package only re-exports them.
"""

from .pendulum import Pendulum, check_pendulum_state
from .registry import models
from .state import FloatArray, State
from .state import _frozen as _frozen

__all__ = ["FloatArray", "Pendulum", "State", "check_pendulum_state", "models"]
