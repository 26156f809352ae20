"""The exact solution's special cases (T-4.6) and ``solve``, which picks the solution for a start on
TS^2: the generic orbit (golden_generic.py) or one of the cases below; anything else raises.
Equation numbers (T-x.y) refer to docs/theory.md; units SI (m, s, rad).

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
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import mpmath
from golden_base import GoldenError, State, Vec, dot, mirror, norm
from golden_generic import GenericSolution, Solution, ellipf_cont, jacobi
from mpmath import mp, mpf


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
