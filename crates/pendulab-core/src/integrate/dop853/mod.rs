//! Adaptive Dormand–Prince 8(5,3), "DOP853" (Hairer, Nørsett & Wanner 1993, Sec. II.10), on the
//! Cartesian first-order system T-2.4 with y = (x, v) ∈ R⁶ (x in m, v in m/s, t in s):
//!
//!   ẋ = v,   v̇ = f(t, x, v) + λ x,   λ = −(|v|² + x·f)/l²    (T-2.4, f the applied acceleration)
//!
//! One step uses the 12 stages of the 8th-order formula; the local error is estimated as in
//! Hairer's code by blending a 5th- and a 3rd-order embedded estimate,
//!
//!   err = |h| · ‖e₅‖² / √(N (‖e₅‖² + 0.01 ‖e₃‖²)),  components scaled by atol + rtol·max(|y₀|, |y₁|),
//!
//! with N = 6, and the step size is controlled by h_new = h / clamp(err^{1/8} / 0.9, 1/6, 1/0.333)
//! (no step growth right after a rejection; the controller is `dop853_control.rs`, apart from the
//! method). The initial step follows Hairer's `hinit`.
//!
//! **Projection.** TS² is invariant but unstable for T-2.4, so by default every accepted step is
//! followed by the projection x ← l x/|x|, v ← v − (x·v/l²) x ([`project_onto_tangent_bundle`]);
//! f at the new point (the first stage of the next step, "first same as last") is then evaluated at the
//! projected state, so a step costs 12 evaluations with or without projection.
//!
//! The files: this one (the method: `Dop853`, its first step, a step with its error estimate and
//! step-size control, the accepted step's projections), `system.rs` (the system T-2.4 as one point y
//! of R⁶, its right-hand side and error weights), `dense.rs` (the dense output of order 7),
//! `invariants.rs` (`conserve=True`: ½|v|² and J₃ imposed after the step, T-8.5).

use super::dop853_control::{off_sphere, StepControl};
use super::dop853_tableau::{A, B, C, E3, E5, STAGES, STAGES_DENSE};
use super::Stats;
use crate::error::{Error, Result};
use crate::model::Model;
use crate::state::{project_onto_tangent_bundle, State};
use glam::DVec3;

/// Smallest relative tolerance accepted: below ~10 ulp the error estimate is round-off.
pub const RTOL_MIN: f64 = 1e-15;
const ERROR_EXPONENT: f64 = 1.0 / 8.0;

mod dense;
mod invariants;
mod system;

pub use invariants::project_invariants;
pub(crate) use system::{error_scale, rhs, Y6};

/// Hairer's `hinit`: a first step [s] from (t, y) with f0 = f(t, y), from the sizes of y, f and an
/// estimate of f', capped by `h_max` and `span` [s] (shared with the vectorised ensemble,
/// `ensemble/adaptive_lanes.rs`, so that both take the same first step).
#[inline(always)]
pub(crate) fn initial_step<M: Model>(
    atol: f64,
    rtol: f64,
    h_max: f64,
    model: &M,
    (t, y, f0): (f64, Y6, Y6),
    span: f64,
    stats: &mut Stats,
) -> f64 {
    let sk = error_scale(atol, rtol, y, y);
    let (dnf, dny) = (f0.scaled_norm2(sk), y.scaled_norm2(sk));
    let usable = dnf.is_finite() && dny.is_finite() && dnf > 1e-10 && dny > 1e-10;
    let mut h = if usable { (dny / dnf).sqrt() * 0.01 } else { 1e-6 };
    h = h.min(h_max).min(span);
    let f1 = rhs(model, t + h, y.axpy(h, f0));
    stats.rhs_evals += 1;
    let der2 = f1.sub(f0).scaled_norm2(sk).sqrt() / h;
    let der12 = der2.max(dnf.sqrt());
    let h1 = if !der12.is_finite() {
        h
    } else if der12 <= 1e-15 {
        (h * 1e-3).max(1e-6)
    } else {
        (0.01 / der12).powf(ERROR_EXPONENT)
    };
    (100.0 * h).min(h1).min(h_max).min(span)
}

/// Where a step from `t0` \[s\] towards `t_stop` \[s\] (may be +∞) must end at the latest: the model's
/// next break ([`Model::next_break`]) when it comes first, unless it lies within round-off of t_stop
/// (a sliver of a step from it to t_stop would be below the smallest step); else t_stop. Shared with
/// the vectorised ensemble.
#[inline(always)]
pub(crate) fn step_end<M: Model>(model: &M, t0: f64, t_stop: f64) -> f64 {
    let b = model.next_break(t0);
    if b < t_stop - 64.0 * f64::EPSILON * t_stop.abs().max(b.abs()) {
        b
    } else {
        t_stop
    }
}

