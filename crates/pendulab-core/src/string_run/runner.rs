//! [`StringRunner`]: a [`StringStepper`] run to t_end in chunks (the Python layer's progress bar and
//! Ctrl-C) with the numbers of one run, keeping samples by a [`SaveAt`] rule (times in s):
//! - [`SaveAt::Every`]`(n)`: the start, every n-th grid point t₀ + k·dt (n ≥ 1), the state after every
//!   event, and t_end.
//! - [`SaveAt::Times`]: exactly these times (strictly increasing, within [t₀, t_end]): taut phases land
//!   on each by shortening the one step that would cross it (the next step is shortened to regain the
//!   grid), slack phases evaluate the exact parabola there; at an event's time, the state after it.
//!   Events are still listed in [`StringRun::events`].
//!
//! After an event the next step is shortened to land on the grid again. Slack samples are the exact
//! parabola. A short slack excursion wholly inside one taut step (T < 0 only between two grid points)
//! is not seen: dt must resolve the motion.

use super::{StringRun, StringStepper};
use crate::error::{Error, Result};
use crate::integrate::Method;
use crate::model::StringPendulum;
use crate::solve::{SaveAt, BYTES_PER_SAMPLE};
use crate::state::State;

/// The samples kept so far, with the memory limit.
#[derive(Debug, Default)]
struct Recorder {
    t: Vec<f64>,
    states: Vec<State>,
    taut: Vec<bool>,
    /// Samples kept since the start (including those already taken).
    kept: u64,
    max_samples: u64,
    /// The taut phases' step \[s\] (named by a divergence).
    dt: f64,
    /// The time of the last sample kept \[s\] (the last finite state: named by a divergence).
    last_t: f64,
}

impl Recorder {
    fn push(&mut self, t: f64, s: State, taut: bool) -> Result<()> {
        if !s.is_finite() {
            return Err(Error::Diverged { t: self.last_t, method: "string", dt: self.dt });
        }
        if self.t.last() == Some(&t) {
            // an event on a grid point: the event's state (after it) replaces the grid sample
            self.t.pop();
            self.states.pop();
            self.taut.pop();
            self.kept -= 1;
        }
        if self.kept >= self.max_samples {
            let samples = self.kept + 1;
            return Err(Error::TooManySamples {
                samples,
                bytes: samples * BYTES_PER_SAMPLE,
                limit: self.max_samples * BYTES_PER_SAMPLE,
            });
        }
        self.t.push(t);
        self.states.push(s);
        self.taut.push(taut);
        self.kept += 1;
        self.last_t = t;
        Ok(())
    }

    /// The first `n` samples, removed.
    fn drain(&mut self, n: usize) -> (Vec<f64>, Vec<State>, Vec<bool>) {
        (self.t.drain(..n).collect(), self.states.drain(..n).collect(), self.taut.drain(..n).collect())
    }
}

/// A batch run of a [`StringStepper`] to t_end in chunks of bounded work, keeping samples by a
/// [`SaveAt`] rule: what the Python layer drives to show progress and to stop cleanly on Ctrl-C
/// between chunks. Chunks end on grid points t₀ + k·dt (or save times, or t_end) and the stepper
/// goes on from there as if it had not stopped, so the samples of a run in chunks of any size are
/// those of [`StringPendulum::simulate`] (one chunk) bit for bit.
#[derive(Debug)]
pub struct StringRunner {
    stepper: StringStepper,
    t_start: f64,
    t_end: f64,
    save: SaveAt,
    /// Index of the next save time ([`SaveAt::Times`]).
    next_time: usize,
    rec: Recorder,
    done: bool,
}

