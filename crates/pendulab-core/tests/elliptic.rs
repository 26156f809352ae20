//! The elliptic layer against 40-digit golden values (`testdata/elliptic_golden.json`, made by
//! `testdata/generate/elliptic.py` with mpmath at the exact float64 arguments), and its
//! behaviour on bad input. Property tests (Legendre relation, identities, quasi-periodicity,
//! oddness) are in `elliptic_properties.rs`.
//!
//! Error measure. Each golden value is stored as v + v_lo (the float64 nearest to the exact
//! value and the float64 of the remainder), so the error |computed − exact| is measured to
//! ~1e-32, not just to the rounding of v. It is reported in two units:
//! - ulp: err / ulp(exact), the plain relative measure;
//! - ulp*: err / (ulp(exact) + ulp(x)·|∂f/∂x|), where x is the large argument (φ for the
//!   incomplete integrals, u for the Jacobi functions). The second term is the change of f
//!   when x moves by one ulp, i.e. the conditioning of f at a float64 argument, and what
//!   reducing φ by π (or u by 2K) in float64 arithmetic costs; it is also the absolute floor
//!   near the zeros of sn and cn, where plain ulp is meaningless.
//!
//! Bounds (asserted; measured values in testdata/README.md). They were also checked on
//! 3000 further random points per function (not stored); the largest values seen there are
//! given in brackets.
//! - K: 1 ulp (double-double AGM, then one rounding) [0.50].
//! - E: 4 ulp [3.2]: m′K + (m m′/3)R_D(0, 1, m′), two positive terms.
//! - Π(n|m): 8 ulp [4.0]: R_F + (n/3)R_J, or the transformed form for n < −½; R_J alone
//!   reaches ~2.5 ε (it sums ~10 R_C terms) and the naive form loses up to a factor 1.5 to
//!   cancellation for −½ ≤ n < 0.
//! - F, E(φ): 4 ulp for |φ| ≤ π/2 (no reduction) [3.5]; Π(n; φ): 8 ulp there [5.0].
//! - Overall (any φ), in ulp*: F 4 [1.4]; E and Π 8 [4.4]. The reduced amplitude
//!   r = φ − jπ carries an error of about ulp(φ), which moves the value by ulp(φ)|∂X/∂φ|
//!   (1/Δ for F: up to 10⁶ at m = 1 − 10⁻¹², φ ≈ π/2 + jπ): that is the allowance. F adds
//!   2jK with the double-double K, exactly; E and Π add 2jX with the few-ulp complete
//!   value, and when r < 0 the sum 2jX − |X(r)| can be half of 2jX, doubling that error.
//! - sn, cn, dn, am: 4 ulp* [3.0]. The reduction by 2K uses the double-double K, so it costs
//!   only a few ulp(K); the inversion returns the amplitude (or co-amplitude) with the
//!   few-ulp error of one F-evaluation mapped through dφ/dx = dn.

use pendulab_core::elliptic::{
    am, carlson_rd, ellipe, ellipe_inc, ellipf, ellipk, ellippi, ellippi_inc, jacobi, Jacobi, JacobiParam,
};
use pendulab_core::Error;
use serde_json::Value;
use std::f64::consts::FRAC_PI_2;

fn ulp(x: f64) -> f64 {
    let a = x.abs();
    f64::from_bits(a.to_bits() + 1) - a
}

/// One golden table: its rows, with column lookup by name.
struct Table {
    cols: Vec<String>,
    rows: Vec<Vec<Value>>,
}

impl Table {
    fn col(&self, name: &str) -> usize {
        self.cols.iter().position(|c| c == name).unwrap_or_else(|| panic!("no column {name}"))
    }
    fn f(&self, row: &[Value], name: &str) -> f64 {
        row[self.col(name)].as_f64().unwrap()
    }
}

fn load() -> Value {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../../testdata/elliptic_golden.json");
    let text = std::fs::read_to_string(path).expect(
        "testdata/elliptic_golden.json is missing: run .venv/bin/python testdata/generate/elliptic.py",
    );
    serde_json::from_str(&text).unwrap()
}

fn table(json: &Value, name: &str) -> Table {
    let t = &json["functions"][name];
    let cols = t["columns"].as_array().unwrap().iter().map(|c| c.as_str().unwrap().to_string()).collect();
    let rows = t["rows"].as_array().unwrap().iter().map(|r| r.as_array().unwrap().clone()).collect();
    Table { cols, rows }
}