/// The accepted y₁ of a step of `h` [s] from `t0` [s], projected onto TS² of length `length` [m]
/// when `project` is on, and then onto the start's energy and J₃ (`targets`, where the model keeps
/// them) when `invariants` is on; shared with the vectorised ensemble. A y₁ that cannot be projected
/// (|x| zero or not finite) is [`Error::Diverged`] naming `t0`, the time of the last good state (as
/// every other divergence does), not the step's end.
#[inline(always)]
pub(crate) fn project_accepted<M: Model>(
    model: &M,
    (project, invariants, length): (bool, bool, f64),
    targets: Option<(DVec3, f64, f64)>,
    (t0, y1): (f64, Y6),
    h: f64,
) -> Result<Y6> {
    if !project {
        return Ok(y1);
    }
    let mut p = project_onto_tangent_bundle(length, y1.x, y1.v).ok_or(Error::Diverged {
        t: t0,
        method: "dop853",
        dt: h,
    })?;
    if let (true, Some((x0, k0, j0))) = (invariants, targets) {
        let e = model.is_conservative().then(|| k0 - model.potential_change_per_mass(x0, p.x));
        // J₃ is an invariant only without damping, drag, forcing or a frame: axisymmetry
        // alone is not enough (damping makes J₃ decay like e^{−ct}).
        let kept = model.is_axisymmetric() && model.is_conservative() && !model.has_velocity_forces();
        let j = kept.then_some(j0);
        p.v = project_invariants(p.x, p.v, e, j);
    }
    Ok(Y6::from(p))
}

/// DOP853 with its step-size controller and the data of its last accepted step.
#[derive(Debug, Clone)]
pub struct Dop853 {
    rtol: f64,
    atol: f64,
    project: bool,
    h_max: f64,
    h_init: Option<f64>,
    /// Step size proposed for the next step (None before the first step and after `reset`).
    h_next: Option<f64>,
    /// f at the current point (first same as last), valid when `h_next` is set.
    f_current: Y6,
    /// Stages of the last accepted step (0‥11), f at its end (12), dense-output stages (13‥15).
    k: [Y6; STAGES_DENSE],
    t_old: f64,
    h_old: f64,
    y_old: Y6,
    y_new: Y6,
    /// Interpolant coefficients F₀‥F₆ of the last step, formed on first request.
    dense: Option<[Y6; 7]>,
    length: f64,
    /// Project also onto the level set of E (conservative models) and J₃ (axisymmetric ones).
    invariants: bool,
    /// The start x₀ [m], ½|v₀|² [J/kg] and J₃/m [m²/s] (captured at the first step after `new` or
    /// `reset`): the kinetic energy imposed at x is ½|v₀|² − (V(x) − V(x₀)), the potential change
    /// measured from the nearer pole ([`Model::potential_change_per_mass`]), not E/m − V(x), which
    /// cancels near the bottom and the top (a 1e-6 rad swing would lose four digits of ½|v|²).
    targets: Option<(DVec3, f64, f64)>,
}

impl Dop853 {
    /// A new integrator. `rtol` ∈ [1e-15, 1] and `atol` ≥ 0 [m and m/s] are the tolerances;
    /// `h_max` \[s\] caps the step (∞ for none); `h_init` \[s\] is the first step (None: Hairer's guess).
    pub fn new(rtol: f64, atol: f64, project: bool, h_max: f64, h_init: Option<f64>) -> Result<Self> {
        if !(RTOL_MIN..=1.0).contains(&rtol) {
            return Err(Error::InvalidParameter {
                name: "rtol",
                value: rtol,
                allowed:
                    "the relative tolerance rtol must be a number in [1e-15, 1] (float64 cannot resolve less)",
            });
        }
        if !(atol >= 0.0 && atol.is_finite()) {
            return Err(Error::InvalidParameter {
                name: "atol",
                value: atol,
                allowed: "the absolute tolerance atol must be a finite number >= 0 (m and m/s)",
            });
        }
        if h_max.is_nan() || h_max <= 0.0 {
            return Err(Error::InvalidParameter {
                name: "h_max",
                value: h_max,
                allowed: "the largest step h_max must be > 0 s (infinity for no limit)",
            });
        }
        if let Some(h) = h_init {
            if !(h > 0.0 && h.is_finite()) {
                return Err(Error::InvalidParameter {
                    name: "dt",
                    value: h,
                    allowed: "the initial step of dop853 must be a finite number > 0 s (or 0 for automatic)",
                });
            }
        }
        Ok(Self {
            rtol,
            atol,
            project,
            h_max,
            h_init,
            h_next: None,
            f_current: Y6::default(),
            k: [Y6::default(); STAGES_DENSE],
            t_old: f64::NAN,
            h_old: 0.0,
            y_old: Y6::default(),
            y_new: Y6::default(),
            dense: None,
            length: f64::NAN,
            invariants: false,
            targets: None,
        })
    }

