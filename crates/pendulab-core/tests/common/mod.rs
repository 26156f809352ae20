//! Shared helpers of the integration tests: the scenarios' initial states and a runner.
#![allow(dead_code)]

pub mod sampled;

use pendulab_core::{IdealPendulum, Method, Model, SolveOptions, State, Stepper};

/// The rosette start of `examples/scenarios/rosette.toml`: l = 1 m, g = 9.81 m/s², θ₀ = 60°,
/// φ̇₀ = 2 rad/s.
pub fn rosette() -> (IdealPendulum, State) {
    let m = IdealPendulum::new(1.0, 1.0, 9.81).unwrap();
    let s = State::from_angles(m.params(), 60f64.to_radians(), 0.0, 0.0, 2.0).unwrap();
    (m, s)
}

/// Fixed-step options for `method` with step `dt` [s].
pub fn fixed(method: Method, dt: f64) -> SolveOptions {
    SolveOptions { method, dt, ..SolveOptions::default() }
}

/// Integrates to `t_end` [s] and returns the final state.
pub fn run_to(model: IdealPendulum, s0: State, t_end: f64, options: &SolveOptions) -> State {
    let mut st = Stepper::new(model, 0.0, s0, options).unwrap();
    st.step_to(t_end).unwrap();
    st.state()
}

/// Distance between two states in R⁶, position in units of l and velocity in units of l ω₀.
pub fn state_distance(a: &State, b: &State, length: f64, speed: f64) -> f64 {
    ((a.x - b.x).length() / length).max((a.v - b.v).length() / speed)
}

/// Every fixed-step method of the registry (all but the adaptive ones).
pub fn fixed_step_methods() -> Vec<Method> {
    Method::ALL.into_iter().filter(|m| !m.info().adaptive).collect()
}
