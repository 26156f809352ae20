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
//! state is rebuilt from angles). Only for the ideal pendulum with gravity along e₃, and for the
//! hoisted rope below a fixed pivot (T-11.10: g/l(t) and the term −(2 l̇/l + c)(θ̇, φ̇), from
//! [`Model::angle_form`]; the angles of the integrators' state are the rope's).
//!
//! Round-off: the angles are carried between steps and advanced by compensated (Kahan) sums of
//! the RK4 increments (φ kept in (−π, π] by subtracting 2π exactly, its low part going into the
//! compensation); they are recomputed from (x, v) only when the state was changed from outside.
//! Converting (x, v) → angles → (x, v) on every step, as earlier versions did, injected O(ε) per
//! step, so that the error grew with the number of steps (×13 from dt = 1e-4 s to 1e-5 s at
//! t = 10 s on a rosette, to 4e-13).

use super::FixedStep;
use crate::error::{Error, Result};
use crate::model::{IdealPendulum, Model};
use crate::state::State;
use glam::DVec3;
use std::f64::consts::{PI, TAU};

/// 2π − TAU: the low part of 2π (2π = TAU + TAU_LO to about 1e-32).
const TAU_LO: f64 = 2.449_293_598_294_706_4e-16;

/// Smallest sin θ the angle method accepts (about 0.57° from a pole).
pub const POLE_LIMIT: f64 = 1e-2;

/// RK4 in (θ, φ, θ̇, φ̇), 4 evaluations per step.
///
/// Carries the angles y and their Kahan compensations between steps; `last` is the state the
/// previous step returned, to recognise a state changed from outside.
#[derive(Debug, Clone, Copy, Default)]
pub struct Rk4Angles {
    y: [f64; 4],
    comp: [f64; 4],
    last: Option<State>,
}

/// (θ, φ, θ̇, φ̇) of a Cartesian state (see [`State::from_angles`] for the inverse).
pub fn to_angles(s: &State, length: f64) -> [f64; 4] {
    let (theta, phi) = s.angles();
    let (st, ct) = theta.sin_cos();
    let (sp, cp) = phi.sin_cos();
    let e_theta = DVec3::new(ct * cp, ct * sp, st);
    let e_phi = DVec3::new(-sp, cp, 0.0);
    [theta, phi, s.v.dot(e_theta) / length, s.v.dot(e_phi) / (length * st)]
}

/// Refuses a stage (or the end) of the step of `h` \[s\] from time `t` \[s\]: a non-finite angle or rate
/// is a divergence ([`Error::Diverged`]), sin θ below [`POLE_LIMIT`] a pole ([`Error::PoleSingularity`]).
/// Both name the step's start `t`, the last state computed, where the run stands (not the stage's time:
/// t + h came out as 0.15000000000000002 s, and a paused lab run then named two times).
fn guard(t: f64, y: &[f64; 4], h: f64) -> Result<()> {
    if !y.iter().all(|c| c.is_finite()) {
        return Err(diverged(t, h));
    }
    let sin_theta = y[0].sin().abs();
    if sin_theta < POLE_LIMIT {
        return Err(Error::PoleSingularity { t, theta: y[0], sin_theta, limit: POLE_LIMIT });
    }
    Ok(())
}

/// The divergence of the step of `h` \[s\] from time `t` \[s\]: the angles this method computed (never
/// the user's) became non-finite or gave a speed beyond the bounds of a state.
fn diverged(t: f64, h: f64) -> Error {
    Error::Diverged { t, method: "rk4_angles", dt: h }
}

impl Rk4Angles {
    /// One RK4 step in angles for the ideal pendulum, refusing near a pole.
    pub fn step_angles(model: &IdealPendulum, t: f64, y: [f64; 4], h: f64) -> Result<[f64; 4]> {
        let dy = Self::increment(model, t, y, h)?;
        let y1 = std::array::from_fn(|i| y[i] + dy[i]);
        guard(t, &y1, h)?;
        Ok(y1)
    }

    /// The RK4 increment y₁ − y₀ (h/6)(k₁ + 2k₂ + 2k₃ + k₄), refusing near a pole.
    fn increment(model: &IdealPendulum, t: f64, y: [f64; 4], h: f64) -> Result<[f64; 4]> {
        Self::increment_of(|_, y| model.angle_rhs(y), t, y, h)
    }