/// Worst errors of one function.
#[derive(Default)]
struct Stat {
    rows: usize,
    ulp: f64,
    ulp_where: String,
    ulp_inner: f64,
    inner_rows: usize,
    ulp_star: f64,
    star_where: String,
}

impl Stat {
    /// Records computed `got` against exact `v + v_lo`; `allowance` = ulp(x)|∂f/∂x| (0 for
    /// complete integrals); `inner` marks rows that need no argument reduction.
    fn add(&mut self, got: f64, v: f64, v_lo: f64, allowance: f64, inner: bool, at: String) {
        let err = ((got - v) - v_lo).abs();
        let e = err / ulp(v);
        let es = err / (ulp(v) + allowance);
        assert!(got.is_finite(), "{at}: got {got}");
        self.rows += 1;
        if e > self.ulp {
            self.ulp = e;
            self.ulp_where = at.clone();
        }
        if inner {
            self.ulp_inner = self.ulp_inner.max(e);
            self.inner_rows += 1;
        }
        if es > self.ulp_star {
            self.ulp_star = es;
            self.star_where = at;
        }
    }
}

fn print_table(title: &str, stats: &[(&str, &Stat)]) {
    println!("\n{title}");
    println!(
        "{:<12} {:>5} {:>9} {:>9} {:>9}  worst ulp* at",
        "function", "rows", "max ulp", "inner ulp", "max ulp*"
    );
    for (name, s) in stats {
        let inner = if s.inner_rows > 0 { format!("{:.2}", s.ulp_inner) } else { "-".to_string() };
        println!("{name:<12} {:>5} {:>9.3e} {inner:>9} {:>9.2}  {}", s.rows, s.ulp, s.ulp_star, s.star_where);
    }
}

#[test]
fn complete_integrals_match_golden() {
    let json = load();
    let mut stats = Vec::new();
    for name in ["ellipk", "ellipe", "ellippi"] {
        let t = table(&json, name);
        let mut s = Stat::default();
        for r in &t.rows {
            let m = t.f(r, "m");
            let (got, at) = match name {
                "ellipk" => (ellipk(m).unwrap(), format!("m={m:e}")),
                "ellipe" => (ellipe(m).unwrap(), format!("m={m:e}")),
                _ => {
                    let n = t.f(r, "n");
                    (ellippi(n, m).unwrap(), format!("n={n:e} m={m:e}"))
                }
            };
            s.add(got, t.f(r, "v"), t.f(r, "v_lo"), 0.0, true, at);
        }
        stats.push((name, s));
    }
    print_table(
        "complete integrals (ulp = error / ulp(exact))",
        &stats.iter().map(|(n, s)| (*n, s)).collect::<Vec<_>>(),
    );
    for (name, s) in &stats {
        let bound = match *name {
            "ellipk" => 1.0,
            "ellipe" => 4.0,
            _ => 8.0,
        };
        assert!(s.ulp <= bound, "{name}: {:.2} ulp at {} exceeds {bound}", s.ulp, s.ulp_where);
    }
}

#[test]
fn incomplete_integrals_match_golden() {
    let json = load();
    let mut stats = Vec::new();
    for name in ["ellipf", "ellipe_inc", "ellippi_inc"] {
        let t = table(&json, name);
        let mut s = Stat::default();
        for r in &t.rows {
            let (phi, m) = (t.f(r, "phi"), t.f(r, "m"));
            let (got, at) = match name {
                "ellipf" => (ellipf(phi, m).unwrap(), format!("phi={phi:e} m={m:e}")),
                "ellipe_inc" => (ellipe_inc(phi, m).unwrap(), format!("phi={phi:e} m={m:e}")),
                _ => {
                    let n = t.f(r, "n");
                    (ellippi_inc(n, phi, m).unwrap(), format!("n={n:e} phi={phi:e} m={m:e}"))
                }
            };
            let allowance = ulp(phi) * t.f(r, "d").abs();
            s.add(got, t.f(r, "v"), t.f(r, "v_lo"), allowance, phi.abs() <= FRAC_PI_2, at);
        }
        stats.push((name, s));
    }
    print_table(
        "incomplete integrals (inner: |phi| <= pi/2; ulp* allows ulp(phi)|dX/dphi|)",
        &stats.iter().map(|(n, s)| (*n, s)).collect::<Vec<_>>(),
    );
    for (name, s) in &stats {
        let (inner, star) = match *name {
            "ellipf" => (4.0, 4.0),
            "ellipe_inc" => (4.0, 8.0),
            _ => (8.0, 8.0),
        };
        assert!(s.ulp_inner <= inner, "{name}: {:.2} ulp for |phi| <= pi/2 exceeds {inner}", s.ulp_inner);
        assert!(s.ulp_star <= star, "{name}: {:.2} ulp* at {} exceeds {star}", s.ulp_star, s.star_where);
    }
}

