//! Identities the elliptic layer must satisfy at random arguments (proptest): Legendre's
//! relation, the Jacobi identities, ellipf(am(u)) = u, quasi-periodicity and oddness.
//! Golden-value accuracy is checked in `elliptic.rs`.
//!
//! Tolerances follow from the accuracy bounds asserted there (ε = 2⁻⁵², ulp(x) ≤ ε|x|):
//! a function value is within 4–8 ulp plus the change caused by moving its large argument
//! by an ulp. Each test states how its tolerance is composed.

use pendulab_core::elliptic::{am, ellipe, ellipe_inc, ellipf, ellipk, ellippi, ellippi_inc, jacobi};
use proptest::prelude::*;
use std::f64::consts::{FRAC_PI_2, PI};

const EPS: f64 = f64::EPSILON;

/// m in [0, 1): uniform, or 1 − 10^(−a) with a up to 15 (where K ≈ 18).
fn param() -> impl Strategy<Value = f64> {
    prop_oneof![0.0..1.0f64, (1.0..15.0f64).prop_map(|a| 1.0 - 10f64.powf(-a)), Just(0.0)]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    /// Legendre's relation E K′ + E′ K − K K′ = π/2 (DLMF 19.7.1), K′ = K(1 − m). For m ≥ ½ the
    /// complement 1 − m is exact. Each product is within ~6 ulp, so the sum is within
    /// 8ε (EK′ + E′K + KK′); near m = 1 that sum is ~60 and two terms cancel.
    #[test]
    fn legendre_relation(m in prop_oneof![0.5..1.0f64, (1.0..15.9f64).prop_map(|a| 1.0 - 10f64.powf(-a))]) {
        let m1 = 1.0 - m;
        let (k, e, k1, e1) = (ellipk(m).unwrap(), ellipe(m).unwrap(), ellipk(m1).unwrap(), ellipe(m1).unwrap());
        let lhs = e * k1 + e1 * k - k * k1;
        let scale = e * k1 + e1 * k + k * k1;
        prop_assert!((lhs - FRAC_PI_2).abs() <= 8.0 * EPS * scale, "m={m:e}: {lhs} vs pi/2");
    }

    /// sn² + cn² = 1, dn² + m sn² = 1 and dn² = cn² + (1 − m) sn² (DLMF 22.6.1), the last one
    /// relative to dn², which tests cn and dn where they are tiny (m → 1).
    #[test]
    fn jacobi_identities(u in -1e4..1e4f64, m in param()) {
        let j = jacobi(u, m).unwrap();
        prop_assert!((j.sn * j.sn + j.cn * j.cn - 1.0).abs() <= 4.0 * EPS);
        prop_assert!((j.dn * j.dn + m * j.sn * j.sn - 1.0).abs() <= 4.0 * EPS);
        let rhs = j.cn * j.cn + (1.0 - m) * j.sn * j.sn;
        prop_assert!((j.dn * j.dn - rhs).abs() <= 8.0 * EPS * j.dn * j.dn, "u={u} m={m:e} {j:?}");
        prop_assert!(j.dn > 0.0 && j.sn.abs() <= 1.0 && j.cn.abs() <= 1.0);
    }

    /// F(am(u)) = u. am is within 4(ulp(am) + ulp(u) dn); F maps that through ∂F/∂φ = 1/dn
    /// and adds its own 4(ulp(u) + ulp(am)/dn): |F(am(u)) − u| ≤ 8ε(|u| + |am|/dn).
    #[test]
    fn ellipf_inverts_am(u in prop_oneof![-50.0..50.0f64, -1e4..1e4f64], m in param()) {
        let j = jacobi(u, m).unwrap();
        prop_assert_eq!(am(u, m).unwrap(), j.am);
        let back = ellipf(j.am, m).unwrap();
        let tol = 8.0 * EPS * (u.abs() + j.am.abs() / j.dn);
        prop_assert!((back - u).abs() <= tol, "u={u} m={m:e}: F(am) = {back}, tol {tol:e}");
    }

    /// am(u + 2K) = am(u) + π, sn(u + 2K) = −sn(u), cn(u + 2K) = −cn(u), dn(u + 2K) = dn(u)
    /// (DLMF 22.4.3, 22.16.2). u + 2K is rounded: that and the golden bounds give
    /// 8ε(|u| + 2jK + |am|) (all derivatives are ≤ 1 in size).
    #[test]
    fn jacobi_quasi_periodicity(u in -100.0..100.0f64, m in param(), jj in -3i32..4) {
        let k = ellipk(m).unwrap();
        let jf = f64::from(jj);
        let v = u + 2.0 * jf * k;
        let (a, b) = (jacobi(u, m).unwrap(), jacobi(v, m).unwrap());
        let tol = 8.0 * EPS * (u.abs() + v.abs() + a.am.abs() + b.am.abs());
        let sign = if jj % 2 == 0 { 1.0 } else { -1.0 };
        prop_assert!((b.am - a.am - jf * PI).abs() <= tol, "am: u={u} m={m:e} j={jj}");
        prop_assert!((b.sn - sign * a.sn).abs() <= tol);
        prop_assert!((b.cn - sign * a.cn).abs() <= tol);
        prop_assert!((b.dn - a.dn).abs() <= tol);
    }

    /// X(φ + jπ) = X(φ) + 2jX_complete for F, E, Π (DLMF 19.2.10). φ + jπ is rounded, which
    /// moves X by up to ulp(φ + jπ)|∂X/∂φ|, with |∂X/∂φ| ≤ 1/((1 − max(n,0))√(1 − m)).
    #[test]
    fn legendre_quasi_periodicity(
        phi in -10.0..10.0f64, m in 0.0..0.999f64, n in prop_oneof![-1e6..0.9f64, -10.0..0.9f64], jj in -4i32..5
    ) {
        let jf = f64::from(jj);
        let psi = phi + jf * PI;
        let slope = 1.0 / ((1.0 - n.max(0.0)) * (1.0 - m).sqrt());
        let tol = |x: f64| 8.0 * EPS * (x.abs() + (phi.abs() + psi.abs() + 1.0) * slope);
        let f = ellipf(psi, m).unwrap();
        let f_want = ellipf(phi, m).unwrap() + 2.0 * jf * ellipk(m).unwrap();
        prop_assert!((f - f_want).abs() <= tol(f), "F: phi={phi} j={jj} m={m}");
        let e = ellipe_inc(psi, m).unwrap();
        let e_want = ellipe_inc(phi, m).unwrap() + 2.0 * jf * ellipe(m).unwrap();
        prop_assert!((e - e_want).abs() <= tol(e), "E: phi={phi} j={jj} m={m}");
        let p = ellippi_inc(n, psi, m).unwrap();
        let p_want = ellippi_inc(n, phi, m).unwrap() + 2.0 * jf * ellippi(n, m).unwrap();
        prop_assert!((p - p_want).abs() <= tol(p), "Pi: n={n} phi={phi} j={jj} m={m}");
    }

    /// F, E, Π and sn, am are odd, cn, dn even — exactly, since the reductions are symmetric.
    #[test]
    fn oddness_is_exact(x in -1e4..1e4f64, m in param(), n in -1e10..0.99f64) {
        prop_assert_eq!(ellipf(-x, m).unwrap(), -ellipf(x, m).unwrap());
        prop_assert_eq!(ellipe_inc(-x, m).unwrap(), -ellipe_inc(x, m).unwrap());
        prop_assert_eq!(ellippi_inc(n, -x, m).unwrap(), -ellippi_inc(n, x, m).unwrap());
        let (a, b) = (jacobi(x, m).unwrap(), jacobi(-x, m).unwrap());
        prop_assert_eq!((b.sn, b.cn, b.dn, b.am), (-a.sn, a.cn, a.dn, -a.am));
    }

    /// Π(0; φ|m) = F(φ|m) exactly; Π(n; φ|0) = atan(√(1−n) tan φ)/√(1−n) for |φ| < π/2
    /// (DLMF 19.6.11), to 8 ulp plus the conditioning of atan's argument.
    #[test]
    fn pi_special_cases(phi in -1.5..1.5f64, m in param(), n in -1e10..0.99f64) {
        prop_assert_eq!(ellippi_inc(0.0, phi, m).unwrap(), ellipf(phi, m).unwrap());
        let r = (1.0 - n).sqrt();
        let want = (r * phi.tan()).atan() / r;
        let got = ellippi_inc(n, phi, 0.0).unwrap();
        let cond = (1.0 + phi.tan().powi(2)) * phi.abs() / (1.0 + (r * phi.tan()).powi(2)); // |φ ∂/∂φ| of the atan
        prop_assert!((got - want).abs() <= 8.0 * EPS * (want.abs() + cond), "n={n} phi={phi}: {got} vs {want}");
    }
}

