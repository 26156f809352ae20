//! The exact solution (docs/theory.md §4, T-4.1 … T-4.7) checked against the mpmath golden states, against
//! DOP853 and RATTLE8, against itself (group property, time reversal, derivatives = the equations of
//! motion T-2.2) and in every special case of T-4.6. Units: SI; error measure as in `golden.rs`,
//! max(|Δx|/l, |Δv|/(l ω₀ + |v|)).

use pendulab_core::exact::{ExactSolution, Kind};
use pendulab_core::model::acceleration;
use pendulab_core::{DVec3, IdealPendulum, Method, Model, Params, SolveOptions, State, Stepper};
use serde_json::Value;
use std::f64::consts::PI;

fn rel_err(p: &Params, a: &State, b: &State) -> f64 {
    ((a.x - b.x).length() / p.length).max((a.v - b.v).length() / (p.length * p.omega0() + b.v.length()))
}

fn vec3(v: &Value) -> DVec3 {
    let a: Vec<f64> = v.as_array().unwrap().iter().map(|x| x.as_f64().unwrap()).collect();
    DVec3::new(a[0], a[1], a[2])
}

fn golden() -> Vec<Value> {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../../testdata/golden_states.json");
    let json: Value = serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    json["cases"].as_array().unwrap().clone()
}

fn case_solution(c: &Value) -> (IdealPendulum, State, ExactSolution) {
    let f = |k: &str| c[k].as_f64().unwrap();
    let m = IdealPendulum::new(f("length"), f("mass"), f("g")).unwrap();
    let s0 = State { x: vec3(&c["x0"]), v: vec3(&c["v0"]) };
    let sol = ExactSolution::new(m.params(), &s0).unwrap();
    (m, s0, sol)
}

#[test]
fn matches_the_golden_states_at_all_times() {
    for c in golden() {
        let (m, _, sol) = case_solution(&c);
        for s in c["samples"].as_array().unwrap() {
            let t = s["t"].as_f64().unwrap();
            let exact = State { x: vec3(&s["x"]), v: vec3(&s["v"]) };
            let floor = s["floor"].as_f64().unwrap();
            let got = sol.state(t).unwrap();
            let err = rel_err(m.params(), &got, &exact);
            let bound = (1e-12f64).max(100.0 * floor);
            eprintln!(
                "{:>14} {:>16} t = {t:>7}: error {err:.2e} (floor {floor:.1e})",
                c["name"],
                sol.kind().name()
            );
            assert!(err <= bound, "{} at t = {t}: {err:e} > {bound:e}", c["name"]);
        }
    }
}

#[test]
fn agrees_with_dop853_and_rattle8_at_100_s() {
    // DOP853 at rtol 1e-13 with E and J₃ projected after each step (`set_invariant_projection`):
    // without it, its linearly growing energy error becomes a phase error near the separatrix
    // (near_top 1.8e-8, planar_large 2.4e-10, over_the_top 2.3e-10 at 100 s; golden.rs); with it all
    // scenarios but near_top are at ≤ 1.4e-11. near_top's passes near the unstable top amplify every
    // local error: the symplectic RATTLE8 is at 0.9e-10 there, and DOP853's error at rtol 1e-13 scatters
    // between 2e-11 and 1.8e-10 as atol goes from 1e-17 to 1e-13 (measured) — the float64 limit of this
    // orbit at t = 100 s, not a trend — so DOP853 is checked against 2e-10 on it.
    for c in golden() {
        let (m, s0, sol) = case_solution(&c);
        let name = c["name"].as_str().unwrap();
        for (method, dt) in [(Method::Dop853, 0.0), (Method::Rattle8, 2e-3)] {
            let opts = SolveOptions { method, dt, rtol: 1e-13, atol: 1e-15, project: true };
            let mut st = Stepper::new(m, 0.0, s0, &opts).unwrap();
            st.set_invariant_projection(true);
            st.step_to(100.0).unwrap();
            let err = rel_err(m.params(), &st.state(), &sol.state(100.0).unwrap());
            eprintln!("{name:>14} {:>8} t = 100: {err:.2e}", method.info().name);
            let bound = if name == "near_top" && method == Method::Dop853 { 2e-10 } else { 1e-10 };
            assert!(err < bound, "{name} {}: {err:e}", method.info().name);
        }
    }
}