#[test]
fn jacobi_functions_match_golden() {
    let json = load();
    let t = table(&json, "jacobi");
    let mut stats: Vec<(&str, Stat)> =
        ["sn", "cn", "dn", "am"].iter().map(|n| (*n, Stat::default())).collect();
    for r in &t.rows {
        let (u, m) = (t.f(r, "u"), t.f(r, "m"));
        let j = jacobi(u, m).unwrap();
        let param = JacobiParam::new(m).unwrap();
        assert_eq!(param.eval(u).unwrap(), j);
        assert_eq!(am(u, m).unwrap(), j.am);
        let (sn, cn, dn) = (t.f(r, "sn"), t.f(r, "cn"), t.f(r, "dn"));
        // ∂/∂u: sn' = cn dn, cn' = −sn dn, dn' = −m sn cn, am' = dn (DLMF 22.13.1–3)
        let derivs = [cn * dn, sn * dn, m * sn * cn, dn];
        let got = [j.sn, j.cn, j.dn, j.am];
        for (i, (name, s)) in stats.iter_mut().enumerate() {
            let v = t.f(r, name);
            let v_lo = t.f(r, &format!("{name}_lo"));
            s.add(got[i], v, v_lo, ulp(u) * derivs[i].abs(), false, format!("u={u:e} m={m:e}"));
        }
    }
    print_table(
        "Jacobi functions (ulp* allows ulp(u)|df/du|)",
        &stats.iter().map(|(n, s)| (*n, s)).collect::<Vec<_>>(),
    );
    for (name, s) in &stats {
        assert!(s.ulp_star <= 4.0, "{name}: {:.2} ulp* at {} exceeds 4", s.ulp_star, s.star_where);
    }
}

fn invalid(r: pendulab_core::Result<impl std::fmt::Debug>) -> &'static str {
    match r {
        Err(Error::InvalidParameter { name, .. }) => name,
        other => panic!("expected InvalidParameter, got {other:?}"),
    }
}

#[test]
fn bad_input_is_rejected_with_the_parameter_name() {
    for m in [-1e-300, -0.5, 1.0 + f64::EPSILON, 2.0, f64::NAN, f64::INFINITY] {
        assert_eq!(invalid(ellipk(m)), "m");
        assert_eq!(invalid(ellipe(m)), "m");
        assert_eq!(invalid(ellippi(0.5, m)), "m");
        assert_eq!(invalid(ellipf(0.5, m)), "m");
        assert_eq!(invalid(ellipe_inc(0.5, m)), "m");
        assert_eq!(invalid(ellippi_inc(0.5, 0.5, m)), "m");
        assert_eq!(invalid(jacobi(0.5, m)), "m");
        assert_eq!(invalid(am(0.5, m)), "m");
        assert_eq!(invalid(JacobiParam::new(m)), "m");
    }
    for n in [1.0, 1.5, f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        assert_eq!(invalid(ellippi(n, 0.5)), "n");
        assert_eq!(invalid(ellippi_inc(n, 0.5, 0.5)), "n");
    }
    for x in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        assert_eq!(invalid(ellipf(x, 0.5)), "phi");
        assert_eq!(invalid(ellipe_inc(x, 0.5)), "phi");
        assert_eq!(invalid(ellippi_inc(0.5, x, 0.5)), "phi");
        assert_eq!(invalid(jacobi(x, 0.5)), "u");
        assert_eq!(invalid(JacobiParam::new(0.5).unwrap().eval(x)), "u");
    }
    assert_eq!(invalid(carlson_rd(-1.0, 1.0, 1.0)), "x");
    assert_eq!(invalid(carlson_rd(0.0, 0.0, 1.0)), "y");
    assert_eq!(invalid(carlson_rd(1.0, f64::NAN, 1.0)), "y");
    assert_eq!(invalid(carlson_rd(1.0, 1.0, 0.0)), "z");
    let msg = ellipk(1.5).unwrap_err().to_string();
    assert!(msg.contains("m = 1.5:") && msg.contains("0 ≤ m ≤ 1"), "{msg}");
}

