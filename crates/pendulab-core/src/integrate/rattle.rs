//! RATTLE (Andersen 1983; Hairer, Lubich & Wanner, *Geometric Numerical Integration*, VII.1.4):
//! the constrained Störmer–Verlet method for ẍ = f + λx with g(x) = (|x|² − l²)/2 = 0 (T-2.1,
//! T-2.2). With step h and applied acceleration f (per unit mass):
//!
//! ```text
//! v½  = v₀ + (h/2)(f(x₀) + μ₀ x₀)        μ₀ chosen so that |x₁| = l
//! x₁  = x₀ + h v½
//! v₁  = v½ + (h/2)(f(x₁) + μ₁ x₁)        μ₁ chosen so that x₁·v₁ = 0
//! ```
//!
//! The position multiplier solves the quadratic |a + m x₀|² = l² with a = x₀ + h v₀ + (h²/2) f₀,
//! m = h²μ₀/2; we take the root near 0 in the cancellation-free form
//! m = −c / (b + √(b² − |x₀|² c)), b = a·x₀, c = |a|² − l² (expanded in powers of h, so that no
//! precision is lost to cancellation against l² when h is small), evaluated for small steps as a
//! truncated Catalan series with no square root. The velocity multiplier is an orthogonal
//! projection of v½ + (h/2) f₁ onto the tangent plane at x₁; for a uniform field its numerator is a
//! quadratic in μ₀ computed alongside it. The arithmetic, shared with the ensemble kernel, is in
//! [`super::rattle_kernel`].
//!
//! Properties: order 2, symmetric, symplectic on T*S² for conservative f; |x| = l and x·v = 0
//! hold to round-off after every step (each step re-imposes them, so errors do not accumulate);
//! J₃ is conserved exactly for axisymmetric f (all forces lie in the plane of e₃ and x).
//!
//! Velocity-dependent forces (damping, drag, Coriolis) are not kicked: the model gives their exact
//! flow at fixed x ([`Model::velocity_flow`]), applied for h/2 before and after the step (Strang
//! splitting; second order, conformal symplectic for linear damping). A flow that changes with time
//! (the hoisted rope's −2(l̇/l)v, T-11.10) is frozen at t before and at t + h after the step, which
//! keeps the step symmetric.

use super::rattle_kernel::{
    advance_position, advance_velocity, dot, fmadd3, Arithmetic, Fused, MulAdd, PositionQuadratic,
    ProjectionPolynomial, Unfused,
};
use super::rattle_vertical::VerticalField;
use super::FixedStep;
use crate::error::{Error, Result};
use crate::model::Model;
use crate::state::State;
use glam::DVec3;

/// The RATTLE step, order 2, 2 evaluations of f per step (1 with caching for position-only f).
///
/// The updates x₁ = x₀ + Δx and v₁ = v₀ + Δv are added with Kahan's compensated summation: the low
/// bits that rounding drops from each small increment are carried into the next step, so that
/// round-off in x, v (and with it J₃ and E) grows like ε·|Δx|·√N rather than ε·|x|·√N over N steps.
/// This matters for long runs near the separatrix, where round-off is amplified.
///
/// The multiply-adds are unfused by default ([`Arithmetic`]; [`Rattle::set_arithmetic`] chooses).
#[derive(Debug, Clone, Copy, Default)]
pub struct Rattle {
    comp_x: DVec3,
    comp_v: DVec3,
    arithmetic: Arithmetic,
}

impl Rattle {
    /// RATTLE with the given rounding of its multiply-adds.
    pub fn with_arithmetic(arithmetic: Arithmetic) -> Self {
        Self { arithmetic, ..Self::default() }
    }

    /// Chooses the rounding of the multiply-adds for the steps that follow.
    pub fn set_arithmetic(&mut self, arithmetic: Arithmetic) {
        self.arithmetic = arithmetic;
    }

    /// The rounding of the multiply-adds.
    pub fn arithmetic(&self) -> Arithmetic {
        self.arithmetic
    }

    /// One RATTLE step of size `h` \[s\]; returns `false` when the position quadratic has no real
    /// root (h far too large for the motion). The arithmetic is in [`super::rattle_kernel`].
    #[inline(always)]
    pub fn advance<M: Model>(&mut self, model: &M, t: f64, s: &mut State, h: f64) -> bool {
        match self.arithmetic {
            Arithmetic::Unfused => self.advance_with::<Unfused, M>(model, t, s, h),
            Arithmetic::Fused => self.advance_with::<Fused, M>(model, t, s, h),
        }
    }

