#!/usr/bin/env python3
"""Golden reference states of the ideal spherical pendulum, from its exact solution.

Writes ``testdata/golden_states.json``: for every scenario in
``examples/scenarios/*.toml`` the state (x, v) at t = 1, 10, 100 and 1000 s, computed
from the closed-form solution in elliptic functions at 40 significant digits (mpmath),
stored as float64 and as 30-digit strings, with conditioning floors per sample.
Equation numbers (T-x.y) refer to shared/THEORY.md.

Usage (from the repository root)::

    python3 testdata/generate/golden_states.py           # regenerate, write the JSON
    python3 testdata/generate/golden_states.py --check   # recompute, compare, no write

Needs Python >= 3.11 and mpmath (>= 1.3); nothing else. Runs in about a minute.

Model (T-2.4): x' = v, v' = -g e3 + ((g z - |v|^2)/l^2) x on TS^2 (|x| = l, x.v = 0),
invariants (T-2.6) E = m(|v|^2/2 + g z) and J3 = m(x1 v2 - x2 v1).

Initial state: the float64 (x0, v0) that Rust's ``State::from_angles`` builds from the
scenario's angles (theta from the downward vertical), taken as exact binary numbers and
projected onto TS^2 at full precision (x <- l x/|x|, v <- v - (x.v/l^2) x). That moves
them by < 1e-15 relative (checked), below the conditioning floor; without it no
solution on TS^2 would pass through the stored floats.

Kind "generic" (g > 0, J3 != 0), dimensionless (T-1): w0 = sqrt(g/l), tau = w0 t,
u = z/l, eps = E/(m g l), j = J3/(m l^2 w0).

* T-4.1  (du/dtau)^2 = P(u) = 2(eps - u)(1 - u^2) - j^2 = 2(u - u1)(u - u2)(u - u3),
  -1 < u1 < u2 < 1 < u3.
* T-4.2  u = u1 + (u2 - u1) sn^2(s | m), s = lam (tau + tau0), m = (u2 - u1)/(u3 - u1),
  lam = sqrt((u3 - u1)/2), du/dtau = 2 (u2 - u1) lam sn cn dn. The phase s0 = lam tau0
  in [-K, K] solves sn^2(s0) = (u0 - u1)/(u2 - u1) with sn cn of the sign of z'(0)
  (THEORY's F(arcsin sqrt((u0 - u1)/(u2 - u1)) | m), signed by z'(0)); near a turning
  point the smaller of sn, cn is taken from z'(0), so no digits are lost.
* T-4.3  T_z = 2 K(m)/(lam w0).
* T-4.4  phi = phi_low + A(s), A(s) = (j/(2 lam)) [Pi(n+; am s | m)/(1 - u1)
  + Pi(n-; am s | m)/(1 + u1)], n+- = +-(u2 - u1)/(1 -+ u1), continued past +-K by
  am(s + 2K) = am(s) + pi and Pi(n; phi + pi | m) = Pi(n; phi | m) + 2 Pi(n | m);
  phi_low = atan2(y0, x0) - A(s0).
* T-4.5  Delta_phi = (j/lam) [Pi(n+ | m)/(1 - u1) + Pi(n- | m)/(1 + u1)].
* T-3.6  x = l (sqrt(1 - u^2) cos phi, sqrt(1 - u^2) sin phi, u), phi' = w0 j/(1 - u^2);
  with rho = l sqrt(1 - u^2), rho' = -z z'/rho:
  v = (rho' cos phi - rho phi' sin phi, rho' sin phi + rho phi' cos phi, z').
  The constants are formed at twice the working precision and 1 - u^2 is evaluated as
  (1 + u)(1 - u) from the nearer turning point, so that a turning point close to a pole
  (near_top: 1 + u1 ~ 3e-10) costs no digits.

Special cases (T-4.6); anything else raises:

* g < 0: mirror z -> -z (x3, v3 and g change sign, J3 does not), solve, mirror back.
  The stored u1, u2, u3 are then those of the mirrored problem (u = -z/l).
* g = 0, kind "great_circle": x = x0 cos(w t) + (v0/w) sin(w t),
  v = -x0 w sin(w t) + v0 cos(w t), w = |v0|/l.
* J3 exactly 0 and g > 0, kind "planar" (libration only; over the top raises): in the
  vertical plane of e_h (horizontal direction of x0) and e3, with the signed polar angle
  theta, sin(theta/2) = k sn(w0 t + c | k^2), k^2 = (1 + eps)/2, so
  l sin(theta) = 2 l k sn dn and z = -l (1 - 2 k^2 sn^2); theta' = 2 k w0 cn gives
  cn(c) = theta'(0)/(2 k w0) and sn(c) = sin(theta0/2)/k (released at rest: c = +-K).
  Its z-period is 2K(k^2)/w0, half the swing period (T-6.2).

Checks (the file is not written unless all pass):

1. x(0), v(0) reproduce the (projected) initial state to 1e-30 relative.
2. At every output time |x| = l, x.v = 0, E and J3 equal their initial values (1e-30).
3. At t = 0.37 s and the output times, mpmath.diff of x(t) equals v(t) and mpmath.diff
   of v(t) equals the T-2.4 acceleration, to 1e-25.
4. mpmath.odefun (Taylor series, 30 digits) on the 6-dim T-2.4 system from t = 0 to
   2 s agrees with the formula to 1e-25.
5. The samples recomputed at 60 digits agree with the 40-digit ones to 1e-32.

Conditioning floors: the start is perturbed by 2^-53 with all 64 sign patterns,
projected onto TS^2 and solved exactly again; the floor is the max over the patterns of
max(|dx|/l, |dv|/max(|v|, l w0)) at each output time. "floor": componentwise relative
perturbation c -> c (1 +- 2^-53), what rounding the start to float64 does.
"floor_normwise": absolute perturbation 2^-53 l (x) and 2^-53 max(|v0|, l w0) (v), the
size of one rounding of a whole state, as an integrator step makes.
"""

