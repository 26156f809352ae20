//! Integration of the crane system ([`CraneSystem`], T-11.5 – T-11.7) by adaptive Dormand–Prince 8(5,3)
//! (the tableau of [`crate::integrate::dop853`]; Hairer, Nørsett & Wanner 1993, Sec. II.10) on
//! y ∈ R¹⁶ (positions \[m\], velocities [m/s], works \[J\]), with the projection onto the constraints
//! (T-11.5) after every accepted step. The steps end exactly on every save time and on every jump of
//! the prescribed motions (a trapezoidal move's acceleration steps), so no step straddles a jump and
//! the stages of a step use the prescribed motion's piece of that step. Error estimate and step
//! control as in `integrate/dop853/` (Hairer's blended 5th/3rd-order estimate, N = 16 components scaled by
//! atol + rtol·max(|y₀|, |y₁|); the works enter with the same tolerances, scaled by 1/m₁ so they are
//! of the order of a velocity squared times a length).
//!
//! Stops with [`Error::Crane`] when the rope (T₁ < 0) or the rigging (T₂ < 0) goes slack, when the
//! rope length is ≤ 0, and with [`Error::StepSizeUnderflow`] when the step collapses.

use super::dynamics::{CraneSystem, DIM, Y};
use crate::error::{Error, Result};
use crate::integrate::dop853_tableau::{A, B, C, E3, E5, STAGES};

/// What a run saves at each save time: t \[s\], the state y and the tensions (T₁, T₂) \[N\].
#[derive(Debug, Clone, Default)]
pub struct CraneOutput {
    /// Save times \[s\].
    pub t: Vec<f64>,
    /// States y (see [`super::dynamics`]).
    pub y: Vec<Y>,
    /// Rope and rigging tension \[N\].
    pub tension: Vec<(f64, f64)>,
    /// Accepted and rejected steps.
    pub steps: (u64, u64),
}

/// Tolerances of a run.
#[derive(Debug, Clone, Copy)]
pub struct Tolerances {
    /// Relative tolerance (≥ 1e-14).
    pub rtol: f64,
    /// Absolute tolerance (> 0).
    pub atol: f64,
    /// Maximum number of steps (bounds the work).
    pub max_steps: u64,
}

const SAFETY: f64 = 0.9;
const FAC_MIN: f64 = 0.333;
const FAC_MAX: f64 = 6.0;

fn axpy(y: &Y, a: f64, k: &Y, out: &mut Y) {
    for i in 0..DIM {
        out[i] = y[i] + a * k[i];
    }
}

/// One DOP853 attempt of `h` from (t0, y0) with k[0] = f(t0, y0): (y₁, err).
fn attempt(
    sys: &CraneSystem,
    t0: f64,
    y0: &Y,
    h: f64,
    k: &mut [Y; STAGES],
    weight: &[f64; DIM],
    tol: &Tolerances,
) -> (Y, f64) {
    let t_piece = t0 + 0.5 * h;
    for i in 1..STAGES {
        let mut yi = *y0;
        for (j, kj) in k.iter().enumerate().take(i) {
            let a = A[i][j];
            if a != 0.0 {
                for d in 0..DIM {
                    yi[d] += h * a * kj[d];
                }
            }
        }
        k[i] = sys.eval(t0 + C[i] * h, t_piece, &yi).dy;
    }
    let (mut incr, mut e5, mut e3) = ([0.0; DIM], [0.0; DIM], [0.0; DIM]);
    for (i, ki) in k.iter().enumerate() {
        for d in 0..DIM {
            incr[d] += B[i] * ki[d];
            e5[d] += E5[i] * ki[d];
            e3[d] += E3[i] * ki[d];
        }
    }
    let mut y1 = [0.0; DIM];
    axpy(y0, h, &incr, &mut y1);
    let (mut n5, mut n3) = (0.0, 0.0);
    for d in 0..DIM {
        let sc = (tol.atol + tol.rtol * (y0[d] * weight[d]).abs().max((y1[d] * weight[d]).abs())) / weight[d];
        n5 += (e5[d] / sc).powi(2);
        n3 += (e3[d] / sc).powi(2);
    }
    let err = if n5 == 0.0 && n3 == 0.0 { 0.0 } else { h * n5 / (DIM as f64 * (n5 + 0.01 * n3)).sqrt() };
    (y1, err)
}

