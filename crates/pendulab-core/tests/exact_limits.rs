//! Limits and published values of the exact solution (docs/theory.md §5–6): the T-5.1 phase example and
//! the golden phase split, Puiseux's π < Δφ < 2π over random (ε, j), the j → 0 limits of Δφ, Airy's
//! precession T-6.3, the conical frequency T-6.1, and Hamiltonian monodromy T-6.4. Dimensionless
//! (ε = E/(m g l), j = J₃/(m l² ω₀)) unless stated.

use pendulab_core::exact::energy_momentum::{monodromy_change, rotation_number, start_for};
use pendulab_core::exact::generic::Generic;
use pendulab_core::exact::phases::phases;
use pendulab_core::exact::ExactSolution;
use pendulab_core::{DVec3, IdealPendulum, Model, State};
use proptest::prelude::*;
use serde_json::Value;
use std::f64::consts::PI;

fn generic(eps: f64, j: f64) -> Generic {
    Generic::new(start_for(eps, j).expect("inside the image"), 0.0).unwrap()
}

fn golden() -> Value {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../../testdata/golden_states.json");
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

#[test]
fn phase_split_of_the_theory_example() {
    // T-5.1: l = g = 1, ε = 0.3, j = 0.5.
    let p = phases(&generic(0.3, 0.5)).unwrap();
    let ex = &golden()["phase_example"];
    for (got, key) in [(p.total, "delta_phi"), (p.dynamic, "phase_dynamic"), (p.geometric, "phase_geometric")]
    {
        let want = ex[key].as_f64().unwrap();
        assert!((got - want).abs() < 1e-12 * want.abs().max(1.0), "{key}: {got} vs {want}");
    }
    assert!((p.sum() - p.total).abs() < 1e-12);
}

#[test]
fn phase_split_matches_the_golden_quadratures() {
    for c in golden()["cases"].as_array().unwrap() {
        if c["kind"] != "generic" {
            continue;
        }
        let f = |k: &str| c[k].as_f64().unwrap();
        let vec3 = |k: &str| {
            let a: Vec<f64> = c[k].as_array().unwrap().iter().map(|x| x.as_f64().unwrap()).collect();
            DVec3::new(a[0], a[1], a[2])
        };
        let m = IdealPendulum::new(f("length"), f("mass"), f("g")).unwrap();
        let sol = ExactSolution::new(m.params(), &State { x: vec3("x0"), v: vec3("v0") }).unwrap();
        let p = phases(sol.generic().unwrap()).unwrap();
        let name = c["name"].as_str().unwrap();
        // near_top's parts are ±1.6e5 rad (j is small): compare relative to their size.
        let scale = f("phase_dynamic").abs().max(1.0);
        assert!(
            (p.total - f("delta_phi")).abs() < 1e-12 * scale,
            "{name}: Δφ {} vs {}",
            p.total,
            f("delta_phi")
        );
        assert!((p.dynamic - f("phase_dynamic")).abs() < 1e-12 * scale, "{name}: dyn {}", p.dynamic);
        assert!((p.geometric - f("phase_geometric")).abs() < 1e-12 * scale, "{name}: geom {}", p.geometric);
        assert!(
            (p.sum() - p.total).abs() <= 1e-10f64.max(1e-12 * scale),
            "{name}: split {}",
            p.sum() - p.total
        );
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]
    /// Puiseux (T-4.5): π < |Δφ| < 2π for every orbit with j ≠ 0.
    #[test]
    fn puiseux_bounds(eps in -0.999f64..6.0, jfrac in 0.001f64..0.999, sign in prop::bool::ANY) {
        // j up to the conical bound at this ε: scan u for max of 2(ε − u)(1 − u²)
        let jmax = (0..2000).map(|i| -1.0 + 2.0 * (i as f64 + 0.5) / 2000.0)
            .map(|u: f64| 2.0 * (eps - u) * (1.0 - u * u)).fold(0.0f64, f64::max).sqrt();
        prop_assume!(jmax > 1e-6);
        let j = if sign { jfrac * jmax } else { -jfrac * jmax };
        if let Some(w) = rotation_number(eps, j) {
            let d = (2.0 * PI * w).abs();
            prop_assert!(d > PI && d < 2.0 * PI, "ε = {eps}, j = {j}: |Δφ| = {d}");
            prop_assert!(w.signum() == j.signum());
        }
    }
}

#[test]
fn small_j_limits_of_the_azimuthal_advance() {
    // T-4.6: as j → 0⁺, Δφ → π below the separatrix (ε < 1) and → 2π above it (ε > 1).
    for (eps, limit) in [(-0.5, PI), (0.5, PI), (1.5, 2.0 * PI), (4.0, 2.0 * PI)] {
        let mut last = f64::INFINITY;
        for j in [1e-2, 1e-4, 1e-6, 1e-8] {
            let d = (2.0 * PI * rotation_number(eps, j).unwrap() - limit).abs();
            assert!(d < last, "ε = {eps}, j = {j}: |Δφ − limit| = {d} did not shrink");
            last = d;
        }
        assert!(last < 1e-6, "ε = {eps}: |Δφ − limit| = {last} at j = 1e-8");
    }
}

#[test]
fn airy_precession_of_small_ellipses() {
    // T-6.3: Ω_p = (3/8)(ab/l²)ω₀ in the sense of revolution, relative corrections O(a²).
    let (l, g): (f64, f64) = (1.0, 9.81);
    let w0 = (g / l).sqrt();
    let m = IdealPendulum::new(l, 1.0, g).unwrap();
    let mut errors = vec![];
    for a in [0.08, 0.04, 0.02] {
        let b = 0.6 * a;
        let x = DVec3::new(a, 0.0, -(l * l - a * a).sqrt());
        let s = State { x, v: DVec3::new(0.0, b * w0, 0.0) };
        let sol = ExactSolution::new(m.params(), &s).unwrap();
        let omega_p = (sol.azimuth_advance().unwrap() - PI) / sol.period_z().unwrap();
        let ratio = omega_p / (3.0 / 8.0 * a * b / (l * l) * w0);
        eprintln!("a = {a}: Ω_p / Airy = {ratio}");
        errors.push((ratio - 1.0).abs());
    }
    assert!(errors[2] < 0.01, "{errors:?}");
    // O(a²): halving a divides the deviation by about 4
    for w in errors.windows(2) {
        assert!(w[1] < 0.35 * w[0], "{errors:?}");
    }
}

#[test]
fn conical_orbits_oscillate_at_nu() {
    // T-6.1: Ω² = g/(l cos α) and ν = Ω√(1 + 3cos²α), so Δφ → 2π/√(1 + 3cos²α) near a conical orbit.
    let m = IdealPendulum::new(1.0, 1.0, 9.81).unwrap();
    for alpha in [0.3f64, 0.8, 1.3] {
        let omega = (9.81 / alpha.cos()).sqrt();
        let want = 2.0 * PI / (1.0 + 3.0 * alpha.cos().powi(2)).sqrt();
        let mut last = f64::INFINITY;
        for delta in [1e-2, 1e-4, 0.0] {
            let s = State::from_angles(m.params(), alpha, 0.0, delta, omega).unwrap();
            let d = (ExactSolution::new(m.params(), &s).unwrap().azimuth_advance().unwrap() - want).abs();
            assert!(d <= last, "α = {alpha}, θ̇₀ = {delta}: {d}");
            last = d;
        }
        assert!(last < 1e-12, "α = {alpha}: exactly conical start gives Δφ off by {last}");
    }
}

#[test]
fn monodromy_around_the_top_is_one() {
    // T-6.4: W carried once around (j, ε) = (0, 1) changes by exactly ±1.
    for r in [0.2, 0.5, 0.9] {
        let change = monodromy_change(r, 720).unwrap();
        assert!((change.abs() - 1.0).abs() < 1e-9, "r = {r}: change {change}");
    }
    assert!(monodromy_change(0.5, 4).is_none());
    assert!(monodromy_change(5.0, 720).is_none(), "a circle leaving the image must be refused");
}
