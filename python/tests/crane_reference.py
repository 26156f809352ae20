"""An independent reference for the crane's nonlinear 3-D dynamics (docs/cranes.md "The crane model",
docs/theory.md T-11.5, T-11.7), used by test_crane_reference.py. It shares only the model's definition
with pendulab, not its equations or code: pendulab integrates Cartesian positions with Lagrange
multipliers and projection; this writes the rope's and the rigging's directions in spherical angles,
q = (θ₁, φ₁, θ₂, φ₂), and integrates Lagrange's equations in these minimal coordinates with SciPy's
DOP853.

Model: body 1 (the hook, or the load alone) at x₁ = P(t) + l(t) e(θ₁, φ₁), the payload at
x₂ = x₁ + l₂ e(θ₂, φ₂); forces m_i g⃗ (g⃗ = (0, 0, −g)), drag ½ρ c_W A |w − v|(w − v) with the wind
w(t) = w₀ + w_g ½(1 − cos 2π(t − t_g)/T_g) during the gust, and damping −m c (v − Ṗ). The chart is
spherical about the horizontal x axis, e(θ, φ) = (cos θ, sin θ cos φ, sin θ sin φ), so a rope
hanging down (θ = π/2, φ = −π/2) is far from its poles (a rope along ±x).

Lagrange's equations for point masses x_i(q, t) with the generalised forces Q_k = Σ_i F_i·∂x_i/∂q_k
(virtual work) read Σ_i m_i (∂x_i/∂q_k)·ẍ_i = Q_k; with ẍ_i = J_i q̈ + a_i (J_i = ∂x_i/∂q, a_i the
rest, written out below) this is M q̈ = Σ_i J_iᵀ(F_i − m_i a_i), M = Σ_i m_i J_iᵀJ_i.
``sympy_accelerations`` derives the same from L = T − V with SymPy (when it is installed), and
test_crane_reference.py checks these hand-written terms against it.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np
from scipy.integrate import solve_ivp

Vec = tuple[float, float, float]
PVA = tuple[Vec, Vec, Vec]


@dataclass(frozen=True)
class Steps:
    """s(t) = s₀ + Σ c_k (t − τ_k)₊ⁿ/n! (a move as steps of its n-th derivative, T-11.3), with ṡ, s̈."""

    knots: Sequence[float]
    coeffs: Sequence[float]
    order: int
    start: float = 0.0

    def __call__(self, t: float) -> tuple[float, float, float]:
        n, out = self.order, [self.start, 0.0, 0.0]
        for tau, c in zip(self.knots, self.coeffs, strict=True):
            d = t - tau
            if d > 0:
                for k in range(3):
                    out[k] += c * d ** (n - k) / math.factorial(n - k)
            elif d == 0 and n == 2:  # the acceleration steps at τ (right-continuous)
                out[2] += c
        return out[0], out[1], out[2]


def gantry(s: Steps, direction: Vec, origin: Vec = (0.0, 0.0, 0.0)) -> Callable[[float], PVA]:
    """P = P₀ + s(t) e along the unit vector e."""
    n = math.sqrt(sum(x * x for x in direction))
    e = [x / n for x in direction]

    def pva(t: float) -> PVA:
        q, dq, ddq = s(t)
        p = (origin[0] + q * e[0], origin[1] + q * e[1], origin[2] + q * e[2])
        return p, (dq * e[0], dq * e[1], dq * e[2]), (ddq * e[0], ddq * e[1], ddq * e[2])

    return pva


def tower(slew: Steps, radius: float, height: float) -> Callable[[float], PVA]:
    """P = (r cos θ, r sin θ, h) for the slew θ(t), differentiated here by the chain rule."""

    def pva(t: float) -> PVA:
        th, w, al = slew(t)
        c, s = math.cos(th), math.sin(th)
        p = (radius * c, radius * s, height)
        v = (-radius * s * w, radius * c * w, 0.0)
        a = (-radius * (c * w * w + s * al), radius * (c * al - s * w * w), 0.0)
        return p, v, a

    return pva


def cubic_pieces(
    breaks: Sequence[float], coeffs: np.ndarray
) -> Callable[[float], tuple[float, float, float]]:
    """A piecewise cubic l(t) = Σ c_k (t − t_i)^(3−k) on [t_i, t_i+1] (SciPy's PPoly layout), held
    constant (l̇ = l̈ = 0) outside the breaks (l̈ right-continuous): the hoist's rope length."""
    ts, cs = list(map(float, breaks)), [list(map(float, coeffs[:, i])) for i in range(coeffs.shape[1])]

    def f(t: float) -> tuple[float, float, float]:
        if t < ts[0] or t >= ts[-1]:
            a, b, c, d = cs[0] if t < ts[0] else cs[-1]
            h = 0.0 if t < ts[0] else ts[-1] - ts[-2]
            return ((a * h + b) * h + c) * h + d, 0.0, 0.0
        i = max(k for k in range(len(ts) - 1) if ts[k] <= t)
        a, b, c, d = cs[i]
        h = t - ts[i]
        return ((a * h + b) * h + c) * h + d, (3 * a * h + 2 * b) * h + c, 6 * a * h + 2 * b

    return f


def gust_wind(
    w0: Vec, gust: Vec, start: float, duration: float, modes: tuple[np.ndarray, ...] | None = None
) -> Callable[[float], Vec]:
    """w(t) = w₀ + w_g ½(1 − cos 2π(t − t_g)/T_g) during the gust, plus Σ_k a_k cos(ω_k t + φ_k) per axis
    for the turbulence's ``modes`` (ω_k (K,), a_k (K, 3), φ_k (K, 3)) (T-11.7)."""
    om, amp, ph = ([], [], []) if modes is None else (m.tolist() for m in modes)

    def w(t: float) -> Vec:
        s = (t - start) / duration
        f = 0.5 * (1.0 - math.cos(2.0 * math.pi * s)) if 0.0 <= s <= 1.0 else 0.0
        out = [w0[i] + f * gust[i] for i in range(3)]
        for wk, ak, pk in zip(om, amp, ph, strict=True):
            for i in range(3):
                out[i] += ak[i] * math.cos(wk * t + pk[i])
        return out[0], out[1], out[2]

    return w


def chart(u: Vec) -> tuple[float, float]:
    """(θ, φ) of the unit vector u in the chart about the x axis."""
    return math.acos(max(-1.0, min(1.0, u[0]))), math.atan2(u[2], u[1])


def frame(th: float, ph: float) -> tuple[Vec, Vec, Vec, Vec, Vec]:
    """e and its partial derivatives e_θ, e_φ, e_θφ, e_φφ (e_θθ = −e)."""
    ct, st, cp, sp = math.cos(th), math.sin(th), math.cos(ph), math.sin(ph)
    e, e_t, e_p = (ct, st * cp, st * sp), (-st, ct * cp, ct * sp), (0.0, -st * sp, st * cp)
    return e, e_t, e_p, (0.0, -ct * sp, ct * cp), (0.0, -st * cp, -st * sp)


def _dot(a: Sequence[float], b: Sequence[float]) -> float:
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def _comb(*terms: tuple[float, Sequence[float]]) -> list[float]:
    """Σ c_k v_k for 3-vectors v_k."""
    x = y = z = 0.0
    for c, v in terms:
        x += c * v[0]
        y += c * v[1]
        z += c * v[2]
    return [x, y, z]


def solve(m: list[list[float]], f: list[float]) -> list[float]:
    """M x = f by Gaussian elimination (M symmetric positive definite, no pivoting needed)."""
    n = len(f)
    a = [[*row, f[i]] for i, row in enumerate(m)]
    for k in range(n):
        ak = a[k]
        for i in range(k + 1, n):
            ai = a[i]
            r = ai[k] / ak[k]
            for j in range(k, n + 1):
                ai[j] -= r * ak[j]
    x = [0.0] * n
    for i in reversed(range(n)):
        ai = a[i]
        acc = ai[n]
        for j in range(i + 1, n):
            acc -= ai[j] * x[j]
        x[i] = acc / ai[i]
    return x


@dataclass(frozen=True)
class Body:
    """A point mass m [kg] with drag area c_W·A [m²]."""

    mass: float
    cwa: float = 0.0


@dataclass(frozen=True)
class Model:
    """The crane as the reference sees it (the module doc); ``rigging`` l₂ [m] and ``payload`` with a hook."""

    hook: Body
    pivot: Callable[[float], PVA]
    rope: Callable[[float], tuple[float, float, float]]
    payload: Body | None = None
    rigging: float = 0.0
    wind: Callable[[float], Vec] = lambda t: (0.0, 0.0, 0.0)
    air_density: float = 1.225
    damping: float = 0.0
    g: float = 9.81

    def _force(self, body: Body, v: Sequence[float], w: Vec, dp: Vec) -> list[float]:
        rel = [w[i] - v[i] for i in range(3)]
        k = 0.5 * self.air_density * body.cwa * math.sqrt(_dot(rel, rel))
        c = body.mass * self.damping
        f = [k * rel[i] - c * (v[i] - dp[i]) for i in range(3)]
        f[2] -= body.mass * self.g
        return f

    def terms(self, t: float, y: Sequence[float]) -> tuple[list[list[float]], list[float], Vec, Vec]:
        """M, the right-hand side Σ J_iᵀ(F_i − m_i a_i), and the positions x₁, x₂ at (t, y)."""
        p, dp, ddp = self.pivot(t)
        ln, dl, ddl = self.rope(t)
        w = self.wind(t)
        n = 2 if self.payload is None else 4
        th1, ph1, dth1, dph1 = y[0], y[1], y[n], y[n + 1]
        e1, e1t, e1p, e1tp, e1pp = frame(th1, ph1)
        de1 = _comb((dth1, e1t), (dph1, e1p))
        x1 = tuple(_comb((1.0, p), (ln, e1)))
        v1 = _comb((1.0, dp), (dl, e1), (ln, de1))
        a1 = _comb(
            (1.0, ddp),
            (ddl, e1),
            (2 * dl, de1),
            (-ln * dth1**2, e1),
            (2 * ln * dth1 * dph1, e1tp),
            (ln * dph1**2, e1pp),
        )
        cols = [[ln * c for c in e1t], [ln * c for c in e1p]]  # J₁'s columns
        m1 = self.hook.mass
        f1 = self._force(self.hook, v1, w, dp)
        g1 = [f1[i] - m1 * a1[i] for i in range(3)]
        if self.payload is None:
            mass = [[m1 * _dot(a, b) for b in cols] for a in cols]
            return mass, [_dot(c, g1) for c in cols], x1, x1  # type: ignore[return-value]
        th2, ph2, dth2, dph2 = y[2], y[3], y[6], y[7]
        e2, e2t, e2p, e2tp, e2pp = frame(th2, ph2)
        big_l, m2 = self.rigging, self.payload.mass
        x2 = tuple(_comb((1.0, x1), (big_l, e2)))
        v2 = _comb((1.0, v1), (big_l * dth2, e2t), (big_l * dph2, e2p))
        a2 = _comb(
            (1.0, a1), (-big_l * dth2**2, e2), (2 * big_l * dth2 * dph2, e2tp), (big_l * dph2**2, e2pp)
        )
        cols2 = [*cols, [big_l * c for c in e2t], [big_l * c for c in e2p]]  # J₂'s columns
        f2 = self._force(self.payload, v2, w, dp)
        g2 = [f2[i] - m2 * a2[i] for i in range(3)]
        mass = [[m2 * _dot(a, b) for b in cols2] for a in cols2]
        rhs = [_dot(c, g2) for c in cols2]
        for i in range(2):
            rhs[i] += _dot(cols[i], g1)
            for j in range(2):
                mass[i][j] += m1 * _dot(cols[i], cols[j])
        return mass, rhs, x1, x2  # type: ignore[return-value]

    def rhs(self, t: float, y: np.ndarray) -> np.ndarray:
        mass, f, _, _ = self.terms(t, y.tolist())
        return np.array(y[len(f) :].tolist() + solve(mass, f))

    def run(
        self,
        times: np.ndarray,
        u1: Vec,
        u2: Vec | None = None,
        breaks: Sequence[float] = (),
        tol: float = 1e-12,
    ) -> tuple[np.ndarray, np.ndarray, float]:
        """Hook (body 1) and payload positions [m] at ``times`` from the rope along u₁ and the rigging
        along u₂ at rest relative to the pivot and the hoist (as ``Crane.simulate`` starts), integrated
        piecewise between the ``breaks`` (jumps of P̈ or of a higher derivative), and the smallest
        sin θ met (the distance from the chart's poles)."""
        q = list(chart(u1)) + ([] if self.payload is None else list(chart(u2 if u2 is not None else u1)))
        y = np.array(q + [0.0] * len(q))
        t0, t1 = float(times[0]), float(times[-1])
        cuts = [t0, *sorted(b for b in set(breaks) if t0 < b < t1), t1]
        ys = []
        for a, b in itertools.pairwise(cuts):
            inside = times[(times >= a) & ((times < b) | (b == t1))]
            pts = np.union1d(inside, [b])
            sol = solve_ivp(self.rhs, (a, b), y, method="DOP853", rtol=tol, atol=tol, t_eval=pts)
            assert sol.success, sol.message
            ys.append(sol.y.T[np.isin(pts, inside)])
            y = sol.y[:, -1]
        states = np.concatenate(ys)
        x = [self.terms(t, s.tolist())[2:] for t, s in zip(times, states, strict=True)]
        pole = float(np.min(np.abs(np.sin(states[:, : len(q) : 2]))))
        return np.array([a for a, _ in x]), np.array([b for _, b in x]), pole


def sympy_accelerations(bodies: int = 2) -> Callable[..., np.ndarray]:
    """q̈ of the load (``bodies`` = 1: q = (θ₁, φ₁)) or of the hook + payload (2) from L = T − V by
    SymPy: Euler–Lagrange with the generalised forces of drag and damping by virtual work,
    Q_k = Σ_i F_i·∂x_i/∂q_k, as a function of (q, q̇, P, Ṗ, P̈, (l, l̇, l̈), w, (m₁, m₂, l₂, c_WA₁, c_WA₂,
    ρ, c, g)). Independent of ``Model.terms``: the test checks one against the other."""
    import sympy as sp

    n = 2 * bodies
    qs, dqs, ddqs = sp.symbols(f"q0:{n}"), sp.symbols(f"dq0:{n}"), sp.symbols(f"ddq0:{n}")
    ps, dps, ddps = sp.symbols("p0:3"), sp.symbols("dp0:3"), sp.symbols("ddp0:3")
    ls = sp.symbols("l dl ddl")
    wv = sp.Matrix(sp.symbols("w0:3"))
    m1, m2, l2, k1, k2, rho, c, g = sp.symbols("m1 m2 l2 k1 k2 rho c g", positive=True)
    rate = dict(zip(qs + dqs + ps + dps + ls[:2], dqs + ddqs + dps + ddps + ls[1:], strict=True))

    def ddt(f: sp.Expr) -> sp.Expr:  # d/dt along the motion, by the chain rule
        return sum((f.diff(s) * ds for s, ds in rate.items()), sp.Integer(0))

    def e(th: sp.Symbol, ph: sp.Symbol) -> sp.Matrix:
        return sp.Matrix([sp.cos(th), sp.sin(th) * sp.cos(ph), sp.sin(th) * sp.sin(ph)])

    p = sp.Matrix(ps)
    x1 = p + ls[0] * e(qs[0], qs[1])
    x2 = x1 + l2 * e(qs[2], qs[3]) if bodies == 2 else x1
    v1, v2 = x1.applyfunc(ddt), x2.applyfunc(ddt)
    lag = m1 * v1.dot(v1) / 2 + m2 * v2.dot(v2) / 2 - g * (m1 * x1[2] + m2 * x2[2])

    def force(k: sp.Symbol, m: sp.Symbol, v: sp.Matrix) -> sp.Matrix:
        rel = wv - v
        return rho * k / 2 * sp.sqrt(rel.dot(rel)) * rel - m * c * (v - sp.Matrix(dps))

    f1, f2 = force(k1, m1, v1), force(k2, m2, v2)
    if bodies == 1:  # the load alone: body 1 with its mass m₁ and drag area k₁
        lag, f2 = m1 * v1.dot(v1) / 2 - g * m1 * x1[2], sp.zeros(3, 1)
    res = sp.Matrix(
        [
            ddt(lag.diff(dq)) - lag.diff(q) - f1.dot(x1.diff(q)) - f2.dot(x2.diff(q))
            for q, dq in zip(qs, dqs, strict=True)
        ]
    )
    mass = res.jacobian(ddqs)
    rest = res.subs(dict.fromkeys(ddqs, 0))
    args = (qs, dqs, ps, dps, ddps, ls, tuple(wv), (m1, m2, l2, k1, k2, rho, c, g))
    fm = sp.lambdify(args, mass.tolist(), "math", cse=True)
    fr = sp.lambdify(args, list(rest), "math", cse=True)

    def acc(*a: Sequence[float]) -> np.ndarray:
        return np.linalg.solve(np.array(fm(*a), dtype=float), -np.array(fr(*a), dtype=float))

    return acc