    /// Also projects v after every step so that E (conservative models) and J₃ (axisymmetric models)
    /// keep their initial values (GNI IV.4 projection, velocity only): see [`project_invariants`].
    pub fn set_invariant_projection(&mut self, on: bool) {
        self.invariants = on;
        self.targets = None;
    }

    /// Forgets the step-size history (call when the state is replaced).
    pub fn reset(&mut self) {
        self.h_next = None;
        self.dense = None;
        self.t_old = f64::NAN;
        self.targets = None;
    }

    /// The interval [t₀, t₁] \[s\] of the last accepted step (empty/NaN before the first step).
    pub fn last_step_interval(&self) -> (f64, f64) {
        (self.t_old, self.t_old + self.h_old)
    }

    /// Hairer's `hinit` ([`initial_step`]) with this integrator's tolerances and h_max.
    fn initial_step<M: Model>(&self, model: &M, t: f64, y: Y6, f0: Y6, span: f64, stats: &mut Stats) -> f64 {
        initial_step(self.atol, self.rtol, self.h_max, model, (t, y, f0), span, stats)
    }

    /// One accepted step from (`t`, `s`), never past `t_stop` \[s\] (which may be +∞) nor past the
    /// model's next break ([`Model::next_break`]: a step ends on it, not across); rejected
    /// attempts are counted in `stats`. Fails with [`Error::StepSizeUnderflow`] when the tolerance
    /// cannot be met with a step above round-off of t (e.g. the solution became non-finite).
    ///
    /// The method (`Dop853::attempt`: stages, solution, error estimate; `Dop853::accept`:
    /// projection and the data of the step) is separate from the step-size controller
    /// (`StepControl`: the trial step, the factors after acceptance and rejection).
    ///
    /// Inlined (with its stages) into its caller, so that the stages are compiled for the
    /// instruction set the caller was dispatched to ([`crate::Stepper`] runs it inside
    /// [`crate::isa::fastest`]).
    #[inline(always)]
    pub fn step<M: Model>(
        &mut self,
        model: &M,
        t: &mut f64,
        s: &mut State,
        t_stop: f64,
        stats: &mut Stats,
    ) -> Result<()> {
        let t0 = *t;
        if t_stop.is_nan() || t_stop <= t0 {
            return Err(Error::InvalidParameter {
                name: "t_stop",
                value: t_stop,
                allowed: "dop853 steps forward only: the stop time must be later than the current time (s)",
            });
        }
        self.length = model.params().length;
        if self.invariants && self.targets.is_none() {
            self.targets = Some((s.x, 0.5 * s.v.length_squared(), s.x.x * s.v.y - s.x.y * s.v.x));
        }
        let y0 = Y6::from(*s);
        let span = t_stop - t0;
        let mut h = match self.h_next {
            Some(h) => h,
            None => {
                self.f_current = rhs(model, t0, y0);
                stats.rhs_evals += 1;
                match self.h_init {
                    Some(h) => h.min(self.h_max),
                    None => self.initial_step(model, t0, y0, self.f_current, span, stats),
                }
            }
        };
        // the step ends on the model's next break (a kink of a sampled pivot's p̈) rather than crossing
        // it; the first step above is still sized for the whole span (as the ensemble's lanes do)
        let t_stop = step_end(model, t0, t_stop);
        let control = StepControl { h_max: self.h_max, rtol: self.rtol, atol: self.atol };
        let mut rejected_last = false;
        self.k[0] = self.f_current;
        loop {
            let (h_trial, last) = control
                .trial(h, t0, t_stop)
                .map_err(|e| off_sphere(e, self.project, (y0.x, y0.v), self.length))?;
            h = h_trial;
            let (y1, err) = self.attempt(model, t0, y0, h);
            stats.rhs_evals += (STAGES - 1) as u64;
            let root = StepControl::error_root(err);
            if err <= 1.0 {
                let h_new = StepControl::after_accept(h, root, rejected_last);
                let t1 = if last { t_stop } else { t0 + h };
                self.accept(model, (t0, y0), (t1, y1), h, stats)?;
                // Do not let a short landing step shrink the next proposal.
                let keep = if last && !rejected_last { self.h_next } else { None };
                self.h_next = Some(keep.map_or(h_new, |p| p.max(h_new)));
                *t = t1;
                *s = State { x: self.y_new.x, v: self.y_new.v };
                stats.steps += 1;
                return Ok(());
            }
            h = StepControl::after_reject(h, root);
            rejected_last = true;
            stats.rejected += 1;
        }
    }