fn check_state(sys: &CraneSystem, t: f64, t_piece: f64, y: &Y) -> Result<(f64, f64)> {
    let l = sys.hoist.eval_on(t, t_piece).0.x;
    if l.is_nan() || l <= 0.0 {
        return Err(Error::Crane {
            reason: format!("the rope length is {l} m at t = {t} s; it must stay > 0 m"),
        });
    }
    let e = sys.eval(t, t_piece, y);
    let (t1, t2) = e.tension;
    // round-off allowance: a rope hanging in zero gravity has tension 0 ± a few ulp of the weight scale
    let mass = sys.body1.mass + sys.body2.map_or(0.0, |(b, _)| b.mass);
    let slack = 1e-9 * mass * sys.g.abs().max(1.0);
    if !(t1.is_finite() && t2.is_finite() && y.iter().all(|v| v.is_finite())) {
        return Err(Error::Crane { reason: format!("the state is not finite at t = {t} s") });
    }
    if t1 < -slack {
        return Err(Error::Crane {
            reason: format!("the rope goes slack at t = {t:.6} s (tension {t1:.6e} N < 0): the model needs a taut rope; hoist or move more gently"),
        });
    }
    if t2 < -slack {
        return Err(Error::Crane {
            reason: format!("the rigging goes slack at t = {t:.6} s (tension {t2:.6e} N < 0): the model needs taut rigging"),
        });
    }
    Ok(e.tension)
}

/// Integrates from (t0, y0) (projected first) to the last of `save` (increasing, ≥ t0) and returns
/// the states at the save times.
pub fn run(sys: &CraneSystem, t0: f64, y0: Y, save: &[f64], tol: Tolerances) -> Result<CraneOutput> {
    sys.validate()?;
    if !(tol.rtol >= 1e-14 && tol.rtol.is_finite() && tol.atol > 0.0 && tol.atol.is_finite()) {
        return Err(Error::InvalidParameter {
            name: "rtol/atol",
            value: tol.rtol,
            allowed: "rtol >= 1e-14 and atol > 0",
        });
    }
    if save.is_empty()
        || save[0] < t0
        || save.windows(2).any(|w| w[1] <= w[0])
        || !save.iter().all(|t| t.is_finite())
    {
        return Err(Error::InvalidSaveTimes {
            reason: "save times must be finite, increasing and >= the start time".into(),
        });
    }
    let t_end = save[save.len() - 1];
    let mut stops: Vec<f64> =
        sys.pivot.breaks().into_iter().chain(sys.hoist.breaks()).filter(|&b| b > t0 && b < t_end).collect();
    stops.extend_from_slice(save);
    stops.sort_by(f64::total_cmp);
    stops.dedup();
    let mut weight = [1.0; DIM];
    for w in weight.iter_mut().skip(12) {
        *w = 1.0 / sys.body1.mass;
    }
    let mut y = y0;
    let mut t = t0;
    sys.project(t, t, &mut y)
        .ok_or(Error::Crane { reason: "the start has the load on the pivot (zero rope)".into() })?;
    let mut out = CraneOutput::default();
    let mut k = [[0.0; DIM]; STAGES];
    let mut h = 1e-3_f64.min(t_end - t0).max(1e-9);
    let (mut accepted, mut rejected) = (0u64, 0u64);
    let mut save_i = 0;
    let span_scale = t0.abs().max(t_end.abs()).max(1.0);
    // stops closer than this to the current time count as reached (two stops a rounding error apart)
    let tiny = 64.0 * f64::EPSILON * span_scale;
    for &stop in &stops {
        while stop - t > tiny {
            let last = t + 1.01 * h >= stop;
            let step = if last { stop - t } else { h };
            if step < 10.0 * f64::EPSILON * span_scale {
                let (rtol, atol) = (tol.rtol, tol.atol);
                return Err(Error::StepSizeUnderflow { t, h: step, rtol, atol, off_sphere: None });
            }
            k[0] = sys.eval(t, t + 0.5 * step, &y).dy;
            let (mut y1, err) = attempt(sys, t, &y, step, &mut k, &weight, &tol);
            let root = err.powf(1.0 / 8.0);
            if err <= 1.0 {
                let t1 = if last { stop } else { t + step };
                sys.project(t1, t + 0.5 * step, &mut y1).ok_or(Error::Crane {
                    reason: format!("a rope collapsed to zero length at t = {t1} s"),
                })?;
                y = y1;
                t = t1;
                accepted += 1;
                let grown = step / (root / SAFETY).clamp(1.0 / FAC_MAX, 1.0 / FAC_MIN);
                h = if last { h.max(grown) } else { grown };
                check_state(sys, t, t - 0.5 * step, &y)?;
            } else {
                h = step / (1.0 / FAC_MIN).min(root / SAFETY);
                rejected += 1;
                if !h.is_finite() {
                    return Err(Error::Crane { reason: format!("the motion is not finite near t = {t} s") });
                }
            }
            if accepted + rejected > tol.max_steps {
                return Err(Error::Crane {
                    reason: format!(
                        "more than {} steps before t = {t} s (raise the tolerances or shorten t_end)",
                        tol.max_steps
                    ),
                });
            }
        }
        if save_i < save.len() && save[save_i] == stop {
            let ten = check_state(sys, t, t, &y)?;
            out.t.push(stop);
            out.y.push(y);
            out.tension.push(ten);
            save_i += 1;
        }
    }
    out.steps = (accepted, rejected);
    Ok(out)
}
