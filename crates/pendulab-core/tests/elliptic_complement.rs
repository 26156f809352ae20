//! The complement-taking variants (`Param::with_complement`, `ellipk_c`, `ellipf_c`, `ellippi_c`,
//! `ellippi_inc_c`, `JacobiParam::with_complement`) that the exact solution uses where m → 1 or
//! n → 1 closer than float64 can say by 1 − m, 1 − n. Checked: identical to the plain functions
//! when the complement is exact, and right (against mpmath, 50 digits) where 1 − n rounds to 0.

use pendulab_core::elliptic::*;
use proptest::prelude::*;

proptest! {
    #[test]
    fn equal_to_the_plain_functions_for_exact_complements(
        m in 0.5f64..1.0, n in 0.5f64..1.0, phi in -7.0f64..7.0, u in -20.0f64..20.0
    ) {
        // for m, n ≥ ½, 1 − m and 1 − n are exact (Sterbenz), so both paths see the same numbers
        let p = Param::with_complement(m, 1.0 - m).unwrap();
        prop_assert_eq!(ellipk_c(p), ellipk(m).unwrap());
        prop_assert_eq!(ellipf_c(phi, p).unwrap(), ellipf(phi, m).unwrap());
        prop_assert_eq!(ellippi_c(n, 1.0 - n, p).unwrap(), ellippi(n, m).unwrap());
        prop_assert_eq!(ellippi_inc_c(n, 1.0 - n, phi, p).unwrap(), ellippi_inc(n, phi, m).unwrap());
        prop_assert_eq!(JacobiParam::with_complement(p).eval(u).unwrap(), JacobiParam::new(m).unwrap().eval(u).unwrap());
    }
}

#[test]
fn complements_below_the_rounding_of_one() {
    // mpmath (dps 50): Π(1 − 1e-20; 1.2 | 0.3), Π(1 − 1e-20 | 0.3), K(1 − 1e-18)
    let p = Param::with_complement(0.3, 0.7).unwrap();
    let pi_inc = ellippi_inc_c(1.0, 1e-20, 1.2, p).unwrap();
    assert!((pi_inc - 2.817_039_059_994_735).abs() < 4e-16 * 2.82, "{pi_inc}");
    let pi = ellippi_c(1.0, 1e-20, p).unwrap();
    assert!((pi - 18_774_607_091.875_465).abs() < 1e-14 * 1.9e10, "{pi}");
    let k = ellipk_c(Param::with_complement(1.0, 1e-18).unwrap());
    assert!((k - 22.109_560_198_066_3).abs() < 4e-16 * 22.1, "{k}");
    // the plain functions cannot see these: 1 − 1e-20 is 1.0
    assert!(ellippi(1.0, 0.3).is_err());
}

#[test]
fn inconsistent_complements_are_refused() {
    assert!(Param::with_complement(0.3, 0.6).unwrap_err().to_string().contains("m1"));
    let p = Param::with_complement(0.3, 0.7).unwrap();
    assert!(ellippi_c(0.5, 0.6, p).unwrap_err().to_string().contains("n1"));
    assert!(ellippi_inc_c(0.5, -0.5, 1.0, p).is_err());
}
