//! Carlson's symmetric elliptic integrals by the duplication algorithm (B. C. Carlson,
//! "Numerical computation of real or complex elliptic integrals", Numer. Algorithms 10 (1995)
//! 13–26; DLMF §19.36(i)), for real non-negative arguments:
//!
//! - R_F(x, y, z) = ½ ∫₀^∞ dt / √((t+x)(t+y)(t+z))                       (DLMF 19.16.1)
//! - R_D(x, y, z) = (3/2) ∫₀^∞ dt / (√((t+x)(t+y)) (t+z)^{3/2})            (DLMF 19.16.5)
//! - R_J(x, y, z, p) = (3/2) ∫₀^∞ dt / (√((t+x)(t+y)(t+z)) (t+p)), p > 0   (DLMF 19.16.2)
//! - R_C(x, y) = R_F(x, y, y) in closed form (DLMF 19.2.17–19.2.18)
//!
//! Duplication (DLMF 19.26.18): with λ = √x√y + √y√z + √z√x,
//! R_F(x, y, z) = R_F((x+λ)/4, (y+λ)/4, (z+λ)/4); the arguments approach their mean A_m
//! geometrically (×¼ per step). The iteration stops when 4⁻ᵐ Q < |A_m|, where
//! Q = c · max |A₀ − x_i|, and the remainder is a Taylor series in the normalised deviations
//! X = (A₀ − x)/(4ᵐ A_m), … (these use the original arguments, so no difference is formed
//! after the iteration):
//!
//! - R_F: the degree-7 series of DLMF 19.36.1,
//!   1 − E₂/10 + E₃/14 + E₂²/24 − 3E₂E₃/44 − 5E₂³/208 + 3E₃²/104 + E₂²E₃/16,
//!   E₂ = XY − Z², E₃ = XYZ, truncation error O(max|X|⁸), so c = (3r)^{−1/8};
//! - R_D and R_J: Carlson's degree-5 series (1995, eq. 2.13 and 2.19; DLMF 19.36.2),
//!   1 − 3E₂/14 + E₃/6 + 9E₂²/88 − 3E₄/22 − 9E₂E₃/52 + 3E₅/26, with c = (r/4)^{−1/6};
//!
//! where r = 2⁻⁵³ is the unit roundoff, so the truncation error is below r relative.
//! R_D and R_J add the sums 3 Σ 4⁻ᵐ/(√z_m (z_m + λ_m)) and 6 Σ 4⁻ᵐ R_C(1, 1 + e_m)/d_m with
//! d_m = (√p+√x)(√p+√y)(√p+√z), e_m = 4⁻³ᵐ δ/d_m², δ = (p−x)(p−y)(p−z) (Carlson 1995, §2).
//! All terms are positive for p > 0, so the results are accurate to a few ulp.
//!
//! These are crate-private building blocks: callers guarantee finite non-negative
//! arguments with at most one zero (R_F), x + y > 0 and z > 0 (R_D), and p > 0 (R_J).
//! Arguments in this module stay within [1e-33, 1e21], far from overflow and underflow.

/// (3r)^(−1/8), r = 2⁻⁵³: stopping constant of R_F.
const RF_C: f64 = 86.03666435637686;
/// (r/4)^(−1/6), r = 2⁻⁵³: stopping constant of R_D and R_J.
const RDJ_C: f64 = 574.7005687343988;
/// More steps than any admissible argument needs (about 10 for a spread of 1e30); a bound
/// so that NaN input cannot loop forever.
const MAX_STEPS: usize = 64;

/// R_F(x, y, z).
#[inline(always)]
pub(crate) fn rf(x: f64, y: f64, z: f64) -> f64 {
    let a0 = (x + y + z) / 3.0;
    let q = RF_C * (a0 - x).abs().max((a0 - y).abs()).max((a0 - z).abs());
    let (mut xm, mut ym, mut zm, mut a, mut f) = (x, y, z, a0, 1.0);
    for _ in 0..MAX_STEPS {
        if q < f * a.abs() {
            break;
        }
        let (sx, sy, sz) = (xm.sqrt(), ym.sqrt(), zm.sqrt());
        let lam = sx * (sy + sz) + sy * sz;
        xm = 0.25 * (xm + lam);
        ym = 0.25 * (ym + lam);
        zm = 0.25 * (zm + lam);
        a = 0.25 * (a + lam);
        f *= 4.0;
    }
    let xx = (a0 - x) / (f * a);
    let yy = (a0 - y) / (f * a);
    let zz = -(xx + yy);
    let e2 = xx * yy - zz * zz;
    let e3 = xx * yy * zz;
    let series = 1.0
        + e2 * (-0.1 + e2 / 24.0 - 3.0 * e3 / 44.0 - 5.0 * e2 * e2 / 208.0 + e2 * e3 / 16.0)
        + e3 * (1.0 / 14.0 + 3.0 * e3 / 104.0);
    series / a.sqrt()
}

