//! A prescribed motion q(t) ∈ R³ (a crane's pivot \[m\], or the rope length in the first component
//! \[m\]) given at knots t_i \[s\] by its value q_i, rate q̇_i and second derivative q̈_i: the piecewise
//! quintic Hermite interpolant (docs/theory.md T-11.4). On [t_i, t_{i+1}], h = t_{i+1} − t_i,
//! s = (t − t_i)/h:
//!
//!   q = c₀ + c₁s + … + c₅s⁵,  c₀ = q_i, c₁ = h q̇_i, c₂ = h² q̈_i/2,
//!   c₃ = 10P − 4V + A/2,  c₄ = −15P + 7V − A,  c₅ = 6P − 3V + A/2,
//!
//! with P = q_{i+1} − (c₀ + c₁ + c₂), V = h q̇_{i+1} − (c₁ + 2c₂), A = h² q̈_{i+1} − 2c₂. It is exact
//! for polynomials of degree ≤ 5 between knots, so a crane move written as steps of acceleration or
//! jerk (piecewise quadratic or cubic, T-11.3) is reproduced exactly when its step times are knots.
//! A knot repeated (t_i = t_{i+1}) is a *jump*: the left and right values there (e.g. the step of
//! acceleration of a trapezoidal move); [`Hermite5::breaks`] lists them so that an integrator stops
//! there. Outside [t₀, t_n] the motion continues with the end's constant second derivative.
//!
//! Rejected: fewer than 2 knots, non-finite values, decreasing times, a time repeated more than twice.

use crate::error::{Error, Result};
use glam::DVec3;

/// One knot: time t \[s\], value q, rate q̇ and second derivative q̈ (units of q per s⁰, s¹, s²).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Knot {
    /// Time \[s\].
    pub t: f64,
    /// Value.
    pub q: DVec3,
    /// Rate dq/dt.
    pub dq: DVec3,
    /// Second derivative d²q/dt².
    pub ddq: DVec3,
}

/// The piecewise quintic Hermite interpolant (see the module doc).
#[derive(Debug, Clone, PartialEq)]
pub struct Hermite5 {
    knots: Vec<Knot>,
    coeffs: Vec<[DVec3; 6]>,
}

fn bad(name: &str, reason: String) -> Error {
    Error::InvalidPivotSamples { reason: format!("{name}: {reason}") }
}

impl Hermite5 {
    /// The interpolant through `knots` (≥ 2, finite, times non-decreasing, each at most twice);
    /// `name` (e.g. "pivot", "hoist") labels errors.
    pub fn new(name: &str, knots: Vec<Knot>) -> Result<Self> {
        if knots.len() < 2 {
            return Err(bad(name, format!("{} knots; at least 2 are needed", knots.len())));
        }
        for (i, k) in knots.iter().enumerate() {
            if !(k.t.is_finite() && k.q.is_finite() && k.dq.is_finite() && k.ddq.is_finite()) {
                return Err(bad(name, format!("knot {i} at t = {} s has a non-finite value", k.t)));
            }
        }
        for i in 1..knots.len() {
            if knots[i].t < knots[i - 1].t {
                return Err(bad(
                    name,
                    format!("times must not decrease, but t[{i}] = {} s < t[{}]", knots[i].t, i - 1),
                ));
            }
            if i >= 2 && knots[i].t == knots[i - 2].t {
                return Err(bad(name, format!("the time {} s appears more than twice", knots[i].t)));
            }
        }
        if knots[knots.len() - 1].t <= knots[0].t {
            return Err(bad(name, "the knots span no time".to_string()));
        }
        let coeffs = knots
            .windows(2)
            .map(|w| {
                let (a, b) = (w[0], w[1]);
                let h = b.t - a.t;
                let (c0, c1, c2) = (a.q, a.dq * h, a.ddq * (0.5 * h * h));
                let p = b.q - (c0 + c1 + c2);
                let v = b.dq * h - (c1 + c2 * 2.0);
                let acc = b.ddq * (h * h) - c2 * 2.0;
                let c3 = p * 10.0 - v * 4.0 + acc * 0.5;
                let c4 = p * -15.0 + v * 7.0 - acc;
                let c5 = p * 6.0 - v * 3.0 + acc * 0.5;
                [c0, c1, c2, c3, c4, c5]
            })
            .collect();
        Ok(Self { knots, coeffs })
    }

    /// The first and last knot times \[s\].
    pub fn span(&self) -> (f64, f64) {
        (self.knots[0].t, self.knots[self.knots.len() - 1].t)
    }

    /// The times \[s\] of the jumps (repeated knots), increasing.
    pub fn breaks(&self) -> Vec<f64> {
        self.knots.windows(2).filter(|w| w[0].t == w[1].t).map(|w| w[0].t).collect()
    }

