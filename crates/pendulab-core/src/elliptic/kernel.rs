//! Legendre's three integrals on the first quarter, 0 ≤ θ ≤ π/2, as Carlson symmetric forms
//! written so that no two terms of opposite sign are added. The amplitude enters as s = sin θ
//! and c = cos θ (both ≥ 0), so that callers can pass exact values (s = 1, c = 0 gives the
//! complete integrals) and the distance to π/2 is never formed by a subtraction.
//!
//! With Δ² = 1 − m s², evaluated as c² + m′s² (m′ = 1 − m) when m s² > ½:
//!
//! - F(θ|m) = s R_F(c², Δ², 1)                                              (DLMF 19.25.5)
//! - E(θ|m) = m′ s R_F(c², Δ², 1) + (m m′/3) s³ R_D(c², 1, Δ²) + m s c/Δ        (DLMF 19.25.10)
//!   — three positive terms. The textbook form s R_F − (m/3) s³ R_D(c², Δ², 1) (DLMF 19.25.9)
//!   loses a factor K/E (≈ 15 at m = 1 − 10⁻¹²) to cancellation near θ = π/2, m → 1.
//!   At m = 1 it reduces to E = s.
//! - Π(n; θ|m) = s R_F(c², Δ², 1) + (n/3) s³ R_J(c², Δ², 1, p), p = 1 − n s²    (DLMF 19.25.14)
//!   for n ≥ −½; p is evaluated as c² + (1 − n) s² when n s² > ½, so n → 1 loses nothing.
//!   For n < 0 the two terms have opposite signs and for n → −∞ both grow like R_F while Π
//!   falls like 1/√(−n) (−10¹⁰ would lose ten digits). For n < −½ the p ↔ q transformation of
//!   R_J (DLMF 19.21.12 with z = 1 as the distinguished variable: (p − 1)(q − 1) = (c² − 1)(Δ² − 1))
//!   gives the cancellation-free form
//!   Π(n; θ|m) = s R_C(c²Δ², p q) − (m s³/(3n)) R_J(c², Δ², 1, q),  q = 1 − m s²/n,
//!   both terms positive, with the gap p q − c²Δ² = s²(1 − n)(1 − m/n) formed exactly as a product.
//!   (Derivation: insert (p − 1)R_J(p) + (q − 1)R_J(q) = 3R_F − 3R_C(c²Δ², pq) into DLMF 19.25.14.
//!   Checked against mpmath to 1e-40 at n = −10¹⁰, −10³, −3, −0.2.)
//!
//! Preconditions (callers check): 0 ≤ m ≤ 1, n < 1, s, c ≥ 0 with s² + c² = 1 (to rounding),
//! and not (m = 1 and c = 0), where F and Π are infinite.

use super::carlson::{rc_gap, rd, rf, rj};

/// The parameter m and its complement m′ = 1 − m. `Param::new` forms m′ by subtraction (exact for
/// m ≥ ½, Sterbenz, but then m′ carries the absolute rounding error of m, relative ε/m′);
/// [`Param::with_complement`] takes an m′ computed to full relative accuracy by the caller (e.g.
/// from differences of roots), which is what keeps K, F, Π accurate as m → 1.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Param {
    /// m = k².
    pub m: f64,
    /// m′ = 1 − m.
    pub m1: f64,
}

impl Param {
    /// m′ = 1 − m by subtraction (unchecked).
    pub(crate) fn new(m: f64) -> Self {
        Param { m, m1: 1.0 - m }
    }

    /// m and its complement m′ given separately: 0 ≤ m ≤ 1, m′ ≥ 0 and m + m′ = 1 within 4 ulp.
    ///
    /// # Errors
    /// [`crate::Error::InvalidParameter`] naming `m` or `m1` otherwise.
    pub fn with_complement(m: f64, m1: f64) -> crate::error::Result<Self> {
        let m = super::check_m(m)?;
        if !((0.0..=1.0).contains(&m1) && (m + m1 - 1.0).abs() <= 4.0 * f64::EPSILON) {
            return Err(crate::error::Error::InvalidParameter {
                name: "m1",
                value: m1,
                allowed: "the complement m1 = 1 − m must lie in [0, 1] and agree with 1 − m to 4 ulp",
            });
        }
        Ok(Param { m, m1 })
    }

    /// Δ² = 1 − m s² = c² + m′ s², whichever form has no cancellation.
    #[inline(always)]
    pub(crate) fn delta2(&self, s: f64, c: f64) -> f64 {
        let t = self.m * s * s;
        if t <= 0.5 {
            1.0 - t
        } else {
            c * c + self.m1 * s * s
        }
    }
}

