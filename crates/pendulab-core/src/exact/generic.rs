//! The exact flow of a spherical (J₃ ≠ 0) orbit, dimensionless (u = z/l, τ = ω₀t, g > 0; the
//! caller mirrors g < 0 and scales to SI):
//!
//! - T-4.2  u(τ) = u₁ + a sn²(s | m),  s = λτ + s₀,  a = u₂ − u₁,  m = a/(u₃ − u₁),  λ = √((u₃ − u₁)/2);
//!   s₀ = F(ϕ₀ | m) with sin ϕ₀ = ±√((u₀ − u₁)/a), cos ϕ₀ = √((u₂ − u₀)/a), the sign that of u̇₀.
//! - T-4.3  the z-period is 2K(m)/λ in τ, so s is reduced to r = s − 2KN, |r| ≤ K, and any t costs the same.
//! - T-4.4  φ = φ_low + N Δφ + Φ(r),  Φ(r) = (j/2λ)[Π(n₊; am r | m)/(1 − u₁) + Π(n₋; am r | m)/(1 + u₁)],
//!   n± = ±a/(1 ∓ u₁), φ_low the azimuth at the lowest point before the start.
//! - T-4.5  Δφ = (j/λ)[Π(n₊ | m)/(1 − u₁) + Π(n₋ | m)/(1 + u₁)].
//! - T-3.6  with ρ = √((1 + u)(1 − u)), 1 + u = (1 + u₁) + a sn², 1 − u = (1 − u₂) + a cn² (sums of
//!   non-negative terms, so ρ keeps its relative accuracy near the poles): x/l = (ρ cos φ, ρ sin φ, u),
//!   v/(lω₀) = ρ_τ e_ρ + (j/ρ) e_φ + u_τ e₃ with u_τ = 2aλ sn cn dn and ρ_τ = −u u_τ/ρ.
//!
//! Near-conical orbits (a → 0) need no special case: m, n± → 0 and Φ → jτ/(1 − u₁²).

use super::cubic::{Root, StartData};
use crate::elliptic::{ellippi_c, ellippi_sc, JacobiParam, Param};
use crate::error::Result;

/// A generic orbit: the roots and every constant of T-4.2 … T-4.5.
#[derive(Debug, Clone)]
pub struct Generic {
    /// Start data (u₀, κ, p±, j, u̇₀).
    pub start: StartData,
    /// Roots u₁ ≤ u₂ ≤ u₃ (anchored, see `cubic`).
    pub roots: [Root; 3],
    /// a = u₂ − u₁.
    pub a: f64,
    /// 1 + u₁ and 1 − u₁.
    pub one_plus_u1: f64,
    /// 1 − u₁.
    pub one_minus_u1: f64,
    /// 1 − u₂.
    pub one_minus_u2: f64,
    /// Parameter m = a/(u₃ − u₁) and its complement 1 − m = (u₃ − u₂)/(u₃ − u₁).
    pub m: f64,
    /// 1 − m.
    pub m1: f64,
    /// λ = √((u₃ − u₁)/2).
    pub lambda: f64,
    /// Characteristics n₊ = a/(1 − u₁), n₋ = −a/(1 + u₁).
    pub n_plus: f64,
    /// n₋.
    pub n_minus: f64,
    /// 1 − n₊ = (1 − u₂)/(1 − u₁).
    pub n1_plus: f64,
    /// 1 − n₋ = (1 + u₂)/(1 + u₁).
    pub n1_minus: f64,
    /// m with its accurate complement.
    pub param: Param,
    /// K(m).
    pub k: f64,
    /// The Jacobi functions at this m (K in double-double).
    pub jp: JacobiParam,
    /// Azimuthal advance per z-period Δφ (T-4.5) \[rad\].
    pub delta_phi: f64,
    /// Start argument s₀ ∈ [−K, K].
    pub s0: f64,
    /// Azimuth at the lowest point preceding the start, φ₀ − Φ(s₀) \[rad\].
    pub phi_low: f64,
}

/// Position and velocity in units of l and lω₀, and the azimuth φ.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct UnitState {
    /// x/l.
    pub x: [f64; 3],
    /// v/(lω₀).
    pub v: [f64; 3],
    /// Continuous azimuth φ \[rad\].
    pub phi: f64,
}

