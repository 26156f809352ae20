//! Incomplete Legendre integrals F(φ|m), E(φ|m), Π(n; φ|m) for every real amplitude φ
//! (DLMF 19.2.4, 19.2.5, 19.2.7; mpmath's `ellipf`, `ellipe(φ, m)`, `ellippi(n, φ, m)`).
//!
//! Continuation (DLMF 19.2.10): the integrands are even and π-periodic in θ, so every
//! integral X is odd in φ and X(φ + jπ) = X(φ) + 2j X_complete. The amplitude is written as
//! φ = jπ + r, |r| ≤ π/2, j = round(φ/π), and r is formed by Cody–Waite reduction with π split
//! into three parts P₁ + P₂ + P₃ (27, 27 and 53 bits): j·P₁ and j·P₂ are exact for |j| < 2²⁶
//! and φ − j·P₁ is exact (Sterbenz), so r carries an absolute error of a few ulp(r) plus
//! |j|·2⁻¹⁰⁷. For |φ| ≤ π/2 nothing is subtracted (r = φ exactly); this matters near φ = π/2
//! and m → 1, where F varies like 1/Δ. Then, with s = sin|r|, c = cos r,
//!
//!   X(φ) = 2j X_complete + sign(r) X_first(s, c)          (c ≥ 0)
//!   X(φ) = 2j X_complete + sign(r) (2 X_complete − X_first(s, −c))  (c < 0, |r| just above π/2)
//!
//! with X_first the Carlson forms of `kernel.rs`; 2jK uses the double-double K.
//!
//! Accuracy (see testdata/README.md): a few ulp for |φ| ≤ π/2; beyond, the reduction error
//! is that of a relative change of φ by an ulp, |φ| ε |∂X/∂φ| (∂F/∂φ = 1/Δ, ∂E/∂φ = Δ,
//! ∂Π/∂φ = 1/((1 − n sin²φ)Δ)), which is the conditioning of X at a float64 φ.
//!
//! m = 1: F and Π are ±∞ for |φ| ≥ π/2 (the integrand has a non-integrable 1/|cos θ|; the
//! integral diverges to +∞, which the sign of φ carries), finite for |φ| < π/2
//! (F = artanh(sin φ)); E(φ|1) = sin φ on [−π/2, π/2], continued with E(1) = 1.

use super::complete::{e_f64, k_dd, k_dd_complement, pi_f64};
use super::dd::Dd;
use super::kernel::{e_first, f_first, pi_first, pi_first_c, Param};
use super::{check_m, check_n};
use crate::error::{require_finite, Result};
use std::f64::consts::{FRAC_PI_2, PI};

/// π = P1 + P2 + P3 (Cody–Waite): P1 and P2 have 27 significant bits.
const P1: f64 = 3.141592651605606;
const P2: f64 = 1.9841871479187034e-09;
const P3: f64 = 1.1442377452219664e-17;

const PHI_ALLOWED: &str = "a finite amplitude φ [rad]";

/// φ = jπ + r with |r| ≤ π/2 (up to rounding); j = 0 and r = φ when |φ| ≤ π/2.
#[inline(always)]
pub(crate) fn reduce_pi(phi: f64) -> (f64, f64) {
    if phi.abs() <= FRAC_PI_2 {
        return (0.0, phi);
    }
    let j = crate::isa::round(phi / PI);
    (j, ((phi - j * P1) - j * P2) - j * P3)
}

/// The continuation of `first` (an integral over [0, θ] on the first quarter) to any φ, given
/// the complete integral.
#[inline(always)]
fn continued(phi: f64, complete: Dd, first: impl Fn(f64, f64) -> f64) -> f64 {
    let (j, r) = reduce_pi(phi);
    let s = r.abs().sin();
    let c = r.cos();
    let v = if c >= 0.0 { first(s, c) } else { 2.0 * complete.hi - first(s, -c) };
    let v = if r < 0.0 { -v } else { v };
    if j == 0.0 {
        return v;
    }
    let tj = 2.0 * j;
    tj * complete.hi + (tj * complete.lo + v)
}