/// The degree-5 series shared by R_D and R_J, in E₂ … E₅.
#[inline(always)]
fn series5(e2: f64, e3: f64, e4: f64, e5: f64) -> f64 {
    1.0 - 3.0 * e2 / 14.0 + e3 / 6.0 + 9.0 * e2 * e2 / 88.0 - 3.0 * e4 / 22.0 - 9.0 * e2 * e3 / 52.0
        + 3.0 * e5 / 26.0
}

/// R_D(x, y, z).
pub(crate) fn rd(x: f64, y: f64, z: f64) -> f64 {
    let a0 = (x + y + 3.0 * z) / 5.0;
    let q = RDJ_C * (a0 - x).abs().max((a0 - y).abs()).max((a0 - z).abs());
    let (mut xm, mut ym, mut zm, mut a, mut f) = (x, y, z, a0, 1.0);
    let mut sum = 0.0;
    for _ in 0..MAX_STEPS {
        if q < f * a.abs() {
            break;
        }
        let (sx, sy, sz) = (xm.sqrt(), ym.sqrt(), zm.sqrt());
        let lam = sx * (sy + sz) + sy * sz;
        sum += 1.0 / (f * sz * (zm + lam));
        xm = 0.25 * (xm + lam);
        ym = 0.25 * (ym + lam);
        zm = 0.25 * (zm + lam);
        a = 0.25 * (a + lam);
        f *= 4.0;
    }
    let xx = (a0 - x) / (f * a);
    let yy = (a0 - y) / (f * a);
    let zz = -(xx + yy) / 3.0;
    let xy = xx * yy;
    let z2 = zz * zz;
    let e2 = xy - 6.0 * z2;
    let e3 = (3.0 * xy - 8.0 * z2) * zz;
    let e4 = 3.0 * (xy - z2) * z2;
    let e5 = xy * z2 * zz;
    series5(e2, e3, e4, e5) / (f * a * a.sqrt()) + 3.0 * sum
}

/// R_J(x, y, z, p) for p > 0.
#[inline(always)]
pub(crate) fn rj(x: f64, y: f64, z: f64, p: f64) -> f64 {
    let a0 = (x + y + z + 2.0 * p) / 5.0;
    let delta = (p - x) * (p - y) * (p - z);
    let q = RDJ_C * (a0 - x).abs().max((a0 - y).abs()).max((a0 - z).abs()).max((a0 - p).abs());
    let (mut xm, mut ym, mut zm, mut pm, mut a, mut f) = (x, y, z, p, a0, 1.0);
    let mut sum = 0.0;
    for _ in 0..MAX_STEPS {
        if q < f * a.abs() {
            break;
        }
        let (sx, sy, sz, sp) = (xm.sqrt(), ym.sqrt(), zm.sqrt(), pm.sqrt());
        let lam = sx * (sy + sz) + sy * sz;
        let d = (sp + sx) * (sp + sy) * (sp + sz);
        let e = delta / (f * f * f * d * d);
        let b = 2.0 * sp * (pm + lam) / d; // = 1 + e, without cancellation
        sum += rc1(e, b) / (f * d);
        xm = 0.25 * (xm + lam);
        ym = 0.25 * (ym + lam);
        zm = 0.25 * (zm + lam);
        pm = 0.25 * (pm + lam);
        a = 0.25 * (a + lam);
        f *= 4.0;
    }
    let xx = (a0 - x) / (f * a);
    let yy = (a0 - y) / (f * a);
    let zz = (a0 - z) / (f * a);
    let pp = -(xx + yy + zz) / 2.0;
    let xyz = xx * yy * zz;
    let p2 = pp * pp;
    let e2 = xx * yy + xx * zz + yy * zz - 3.0 * p2;
    let e3 = xyz + 2.0 * e2 * pp + 4.0 * p2 * pp;
    let e4 = (2.0 * xyz + e2 * pp + 3.0 * p2 * pp) * pp;
    let e5 = xyz * p2;
    series5(e2, e3, e4, e5) / (f * a * a.sqrt()) + 6.0 * sum
}

