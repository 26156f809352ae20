//! Batch solving: a [`Stepper`] plus what to keep ([`SaveAt`]). Stepping and saving are separate,
//! so 10⁸ and more steps cost memory only for the samples kept. The [`Solver`] advances in
//! bounded chunks so that a caller (the Python layer, the CLI) can show progress and stop cleanly
//! between chunks, keeping everything computed so far.
//!
//! Saving rules (times in s):
//! - [`SaveAt::Every`]`(n)`: the initial state, every n-th step, and always the final state at t_end.
//!   Fixed-step methods step on the grid t₀ + k·dt; the last step is shortened to land on t_end.
//! - [`SaveAt::Times`]: exactly the given times (sorted, within [t₀, t_end]). `dop853` interpolates
//!   with its dense output (order 7); fixed-step methods land on each time by shortening the one
//!   step that would cross it.

use crate::error::{Error, Result, Shown};
use crate::integrate::Stats;
use crate::model::Model;
use crate::state::State;
use crate::stepper::{SolveOptions, Stepper};

/// What to save.
#[derive(Debug, Clone, PartialEq)]
pub enum SaveAt {
    /// The initial state, every n-th step (n ≥ 1) and the final state.
    Every(u64),
    /// Exactly these times \[s\], increasing, within [t₀, t_end].
    Times(Vec<f64>),
}

/// What [`Solver::advance`] does next under its [`SaveAt`]: steps towards the next n-th step, or
/// towards the next save time \[s\], or nothing (every save time done).
#[derive(Clone, Copy)]
enum Next {
    Every(u64),
    Time(f64),
    Done,
}

/// Bytes one saved sample takes (t, x, v as f64).
pub const BYTES_PER_SAMPLE: u64 = 7 * 8;
/// Default limit on the memory of saved samples: 4 GiB.
pub const DEFAULT_MAX_SAVED_BYTES: u64 = 4 << 30;

/// Saved samples: times \[s\] and states.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Samples {
    /// Times \[s\].
    pub t: Vec<f64>,
    /// States at those times.
    pub states: Vec<State>,
}

/// A batch solver: stepper, save rule, end time and the samples kept so far.
#[derive(Debug, Clone)]
pub struct Solver<M: Model> {
    stepper: Stepper<M>,
    t0: f64,
    t_end: f64,
    save: SaveAt,
    next_time: usize,
    since_save: u64,
    samples: Samples,
    saved_total: u64,
    max_samples: u64,
    done: bool,
    /// The time \[s\] of the last state known finite (named by a divergence): the last one saved, for
    /// `dop853` the start of its last step (every step's state is checked).
    last_finite: f64,
}

fn too_many(samples: u64, max_samples: u64) -> Result<()> {
    if samples > max_samples {
        return Err(Error::TooManySamples {
            samples,
            bytes: samples.saturating_mul(BYTES_PER_SAMPLE),
            limit: max_samples.saturating_mul(BYTES_PER_SAMPLE),
        });
    }
    Ok(())
}

/// Refuses a fixed-step run that plans more than the registry's `steps` limit of (t_end − t₀)/dt
/// steps (10¹⁰), before any work starts.
pub fn check_planned_steps(steps: f64) -> Result<()> {
    let limit = crate::limits::limit("steps");
    if steps.is_nan() || steps > limit.max {
        return Err(Error::InvalidParameter {
            name: "(t_end - t0)/dt",
            value: steps,
            allowed: limit.allowed,
        });
    }
    Ok(())
}

impl<M: Model> Solver<M> {
    /// Validates everything up front: t_end > t₀ finite, save rule, expected memory.
    pub fn new(
        model: M,
        t0: f64,
        state: State,
        t_end: f64,
        options: &SolveOptions,
        save: SaveAt,
        max_saved_bytes: u64,
    ) -> Result<Self> {
        if t_end.is_finite() && t_end >= t0 {
            model.check_run(t0, t_end)?;
        }
        let stepper = Stepper::new(model, t0, state, options)?;
        let fixed_steps = (!options.method.info().adaptive).then(|| (t_end - t0) / options.dt);
        let max_samples = check_run(t0, t_end, &save, max_saved_bytes, fixed_steps)?;
        let mut solver = Self {
            stepper,
            t0,
            t_end,
            save,
            next_time: 0,
            since_save: 0,
            samples: Samples::default(),
            saved_total: 0,
            max_samples,
            done: false,
            last_finite: t0,
        };
        let starts_saved = match &solver.save {
            SaveAt::Every(_) => true,
            SaveAt::Times(ts) => ts[0] == t0,
        };
        if starts_saved {
            // the stepper's start, physical (a hoisted rope: the rope's rate added to the given state)
            let start = solver.stepper.state();
            solver.push(t0, start)?;
            solver.next_time = usize::from(matches!(solver.save, SaveAt::Times(_)));
        }
        Ok(solver)
    }

