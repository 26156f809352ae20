//! The step-size controller of DOP853 ([`super::dop853::Dop853`]), apart from the method (Hairer,
//! Nørsett & Wanner 1993, Sec. II.4, and their code dop853.f): from the error estimate err of a step
//! of h [s] (err ≤ 1: accept),
//!
//!   h_new = h / clamp(err^{1/8} / 0.9, 1/6, 1/0.333),
//!
//! without growth right after a rejection; a rejected step is retried with h / min(1/0.333,
//! err^{1/8} / 0.9). The trial step is capped by h_max, stretched to land on the stop time when within
//! 1.01 h of it, and refused below round-off of t. Times and steps in s.
//!
//! Without projection the state drifts off TS², and T-2.4 is unstable there wherever the rod pushes
//! (the bob high and slow, g z > |v|², docs/theory.md T-2.4: the error δ = |x|²/l² − 1 obeys
//! l² δ̈ = 2 (g z − |v|²) δ), so near the top the drift grows until no step meets the tolerance. An
//! underflow then names the drift ([`off_sphere`]) and says to project (`error::hint::drift_advice`).

use crate::error::{Error, Result};
use glam::DVec3;

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
            return Err(Error::StepSizeUnderflow {
                t: t0,
                h,
                rtol: self.rtol,
                atol: self.atol,
                off_sphere: None,
            });
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

/// `e` with the constraint residuals of the state (`x` [m], `v` [m/s]) at the start of the failed step
/// when it is a [`Error::StepSizeUnderflow`] of an unprojected run (`project` off) whose state had left
/// TS² of length `length` [m] by more than 100·rtol (a projected step leaves it by about rtol at most):
/// (|x| − l)/l and x·v/(l·|v|) (0 at rest). Any other error, or a state still on TS², is left as it is.
pub(crate) fn off_sphere(e: Error, project: bool, (x, v): (DVec3, DVec3), length: f64) -> Error {
    match e {
        Error::StepSizeUnderflow { t, h, rtol, atol, off_sphere: None } if !project => {
            let radial = x.length() / length - 1.0;
            let speed = v.length();
            let tangential = if speed > 0.0 { x.dot(v) / (length * speed) } else { 0.0 };
            let far = [radial, tangential].iter().any(|r| r.is_nan() || r.abs() > 100.0 * rtol);
            let off_sphere = far.then_some((radial, tangential));
            Error::StepSizeUnderflow { t, h, rtol, atol, off_sphere }
        }
        other => other,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Only the underflow of an unprojected run whose state left TS² by more than 100·rtol names it.
    #[test]
    fn an_underflow_names_the_drift_only_of_an_unprojected_run_off_ts2() {
        let e = Error::StepSizeUnderflow { t: 0.5, h: 1e-17, rtol: 1e-10, atol: 1e-12, off_sphere: None };
        let (on, off) = ((DVec3::new(0.0, 0.0, 1.0), DVec3::X), (DVec3::new(0.0, 0.0, 1.5), DVec3::X));
        assert_eq!(off_sphere(e.clone(), true, off, 1.0), e);
        assert_eq!(off_sphere(e.clone(), false, on, 1.0), e);
        assert_eq!(
            e.to_string(),
            "step size underflow at t = 0.5 s: h = 1e-17 s is too small for rtol = 1e-10, atol = 1e-12"
        );
        let named = off_sphere(e.clone(), false, (DVec3::new(0.0, 0.0, 1.5), DVec3::Z), 1.0);
        assert!(
            matches!(named, Error::StepSizeUnderflow { off_sphere: Some((r, c)), .. } if r == 0.5 && c == 1.5)
        );
        let words = named.to_string();
        assert!(words.contains("(|x| - l)/l = 0.5 and x·v/(l·|v|) = 1.5"), "{words}");
        assert!(words.contains("use project=True (the default)"), "{words}");
        let rest = off_sphere(e, false, (DVec3::new(0.0, 0.0, 1.5), DVec3::ZERO), 1.0);
        assert!(rest.to_string().contains("x·v/(l·|v|) = 0:"), "{rest}");
        let other = Error::Diverged { t: 0.5, method: "dop853", dt: 0.1 };
        assert_eq!(off_sphere(other.clone(), false, off, 1.0), other);
    }
}
