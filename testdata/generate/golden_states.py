#!/usr/bin/env python3
"""Golden reference states of the ideal spherical pendulum, from its exact solution.

Writes ``testdata/golden_states.json``: for every scenario in
``examples/scenarios/*.toml`` the state (x, v) at t = 1, 10, 100, 1000 and 10^4 s,
computed from the closed-form solution in elliptic functions at 40 significant digits
(mpmath), stored as float64 and as 30-digit strings, with conditioning floors per sample;
the orbit's scalar quantities (eps, j, heights z1 < z2, roots, m, period, Delta_phi and its
T-5.1 split into a dynamic and a geometric phase), each as float and 30-digit string; and
the worked example of docs/theory.md T-5.1 ("phase_example"). Equation numbers (T-x.y) refer to
docs/theory.md.

Usage (from the repository root)::

    python3 testdata/generate/golden_states.py           # regenerate, write the JSON
    python3 testdata/generate/golden_states.py --check   # recompute, compare, no write

Needs Python >= 3.11 and mpmath (>= 1.3); nothing else. Runs in about a minute.

Model (T-2.4): x' = v, v' = -g e3 + ((g z - |v|^2)/l^2) x on TS^2 (|x| = l, x.v = 0),
invariants (T-2.6) E = m(|v|^2/2 + g z) and J3 = m(x1 v2 - x2 v1).

Initial state: the float64 (x0, v0) that Rust's ``State::from_angles`` builds from the
scenario's angles (theta from the downward vertical), taken as exact binary numbers and
projected onto TS^2 (x <- l x/|x|, v <- v - (x.v/l^2) x) at twice the working precision,
which the values keep (rounded to 40 digits, the start would move the nearly conical
orbit's u2 - u1 by 1e-24 relative). That moves them by < 1e-15 relative (checked), below
the conditioning floor; without it no solution on TS^2 would pass through the stored floats.

Kind "generic" (g > 0, J3 != 0), dimensionless (T-1): w0 = sqrt(g/l), tau = w0 t,
u = z/l, eps = E/(m g l), j = J3/(m l^2 w0).

* T-4.1  (du/dtau)^2 = P(u) = 2(eps - u)(1 - u^2) - j^2 = 2(u - u1)(u - u2)(u - u3),
  -1 < u1 < u2 < 1 < u3.
* T-4.2  u = u1 + (u2 - u1) sn^2(s | m), s = lam (tau + tau0), m = (u2 - u1)/(u3 - u1),
  lam = sqrt((u3 - u1)/2), du/dtau = 2 (u2 - u1) lam sn cn dn. The phase s0 = lam tau0
  in [-K, K] solves sn^2(s0) = (u0 - u1)/(u2 - u1) with sn cn of the sign of z'(0)
  (docs/theory.md's F(arcsin sqrt((u0 - u1)/(u2 - u1)) | m), signed by z'(0)); near a turning
  point the smaller of sn, cn is taken from z'(0), so no digits are lost.
* T-4.3  T_z = 2 K(m)/(lam w0).
* T-4.4  phi = phi_low + A(s), A(s) = (j/(2 lam)) [Pi(n+; am s | m)/(1 - u1)
  + Pi(n-; am s | m)/(1 + u1)], n+- = +-(u2 - u1)/(1 -+ u1), continued past +-K by
  am(s + 2K) = am(s) + pi and Pi(n; phi + pi | m) = Pi(n; phi | m) + 2 Pi(n | m);
  phi_low = atan2(y0, x0) - A(s0).
* T-4.5  Delta_phi = (j/lam) [Pi(n+ | m)/(1 - u1) + Pi(n- | m)/(1 + u1)].
  Pi is evaluated in Carlson's form (ellippi_am) with 1 - n+ = (1 - u2)/(1 - u1) and
  1 - n- = (1 + u2)/(1 + u1): n+ is close to 1 when u2 is close to the top.
* T-5.1  Delta_phi = phase_dynamic + phase_geometric, phase_dynamic = (1/j) int sigma3 dtau,
  phase_geometric = -(1/j) int p_z du over one z-period, sigma3 = (u'^2 + j^2)/(1 - u^2),
  p_z = u'/(1 - u^2), both by mpmath.quad along u(tau) (GenericSolution.phases).
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
* J3 exactly 0 and g > 0, eps < 1, kind "planar" (libration): in the vertical plane of
  e_h (horizontal direction of x0) and e3, with the signed polar angle theta,
  sin(theta/2) = k sn(w0 t + c | k^2), k^2 = (1 + eps)/2, so
  l sin(theta) = 2 l k sn dn and z = -l (1 - 2 k^2 sn^2); theta' = 2 k w0 cn gives
  cn(c) = theta'(0)/(2 k w0) and sn(c) = sin(theta0/2)/k (released at rest: c = +-K).
  period_z is the swing period 4K(k^2)/w0 (T-6.2; z itself repeats after half of it).
* J3 exactly 0 and g > 0, eps > 1, kind "planar_rotating" (over the top, T-4.6): in the
  same plane, theta = 2 am(sigma lam tau + s0 | m), m = 2/(1 + eps),
  lam = sqrt((1 + eps)/2), sigma = sign(theta'(0)), s0 = F(theta0/2 | m); period_z is
  the revolution time 2K(m)/(lam w0) = 2 k K(k)/w0 with k^2 = m. eps = 1 (the separatrix)
  raises.

Checks (the file is not written unless all pass):

1. x(0), v(0) reproduce the (projected) initial state to 1e-30 relative.
2. At every output time |x| = l, x.v = 0, E and J3 equal their initial values (1e-30).
3. At t = 0.37 s and the output times, mpmath.diff of x(t) equals v(t) and mpmath.diff
   of v(t) equals the T-2.4 acceleration, to 1e-25.
4. mpmath.odefun (Taylor series, 30 digits) on the 6-dim T-2.4 system from t = 0 to
   2 s agrees with the formula to 1e-25.
5. Recomputed at 60 digits, the samples agree with the 40-digit ones to 1e-32, the
   scalar quantities to 1e-32 relative, and the perturbed orbits that set the floors
   (below) to 1e-25.
6. Generic orbits: phase_dynamic + phase_geometric = Delta_phi to 1e-25, and
   phase_dynamic equals its closed form (4/(j lam)) [K (eps - u1) - (u3 - u1)(K - E)]
   (from sigma3 = |v|^2 = 2(eps - u)) to 1e-25 relative. The T-5.1 example of docs/theory.md
   (l = g = 1, eps = 0.3, j = 0.5) must reproduce every digit docs/theory.md prints.

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
TIMES = (1.0, 10.0, 100.0, 1000.0, 10000.0)  # output times [s]
DIFF_TIMES = (0.37, *TIMES)  # times of check 3 [s]
TOL_STATE = mpf("1e-30")  # checks 1, 2
TOL_ODE = mpf("1e-25")  # checks 3, 4
TOL_HIGH = mpf("1e-32")  # check 5
TOL_FLOOR = mpf("1e-25")  # check 5, the orbits that set the floors
TOL_PHASE = mpf("1e-25")  # check 6
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
    "eps, j": "1 (eps = E/(m |g| l), j = J3/(m l^2 w0), of the g > 0 (mirrored) problem)",
    "z1, z2": "m (lowest and highest height of the bob, physical frame)",
    "phase_dynamic, phase_geometric": "rad",
    "*_str": "the same quantity as a decimal string with string_digits significant digits",
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
        if "crane" in doc:
            continue  # a crane scenario (docs/cranes.md) describes no pendulum of its own
        try:
            pend, init = doc["pendulum"], doc["initial"]
            model = pend.get("model", "ideal")
            if model != "ideal":
                continue  # the exact solution exists for the ideal pendulum only (damped, pivot, ...)
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
    eps: Any = field(init=False, default=None)  # E/(m g l) of the g > 0 problem; None if g = 0
    j: Any = field(init=False, default=None)  # J3/(m l^2 w0); None if g = 0
    z_range: tuple[Any, Any] | None = field(init=False, default=None)  # (z1, z2) [m], ascending
    info: dict[str, Any] = field(init=False, default_factory=dict)

    def state(self, t: Any) -> State:  # pragma: no cover - abstract
        raise NotImplementedError


def jacobi(s: Any, m: Any, big_k: Any) -> tuple[Any, Any, Any, tuple[Any, Any], int]:
    """sn, cn, dn of s; (sn, cn) of the reduced argument r = s - 2kK in [-K, K], and k.

    On [-K, K], cn >= 0 and am(r) = atan2(sn(r), cn(r)) lies in [-pi/2, pi/2];
    am(s) = am(r) + k pi.
    """
    k = int(mp.nint(s / (2 * big_k)))
    r = s - 2 * k * big_k
    sn = mpmath.ellipfun("sn", r, m=m)
    cn = mpmath.ellipfun("cn", r, m=m)
    dn = mpmath.ellipfun("dn", r, m=m)
    sign = -1 if k % 2 else 1
    return sign * sn, sign * cn, dn, (sn, cn), k


def ellippi_am(n: Any, one_minus_n: Any, sn: Any, cn: Any, dn: Any) -> Any:
    """Pi(n; am | m) for am in [-pi/2, pi/2] given sin am = sn, cos am = cn >= 0 and
    dn = sqrt(1 - m sn^2), with 1 - n passed separately (Carlson's form, DLMF §19.25(i), as mpmath.ellippi):

        Pi = sn RF(cn^2, dn^2, 1) + (n/3) sn^3 RJ(cn^2, dn^2, 1, cn^2 + (1 - n) sn^2).

    mpmath.ellippi forms 1 - n sin^2 from n and sin(am) rounded to the working precision;
    when n is close to 1 (a turning point close to a pole: n+ = 1 - (1 - u2)/(1 - u1))
    that cancels most of the digits. Here 1 - n sn^2 = cn^2 + (1 - n) sn^2 has none.
    The complete integral is the case sn = 1, cn = 0, dn = sqrt(1 - m).
    """
    c2, d2 = cn * cn, dn * dn

    def terms() -> tuple[Any, Any]:
        rf = mpmath.elliprf(c2, d2, 1)
        rj = mpmath.elliprj(c2, d2, 1, c2 + one_minus_n * sn * sn)
        return sn * rf, n * sn**3 * rj / 3

    # For n << 0 the two terms nearly cancel (Pi ~ 1/sqrt(-n)); sum_accurately raises the
    # precision until the sum is stable, as mpmath.ellippi does.
    return mp.sum_accurately(terms)


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
            consts.append((u3 - u2) / (u3 - u1))  # 1 - m
        w0, u0, up0, eps, j, u1, u2, u3, d, m, lam, p1, q1, p2, q2, r1, r2, m1 = (+c for c in consts)
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
        # 1 - n+ = (1 - u2)/(1 - u1), 1 - n- = (1 + u2)/(1 + u1), without cancellation
        self.one_n_plus, self.one_n_minus = q2 / q1, p2 / p1
        dn_k = mp.sqrt(m1)
        self.pi_plus = ellippi_am(n_plus, self.one_n_plus, mpf(1), mpf(0), dn_k)
        self.pi_minus = ellippi_am(n_minus, self.one_n_minus, mpf(1), mpf(0), dn_k)

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
        self.z_range = (ell * u1, ell * u2)
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
        sn, cn, dn, (sn_r, cn_r), k = jacobi(s, self.m, self.big_k)
        p_plus = ellippi_am(self.n_plus, self.one_n_plus, sn_r, cn_r, dn) + 2 * k * self.pi_plus
        p_minus = ellippi_am(self.n_minus, self.one_n_minus, sn_r, cn_r, dn) + 2 * k * self.pi_minus
        a = (self.j / (2 * self.lam)) * (p_plus / self.q1 + p_minus / self.p1)
        return a, sn, cn, dn

    def _one_minus_u2(self, sn2: Any, cn2: Any) -> Any:
        """1 - u^2 as (1 + u)(1 - u) from the nearer turning point, without cancellation."""
        if sn2 <= 0.5:
            return (self.p1 + self.d * sn2) * (self.q1 - self.d * sn2)
        return (self.p2 - self.d * cn2) * (self.q2 + self.d * cn2)

    def phases(self) -> tuple[Any, Any, Any]:
        """T-5.1 split of Delta_phi by quadrature along the exact u(tau), and a closed form.

        With s = lam tau over one z-period s in [0, 2K] (symmetric about K, so twice [0, K]),
        u' = du/dtau = 2 d lam sn cn dn, sigma3 = (u'^2 + j^2)/(1 - u^2) (H1.17) and
        p_z = u'/(1 - u^2):
        dyn = (1/j) int sigma3 dtau,  geom = -(1/j) int p_z du = -(1/j) int u'^2/(1 - u^2) dtau.
        Returns (dyn, geom, dyn_closed) where dyn_closed uses sigma3 = |v|^2 = 2(eps - u)
        and int_0^2K sn^2 = 2(K - E)/m: dyn = (4/(j lam)) [K (eps - u1) - (u3 - u1)(K - E)].
        """
        d, lam, j, m = self.d, self.lam, self.j, self.m
        cache: dict[Any, tuple[Any, Any]] = {}

        def parts(s: Any) -> tuple[Any, Any]:
            key = (s._mpf_, mp.prec)
            if key not in cache:
                sn = mpmath.ellipfun("sn", s, m=m)
                cn = mpmath.ellipfun("cn", s, m=m)
                dn = mpmath.ellipfun("dn", s, m=m)
                up = 2 * d * lam * sn * cn * dn
                cache[key] = (up * up, self._one_minus_u2(sn * sn, cn * cn))
            return cache[key]

        def f_dyn(s: Any) -> Any:
            up2, one_u2 = parts(s)
            return (up2 + j * j) / one_u2

        def f_geom(s: Any) -> Any:
            up2, one_u2 = parts(s)
            return up2 / one_u2

        ends = [mpf(0), self.big_k]
        dyn = 2 * mp.quad(f_dyn, ends) / (j * lam)
        geom = -2 * mp.quad(f_geom, ends) / (j * lam)
        big_e = mpmath.ellipe(m)
        dyn_closed = (4 / (j * lam)) * (
            self.big_k * (self.eps - self.u1) - (self.u3 - self.u1) * (self.big_k - big_e)
        )
        return dyn, geom, dyn_closed

    def state(self, t: Any) -> State:
        ell, w0 = self.length, self.w0
        s = self.lam * (w0 * t + self.tau0)
        a, sn, cn, dn = self._azimuth(s)
        sn2 = sn**2
        u = self.u1 + self.d * sn2
        one_u2 = self._one_minus_u2(sn2, cn**2)
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


@dataclass
class PlanarFrame:
    """A start with J3 exactly 0 (g > 0) in its vertical plane.

    e_h is the horizontal unit vector of x0 (of v0 if x0 is on the axis); theta0 is the
    polar angle from the downward vertical, signed along e_h; eps = E/(m g l).
    """

    w0: Any
    e_h: Vec
    theta0: Any
    thetadot0: Any
    eps: Any


def planar_frame(length: Any, g: Any, x0: Vec, v0: Vec) -> PlanarFrame:
    ell = length
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
    return PlanarFrame(w0, e_h, theta0, thetadot0, eps)


def planar_solution(length: Any, g: Any, x0: Vec, v0: Vec) -> Solution:
    """J3 exactly 0, g > 0: libration (eps < 1) or over the top (eps > 1)."""
    fr = planar_frame(length, g, x0, v0)
    if fr.eps < 1:
        return PlanarSolution(length, g, fr)
    if fr.eps > 1:
        return PlanarRotatingSolution(length, g, fr)
    raise GoldenError("planar motion on the separatrix (eps = 1): not supported")


class PlanarSolution(Solution):
    """g > 0, J3 = 0, libration in a vertical plane (T-4.6, T-6.2)."""

    def __init__(self, length: Any, g: Any, fr: PlanarFrame) -> None:
        super().__init__(length, g)
        self.kind = "planar"
        ell, w0, eps = self.length, fr.w0, fr.eps
        k2 = (1 + eps) / 2
        if k2 <= 0:
            raise GoldenError("planar case at rest at the bottom: nothing to compute")
        k = mp.sqrt(k2)
        big_k = mpmath.ellipk(k2)
        sn0 = mp.sin(fr.theta0 / 2) / k
        cn0 = fr.thetadot0 / (2 * k * w0)
        self.c = ellipf_cont(mp.atan2(sn0, cn0), k2, big_k)
        self.w0, self.k, self.k2, self.big_k, self.e_h = w0, k, k2, big_k, fr.e_h
        self.eps, self.j = eps, mpf(0)
        self.z_range = (-ell, ell * eps)  # z = -l cos(theta), |theta| <= theta_max
        self.period_z = 4 * big_k / w0  # the swing period; z itself repeats after half of it
        self.info = {
            "k2": k2,
            "theta_max": 2 * mp.asin(k),
            "period_z": self.period_z,
            "period_swing": self.period_z,
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


class PlanarRotatingSolution(Solution):
    """g > 0, J3 = 0, eps > 1: over the top in a vertical plane (T-4.6).

    theta = 2 am(sigma lam tau + s0 | m), m = 2/(1 + eps), lam = sqrt((1 + eps)/2),
    sigma = sign(theta'(0)), s0 = F(theta0/2 | m); theta' = 2 sigma lam w0 dn. With
    sn, cn of the full argument: sin(theta) = 2 sn cn, cos(theta) = 1 - 2 sn^2. One
    revolution (theta -> theta + 2 pi) takes 2K(m)/(lam w0) = 2 k K(k)/w0, k^2 = m.
    """

    def __init__(self, length: Any, g: Any, fr: PlanarFrame) -> None:
        super().__init__(length, g)
        self.kind = "planar_rotating"
        ell, w0, eps = self.length, fr.w0, fr.eps
        m = 2 / (1 + eps)
        lam = mp.sqrt((1 + eps) / 2)
        big_k = mpmath.ellipk(m)
        self.sigma = 1 if fr.thetadot0 > 0 else -1
        self.s0 = ellipf_cont(fr.theta0 / 2, m, big_k)
        self.w0, self.m, self.lam, self.big_k, self.e_h = w0, m, lam, big_k, fr.e_h
        self.eps, self.j = eps, mpf(0)
        self.z_range = (-ell, ell)
        self.period_z = 2 * big_k / (lam * w0)  # the revolution time
        self.info = {"m": m, "period_z": self.period_z}

    def state(self, t: Any) -> State:
        ell = self.length
        sn, cn, dn, _, _ = jacobi(self.sigma * self.lam * self.w0 * t + self.s0, self.m, self.big_k)
        sin_t, cos_t = 2 * sn * cn, 1 - 2 * sn**2
        thetadot = 2 * self.sigma * self.lam * self.w0 * dn
        h, z = ell * sin_t, -ell * cos_t
        hp, zp = ell * cos_t * thetadot, ell * sin_t * thetadot
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
        if self.w == 0:
            self.z_range = (x0[2], x0[2])
        else:  # the plane of the great circle has the unit normal x0 x v0/(l |v0|)
            nn = [x0[1] * v0[2] - x0[2] * v0[1], x0[2] * v0[0] - x0[0] * v0[2]]
            z_max = mp.sqrt(nn[0] ** 2 + nn[1] ** 2) / (self.w * self.length)
            self.z_range = (-z_max, z_max)
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
        self.eps, self.j = self.inner.eps, self.inner.j
        zr = self.inner.z_range
        self.z_range = None if zr is None else (-zr[1], -zr[0])
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
        return planar_solution(length, g, x0, v0)
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
    derived: dict[str, Any]  # scalar quantities of the orbit (mpf or None), see derived()


def derived(sol: Solution) -> dict[str, Any]:
    """The orbit's scalar quantities: period_z, eps, j, z1, z2, then the kind's own (info)."""
    z1, z2 = sol.z_range if sol.z_range is not None else (None, None)
    out = {"period_z": sol.period_z, "eps": sol.eps, "j": sol.j, "z1": z1, "z2": z2}
    out.update((k, v) for k, v in sol.info.items() if k != "period_z")
    return out


def generic_part(sol: Solution) -> GenericSolution | None:
    """The generic solution behind sol (also through the mirror), or None."""
    inner = sol.inner if isinstance(sol, MirroredSolution) else sol
    return inner if isinstance(inner, GenericSolution) else None


def phase_split(name: str, gen: GenericSolution) -> dict[str, Any]:
    """Check 6: the T-5.1 phases by quadrature sum to Delta_phi (T-4.5), and the dynamic
    phase equals its closed form, both to 1e-25."""
    dyn, geom, dyn_closed = gen.phases()
    err_sum = abs(dyn + geom - gen.delta_phi)
    err_dyn = abs(dyn - dyn_closed) / abs(dyn)
    if not (err_sum <= TOL_PHASE and err_dyn <= TOL_PHASE):
        raise GoldenError(
            f"{name}: phases: dyn + geom - delta_phi = {mpmath.nstr(err_sum, 5)}, "
            f"dyn vs closed form {mpmath.nstr(err_dyn, 5)} (tolerance {TOL_PHASE})"
        )
    return {"phase_dynamic": dyn, "phase_geometric": geom, "6_sum": err_sum, "6_closed": err_dyn}


def initial_state(sc: Scenario) -> State:
    """The float64 start projected onto TS^2 at twice the working precision (the values keep
    it): a start rounded to the working precision would move a nearly conical orbit's
    u2 - u1 (conical: 7e-18) by 1e-24 relative."""
    with mp.extraprec(mp.prec):
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


def conditioning_floors(sc: Scenario, samples: list[State], normwise: bool) -> tuple[list[float], float]:
    """Worst relative state error at each output time from a 2^-53 change of the start.

    Componentwise (normwise=False): each component c -> c (1 +- 2^-53), the rounding of
    the start to float64 (zero components stay exact). Normwise: x_i -> x_i +- 2^-53 l
    and v_i -> v_i +- 2^-53 max(|v0|, l w0), the size of one rounding of a whole state.
    Either way the result is projected onto TS^2 and solved exactly. The perturbed orbits
    that set the floors are solved again at HIGH_DPS digits; returns the floors and the
    largest difference found (check 5).
    """

    def perturbed(signs: tuple[int, ...]) -> list[State]:
        ell, g = mpf(sc.length), mpf(sc.g)
        raw = to_mp(sc.x0) + to_mp(sc.v0)
        rel = mpf(FLOOR_REL)
        if normwise:
            vs0 = v_scale(ell, g, raw[3:])
            y = [
                c + s * rel * (ell if i < 3 else vs0) for i, (c, s) in enumerate(zip(raw, signs, strict=True))
            ]
        else:
            y = [c * (1 + s * rel) for c, s in zip(raw, signs, strict=True)]
        with mp.extraprec(mp.prec):  # as initial_state: near-conical orbits need it
            x0, v0 = project(ell, y[:3], y[3:])
        sol = solve(ell, g, x0, v0)
        return [sol.state(mpf(t)) for t in TIMES]

    ell, g = mpf(sc.length), mpf(sc.g)
    scales = [v_scale(ell, g, ref[1]) for ref in samples]
    worst = [mpf(0)] * len(TIMES)
    worst_at: list[tuple[int, ...]] = [()] * len(TIMES)
    states: dict[tuple[int, ...], list[State]] = {}
    for signs in floor_patterns():
        states[signs] = perturbed(signs)
        for i, (got, ref, vs) in enumerate(zip(states[signs], samples, scales, strict=True)):
            err = state_error(ell, vs, got, ref)
            if err > worst[i]:
                worst[i], worst_at[i] = err, signs
    recheck = mpf(0)
    for signs in sorted(set(worst_at)):
        with mp.workdps(HIGH_DPS):
            high = perturbed(signs)
        for lo, hi, vs in zip(states[signs], high, scales, strict=True):
            recheck = max(recheck, state_error(ell, vs, lo, hi))
    if not recheck <= TOL_FLOOR:
        kind = "normwise" if normwise else "componentwise"
        raise GoldenError(
            f"{sc.name}: {kind} floor orbits differ by {recheck} at {DPS} and {HIGH_DPS} digits"
        )
    return [float(mpmath.nstr(w, 3)) for w in worst], float(recheck)


def run_case(sc: Scenario, log: Callable[[str], None]) -> CaseResult:
    t_start = time.perf_counter()
    x0, v0 = initial_state(sc)
    sol = solve(sc.length, sc.g, x0, v0)
    log(f"[{sc.name}] kind={sol.kind}, g={sc.g}")
    checks = verify(sc, sol, x0, v0, log)
    samples = [sol.state(mpf(t)) for t in TIMES]

    quantities = derived(sol)

    # 5. recompute at higher precision: the samples and the scalar quantities
    with mp.workdps(HIGH_DPS):
        xh, vh = initial_state(sc)
        sol_h = solve(sc.length, sc.g, xh, vh)
        ell = mpf(sc.length)
        worst = mpf(0)
        for t, ref in zip(TIMES, samples, strict=True):
            hi = sol_h.state(mpf(t))
            worst = max(worst, state_error(ell, v_scale(ell, mpf(sc.g), hi[1]), hi, ref))
        worst_q, worst_key = mpf(0), ""
        for key, val in derived(sol_h).items():
            ref = quantities[key]
            if (val is None) != (ref is None):
                raise GoldenError(f"{sc.name}: {key} is {ref} at {DPS} digits, {val} at {HIGH_DPS}")
            if val is not None and val != ref:
                err = abs(val - ref) / abs(val)
                if err > worst_q:
                    worst_q, worst_key = err, key
    checks["5_high_precision"] = float(worst)
    checks["5_quantities"] = float(worst_q)
    if not worst <= TOL_HIGH:
        raise GoldenError(f"{sc.name}: {DPS}-digit and {HIGH_DPS}-digit results differ by {worst}")
    if not worst_q <= TOL_HIGH:
        raise GoldenError(f"{sc.name}: {worst_key} at {DPS} and {HIGH_DPS} digits differs by {worst_q}")

    # 6. the phase split of T-5.1 (generic orbits)
    gen = generic_part(sol)
    if gen is not None:
        split = phase_split(sc.name, gen)
        quantities["phase_dynamic"] = split["phase_dynamic"]
        quantities["phase_geometric"] = split["phase_geometric"]
        checks["6_phase_sum"] = float(split["6_sum"])
        checks["6_phase_closed"] = float(split["6_closed"])
        log(
            f"    phases: dynamic {mpmath.nstr(split['phase_dynamic'], 12)}, geometric "
            f"{mpmath.nstr(split['phase_geometric'], 12)}; sum - delta_phi {mpmath.nstr(split['6_sum'], 2)}"
        )

    floors, checks["5_floor_orbits"] = conditioning_floors(sc, samples, normwise=False)
    floors_nw, recheck_nw = conditioning_floors(sc, samples, normwise=True)
    checks["5_floor_orbits"] = max(checks["5_floor_orbits"], recheck_nw)
    mass, g = mpf(sc.mass), mpf(sc.g)
    log(
        f"    check 5 ({HIGH_DPS} digits): samples {checks['5_high_precision']:.1e}, quantities "
        f"{checks['5_quantities']:.1e}, floor orbits {checks['5_floor_orbits']:.1e}"
    )
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
        quantities,
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


def opt_sci(x: Any) -> str | None:
    return None if x is None else sci(x)


def quantity_fields(quantities: dict[str, Any]) -> dict[str, Any]:
    """Each quantity as a float (nearest float64) and as a 30-digit string, key + "_str"."""
    out: dict[str, Any] = {}
    for key, val in quantities.items():
        out[key] = opt_float(val)
        out[key + "_str"] = opt_sci(val)
    return out


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
    }
    out.update(quantity_fields(r.derived))
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


# The T-5.1 example of docs/theory.md: l = g = 1, eps = 0.3, j = 0.5, as printed there.
PHASE_EXAMPLE_PRINTED = {
    "delta_phi": "4.16859732561",
    "phase_dynamic": "9.5651005316",
    "phase_geometric": "-5.39650320598",
}


def phase_example(log: Callable[[str], None]) -> dict[str, Any]:
    """The T-5.1 example of docs/theory.md, recomputed; its printed digits must agree (half a unit in
    the last printed place). Start on the equator (u0 = 0, x0 = (l, 0, 0)) with
    v0 = (0, j, sqrt(2 eps - j^2)) in units l = g = m = 1, so that E = eps and J3 = j."""
    eps, j = mpf("0.3"), mpf("0.5")
    x0 = [mpf(1), mpf(0), mpf(0)]
    v0 = [mpf(0), j, mp.sqrt(2 * eps - j * j)]
    sol = solve(1, 1, x0, v0)
    if not isinstance(sol, GenericSolution):
        raise GoldenError("phase example: not a generic orbit")
    tiny = mpf(10) ** (-DPS + 2)
    if abs(sol.eps - eps) > tiny or abs(sol.j - j) > tiny:
        raise GoldenError(f"phase example: eps = {sol.eps}, j = {sol.j}")
    split = phase_split("phase_example", sol)
    quantities = derived(sol)
    quantities.update(phase_dynamic=split["phase_dynamic"], phase_geometric=split["phase_geometric"])
    for key, printed in PHASE_EXAMPLE_PRINTED.items():
        decimals = len(printed.split(".")[1])
        err = abs(quantities[key] - mpf(printed))
        if not err <= mpf(10) ** (-decimals) / 2:
            raise GoldenError(
                f"phase example: {key} = {mpmath.nstr(quantities[key], 20)}, docs/theory.md prints {printed}"
            )
    log(
        "[phase_example] docs/theory.md T-5.1 reproduced: delta_phi, dynamic, geometric = "
        + ", ".join(mpmath.nstr(quantities[k], 15) for k in PHASE_EXAMPLE_PRINTED)
    )
    return {
        "source": "docs/theory.md T-5.1",
        "length": 1.0,
        "mass": 1.0,
        "g": 1.0,
        "x0_str": [sci(c) for c in x0],
        "v0_str": [sci(c) for c in v0],
        "kind": sol.kind,
        **quantity_fields(quantities),
        "theory_printed": dict(PHASE_EXAMPLE_PRINTED),
    }


def document(results: list[CaseResult], example: dict[str, Any]) -> dict[str, Any]:
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
        "phase_example": example,
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
        for key in ("scenario", "length", "mass", "g", "x0", "v0", "kind", "mirrored"):
            if a[key] != b.get(key):
                problems.append(f"{name}.{key}: committed {b.get(key)!r}, now {a[key]!r}")
        problems += compare_quantities(name, a, b)
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
    problems += compare_quantities("phase_example", new["phase_example"], old.get("phase_example", {}))
    return problems


def compare_quantities(name: str, a: dict[str, Any], b: dict[str, Any]) -> list[str]:
    """Same keys (except samples) and every scalar *_str (energy, j3 too) to 1e-28 relative."""
    problems: list[str] = []
    if set(a) != set(b):
        problems.append(f"{name}: keys differ: {sorted(set(a) ^ set(b))}")
    for key in sorted(set(a) & set(b)):
        va, vb = a[key], b[key]
        if not (key.endswith("_str") or key in ("energy", "j3")) or not isinstance(va, str):
            continue
        if not isinstance(vb, str):
            problems.append(f"{name}.{key}: committed {vb!r}, now {va!r}")
            continue
        ma, mb = mpf(va), mpf(vb)
        if abs(ma - mb) > mpf("1e-28") * max(abs(ma), mpf(1e-300)):
            problems.append(f"{name}.{key}: committed {vb}, now {va}")
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
        example = phase_example(log)
    except GoldenError as e:
        print(f"error: {e}", file=sys.stderr)
        return 1
    doc = document(results, example)
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