    /// The method: stages 1‥11 of a step of `h` [s] from (`t0`, `y0`) (stage 0, f(t0, y0), is in
    /// `k[0]`), the 8th-order solution y₁ and the blended error estimate `err` (≤ 1: acceptable).
    #[inline(always)]
    fn attempt<M: Model>(&mut self, model: &M, t0: f64, y0: Y6, h: f64) -> (Y6, f64) {
        let k = &mut self.k;
        // Stage i uses k₀ … k_{i−1} (A is strictly lower triangular), written out per stage so
        // that every loop has a constant length and unrolls (zeros of A included: 0·k adds
        // nothing); the newest stage is added last, so the sum of the older ones is ready while
        // k_{i−1} is computed.
        macro_rules! stage {
            ($($i:literal)*) => {$(
                let mut yi = y0;
                for j in 0..$i {
                    yi = yi.axpy(h * A[$i][j], k[j]);
                }
                k[$i] = rhs(model, t0 + C[$i] * h, yi);
            )*};
        }
        stage!(1 2 3 4 5 6 7 8 9 10 11);
        let (mut incr, mut e5, mut e3) = (Y6::default(), Y6::default(), Y6::default());
        for i in 0..STAGES {
            incr = incr.axpy(B[i], k[i]);
            e5 = e5.axpy(E5[i], k[i]);
            e3 = e3.axpy(E3[i], k[i]);
        }
        let y1 = y0.axpy(h, incr);
        let sk = error_scale(self.atol, self.rtol, y0, y1);
        let (n5, n3) = (e5.scaled_norm2(sk), e3.scaled_norm2(sk));
        let err = if n5 == 0.0 && n3 == 0.0 { 0.0 } else { h * n5 / (6.0 * (n5 + 0.01 * n3)).sqrt() };
        (y1, err)
    }

    /// Takes the accepted step `h` [s] from (`t0`, `y0`) to (`t1`, `y1`): projects y₁ (when on),
    /// evaluates f there (the next step's first stage) and keeps the step's data for the dense output.
    #[inline(always)]
    fn accept<M: Model>(
        &mut self,
        model: &M,
        (t0, y0): (f64, Y6),
        (t1, y1): (f64, Y6),
        h: f64,
        stats: &mut Stats,
    ) -> Result<()> {
        let flags = (self.project, self.invariants, self.length);
        let y1 = project_accepted(model, flags, self.targets, (t0, y1), h)?;
        let f1 = rhs(model, t1, y1);
        stats.rhs_evals += 1;
        self.k[STAGES] = f1;
        self.f_current = f1;
        self.t_old = t0;
        self.h_old = t1 - t0;
        self.y_old = y0;
        self.y_new = y1;
        self.dense = None;
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::IdealPendulum;

    #[test]
    fn a_step_that_cannot_be_projected_names_its_start_the_last_good_state() {
        // |x| = 0 or not finite after an accepted step: no point of TS² to project to. Named was
        // the step's end t1 (0.375 s here), a time no state was ever computed at; now its start,
        // as the controller's own divergence (`StepControl::trial`) and every other method name it
        let m = IdealPendulum::new(1.0, 1.0, 9.81).unwrap();
        let mut d = Dop853::new(1e-10, 1e-12, true, f64::INFINITY, None).unwrap();
        d.length = 1.0;
        let y0 = Y6 { x: DVec3::new(0.0, 0.0, -1.0), v: DVec3::X };
        for x in [DVec3::ZERO, DVec3::new(f64::INFINITY, 0.0, 0.0), DVec3::splat(1e300)] {
            let y1 = Y6 { x, v: DVec3::X };
            let e = d.accept(&m, (0.25, y0), (0.375, y1), 0.125, &mut Stats::default()).unwrap_err();
            assert!(
                matches!(e, Error::Diverged { t, method: "dop853", dt } if t == 0.25 && dt == 0.125),
                "{e}"
            );
        }
        // without projection nothing is checked here (the solver checks the saved state)
        let y1 = Y6 { x: DVec3::ZERO, v: DVec3::X };
        assert!(project_accepted(&m, (false, false, 1.0), None, (0.25, y1), 0.125).is_ok());
    }
}
