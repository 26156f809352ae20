//! Round-off of the fourth-order methods that carry their own variables (RKMK4: ω; RK4 in angles:
//! θ, φ, θ̇, φ̇): the error must fall like h⁴ down to the round-off floor and stay there as the step
//! shrinks, not grow with the number of steps.
//!
//! Numerics checked: earlier versions recomputed ω = x × v / l² from the rounded state, formed
//! x₁ = exp(û)x₀ in one expression and rescaled |x₁| to l in floating point on every step; each
//! injected O(ε) per step, biased in energy, and near the separatrix the energy error turns into a
//! phase error. On `near_top` (θ₀ = 179°, φ̇₀ = 0.5 rad/s) at t = 10 s that gave 9.3e-8 at
//! dt = 1e-4 s and 9.2e-7 at dt = 1e-5 s (truncation alone is 5e-10 at 1e-3 s); on `over_the_top`
//! (θ₀ = 30°, θ̇₀ = 8 rad/s) 3.8e-10 and 3.8e-9. With compensated increments and ω carried between
//! steps the errors are ~1e-13 and ~1e-14 at both steps. Reference: the exact solution.
//! Error measure: max(|Δx|/l, |Δv|/(l ω₀ + |v|)).

use crate::common;

use common::{fixed, run_to};
use pendulab_core::exact::ExactSolution;
use pendulab_core::{IdealPendulum, Method, Model, State, Stepper};

fn relative_error(model: &IdealPendulum, a: &State, b: &State) -> f64 {
    let p = model.params();
    ((a.x - b.x).length() / p.length).max((a.v - b.v).length() / (p.length * p.omega0() + b.v.length()))
}

fn error(method: Method, model: IdealPendulum, s0: State, t_end: f64, dt: f64) -> f64 {
    let exact = ExactSolution::new(model.params(), &s0).unwrap().state(t_end).unwrap();
    relative_error(&model, &run_to(model, s0, t_end, &fixed(method, dt)), &exact)
}

fn rkmk4_error(model: IdealPendulum, s0: State, t_end: f64, dt: f64) -> f64 {
    error(Method::Rkmk4, model, s0, t_end, dt)
}

#[test]
fn rkmk4_error_does_not_grow_as_the_step_shrinks() {
    let model = IdealPendulum::new(1.0, 1.0, 9.81).unwrap();
    let cases = [
        ("near_top", State::from_angles(model.params(), 179f64.to_radians(), 0.0, 0.0, 0.5).unwrap()),
        ("over_the_top", State::from_angles(model.params(), 30f64.to_radians(), 0.0, 8.0, 0.0).unwrap()),
    ];
    for (name, s0) in cases {
        let t_end = 10.0;
        let moderate = rkmk4_error(model, s0, t_end, 1e-4);
        let tiny = rkmk4_error(model, s0, t_end, 1e-5);
        eprintln!("{name}: error at t = {t_end} s: dt = 1e-4 s {moderate:.2e}, dt = 1e-5 s {tiny:.2e}");
        // Truncation at 1e-4 s is below 1e-13 (h⁴ from 5e-10 at 1e-3 s); the old code had 9.3e-8.
        assert!(moderate < 1e-11, "{name}: error {moderate:.2e} at dt = 1e-4 s (round-off piles up)");
        // Ten times the steps: at most a few times the floor, not ten times the error (old: 9.2e-7).
        assert!(
            tiny < 1e-11 && tiny <= (4.0 * moderate).max(1e-12),
            "{name}: error {tiny:.2e} at dt = 1e-5 s against {moderate:.2e} at dt = 1e-4 s: it grows with the number of steps"
        );
    }
}

#[test]
fn rkmk4_restarts_its_carried_state_when_the_state_is_replaced() {
    // ω and the compensations are carried between steps; a state set from outside must give the
    // same numbers as a fresh stepper started there.
    let model = IdealPendulum::new(1.0, 1.0, 9.81).unwrap();
    let opts = fixed(Method::Rkmk4, 1e-3);
    let a = State::from_angles(model.params(), 1.0, 0.0, 0.3, 1.5).unwrap();
    let b = State::from_angles(model.params(), 2.0, 0.5, -0.4, 0.7).unwrap();
    let mut st = Stepper::new(model, 0.0, a, &opts).unwrap();
    st.step_to(0.5).unwrap();
    st.set_state(b);
    st.step_to(1.0).unwrap();
    let mut fresh = Stepper::new(model, 0.5, b, &opts).unwrap();
    fresh.step_to(1.0).unwrap();
    assert_eq!(st.state(), fresh.state());
}

#[test]
fn rk4_angles_error_does_not_grow_as_the_step_shrinks() {
    // Earlier versions converted (x, v) → angles → (x, v) on every step: on this rosette (θ₀ = 1,
    // φ̇₀ = 3.5 rad/s, away from the poles) at t = 10 s the position error went from 3.3e-14 at
    // dt = 1e-4 s to 4.2e-13 at 1e-5 s. Carrying the angles with compensated sums: 4e-15 and 3e-15.
    let model = IdealPendulum::new(1.0, 1.0, 9.81).unwrap();
    let s0 = State::from_angles(model.params(), 1.0, 0.0, 0.0, 3.5).unwrap();
    let moderate = error(Method::Rk4Angles, model, s0, 10.0, 1e-4);
    let tiny = error(Method::Rk4Angles, model, s0, 10.0, 1e-5);
    eprintln!("rk4_angles: error at t = 10 s: dt = 1e-4 s {moderate:.2e}, dt = 1e-5 s {tiny:.2e}");
    assert!(
        tiny < 1e-13 && tiny <= (4.0 * moderate).max(2e-14),
        "error {tiny:.2e} at dt = 1e-5 s against {moderate:.2e} at dt = 1e-4 s: it grows with the number of steps"
    );
}

#[test]
fn rk4_angles_restarts_its_carried_angles_when_the_state_is_replaced() {
    use pendulab_core::integrate::{rk4_angles::Rk4Angles, FixedStep};
    let model = IdealPendulum::new(1.0, 1.0, 9.81).unwrap();
    let a = State::from_angles(model.params(), 1.0, 3.0, 0.3, 1.5).unwrap();
    let b = State::from_angles(model.params(), 2.0, 0.5, -0.4, 0.7).unwrap();
    let (mut carried, mut fresh) = (Rk4Angles::default(), Rk4Angles::default());
    let mut s = a;
    // Crosses φ = π, where the carried azimuth is wrapped.
    for k in 0..300 {
        carried.step(&model, k as f64 * 1e-3, &mut s, 1e-3).unwrap();
    }
    assert!(s.angles().1 < 0.0, "φ did not cross π: {}", s.angles().1);
    let (mut s1, mut s2) = (b, b);
    carried.step(&model, 0.3, &mut s1, 1e-3).unwrap();
    fresh.step(&model, 0.3, &mut s2, 1e-3).unwrap();
    assert_eq!(s1, s2);
}
