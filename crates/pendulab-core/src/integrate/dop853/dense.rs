//! DOP853's dense output of order 7 (Hairer's `contd8`; docs/theory.md T-8.5): on first request
//! after a step, three extra stages are computed and the interpolant
//!
//!   y(t₀ + θh) = y₀ + θ(F₀ + (1−θ)(F₁ + θ(F₂ + (1−θ)(F₃ + θ(F₄ + (1−θ)(F₅ + θF₆))))))
//!
//! is formed, with F₀ = Δy, F₁ = h f₀ − Δy, F₂ = 2Δy − h(f₁ + f₀), F₃‥₆ = h Σ dᵢⱼ kⱼ. It passes
//! through y₀ and the (projected) y₁ with the right slopes; with projection on, interpolated states
//! are projected onto TS² as well (T-1.1). Times in s, x in m, v in m/s.

use super::super::dop853_tableau::{A, C, D, STAGES, STAGES_DENSE};
use super::system::{rhs, Y6};
use super::Dop853;
use crate::model::Model;
use crate::state::{project_onto_tangent_bundle, State};

impl Dop853 {
    /// The state at `t_out` ∈ [t₀, t₁] \[s\] of the last accepted step, from the order-7 interpolant
    /// (projected onto TS² when projection is on). Costs three evaluations on the first call per step.
    /// Inlined like [`Dop853::step`] ([`crate::Stepper::dense_output`] dispatches it).
    #[inline(always)]
    pub fn dense_output<M: Model>(&mut self, model: &M, t_out: f64) -> State {
        let h = self.h_old;
        // The ends exactly, not up to the interpolant's round-off.
        if t_out == self.t_old + h {
            return State { x: self.y_new.x, v: self.y_new.v };
        } else if t_out == self.t_old {
            return State { x: self.y_old.x, v: self.y_old.v };
        }
        let dense = match self.dense {
            Some(d) => d,
            None => {
                let d = self.interpolant(model);
                self.dense = Some(d);
                d
            }
        };
        let th = if h > 0.0 { (t_out - self.t_old) / h } else { 0.0 };
        let th1 = 1.0 - th;
        let mut acc = dense[6];
        for (i, f) in dense[..6].iter().enumerate().rev() {
            acc = f.axpy(if i % 2 == 0 { th1 } else { th }, acc);
        }
        let y = self.y_old.axpy(th, acc);
        if self.project {
            if let Some(p) = project_onto_tangent_bundle(self.length, y.x, y.v) {
                return p;
            }
        }
        State { x: y.x, v: y.v }
    }

    /// Extra stages 13‥15 and the coefficients F₀‥F₆ (Hairer's `contd8`).
    #[inline(always)]
    fn interpolant<M: Model>(&mut self, model: &M) -> [Y6; 7] {
        let (h, t0, y0) = (self.h_old, self.t_old, self.y_old);
        for i in STAGES + 1..STAGES_DENSE {
            let mut yi = y0;
            for (j, &a) in A[i].iter().enumerate() {
                if a != 0.0 {
                    yi = yi.axpy(h * a, self.k[j]);
                }
            }
            self.k[i] = rhs(model, t0 + C[i] * h, yi);
        }
        let dy = self.y_new.sub(y0);
        let (f0, f1) = (self.k[0], self.k[STAGES]);
        let mut out = [Y6::default(); 7];
        out[0] = dy;
        out[1] = f0.scale(h).sub(dy);
        out[2] = dy.scale(2.0).sub(f0.axpy(1.0, f1).scale(h));
        for (r, drow) in D.iter().enumerate() {
            let mut acc = Y6::default();
            for (j, &d) in drow.iter().enumerate() {
                if d != 0.0 {
                    acc = acc.axpy(d, self.k[j]);
                }
            }
            out[3 + r] = acc.scale(h);
        }
        out
    }
}