/// Incomplete elliptic integral of the first kind F(φ|m) = ∫₀^φ dθ/√(1 − m sin²θ)
/// (DLMF 19.2.4), any real φ, parameter m = k².
///
/// Odd in φ; F(φ + jπ|m) = F(φ|m) + 2jK(m). At m = 1: artanh(sin φ) for |φ| < π/2 and
/// ±∞ for |φ| ≥ π/2 (the integral diverges). F(φ|0) = φ exactly.
///
/// # Errors
/// [`crate::Error::InvalidParameter`] unless 0 ≤ m ≤ 1 and φ is finite.
pub fn ellipf(phi: f64, m: f64) -> Result<f64> {
    let m = check_m(m)?;
    let phi = require_finite("phi", phi, PHI_ALLOWED)?;
    if m == 0.0 || phi == 0.0 {
        return Ok(phi);
    }
    let p = Param::new(m);
    if m == 1.0 {
        return Ok(if phi.abs() <= FRAC_PI_2 {
            f_first(p, phi.abs().sin(), phi.cos()).copysign(phi)
        } else {
            f64::INFINITY.copysign(phi)
        });
    }
    let k = if phi.abs() > FRAC_PI_2 { k_dd(m) } else { Dd { hi: 0.0, lo: 0.0 } };
    Ok(continued(phi, k, |s, c| f_first(p, s, c)))
}

/// Incomplete elliptic integral of the second kind E(φ|m) = ∫₀^φ √(1 − m sin²θ) dθ
/// (DLMF 19.2.5), any real φ, parameter m = k² (mpmath's `ellipe(φ, m)`).
///
/// Odd in φ; E(φ + jπ|m) = E(φ|m) + 2jE(m). Finite for every φ, also at m = 1.
///
/// # Errors
/// [`crate::Error::InvalidParameter`] unless 0 ≤ m ≤ 1 and φ is finite.
pub fn ellipe_inc(phi: f64, m: f64) -> Result<f64> {
    let m = check_m(m)?;
    let phi = require_finite("phi", phi, PHI_ALLOWED)?;
    if m == 0.0 || phi == 0.0 {
        return Ok(phi);
    }
    let p = Param::new(m);
    let e = if phi.abs() > FRAC_PI_2 { e_f64(m) } else { 0.0 };
    Ok(continued(phi, Dd { hi: e, lo: 0.0 }, |s, c| e_first(p, s, c)))
}

/// Incomplete elliptic integral of the third kind
/// Π(n; φ|m) = ∫₀^φ dθ / ((1 − n sin²θ)√(1 − m sin²θ)) (DLMF 19.2.7; mpmath's
/// `ellippi(n, φ, m)`), any real φ, characteristic n < 1, parameter m = k².
///
/// Odd in φ; Π(n; φ + jπ|m) = Π(n; φ|m) + 2jΠ(n|m). At m = 1 finite for |φ| < π/2 and ±∞
/// beyond. Accurate for n → −∞ (Π ~ atan(√(1−n) tan φ)/√(1−n)) and n → 1. Π(0; φ|m) is
/// exactly [`ellipf`]`(φ, m)`.
///
/// # Errors
/// [`crate::Error::InvalidParameter`] unless 0 ≤ m ≤ 1, n is finite with n < 1, and φ is
/// finite.
pub fn ellippi_inc(n: f64, phi: f64, m: f64) -> Result<f64> {
    let n = check_n(n)?;
    let m = check_m(m)?;
    let phi = require_finite("phi", phi, PHI_ALLOWED)?;
    if n == 0.0 {
        return ellipf(phi, m);
    }
    if phi == 0.0 {
        return Ok(phi);
    }
    let p = Param::new(m);
    if m == 1.0 {
        return Ok(if phi.abs() <= FRAC_PI_2 {
            pi_first(n, p, phi.abs().sin(), phi.cos()).copysign(phi)
        } else {
            f64::INFINITY.copysign(phi)
        });
    }
    let pc = if phi.abs() > FRAC_PI_2 { pi_f64(n, m) } else { 0.0 };
    Ok(continued(phi, Dd { hi: pc, lo: 0.0 }, |s, c| pi_first(n, p, s, c)))
}

/// F(φ|m) for any real φ from m with its complement ([`Param::with_complement`]); m′ = 0 as in
/// [`ellipf`] at m = 1.
///
/// # Errors
/// [`crate::Error::InvalidParameter`] unless φ is finite.
pub fn ellipf_c(phi: f64, p: Param) -> Result<f64> {
    let phi = require_finite("phi", phi, PHI_ALLOWED)?;
    if p.m == 0.0 || phi == 0.0 {
        return Ok(phi);
    }
    if p.m1 == 0.0 {
        return ellipf(phi, 1.0);
    }
    let k = if phi.abs() > FRAC_PI_2 {
        k_dd_complement(Dd { hi: p.m1, lo: 0.0 })
    } else {
        Dd { hi: 0.0, lo: 0.0 }
    };
    Ok(continued(phi, k, |s, c| f_first(p, s, c)))
}