    /// The RK4 increment of y' = rhs(t, y), refusing near a pole.
    fn increment_of(
        rhs: impl Fn(f64, [f64; 4]) -> [f64; 4],
        t: f64,
        y: [f64; 4],
        h: f64,
    ) -> Result<[f64; 4]> {
        let add = |a: &[f64; 4], k: &[f64; 4], c: f64| std::array::from_fn::<f64, 4, _>(|i| a[i] + c * k[i]);
        guard(t, &y, h)?;
        let k1 = rhs(t, y);
        let y2 = add(&y, &k1, 0.5 * h);
        guard(t, &y2, h)?;
        let k2 = rhs(t + 0.5 * h, y2);
        let y3 = add(&y, &k2, 0.5 * h);
        guard(t, &y3, h)?;
        let k3 = rhs(t + 0.5 * h, y3);
        let y4 = add(&y, &k3, h);
        guard(t, &y4, h)?;
        let k4 = rhs(t + h, y4);
        Ok(std::array::from_fn(|i| h / 6.0 * (k1[i] + 2.0 * (k2[i] + k3[i]) + k4[i])))
    }
}

/// The angle form T-2.5 with the time-dependent g/l(t) and the term −γ(t)(θ̇, φ̇) of a model's
/// [`Model::angle_form`] (the hoisted rope, T-11.10; γ = 2 l̇/l + c).
fn angle_rhs_with<M: Model>(model: &M, t: f64, y: [f64; 4]) -> [f64; 4] {
    let [theta, _phi, theta_dot, phi_dot] = y;
    let (s, c) = theta.sin_cos();
    let (g_over_l, gamma) = model.angle_form(t).unwrap_or((f64::NAN, f64::NAN));
    [
        theta_dot,
        phi_dot,
        phi_dot * phi_dot * s * c - g_over_l * s - gamma * theta_dot,
        -2.0 * theta_dot * phi_dot * c / s - gamma * phi_dot,
    ]
}

/// Kahan summation: returns s + d with the running compensation `c` (true sum ≈ result − c).
#[inline(always)]
fn compensated_add(s: f64, d: f64, c: &mut f64) -> f64 {
    let y = d - *c;
    let t = s + y;
    *c = (t - s) - y;
    t
}

impl FixedStep for Rk4Angles {
    fn step<M: Model>(&mut self, model: &M, t: f64, s: &mut State, h: f64) -> Result<()> {
        // T-2.5 is the ideal pendulum's angle form: rebuild it from the model's parameters.
        let ideal = IdealPendulum::from_params(*model.params());
        let l = ideal.params().length;
        if self.last != Some(*s) {
            // A new state, or one changed from outside: start from its angles.
            *self = Self { y: to_angles(s, l), ..Self::default() };
        }
        let y = self.y;
        guard(t, &y, h)?;
        let dy = if model.is_ideal() {
            Self::increment(&ideal, t, y, h)?
        } else {
            Self::increment_of(|t, y| angle_rhs_with(model, t, y), t, y, h)?
        };
        let mut comp = self.comp;
        let mut y1: [f64; 4] = std::array::from_fn(|i| compensated_add(y[i], dy[i], &mut comp[i]));
        // φ back into (−π, π]: φ ∓ TAU is exact here (Sterbenz), TAU_LO goes into the compensation.
        if y1[1] > PI {
            y1[1] -= TAU;
            comp[1] += TAU_LO;
        } else if y1[1] <= -PI {
            y1[1] += TAU;
            comp[1] -= TAU_LO;
        }
        guard(t, &y1, h)?;
        let [theta, phi, theta_dot, phi_dot] = y1;
        // finite angles whose speed l·|(θ̇, φ̇ sin θ)| passes the bounds of a state: diverged, not bad input
        *s =
            State::from_angles(ideal.params(), theta, phi, theta_dot, phi_dot).map_err(|_| diverged(t, h))?;
        (self.y, self.comp, self.last) = (y1, comp, Some(*s));
        Ok(())
    }

    fn evals_per_step(&self) -> u64 {
        4
    }

    fn reset(&mut self) {
        *self = Self::default();
    }
}