    /// The divergence of a run whose state was found not finite: named by the last time it was known
    /// finite (methods that do not check every step, such as `rk4`, are found out at a save).
    fn diverged(&self) -> Error {
        Error::Diverged {
            t: self.last_finite,
            method: self.stepper.method().info().name,
            dt: self.stepper.dt(),
        }
    }

    fn push(&mut self, t: f64, s: State) -> Result<()> {
        if !s.is_finite() {
            return Err(self.diverged());
        }
        self.last_finite = t;
        self.saved_total += 1;
        too_many(self.saved_total, self.max_samples)?;
        self.samples.t.push(t);
        self.samples.states.push(s);
        Ok(())
    }

    /// True once t_end is reached.
    pub fn is_done(&self) -> bool {
        self.done
    }
    /// The end of the run, t_end \[s\].
    pub fn t_end(&self) -> f64 {
        self.t_end
    }
    /// Fraction of [t₀, t_end] covered so far, in [0, 1].
    pub fn progress(&self) -> f64 {
        ((self.stepper.t() - self.t0) / (self.t_end - self.t0)).clamp(0.0, 1.0)
    }
    /// The stepper (current time, state, counters).
    pub fn stepper(&self) -> &Stepper<M> {
        &self.stepper
    }
    /// The stepper, to adjust it before the run (e.g. [`Stepper::set_invariant_projection`]).
    pub fn stepper_mut(&mut self) -> &mut Stepper<M> {
        &mut self.stepper
    }
    /// Work counters.
    pub fn stats(&self) -> Stats {
        self.stepper.stats()
    }
    /// Removes and returns the samples saved since the last call (lets callers stream them out).
    pub fn take_samples(&mut self) -> Samples {
        std::mem::take(&mut self.samples)
    }

    /// Advances by at most about `budget` steps (≥ 1); returns whether t_end has been reached.
    pub fn advance(&mut self, budget: u64) -> Result<bool> {
        let budget = budget.max(1);
        let mut used = 0u64;
        while !self.done && used < budget {
            // the rule read, not cloned: a clone of the save times on every pass (one per saved time
            // at least) made a run with n of them cost O(n²) (457 k times, the error estimate's
            // companion of a 457 k-step DOP853 run: 75 s, now 1 s)
            let next = match &self.save {
                SaveAt::Every(n) => Next::Every(*n),
                SaveAt::Times(ts) => ts.get(self.next_time).map_or(Next::Done, |&t| Next::Time(t)),
            };
            match next {
                Next::Every(n) => {
                    let want = (n - self.since_save).min(budget - used);
                    let taken = self.steps_towards(self.t_end, want)?;
                    used += taken;
                    self.since_save += taken;
                    let at_end = self.stepper.t() >= self.t_end;
                    if self.since_save == n || at_end {
                        self.since_save = 0;
                        let (t, s) = (self.stepper.t(), self.stepper.state());
                        self.push(t, s)?;
                    }
                    self.done = at_end;
                }
                Next::Done => {
                    self.done = true;
                    break;
                }
                Next::Time(target) => {
                    used += self.steps_towards(target, budget - used)?;
                    if let Some(s) = self.sample_at(target) {
                        self.next_time += 1;
                        self.push(target, s)?;
                    }
                }
            }
        }
        if !self.stepper.state().is_finite() {
            return Err(self.diverged());
        }
        Ok(self.done)
    }

    /// Up to `n` steps towards `target` [s] (≤ t_end), never past it; returns steps taken. Fixed-step
    /// methods take full steps in the stepper's tight loop and shorten the one that would cross
    /// `target`; `dop853` takes accepted steps towards t_end until it has passed `target` (and
    /// interpolates there, [`Solver::sample_at`]).
    fn steps_towards(&mut self, target: f64, n: u64) -> Result<u64> {
        let mut taken = 0;
        if self.stepper.method().info().adaptive {
            while taken < n && self.stepper.t() < target {
                // every accepted step is checked: a state not finite is named by the step's start
                // (the last saved sample may lie many steps back), as dop853's own failures are
                self.last_finite = self.stepper.t();
                self.stepper.step_towards(self.t_end)?;
                taken += 1;
                if !self.stepper.state().is_finite() {
                    let (t, dt) = (self.last_finite, self.stepper.t() - self.last_finite);
                    return Err(Error::Diverged { t, method: self.stepper.method().info().name, dt });
                }
            }
        } else {
            let dt = self.stepper.dt();
            let room = ((target - self.stepper.t()) / dt - 1e-9).floor().max(0.0) as u64;
            let bulk = n.min(room.saturating_sub(1));
            self.stepper.step_n(bulk)?;
            taken += bulk;
            while taken < n && self.stepper.t() < target {
                self.stepper.step_towards(target)?;
                taken += 1;
            }
        }
        Ok(taken)
    }

