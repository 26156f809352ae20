//! The sampled-pivot runs' shared start: l = 1 m, m = 1 kg, g = 9.81 m/s², the start (θ, φ, θ̇, φ̇) =
//! (1.3 rad, 0.9 rad, 0.6 rad/s, 2.5 rad/s), and the smooth 3-D path (0.3 sin 1.3t, 0.2 sin(0.7t + 0.5),
//! 0.1 cos 2t) m sampled at given times with damping 0.03 1/s (docs/integrators.md, *Sampled pivot*).

use pendulab_core::model::registry::AnyModel;
use pendulab_core::{DVec3, Params, State};

/// l = 1 m, m = 1 kg, g = 9.81 m/s².
pub fn params() -> Params {
    Params::new(1.0, 1.0, 9.81).unwrap()
}

/// θ = 1.3 rad, φ = 0.9 rad, θ̇ = 0.6 rad/s, φ̇ = 2.5 rad/s.
pub fn start() -> State {
    State::from_angles(&params(), 1.3, 0.9, 0.6, 2.5).unwrap()
}

/// The path (0.3 sin 1.3t, 0.2 sin(0.7t + 0.5), 0.1 cos 2t) m sampled at `times` [s], damping 0.03 1/s.
pub fn path(times: &[f64]) -> AnyModel {
    let positions: Vec<DVec3> = times
        .iter()
        .map(|&t| DVec3::new(0.3 * (1.3 * t).sin(), 0.2 * (0.7 * t + 0.5).sin(), 0.1 * (2.0 * t).cos()))
        .collect();
    AnyModel::sampled_pivot(params(), times, &positions, 0.03).unwrap()
}