/// Generic, planar (libration and over the top), conical, negative g, zero g, a skim past the pole.
fn starts() -> Vec<(&'static str, IdealPendulum, State)> {
    let p = |g: f64| IdealPendulum::new(1.3, 0.7, g).unwrap();
    let a = |m: &IdealPendulum, th: f64, ph: f64, thd: f64, phd: f64| {
        State::from_angles(m.params(), th, ph, thd, phd).unwrap()
    };
    let (g, neg, zero) = (p(9.81), p(-9.81), p(0.0));
    vec![
        ("generic", g, a(&g, 1.1, 0.4, 0.8, 1.7)),
        ("generic_up", g, a(&g, 2.0, -2.0, -0.3, 1.2)),
        ("libration", g, a(&g, 1.0, 0.3, 1.5, 0.0)),
        ("rotation", g, a(&g, 0.5, 1.0, 7.0, 0.0)),
        ("conical", g, a(&g, 0.9, 0.0, 0.0, (9.81 / (1.3 * 0.9f64.cos())).sqrt())),
        ("negative_g", neg, a(&neg, 2.2, 0.1, 0.5, 1.1)),
        ("zero_g", zero, a(&zero, 1.0, 0.5, 0.7, 1.3)),
        ("skim", g, a(&g, 2.5, 0.0, 0.0, 1e-3)),
    ]
}

#[test]
fn derivatives_are_the_equations_of_motion() {
    let h = 1e-5;
    for (name, m, s0) in starts() {
        let sol = ExactSolution::new(m.params(), &s0).unwrap();
        for t in [0.3, 7.1, -4.2, 123.4] {
            let (a, b, c) = (sol.state(t - h).unwrap(), sol.state(t).unwrap(), sol.state(t + h).unwrap());
            let vdiff = (c.x - a.x) / (2.0 * h);
            let adiff = (c.v - a.v) / (2.0 * h);
            let acc = acceleration(&m, t, b.x, b.v);
            let scale = 1.0 + b.v.length() + acc.length();
            assert!(
                (vdiff - b.v).length() < 1e-7 * scale,
                "{name} t = {t}: ẋ ≠ v ({:e})",
                (vdiff - b.v).length()
            );
            assert!(
                (adiff - acc).length() < 1e-6 * scale,
                "{name} t = {t}: v̇ ≠ T-2.2 ({:e})",
                (adiff - acc).length()
            );
            let r = b.residuals(1.3);
            assert!(r.length.abs() < 1e-14 && r.tangency.abs() < 1e-13, "{name}: off TS² {r:?}");
        }
    }
}

#[test]
fn flows_compose_and_reverse() {
    for (name, m, s0) in starts() {
        let sol = ExactSolution::new(m.params(), &s0).unwrap();
        let (t1, t2) = (3.7, 11.9);
        let mid = sol.state(t1).unwrap();
        let direct = sol.state(t1 + t2).unwrap();
        let composed = ExactSolution::new(m.params(), &mid).unwrap().state(t2).unwrap();
        let e = rel_err(m.params(), &composed, &direct);
        assert!(e < 1e-12, "{name}: φ(t1+t2) vs φ(t2)∘φ(t1): {e:e}");
        // time reversal: the start with −v, run forward by t, is the state at −t with −v
        let back = ExactSolution::new(m.params(), &State { x: s0.x, v: -s0.v }).unwrap().state(t2).unwrap();
        let minus = sol.state(-t2).unwrap();
        let e = rel_err(m.params(), &State { x: back.x, v: -back.v }, &minus);
        assert!(e < 1e-12, "{name}: time reversal {e:e}");
    }
}

#[test]
fn azimuth_is_continuous_and_advances_by_delta_phi_per_period() {
    for (name, m, s0) in starts() {
        let sol = ExactSolution::new(m.params(), &s0).unwrap();
        let Some(dphi) = sol.azimuth_advance() else { continue };
        let tz = sol.period_z().unwrap();
        // φ̇ = J₃/(m ρ²) has the sign of J₃: φ(t) is monotone, and between samples it moves by less
        // than 2π (by up to ~π where the bob skims a pole) — never a jump by 2π from wrapping.
        let sign = s0.x.x * s0.v.y - s0.x.y * s0.v.x;
        let n = 4000;
        let mut prev = sol.state_and_azimuth(0.0).unwrap().1;
        for k in 1..=n {
            let phi = sol.state_and_azimuth(3.0 * tz * k as f64 / n as f64).unwrap().1;
            let step = (phi - prev) * sign.signum();
            assert!(step > -1e-12 && step < 2.0 * PI - 0.1, "{name}: φ moves by {} at step {k}", phi - prev);
            prev = phi;
        }
        let (a, b) = (sol.state_and_azimuth(1.234).unwrap().1, sol.state_and_azimuth(1.234 + tz).unwrap().1);
        assert!((b - a - dphi).abs() < 1e-12, "{name}: φ(t + T_z) − φ(t) = {} vs Δφ = {dphi}", b - a);
        let st = sol.state(1.234 + 7.0 * tz).unwrap();
        assert!((st.x.z - sol.state(1.234).unwrap().x.z).abs() < 1e-12, "{name}: z not T_z-periodic");
    }
}

