//! Jacobi elliptic functions sn, cn, dn and the amplitude am for real u and 0 ≤ m ≤ 1
//! (DLMF 22.2, 22.16.1), by inverting F with Carlson's R_F.
//!
//! am(u|m) = φ is defined by F(φ|m) = u (DLMF 22.16.1) and is continuous and increasing:
//! am(u + 2K) = am(u) + π (DLMF 22.16.2); sn = sin am, cn = cos am, dn = √(1 − m sn²)
//! (DLMF 22.16.11–12). Method:
//!
//! 1. Special parameters: m = 0 gives sin u, cos u, 1, u; m = 1 gives tanh u, sech u, sech u,
//!    gd u = atan(sinh u) (DLMF 22.5.3), with sech u = 2e^{−|u|}/(1 + e^{−2|u|}).
//! 2. Reduction by the half period 2K (DLMF 22.4.3: sn, cn change sign, dn does not):
//!    u = 2jK + x, j = round(u/2K), |x| ≤ K. K is the double-double AGM value (`complete.rs`),
//!    j·2K_hi is split exactly by one fused multiply-add and u − j·2K_hi is exact (Sterbenz),
//!    so x is accurate to a few ulp(K) for any |u| < 2⁶⁰ — not only to |u|·ε, as a 53-bit K
//!    would give. (For |u| ≥ 2⁶⁰, where ulp(u) exceeds 2⁸ and u's phase is meaningless, u is
//!    first reduced exactly modulo the float 4K_hi, so the result stays finite.)
//! 3. On [0, K] the amplitude is found in two regions split at φ = π/4 (x = F(π/4|m)), so
//!    that the smaller of sin φ, cos φ is always computed from a small angle and keeps its
//!    relative accuracy — also for m → 1, where cn and dn are tiny over most of [0, K]:
//!    - x ≤ F(π/4|m): solve F(φ|m) = x for φ ∈ [0, π/4]; sn = sin φ, cn = cos φ,
//!      dn = √(1 − m sin²φ). F′ = 1/Δ, F″ = m sin φ cos φ/Δ³; start from the inverted Maclaurin
//!      series φ₀ = x − (m/6)x³ + (m/30 + m²/120)x⁵.
//!    - x > F(π/4|m): solve for the co-amplitude χ = π/2 − φ ∈ [0, π/4] from the distance to
//!      the quarter period, w = K − x (formed in double-double):
//!      G(χ) := K − F(π/2 − χ|m) = ∫₀^χ dψ/√(m′cos²ψ + sin²ψ) = sin χ · R_F(m′cos²χ, m′cos²χ + sin²χ, m′)
//!      (substitute t = sin ψ, then DLMF 19.25.5 with homogeneity of R_F). Then sn = cos χ,
//!      cn = sin χ, dn = √(sin²χ + m′cos²χ), am = π/2 − χ. G′ = 1/√(m′cos²χ + sin²χ) is 1/k′
//!      at χ = 0, so G is solved in the stretched variable y = asinh(tan χ/k′), i.e.
//!      χ = atan(k′ sinh y): dG/dy = cos χ ∈ [0.7, 1] and d²G/dy² = −sin χ cos χ Δ, so the
//!      iteration is uniform in m′ (G ≤ y ≤ G + χ²/4 roughly); start y₀ = w. The update is applied to χ directly
//!      (tan χ(y − δ) = (sin χ cosh δ − Δ sinh δ)/cos χ), never through the large y.
//!      The residual is G(χ) − w when w < x and x − F(π/2 − χ|m) (F at s = cos χ, c = sin χ)
//!      otherwise, so that its absolute error is a few ulp of min(x, w).
//!
//!    Both use Halley's iteration (cubic) and stop after a step below 2⁻²⁴ relative (in y:
//!    2⁻²⁴ min(1, |y|)), whose successor would be of order 2⁻⁷²; 1–3 steps in practice.
//! 4. Signs: sn and am are odd in x, cn and dn even; then the parity of j, and
//!    am = jπ + am(x) with π in two parts.
//!
//! Accuracy (testdata/README.md): at most 3 ulp* measured, where ulp* allows, besides an ulp
//! of the value, the change ulp(u)|∂f/∂u| that moving u by one ulp causes. That allowance is
//! where the few-ulp error of the F-evaluation in the final residual shows (it maps to the
//! amplitude through dφ/dx = dn), and where cn has its zeros. No step loses more: the
//! reduction costs a few ulp(K) ≤ ulp(u), and the residual is taken from the smaller of
//! x and K − x.

use super::complete::{k_dd, k_dd_complement};
use super::dd::Dd;
use super::kernel::{f_first, Param};
use super::{carlson::rf, check_m};
use crate::error::{require_finite, Result};
use std::f64::consts::{FRAC_PI_2, PI};