from __future__ import annotations

import argparse
import itertools
import json
import math
import os
import re
import sys
import tempfile
import time
import tomllib
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import mpmath
from mpmath import mp, mpf

REPO = Path(__file__).resolve().parents[2]
SCENARIO_DIR = REPO / "examples" / "scenarios"
OUTPUT = REPO / "testdata" / "golden_states.json"
GENERATOR = "testdata/generate/golden_states.py"

DPS = 40  # working precision [significant digits]
HIGH_DPS = 60  # precision of the self-consistency recomputation (check 5)
STR_DIGITS = 30  # digits of the stored strings
TIMES = (1.0, 10.0, 100.0, 1000.0)  # output times [s]
DIFF_TIMES = (0.37, *TIMES)  # times of check 3 [s]
TOL_STATE = mpf("1e-30")  # checks 1, 2
TOL_ODE = mpf("1e-25")  # checks 3, 4
TOL_HIGH = mpf("1e-32")  # check 5
ODE_DPS = 30
ODE_T_END = 2.0  # [s]
FLOOR_REL = 2.0**-53

UNITS = {
    "length": "m",
    "mass": "kg",
    "g": "m/s^2",
    "t": "s",
    "x": "m",
    "v": "m/s",
    "energy": "J",
    "j3": "kg m^2/s",
    "period_z": "s",
    "delta_phi": "rad",
    "u1, u2, u3, m": "1 (u = z/l, or -z/l when g < 0; m is the elliptic parameter k^2)",
    "floor": "1 (relative, max(|dx|/l, |dv|/max(|v|, l w0)))",
}

Vec = list[Any]  # three mpf components
State = tuple[Vec, Vec]


class GoldenError(RuntimeError):
    """A case the generator cannot solve, or a failed verification."""


# --------------------------------------------------------------------------------------
# Small vector helpers (mpf lists of length 3)


def dot(a: Sequence[Any], b: Sequence[Any]) -> Any:
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def norm(a: Sequence[Any]) -> Any:
    return mp.sqrt(dot(a, a))


def sub(a: Sequence[Any], b: Sequence[Any]) -> Vec:
    return [a[i] - b[i] for i in range(3)]


def scale(c: Any, a: Sequence[Any]) -> Vec:
    return [c * a[i] for i in range(3)]


def mirror(a: Sequence[Any]) -> Vec:
    return [a[0], a[1], -a[2]]


def to_mp(a: Sequence[float]) -> Vec:
    return [mpf(c) for c in a]


# --------------------------------------------------------------------------------------
# Scenarios and the float64 initial state


@dataclass(frozen=True)
class Scenario:
    name: str
    path: str  # relative to the repository root
    length: float
    mass: float
    g: float
    x0: tuple[float, float, float]
    v0: tuple[float, float, float]


def float_initial_state(
    length: float, theta_deg: float, phi_deg: float, theta_dot: float, phi_dot: float
) -> tuple[tuple[float, float, float], tuple[float, float, float]]:
    """Float64 (x0, v0) exactly as Rust's `State::from_angles` with `to_radians()`."""
    theta = theta_deg * (math.pi / 180.0)  # Rust f64::to_radians
    phi = phi_deg * (math.pi / 180.0)
    st, ct = math.sin(theta), math.cos(theta)
    sp, cp = math.sin(phi), math.cos(phi)
    ell, thd, phd = length, theta_dot, phi_dot
    x = (ell * st * cp, ell * st * sp, -ell * ct)
    v = (
        ell * (thd * ct * cp - phd * st * sp),
        ell * (thd * ct * sp + phd * st * cp),
        ell * thd * st,
    )
    return x, v


