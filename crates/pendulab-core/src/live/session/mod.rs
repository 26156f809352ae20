//! One lab session without any I/O (docs/web.md, "Pacing"): a pendulum, its stepper, the start, the
//! pacing by the wall clock × time scale, the commands, and one tick's work within a wall-time budget —
//! the Python server's `pendulab.server.session` and `tick`, once in Rust, so that the page's own
//! engine (WebAssembly in a Web Worker) runs the same session as the server. Time is passed in: the
//! wall-clock seconds elapsed since the last tick, and a [`Clock`](crate::live::budget::Clock) for the budget.
//!
//! Fixed-step methods take whole steps of exactly dt, so a live run is the same sequence of steps as a
//! batch run with that dt; `dop853` lands on the target times. A tick sends up to [`MAX_SUBSAMPLES`]
//! records spread over its simulated interval. Units: SI (s, m, m/s, kg, m/s²).

use super::budget::{Budget, Slicer};
use super::error::{LiveError, Reference};
use super::frame::{Record, FRAME_FIELDS};
use super::pendulum::{LivePendulum, LiveStepper};
use crate::error::{Error, Result};
use crate::integrate::Method;
use crate::state::State;
use crate::stepper::SolveOptions;
use crate::string_run::StringEvent;
use serde_json::{json, Value};

mod apply;
mod command;
mod tick;

pub use command::{Command, Out, Setup, StateSpec, DEFAULT_ATOL, DEFAULT_RTOL};

/// Most steps of `step` commands waiting to be taken.
pub const MAX_PENDING_STEPS: u64 = 1_000_000;
/// Most frame records sent per tick.
pub const MAX_SUBSAMPLES: usize = 16;
/// Longest wall-clock interval \[s\] one tick catches up on.
pub const MAX_ELAPSED: f64 = 0.1;
/// Most `event` notices sent per tick (the latest).
pub const MAX_EVENT_NOTICES: usize = 16;

/// One client's lab (not thread-safe: one owner calls [`LiveSession::tick`]).
#[derive(Debug, Clone)]
pub struct LiveSession {
    /// Scenario name and title.
    pub scenario: Option<String>,
    /// Scenario title.
    pub title: Option<String>,
    /// The pendulum.
    pub pendulum: LivePendulum,
    /// The stepper.
    pub stepper: LiveStepper,
    /// The error estimate of the stepper's run.
    pub error: LiveError,
    /// Method.
    pub method: Method,
    /// Step \[s\] of a fixed-step method. `dop853` does not use it (its live stepper always chooses its
    /// first step: `make` passes it 0); it is kept as the step of a fixed-step method chosen next.
    pub dt: f64,
    /// dop853 relative tolerance (in the `status` notice, as `atol`).
    pub rtol: f64,
    /// dop853 absolute tolerance.
    pub atol: f64,
    /// Start time of the scenario \[s\].
    pub t0: f64,
    /// Simulated seconds per wall-clock second.
    pub time_scale: f64,
    /// Paused.
    pub paused: bool,
    /// Counts discontinuities (reset, new state, parameters, model, scenario).
    pub epoch: u64,
    /// Out of budget in the last advance.
    pub lagging: bool,
    /// Steps of `step` commands waiting.
    pub pending_steps: u64,
    /// Command messages handled (applied, refused or dropped).
    pub commands: u64,
    /// Estimate the ideal pendulum's error from the exact solution.
    pub exact_error: bool,
    clock: f64,
    start: State,
    start_length: f64,
    slicer: Slicer,
    events: Vec<(StringEvent, u64)>,
}

/// A live run's integrator settings (the live steppers always project onto TS²).
fn solve_options(method: Method, dt: f64, rtol: f64, atol: f64) -> SolveOptions {
    SolveOptions { method, dt, rtol, atol, project: true }
}

impl LiveSession {
    /// A session from `setup`.
    pub fn new(setup: Setup) -> Result<Self> {
        let stepper =
            make(&setup.pendulum, setup.state, setup.t0, setup.method, setup.dt, setup.rtol, setup.atol)?;
        let options = solve_options(setup.method, setup.dt, setup.rtol, setup.atol);
        let error = LiveError::new(&setup.pendulum, setup.state, setup.t0, &options, true);
        Ok(Self {
            scenario: setup.name,
            title: setup.title,
            start_length: setup.pendulum.params.length,
            pendulum: setup.pendulum,
            stepper,
            error,
            method: setup.method,
            dt: setup.dt,
            rtol: setup.rtol,
            atol: setup.atol,
            t0: setup.t0,
            time_scale: 1.0,
            paused: false,
            epoch: 0,
            lagging: false,
            pending_steps: 0,
            commands: 0,
            exact_error: true,
            clock: setup.t0,
            start: setup.state,
            slicer: Slicer::new(),
            events: Vec::new(),
        })
    }

    /// The start for the current pendulum: after a length change, the same angles and rates.
    pub fn start_state(&self) -> State {
        let ell = self.pendulum.params.length;
        if ell == self.start_length {
            return self.start;
        }
        let k = ell / self.start_length;
        self.pendulum.carry(&State { x: self.start.x * k, v: self.start.v * k }).unwrap_or(self.start)
    }

    /// Estimate the ideal pendulum's error from the exact solution (`on`, the default) or with a
    /// companion as for the other models (tests of the estimate); the estimate starts afresh from the
    /// current state.
    pub fn set_exact_error(&mut self, on: bool) -> Result<()> {
        self.exact_error = on;
        self.new_stepper(self.stepper.state(), self.stepper.t(), None)
    }

    /// The simulated time \[s\] the pacing aims at (the stepper's time when it keeps up).
    pub fn clock(&self) -> f64 {
        self.clock
    }