/// π − fl(π).
const PI_LO: f64 = 1.2246467991473532e-16;
/// π/2 − fl(π/2).
const FRAC_PI_2_LO: f64 = 6.123233995736766e-17;
/// Halley stops after a relative step below this (2⁻²⁴).
const STEP_TOL: f64 = 5.960464477539063e-8;
/// Iteration cap (never reached for admissible input; bounds the work for any input).
const MAX_STEPS: usize = 12;
/// Beyond this |u| the argument is first reduced modulo the float 4K (2⁶⁰).
const HUGE_U: f64 = 1.152921504606847e18;

/// The Jacobi elliptic functions at one argument u (DLMF 22.2.4, 22.16.1).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Jacobi {
    /// sn(u|m) = sin am(u|m).
    pub sn: f64,
    /// cn(u|m) = cos am(u|m).
    pub cn: f64,
    /// dn(u|m) = √(1 − m sn²(u|m)) > 0 for m < 1.
    pub dn: f64,
    /// am(u|m), continuous in u: am(u + 2K) = am(u) + π (rad).
    pub am: f64,
}

/// The Jacobi functions for one parameter m, with K(m) (double-double) and the region split
/// precomputed: evaluating many u at one m costs only the inversion.
#[derive(Debug, Clone, Copy)]
pub struct JacobiParam {
    p: Param,
    /// k′ = √(1 − m).
    kp: f64,
    /// K(m) as a double-double (+∞ at m = 1).
    k: Dd,
    /// F(π/4|m): where the co-amplitude region starts.
    split: f64,
}

impl JacobiParam {
    /// Precomputes K(m) and F(π/4|m) for 0 ≤ m ≤ 1.
    ///
    /// # Errors
    /// [`crate::Error::InvalidParameter`] unless 0 ≤ m ≤ 1 (NaN included).
    pub fn new(m: f64) -> Result<Self> {
        let m = check_m(m)?;
        let p = Param::new(m);
        if m == 1.0 {
            return Ok(JacobiParam { p, kp: 0.0, k: Dd { hi: f64::INFINITY, lo: 0.0 }, split: 0.0 });
        }
        let h = std::f64::consts::FRAC_1_SQRT_2;
        Ok(JacobiParam { p, kp: p.m1.sqrt(), k: k_dd(m), split: f_first(p, h, h) })
    }

    /// Like [`Self::new`] from m with its complement m′ given to full relative accuracy
    /// ([`Param::with_complement`]): K and the functions near the quarter period then keep their
    /// accuracy as m → 1, where 1 − m formed from m would lose it.
    pub fn with_complement(p: Param) -> Self {
        if p.m1 == 0.0 {
            return JacobiParam { p, kp: 0.0, k: Dd { hi: f64::INFINITY, lo: 0.0 }, split: 0.0 };
        }
        let h = std::f64::consts::FRAC_1_SQRT_2;
        JacobiParam {
            p,
            kp: p.m1.sqrt(),
            k: k_dd_complement(Dd { hi: p.m1, lo: 0.0 }),
            split: f_first(p, h, h),
        }
    }

    /// The parameter m = k².
    pub fn m(&self) -> f64 {
        self.p.m
    }

    /// The quarter period K(m) (+∞ at m = 1).
    pub fn quarter_period(&self) -> f64 {
        self.k.hi
    }

    /// sn, cn, dn and am at u. Inlined into its caller with the inversion (so that a caller
    /// dispatched by [`crate::isa`] gets it compiled for its instruction set).
    ///
    /// # Errors
    /// [`crate::Error::InvalidParameter`] if u is not finite.
    #[inline(always)]
    pub fn eval(&self, u: f64) -> Result<Jacobi> {
        let u = require_finite("u", u, "a finite argument u (dimensionless)")?;
        Ok(self.eval_finite(u))
    }

    /// [`Self::eval`] for finite u.
    #[inline(always)]
    fn eval_finite(&self, u: f64) -> Jacobi {
        let m = self.p.m;
        if m == 0.0 {
            return Jacobi { sn: u.sin(), cn: u.cos(), dn: 1.0, am: u };
        }
        // m = 1 means m′ = 0: with its complement given (`with_complement`), a float m that rounds
        // to 1 may still have m′ = 5e-17 > 0, a finite K ≈ 20 and cn, dn ≈ k′ sinh(K − u) near K —
        // not sech u (an orbit next to the top read cn = 4e-9 for 6e-10 there).
        if self.p.m1 == 0.0 {
            let t = (-u.abs()).exp();
            let sech = 2.0 * t / (1.0 + t * t);
            return Jacobi { sn: u.tanh(), cn: sech, dn: sech, am: u.sinh().atan() };
        }
        if u.abs() >= HUGE_U {
            return self.eval_huge(u);
        }
        let two_k = 2.0 * self.k.hi;
        let j = crate::isa::round(u / two_k);
        let x = if j == 0.0 {
            u
        } else {
            let hi = j * two_k;
            let lo = j.mul_add(two_k, -hi); // j·2K_hi = hi + lo exactly
            ((u - hi) - lo) - j * (2.0 * self.k.lo)
        };
        let ax = x.abs();
        let (sn, cn, dn, am) = if ax <= self.split {
            let phi = self.amplitude(ax);
            let (s, c) = phi.sin_cos();
            (s, c, self.p.delta2(s, c).sqrt(), phi)
        } else {
            let w = (self.k.hi - ax) + self.k.lo;
            let chi = self.co_amplitude(ax, w);
            let (s, c) = chi.sin_cos();
            (c, s, (s * s + self.p.m1 * c * c).sqrt(), (FRAC_PI_2 - chi) + FRAC_PI_2_LO)
        };
        let (sn, am) = if x < 0.0 { (-sn, -am) } else { (sn, am) };
        let (sn, cn) = if j % 2.0 != 0.0 { (-sn, -cn) } else { (sn, cn) };
        let am = if j == 0.0 { am } else { j * PI + (j * PI_LO + am) };
        Jacobi { sn, cn, dn, am }
    }

