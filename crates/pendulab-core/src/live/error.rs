//! The global error of a live run, in every frame record's `error_x` \[m\] (docs/web.md, "Error
//! estimate"), as the Python server's `pendulab.server.live_error` computes it:
//!
//! - **exact** (the ideal pendulum): |x − x_exact(t)| against the exact solution from the same start
//!   (T-4.1–T-4.6);
//! - **richardson** (fixed-step methods of order p): a companion from the same start whose every
//!   (sub-)step is half of one of the run's ([`LiveStepper::halved`]: for the rod models the run itself
//!   with each step taken as two halves, `Stepper::set_halved_steps`, as `simulate(...,
//!   error_estimate=True)` does on a sampled pivot), advanced to the same grid points;
//!   e ≈ |x_h − x_{h/2}| · 2^p/(2^p − 1) (Hairer, Nørsett & Wanner I, §II.4);
//! - **companion** (`dop853`): a companion at rtol_c = rtol/10 (×10 when rtol is within 2× of 1e-15),
//!   atol scaled alike, landing on the same times; e ≈ |x − x_c| / |1 − rtol_c/rtol|.
//!
//! The companion steps only in what is left of the tick's budget; records it has not reached keep
//! [`UNKNOWN`] and it catches up later.

use super::budget::{Budget, Slicer};
use super::frame::{Record, ERROR_X, UNKNOWN};
use super::pendulum::{LivePendulum, LiveStepper};
use crate::error::Result;
use crate::exact::ExactSolution;
use crate::state::State;
use crate::stepper::SolveOptions;

/// The companion's tolerance factor for `dop853` (`pendulab.accuracy.estimate.COMPANION_FACTOR`).
pub const COMPANION_FACTOR: f64 = 0.1;
/// The smallest rtol of `dop853`.
pub const RTOL_MIN: f64 = 1e-15;

/// How the error is obtained.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum How {
    /// Against the exact solution.
    Exact,
    /// Richardson extrapolation against a companion of halved steps.
    Richardson,
    /// A tighter-tolerance `dop853` companion.
    Companion,
}

impl How {
    /// The status's name.
    pub fn name(self) -> &'static str {
        match self {
            How::Exact => "exact",
            How::Richardson => "richardson",
            How::Companion => "companion",
        }
    }
}

/// The companion's settings: dt \[s\], or rtol and atol.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Reference {
    /// None (exact, or no estimate).
    None,
    /// A fixed step \[s\]: dt/2, each step of the companion (half of one of the run's).
    Dt(f64),
    /// Tolerances.
    Tol {
        /// Relative.
        rtol: f64,
        /// Absolute [m, m/s].
        atol: f64,
    },
}

/// The live error estimate of one stepper's run from its start.
#[derive(Debug, Clone)]
pub struct LiveError {
    /// Start time \[s\]: the error is counted from here.
    pub t0: f64,
    /// The start state (x \[m\], v [m/s]) the error is counted from.
    pub start: State,
    /// How (None: no estimate; `note` says why).
    pub how: Option<How>,
    /// The method's order (Richardson).
    pub order: Option<u32>,
    /// The companion's settings.
    pub reference: Reference,
    /// Why there is no estimate.
    pub note: Option<String>,
    exact: Option<ExactSolution>,
    companion: Option<LiveStepper>,
    dt: f64,
    /// The companion's steps per step of the run (fixed-step methods; [`LiveStepper::halved`]).
    per_step: u64,
    steps: u64,
    slicer: Slicer,
    scale: f64,
}

