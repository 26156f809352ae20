//! The Weierstrass form of the height (T-4.7, `exact::weierstrass`) against the Jacobi form (T-4.2,
//! `ExactSolution::state`) and the 40-digit golden states (`testdata/golden_states.json`): every
//! golden case at every stored time (1 … 10⁴ s), plus hard starts the golden file does not hold
//! (next to the bottom and the top, near the separatrix, high energy, the separatrix itself).
//! Measure: |Δz|/l and |Δż|/(lω₀ + |v|), SI units.

use pendulab_core::exact::ExactSolution;
use pendulab_core::{DVec3, IdealPendulum, Model, State};
use serde_json::Value;

fn vec3(v: &Value) -> DVec3 {
    let a: Vec<f64> = v.as_array().unwrap().iter().map(|x| x.as_f64().unwrap()).collect();
    DVec3::new(a[0], a[1], a[2])
}

/// Largest |Δz|/l and |Δż|/(lω₀ + |v|) between the two forms at times `t` [s].
fn disagreement(sol: &ExactSolution, t: &[f64]) -> (f64, f64) {
    let p = *sol.params();
    let w = sol.height_weierstrass(t).unwrap().expect("a Weierstrass form");
    let (mut dz, mut dv) = (0.0f64, 0.0f64);
    for (&ti, &(z, zdot)) in t.iter().zip(&w) {
        let s = sol.state(ti).unwrap();
        dz = dz.max((z - s.x.z).abs() / p.length);
        dv = dv.max((zdot - s.v.z).abs() / (p.length * p.omega0() + s.v.length()));
    }
    (dz, dv)
}

#[test]
fn weierstrass_agrees_with_jacobi_and_the_golden_states_on_every_golden_case() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../../testdata/golden_states.json");
    let json: Value = serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    let mut checked = 0;
    for c in json["cases"].as_array().unwrap() {
        let f = |k: &str| c[k].as_f64().unwrap();
        let m = IdealPendulum::new(f("length"), f("mass"), f("g")).unwrap();
        let s0 = State::on_tangent_bundle(m.params(), vec3(&c["x0"]), vec3(&c["v0"])).unwrap();
        let sol = ExactSolution::new(m.params(), &s0).unwrap();
        let name = c["name"].as_str().unwrap();
        if sol.weierstrass().is_none() {
            assert_eq!(c["kind"], "great_circle", "{name}: only g = 0 has no cubic");
            continue;
        }
        let samples = c["samples"].as_array().unwrap();
        let t: Vec<f64> = samples.iter().map(|s| s["t"].as_f64().unwrap()).collect();
        // a dense grid over the first two z-periods as well (every phase of the motion)
        let period = sol.period_z().unwrap();
        let dense: Vec<f64> = (0..=400).map(|i| i as f64 * period / 200.0).collect();
        let (dz, dv) = disagreement(&sol, &dense);
        let w = sol.height_weierstrass(&t).unwrap().unwrap();
        let mut golden_dz = 0.0f64;
        let mut floor = 0.0f64;
        for (s, &(z, _)) in samples.iter().zip(&w) {
            let dz = (z - vec3(&s["x"]).z).abs() / f("length");
            let fl = s["floor"].as_f64().unwrap();
            let zj = sol.state(s["t"].as_f64().unwrap()).unwrap().x.z;
            let (dj, dwj) = ((zj - vec3(&s["x"]).z).abs() / f("length"), (z - zj).abs() / f("length"));
            eprintln!("   t = {:>7}: W {dz:.1e}, J {dj:.1e}, W − J {dwj:.1e}, floor {fl:.1e}", s["t"]);
            // 1e-13, or twice the change that rounding the start to float64 alone makes (the golden
            // floor: either form rounds its derived constants, ε, the roots, a few times more); where
            // the two forms differ by more, the Jacobi form is the one off the golden state
            let bound = 1e-13f64.max(2.0 * fl);
            assert!(dz <= bound, "{name} at t = {}: {dz:e} from the golden z", s["t"]);
            assert!(dwj <= bound.max(dj + bound), "{name} at t = {}: {dwj:e} from the Jacobi z", s["t"]);
            golden_dz = golden_dz.max(dz);
            floor = floor.max(fl);
        }
        eprintln!(
            "{name:>14}: Weierstrass vs Jacobi |Δz|/l {dz:.1e}, |Δż| {dv:.1e}; vs golden |Δz|/l {golden_dz:.1e} (floor {floor:.1e})"
        );
        assert!(dz <= 1e-13 && dv <= 1e-13, "{name}: the two forms differ by {dz:e} (z), {dv:e} (ż)");
        checked += 1;
    }
    assert!(checked >= 6, "only {checked} golden cases had a Weierstrass form");
}