    /// [`Self::eval_finite`] for |u| ≥ 2⁶⁰: u is first reduced exactly modulo the float 4K.
    #[cold]
    #[inline(never)]
    fn eval_huge(&self, u: f64) -> Jacobi {
        let four_k = 4.0 * self.k.hi;
        let rest = u % four_k; // exact
        let mut v = self.eval_finite(rest);
        v.am += (u - rest) / (2.0 * self.k.hi) * PI;
        v
    }

    /// φ ∈ [0, ~π/4] with F(φ|m) = x, for 0 ≤ x ≤ F(π/4|m).
    #[inline(always)]
    fn amplitude(&self, x: f64) -> f64 {
        let m = self.p.m;
        let x2 = x * x;
        let mut phi = x * (1.0 - x2 * (m / 6.0 - x2 * (m / 30.0 + m * m / 120.0)));
        for _ in 0..MAX_STEPS {
            let (s, c) = phi.sin_cos();
            let d = self.p.delta2(s, c).sqrt();
            let f = f_first(self.p, s, c) - x;
            let step = f * d / (1.0 - 0.5 * f * m * s * c / d);
            phi -= step;
            if step.abs() <= STEP_TOL * phi.abs() {
                break;
            }
        }
        phi
    }

    /// χ ∈ [~0, π/4] with F(π/2 − χ|m) = x, i.e. G(χ) = w = K − x (w may be slightly negative
    /// when rounding puts x just beyond K; then χ < 0, as it should). The residual is taken
    /// from whichever of x, w is smaller, so that its absolute error is a few ulp of min(x, w).
    #[inline(always)]
    fn co_amplitude(&self, x: f64, w: f64) -> f64 {
        let m1 = self.p.m1;
        let near_k = w < x;
        let mut y = w;
        let mut chi = (self.kp * y.sinh()).atan();
        for _ in 0..MAX_STEPS {
            let (s, c) = chi.sin_cos();
            let d2 = s * s + m1 * c * c;
            let d = d2.sqrt();
            let g = if near_k { s * rf(m1 * c * c, d2, m1) - w } else { x - f_first(self.p, c, s) };
            let step = (g / c) / (1.0 + 0.5 * g * s * d / c);
            // χ(y − δ) from χ(y) without forming y (≈ ln(2/k′) ≈ 20 for m → 1, whose ulp would
            // cost 3e-15 in χ): tan χ(y − δ) = (sin χ cosh δ − Δ sinh δ)/cos χ, because
            // k′ sinh y = tan χ and k′ cosh y = Δ/cos χ.
            chi = (s * step.cosh() - d * step.sinh()).atan2(c);
            y -= step;
            if step.abs() <= STEP_TOL * y.abs().min(1.0) {
                break;
            }
        }
        chi
    }
}

/// The Jacobi elliptic functions sn, cn, dn and the amplitude am at real u, parameter
/// 0 ≤ m ≤ 1 (DLMF 22.2, 22.16.1). am is continuous: am(u + 2K) = am(u) + π. At m = 0:
/// sin, cos, 1, u; at m = 1: tanh, sech, sech, gd (DLMF 22.5.3). For many u at one m use
/// [`JacobiParam`].
///
/// # Errors
/// [`crate::Error::InvalidParameter`] unless 0 ≤ m ≤ 1 and u is finite.
pub fn jacobi(u: f64, m: f64) -> Result<Jacobi> {
    JacobiParam::new(m)?.eval(u)
}

/// The Jacobi amplitude am(u|m), the inverse of F: F(am(u|m)|m) = u (DLMF 22.16.1),
/// continuous in u.
///
/// # Errors
/// [`crate::Error::InvalidParameter`] unless 0 ≤ m ≤ 1 and u is finite.
pub fn am(u: f64, m: f64) -> Result<f64> {
    Ok(jacobi(u, m)?.am)
}
