"""The exact solution of the ideal spherical pendulum in elliptic functions, generic orbits (g > 0,
J3 != 0), at mpmath's working precision; the base class of every exact solution and the elliptic
helpers (Jacobi functions with the reduced argument, Pi in Carlson's form, F continued). Equation
numbers (T-x.y) refer to docs/theory.md; units SI (m, s, rad), u and tau dimensionless.

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
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import mpmath
from golden_base import GoldenError, State, Vec, dot
from mpmath import mp, mpf

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