def load_scenarios(directory: Path = SCENARIO_DIR) -> list[Scenario]:
    files = sorted(directory.glob("*.toml"))
    if not files:
        raise GoldenError(f"no scenario files in {directory}")
    out = []
    for f in files:
        with f.open("rb") as fh:
            doc = tomllib.load(fh)
        try:
            pend, init = doc["pendulum"], doc["initial"]
            model = pend.get("model", "ideal")
            if model != "ideal":
                raise GoldenError(f"{f.name}: model {model!r} is not the ideal pendulum")
            length, mass, g = (
                float(pend["length"]),
                float(pend["mass"]),
                float(pend["g"]),
            )
            angles = [float(init[k]) for k in ("theta_deg", "phi_deg", "theta_dot", "phi_dot")]
        except KeyError as e:
            raise GoldenError(f"{f.name}: missing key {e}") from e
        x0, v0 = float_initial_state(length, *angles)
        rel = f.relative_to(REPO).as_posix()
        out.append(Scenario(f.stem, rel, length, mass, g, x0, v0))
    return out


def project(length: Any, x: Sequence[Any], v: Sequence[Any]) -> State:
    """Projection onto TS^2 (working precision): x <- l x/|x|, v <- v - (x.v/l^2) x."""
    xp = scale(length / norm(x), x)
    vp = sub(v, scale(dot(xp, v) / length**2, xp))
    return xp, vp


# --------------------------------------------------------------------------------------
# Exact solutions


@dataclass
class Solution:
    """Base class: the exact motion through a given state on TS^2."""

    length: Any
    g: Any
    kind: str = field(init=False, default="")
    period_z: Any = field(init=False, default=None)
    info: dict[str, Any] = field(init=False, default_factory=dict)

    def state(self, t: Any) -> State:  # pragma: no cover - abstract
        raise NotImplementedError


def jacobi(s: Any, m: Any, big_k: Any) -> tuple[Any, Any, Any, Any, int]:
    """sn, cn, dn of s, and am of the reduced argument r = s - 2kK in [-K, K], and k."""
    k = int(mp.nint(s / (2 * big_k)))
    r = s - 2 * k * big_k
    sn = mpmath.ellipfun("sn", r, m=m)
    cn = mpmath.ellipfun("cn", r, m=m)
    dn = mpmath.ellipfun("dn", r, m=m)
    am_r = mp.atan2(sn, cn)  # cn >= 0 on [-K, K]
    sign = -1 if k % 2 else 1
    return sign * sn, sign * cn, dn, am_r, k


def ellipf_cont(a: Any, m: Any, big_k: Any) -> Any:
    """F(a | m) for any real amplitude, by F(a + k pi) = F(a) + 2k K."""
    k = int(mp.nint(a / mp.pi))
    return mpmath.ellipf(a - k * mp.pi, m) + 2 * k * big_k


