//! The exact flow of a planar (J₃ = 0) orbit in the vertical plane spanned by a horizontal unit
//! vector e and e₃, dimensionless (u = z/l, τ = ω₀t, g > 0), with the in-plane angle θ from the
//! downward vertical (x/l = sin θ e − cos θ e₃, so u = −cos θ and the signed horizontal coordinate is
//! h = sin θ). The bob passes through the poles; its azimuth jumps by π there and nowhere else.
//! T-4.6 and T-6.2; ε = E/(m g l) = κ + u₀.
//!
//! - Libration, ε < 1: sin(θ/2) = k sn(τ + s₀ | m), m = k² = (1 + ε)/2 (T-6.2: period 4K(m)/ω₀), so
//!   h = 2k sn dn, u = −1 + 2m sn², θ_τ = 2k cn.
//! - Rotation over the top, ε > 1: θ = 2 am(λτ + s₀ | m), m = 2/(1 + ε), λ = √((1 + ε)/2) = 1/k
//!   (T-4.6: one revolution takes 2K(m)/λ = 2kK(k)/ω₀), so h = 2 sn cn, u = sn² − cn², θ_τ = 2λ dn.
//! - Separatrix, ε = 1: the libration formulas at m = 1, sn = tanh, cn = dn = sech; θ → ±π as τ → ∞.
//!
//! e is oriented so that θ̇ ≥ 0 at the start; the argument s is reduced by the period (4K or 2K).

use super::generic::UnitState;
use crate::elliptic::{JacobiParam, Param};
use crate::error::Result;

/// Which planar motion.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PlanarMotion {
    /// Swinging back and forth through the bottom (ε < 1).
    Libration,
    /// Going over the top (ε > 1).
    Rotation,
    /// Exactly the separatrix energy (ε = 1): approaches the top forever.
    Separatrix,
}

/// A planar orbit.
#[derive(Debug, Clone)]
pub struct Planar {
    /// Libration, rotation or separatrix.
    pub motion: PlanarMotion,
    /// Parameter m.
    pub m: f64,
    /// λ (1 for libration and separatrix).
    pub lambda: f64,
    /// K(m) (∞ on the separatrix).
    pub k: f64,
    /// The Jacobi functions at this m.
    pub jp: JacobiParam,
    /// Start argument s₀.
    pub s0: f64,
    /// Horizontal unit vector e of the plane (x, y).
    pub e: [f64; 2],
}