impl LiveError {
    /// The estimate for a run of `p` from `start` at `t0` \[s\] with the run's `options` (method, dt
    /// \[s\], rtol, atol; the live steppers always project); `exact = false` estimates the ideal
    /// pendulum's error with a companion too.
    pub fn new(p: &LivePendulum, start: State, t0: f64, options: &SolveOptions, exact: bool) -> Self {
        let &SolveOptions { method, dt, rtol, atol, .. } = options;
        let mut e = LiveError {
            t0,
            start,
            how: None,
            order: None,
            reference: Reference::None,
            note: None,
            exact: None,
            companion: None,
            dt,
            per_step: 0,
            steps: 0,
            slicer: Slicer::new(),
            scale: 1.0,
        };
        if p.model == super::crane::CRANE {
            e.note = Some(
                "no estimate: the crane mode runs the crane's DOP853 at the session's rtol, atol".into(),
            );
            return e;
        }
        if exact && p.model == "ideal" {
            if let Ok(sol) = ExactSolution::new(&p.params, &start) {
                e.exact = Some(sol);
                e.how = Some(How::Exact);
                return e;
            }
        }
        let info = method.info();
        let made = if info.adaptive {
            let factor = if rtol * COMPANION_FACTOR >= 2.0 * RTOL_MIN {
                COMPANION_FACTOR
            } else {
                1.0 / COMPANION_FACTOR
            };
            let rtol_c = (rtol * factor).max(RTOL_MIN);
            e.reference = Reference::Tol { rtol: rtol_c, atol: atol * rtol_c / rtol };
            e.scale = 1.0 / (1.0 - rtol_c / rtol).abs();
            LiveStepper::new(p, start, t0, method, 0.0, rtol_c, atol * rtol_c / rtol)
        } else {
            e.reference = Reference::Dt(dt / 2.0);
            let q = 2f64.powi(info.order as i32);
            e.scale = q / (q - 1.0);
            LiveStepper::halved(p, start, t0, method, dt).map(|(c, per_step)| {
                e.per_step = per_step;
                c
            })
        };
        match made {
            Ok(c) => {
                e.companion = Some(c);
                if info.adaptive {
                    e.how = Some(How::Companion);
                } else {
                    e.how = Some(How::Richardson);
                    e.order = Some(info.order);
                }
            }
            Err(err) => e.note = Some(format!("no estimate: the companion run cannot start ({err})")),
        }
        e
    }

    /// Sets `error_x` \[m\] of `records` (this run's, in time order): 0 at the start, the error where
    /// known, [`UNKNOWN`] where the companion did not get there within `budget`.
    pub fn fill(&mut self, records: &mut [Record], budget: &Budget<'_>) {
        let mut reached = true;
        for r in records.iter_mut() {
            let since = r.t() - self.t0;
            r.0[ERROR_X] = if since <= 0.0 {
                0.0
            } else if let Some(sol) = &self.exact {
                sol.state(since).map_or(UNKNOWN, |s| (r.x() - s.x).length())
            } else if reached && self.companion.is_some() {
                match self.reach(r.t(), budget) {
                    Ok(true) => {
                        let c = self.companion.as_ref().map(|c| c.state().x).unwrap_or_default();
                        self.scale * (r.x() - c).length()
                    }
                    Ok(false) => {
                        reached = false; // out of budget: the rest stay unknown (estimate paused)
                        UNKNOWN
                    }
                    Err(err) => {
                        self.companion = None;
                        self.how = None;
                        self.note = Some(format!("no estimate: the companion run stopped ({err})"));
                        reached = false;
                        UNKNOWN
                    }
                }
            } else {
                UNKNOWN
            };
        }
    }

    /// Advances the companion to `t` [s] within `budget`; true once it is there.
    fn reach(&mut self, t: f64, budget: &Budget<'_>) -> Result<bool> {
        let Some(c) = self.companion.as_mut() else { return Ok(false) };
        if self.per_step == 0 {
            if c.t() >= t {
                return Ok(c.t() == t);
            }
            if budget.spent() {
                return Ok(false);
            }
            return self.slicer.until(|cap| c.step_to_capped(t, cap), budget);
        }
        // fixed step: the record is grid point n of the run, the companion's grid point per_step·n
        let target = self.per_step as i64 * ((t - self.t0) / self.dt).round() as i64;
        let want = target - self.steps as i64;
        if want < 0 {
            return Ok(false);
        }
        if want > 0 {
            if budget.spent() {
                return Ok(false);
            }
            self.steps += self.slicer.steps(|k| c.step(k), want as u64, budget)?;
            c.take_events(); // the string companion's events are not news
        }
        Ok(target == self.steps as i64)
    }
}