class GenericSolution(Solution):
    """g > 0, J3 != 0: T-4.1 to T-4.5."""

    def __init__(self, length: Any, g: Any, x0: Vec, v0: Vec) -> None:
        super().__init__(length, g)
        self.kind = "generic"
        ell = self.length
        # Constants at twice the working precision from the (exact) start, then rounded:
        # 1 +- u1 and 1 +- u2 keep their relative precision even when a turning point is
        # close to a pole (near_top: 1 + u1 ~ 3e-10).
        with mp.extraprec(mp.prec):
            w0 = mp.sqrt(g / ell)
            u0 = x0[2] / ell
            up0 = v0[2] / (ell * w0)
            eps = dot(v0, v0) / (2 * g * ell) + u0
            j = (x0[0] * v0[1] - x0[1] * v0[0]) / (ell**2 * w0)
            if j == 0:
                raise GoldenError("J3 = 0: use the planar solution")
            u1, u2, u3 = self._roots(eps, j, u0, up0)
            tol = mp.mpf(10) ** (-mp.dps + 8)
            if not (u1 > -1 and u2 < 1 < u3 and u1 - tol <= u0 <= u2 + tol):
                raise GoldenError(f"roots out of order: u1={u1}, u0={u0}, u2={u2}, u3={u3}")
            d = u2 - u1
            if d <= 0:
                raise GoldenError("exactly conical (u1 == u2): not supported")
            consts = [
                w0,
                u0,
                up0,
                eps,
                j,
                u1,
                u2,
                u3,
                d,
                d / (u3 - u1),
                mp.sqrt((u3 - u1) / 2),
            ]
            consts += [1 + u1, 1 - u1, 1 + u2, 1 - u2, (u0 - u1) / d, (u2 - u0) / d]
        w0, u0, up0, eps, j, u1, u2, u3, d, m, lam, p1, q1, p2, q2, r1, r2 = (+c for c in consts)
        big_k = mpmath.ellipk(m)
        n_plus, n_minus = d / q1, -d / p1
        self.w0, self.j, self.eps = w0, j, eps
        self.u1, self.u2, self.u3, self.d, self.m, self.lam, self.big_k = (
            u1,
            u2,
            u3,
            d,
            m,
            lam,
            big_k,
        )
        self.p1, self.q1, self.p2, self.q2 = p1, q1, p2, q2
        self.n_plus, self.n_minus = n_plus, n_minus
        self.pi_plus = mpmath.ellippi(n_plus, m)
        self.pi_minus = mpmath.ellippi(n_minus, m)

        # Phase s0 in [-K, K] (cn >= 0): sn^2 = (u0 - u1)/d, sn cn dn = up0/(2 d lam).
        r1, r2 = max(r1, mpf(0)), max(r2, mpf(0))
        dn = mp.sqrt(max(1 - m * min(r1, mpf(1)), mpf(0)))
        q = up0 / (2 * d * lam * dn)  # = sn cn
        if r1 <= r2:
            cn = mp.sqrt(r2)
            sn = q / cn
        else:
            sn = mp.sqrt(r1) if q >= 0 else -mp.sqrt(r1)
            cn = q / sn
        amp = mp.atan2(sn, cn)
        self.s0 = mpmath.ellipf(amp, m)
        self.tau0 = self.s0 / lam
        phi0 = mp.atan2(x0[1], x0[0])
        self.phi_low = phi0 - self._azimuth(self.s0)[0]

        self.period_z = 2 * big_k / (lam * w0)
        self.delta_phi = (j / lam) * (self.pi_plus / q1 + self.pi_minus / p1)
        self.info = {
            "u1": u1,
            "u2": u2,
            "u3": u3,
            "m": m,
            "period_z": self.period_z,
            "delta_phi": self.delta_phi,
        }

    @staticmethod
    def _roots(eps: Any, j: Any, u0: Any, up0: Any) -> tuple[Any, Any, Any]:
        """Roots of P(u) = 2u^3 - 2 eps u^2 - 2u + 2 eps - j^2, sorted."""
        if up0 == 0:
            # u0 is a turning point, hence a root: deflate exactly,
            # P(u)/(2(u - u0)) = u^2 + b u + c.
            b = u0 - eps
            c = u0 * u0 - eps * u0 - 1
            disc = b * b - 4 * c
            if disc < 0:
                raise GoldenError(f"complex roots (discriminant {disc})")
            qq = -(b + mp.sign(b) * mp.sqrt(disc)) / 2 if b != 0 else -mp.sqrt(disc) / 2
            roots = [u0, qq, c / qq]
        else:
            with mp.extraprec(3 * mp.prec):
                raw = mpmath.polyroots(
                    [2, -2 * eps, -2, 2 * eps - j * j],
                    maxsteps=500,
                    extraprec=3 * mp.prec,
                )
                tiny = mp.mpf(10) ** (-2 * mp.dps)
                for r in raw:
                    if abs(mp.im(r)) > tiny:
                        raise GoldenError(f"complex root {r} of P(u)")
                roots = [mp.re(r) for r in raw]
            roots = [+r for r in roots]  # round to the working precision
        roots.sort()
        return roots[0], roots[1], roots[2]

    def _azimuth(self, s: Any) -> tuple[Any, Any, Any, Any]:
        """A(s) of T-4.4 with the continued amplitude, and sn, cn, dn at s."""
        sn, cn, dn, am_r, k = jacobi(s, self.m, self.big_k)
        p_plus = mpmath.ellippi(self.n_plus, am_r, self.m) + 2 * k * self.pi_plus
        p_minus = mpmath.ellippi(self.n_minus, am_r, self.m) + 2 * k * self.pi_minus
        a = (self.j / (2 * self.lam)) * (p_plus / self.q1 + p_minus / self.p1)
        return a, sn, cn, dn

    def state(self, t: Any) -> State:
        ell, w0 = self.length, self.w0
        s = self.lam * (w0 * t + self.tau0)
        a, sn, cn, dn = self._azimuth(s)
        sn2, cn2 = sn**2, cn**2
        u = self.u1 + self.d * sn2
        # 1 + u and 1 - u from the nearer turning point, without cancellation.
        if sn2 <= 0.5:
            one_u2 = (self.p1 + self.d * sn2) * (self.q1 - self.d * sn2)
        else:
            one_u2 = (self.p2 - self.d * cn2) * (self.q2 + self.d * cn2)
        dudtau = 2 * self.d * self.lam * sn * cn * dn
        phi = self.phi_low + a
        rho = ell * mp.sqrt(one_u2)
        z, zp = ell * u, ell * w0 * dudtau
        phip = w0 * self.j / one_u2
        rhop = -z * zp / rho
        c, sp = mp.cos(phi), mp.sin(phi)
        x = [rho * c, rho * sp, z]
        v = [rhop * c - rho * phip * sp, rhop * sp + rho * phip * c, zp]
        return x, v