impl StringRunner {
    /// A run of `stepper` from its time to `t_end` \[s\] keeping `save`; `max_saved_bytes` bounds the
    /// memory of the samples (an error when exceeded). Checks the save rule and keeps the start
    /// (for [`SaveAt::Times`]: when the first time is the start time).
    pub fn new(stepper: StringStepper, t_end: f64, save: SaveAt, max_saved_bytes: u64) -> Result<Self> {
        let t0 = stepper.t();
        // the same checks as the rod's Solver (its steps are not planned: events add states)
        let max_samples = crate::solve::check_run(t0, t_end, &save, max_saved_bytes, None)?;
        let mut runner = Self {
            t_start: t0,
            t_end,
            save,
            next_time: 0,
            rec: Recorder { max_samples, dt: stepper.dt, last_t: t0, ..Recorder::default() },
            done: false,
            stepper,
        };
        let (s, taut) = (runner.stepper.state(), runner.stepper.is_taut());
        match &runner.save {
            SaveAt::Every(_) => runner.rec.push(t0, s, taut)?,
            SaveAt::Times(ts) if ts[0] == t0 => {
                runner.rec.push(t0, s, taut)?;
                runner.next_time = 1;
            }
            SaveAt::Times(_) => {}
        }
        Ok(runner)
    }

    /// Advances by about `max_steps` grid steps of dt (fewer at t_end); returns true once t_end is
    /// reached.
    pub fn advance(&mut self, max_steps: u64) -> Result<bool> {
        if self.done {
            return Ok(true);
        }
        let (t0, dt) = (self.stepper.t0, self.stepper.dt);
        let grid = |k: u64| t0 + k as f64 * dt;
        // the chunk ends at this grid point (after the time reached: at least one grid step)
        let mut k_limit = self.stepper.k.saturating_add(max_steps.max(1));
        while grid(k_limit) <= self.stepper.t {
            k_limit += 1;
        }
        let rec = &mut self.rec;
        loop {
            let (target, save_every) = match &self.save {
                SaveAt::Every(n) => (self.t_end, *n),
                SaveAt::Times(ts) => (ts.get(self.next_time).copied().unwrap_or(self.t_end), u64::MAX),
            };
            let mut keep = |t: f64, s: State, taut: bool| rec.push(t, s, taut);
            let mut ignore = |_: f64, _: State, _: bool| Ok(());
            let push: &mut dyn FnMut(f64, State, bool) -> Result<()> =
                if save_every == u64::MAX { &mut ignore } else { &mut keep };
            let chunk_end = grid(k_limit);
            if chunk_end < target {
                self.stepper.advance_to(chunk_end, false, save_every, push)?;
                return Ok(false);
            }
            self.stepper.advance_to(target, target == self.t_end, save_every, push)?;
            if let SaveAt::Times(ts) = &self.save {
                if self.next_time < ts.len() {
                    // at the save time: the state reached (after any event there)
                    self.next_time += 1;
                    rec.push(target, self.stepper.state(), self.stepper.is_taut())?;
                }
            }
            if target == self.t_end {
                self.done = true;
                return Ok(true);
            }
        }
    }

    /// The samples kept since the last call, the events since the last call and the work so far
    /// (the last sample is held back until the run is done: an event at its time may replace it).
    pub fn take(&mut self) -> StringRun {
        let n = if self.done { self.rec.t.len() } else { self.rec.t.len().saturating_sub(1) };
        self.take_first(n)
    }

    /// Like [`StringRunner::take`], the last sample included: for a run stopped before t_end (going
    /// on after it could keep a grid sample that an event at the same time would have replaced).
    pub fn take_all(&mut self) -> StringRun {
        self.take_first(self.rec.t.len())
    }

    fn take_first(&mut self, n: usize) -> StringRun {
        let (t, states, taut) = self.rec.drain(n);
        StringRun { t, states, taut, events: self.stepper.take_events(), stats: self.stepper.stats() }
    }

    /// The end of the run, t_end \[s\].
    pub fn t_end(&self) -> f64 {
        self.t_end
    }