#[test]
fn special_cases_are_recognised() {
    let kinds: Vec<Kind> =
        starts().iter().map(|(_, m, s)| ExactSolution::new(m.params(), s).unwrap().kind()).collect();
    use Kind::*;
    assert_eq!(kinds, vec![Generic, Generic, Planar, PlanarRotating, Conical, Generic, GreatCircle, Generic]);
    let m = IdealPendulum::new(1.0, 1.0, 9.81).unwrap();
    for z in [-1.0, 1.0] {
        let rest = State { x: DVec3::new(0.0, 0.0, z), v: DVec3::ZERO };
        let sol = ExactSolution::new(m.params(), &rest).unwrap();
        assert_eq!(sol.kind(), Rest);
        assert_eq!(sol.state(1e6).unwrap(), rest);
    }
    // the separatrix: released at the bottom with exactly the speed to reach the top, 2√(g l)
    let sep = State { x: DVec3::new(0.0, 0.0, -1.0), v: DVec3::new(2.0 * 9.81f64.sqrt(), 0.0, 0.0) };
    let sol = ExactSolution::new(m.params(), &sep).unwrap();
    assert_eq!(sol.kind(), Separatrix);
    let late = sol.state(20.0).unwrap();
    assert!(late.x.z > 1.0 - 1e-9 && late.v.length() < 1e-4, "{late:?}");
}

#[test]
fn planar_periods_and_conical_rate_are_the_textbook_ones() {
    let m = IdealPendulum::new(1.0, 1.0, 9.81).unwrap();
    let w0 = 9.81f64.sqrt();
    // EB1911 (T-6.2): period/(2π√(l/g)) against θ₀/π, from rest at θ₀
    for (frac, ratio) in [(0.1, 1.0062), (0.5, 1.1804), (0.9, 2.0724)] {
        let s = State::from_angles(m.params(), frac * PI, 0.0, 0.0, 0.0).unwrap();
        let t = ExactSolution::new(m.params(), &s).unwrap().period_z().unwrap();
        let r = t / (2.0 * PI / w0);
        assert!((r - ratio).abs() < 6e-5, "θ₀ = {frac}π: {r} vs {ratio}");
    }
    // conical (T-6.1): Ω² = g/(l cos α); one revolution in 2π/Ω
    let alpha: f64 = 0.7;
    let omega = (9.81 / alpha.cos()).sqrt();
    let s = State::from_angles(m.params(), alpha, 0.0, 0.0, omega).unwrap();
    let sol = ExactSolution::new(m.params(), &s).unwrap();
    assert_eq!(sol.kind(), Kind::Conical);
    let after = sol.state(2.0 * PI / omega).unwrap();
    assert!((after.x - s.x).length() < 1e-12 && (after.v - s.v).length() < 1e-11, "{after:?}");
    // over the top (T-4.6): the revolution time is 2kK(k)/ω₀ with k² = 2/(1 + ε)
    let s = State { x: DVec3::new(0.0, 0.0, -1.0), v: DVec3::new(8.0, 0.0, 0.0) };
    let sol = ExactSolution::new(m.params(), &s).unwrap();
    let eps: f64 = (0.5 * 64.0 - 9.81) / 9.81;
    let k2 = 2.0 / (1.0 + eps);
    let expected = 2.0 * k2.sqrt() * pendulab_core::elliptic::ellipk(k2).unwrap() / w0;
    assert!((sol.period_z().unwrap() - expected).abs() < 1e-13 * expected);
    let after = sol.state(expected).unwrap();
    assert!((after.x - s.x).length() < 1e-12, "{after:?}");
}

#[test]
fn bad_input_is_refused() {
    let m = IdealPendulum::new(1.0, 1.0, 9.81).unwrap();
    let off = State { x: DVec3::new(0.0, 0.0, -1.1), v: DVec3::ZERO };
    assert!(ExactSolution::new(m.params(), &off).unwrap_err().to_string().contains("TS"));
    let s = State::from_angles(m.params(), 1.0, 0.0, 0.0, 1.0).unwrap();
    let sol = ExactSolution::new(m.params(), &s).unwrap();
    assert!(sol.state(f64::NAN).unwrap_err().to_string().contains("t"));
    let nan = State { x: DVec3::new(f64::NAN, 0.0, -1.0), v: DVec3::ZERO };
    assert!(ExactSolution::new(m.params(), &nan).is_err());
}
