//! The Weierstrass form of the exact height (T-4.7), dimensionless (u = z/l, τ = ω₀t, g > 0; the
//! caller mirrors g < 0 and scales to SI): a second path to u(τ), independent of the Jacobi form of
//! T-4.2 (no sn, no Carlson integral, no K), for checking it.
//!
//! With u = 2w + ε/3 the cubic of T-4.1, u_τ² = P(u) = 2u³ − 2εu² − 2u + 2ε − j², becomes
//! Weierstrass's normal form
//!
//!   w_τ² = 4w³ − g₂w − g₃,   g₂ = ε²/3 + 1,   g₃ = ε³/27 − ε/3 + j²/4,
//!
//! with roots e₁ ≥ e₂ ≥ e₃, e_i = (u_{4−i} − ε/3)/2 (e₁ from u₃, e₃ from u₁). Its solution through
//! (w₀, w₀′) = ((u₀ − ε/3)/2, u̇₀/2) is w(τ) = ℘(τ + z₀) for the z₀ with ℘(z₀) = w₀, ℘′(z₀) = w₀′, and
//! the addition theorem of ℘ gives it from ℘(τ), ℘′(τ) at the real τ alone, without z₀ (which is
//! complex); with D = ℘(τ) − w₀ and P′(u₀) = −2(ρ₀² + 2κu₀) (`cubic`: no cancellation),
//!
//!   u(τ) − u₀ = P′(u₀)/(4D) + u̇₀(u̇₀/2 − ℘′(τ))/(2D²),
//!   u_τ(τ)    = −u̇₀ − (℘′(τ) − u̇₀/2)(u(τ) − u₀)/D,
//!
//! (the first from ℘(τ + z₀) = −℘(τ) − w₀ + ¼((℘′(τ) − w₀′)/(℘(τ) − w₀))² with ℘′² − w₀′² expanded,
//! the second from the three collinear points τ, z₀, −(τ + z₀) of the curve). D ≥ e₁ − e₂ > 0 on the
//! real axis, so neither has a pole, and as τ → 0 both tend to (u₀, u̇₀) without cancellation.
//!
//! ℘ itself, on the real axis, through q(x) = ℘(x) − e₁ ≥ 0, which keeps its relative accuracy where
//! ℘ → e₁ (d₂ = e₁ − e₂, d₃ = e₁ − e₃, c = d₂d₃; DLMF 23.2, 23.8, 23.10):
//! - the real half-period ω₁ = π / (2 AGM(√d₃, √d₂)) (∞ on the separatrix, d₂ = 0); x = τ reduced by
//!   2ω₁ into [−ω₁, ω₁], ℘ being even and 2ω₁-periodic (AGM and reduction in double-double, so that
//!   10⁴ periods cost no more than a few ulp of the phase);
//! - for |x| ≤ ω₁/2: the Laurent series ℘(z) = z⁻² + Σ_{k≥2} c_k z^{2k−2}, c₂ = g₂/20, c₃ = g₃/28,
//!   c_k = 3/((2k+1)(k−3)) Σ_{m=2}^{k−2} c_m c_{k−m}, at z = x/2ⁿ small, then n doublings
//!   q(2z) = (q² − c)² / (4q(q + d₂)(q + d₃)) (every factor positive there);
//! - for ω₁/2 < |x| ≤ ω₁: the half-period shift q(x) = c / q(ω₁ − |x|);
//! - ℘′(x) = −sgn(x)·2√(q(q + d₂)(q + d₃)).
//!
//! The roots enter only as the differences d₂, d₃ and e₁ − w₀ = (u₃ − u₀)/2, taken from the anchored
//! roots of `cubic` (the same cubic; its differences are what keeps D and q accurate near the poles
//! and the separatrix). Nothing else is shared with the Jacobi path.

use super::cubic::StartData;
use crate::elliptic::dd::{two_prod, Dd, FRAC_PI_2};

/// Laurent coefficients c₂ … c_{LAURENT_TERMS+1}.
const LAURENT_TERMS: usize = 10;
/// |z|·s at which the Laurent series is summed (s = max(|g₂|^{1/4}, |g₃|^{1/6})): the terms fall
/// like (|z|s)^{2k}, so ten terms reach 1e-19.
const LAURENT_RADIUS: f64 = 0.125;

/// The Weierstrass form of one orbit (see the module doc).
#[derive(Debug, Clone)]
pub struct Weierstrass {
    /// Invariant g₂ = ε²/3 + 1 (dimensionless).
    pub g2: f64,
    /// Invariant g₃ = ε³/27 − ε/3 + j²/4 (dimensionless).
    pub g3: f64,
    /// Roots e₁ ≥ e₂ ≥ e₃ of 4w³ − g₂w − g₃.
    pub e: [f64; 3],
    /// The real half-period ω₁ (in τ; ∞ on the separatrix). The z-period is 2ω₁.
    pub omega1: f64,
    /// ω₁ in double-double (None on the separatrix).
    omega1_dd: Option<Dd>,
    /// ε/3, the shift of u = 2w + ε/3.
    pub shift: f64,
    d2: f64,
    d3: f64,
    /// e₁ − w₀ = (u₃ − u₀)/2 ≥ 0.
    e1_minus_w0: f64,
    u0: f64,
    udot0: f64,
    /// P′(u₀) = −2(ρ₀² + 2κu₀).
    dp0: f64,
    laurent: [f64; LAURENT_TERMS],
    /// s = max(|g₂|^{1/4}, |g₃|^{1/6}), the scale of the lattice.
    scale: f64,
}

