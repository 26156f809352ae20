//! Runge–Kutta–Munthe-Kaas of order 4 on TS² (Munthe-Kaas 1999; Iserles, Munthe-Kaas, Nørsett &
//! Zanna, *Lie-group methods*, Acta Numerica 2000, §5), with the exponential map of SO(3).
//!
//! The state is written as (x, ω) with the angular velocity ω = x × v / l², so that v = ω × x.
//! The group G = SO(3) × R³ acts by (R, b)·(x, ω) = (R x, ω + b), and the equations of motion
//! (from T-2.2: d/dt (x × v) = x × f because x × λx = 0) read
//!
//! ```text
//! ẋ = ω × x,            ω̇ = x × f(t, x, ω × x) / l²,
//! ```
//!
//! i.e. ẏ = F(y)·y with F = (ω, x × f / l²) in the Lie algebra so(3) × R³, whose bracket is
//! [(a₁, b₁), (a₂, b₂)] = (a₁ × a₂, 0). RKMK applies the classic RK4 tableau to the algebra ODE
//! u̇ = dexp⁻¹_u(F(exp(u)·y₀)), with dexp⁻¹_u(w) = w − ½[u, w] + (1/12)[u, [u, w]] + O(u⁴) (enough
//! for order 4), and sets y₁ = exp(u₁)·y₀. The exponential of a ∈ so(3) is Rodrigues' rotation.
//!
//! Properties: order 4; x stays on the sphere exactly (rotations; |x| is re-normalised to l after
//! each step so that round-off does not accumulate) and v = ω × x is tangent by construction.
//! Not symplectic; energy and J₃ drift like O(h⁴) per unit time.

use super::FixedStep;
use crate::error::{Error, Result};
use crate::model::Model;
use crate::state::State;
use glam::DVec3;

/// RKMK4 on TS², 4 evaluations per step.
#[derive(Debug, Clone, Copy, Default)]
pub struct Rkmk4;

/// Rodrigues' formula: exp(â) x, the rotation of x by angle |a| about a/|a|.
#[inline]
pub fn rotate(a: DVec3, x: DVec3) -> DVec3 {
    let angle2 = a.length_squared();
    // sin(θ)/θ and (1 − cos θ)/θ² with series near θ = 0 (accurate to round-off below 1e-4).
    let (s, c) = if angle2 < 1e-8 {
        (1.0 - angle2 / 6.0, 0.5 - angle2 / 24.0)
    } else {
        let angle = angle2.sqrt();
        (angle.sin() / angle, (1.0 - angle.cos()) / angle2)
    };
    x + a.cross(x) * s + a.cross(a.cross(x)) * c
}

/// The algebra element F(t, x, ω) = (ω, x × f / l²) of the equations above.
#[inline]
fn field<M: Model>(model: &M, t: f64, x: DVec3, omega: DVec3) -> (DVec3, DVec3) {
    let l2 = model.params().length.powi(2);
    let v = omega.cross(x);
    (omega, x.cross(model.applied_acceleration(t, x, v)) / l2)
}

/// dexp⁻¹_u(w) truncated after the second commutator; only the so(3) part has a bracket.
#[inline]
fn dexp_inv(u: (DVec3, DVec3), w: (DVec3, DVec3)) -> (DVec3, DVec3) {
    let uw = u.0.cross(w.0);
    (w.0 - uw * 0.5 + u.0.cross(uw) / 12.0, w.1)
}

impl FixedStep for Rkmk4 {
    fn step<M: Model>(&mut self, model: &M, t: f64, s: &mut State, h: f64) -> Result<()> {
        let l = model.params().length;
        let (x0, omega0) = (s.x, s.x.cross(s.v) / (l * l));
        let act = |u: (DVec3, DVec3)| (rotate(u.0, x0), omega0 + u.1);
        let scale = |k: (DVec3, DVec3), c: f64| (k.0 * c, k.1 * c);
        let stage = |u: (DVec3, DVec3), tau: f64| {
            let (x, om) = act(u);
            scale(dexp_inv(u, field(model, tau, x, om)), h)
        };
        let k1 = scale(field(model, t, x0, omega0), h);
        let k2 = stage(scale(k1, 0.5), t + 0.5 * h);
        let k3 = stage(scale(k2, 0.5), t + 0.5 * h);
        let k4 = stage(k3, t + h);
        let u = ((k1.0 + (k2.0 + k3.0) * 2.0 + k4.0) / 6.0, (k1.1 + (k2.1 + k3.1) * 2.0 + k4.1) / 6.0);
        let (x1, omega1) = act(u);
        let x1 = x1 * (l / x1.length());
        s.x = x1;
        s.v = omega1.cross(x1);
        if !s.is_finite() {
            return Err(Error::Diverged { t, method: "rkmk4", dt: h });
        }
        Ok(())
    }

    fn evals_per_step(&self) -> u64 {
        4
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rodrigues_rotates_by_the_right_angle() {
        let x = DVec3::X;
        let r = rotate(DVec3::Z * std::f64::consts::FRAC_PI_2, x);
        assert!((r - DVec3::Y).length() < 1e-15);
        let small = rotate(DVec3::Z * 1e-6, x);
        assert!((small - DVec3::new(1e-6f64.cos(), 1e-6f64.sin(), 0.0)).length() < 1e-17);
    }
}
