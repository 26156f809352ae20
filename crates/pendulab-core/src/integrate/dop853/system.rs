//! DOP853's system: the Cartesian first-order form T-2.4 of the pendulum as one point y = (x, v) of
//! R⁶ (x in m, v in m/s, t in s),
//!
//!   ẋ = v,   v̇ = f(t, x, v) + λ x,   λ = −(|v|² + x·f)/l²    (T-2.4, f the applied acceleration),
//!
//! with the vector operations a Runge–Kutta step needs and the error weights
//! atol + rtol·max(|y₀|, |y₁|) of the step-size control (componentwise).

use crate::model::{acceleration, Model};
use crate::state::State;
use glam::DVec3;

/// A point of the first-order system: position and velocity, or their derivatives.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub(crate) struct Y6 {
    pub(crate) x: DVec3,
    pub(crate) v: DVec3,
}

impl Y6 {
    #[inline(always)]
    pub(crate) fn axpy(self, a: f64, k: Y6) -> Y6 {
        Y6 { x: self.x + k.x * a, v: self.v + k.v * a }
    }
    #[inline(always)]
    pub(crate) fn sub(self, o: Y6) -> Y6 {
        Y6 { x: self.x - o.x, v: self.v - o.v }
    }
    #[inline(always)]
    pub(crate) fn scale(self, a: f64) -> Y6 {
        Y6 { x: self.x * a, v: self.v * a }
    }
    /// Σ (yᵢ/scaleᵢ)² over the six components.
    #[inline(always)]
    pub(crate) fn scaled_norm2(self, scale: Y6) -> f64 {
        // A zero weight (atol = 0 and a component exactly 0) counts a zero as 0 and anything else as ∞.
        let q = |d: f64, s: f64| {
            if s > 0.0 {
                d / s
            } else if d == 0.0 {
                0.0
            } else {
                f64::INFINITY
            }
        };
        let (a, b) = (self.x, self.v);
        let (sa, sb) = (scale.x, scale.v);
        let c = [q(a.x, sa.x), q(a.y, sa.y), q(a.z, sa.z), q(b.x, sb.x), q(b.y, sb.y), q(b.z, sb.z)];
        c.iter().map(|v| v * v).sum()
    }
}

impl From<State> for Y6 {
    #[inline(always)]
    fn from(s: State) -> Self {
        Y6 { x: s.x, v: s.v }
    }
}

/// The right-hand side of T-2.4: (ẋ, v̇).
#[inline(always)]
pub(crate) fn rhs<M: Model>(model: &M, t: f64, y: Y6) -> Y6 {
    Y6 { x: y.v, v: acceleration(model, t, y.x, y.v) }
}

/// Error weights atol + rtol·max(|a|, |b|), componentwise.
#[inline(always)]
pub(crate) fn error_scale(atol: f64, rtol: f64, a: Y6, b: Y6) -> Y6 {
    let s = |p: DVec3, q: DVec3| DVec3::splat(atol) + p.abs().max(q.abs()) * rtol;
    Y6 { x: s(a.x, b.x), v: s(a.v, b.v) }
}