/// ω₁ = π/(2 AGM(√d₃, √d₂)) in double-double (DLMF 19.8.1 with 23.6.? scaling); None when d₂ = 0.
fn half_period(d3: f64, d2: f64) -> Option<Dd> {
    if !(d2 > 0.0 && d3 > 0.0) {
        return None;
    }
    let (mut a, mut b) = (Dd { hi: d3, lo: 0.0 }.sqrt(), Dd { hi: d2, lo: 0.0 }.sqrt());
    for _ in 0..64 {
        if (a.hi - b.hi).abs() <= 1e-30 * a.hi {
            break;
        }
        (a, b) = (a.add(b).scale(0.5), a.mul(b).sqrt());
    }
    Some(FRAC_PI_2.div(a.add(b).scale(0.5)))
}

impl Weierstrass {
    /// The Weierstrass form of the orbit through `start` (g > 0 frame, any j; not a rest state).
    pub fn new(start: &StartData) -> Self {
        let eps = start.epsilon();
        let j2 = start.j * start.j;
        let g2 = eps * eps / 3.0 + 1.0;
        let g3 = eps * eps * eps / 27.0 - eps / 3.0 + 0.25 * j2;
        let [u1, u2, u3] = start.roots();
        let shift = eps / 3.0;
        let e = [
            0.5 * (start.value(u3) - shift),
            0.5 * (start.value(u2) - shift),
            0.5 * (start.value(u1) - shift),
        ];
        let d2 = (0.5 * start.diff(u3, u2)).max(0.0);
        let d3 = (0.5 * start.diff(u3, u1)).max(0.0);
        let omega1_dd = half_period(d3, d2);
        let omega1 = omega1_dd.map_or(f64::INFINITY, |w| w.hi);
        let mut c = [0.0; LAURENT_TERMS];
        c[0] = g2 / 20.0;
        c[1] = g3 / 28.0;
        for k in 4..LAURENT_TERMS + 2 {
            let sum: f64 = (2..=k - 2).map(|m| c[m - 2] * c[k - m - 2]).sum();
            c[k - 2] = 3.0 * sum / (((2 * k + 1) * (k - 3)) as f64);
        }
        let rho2 = start.p_minus * start.p_plus;
        Self {
            g2,
            g3,
            e,
            omega1,
            omega1_dd,
            shift,
            d2,
            d3,
            e1_minus_w0: (0.5 * start.from_start(u3)).max(0.0),
            u0: start.u0,
            udot0: start.udot,
            dp0: -2.0 * (rho2 + 2.0 * start.kappa * start.u0),
            laurent: c,
            scale: g2.abs().sqrt().sqrt().max(g3.abs().cbrt().sqrt()),
        }
    }

    /// q(x) = ℘(x) − e₁ for 0 < x ≤ ω₁/2 (any x > 0 on the separatrix): Laurent series, then doublings.
    fn q_near_pole(&self, x: f64) -> f64 {
        let mut n = 0;
        let mut z = x;
        while z * self.scale > LAURENT_RADIUS {
            z *= 0.5;
            n += 1;
        }
        let z2 = z * z;
        let mut series = 0.0;
        for &ck in self.laurent.iter().rev() {
            series = series * z2 + ck;
        }
        // ℘ = z⁻² + z²(c₂ + c₃z² + …); q = ℘ − e₁
        let mut q = 1.0 / z2 + (z2 * series - self.e[0]);
        let c = self.d2 * self.d3;
        for _ in 0..n {
            let num = q * q - c;
            q = num * num / (4.0 * q * (q + self.d2) * (q + self.d3));
        }
        q
    }

    /// ℘(x) − e₁ and ℘′(x) at a real x.
    pub fn wp(&self, x: f64) -> (f64, f64) {
        // x − 2ω₁n and ω₁ − |x − 2ω₁n| in double-double
        let (xr, y) = match self.omega1_dd {
            Some(w) => {
                let p = w.scale(2.0);
                let n = (x / p.hi).round();
                let r = Dd { hi: x, lo: 0.0 }.sub(two_prod(n, p.hi)).sub(Dd { hi: n * p.lo, lo: 0.0 });
                let ar = if r.hi < 0.0 { Dd { hi: -r.hi, lo: -r.lo } } else { r };
                (r.hi, w.sub(ar).hi)
            }
            None => (x, f64::INFINITY),
        };
        let ax = xr.abs();
        let q = if ax == 0.0 {
            f64::INFINITY
        } else if ax <= 0.5 * self.omega1 {
            self.q_near_pole(ax)
        } else {
            if y <= 0.0 {
                0.0
            } else {
                self.d2 * self.d3 / self.q_near_pole(y)
            }
        };
        let dp = -2.0 * (q * (q + self.d2) * (q + self.d3)).sqrt();
        (q, if xr < 0.0 { -dp } else { dp })
    }

    /// u(τ) and u_τ(τ) at τ after the start.
    pub fn at(&self, tau: f64) -> (f64, f64) {
        let (q, dp) = self.wp(tau);
        if !q.is_finite() || !(q * q).is_finite() {
            // at (or within 1e-150 of) a pole of ℘, i.e. at the start or a whole number of z-periods on
            return (self.u0, self.udot0);
        }
        let d = q + self.e1_minus_w0;
        let du = self.dp0 / (4.0 * d) + self.udot0 * (0.5 * self.udot0 - dp) / (2.0 * d * d);
        let u_tau = -self.udot0 - (dp - 0.5 * self.udot0) * du / d;
        (self.u0 + du, u_tau)
    }
}
