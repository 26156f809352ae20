//! Observed order of convergence of every fixed-step method in the registry.
//!
//! Physics/numerics checked: a method of order p has global error C h^p. Without a reference
//! solution, successive differences of runs with h, h/2, h/4 to the same time behave like
//! C' h^p, so p ≈ log₂(|y_h − y_{h/2}| / |y_{h/2} − y_{h/4}|). The observed p must lie within ±0.3
//! of the declared order. Case: the rosette (θ₀ = 60°, φ̇₀ = 2 rad/s) to t = 1 s, and for the angle
//! method a start that stays away from the poles.

use crate::common;

use common::{fixed, fixed_step_methods, rosette, run_to, state_distance};
use pendulab_core::{Method, Model, State};

/// Coarsest step for a method of the given order, chosen so that the finest differences stay well
/// above round-off (≥ 1e-12) and the coarsest inside the asymptotic regime.
fn coarsest_step(order: u32) -> f64 {
    match order {
        2 => 0.02,
        4 => 0.04,
        _ => 0.1,
    }
}

fn observed_order(method: Method) -> f64 {
    let (model, mut s0) = rosette();
    if method == Method::Rk4Angles {
        // Off the poles: θ ∈ [≈40°, 60°], never near sin θ = 0.
        s0 = State::from_angles(model.params(), 1.0, 0.0, 0.0, 3.5).unwrap();
    }
    let h = coarsest_step(method.info().order);
    let speed = model.params().length * model.params().omega0();
    let ys: Vec<State> = (0..4).map(|k| run_to(model, s0, 1.0, &fixed(method, h / 2f64.powi(k)))).collect();
    let d: Vec<f64> = ys.windows(2).map(|w| state_distance(&w[0], &w[1], 1.0, speed)).collect();
    // Use the two finest ratios; both must agree with the order.
    let p1 = (d[0] / d[1]).log2();
    let p2 = (d[1] / d[2]).log2();
    eprintln!("{:>11}: differences {:?}, observed orders {p1:.3}, {p2:.3}", method.info().name, d);
    assert!(
        d[2] > 1e-13,
        "{}: differences reached round-off, the test cannot see the order",
        method.info().name
    );
    p2
}

#[test]
fn every_fixed_step_method_converges_at_its_declared_order() {
    let mut failures = Vec::new();
    for method in fixed_step_methods() {
        let p = observed_order(method);
        let declared = method.info().order as f64;
        if (p - declared).abs() > 0.3 {
            failures.push(format!("{}: observed {p:.3}, declared {declared}", method.info().name));
        }
    }
    assert!(failures.is_empty(), "orders off by more than 0.3: {failures:?}");
}