impl Planar {
    /// The orbit through the start. `x`, `v` in units of l and lω₀ (g > 0 frame), with J₃ = 0;
    /// `kappa` = |v|²/2, `p_minus` = 1 + u₀ and `p_plus` = 1 − u₀ as in `cubic::StartData`.
    pub fn new(x: [f64; 3], v: [f64; 3], kappa: f64, p_minus: f64, p_plus: f64) -> Result<Self> {
        let (xh, vh) = ([x[0], x[1]], [v[0], v[1]]);
        let norm = |a: [f64; 2]| a[0].hypot(a[1]);
        // The plane: along the horizontal position, or along the horizontal velocity where that is
        // the longer (always at a pole). With J₃ = 0 they are parallel; a J₃ at rounding level or
        // below `PLANAR_J` tilts them by j/(ρ|v_h|), and the longer of the two loses the least:
        // j/max(ρ, |v_h|) in x or v (units l, lω₀).
        let mut e = if norm(xh) >= norm(vh) && norm(xh) > 0.0 { xh } else { vh };
        let ne = norm(e);
        e = if ne > 0.0 { [e[0] / ne, e[1] / ne] } else { [1.0, 0.0] };
        let h0 = x[0] * e[0] + x[1] * e[1];
        let mut theta0 = h0.atan2(-x[2]);
        let (st, ct) = theta0.sin_cos();
        let theta_dot = (v[0] * e[0] + v[1] * e[1]) * ct + v[2] * st;
        if theta_dot < 0.0 {
            e = [-e[0], -e[1]];
            theta0 = -theta0;
        }
        let one_plus_eps = kappa + p_minus;
        let eps_minus_one = kappa - p_plus;
        let motion = if eps_minus_one < 0.0 {
            PlanarMotion::Libration
        } else if eps_minus_one > 0.0 {
            PlanarMotion::Rotation
        } else {
            PlanarMotion::Separatrix
        };
        let sign = if theta0 < 0.0 { -1.0 } else { 1.0 };
        let (param, lambda, s0) = match motion {
            PlanarMotion::Libration | PlanarMotion::Separatrix => {
                // m = (1 + ε)/2, m′ = (1 − ε)/2 = (p₊ − κ)/2
                let m = (0.5 * one_plus_eps).min(1.0);
                let param = Param::with_complement(m, (-0.5 * eps_minus_one).max(0.0))
                    .unwrap_or(Param { m, m1: 1.0 - m });
                // sn₀ = sin(θ₀/2)/k = ±√(p₋/(1 + ε)), cn₀ = θ̇₀/(2k) ≥ 0 = √(κ/(1 + ε)).
                let sn0 = sign * (p_minus / one_plus_eps).sqrt();
                let cn0 = (kappa / one_plus_eps).sqrt();
                let k = JacobiParam::with_complement(param).quarter_period();
                (param, 1.0, super::amplitude_argument(sn0, cn0, param, k)?)
            }
            PlanarMotion::Rotation => {
                // m = 2/(1 + ε), m′ = (ε − 1)/(ε + 1)
                let m = 2.0 / one_plus_eps;
                let param = Param::with_complement(m, eps_minus_one / one_plus_eps)
                    .unwrap_or(Param { m, m1: 1.0 - m });
                // s₀ = F(θ₀/2 | m) from sin(θ₀/2) = ±√(p₋/2), cos(θ₀/2) = √(p₊/2) (not from fl(θ₀/2),
                // which next to the top, θ₀/2 → π/2 with m → 1, is as bad as in `amplitude_argument`)
                let (sh, ch) = (sign * (0.5 * p_minus).sqrt(), (0.5 * p_plus).sqrt());
                let k = JacobiParam::with_complement(param).quarter_period();
                (param, (0.5 * one_plus_eps).sqrt(), super::amplitude_argument(sh, ch, param, k)?)
            }
        };
        let jp = JacobiParam::with_complement(param);
        Ok(Self { motion, m: param.m, lambda, k: jp.quarter_period(), jp, s0, e })
    }

    /// Period of the argument s: 4K (libration), 2K (rotation), ∞ (separatrix).
    #[inline(always)]
    fn period_s(&self) -> f64 {
        match self.motion {
            PlanarMotion::Libration => 4.0 * self.k,
            PlanarMotion::Rotation => 2.0 * self.k,
            PlanarMotion::Separatrix => f64::INFINITY,
        }
    }

    /// Period of the motion in τ (swing or revolution); ∞ on the separatrix.
    pub fn period_tau(&self) -> f64 {
        self.period_s() / self.lambda
    }

    /// The state at dimensionless time τ after the start (inlined into the dispatched callers of
    /// [`super::ExactSolution`]).
    #[inline(always)]
    pub fn at(&self, tau: f64) -> Result<UnitState> {
        let s = self.lambda * tau + self.s0;
        let period = self.period_s();
        let r = if period.is_finite() { (-period).mul_add(crate::isa::round(s / period), s) } else { s };
        let jf = self.jp.eval(r)?;
        let (sn, cn, dn) = (jf.sn, jf.cn, jf.dn);
        let (h, u, h_tau, u_tau) = match self.motion {
            PlanarMotion::Libration | PlanarMotion::Separatrix => {
                let k = self.m.sqrt();
                let u = -1.0 + 2.0 * self.m * sn * sn;
                (2.0 * k * sn * dn, u, -u * 2.0 * k * cn, 4.0 * self.m * sn * cn * dn)
            }
            PlanarMotion::Rotation => {
                let u = sn * sn - cn * cn;
                let theta_tau = 2.0 * self.lambda * dn;
                (2.0 * sn * cn, u, -u * theta_tau, 2.0 * sn * cn * theta_tau)
            }
        };
        let e = self.e;
        let phi = if h < 0.0 { (-e[1]).atan2(-e[0]) } else { e[1].atan2(e[0]) };
        Ok(UnitState { x: [h * e[0], h * e[1], u], v: [h_tau * e[0], h_tau * e[1], u_tau], phi })
    }
}