/// R_C(1, b) for b = 1 + e > 0, given both e and b (each computed without cancellation):
/// atan(√e)/√e for e > 0, atanh(t)/t with t = √(−e) for −½ ≤ e < 0 (DLMF 19.2.18–19), and
/// ln((1 + t)/√b)/t for e < −½, since atanh t = ½ ln((1+t)²/(1 − t²)) and 1 − t² = b: this
/// keeps full accuracy when b ≪ 1 (p ≪ x, y, z in R_J), where 1 + e would cancel.
/// 1 + e_m = 2√p_m(p_m + λ_m)/d_m follows from expanding Π(√p ± √x_i) (cf. Boost.Math's
/// ellint_rj, which uses the same identity).
#[inline(always)]
fn rc1(e: f64, b: f64) -> f64 {
    if e > 0.0 {
        let t = e.sqrt();
        t.atan() / t
    } else if e < -0.5 {
        let t = (-e).sqrt();
        ((1.0 + t) / b.sqrt()).ln() / t
    } else if e < 0.0 {
        let t = (-e).sqrt();
        t.atanh() / t
    } else {
        1.0
    }
}

/// R_C(x, y) for 0 ≤ x < y, given the gap y − x > 0 separately (so that the caller can form it
/// without cancellation): atan(√((y−x)/x))/√(y−x) = atan2(√(y−x), √x)/√(y−x) (DLMF 19.2.18).
#[inline(always)]
pub(crate) fn rc_gap(x: f64, gap: f64) -> f64 {
    let t = gap.sqrt();
    if t == 0.0 {
        return 1.0 / x.sqrt(); // R_C(x, x)
    }
    t.atan2(x.sqrt()) / t
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: f64, b: f64, ulps: f64) -> bool {
        (a - b).abs() <= ulps * f64::EPSILON * b.abs()
    }

    /// Carlson (1995), §3 test values, and extreme arguments, against mpmath (float64 of the
    /// exact value).
    #[test]
    fn reference_values() {
        let cases = [
            (rf(1.0, 2.0, 0.0), 1.3110287771460598),
            (rf(2.0, 3.0, 4.0), 0.5840828416771517),
            (rd(0.0, 2.0, 1.0), 1.7972103521033884),
            (rd(2.0, 3.0, 4.0), 0.16510527294261054),
            (rj(0.0, 1.0, 2.0, 3.0), 0.7768862377858233),
            (rj(2.0, 3.0, 4.0, 5.0), 0.14297579667156754),
            (rj(2.0, 3.0, 4.0, 1e-12), 8.58923293749181),
            (rf(1e-16, 1.0, 1e-16), 19.11382792451231),
            (rj(0.0, 1e-16, 1.0, 1e10), 5.942087819162696e-09),
            (rd(1e-16, 1.0, 1e-16), 1.4999999999999974e+16),
            (rc_gap(0.0, 0.25), std::f64::consts::PI),
        ];
        for (i, (got, want)) in cases.into_iter().enumerate() {
            assert!(close(got, want, 4.0), "case {i}: {got:e} vs {want:e}");
        }
    }

    /// Closed forms: R_F(x,x,x) = x^(−1/2), R_D(x,x,x) = R_J(x,x,x,x) = x^(−3/2),
    /// R_F(0,1,1) = π/2, R_D(0,1,1) = 3π/4 (DLMF 19.20.1, 19.20.18, 19.20.5).
    #[test]
    fn closed_forms() {
        assert!(close(rf(4.0, 4.0, 4.0), 0.5, 1.0));
        assert!(close(rd(4.0, 4.0, 4.0), 0.125, 2.0));
        assert!(close(rj(4.0, 4.0, 4.0, 4.0), 0.125, 2.0));
        assert!(close(rf(0.0, 1.0, 1.0), std::f64::consts::FRAC_PI_2, 2.0));
        assert!(close(rd(0.0, 1.0, 1.0), 0.75 * std::f64::consts::PI, 4.0));
        assert!(close(rc1(1e-30, 1.0), 1.0, 0.0));
        assert!(close(rc1(3.0, 4.0), std::f64::consts::PI / 3.0 / 3f64.sqrt(), 2.0));
        // R_C(1, b) = atanh(√(1−b))/√(1−b); at b = 1e-20 it is ln(2/√b)/1 to 1e-20
        assert!(close(rc1(-1.0, 1e-20), (2e10f64).ln(), 2.0));
        assert!(close(rc1(-0.75, 0.25), (0.75f64).sqrt().atanh() / 0.75f64.sqrt(), 2.0));
    }
}