    /// The state at `target` if the stepper has reached it (dense output for `dop853`).
    fn sample_at(&mut self, target: f64) -> Option<State> {
        let t = self.stepper.t();
        if t == target {
            Some(self.stepper.state())
        } else if t > target {
            self.stepper.dense_output(target)
        } else {
            None
        }
    }
}

/// Solves from (t₀, state) to t_end in one call, calling `progress(fraction)` between chunks;
/// when it returns `false` the solve stops and the samples so far are returned with
/// `interrupted = true`.
pub fn solve<M: Model>(
    model: M,
    t0: f64,
    state: State,
    t_end: f64,
    options: &SolveOptions,
    save: SaveAt,
    mut progress: impl FnMut(f64) -> bool,
) -> Result<(Samples, Stats, bool)> {
    let mut solver = Solver::new(model, t0, state, t_end, options, save, DEFAULT_MAX_SAVED_BYTES)?;
    let mut interrupted = false;
    while !solver.advance(1 << 16)? {
        if !progress(solver.progress()) {
            interrupted = true;
            break;
        }
    }
    Ok((solver.take_samples(), solver.stats(), interrupted))
}

/// The checks of a batch run's end and save rule, made before any step by [`Solver`] and the string
/// pendulum's runner alike: t_end \[s\] finite and after t₀; with `fixed_steps` (the (t_end − t₀)/dt
/// of a fixed-step method) the planned steps within their limit; `save_every` ≥ 1; the save times
/// ([`check_save_times`]); and the samples the rule will keep within `max_saved_bytes` (save times:
/// their number; every n-th of fixed steps: ⌈steps/n⌉ + 2). Returns the cap on samples.
pub(crate) fn check_run(
    t0: f64,
    t_end: f64,
    save: &SaveAt,
    max_saved_bytes: u64,
    fixed_steps: Option<f64>,
) -> Result<u64> {
    if !(t_end.is_finite() && t_end > t0) {
        return Err(Error::InvalidParameter {
            name: "t_end",
            value: t_end,
            allowed: "the end time must be a finite number of seconds after the start time",
        });
    }
    if let Some(steps) = fixed_steps {
        check_planned_steps(steps)?;
    }
    let max_samples = max_saved_bytes / BYTES_PER_SAMPLE;
    match save {
        SaveAt::Every(0) => {
            return Err(Error::InvalidParameter {
                name: "save_every",
                value: 0.0,
                allowed: "save_every must be an integer ≥ 1 (steps between saved samples)",
            })
        }
        SaveAt::Every(n) => {
            if let Some(steps) = fixed_steps {
                too_many((steps.ceil() / *n as f64).ceil() as u64 + 2, max_samples)?;
            }
        }
        SaveAt::Times(ts) => {
            check_save_times(ts, t0, t_end)?;
            too_many(ts.len() as u64, max_samples)?;
        }
    }
    Ok(max_samples)
}

/// Save times [s] must be given, finite, within [`t0`, `t_end`] and strictly increasing (shared by
/// [`Solver`] and the string pendulum's runner).
pub(crate) fn check_save_times(ts: &[f64], t0: f64, t_end: f64) -> Result<()> {
    if ts.is_empty() {
        return Err(Error::InvalidSaveTimes { reason: "no save times were given".into() });
    }
    if let Some(bad) = ts.iter().find(|t| !t.is_finite() || **t < t0 || **t > t_end) {
        return Err(Error::InvalidSaveTimes {
            reason: format!(
                "{} s is not a finite time within [t0, t_end] = [{}, {}] s",
                Shown(*bad),
                Shown(t0),
                Shown(t_end)
            ),
        });
    }
    if let Some(w) = ts.windows(2).find(|w| w[1] <= w[0]) {
        return Err(Error::InvalidSaveTimes {
            reason: format!(
                "times must be strictly increasing, but {} s is followed by {} s",
                Shown(w[0]),
                Shown(w[1])
            ),
        });
    }
    Ok(())
}
