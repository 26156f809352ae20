//! Elliptic integrals and Jacobi elliptic functions for the exact solution (docs/theory.md §4–5:
//! T-4.2 uses sn and F, T-4.3 K, T-4.4 Π and am, T-4.5 Π(n|m)).
//!
//! ## Conventions
//! Parameter m = k² (as DLMF 19.2.4 and mpmath), characteristic n (Π has 1 − n sin²θ in the
//! denominator, mpmath's `ellippi(n, φ, m)`), amplitude φ in radians.
//!
//! | function | definition | domain |
//! | --- | --- | --- |
//! | [`ellipk`]`(m)` | K(m) = F(π/2\|m) | 0 ≤ m ≤ 1; K(1) = +∞ |
//! | [`ellipe`]`(m)` | E(m) = E(π/2\|m) | 0 ≤ m ≤ 1; E(1) = 1 |
//! | [`ellippi`]`(n, m)` | Π(n\|m) = Π(n; π/2\|m) | n < 1, 0 ≤ m ≤ 1; +∞ at m = 1 |
//! | [`ellipf`]`(φ, m)` | ∫₀^φ dθ/√(1 − m sin²θ) (DLMF 19.2.4) | any finite φ |
//! | [`ellipe_inc`]`(φ, m)` | ∫₀^φ √(1 − m sin²θ) dθ (DLMF 19.2.5) | any finite φ |
//! | [`ellippi_inc`]`(n, φ, m)` | ∫₀^φ dθ/((1 − n sin²θ)√(1 − m sin²θ)) (DLMF 19.2.7) | any finite φ, n < 1 |
//! | [`jacobi`]`(u, m)` | sn, cn, dn, am with F(am(u)\|m) = u (DLMF 22.16.1) | any finite u |
//! | [`am`]`(u, m)` | the amplitude alone, continuous in u | any finite u |
//!
//! The incomplete integrals are odd in φ and continued past ±π/2 by quasi-periodicity,
//! X(φ + jπ) = X(φ) + 2jX_complete (DLMF 19.2.10), so that Π(n; am(u)|m) is smooth in u as
//! T-4.4 needs. At m = 1, F and Π are +∞ for φ ≥ π/2 (−∞ for φ ≤ −π/2) because their
//! integrals diverge; E stays finite.
//!
//! ## Bad input
//! Every public function returns [`crate::Error::InvalidParameter`] (naming `m`, `n`, `phi`
//! or `u`; [`carlson_rd`]: `x`, `y`, `z`) for m < 0, m > 1,
//! n ≥ 1, non-finite n, φ or u, and NaN anywhere; it never panics and never returns NaN.
//! (m < 0 and n > 1 are meaningful elsewhere — imaginary modulus, principal values — but the
//! pendulum never needs them.) Infinite results occur only where the integral diverges (K, F,
//! Π at m = 1, see above) or the true value overflows.
//!
//! ## Method
//! All integrals reduce to Carlson's symmetric forms R_F, R_D, R_J, R_C (`carlson.rs`, duplication
//! algorithm, Carlson 1995), in forms chosen so that no terms cancel (`kernel.rs`), and K to a
//! double-double AGM (`complete.rs`, `dd.rs`); the Jacobi functions invert F (`jacobi.rs`).
//! We do not use the `ellip` crate (1.2.3) that the design notes named. Run over the golden set of
//! `tests/elliptic.rs`, its complete integrals are fine (≤ 4 ulp), but its incomplete E
//! loses 37 ulp* at φ = 1.5, m = 1 − 10⁻¹² (the cancelling form DLMF 19.25.9), its
//! Π(1 − 10⁻¹²; 1.5|1) is wrong in the fourth digit, at m = 1 it returns errors for F and Π
//! at φ = fl(π/2) (finite: F = 38.03), its Π reduces φ by `φ mod π/2` in f64
//! (Π(−10¹⁰; 10⁴|0.5) is 3·10⁵ ulp off), its R_F stops after 11 duplication steps, and every
//! call returns `Result<_, &str>`. Owning the duplication code (~200 lines) lets every
//! formula be chosen for accuracy and tested against mpmath.
//!
//! ## Accuracy
//! Measured against 40-digit mpmath values at float64 arguments
//! (`testdata/elliptic_golden.json`, `tests/elliptic.rs`; table in `testdata/README.md`).
//! Asserted bounds: K 1 ulp (correctly rounded in every case seen), E 4 ulp, Π(n|m) 8 ulp;
//! for |φ| ≤ π/2 F and E 4 ulp, Π 8 ulp. Beyond π/2 and for the Jacobi functions the unit is
//! ulp*, which also allows ulp(x)|∂f/∂x| for the large argument x = φ or u (the change that
//! moving x by one ulp causes): F 4, E and Π 8, sn, cn, dn, am 4 ulp* (≤ 3 measured).

