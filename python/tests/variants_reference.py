"""An independent reference for the real pendulums of Pendulab (test helper; no pendulab import):
Lagrange's equations in spherical coordinates about a *horizontal* polar axis, integrated by SciPy's
DOP853. Pendulab's core works in Cartesian coordinates with the rod's multiplier (T-2.2) or, for the
spring, in Cartesian Störmer–Verlet; this helper shares neither the formulation nor the code.

Coordinates. The bob's position relative to the pivot is x = ρ u(θ, φ) with

    u   = (sin θ sin φ, cos θ, −sin θ cos φ),
    e_θ = ∂u/∂θ = (cos θ sin φ, −sin θ, −cos θ cos φ),
    e_φ = (∂u/∂φ)/sin θ = (cos φ, 0, sin φ),

an orthonormal frame. The polar axis is e₂ (horizontal), so the hanging position −e₃ (θ = π/2,
φ = 0), the whole x–z plane and the top +e₃ are regular points; only x ∥ ±e₂ is singular, and each
run checks that it stays away from there (sin θ > 0.05). φ is the planar swing angle and may wind.

Equations. With x = ρu, ẋ = ρ̇ u + ρ θ̇ e_θ + ρ sin θ φ̇ e_φ and the kinetic energy per unit mass
T = ½(ρ̇² + ρ² θ̇² + ρ² sin²θ φ̇²). Every force per unit mass F(t, x, ẋ) (gravity, damping, drag,
friction, forcing, Coriolis and centrifugal terms, the spring) enters through the generalised forces
Q_q = F·∂x/∂q: Q_ρ = F·u, Q_θ = ρ F·e_θ, Q_φ = ρ sin θ F·e_φ. Lagrange's equations
d/dt ∂T/∂q̇ − ∂T/∂q = Q_q give

    ρ̈ = ρ θ̇² + ρ sin²θ φ̇² + F·u                                   (spring only; the rod has ρ ≡ l)
    θ̈ = sin θ cos θ φ̇² − 2 ρ̇ θ̇/ρ + F·e_θ/ρ
    φ̈ = −2 cot θ θ̇ φ̇ − 2 ρ̇ φ̇/ρ + F·e_φ/(ρ sin θ).

A moving pivot p(t): the bob is at r = p(t) + x and T = ½|ṗ + ẋ|². The cross term ṗ·ẋ = ṗ·(∂x/∂q) q̇
contributes d/dt(ṗ·∂x/∂q) − ṗ·∂ẋ/∂q = p̈·∂x/∂q to the left side, i.e. the generalised force of the
uniform field −p̈(t): F gains −p̈ (the inertial force of the non-rotating pivot frame), and a damping
force relative to the pivot is −c ẋ. A frame turning at Ω: T = ½|ẋ + Ω×x|² gives, in the same way,
the terms −2Ω×ẋ − Ω×(Ω×x) in F. A rope of prescribed length ρ = l(t) (a hoist) is a rheonomic
constraint: ρ, ρ̇, ρ̈ are then given and the θ and φ equations above hold as written, with their
ρ̇ terms (the Coriolis-like −2ρ̇θ̇/ρ, −2ρ̇φ̇/ρ of a changing radius).
"""

from __future__ import annotations

import itertools
from collections.abc import Callable, Sequence

import numpy as np
from scipy.integrate import solve_ivp

Force = Callable[[float, np.ndarray, np.ndarray], np.ndarray]
Rope = Callable[[float], tuple[float, float, float]]