/// Threshold below which Π uses the transformed (p ↔ q) Carlson form.
const N_TRANSFORM: f64 = -0.5;

/// F(θ|m) for s = sin θ, c = cos θ ≥ 0.
#[inline(always)]
pub(crate) fn f_first(p: Param, s: f64, c: f64) -> f64 {
    if s == 0.0 {
        return 0.0;
    }
    s * rf(c * c, p.delta2(s, c), 1.0)
}

/// E(θ|m) for s = sin θ, c = cos θ ≥ 0.
pub(crate) fn e_first(p: Param, s: f64, c: f64) -> f64 {
    if s == 0.0 {
        return 0.0;
    }
    if p.m1 == 0.0 {
        return s;
    }
    let d2 = p.delta2(s, c);
    let c2 = c * c;
    p.m1 * s * rf(c2, d2, 1.0) + (p.m * p.m1 / 3.0) * s * s * s * rd(c2, 1.0, d2) + p.m * s * c / d2.sqrt()
}

/// Π(n; θ|m) for s = sin θ, c = cos θ ≥ 0, n < 1.
pub(crate) fn pi_first(n: f64, p: Param, s: f64, c: f64) -> f64 {
    pi_first_c(n, 1.0 - n, p, s, c)
}

/// [`pi_first`] with the complement n′ = 1 − n given to full relative accuracy.
#[inline(always)]
pub(crate) fn pi_first_c(n: f64, n1: f64, p: Param, s: f64, c: f64) -> f64 {
    if s == 0.0 {
        return 0.0;
    }
    let d2 = p.delta2(s, c);
    let c2 = c * c;
    let s2 = s * s;
    if n < N_TRANSFORM {
        let q = 1.0 - p.m * s2 / n;
        let gap = s2 * n1 * (1.0 - p.m / n);
        s * rc_gap(c2 * d2, gap) - (p.m * s2 * s / (3.0 * n)) * rj(c2, d2, 1.0, q)
    } else {
        let f = s * rf(c2, d2, 1.0);
        if n == 0.0 {
            return f;
        }
        let ns2 = n * s2;
        let pp = if ns2 <= 0.5 { 1.0 - ns2 } else { c2 + n1 * s2 };
        f + (n / 3.0) * s2 * s * rj(c2, d2, 1.0, pp)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Where neither form cancels, the positive forms agree with the textbook ones
    /// (DLMF 19.25.9 for E, 19.25.14 for Π with n < −½), which checks their derivation.
    #[test]
    fn positive_forms_agree_with_textbook_forms() {
        for (m, theta) in [(0.3, 0.4), (0.5, 1.0), (0.9, 1.3), (1e-9, 0.7)] {
            let p = Param::new(m);
            let (s, c) = f64::sin_cos(theta);
            let d2 = p.delta2(s, c);
            let e_textbook = s * rf(c * c, d2, 1.0) - (m / 3.0) * s * s * s * rd(c * c, d2, 1.0);
            let e = e_first(p, s, c);
            assert!((e - e_textbook).abs() <= 8.0 * f64::EPSILON * e, "E: m={m} θ={theta}");
            for n in [-0.6, -2.0, -40.0] {
                let pp = 1.0 - n * s * s;
                let pi_textbook = s * rf(c * c, d2, 1.0) + (n / 3.0) * s * s * s * rj(c * c, d2, 1.0, pp);
                let pi = pi_first(n, p, s, c);
                let cancel = 1.0 + (n / 3.0 * s * s * s * rj(c * c, d2, 1.0, pp) / pi).abs();
                let tol = 8.0 * f64::EPSILON * pi * cancel;
                assert!((pi - pi_textbook).abs() <= tol, "Π: n={n} m={m} θ={theta}: {pi} vs {pi_textbook}");
            }
        }
    }

    /// Closed forms: F(θ|0) = θ, E(θ|1) = sin θ, Π(n; θ|0) = atan(√(1−n) tan θ)/√(1−n).
    #[test]
    fn closed_forms() {
        let theta: f64 = 0.9;
        let (s, c) = theta.sin_cos();
        assert!((f_first(Param::new(0.0), s, c) - theta).abs() <= 2.0 * f64::EPSILON);
        assert_eq!(e_first(Param::new(1.0), s, c), s);
        for n in [-1e10f64, -3.0, 0.5, 0.999] {
            let r = (1.0 - n).sqrt();
            let want = (r * theta.tan()).atan() / r;
            let got = pi_first(n, Param::new(0.0), s, c);
            assert!((got - want).abs() <= 8.0 * f64::EPSILON * want, "n={n}: {got} vs {want}");
        }
    }
}
