//! Classic RK4 in spherical angles y = (θ, φ, θ̇, φ̇), on the Euler–Lagrange equations T-2.5 of
//! L = ½ m l²(θ̇² + φ̇² sin²θ) + m g l cos θ (θ from the downward vertical):
//!
//! ```text
//! θ̈ = φ̇² sin θ cos θ − (g/l) sin θ,      φ̈ = −2 θ̇ φ̇ cos θ / sin θ.
//! ```
//!
//! Kept for teaching: the chart (θ, φ) is singular at both poles (sin θ = 0), where φ̈ blows up and
//! φ is undefined, so a planar swing through the bottom or any orbit near the top breaks it. This
//! method **refuses** (returns [`Error::PoleSingularity`]) as soon as any stage comes within
//! sin θ < [`POLE_LIMIT`] of a pole, instead of returning garbage. The sphere itself is exact (the
//! state is rebuilt from angles). Only for the ideal pendulum with gravity along e₃.

use super::FixedStep;
use crate::error::{Error, Result};
use crate::model::{IdealPendulum, Model};
use crate::state::State;
use glam::DVec3;

/// Smallest sin θ the angle method accepts (about 0.57° from a pole).
pub const POLE_LIMIT: f64 = 1e-2;

/// RK4 in (θ, φ, θ̇, φ̇), 4 evaluations per step.
#[derive(Debug, Clone, Copy, Default)]
pub struct Rk4Angles;

/// (θ, φ, θ̇, φ̇) of a Cartesian state (see [`State::from_angles`] for the inverse).
pub fn to_angles(s: &State, length: f64) -> [f64; 4] {
    let (theta, phi) = s.angles();
    let (st, ct) = theta.sin_cos();
    let (sp, cp) = phi.sin_cos();
    let e_theta = DVec3::new(ct * cp, ct * sp, st);
    let e_phi = DVec3::new(-sp, cp, 0.0);
    [theta, phi, s.v.dot(e_theta) / length, s.v.dot(e_phi) / (length * st)]
}

fn guard(t: f64, y: &[f64; 4]) -> Result<()> {
    let sin_theta = y[0].sin().abs();
    if sin_theta < POLE_LIMIT || !sin_theta.is_finite() {
        return Err(Error::PoleSingularity { t, theta: y[0], sin_theta, limit: POLE_LIMIT });
    }
    Ok(())
}

impl Rk4Angles {
    /// One RK4 step in angles for the ideal pendulum, refusing near a pole.
    pub fn step_angles(model: &IdealPendulum, t: f64, y: [f64; 4], h: f64) -> Result<[f64; 4]> {
        let add = |a: &[f64; 4], k: &[f64; 4], c: f64| std::array::from_fn::<f64, 4, _>(|i| a[i] + c * k[i]);
        guard(t, &y)?;
        let k1 = model.angle_rhs(y);
        let y2 = add(&y, &k1, 0.5 * h);
        guard(t + 0.5 * h, &y2)?;
        let k2 = model.angle_rhs(y2);
        let y3 = add(&y, &k2, 0.5 * h);
        guard(t + 0.5 * h, &y3)?;
        let k3 = model.angle_rhs(y3);
        let y4 = add(&y, &k3, h);
        guard(t + h, &y4)?;
        let k4 = model.angle_rhs(y4);
        let y1 = std::array::from_fn(|i| y[i] + h / 6.0 * (k1[i] + 2.0 * (k2[i] + k3[i]) + k4[i]));
        guard(t + h, &y1)?;
        Ok(y1)
    }
}

impl FixedStep for Rk4Angles {
    fn step<M: Model>(&mut self, model: &M, t: f64, s: &mut State, h: f64) -> Result<()> {
        // T-2.5 is the ideal pendulum's angle form: rebuild it from the model's parameters.
        let ideal = IdealPendulum::from_params(*model.params());
        let l = ideal.params().length;
        let y = to_angles(s, l);
        guard(t, &y)?;
        let [theta, phi, theta_dot, phi_dot] = Self::step_angles(&ideal, t, y, h)?;
        *s = State::from_angles(ideal.params(), theta, phi, theta_dot, phi_dot)?;
        Ok(())
    }

    fn evals_per_step(&self) -> u64 {
        4
    }
}