/// The public R_D against Carlson's (1995) test values (float64 of mpmath's values) and
/// K − E = (m/3) R_D(0, 1 − m, 1) (DLMF 19.25.1).
#[test]
fn carlson_rd_reference_values() {
    for (got, want) in [
        (carlson_rd(0.0, 2.0, 1.0).unwrap(), 1.7972103521033884),
        (carlson_rd(2.0, 3.0, 4.0).unwrap(), 0.16510527294261054),
    ] {
        assert!((got - want).abs() <= 4.0 * f64::EPSILON * want, "{got} vs {want}");
    }
    for m in [0.1, 0.5, 0.9] {
        let k_minus_e = ellipk(m).unwrap() - ellipe(m).unwrap();
        let rd = m / 3.0 * carlson_rd(0.0, 1.0 - m, 1.0).unwrap();
        assert!((rd - k_minus_e).abs() <= 8.0 * f64::EPSILON * ellipk(m).unwrap(), "m={m}");
    }
}

#[test]
fn parameter_one_is_documented_behaviour() {
    assert_eq!(ellipk(1.0).unwrap(), f64::INFINITY);
    assert_eq!(ellipe(1.0).unwrap(), 1.0);
    assert_eq!(ellippi(-3.0, 1.0).unwrap(), f64::INFINITY);
    // F(φ|1) = artanh(sin φ) inside (−π/2, π/2), ±∞ beyond; E(φ|1) = sin φ, continued.
    for phi in [0.3, 1.2, FRAC_PI_2, -1.0] {
        let want = phi.sin().atanh();
        assert!((ellipf(phi, 1.0).unwrap() - want).abs() <= 4.0 * f64::EPSILON * want.abs(), "{phi}");
        assert_eq!(ellipe_inc(phi, 1.0).unwrap(), phi.sin());
        assert!(ellippi_inc(0.5, phi, 1.0).unwrap().is_finite());
    }
    for phi in [1.5707963267948968, 2.0, 100.0] {
        assert_eq!(ellipf(phi, 1.0).unwrap(), f64::INFINITY);
        assert_eq!(ellipf(-phi, 1.0).unwrap(), f64::NEG_INFINITY);
        assert_eq!(ellippi_inc(-2.0, phi, 1.0).unwrap(), f64::INFINITY);
    }
    assert!((ellipe_inc(2.0, 1.0).unwrap() - (2.0 - 2f64.sin())).abs() <= 2.0 * f64::EPSILON);
    // Jacobi at m = 1: tanh, sech, sech, gd; no overflow far out.
    let j = jacobi(700.0, 1.0).unwrap();
    assert_eq!((j.sn, j.am), (1.0, FRAC_PI_2));
    assert!(j.cn > 0.0 && (j.cn - 2.0 * (-700f64).exp()).abs() <= 2.0 * f64::EPSILON * j.cn);
    assert_eq!(jacobi(-800.0, 1.0).unwrap().cn, 0.0); // sech 800 underflows
    let j = jacobi(-0.7, 1.0).unwrap();
    assert_eq!(j.sn, (-0.7f64).tanh());
    assert!((j.cn - 1.0 / 0.7f64.cosh()).abs() <= 2.0 * f64::EPSILON);
    assert_eq!(j.cn, j.dn);
}

#[test]
fn extreme_finite_arguments_give_finite_results() {
    // (Π(1 − ε/2; 10³⁰⁰|1 − ε/2) ≈ 10³¹⁵ really overflows, so the integrals stop at 10²⁸⁰.)
    for &m in &[0.0, 5e-324, 1e-300, 0.5, 1.0 - f64::EPSILON / 2.0] {
        for &x in &[1e300, -1e300, 1e280, -1e280, 1e18, 4.5e15, 5e-324] {
            let j: Jacobi = jacobi(x, m).unwrap();
            assert!([j.sn, j.cn, j.dn, j.am].iter().all(|v| v.is_finite()), "jacobi({x}, {m}) = {j:?}");
            assert!(j.sn.abs() <= 1.0 && j.cn.abs() <= 1.0 && j.dn > 0.0);
            if x.abs() > 1e290 {
                continue;
            }
            assert!(ellipf(x, m).unwrap().is_finite());
            assert!(ellipe_inc(x, m).unwrap().is_finite());
            for n in [-1e300, -1e10, 0.0, 1.0 - f64::EPSILON / 2.0] {
                assert!(ellippi_inc(n, x, m).unwrap().is_finite(), "Pi({n}; {x}|{m})");
                assert!(ellippi(n, m).unwrap().is_finite());
            }
        }
    }
}
