"""Cranes as crane engineers meet them (docs/cranes.md, docs/theory.md §11): command shapers and their
residual vibration, acceleration- and jerk-limited moves shaped by convolution, crane kinematics
(gantry, tower, luffing boom) as pivot paths, the crane's dynamics (hoisting, hook + payload, wind;
computed in the core) and LQR anti-sway feedback. SI units (m, s, rad, rad/s, kg, N, J).

    from pendulab import crane
    s = crane.shaper("zvd", omega=0.99)                  # .times [s], .amplitudes (sum 1)
    V = crane.residual_vibration(s, omega=np.linspace(0.5, 1.5, 201))
    path = crane.move(distance=5.0, v_max=0.5, a_max=0.5, shaper=s, t_start=1.0)
    c = crane.Crane(rope=10.0, pivot=path, payload_mass=1000.0)
    run = c.simulate(t_end=40.0)                         # .t, .payload, .sway, .rope, .energy, ...

Needs SciPy (``pip install 'pendulab[crane]'``).
"""

try:
    import scipy  # noqa: F401
except ImportError as exc:  # pragma: no cover - exercised only without SciPy
    raise ImportError("pendulab.crane needs SciPy: pip install 'pendulab[crane]' (or scipy>=1.11)") from exc

from .grid import GridResult, residual_grid
from .hoist import Hoist
from .lqr import LQR, LQRRun, lqr
from .move import Profile, profile
from .paths import Gantry, Path, Sampled, Tower, move
from .robust import rope_range, shaper_for_range, worst_vibration
from .scenario import CraneFileError
from .shaper import KINDS, Shaper, insensitivity, residual_vibration, shaper
from .system import Crane, CraneRun, Wind

__all__ = [
    "KINDS",
    "LQR",
    "Crane",
    "CraneFileError",
    "CraneRun",
    "Gantry",
    "GridResult",
    "Hoist",
    "LQRRun",
    "Path",
    "Profile",
    "Sampled",
    "Shaper",
    "Tower",
    "Wind",
    "insensitivity",
    "lqr",
    "move",
    "profile",
    "residual_grid",
    "residual_vibration",
    "rope_range",
    "shaper",
    "shaper_for_range",
    "worst_vibration",
]
