"""Symmetry reduction by rotations about the vertical (docs/theory.md §3) and the azimuth it reconstructs.

Holm's invariants are taken in unit-length variables (positions in units of l, time in s):

====== ============================== ========
σ₁     z/l                            1
σ₂     ż/l                            1/s
σ₃     |v|²/l²                        1/s²
σ₄     (x² + y²)/l²                   1
σ₅     (x ẋ + y ẏ)/l²                 1/s
σ₆     (x ẏ − y ẋ)/l² = J₃/(m l²)     1/s
====== ============================== ========

with γ = g/l [1/s²] in place of g. Then (T-3.2, T-3.3) the relations σ₅² + σ₆² = σ₄(σ₃ − σ₂²),
σ₄ + σ₁² = 1, σ₅ + σ₁σ₂ = 0, σ₂² + σ₆² = σ₃(1 − σ₁²) hold on TS²; the Casimir
C = σ₃(1 − σ₁²) − σ₂² − σ₆² [1/s²] vanishes; the reduced Hamiltonian H = ½σ₃ + γσ₁ [1/s²] is
E/(m l²). The motion lies on the intersection of the surface C = 0 with the plane H = const
(Holm's Figure 2; see :mod:`pendulab.plot.reduced`).

- :func:`reduce` evaluates all of that along a trajectory.
- :func:`reduced_flow` integrates the reduced flow T-3.4 with the reconstruction T-3.6 — a path to
  x(t) independent of the Cartesian integrators and of the elliptic solution.

Measuring Δφ per z-period from a trajectory: :mod:`pendulab.theory.advance`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .._core import InvalidInputError, RunOptions
from .._core import invariants as _invariants
from .._core import reduced_flow as _reduced_flow
from .._core import relation_residuals as _relation_residuals
from ..display import html_table
from ..display import number as fmt
from ..model import FloatArray, Pendulum, State, check_pendulum_state
from ..trajectory import Trajectory
from ..validate import number

SIGMA_UNITS = ("1", "1/s", "1/s^2", "1", "1/s", "1/s")
"""Units of σ₁ … σ₆ (unit-length variables, time in s)."""

RESIDUAL_UNITS = ("1/s^2", "1", "1/s", "1/s^2")
"""Units of the four relation residuals (T-3.2, in the order of :attr:`Reduced.relation_residuals`)."""

MAX_REDUCED_STEPS = 20_000_000
"""Largest number of RK4 steps :func:`reduced_flow` accepts (every step is kept: ~1 GB)."""


@dataclass(frozen=True)
class Reduced:
    """The reduced description of a trajectory (N samples); units in the module docstring.

    ``sigma`` (N, 6): σ₁ … σ₆. ``relation_residuals`` (N, 4): σ₅² + σ₆² − σ₄(σ₃ − σ₂²) [1/s²],
    σ₄ + σ₁² − 1 [1], σ₅ + σ₁σ₂ [1/s], σ₂² + σ₆² − σ₃(1 − σ₁²) [1/s²] — all zero on TS².
    ``casimir`` (N,): C = σ₃(1 − σ₁²) − σ₂² − σ₆² [1/s²] (zero on the orbit manifold, T-3.3).
    ``hamiltonian`` (N,): H = ½σ₃ + (g/l)σ₁ [1/s²] = E/(m l²), conserved along the motion.
    """

    pendulum: Pendulum
    t: FloatArray
    sigma: FloatArray
    relation_residuals: FloatArray
    casimir: FloatArray
    hamiltonian: FloatArray

    def _summary(self) -> list[tuple[str, float, str]]:
        h = self.hamiltonian
        return [
            ("samples", len(self.t), ""),
            ("t", float(self.t[-1]) if len(self.t) else 0.0, "s (last)"),
            ("σ₆ = J₃/(m l²) (first)", float(self.sigma[0, 5]) if len(self.t) else math.nan, "1/s"),
            ("max |Casimir| (T-3.3)", float(np.max(np.abs(self.casimir), initial=0.0)), "1/s²"),
            ("max |relations| (T-3.2)", float(np.max(np.abs(self.relation_residuals), initial=0.0)), ""),
            (
                "max |H − H₀| (H = E/(m l²))",
                float(np.max(np.abs(h - h[0]), initial=0.0)) if len(h) else 0.0,
                "1/s²",
            ),
        ]

    def __repr__(self) -> str:
        n, t_end, j, cas, _, dh = (v for _, v, _ in self._summary())
        return (
            f"Reduced({n} samples, t = 0 … {fmt(t_end)} s, σ₆ = {fmt(j)} 1/s, max |C| = {fmt(cas, 3)} 1/s², "
            f"max |ΔH| = {fmt(dh, 3)} 1/s²)"
        )

    def _repr_html_(self) -> str:
        return html_table("Reduced (Holm's σ₁…σ₆ along a trajectory)", self._summary())

    @property
    def j(self) -> FloatArray:
        """σ₆ = J₃/(m l²) [1/s] at each sample (constant along the ideal motion)."""
        return self.sigma[:, 5]

    @property
    def gamma(self) -> float:
        """γ = g/l [1/s²]."""
        return self.pendulum.g / self.pendulum.length


def invariants(pendulum: Pendulum, x: object, v: object) -> FloatArray:
    """σ₁ … σ₆ (T-3.1, units in the module docstring) for positions x [m] and velocities v [m/s] of
    shape (N, 3) (or (3,)): an array of shape (N, 6)."""
    xa = np.ascontiguousarray(np.atleast_2d(np.asarray(x, dtype=np.float64)))
    va = np.ascontiguousarray(np.atleast_2d(np.asarray(v, dtype=np.float64)))
    return _invariants(pendulum.length, xa, va)


def reduce(traj: Trajectory) -> Reduced:
    """σ₁ … σ₆, the relation residuals, the Casimir and H along a trajectory (T-3.1 … T-3.3).

    Examples
    --------
    >>> import numpy as np
    >>> import pendulab as pl
    >>> p = pl.Pendulum()
    >>> tr = pl.simulate(p, p.state_from_angles(theta=1.0, phi_dot=2.0), t_end=1.0, save_every=100)
    >>> red = pl.reduce(tr)
    >>> red.sigma.shape
    (11, 6)
    >>> abs(red.casimir).max() < 1e-12
    True
    """
    if not isinstance(traj, Trajectory):
        raise InvalidInputError(f"reduce needs a pendulab.Trajectory, got {type(traj).__name__}")
    p = traj.pendulum
    sigma = invariants(p, traj.x, traj.v)
    s1, s2, s3, s6 = sigma[:, 0], sigma[:, 1], sigma[:, 2], sigma[:, 5]
    casimir = s3 * (1.0 - s1 * s1) - s2 * s2 - s6 * s6
    hamiltonian = 0.5 * s3 + (p.g / p.length) * s1
    residuals = _relation_residuals(np.ascontiguousarray(sigma))
    return Reduced(p, traj.t.copy(), sigma, residuals, casimir, hamiltonian)


def reduced_flow(pendulum: Pendulum, state: State, t_end: float, dt: float = 1e-3) -> Trajectory:
    """Integrates the reduced (Nambu) flow T-3.4 on (σ₁, σ₂, σ₃) with the azimuth φ̇ = σ₆/(1 − σ₁²)
    (T-3.6) by classical RK4 from ``state`` at t = 0 to ``t_end`` [s], and rebuilds x [m], v [m/s].

    Every step is kept; ``dt`` [s] is shortened so that a whole number of steps ends exactly at
    ``t_end``. Like the angle form, the reconstruction is singular at the poles: J₃ = 0 is refused
    (:class:`pendulab.IntegrationError`), and so is an orbit that passes so close to a pole that
    φ̇·dt would exceed 0.05 rad (use a smaller dt there). Method name of the result:
    ``"reduced_rk4"``; its error is O(dt⁴).
    """
    check_pendulum_state(pendulum, state)
    t_end, dt = number("t_end", t_end, "time", positive=True), number("dt", dt, "dt")
    if not pendulum.is_ideal:
        raise InvalidInputError(
            f"the reduced flow (T-3.4) is that of the ideal pendulum, not the {pendulum.model!r} model"
        )
    n = math.ceil(t_end / dt * (1.0 - 1e-12))
    if n > MAX_REDUCED_STEPS:
        raise InvalidInputError(
            f"t_end / dt = {t_end / dt:.3g} steps exceeds the limit of {MAX_REDUCED_STEPS} "
            "(every step is kept); use a larger dt or a shorter t_end"
        )
    n = max(n, 1)
    h = t_end / n
    x, v = _reduced_flow(pendulum.spec, state.pair, RunOptions(dt=h), n)
    t = h * np.arange(n + 1, dtype=np.float64)
    t[-1] = t_end
    return Trajectory(pendulum, t, x, v, "reduced_rk4", {"dt": h, "t0": 0.0, "t_end": t_end}, {"steps": n})


@dataclass(frozen=True)
class ReducedSurfaces:
    """Holm's Figure 2 computed (T-3.3): on a grid of σ₁ [1] × σ₂ [1/s] (``sigma1``, ``sigma2``, each
    (n, n)), the orbit manifold C = 0 as σ₃ = (σ₂² + J²)/(1 − σ₁²) [1/s²] (``surface``) and the energy
    plane H = ½σ₃ + (g/l)σ₁ as σ₃ = 2(H − (g/l)σ₁) (``plane``), both NaN above ``cap`` = 1.4 times the
    orbit's largest σ₃ [1/s²] (and the plane below 0); ``j`` = J₃/(m l²) [1/s] and ``h`` = E/(m l²)
    [1/s²] of the orbit (means over its samples); ``reduced``: the orbit itself."""

    reduced: Reduced
    sigma1: FloatArray
    sigma2: FloatArray
    surface: FloatArray
    plane: FloatArray
    cap: float
    j: float
    h: float


def reduced_surfaces(data: Trajectory | Reduced, resolution: int = 60) -> ReducedSurfaces:
    """The surfaces of Holm's Figure 2 around the orbit of ``data`` (a trajectory, or its
    :func:`reduce`) on a ``resolution`` × ``resolution`` grid: σ₁ over the orbit's range and 30 %
    more on each side (within ±0.99; all of it for a pole at rest), σ₂ over ±1.3 times the orbit's
    largest |σ₂| (at least a tenth of its speed scale √σ₃)."""
    red = data if isinstance(data, Reduced) else reduce(data)
    s = red.sigma
    s1, s2, s3 = s[:, 0], s[:, 1], s[:, 2]
    j, h, gamma = float(np.mean(red.j)), float(np.mean(red.hamiltonian)), red.gamma
    span1 = max(float(np.ptp(s1)), 0.1)
    lo1 = max(float(s1.min()) - 0.3 * span1, -0.99)
    hi1 = min(float(s1.max()) + 0.3 * span1, 0.99)
    if hi1 <= lo1:  # a pole at rest: show a little of the sphere around it
        lo1, hi1 = -0.99, 0.99
    span2 = max(float(np.max(np.abs(s2))), 0.1 * float(np.sqrt(max(np.max(s3), 1e-300))), 1e-3)
    cap = 1.4 * max(float(np.max(s3)), 1e-12)
    a, b = np.meshgrid(np.linspace(lo1, hi1, resolution), np.linspace(-1.3 * span2, 1.3 * span2, resolution))
    surface = (b * b + j * j) / (1.0 - a * a)
    surface[surface > cap] = np.nan  # cut off (matplotlib leaves those cells out)
    plane = 2.0 * (h - gamma * a)
    plane[(plane > cap) | (plane < 0.0)] = np.nan
    return ReducedSurfaces(red, a, b, surface, plane, cap, j, h)