    /// [`Rattle::advance`] with the rounding `A`: the velocity flow (if any) for h/2 on either side
    /// of the kicks and the constrained drift.
    #[inline(always)]
    fn advance_with<A: MulAdd, M: Model>(&mut self, model: &M, t: f64, s: &mut State, h: f64) -> bool {
        let half = 0.5 * h;
        if model.has_velocity_forces() {
            // Strang splitting: the exact velocity flow for h/2 on either side (see model::extended).
            s.v = model.velocity_flow_at(t, s.x, s.v, half);
        }
        // a uniform field's kicks (h/2) f at t and t + h, computed once for whichever form runs
        let uniform = model
            .kick_is_uniform()
            .then(|| (model.kick_acceleration(t, s.x) * half, model.kick_acceleration(t + h, s.x) * half));
        let ok = match uniform {
            Some((k0, k1)) if A::FUSED && is_vertical(k0, k1) => self.vertical(model, s, h, (k0.z, k1.z)),
            _ => self.kick_drift::<A, M>(model, t, s, h, uniform),
        };
        if !ok {
            return false;
        }
        if model.has_velocity_forces() {
            s.v = model.velocity_flow_at(t + h, s.x, s.v, half);
        }
        true
    }

    /// The fused step in a vertical uniform field (`rattle_vertical.rs`, the ensemble kernel's form),
    /// given the kicks' vertical components κ₀, κ₁ [m/s] at t and t + h.
    #[inline(always)]
    fn vertical<M: Model>(&mut self, model: &M, s: &mut State, h: f64, (kick0, kick1): (f64, f64)) -> bool {
        let l2 = model.params().length * model.params().length;
        let field = VerticalField { h, kick0, kick1, l2, inv_l2: 1.0 / l2 };
        let (w, quad) = field.quadratic(s.x, s.v);
        let mu = quad.multiplier::<Fused>(h);
        if mu.is_nan() {
            return false;
        }
        let end = field.finish((s.x, s.v), (w, &quad), mu, (self.comp_x, self.comp_v));
        (s.x, s.v, self.comp_x, self.comp_v) = (end.x, end.v, end.comp_x, end.comp_v);
        true
    }

    /// The kicks and the constrained drift in the general form of [`super::rattle_kernel`], with a
    /// uniform field's kicks (h/2) f(t), (h/2) f(t + h) [m/s] when the model has one (`uniform`); false
    /// when the position quadratic has no root.
    #[inline(always)]
    fn kick_drift<A: MulAdd, M: Model>(
        &mut self,
        model: &M,
        t: f64,
        s: &mut State,
        h: f64,
        uniform: Option<(DVec3, DVec3)>,
    ) -> bool {
        let l = model.params().length;
        let l2 = l * l;
        // 1/l² is a loop invariant the compiler hoists out of a stepping loop.
        let inv_l2 = 1.0 / l2;
        let half = 0.5 * h;
        let (x0, v0) = (s.x, s.v);
        let kick0 = uniform.map_or_else(|| model.kick_acceleration(t, x0) * half, |(k0, _)| k0);
        let w = v0 + kick0;
        let quad = PositionQuadratic::new::<A>(x0, w, h, l2);
        let mu = quad.multiplier::<A>(h);
        if mu.is_nan() {
            return false;
        }
        // x₁ = x₀ + h v½ exactly as RATTLE writes it, so that x₁ and v½ are consistent by
        // construction (J₃ is kept without bias even for step sizes whose reciprocal is inexact, as
        // in the compositions).
        let v_half = fmadd3::<A>(x0, mu, w);
        let x1 = advance_position::<A>(x0, v_half, h, &mut self.comp_x);
        let (kick1, p) = if let Some((_, kick1)) = uniform {
            // known before x₁: the projection's numerator is a quadratic in μ (module doc of
            // rattle_kernel), its coefficients computed alongside μ
            (kick1, ProjectionPolynomial::new::<A>(x0, w, kick1, &quad, h, inv_l2).at::<A>(mu))
        } else {
            let kick1 = model.kick_acceleration(t + h, x1) * half;
            (kick1, dot::<A>(x1, v_half + kick1) * inv_l2)
        };
        // v₁ = u − x₁ (x₁·u)/l², written as the increment Δv = v₁ − v₀ (|x₁|² = l² to round-off, so
        // x₁·v₁ = (x₁·u)(1 − |x₁|²/l²) is round-off of an O(h) quantity).
        s.v = advance_velocity::<A>(v0, kick0 + kick1, x0, mu, x1, p, &mut self.comp_v);
        s.x = x1;
        true
    }
}

/// Whether both kicks [m/s] are vertical (their horizontal components exactly zero): the fused
/// arithmetic then takes the vertical-field form.
#[inline(always)]
fn is_vertical(k0: DVec3, k1: DVec3) -> bool {
    k0.x == 0.0 && k0.y == 0.0 && k1.x == 0.0 && k1.y == 0.0
}

impl FixedStep for Rattle {
    #[inline(always)]
    fn step<M: Model>(&mut self, model: &M, t: f64, s: &mut State, h: f64) -> Result<()> {
        if self.advance(model, t, s, h) {
            Ok(())
        } else {
            Err(Error::Diverged { t, method: "rattle", dt: h })
        }
    }

    fn evals_per_step(&self) -> u64 {
        2
    }

    fn reset(&mut self) {
        *self = Self::with_arithmetic(self.arithmetic);
    }
}
