//! The fused arithmetic's RATTLE step in a vertical uniform field (T-2.1, T-2.2; the step of
//! [`super::rattle_kernel`], same mathematics, fewer operations).
//!
//! When the applied acceleration is uniform and vertical (gravity along ∓e₃: the ideal and the
//! linearly damped pendulum, and every trajectory of the ensemble kernel), the kicks are
//! k₀ = (h/2) f(t) = κ₀ e₃ and k₁ = (h/2) f(t + h) = κ₁ e₃, and with e = w + k₁ the step reads
//!
//! ```text
//! w = (v₀ₓ, v₀ᵧ, v₀_z + κ₀),   q m² + 2 b m + c = 0 as in rattle_kernel (μ = m/h),
//! x₀·e = x₀·w + x₀_z κ₁,   w·e = |w|² + w_z κ₁,
//! p = (x₀·e + h w·e + μ (b + h x₀·e) + μ² h q) / l²,
//! x₁ = x₀ + (h (w + μ x₀) − cₓ),   v₁ = v₀ + (−p x₁ + (μ x₀ + ((κ₀ + κ₁) e₃ − c_v))),
//! ```
//!
//! with Kahan compensations cₓ, c_v as in the general form. Compared with it, the additions of
//! exact zeros (the horizontal parts of the kicks) are dropped, and the two dot products with e are
//! taken from x₀·w and |w|², which the position quadratic computes anyway: 11 fewer operations of
//! about 80 per step, some of them on the chain from one step to the next. The roundings differ from the
//! general form's (a few ulp of a step's increment), so this is a form of the opt-in fused arithmetic
//! only ([`super::rattle_kernel::Arithmetic::Fused`]): the single-trajectory RATTLE takes it whenever
//! both kicks are vertical, the ensemble kernel always, and the two agree bit for bit; the unfused
//! default keeps the general form and its bits. SI units: \[m\], [m/s], \[s\], [1/s].

use super::rattle_kernel::{advance_position, fmadd, fmadd3, Fused, PositionQuadratic};
use glam::DVec3;

/// One step's setting in a vertical uniform field: h \[s\], the kicks κ₀, κ₁ [m/s] (the vertical
/// components of (h/2) f at the start and the end of the step), l² \[m²\] and 1/l² [1/m²].
#[derive(Debug, Clone, Copy)]
pub struct VerticalField {
    /// The step h \[s\].
    pub h: f64,
    /// κ₀ = (h/2) f_z(t) [m/s].
    pub kick0: f64,
    /// κ₁ = (h/2) f_z(t + h) [m/s].
    pub kick1: f64,
    /// l² \[m²\].
    pub l2: f64,
    /// 1/l² [1/m²].
    pub inv_l2: f64,
}

/// The end of one step: position x₁ \[m\], velocity v₁ [m/s], their Kahan compensations, and the
/// position multiplier μ [1/s] (NaN when the quadratic has no root: the step is then void).
#[derive(Debug, Clone, Copy)]
pub struct StepEnd {
    /// x₁ \[m\].
    pub x: DVec3,
    /// v₁ [m/s].
    pub v: DVec3,
    /// The position compensation after the step \[m\].
    pub comp_x: DVec3,
    /// The velocity compensation after the step [m/s].
    pub comp_v: DVec3,
    /// μ [1/s].
    pub mu: f64,
}

impl VerticalField {
    /// w = v₀ + κ₀ e₃ [m/s] and the position quadratic of the step from x₀ \[m\], v₀ [m/s]: μ [1/s]
    /// is to be found from it (the series, the closed form, or `PositionQuadratic::multiplier`'s
    /// choice of the two) and handed to [`VerticalField::finish`].
    #[inline(always)]
    pub fn quadratic(&self, x0: DVec3, v0: DVec3) -> (DVec3, PositionQuadratic) {
        let w = DVec3::new(v0.x, v0.y, v0.z + self.kick0);
        (w, PositionQuadratic::new::<Fused>(x0, w, self.h, self.l2))
    }

    /// The rest of the step from x₀ \[m\], v₀ [m/s] with compensations `comp_x`, `comp_v`, given w and
    /// the quadratic of [`VerticalField::quadratic`] and its multiplier μ [1/s] (module doc).
    #[inline(always)]
    pub fn finish(
        &self,
        (x0, v0): (DVec3, DVec3),
        (w, quad): (DVec3, &PositionQuadratic),
        mu: f64,
        (comp_x, comp_v): (DVec3, DVec3),
    ) -> StepEnd {
        let &Self { h, kick0, kick1, inv_l2, .. } = self;
        let f = fmadd::<Fused>;
        let xe = f(x0.z, kick1, quad.xw);
        let we = f(w.z, kick1, quad.ww);
        let (a, b, c) = (f(h, we, xe), f(h, xe, quad.b), h * quad.q);
        let p = f(mu, f(mu, c, b), a) * inv_l2;
        let mut comp_x = comp_x;
        let x1 = advance_position::<Fused>(x0, fmadd3::<Fused>(x0, mu, w), h, &mut comp_x);
        let inner = DVec3::new(
            f(x0.x, mu, -comp_v.x),
            f(x0.y, mu, -comp_v.y),
            f(x0.z, mu, (kick0 + kick1) - comp_v.z),
        );
        let y = fmadd3::<Fused>(x1, -p, inner);
        let v1 = v0 + y;
        StepEnd { x: x1, v: v1, comp_x, comp_v: (v1 - v0) - y, mu }
    }
}