#[test]
fn weierstrass_agrees_with_jacobi_on_hard_starts() {
    let pi = std::f64::consts::PI;
    // (label, l, g, θ, φ̇ [rad/s], θ̇ [rad/s])
    let cases = [
        ("1e-8 rad swing", 1.0, 9.81, 1e-8, 0.0, 0.0),
        ("1e-6 rad ellipse", 1.0, 9.81, 1e-6, 2.0, 0.0),
        ("near-conical", 1.0, 9.81, 1.0, 3.7, 0.0),
        ("1e-6 rad from the top", 1.0, 9.81, pi - 1e-6, 0.0, 0.0),
        ("next to the top, spherical", 1.0, 9.81, pi - 1e-4, 0.05, 0.0),
        ("high energy", 0.01, 9.81, 2.0, 300.0, 100.0),
        ("weak gravity", 100.0, 1e-6, 1.0, 0.0, 1e-4),
        ("strong negative gravity", 1.0, -274.0, 0.3, 4.0, 1.0),
        ("near the separatrix", 1.0, 9.81, 0.5 * pi, 0.0, (9.81f64 * 2.0).sqrt() * (1.0 - 1e-5)),
        ("over the top", 1.0, 9.81, 0.2, 0.0, 8.0),
    ];
    for (label, l, g, theta, phi_dot, theta_dot) in cases {
        let m = IdealPendulum::new(l, 1.0, g).unwrap();
        let s0 = State::from_angles(m.params(), theta, 0.4, theta_dot, phi_dot).unwrap();
        let sol = ExactSolution::new(m.params(), &s0).unwrap();
        let w0 = m.params().omega0();
        let t: Vec<f64> = (0..=300).map(|i| (i as f64 * 0.173) / w0).collect();
        let (dz, dv) = disagreement(&sol, &t);
        let (dz_long, dv_long) = disagreement(&sol, &[100.0 / w0, 1e4 / w0]);
        eprintln!(
            "{label:>28} ({:?}): |Δz|/l {dz:.1e}, |Δż| {dv:.1e}; at τ = 100 and 1e4: {dz_long:.1e}, {dv_long:.1e}",
            sol.kind()
        );
        assert!(dz <= 1e-13 && dv <= 1e-13, "{label}: the two forms differ by {dz:e} (z), {dv:e} (ż)");
        // at τ = 1e4 the phase carries 1e4 periods' worth of rounding in either form (see the docs)
        assert!(dz_long <= 1e-11 && dv_long <= 1e-11, "{label}: {dz_long:e}, {dv_long:e} at long times");
    }
}

#[test]
fn the_invariants_and_roots_are_those_of_the_cubic() {
    let m = IdealPendulum::new(1.0, 1.0, 9.81).unwrap();
    let s0 = State::from_angles(m.params(), 1.2, 0.0, 0.3, 1.1).unwrap();
    let sol = ExactSolution::new(m.params(), &s0).unwrap();
    let w = sol.weierstrass().unwrap();
    let [e1, e2, e3] = w.e;
    assert!(e1 >= e2 && e2 >= e3);
    assert!((e1 + e2 + e3).abs() < 1e-15, "Σe = {}", e1 + e2 + e3);
    assert!((w.g2 + 4.0 * (e1 * e2 + e1 * e3 + e2 * e3)).abs() < 1e-14);
    assert!((w.g3 - 4.0 * e1 * e2 * e3).abs() < 1e-14);
    // the z-period is 2ω₁/ω₀
    let period = sol.period_z().unwrap();
    assert!((2.0 * w.omega1 / sol.omega0() - period).abs() < 1e-14 * period);
    // the separatrix: ω₁ = ∞, and the bob creeps up towards the top
    let top = State::from_angles(m.params(), 0.0, 0.0, (4.0f64 * 9.81).sqrt(), 0.0).unwrap();
    let sep = ExactSolution::new(m.params(), &top).unwrap();
    assert_eq!(sep.kind().name(), "separatrix");
    assert!(sep.weierstrass().unwrap().omega1.is_infinite());
    let (dz, _) = disagreement(&sep, &[0.1, 1.0, 3.0, 10.0]);
    assert!(dz < 1e-13, "separatrix: {dz:e}");
}
