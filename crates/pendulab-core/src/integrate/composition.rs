//! Symmetric compositions of RATTLE (Yoshida 1990; Suzuki 1990; Hairer, Lubich & Wanner,
//! *Geometric Numerical Integration*, II.4 and V.3): one step of size h is the sequence of RATTLE
//! steps of sizes w₁h, w₂h, …, w_s h with palindromic weights (w_i = w_{s+1−i}) summing to 1.
//! A symmetric method of order 2 composed this way reaches order 4, 6 or 8 when the weights solve
//! the order conditions; every sub-step is RATTLE, so the composition inherits symplecticity, the
//! constraints |x| = l, x·v = 0 and J₃ conservation.
//!
//! Weights (one generic composer, coefficients as arrays):
//! - order 4: the triple jump w₁ = w₃ = 1/(2 − 2^{1/3}), w₂ = 1 − 2w₁;
//! - order 6: Yoshida's 7-stage solution A (digits from the 32-digit re-solution used in
//!   accelerator physics codes);
//! - order 8: Yoshida's 15-stage solution D (15 digits as printed in Yoshida 1990, Table 2;
//!   the central weight is 1 − 2Σ so the weights sum to 1 to round-off).

use super::rattle::Rattle;
use super::FixedStep;
use crate::error::{Error, Result};
use crate::model::Model;
use crate::state::State;

/// Outer weights w₁ … w_m of a symmetric composition; the central weight is 1 − 2Σw and the
/// sequence is w_m … w₁, w₀, w₁ … w_m as in Yoshida (1990).
const TRIPLE_JUMP: [f64; 1] = [1.351_207_191_959_657_8]; // 1/(2 − 2^{1/3})
                                                         // 32-digit values: 0.784513610477557263819497633866351, 0.235573213359358133684793182978535,
                                                         // −1.17767998417887100694641568096432 (rounded to the nearest f64 below).
const YOSHIDA6_A: [f64; 3] = [0.784_513_610_477_557_3, 0.235_573_213_359_358_13, -1.177_679_984_178_871];
const YOSHIDA8_D: [f64; 7] = [
    0.914_844_246_229_740,
    0.253_693_336_566_229,
    -1.444_852_236_860_48,
    -0.158_240_635_368_243,
    1.938_139_137_622_76,
    -1.960_610_232_975_49,
    0.102_799_849_391_985,
];

/// The full palindromic weight sequence from the outer weights listed from the outside in.
fn palindrome(outer: &[f64]) -> Vec<f64> {
    let centre = 1.0 - 2.0 * outer.iter().sum::<f64>();
    let mut w: Vec<f64> = outer.to_vec();
    w.push(centre);
    w.extend(outer.iter().rev());
    w
}

/// A symmetric composition of RATTLE steps.
#[derive(Debug, Clone)]
pub struct Composition {
    weights: Vec<f64>,
    order: u32,
    rattle: Rattle,
}

impl Composition {
    /// Composition of the given order: 4 (3 stages), 6 (7 stages) or 8 (15 stages).
    pub fn of_order(order: u32) -> Self {
        let outer: &[f64] = match order {
            4 => &TRIPLE_JUMP,
            6 => &YOSHIDA6_A,
            8 => &YOSHIDA8_D,
            _ => panic!("no RATTLE composition of order {order} is registered (4, 6, 8 are)"),
        };
        Self { weights: palindrome(outer), order, rattle: Rattle::default() }
    }

    /// Chooses the rounding of the RATTLE substeps' multiply-adds ([`Rattle::set_arithmetic`]).
    pub fn set_arithmetic(&mut self, arithmetic: super::rattle_kernel::Arithmetic) {
        self.rattle.set_arithmetic(arithmetic);
    }

    /// The weights w₁ … w_s (sum 1, palindromic).
    pub fn weights(&self) -> &[f64] {
        &self.weights
    }

    /// Declared order.
    pub fn order(&self) -> u32 {
        self.order
    }
}

impl FixedStep for Composition {
    #[inline(always)]
    fn step<M: Model>(&mut self, model: &M, t: f64, s: &mut State, h: f64) -> Result<()> {
        let mut tau = t;
        for &w in &self.weights {
            if !self.rattle.advance(model, tau, s, w * h) {
                // the step's start: the last state computed (tau is inside the step)
                return Err(Error::Diverged { t, method: "rattle composition", dt: h });
            }
            tau += w * h;
        }
        Ok(())
    }

    fn evals_per_step(&self) -> u64 {
        2 * self.weights.len() as u64
    }

    fn reset(&mut self) {
        self.rattle.reset();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn weights_are_palindromic_and_sum_to_one() {
        for order in [4, 6, 8] {
            let c = Composition::of_order(order);
            let w = c.weights();
            assert!((w.iter().sum::<f64>() - 1.0).abs() < 1e-14);
            assert!(w.iter().zip(w.iter().rev()).all(|(a, b)| a == b));
        }
        assert!((TRIPLE_JUMP[0] - 1.0 / (2.0 - 2f64.cbrt())).abs() < 1e-15);
    }

    #[test]
    fn third_order_condition_holds() {
        // For a symmetric composition of a symmetric 2nd-order method, order ≥ 4 needs Σ w³ = 0.
        for order in [4, 6, 8] {
            let s3: f64 = Composition::of_order(order).weights().iter().map(|w| w * w * w).sum();
            assert!(s3.abs() < 1e-13, "order {order}: Σw³ = {s3}");
        }
        // Order ≥ 6 also needs Σ w⁵ = 0.
        for order in [6, 8] {
            let s5: f64 = Composition::of_order(order).weights().iter().map(|w| w.powi(5)).sum();
            assert!(s5.abs() < 1e-12, "order {order}: Σw⁵ = {s5}");
        }
    }
}