class PlanarSolution(Solution):
    """g > 0, J3 = 0, libration in a vertical plane (T-4.6, T-6.2)."""

    def __init__(self, length: Any, g: Any, x0: Vec, v0: Vec) -> None:
        super().__init__(length, g)
        self.kind = "planar"
        ell = self.length
        w0 = mp.sqrt(g / ell)
        hx, hy = x0[0], x0[1]
        hn = mp.sqrt(hx * hx + hy * hy)
        if hn == 0:
            hx, hy = v0[0], v0[1]
            hn = mp.sqrt(hx * hx + hy * hy)
        if hn == 0:
            raise GoldenError("planar case on the vertical axis with no horizontal velocity")
        e_h = [hx / hn, hy / hn, mpf(0)]
        sin_t, cos_t = dot(x0, e_h) / ell, -x0[2] / ell
        theta0 = mp.atan2(sin_t, cos_t)
        thetadot0 = (dot(v0, e_h) * cos_t + v0[2] * sin_t) / ell
        eps = (thetadot0 / w0) ** 2 / 2 - cos_t
        k2 = (1 + eps) / 2
        if k2 >= 1:
            raise GoldenError("planar motion over the top (or on the separatrix): not supported")
        if k2 <= 0:
            raise GoldenError("planar case at rest at the bottom: nothing to compute")
        k = mp.sqrt(k2)
        big_k = mpmath.ellipk(k2)
        sn0 = mp.sin(theta0 / 2) / k
        cn0 = thetadot0 / (2 * k * w0)
        self.c = ellipf_cont(mp.atan2(sn0, cn0), k2, big_k)
        self.w0, self.k, self.k2, self.big_k, self.e_h = w0, k, k2, big_k, e_h
        self.period_z = 2 * big_k / w0
        self.info = {
            "k2": k2,
            "theta_max": 2 * mp.asin(k),
            "period_z": self.period_z,
            "period_swing": 2 * self.period_z,
        }

    def state(self, t: Any) -> State:
        ell, w0, k, k2 = self.length, self.w0, self.k, self.k2
        sn, cn, dn, _, _ = jacobi(w0 * t + self.c, k2, self.big_k)
        cos_t = 1 - 2 * k2 * sn**2
        h = 2 * ell * k * sn * dn
        z = -ell * cos_t
        hp = 2 * ell * k * w0 * cn * cos_t
        zp = 4 * ell * k2 * w0 * sn * cn * dn
        e = self.e_h
        return [h * e[0], h * e[1], z], [hp * e[0], hp * e[1], zp]


class GreatCircleSolution(Solution):
    """g = 0: uniform motion on a great circle (T-4.6)."""

    def __init__(self, length: Any, g: Any, x0: Vec, v0: Vec) -> None:
        super().__init__(length, g)
        self.kind = "great_circle"
        self.x0, self.v0 = x0, v0
        self.w = norm(v0) / self.length
        moving_z = self.w != 0 and (x0[2] != 0 or v0[2] != 0)
        self.period_z = 2 * mp.pi / self.w if moving_z else None
        self.info = {"period_z": self.period_z, "omega": self.w}

    def state(self, t: Any) -> State:
        if self.w == 0:
            return list(self.x0), list(self.v0)
        c, s = mp.cos(self.w * t), mp.sin(self.w * t)
        x = [self.x0[i] * c + self.v0[i] * s / self.w for i in range(3)]
        v = [-self.x0[i] * self.w * s + self.v0[i] * c for i in range(3)]
        return x, v


class MirroredSolution(Solution):
    """g < 0: the motion of the mirror image z -> -z under gravity -g > 0."""

    def __init__(self, length: Any, g: Any, x0: Vec, v0: Vec) -> None:
        super().__init__(length, g)
        self.inner = solve(length, -g, mirror(x0), mirror(v0))
        self.kind = self.inner.kind
        self.period_z = self.inner.period_z
        self.info = dict(self.inner.info)

    def state(self, t: Any) -> State:
        x, v = self.inner.state(t)
        return mirror(x), mirror(v)


def solve(length: Any, g: Any, x0: Vec, v0: Vec) -> Solution:
    """The exact solution through (x0, v0), which must lie on TS^2."""
    length, g = mpf(length), mpf(g)
    if g == 0:
        return GreatCircleSolution(length, g, x0, v0)
    if g < 0:
        return MirroredSolution(length, g, x0, v0)
    if x0[0] * v0[1] - x0[1] * v0[0] == 0:
        return PlanarSolution(length, g, x0, v0)
    return GenericSolution(length, g, x0, v0)


# --------------------------------------------------------------------------------------
# Invariants, scales, errors


def energy(mass: Any, g: Any, x: Vec, v: Vec) -> Any:
    return mass * (dot(v, v) / 2 + g * x[2])


def j3(mass: Any, x: Vec, v: Vec) -> Any:
    return mass * (x[0] * v[1] - x[1] * v[0])


