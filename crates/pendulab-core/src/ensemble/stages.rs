//! The sub-steps of one ensemble step (T-2.1, T-2.2, T-8.2): one RATTLE step of dt for
//! [`Method::Rattle`], or for [`Method::Rattle4`], `Rattle6` and `Rattle8` the symmetric composition
//! of `integrate/composition.rs`, RATTLE steps of w₁dt, w₂dt, …, w_s dt (3, 7 or 15 of them,
//! palindromic: w_k = w_{s+1−k}, Σ w_k = 1, some w_k < 0), each computed as w_k · dt like the
//! single-trajectory composition, so each trajectory gets its numbers bit for bit. A damped lane's
//! flow v ↦ e^{−c h_k/2} v (T-7.1) then depends on the sub-step; the block keeps one factor per
//! distinct weight (`Block::decay_half`, [`DISTINCT`] rows), stage k using row
//! [`Stages::distinct`]`(k)` = min(k, s − 1 − k). SI units: dt, h_k \[s\].

use crate::error::{Error, Result};
use crate::integrate::composition::Composition;
use crate::integrate::Method;

/// The most sub-steps of one step (the 15 of the order-8 composition).
pub const MOST: usize = 15;
/// The most distinct sub-step sizes of one step (a palindrome of 15 has 8).
pub const DISTINCT: usize = MOST.div_ceil(2);

/// The sub-step sizes h_k \[s\] of one ensemble step of dt.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Stages {
    h: [f64; MOST],
    len: usize,
}

impl Stages {
    /// The sub-steps of `method` for a step of `dt` \[s\]: RATTLE (one, dt itself) or its
    /// composition of order 4, 6, 8 (w_k · dt); other methods are refused.
    pub(crate) fn of(method: Method, dt: f64) -> Result<Self> {
        let order = match method {
            Method::Rattle => {
                let mut h = [0.0; MOST];
                h[0] = dt;
                return Ok(Self { h, len: 1 });
            }
            Method::Rattle4 => 4,
            Method::Rattle6 => 6,
            Method::Rattle8 => 8,
            other => return Err(Error::UnsupportedEnsembleMethod { method: other.info().name }),
        };
        let composition = Composition::of_order(order);
        let weights = composition.weights();
        let mut h = [0.0; MOST];
        for (hk, &w) in h.iter_mut().zip(weights) {
            *hk = w * dt; // as Composition::step writes the sub-step
        }
        Ok(Self { h, len: weights.len() })
    }

    /// How many sub-steps one step takes (1, 3, 7 or 15).
    #[inline(always)]
    pub(crate) fn len(&self) -> usize {
        self.len
    }

    /// Sub-step k's size h_k \[s\].
    #[inline(always)]
    pub(crate) fn h(&self, k: usize) -> f64 {
        self.h[k]
    }

    /// The row of the damping factors that sub-step k uses: the palindrome's sub-steps k and
    /// s − 1 − k have the same size.
    #[inline(always)]
    pub(crate) fn distinct(&self, k: usize) -> usize {
        k.min(self.len - 1 - k)
    }

    /// How many distinct sub-step sizes there are ((s + 1)/2).
    pub(crate) fn distinct_len(&self) -> usize {
        self.len.div_ceil(2)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rattle_is_one_step_of_dt_and_compositions_their_weights_times_dt() {
        let s = Stages::of(Method::Rattle, 1e-3).unwrap();
        assert_eq!((s.len(), s.h(0), s.distinct_len()), (1, 1e-3, 1));
        for (method, len) in [(Method::Rattle4, 3), (Method::Rattle6, 7), (Method::Rattle8, 15)] {
            let s = Stages::of(method, 0.01).unwrap();
            assert_eq!(s.len(), len);
            assert_eq!(s.distinct_len(), len.div_ceil(2));
            for k in 0..len {
                assert_eq!(s.h(k).to_bits(), s.h(len - 1 - k).to_bits(), "{method:?} palindrome");
                assert_eq!(s.h(k).to_bits(), s.h(s.distinct(k)).to_bits());
            }
            let total: f64 = (0..len).map(|k| s.h(k)).sum();
            assert!((total - 0.01).abs() < 1e-15, "{method:?}: Σ h_k = {total}");
            assert!((0..len).any(|k| s.h(k) < 0.0), "{method:?} has a backward sub-step");
            // tile.rs (`Tile::rattle`): the first sub-step is forward, so it leaves every zero
            // component +0, and the backward sub-steps' −0 kick components cannot change a sign
            assert!(s.h(0) > 0.0, "{method:?} begins with a forward sub-step");
        }
        assert!(DISTINCT >= Stages::of(Method::Rattle8, 1.0).unwrap().distinct_len());
    }

    #[test]
    fn other_methods_are_refused_by_name() {
        for m in [Method::Dop853, Method::Rk4, Method::Rkmk4, Method::Rk4Angles] {
            let e = Stages::of(m, 1e-3).unwrap_err().to_string();
            assert!(e.contains(m.info().name) && e.contains("rattle4"), "{e}");
        }
    }
}