    /// The `status` notice (docs/web.md, "Notices"): everything the page shows and encodes in its URL.
    pub fn status(&self) -> Value {
        let p = &self.pendulum.params;
        let start = self.start_state();
        let e = &self.error;
        let reference = match e.reference {
            Reference::None => json!({}),
            Reference::Dt(dt) => json!({ "dt": dt }),
            Reference::Tol { rtol, atol } => json!({ "rtol": rtol, "atol": atol }),
        };
        let own: serde_json::Map<String, Value> =
            self.pendulum.own.iter().map(|(k, v)| (k.to_string(), json!(v))).collect();
        json!({
            "type": "status",
            "epoch": self.epoch,
            "scenario": self.scenario,
            "title": self.title,
            "paused": self.paused,
            "time_scale": self.time_scale,
            "method": self.method.info().name,
            "adaptive": self.adaptive(),
            "dt": self.dt,
            "rtol": self.rtol,
            "atol": self.atol,
            "params": { "length": p.length, "mass": p.mass, "g": p.g },
            "model": self.pendulum.model,
            "model_params": own,
            "t": self.stepper.t(),
            "t0": self.t0,
            "start": { "x": start.x.to_array(), "v": start.v.to_array() },
            "lagging": self.lagging,
            "error_estimate": {
                "how": e.how.map(|h| h.name()),
                "order": e.order,
                "reference": reference,
                "since": e.t0,
                "note": e.note,
            },
            "commands": self.commands,
            "frame_fields": FRAME_FIELDS,
            "crane": match &self.stepper {
                LiveStepper::Crane(c) => c.status(),
                _ => Value::Null,
            },
        })
    }

    /// True when the method chooses its own steps (`dop853`).
    pub fn adaptive(&self) -> bool {
        self.method.info().adaptive
    }

    /// The current state as one record (error_x unknown until filled).
    pub fn record(&self) -> Record {
        self.stepper.record()
    }

    /// The integration cannot go on (`cause`: it diverged, came within reach of a pole, …): pauses at the
    /// last state computed, where `cause`'s time is, and returns [`Error::Stopped`] (keyed
    /// `integration_stopped`, with the cause's key as `why`) — the one error a caller of
    /// [`LiveSession::advance`], [`LiveSession::take_pending_steps`] or [`LiveSession::apply`] gets, and
    /// nothing of it is left behind for a later error.
    pub(super) fn stopped(&mut self, cause: Error) -> Error {
        self.paused = true;
        Error::Stopped { cause: Box::new(cause) }
    }

    /// Takes the waiting steps of `step` commands within `budget`; the record reached (None when none
    /// were waiting). On [`Error::Stopped`] no steps are left waiting and the session is paused.
    pub fn take_pending_steps(&mut self, budget: &Budget<'_>) -> Result<Option<Record>> {
        if self.pending_steps == 0 {
            return Ok(None);
        }
        let stepper = &mut self.stepper;
        match self.slicer.steps(|k| stepper.step(k), self.pending_steps, budget) {
            Ok(n) => self.pending_steps -= n.min(self.pending_steps),
            Err(e) => {
                self.pending_steps = 0;
                return Err(self.stopped(e));
            }
        }
        self.clock = self.stepper.t();
        Ok(Some(self.record()))
    }

    /// Advances by `elapsed` wall-clock seconds × time_scale within `budget`; the records reached. Out
    /// of budget it stops where it got to and sets `lagging`. On [`Error::Stopped`] the session is paused
    /// at the last state computed (the records of the slices before are not returned).
    pub fn advance(&mut self, elapsed: f64, budget: &Budget<'_>) -> Result<Vec<Record>> {
        if self.paused {
            return Ok(Vec::new());
        }
        let elapsed = if elapsed.is_nan() { 0.0 } else { elapsed.clamp(0.0, MAX_ELAPSED) };
        let t = self.stepper.t();
        self.clock = self.clock.max(t) + elapsed * self.time_scale;
        let mut n_sub = ((self.time_scale - 1e-9).ceil() as usize).clamp(1, MAX_SUBSAMPLES);
        let mut out = Vec::with_capacity(n_sub);
        let mut done = true;
        let result: Result<()> = (|| {
            if self.adaptive() {
                for i in 0..n_sub {
                    let target = t + (self.clock - t) * (i + 1) as f64 / n_sub as f64;
                    let stepper = &mut self.stepper;
                    done = self.slicer.until(|cap| stepper.step_to_capped(target, cap), budget)?;
                    out.push(self.stepper.record());
                    if !done {
                        break;
                    }
                }
                return Ok(());
            }
            let n = ((self.clock - t) / self.dt + 1e-9).floor();
            if n <= 0.0 {
                return Ok(());
            }
            let n = n as u64;
            n_sub = n_sub.min(n as usize);
            let mut prev = 0u64;
            for i in 0..n_sub {
                let bound = (n as f64 * (i + 1) as f64 / n_sub as f64).round() as u64;
                let want = bound - prev;
                prev = bound;
                let stepper = &mut self.stepper;
                done = self.slicer.steps(|k| stepper.step(k), want, budget)? == want;
                out.push(self.stepper.record());
                if !done {
                    break;
                }
            }
            Ok(())
        })();
        if let Err(e) = result {
            return Err(self.stopped(e));
        }
        self.lagging = !done;
        if !done {
            self.clock = self.stepper.t();
        }
        Ok(out)
    }
}

fn make(
    p: &LivePendulum,
    state: State,
    t: f64,
    method: Method,
    dt: f64,
    rtol: f64,
    atol: f64,
) -> Result<LiveStepper> {
    let dt = if method.info().adaptive { 0.0 } else { dt };
    LiveStepper::new(p, state, t, method, dt, rtol, atol)
}