def acceleration(length: Any, g: Any, x: Vec, v: Vec) -> Vec:
    """T-2.4: v' = -g e3 + ((g z - |v|^2)/l^2) x."""
    lam = (g * x[2] - dot(v, v)) / length**2
    return [lam * x[0], lam * x[1], lam * x[2] - g]


def v_scale(length: Any, g: Any, v: Vec) -> Any:
    """max(|v|, l w0): the velocity scale of relative errors."""
    s = max(norm(v), length * mp.sqrt(abs(g) / length))
    return s if s > 0 else mpf(1)


def state_error(length: Any, vs: Any, a: State, b: State) -> Any:
    return max(norm(sub(a[0], b[0])) / length, norm(sub(a[1], b[1])) / vs)


# --------------------------------------------------------------------------------------
# One case


@dataclass
class CaseResult:
    scenario: Scenario
    solution: Solution
    x0: Vec  # projected initial state
    v0: Vec
    energy: Any
    j3: Any
    samples: list[State]
    floors: list[float]
    floors_normwise: list[float]
    checks: dict[str, float]


def initial_state(sc: Scenario) -> State:
    return project(mpf(sc.length), to_mp(sc.x0), to_mp(sc.v0))


def verify(sc: Scenario, sol: Solution, x0: Vec, v0: Vec, log: Callable[[str], None]) -> dict[str, float]:
    """Checks 1 to 4; raises GoldenError on failure, returns the worst error of each."""
    ell, g, mass = mpf(sc.length), mpf(sc.g), mpf(sc.mass)
    vs = v_scale(ell, g, v0)
    e0, jz0 = energy(mass, g, x0, v0), j3(mass, x0, v0)
    e_scale = mass * (vs**2 + abs(g) * ell)
    j_scale = mass * ell * vs
    res: dict[str, float] = {}

    def need(name: str, err: Any, tol: Any) -> None:
        res[name] = max(res.get(name, 0.0), float(err))
        if not err <= tol:
            raise GoldenError(f"{sc.name}: check {name} failed: {mpmath.nstr(err, 5)} > {tol}")

    # 1. initial state
    need("1_initial", state_error(ell, vs, sol.state(mpf(0)), (x0, v0)), TOL_STATE)
    raw = (to_mp(sc.x0), to_mp(sc.v0))
    res["projection_shift"] = float(state_error(ell, vs, raw, (x0, v0)))
    if res["projection_shift"] > 1e-15:
        raise GoldenError(f"{sc.name}: float64 start is far from TS^2 ({res['projection_shift']})")

    # 2. invariants at the output times
    for t in TIMES:
        x, v = sol.state(mpf(t))
        need("2_length", abs(norm(x) - ell) / ell, TOL_STATE)
        need("2_tangency", abs(dot(x, v)) / (ell * vs), TOL_STATE)
        need("2_energy", abs(energy(mass, g, x, v) - e0) / e_scale, TOL_STATE)
        need("2_j3", abs(j3(mass, x, v) - jz0) / j_scale, TOL_STATE)

    # 3. the formula solves T-2.4 (numerical derivative of the closed form)
    cache: dict[tuple[Any, int], State] = {}

    def st(t: Any) -> State:
        key = (mpf(t)._mpf_, mp.prec)
        if key not in cache:
            cache[key] = sol.state(t)
        return cache[key]

    for t in DIFF_TIMES:
        tt = mpf(t)
        x, v = sol.state(tt)
        acc = acceleration(ell, g, x, v)
        a_scale = max(norm(acc), abs(g), dot(v, v) / ell, mpf(1e-300))
        dx = [mp.diff(lambda s, i=i: st(s)[0][i], tt) for i in range(3)]
        dv = [mp.diff(lambda s, i=i: st(s)[1][i], tt) for i in range(3)]
        need("3_dx_dt", norm(sub(dx, v)) / vs, TOL_ODE)
        need("3_dv_dt", norm(sub(dv, acc)) / a_scale, TOL_ODE)

    # 4. independent Taylor-series integration of T-2.4
    with mp.workdps(ODE_DPS):
        lw, gw = +ell, +g

        def rhs(_t: Any, y: Sequence[Any]) -> list[Any]:
            xx, vv = list(y[:3]), list(y[3:])
            return vv + acceleration(lw, gw, xx, vv)

        f = mpmath.odefun(rhs, 0, [+c for c in x0 + v0])
        y_end = f(mpf(ODE_T_END))
    x_ref, v_ref = sol.state(mpf(ODE_T_END))
    need(
        "4_odefun",
        state_error(ell, vs, (list(y_end[:3]), list(y_end[3:])), (x_ref, v_ref)),
        TOL_ODE,
    )
    log(f"    checks 1-4 passed (odefun to t = {ODE_T_END} s: {res['4_odefun']:.1e})")
    return res