/// F(fl(π/2)|m) = K − (π/2 − fl(π/2))/√(1 − m) + O(δ²), and the same for Π, E; am(K) = π/2.
#[test]
fn quarter_period_consistency() {
    let delta = 6.123233995736766e-17; // π/2 − fl(π/2)
    for m in [0.0, 1e-15, 0.3, 0.9, 1.0 - 1e-8, 1.0 - 1e-15] {
        let k = ellipk(m).unwrap();
        let f = ellipf(FRAC_PI_2, m).unwrap();
        let slope = 1.0 / (1.0 - m).sqrt();
        assert!((f - (k - delta * slope)).abs() <= 4.0 * EPS * k, "m={m:e}");
        let e = ellipe_inc(FRAC_PI_2, m).unwrap();
        assert!((e - ellipe(m).unwrap()).abs() <= 4.0 * EPS, "m={m:e}");
        for n in [-1e10, -0.45, 0.5, 1.0 - 1e-6] {
            let p = ellippi_inc(n, FRAC_PI_2, m).unwrap();
            let pc = ellippi(n, m).unwrap();
            let d = delta * slope / (1.0 - n);
            assert!((p - (pc - d)).abs() <= 8.0 * EPS * pc, "n={n:e} m={m:e}: {p} vs {pc}");
        }
        let j = jacobi(k, m).unwrap();
        assert!((j.am - FRAC_PI_2).abs() <= 4.0 * EPS, "m={m:e}: am(K) = {}", j.am);
        assert!((j.sn - 1.0).abs() <= 2.0 * EPS);
        // cn(K) = 0: the float K differs from K by ≤ ulp(K)/2, and cn′(K) = −√(1−m).
        assert!(j.cn.abs() <= 2.0 * EPS * k * (1.0 - m).sqrt() + 1e-300, "m={m:e}: cn(K) = {:e}", j.cn);
    }
}

/// am is continuous and increasing across the reduction boundaries u = (2j + 1)K.
#[test]
fn amplitude_is_continuous_across_periods() {
    for m in [0.5, 0.99, 1.0 - 1e-12] {
        let k = ellipk(m).unwrap();
        for j in -3..=3 {
            let c = f64::from(2 * j + 1) * k;
            let below = am(c - 1e-9 * k, m).unwrap();
            let above = am(c + 1e-9 * k, m).unwrap();
            let mid = f64::from(2 * j + 1) * FRAC_PI_2;
            assert!(below < above, "m={m} j={j}");
            assert!((below - mid).abs() < 1e-8 && (above - mid).abs() < 1e-8, "m={m} j={j}: {below} {above}");
        }
    }
}