    /// (q, q̇, q̈) at t \[s\], on the piece that contains t; at a knot time, on the side of `t_piece`
    /// (an integrator passes the middle of its step, so that a stage at the end of a step that ends on
    /// a jump uses the values from before it, one at its start those from after it). Every stage of a
    /// step that crosses ordinary knots uses its own piece: a piece is never extrapolated into its
    /// neighbours (only the first and last beyond the span, as the module doc says).
    pub fn eval_on(&self, t: f64, t_piece: f64) -> (DVec3, DVec3, DVec3) {
        let n = self.knots.len();
        // the number of knots before t, those at t counted on t_piece's side
        let before = if t_piece < t {
            self.knots.partition_point(|k| k.t < t)
        } else {
            self.knots.partition_point(|k| k.t <= t)
        };
        if before == 0 {
            let first = self.knots[0];
            let d = t - first.t;
            return (first.q + first.dq * d + first.ddq * (0.5 * d * d), first.dq + first.ddq * d, first.ddq);
        }
        if before == n {
            let last = self.knots[n - 1];
            let d = t - last.t;
            return (last.q + last.dq * d + last.ddq * (0.5 * d * d), last.dq + last.ddq * d, last.ddq);
        }
        // the piece i with t_i ≤ t ≤ t_{i+1}, of positive length: a repeated knot is counted whole
        let i = before - 1;
        let h = self.knots[i + 1].t - self.knots[i].t;
        let s = (t - self.knots[i].t) / h;
        let c = &self.coeffs[i];
        let q = c[0] + (c[1] + (c[2] + (c[3] + (c[4] + c[5] * s) * s) * s) * s) * s;
        let dq = c[1] + (c[2] * 2.0 + (c[3] * 3.0 + (c[4] * 4.0 + c[5] * (5.0 * s)) * s) * s) * s;
        let ddq = c[2] * 2.0 + (c[3] * 6.0 + (c[4] * 12.0 + c[5] * (20.0 * s)) * s) * s;
        (q, dq / h, ddq / (h * h))
    }

    /// (q, q̇, q̈) at t \[s\] (right-continuous at jumps).
    pub fn eval(&self, t: f64) -> (DVec3, DVec3, DVec3) {
        self.eval_on(t, t)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn knot(t: f64, f: impl Fn(f64) -> [f64; 3]) -> Knot {
        let [q, dq, ddq] = f(t);
        Knot { t, q: DVec3::splat(q), dq: DVec3::splat(dq), ddq: DVec3::splat(ddq) }
    }

    #[test]
    fn reproduces_a_quintic_exactly() {
        let f = |t: f64| {
            [
                1.0 + t - 2.0 * t.powi(3) + 0.5 * t.powi(5),
                1.0 - 6.0 * t * t + 2.5 * t.powi(4),
                -12.0 * t + 10.0 * t.powi(3),
            ]
        };
        let h = Hermite5::new("test", [0.0, 0.3, 1.1, 2.0].iter().map(|&t| knot(t, f)).collect()).unwrap();
        for t in [0.05, 0.29, 0.7, 1.5, 1.99] {
            let (q, dq, ddq) = h.eval(t);
            let [a, b, c] = f(t);
            assert!((q.x - a).abs() < 1e-13 && (dq.x - b).abs() < 1e-12 && (ddq.x - c).abs() < 1e-11, "{t}");
        }
    }

    #[test]
    fn a_stage_past_an_ordinary_knot_uses_its_own_piece() {
        // two cubics joined C² at t = 1 (a spline node): a step from 0.8 to 1.4 has its middle at 1.1,
        // its first stages before the knot; each must be on the cubic of its own time, not on the
        // other one extrapolated
        let left = |t: f64| [t * t * t, 3.0 * t * t, 6.0 * t];
        let right = |t: f64| {
            let d = t - 1.0;
            [1.0 + 3.0 * d + 3.0 * d * d - 2.0 * d * d * d, 3.0 + 6.0 * d - 6.0 * d * d, 6.0 - 12.0 * d]
        };
        let h = Hermite5::new("test", vec![knot(0.0, left), knot(1.0, left), knot(2.0, right)]).unwrap();
        for (t, f) in [(0.85, left(0.85)), (0.99, left(0.99)), (1.0, left(1.0)), (1.3, right(1.3))] {
            for t_piece in [0.5, 1.1] {
                let (q, dq, ddq) = h.eval_on(t, t_piece);
                assert!((q.x - f[0]).abs() < 1e-14 && (dq.x - f[1]).abs() < 1e-13, "{t} {t_piece}");
                assert!((ddq.x - f[2]).abs() < 1e-12, "{t} {t_piece}");
            }
        }
    }

    #[test]
    fn a_repeated_knot_is_a_jump() {
        let up = |t: f64| [0.5 * t * t, t, 1.0];
        let k1 = knot(1.0, up);
        let k2 = Knot { ddq: DVec3::ZERO, ..k1 };
        let k3 = Knot { t: 2.0, q: k1.q + k1.dq, dq: k1.dq, ddq: DVec3::ZERO };
        let h = Hermite5::new("test", vec![knot(0.0, up), k1, k2, k3]).unwrap();
        assert_eq!(h.breaks(), vec![1.0]);
        assert_eq!(h.eval_on(1.0, 0.9).2.x, 1.0);
        assert_eq!(h.eval(1.0).2.x, 0.0);
        assert!((h.eval(1.5).0.x - 1.0).abs() < 1e-14);
        assert!(Hermite5::new("test", vec![k1, k2, k2]).is_err());
        assert!(Hermite5::new("test", vec![k3, k1]).is_err());
    }
}