    /// The fraction of [t₀, t_end] done, in [0, 1].
    pub fn progress(&self) -> f64 {
        ((self.stepper.t() - self.t_start) / (self.t_end - self.t_start)).clamp(0.0, 1.0)
    }

    /// True once t_end is reached.
    pub fn is_done(&self) -> bool {
        self.done
    }

    /// The stepper (time and state reached, mode).
    pub fn stepper(&self) -> &StringStepper {
        &self.stepper
    }
}

/// How [`StringPendulum::simulate`] steps and what it keeps: `method` (rattle, rattle4, rattle6,
/// rattle8 or rkmk4) with step `dt` \[s\] in the taut phases, every `save_every`-th grid point kept
/// (with every event and t_end), the samples' memory bounded by `max_saved_bytes`.
#[derive(Debug, Clone, Copy)]
pub struct StringSettings {
    /// The integrator of the taut phases.
    pub method: Method,
    /// Its step \[s\] (> 0).
    pub dt: f64,
    /// Grid points between kept samples (≥ 1).
    pub save_every: u64,
    /// Most memory of the samples \[bytes\].
    pub max_saved_bytes: u64,
}

impl StringSettings {
    /// `method` with step `dt` \[s\], every grid point kept, no memory bound.
    pub fn new(method: Method, dt: f64) -> Self {
        Self { method, dt, save_every: 1, max_saved_bytes: u64::MAX }
    }
}

impl StringPendulum {
    /// Simulates from `state` at `t0` \[s\] to `t_end` \[s\] as `settings` say. The start may be on the
    /// sphere (|x| = l within 1e-9 relative) or inside it (slack); outside it is an error. One
    /// [`StringStepper`] run to `t_end`.
    pub fn simulate(
        &self,
        t0: f64,
        state: State,
        t_end: f64,
        settings: &StringSettings,
    ) -> Result<StringRun> {
        let &StringSettings { method, dt, save_every, max_saved_bytes } = settings;
        crate::error::require_finite("t0", t0, "the start time must be finite (s)")?;
        if !(t_end.is_finite() && t_end > t0) {
            return Err(Error::InvalidParameter {
                name: "t_end",
                value: t_end,
                allowed: "the end time must be a finite number of seconds after the start time",
            });
        }
        crate::error::require_positive("dt", dt, "the step size dt must be a finite number > 0 s")?;
        if save_every == 0 {
            return Err(Error::InvalidParameter {
                name: "save_every",
                value: 0.0,
                allowed: "save_every must be an integer ≥ 1 (steps between saved samples)",
            });
        }
        let stepper = StringStepper::new(*self, t0, state, method, dt)?;
        let mut runner = StringRunner::new(stepper, t_end, SaveAt::Every(save_every), max_saved_bytes)?;
        while !runner.advance(u64::MAX)? {}
        Ok(runner.take())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A sample that is not finite is a divergence naming the last finite sample's time and the taut
    /// phases' step (it named the bad sample's time and dt = 0).
    #[test]
    fn a_non_finite_sample_names_the_last_finite_time_and_the_step() {
        let mut rec = Recorder { max_samples: 10, dt: 0.01, last_t: 0.0, ..Recorder::default() };
        let ok = State { x: glam::DVec3::new(0.0, 0.0, -1.0), v: glam::DVec3::ZERO };
        rec.push(0.0, ok, true).unwrap();
        rec.push(0.01, ok, true).unwrap();
        let bad = State { x: glam::DVec3::new(f64::NAN, 0.0, -1.0), v: glam::DVec3::ZERO };
        let e = rec.push(0.02, bad, true).unwrap_err();
        assert_eq!(e, Error::Diverged { t: 0.01, method: "string", dt: 0.01 });
        assert!(e
            .to_string()
            .starts_with("the integration diverged after t = 0.01 s with method 'string' (dt = 0.01 s)"));
        assert!(e.to_string().ends_with("; reduce dt"), "{e}");
    }
}