def floor_patterns() -> list[tuple[int, ...]]:
    """All 2^6 sign patterns of a perturbation of (x1, x2, x3, v1, v2, v3)."""
    return list(itertools.product((-1, 1), repeat=6))


def conditioning_floors(sc: Scenario, samples: list[State], normwise: bool) -> list[float]:
    """Worst relative state error at each output time from a 2^-53 change of the start.

    Componentwise (normwise=False): each component c -> c (1 +- 2^-53), the rounding of
    the start to float64 (zero components stay exact). Normwise: x_i -> x_i +- 2^-53 l
    and v_i -> v_i +- 2^-53 max(|v0|, l w0), the size of one rounding of a whole state.
    Either way the result is projected onto TS^2 and solved exactly.
    """
    ell, g = mpf(sc.length), mpf(sc.g)
    raw = to_mp(sc.x0) + to_mp(sc.v0)
    rel = mpf(FLOOR_REL)
    vs0 = v_scale(ell, g, raw[3:])
    worst = [mpf(0)] * len(TIMES)
    for signs in floor_patterns():
        if normwise:
            y = [
                c + s * rel * (ell if i < 3 else vs0) for i, (c, s) in enumerate(zip(raw, signs, strict=True))
            ]
        else:
            y = [c * (1 + s * rel) for c, s in zip(raw, signs, strict=True)]
        x0, v0 = project(ell, y[:3], y[3:])
        sol = solve(ell, g, x0, v0)
        for i, t in enumerate(TIMES):
            ref = samples[i]
            err = state_error(ell, v_scale(ell, g, ref[1]), sol.state(mpf(t)), ref)
            worst[i] = max(worst[i], err)
    return [float(mpmath.nstr(w, 3)) for w in worst]


def run_case(sc: Scenario, log: Callable[[str], None]) -> CaseResult:
    t_start = time.perf_counter()
    x0, v0 = initial_state(sc)
    sol = solve(sc.length, sc.g, x0, v0)
    log(f"[{sc.name}] kind={sol.kind}, g={sc.g}")
    checks = verify(sc, sol, x0, v0, log)
    samples = [sol.state(mpf(t)) for t in TIMES]

    # 5. recompute at higher precision
    with mp.workdps(HIGH_DPS):
        xh, vh = initial_state(sc)
        sol_h = solve(sc.length, sc.g, xh, vh)
        ell = mpf(sc.length)
        worst = mpf(0)
        for t, ref in zip(TIMES, samples, strict=True):
            hi = sol_h.state(mpf(t))
            worst = max(worst, state_error(ell, v_scale(ell, mpf(sc.g), hi[1]), hi, ref))
    checks["5_high_precision"] = float(worst)
    if not worst <= TOL_HIGH:
        raise GoldenError(f"{sc.name}: {DPS}-digit and {HIGH_DPS}-digit results differ by {worst}")

    floors = conditioning_floors(sc, samples, normwise=False)
    floors_nw = conditioning_floors(sc, samples, normwise=True)
    mass, g = mpf(sc.mass), mpf(sc.g)
    log(
        f"    floors at t = {', '.join(f'{t:g}' for t in TIMES)} s: "
        + ", ".join(f"{f:.2e}" for f in floors)
        + "; normwise: "
        + ", ".join(f"{f:.2e}" for f in floors_nw)
        + f"  ({time.perf_counter() - t_start:.1f} s)"
    )
    return CaseResult(
        sc,
        sol,
        x0,
        v0,
        energy(mass, g, x0, v0),
        j3(mass, x0, v0),
        samples,
        floors,
        floors_nw,
        checks,
    )


# --------------------------------------------------------------------------------------
# JSON


def sci(x: Any, digits: int = STR_DIGITS) -> str:
    """x to `digits` significant digits in exponent notation."""
    if x == 0:
        return "0.0"
    return mpmath.nstr(x, digits, strip_zeros=False, min_fixed=0, max_fixed=0)


def opt_float(x: Any) -> float | None:
    return None if x is None else float(x)


def case_json(r: CaseResult) -> dict[str, Any]:
    sc, sol = r.scenario, r.solution
    out: dict[str, Any] = {
        "name": sc.name,
        "scenario": sc.path,
        "length": sc.length,
        "mass": sc.mass,
        "g": sc.g,
        "x0": list(sc.x0),
        "v0": list(sc.v0),
        "kind": sol.kind,
        "mirrored": isinstance(sol, MirroredSolution),
        "energy": sci(r.energy),
        "j3": sci(r.j3),
        "period_z": opt_float(sol.period_z),
    }
    for key, val in sol.info.items():
        if key != "period_z":
            out[key] = opt_float(val)
    out["samples"] = [
        {
            "t": t,
            "x": [float(c) for c in x],
            "v": [float(c) for c in v],
            "x_str": [sci(c) for c in x],
            "v_str": [sci(c) for c in v],
            "floor": f,
            "floor_normwise": fn,
        }
        for t, (x, v), f, fn in zip(TIMES, r.samples, r.floors, r.floors_normwise, strict=True)
    ]
    return out


