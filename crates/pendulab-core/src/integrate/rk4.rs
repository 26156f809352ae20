//! Classic fourth-order Runge–Kutta on the Cartesian ODE T-2.4 (y = ẋ):
//! ẋ = y, ẏ = f + λ(x, y) x with λ = −(|y|² + x·f)/l², with **no projection**.
//!
//! This is the baseline that shows why structure matters: TS² is invariant but unstable for T-2.4
//! (the constraint error ε = |x|²/l² − 1 obeys ε̈ = 2(g z − |y|²)ε/l², docs/theory.md T-2.4), so the
//! truncation error of each step is amplified and |x| − l, x·v, E and J₃ drift.

use super::FixedStep;
use crate::error::Result;
use crate::model::{acceleration, Model};
use crate::state::State;

/// Classic RK4 (Kutta 1901), order 4, 4 evaluations per step.
#[derive(Debug, Clone, Copy, Default)]
pub struct Rk4;

impl FixedStep for Rk4 {
    #[inline]
    fn step<M: Model>(&mut self, model: &M, t: f64, s: &mut State, h: f64) -> Result<()> {
        let (x, v) = (s.x, s.v);
        let half = 0.5 * h;
        let a1 = acceleration(model, t, x, v);
        let (x2, v2) = (x + v * half, v + a1 * half);
        let a2 = acceleration(model, t + half, x2, v2);
        let (x3, v3) = (x + v2 * half, v + a2 * half);
        let a3 = acceleration(model, t + half, x3, v3);
        let (x4, v4) = (x + v3 * h, v + a3 * h);
        let a4 = acceleration(model, t + h, x4, v4);
        let sixth = h / 6.0;
        s.x = x + (v + (v2 + v3) * 2.0 + v4) * sixth;
        s.v = v + (a1 + (a2 + a3) * 2.0 + a4) * sixth;
        Ok(())
    }

    fn evals_per_step(&self) -> u64 {
        4
    }
}