impl Generic {
    /// Sets up the orbit through a start with azimuth `phi0` \[rad\] (requires j ≠ 0). Errors only if
    /// the start data are not finite.
    pub fn new(start: StartData, phi0: f64) -> Result<Self> {
        let roots = start.roots();
        let [u1, u2, u3] = roots;
        let a = start.diff(u2, u1).max(0.0);
        let b = start.diff(u3, u1);
        let m1 = (start.diff(u3, u2) / b).clamp(0.0, 1.0);
        let m = (a / b).clamp(0.0, 1.0);
        let lambda = (0.5 * b).sqrt();
        let one_plus_u1 = start.one_plus(u1);
        let one_minus_u1 = 2.0 - one_plus_u1;
        let one_minus_u2 = start.one_minus(u2);
        let n_plus = a / one_minus_u1;
        let n_minus = -a / one_plus_u1;
        // complements 1 − n± = (1 ∓ u₂)/(1 ∓ u₁): n₋ ≤ 0 and n₊ ≤ ½ have no cancellation in 1 − n (and
        // stay consistent with n when 1 + u₁ is tiny: near-planar orbits skim the pole, n₋ → −∞);
        // n₊ > ½ (the orbit reaches up close to the top) takes it from the anchored differences.
        let n1_plus = if n_plus <= 0.5 { 1.0 - n_plus } else { one_minus_u2 / one_minus_u1 };
        let n1_minus = 1.0 - n_minus;
        let param = Param::with_complement(m, m1).unwrap_or(Param { m, m1: 1.0 - m });
        let jp = JacobiParam::with_complement(param);
        let k = jp.quarter_period();
        let coef = start.j / lambda;
        let delta_phi = coef
            * (ellippi_c(n_plus, n1_plus, param)? / one_minus_u1
                + ellippi_c(n_minus, n1_minus, param)? / one_plus_u1);
        // Start argument from sn₀², cn₀² (both from anchored differences) and the sign of u̇₀.
        let (below, above) = (-start.from_start(u1), start.from_start(u2));
        let (sn0, cn0) = if a > 0.0 {
            let sn0 = (below.max(0.0) / a).sqrt();
            (if start.udot < 0.0 { -sn0 } else { sn0 }, (above.max(0.0) / a).sqrt())
        } else {
            (0.0, 1.0)
        };
        let s0 = super::amplitude_argument(sn0, cn0, param, k)?;
        let mut g = Self {
            start,
            roots,
            a,
            one_plus_u1,
            one_minus_u1,
            one_minus_u2,
            m,
            m1,
            lambda,
            n_plus,
            n_minus,
            n1_plus,
            n1_minus,
            param,
            k,
            jp,
            delta_phi,
            s0,
            phi_low: 0.0,
        };
        g.phi_low = phi0 - g.phi_partial(sn0, cn0)?;
        Ok(g)
    }

    /// Φ of T-4.4 at the amplitude ϕ ∈ [−π/2, π/2] with sin ϕ = `sn`, cos ϕ = `cn` ≥ 0 (given as sn and
    /// cn, not ϕ: at the top turning point ϕ = ±π/2, where an orbit passing close to the top pole has
    /// n₊ → 1 and Φ varies like 1/cn², fl(ϕ) would cost the start's azimuth 1e-8 rad).
    #[inline(always)]
    fn phi_partial(&self, sn: f64, cn: f64) -> Result<f64> {
        let (sn, cn) = (sn.clamp(-1.0, 1.0), cn.max(0.0));
        Ok(0.5 * self.start.j / self.lambda
            * (ellippi_sc(self.n_plus, self.n1_plus, sn, cn, self.param)? / self.one_minus_u1
                + ellippi_sc(self.n_minus, self.n1_minus, sn, cn, self.param)? / self.one_plus_u1))
    }

    /// The state at dimensionless time τ after the start (inlined into the dispatched callers of
    /// [`super::ExactSolution`]).
    #[inline(always)]
    pub fn at(&self, tau: f64) -> Result<UnitState> {
        let s = self.lambda * tau + self.s0;
        let period = 2.0 * self.k;
        let n = crate::isa::round(s / period);
        let r = (-period).mul_add(n, s);
        let jf = self.jp.eval(r)?;
        let (sn, cn, dn) = (jf.sn, jf.cn, jf.dn);
        let sn2 = sn * sn;
        let one_plus_u = self.one_plus_u1 + self.a * sn2;
        let one_minus_u = self.one_minus_u2 + self.a * cn * cn;
        let u = if one_plus_u < one_minus_u { one_plus_u - 1.0 } else { 1.0 - one_minus_u };
        let rho = (one_plus_u * one_minus_u).sqrt();
        let u_tau = 2.0 * self.a * self.lambda * sn * cn * dn;
        let phi = self.phi_low + n * self.delta_phi + self.phi_partial(sn, cn)?;
        let (sp, cp) = phi.sin_cos();
        let rho_tau = -u * u_tau / rho;
        let w = self.start.j / rho;
        Ok(UnitState {
            x: [rho * cp, rho * sp, u],
            v: [rho_tau * cp - w * sp, rho_tau * sp + w * cp, u_tau],
            phi,
        })
    }

    /// The z-period in τ: 2K/λ.
    pub fn period_tau(&self) -> f64 {
        2.0 * self.k / self.lambda
    }
}