mod carlson;
mod complete;
pub(crate) mod dd;
mod jacobi;
mod kernel;
mod legendre;

pub use complete::{ellipe, ellipk, ellipk_c, ellippi, ellippi_c};
pub use jacobi::{am, jacobi, Jacobi, JacobiParam};
pub use kernel::Param;
pub use legendre::{ellipe_inc, ellipf, ellipf_c, ellipf_sc, ellippi_inc, ellippi_inc_c, ellippi_sc};

use crate::error::{Error, Result};

/// Checks 0 ≤ m ≤ 1 (rejects NaN).
pub(crate) fn check_m(m: f64) -> Result<f64> {
    if (0.0..=1.0).contains(&m) {
        Ok(m)
    } else {
        Err(Error::InvalidParameter {
            name: "m",
            value: m,
            allowed: "the parameter m = k² must satisfy 0 ≤ m ≤ 1",
        })
    }
}

/// Checks n < 1 with its complement n′ = 1 − n > 0 consistent to 4 ulp of max(1, |n|).
/// (n may round to 1 when n′ is tiny; n′ > 0 keeps the integral finite.)
#[inline(always)]
pub(crate) fn check_n_pair(n: f64, n1: f64) -> Result<(f64, f64)> {
    let n = if n == 1.0 { n } else { check_n(n)? };
    if n1 > 0.0 && n1.is_finite() && (n + n1 - 1.0).abs() <= 4.0 * f64::EPSILON * n.abs().max(1.0) {
        Ok((n, n1))
    } else {
        Err(Error::InvalidParameter {
            name: "n1",
            value: n1,
            allowed: "the complement n1 = 1 − n must be > 0 and agree with 1 − n to 4 ulp",
        })
    }
}

/// Checks that n is finite and n < 1 (rejects NaN).
#[inline(always)]
pub(crate) fn check_n(n: f64) -> Result<f64> {
    if n.is_finite() && n < 1.0 {
        Ok(n)
    } else {
        Err(Error::InvalidParameter {
            name: "n",
            value: n,
            allowed: "the characteristic n must be finite and n < 1 (Π diverges at n = 1)",
        })
    }
}

/// Carlson's symmetric integral R_D(x, y, z) = (3/2)∫₀^∞ dt / ((t + z)√((t + x)(t + y)(t + z)))
/// (DLMF 19.16.5) for x, y ≥ 0 with at most one of them zero and z > 0. Used for
/// K − E = (m/3) R_D(0, 1 − m, 1) (DLMF 19.25.1) without cancellation at small m.
///
/// # Errors
/// [`crate::Error::InvalidParameter`] outside that domain (NaN included).
pub fn carlson_rd(x: f64, y: f64, z: f64) -> Result<f64> {
    let ok =
        x >= 0.0 && y >= 0.0 && x + y > 0.0 && z > 0.0 && x.is_finite() && y.is_finite() && z.is_finite();
    if ok {
        Ok(carlson::rd(x, y, z))
    } else {
        let (name, value) = if !(z > 0.0 && z.is_finite()) {
            ("z", z)
        } else if x.is_nan() || x < 0.0 {
            ("x", x)
        } else {
            ("y", y)
        };
        Err(Error::InvalidParameter {
            name,
            value,
            allowed: "R_D(x, y, z) needs finite x, y ≥ 0 (not both 0) and z > 0",
        })
    }
}