def document(results: list[CaseResult]) -> dict[str, Any]:
    return {
        "generator": GENERATOR,
        "mp_dps": DPS,
        "string_digits": STR_DIGITS,
        "units": UNITS,
        "times": list(TIMES),
        "floor_method": (
            "floor: x0, v0 perturbed componentwise by relative 2^-53 (all 64 sign "
            "patterns), "
            "projected onto TS^2, solved exactly; max over the patterns of "
            "max(|dx|/l, |dv|/max(|v|, l w0)). floor_normwise: the same with absolute "
            "perturbations 2^-53 l (x) and 2^-53 max(|v0|, l w0) (v)"
        ),
        "cases": [case_json(r) for r in results],
    }


def to_json(doc: dict[str, Any]) -> str:
    """Indented JSON with every list of numbers or strings on one line."""
    text = json.dumps(doc, indent=1)
    text = re.sub(
        r"\[\s*([^\[\]{}\n]*(?:\n[^\[\]{}\n]*)*?)\s*\]",
        lambda mo: "[" + " ".join(mo.group(1).split()) + "]",
        text,
    )
    if json.loads(text) != doc:  # pragma: no cover - guards the regex
        raise GoldenError("internal error: compacted JSON does not round-trip")
    return text + "\n"


def write_atomic(path: Path, text: str) -> None:
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=path.name + ".", suffix=".tmp")
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as fh:
            fh.write(text)
            fh.flush()
            os.fsync(fh.fileno())
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(tmp, 0o666 & ~umask)  # mkstemp makes it 0600
        os.replace(tmp, path)
    except BaseException:
        if os.path.exists(tmp):
            os.unlink(tmp)
        raise


def compare(new: dict[str, Any], old: dict[str, Any]) -> list[str]:
    """Differences that matter between a recomputed and a committed document."""
    problems: list[str] = []
    for key in ("generator", "mp_dps", "times"):
        if new[key] != old.get(key):
            problems.append(f"{key}: {old.get(key)!r} != {new[key]!r}")
    new_cases = {c["name"]: c for c in new["cases"]}
    old_cases = {c["name"]: c for c in old.get("cases", [])}
    if set(new_cases) != set(old_cases):
        problems.append(f"case names differ: {sorted(old_cases)} vs {sorted(new_cases)}")
    for name in sorted(set(new_cases) & set(old_cases)):
        a, b = new_cases[name], old_cases[name]
        for key in ("scenario", "length", "mass", "g", "x0", "v0", "kind"):
            if a[key] != b.get(key):
                problems.append(f"{name}.{key}: committed {b.get(key)!r}, now {a[key]!r}")
        for sa, sb in zip(a["samples"], b.get("samples", []), strict=False):
            for key in ("x_str", "v_str"):
                va = [mpf(s) for s in sa[key]]
                vb = [mpf(s) for s in sb[key]]
                sc = max(norm(va), mpf(1e-300))
                if norm(sub(va, vb)) / sc > mpf("1e-28"):
                    problems.append(f"{name} t={sa['t']} {key}: committed {sb[key]}, now {sa[key]}")
            for key in ("floor", "floor_normwise"):
                if not math.isclose(sa[key], sb.get(key, math.nan), rel_tol=0.05):
                    problems.append(f"{name} t={sa['t']} {key}: committed {sb.get(key)}, now {sa[key]}")
        if len(a["samples"]) != len(b.get("samples", [])):
            problems.append(f"{name}: number of samples differs")
    return problems


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument(
        "--check",
        action="store_true",
        help="recompute and compare to the committed JSON",
    )
    ap.add_argument("--out", type=Path, default=OUTPUT, help="output file (default: %(default)s)")
    args = ap.parse_args(argv)
    mp.dps = DPS
    t0 = time.perf_counter()

    def log(msg: str) -> None:
        print(msg, flush=True)

    try:
        results = [run_case(sc, log) for sc in load_scenarios()]
    except GoldenError as e:
        print(f"error: {e}", file=sys.stderr)
        return 1
    doc = document(results)
    text = to_json(doc)
    elapsed = time.perf_counter() - t0
    if args.check:
        try:
            old = json.loads(args.out.read_text(encoding="utf-8"))
        except (OSError, ValueError) as e:
            print(f"error: cannot read {args.out}: {e}", file=sys.stderr)
            return 1
        problems = compare(doc, old)
        for p in problems:
            print(f"MISMATCH {p}", file=sys.stderr)
        print(f"{'FAILED' if problems else 'OK'}: {args.out} checked in {elapsed:.0f} s")
        return 1 if problems else 0
    write_atomic(args.out, text)
    print(f"wrote {args.out} ({len(results)} cases) in {elapsed:.0f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
