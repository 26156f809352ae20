//! The step-size controller of DOP853 ([`super::dop853::Dop853`]), apart from the method (Hairer,
//! Nørsett & Wanner 1993, Sec. II.4, and their code dop853.f): from the error estimate err of a step
//! of h [s] (err ≤ 1: accept),
//!
//!   h_new = h / clamp(err^{1/8} / 0.9, 1/6, 1/0.333),
//!
//! without growth right after a rejection; a rejected step is retried with h / min(1/0.333,
//! err^{1/8} / 0.9). The trial step is capped by h_max, stretched to land on the stop time when within
//! 1.01 h of it, and refused below round-off of t. Times and steps in s.

use crate::error::{Error, Result};

const SAFETY: f64 = 0.9;
/// Largest step shrink (1/FAC_MIN) and growth (1/FAC_MAX) factors, as in dop853.f.
const FAC_MIN: f64 = 0.333;
const FAC_MAX: f64 = 6.0;

/// The controller's limits: the largest step `h_max` [s], and the tolerances (named when the step
/// underflows).
#[derive(Debug, Clone, Copy)]
pub(crate) struct StepControl {
    pub(crate) h_max: f64,
    pub(crate) rtol: f64,
    pub(crate) atol: f64,
}

impl StepControl {
    /// The trial step from `t0` for the proposal `h`, and whether it lands on `t_stop`: capped by
    /// h_max; the rest of the span when within 1.01 h of `t_stop` (dop853.f: land rather than leave a
    /// sliver). [`Error::StepSizeUnderflow`] when it is NaN or below ten ulp of t, [`Error::Diverged`] when
    /// it or t + h is infinite.
    #[inline(always)]
    pub(crate) fn trial(&self, h: f64, t0: f64, t_stop: f64) -> Result<(f64, bool)> {
        let span = t_stop - t0;
        let mut h = h.min(self.h_max);
        let last = t0 + 1.01 * h >= t_stop;
        if last {
            h = span;
        }
        // a step so large that the time overflows (a state at rest accepts any step, which then
        // grows by FAC_MAX each time; or a first step near f64::MAX): refused, or the rejections
        // would divide an infinite step for ever (tests/fuzz_props.rs hung on it)
        if !(h.is_nan() || (h.is_finite() && (t0 + h).is_finite())) {
            return Err(Error::Diverged { t: t0, method: "dop853", dt: h });
        }
        let h_floor = 10.0 * (t0.abs().max(span.min(1.0)) * f64::EPSILON).max(f64::MIN_POSITIVE);
        if h.is_nan() || h < h_floor {
            return Err(Error::StepSizeUnderflow { t: t0, h, rtol: self.rtol, atol: self.atol });
        }
        Ok((h, last))
    }

    /// err^{1/8} by three square roots: several times cheaper than powf, same to ~1 ulp.
    #[inline(always)]
    pub(crate) fn error_root(err: f64) -> f64 {
        err.sqrt().sqrt().sqrt()
    }

    /// The next step after accepting `h` with error root `root` (no growth after a rejection).
    #[inline(always)]
    pub(crate) fn after_accept(h: f64, root: f64, rejected_last: bool) -> f64 {
        let fac = (root / SAFETY).clamp(1.0 / FAC_MAX, 1.0 / FAC_MIN);
        let h_new = h / fac;
        if rejected_last {
            h_new.min(h)
        } else {
            h_new
        }
    }

    /// The retry after rejecting `h` (err > 1, or NaN: f64::min ignores the NaN and the step shrinks
    /// by 1/FAC_MIN).
    #[inline(always)]
    pub(crate) fn after_reject(h: f64, root: f64) -> f64 {
        h / (1.0 / FAC_MIN).min(root / SAFETY)
    }
}