/// Π(n; φ|m) for any real φ from n with its complement n′ = 1 − n and m with m′
/// ([`Param::with_complement`]), accurate as n → 1 and m → 1 (see [`super::ellippi_c`]).
///
/// # Errors
/// [`crate::Error::InvalidParameter`] unless φ is finite, n < 1, n′ > 0 and n + n′ = 1 within
/// 4 ulp of max(1, |n|). Inlined into its caller (the exact solution's dispatched loops, [`crate::isa`]).
#[inline(always)]
pub fn ellippi_inc_c(n: f64, n1: f64, phi: f64, p: Param) -> Result<f64> {
    let (n, n1) = super::check_n_pair(n, n1)?;
    let phi = require_finite("phi", phi, PHI_ALLOWED)?;
    if phi == 0.0 {
        return Ok(phi);
    }
    if p.m1 == 0.0 {
        return Ok(if phi.abs() <= FRAC_PI_2 {
            pi_first_c(n, n1, p, phi.abs().sin(), phi.cos()).copysign(phi)
        } else {
            f64::INFINITY.copysign(phi)
        });
    }
    let complete = if phi.abs() > FRAC_PI_2 { pi_first_c(n, n1, p, 1.0, 0.0) } else { 0.0 };
    Ok(continued(phi, Dd { hi: complete, lo: 0.0 }, |s, c| pi_first_c(n, n1, p, s, c)))
}

/// Π(n; ϕ|m) for |ϕ| ≤ π/2 given by `s` = sin ϕ and `c` = cos ϕ ≥ 0 rather than by ϕ, with n′ = 1 − n
/// and m′ as in [`ellippi_inc_c`]. Next to ϕ = ±π/2 the float ϕ fixes c only to ulp(π/2) = 2e-16
/// absolute, and for n → 1 Π varies like 1/(c² + n′s²) there (1e16 for c² ≈ n′ ≈ 1e-17): an orbit
/// passing 1e-8 l from the top pole lost 1e-8 rad of its azimuth that way. Here c keeps its own
/// relative accuracy.
///
/// # Errors
/// [`crate::Error::InvalidParameter`] unless s, c are finite with |s| ≤ 1 and c ≥ 0 (and n, n′ as in
/// [`ellippi_inc_c`]).
#[inline(always)]
pub fn ellippi_sc(n: f64, n1: f64, s: f64, c: f64, p: Param) -> Result<f64> {
    let (n, n1) = super::check_n_pair(n, n1)?;
    let s = require_finite("s", s, "sin ϕ: finite, |s| ≤ 1")?;
    let c = require_finite("c", c, "cos ϕ: finite, ≥ 0")?;
    if s.abs() > 1.0 {
        return Err(crate::Error::InvalidParameter { name: "s", value: s, allowed: "sin ϕ: |s| ≤ 1" });
    }
    if c < 0.0 {
        return Err(crate::Error::InvalidParameter {
            name: "c", value: c, allowed: "cos ϕ ≥ 0 (|ϕ| ≤ π/2)"
        });
    }
    if s == 0.0 {
        return Ok(s);
    }
    if p.m1 == 0.0 && c == 0.0 {
        return Ok(f64::INFINITY.copysign(s));
    }
    Ok(pi_first_c(n, n1, p, s.abs(), c).copysign(s))
}

/// F(ϕ|m) for |ϕ| ≤ π/2 given by `s` = sin ϕ and `c` = cos ϕ ≥ 0 (normalised here), m with m′ as in
/// [`ellipf_c`]: like [`ellippi_sc`], c keeps its relative accuracy next to ϕ = ±π/2, where
/// ∂F/∂ϕ = 1/√(c² + m′s²) reaches 1/k′ (a start next to the separatrix, m′ = 5e-16, lost 6e-9 of its
/// argument to fl(ϕ)). +∞ (sign of s) at c = 0 when m = 1.
///
/// # Errors
/// [`crate::Error::InvalidParameter`] unless s, c are finite, c ≥ 0 and (s, c) ≠ (0, 0).
pub fn ellipf_sc(s: f64, c: f64, p: Param) -> Result<f64> {
    let s = require_finite("s", s, "sin ϕ: finite")?;
    let c = require_finite("c", c, "cos ϕ: finite, ≥ 0")?;
    let r = s.hypot(c);
    if c < 0.0 || r == 0.0 {
        return Err(crate::Error::InvalidParameter {
            name: "c",
            value: c,
            allowed: "cos ϕ ≥ 0 (|ϕ| ≤ π/2), with sin ϕ and cos ϕ not both 0",
        });
    }
    let (s, c) = (s / r, c / r);
    if s == 0.0 {
        return Ok(s);
    }
    if p.m1 == 0.0 && c == 0.0 {
        return Ok(f64::INFINITY.copysign(s));
    }
    Ok(f_first(p, s.abs(), c).copysign(s))
}