def frame(th: float, ph: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """u, e_θ, e_φ at (θ, φ) (see the module's docstring)."""
    st, ct, sp, cp = np.sin(th), np.cos(th), np.sin(ph), np.cos(ph)
    return (
        np.array([st * sp, ct, -st * cp]),
        np.array([ct * sp, -st, -ct * cp]),
        np.array([cp, 0.0, sp]),
    )


def to_angles(x: np.ndarray, v: np.ndarray) -> np.ndarray:
    """(ρ, θ, φ, ρ̇, θ̇, φ̇) of a Cartesian state x [m], v [m/s]."""
    rho = float(np.linalg.norm(x))
    th, ph = np.arccos(x[1] / rho), np.arctan2(x[0], -x[2])
    u, e_th, e_ph = frame(th, ph)
    return np.array([rho, th, ph, u @ v, e_th @ v / rho, e_ph @ v / (rho * np.sin(th))])


def to_cartesian(y: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """x [m], v [m/s] (N, 3) of angle states y (6, N)."""
    xs, vs = [], []
    for rho, th, ph, rd, thd, phd in y.T:
        u, e_th, e_ph = frame(th, ph)
        xs.append(rho * u)
        vs.append(rd * u + rho * thd * e_th + rho * np.sin(th) * phd * e_ph)
    return np.array(xs), np.array(vs)


def reference(
    force: Force,
    x0: np.ndarray,
    v0: np.ndarray,
    t: np.ndarray,
    *,
    rod: bool = True,
    rope: Rope | None = None,
    breaks: Sequence[float] = (),
) -> tuple[np.ndarray, np.ndarray]:
    """x [m], v [m/s] at the times t [s] (t[0] the start) of the bob under the force per unit mass
    ``force(t, x, ẋ)`` [m/s²], on a rod (|x| fixed) or, with ``rod=False``, free in ρ (the spring's
    pull is then part of ``force``), or on a rope of prescribed length ``rope(t)`` = (l, l̇, l̈) [m, m/s,
    m/s²] (x0, v0 then with |x0| = l(t[0]), x0·v0 = l l̇). DOP853, rtol 1e-13, atol 1e-14, restarted at
    each of the ``breaks`` [s] (times where the force is not smooth in t, e.g. a spline's knots)."""

    def rhs(tt: float, y: np.ndarray) -> np.ndarray:
        rho, th, ph, rd, thd, phd = y
        u, e_th, e_ph = frame(th, ph)
        st, ct = np.sin(th), np.cos(th)
        x = rho * u
        xd = rd * u + rho * thd * e_th + rho * st * phd * e_ph
        f = force(tt, x, xd)
        if rope is not None:
            rdd = rope(tt)[2]
        else:
            rdd = 0.0 if rod else rho * thd**2 + rho * st**2 * phd**2 + f @ u
        thdd = st * ct * phd**2 - 2.0 * rd * thd / rho + f @ e_th / rho
        phdd = -2.0 * ct / st * thd * phd - 2.0 * rd * phd / rho + f @ e_ph / (rho * st)
        return np.array([rd, thd, phd, rdd, thdd, phdd])

    y0 = to_angles(np.asarray(x0, float), np.asarray(v0, float))
    if rod and rope is None:
        y0[3] = 0.0
    cuts = [float(t[0]), *sorted(b for b in set(map(float, breaks)) if t[0] < b < t[-1]), float(t[-1])]
    ys, y = [], y0
    for a, b in itertools.pairwise(cuts):
        inside = t[(t >= a) & ((t < b) | (b == t[-1]))]
        pts = np.union1d(inside, [b])
        sol = solve_ivp(rhs, (a, b), y, method="DOP853", t_eval=pts, rtol=1e-13, atol=1e-14)
        assert sol.success, sol.message
        ys.append(sol.y[:, np.isin(pts, inside)])
        y = sol.y[:, -1]
    out = np.concatenate(ys, axis=1)
    assert np.min(np.abs(np.sin(out[1]))) > 0.05, "the run came near the coordinates' pole ±e₂"
    return to_cartesian(out)


def start(rho: float, th: float, ph: float, thd: float, phd: float) -> tuple[np.ndarray, np.ndarray]:
    """A start on the sphere of radius ρ [m] from the helper's angles [rad] and rates [rad/s]."""
    x, v = to_cartesian(np.array([[rho], [th], [ph], [0.0], [thd], [phd]]))
    return x[0], v[0]
