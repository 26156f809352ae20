//! The hybrid simulation of the string pendulum ([`StringPendulum`], see its module for the physics
//! and equations): taut phases with a fixed-step method that keeps TS² (T-2.2), the leave event where
//! the tension T-2.3 reaches 0 (bisection on the step length), analytic free flight, the re-taut
//! event on the exact parabola, and the snap.
//!
//! Times [s] lie on the grid t₀ + k·dt as in [`crate::Stepper`]: full steps are exactly dt, so a
//! motion that never goes slack is the rod pendulum's, bit for bit. After an event the next step is
//! shortened to land on the grid again. Samples ([`StringSave`]): the start, every `save_every`-th grid
//! point, every event (the state after it) and t_end; or exactly given times, landed on by shortening
//! a taut step. Slack samples are the exact parabola. [`StringRunner`] runs a [`StringStepper`] to
//! t_end in chunks (the Python layer's progress bar and Ctrl-C) with the numbers of one run. A short slack
//! excursion wholly inside one taut step (T < 0 only between two grid points) is not seen: dt must
//! resolve the motion.

use super::string::{bisect, StringPendulum};
use super::{IdealPendulum, Model};
use crate::error::{Error, Result};
use crate::integrate::composition::Composition;
use crate::integrate::rattle::Rattle;
use crate::integrate::rkmk4::Rkmk4;
use crate::integrate::{FixedStep, Method, Stats};
use crate::solve::BYTES_PER_SAMPLE;
use crate::state::{State, TS2_TOLERANCE};
use glam::DVec3;

/// What happened at an event.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum EventKind {
    /// The tension reached 0: the string goes slack, the bob flies freely.
    Slack,
    /// The bob reached |x| = l: the string snaps taut (radial velocity removed or reflected).
    Taut,
}

/// One event of a run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StringEvent {
    /// Time [s].
    pub t: f64,
    /// Leave or snap.
    pub kind: EventKind,
    /// State just before (for a leave: the state where T = 0).
    pub before: State,
    /// State just after (equal to `before` for a leave).
    pub after: State,
    /// Kinetic energy lost in the event [J] (0 for a leave; ½m(1 − e²)|u|² for a snap).
    pub energy_lost: f64,
}

/// The result of [`StringPendulum::simulate`].
#[derive(Debug, Clone, Default, PartialEq)]
pub struct StringRun {
    /// Times [s].
    pub t: Vec<f64>,
    /// States (x [m], v [m/s]); off the sphere while slack.
    pub states: Vec<State>,
    /// Whether the string is taut at each sample.
    pub taut: Vec<bool>,
    /// Every leave and snap, in order.
    pub events: Vec<StringEvent>,
    /// Taut-phase steps and evaluations.
    pub stats: Stats,
}

#[derive(Debug, Clone)]
enum Scheme {
    Rattle(Rattle),
    Composition(Composition),
    Rkmk4(Rkmk4),
}

impl Scheme {
    fn new(method: Method) -> Result<Self> {
        Ok(match method {
            Method::Rattle => Scheme::Rattle(Rattle::default()),
            Method::Rattle4 => Scheme::Composition(Composition::of_order(4)),
            Method::Rattle6 => Scheme::Composition(Composition::of_order(6)),
            Method::Rattle8 => Scheme::Composition(Composition::of_order(8)),
            Method::Rkmk4 => Scheme::Rkmk4(Rkmk4::default()),
            _ => return Err(Error::UnsupportedModel { method: method.info().name, model: "string" }),
        })
    }
    fn step(&mut self, m: &IdealPendulum, t: f64, s: &mut State, h: f64) -> Result<()> {
        match self {
            Scheme::Rattle(r) => r.step(m, t, s, h),
            Scheme::Composition(c) => c.step(m, t, s, h),
            Scheme::Rkmk4(r) => r.step(m, t, s, h),
        }
    }
    fn evals(&self) -> u64 {
        match self {
            Scheme::Rattle(r) => r.evals_per_step(),
            Scheme::Composition(c) => c.evals_per_step(),
            Scheme::Rkmk4(r) => r.evals_per_step(),
        }
    }
    fn reset(&mut self) {
        match self {
            Scheme::Rattle(r) => r.reset(),
            Scheme::Composition(c) => c.reset(),
            Scheme::Rkmk4(r) => r.reset(),
        }
    }
}

/// Where the bob is between events.
#[derive(Debug, Clone, Copy)]
enum Phase {
    Taut,
    /// Flying since the event at `t` from `from`; arrives on the sphere at `arrival` (∞: never).
    Slack {
        t: f64,
        from: State,
        arrival: f64,
    },
}

/// What a [`StringRunner`] keeps (times in s).
#[derive(Debug, Clone, PartialEq)]
pub enum StringSave {
    /// The start, every n-th grid point t₀ + k·dt (n ≥ 1), the state after every event, and t_end.
    Every(u64),
    /// Exactly these times (strictly increasing, within [t₀, t_end]): taut phases land on each by
    /// shortening the one step that would cross it (the next step is shortened to regain the grid),
    /// slack phases evaluate the exact parabola there; at an event's time, the state after it.
    /// Events are still listed in [`StringRun::events`].
    Times(Vec<f64>),
}

/// The samples kept so far, with the memory limit.
#[derive(Debug, Default)]
struct Recorder {
    t: Vec<f64>,
    states: Vec<State>,
    taut: Vec<bool>,
    /// Samples kept since the start (including those already taken).
    kept: u64,
    max_samples: u64,
}

impl Recorder {
    fn push(&mut self, t: f64, s: State, taut: bool) -> Result<()> {
        if !s.is_finite() {
            return Err(Error::Diverged { t, method: "string", dt: 0.0 });
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
        Ok(())
    }

    /// The first `n` samples, removed.
    fn drain(&mut self, n: usize) -> (Vec<f64>, Vec<State>, Vec<bool>) {
        (self.t.drain(..n).collect(), self.states.drain(..n).collect(), self.taut.drain(..n).collect())
    }
}

/// A batch run of a [`StringStepper`] to t_end in chunks of bounded work, keeping samples by a
/// [`StringSave`] rule: what the Python layer drives to show progress and to stop cleanly on Ctrl-C
/// between chunks. Chunks end on grid points t₀ + k·dt (or save times, or t_end) and the stepper
/// goes on from there as if it had not stopped, so the samples of a run in chunks of any size are
/// those of [`StringPendulum::simulate`] (one chunk) bit for bit.
#[derive(Debug)]
pub struct StringRunner {
    stepper: StringStepper,
    t_start: f64,
    t_end: f64,
    save: StringSave,
    /// Index of the next save time ([`StringSave::Times`]).
    next_time: usize,
    rec: Recorder,
    done: bool,
}

impl StringRunner {
    /// A run of `stepper` from its time to `t_end` [s] keeping `save`; `max_saved_bytes` bounds the
    /// memory of the samples (an error when exceeded). Checks the save rule and keeps the start
    /// (for [`StringSave::Times`]: when the first time is the start time).
    pub fn new(stepper: StringStepper, t_end: f64, save: StringSave, max_saved_bytes: u64) -> Result<Self> {
        let t0 = stepper.t();
        if !(t_end.is_finite() && t_end > t0) {
            return Err(Error::InvalidParameter {
                name: "t_end",
                value: t_end,
                allowed: "the end time must be a finite number of seconds after the start time",
            });
        }
        let max_samples = max_saved_bytes / BYTES_PER_SAMPLE;
        match &save {
            StringSave::Every(0) => {
                return Err(Error::InvalidParameter {
                    name: "save_every",
                    value: 0.0,
                    allowed: "save_every must be an integer ≥ 1 (steps between saved samples)",
                })
            }
            StringSave::Every(_) => {}
            StringSave::Times(ts) => {
                if ts.is_empty() {
                    return Err(Error::InvalidSaveTimes { reason: "no save times were given".into() });
                }
                if let Some(bad) = ts.iter().find(|t| !t.is_finite() || **t < t0 || **t > t_end) {
                    return Err(Error::InvalidSaveTimes {
                        reason: format!(
                            "{bad} s is not a finite time within [t0, t_end] = [{t0}, {t_end}] s"
                        ),
                    });
                }
                if let Some(w) = ts.windows(2).find(|w| w[1] <= w[0]) {
                    return Err(Error::InvalidSaveTimes {
                        reason: format!(
                            "times must be strictly increasing, but {} s is followed by {} s",
                            w[0], w[1]
                        ),
                    });
                }
                if ts.len() as u64 > max_samples {
                    let samples = ts.len() as u64;
                    return Err(Error::TooManySamples {
                        samples,
                        bytes: samples * BYTES_PER_SAMPLE,
                        limit: max_samples * BYTES_PER_SAMPLE,
                    });
                }
            }
        }
        let mut runner = Self {
            t_start: t0,
            t_end,
            save,
            next_time: 0,
            rec: Recorder { max_samples, ..Recorder::default() },
            done: false,
            stepper,
        };
        let (s, taut) = (runner.stepper.state(), runner.stepper.is_taut());
        match &runner.save {
            StringSave::Every(_) => runner.rec.push(t0, s, taut)?,
            StringSave::Times(ts) if ts[0] == t0 => {
                runner.rec.push(t0, s, taut)?;
                runner.next_time = 1;
            }
            StringSave::Times(_) => {}
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
                StringSave::Every(n) => (self.t_end, *n),
                StringSave::Times(ts) => (ts.get(self.next_time).copied().unwrap_or(self.t_end), u64::MAX),
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
            if let StringSave::Times(ts) = &self.save {
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

impl StringPendulum {
    /// Simulates from `state` at `t0` [s] to `t_end` [s] with `method` (rattle, rattle4, rattle6,
    /// rattle8 or rkmk4) and step `dt` [s] in the taut phases, keeping every `save_every`-th grid
    /// point, every event and t_end. The start may be on the sphere (|x| = l within 1e-9 relative) or
    /// inside it (slack); outside it is an error. `max_saved_bytes` bounds the memory of the samples.
    /// One [`StringStepper`] run to `t_end`.
    #[allow(clippy::too_many_arguments)]
    pub fn simulate(
        &self,
        t0: f64,
        state: State,
        t_end: f64,
        method: Method,
        dt: f64,
        save_every: u64,
        max_saved_bytes: u64,
    ) -> Result<StringRun> {
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
        let mut runner = StringRunner::new(stepper, t_end, StringSave::Every(save_every), max_saved_bytes)?;
        while !runner.advance(u64::MAX)? {}
        Ok(runner.take())
    }

    fn flight_from(&self, t: f64, s: State, zeros: usize) -> Phase {
        let arrival = self.flight_time(&s, zeros).map_or(f64::INFINITY, |tau| t + tau);
        Phase::Slack { t, from: s, arrival }
    }
}

/// The string pendulum stepped incrementally (what the lab runs): the hybrid run of
/// [`StringPendulum::simulate`], resumable at any time with its mode — taut, or slack with the flight
/// it is on (departure state and time, arrival) — carried as state, so that a run cut into pieces
/// is the same run: stepping to t₁ and then to t₂ gives the states of one run to t₂ when t₁ is a grid
/// point t₀ + k·dt ([`StringStepper::step`] always lands on one).
#[derive(Debug, Clone)]
pub struct StringStepper {
    model: StringPendulum,
    rod: IdealPendulum,
    scheme: Scheme,
    t0: f64,
    dt: f64,
    /// Time reached [s].
    t: f64,
    /// State reached (off the sphere while slack).
    s: State,
    /// Index of the last grid point t₀ + k·dt at or before t.
    k: u64,
    /// Grid index of the last target of [`StringStepper::step`].
    target: u64,
    on_grid: bool,
    phase: Phase,
    events: Vec<StringEvent>,
    stats: Stats,
}

impl StringStepper {
    /// A stepper from `state` at `t0` [s] with `method` (rattle, rattle4, rattle6, rattle8 or rkmk4)
    /// and step `dt` [s] in the taut phases. The start may be on the sphere (|x| = l within 1e-9
    /// relative: taut, unless T < 0 or it moves off the sphere) or inside it (slack, flying); beyond
    /// it is an error.
    pub fn new(model: StringPendulum, t0: f64, state: State, method: Method, dt: f64) -> Result<Self> {
        crate::error::require_finite("t0", t0, "the start time must be finite (s)")?;
        crate::error::require_positive("dt", dt, "the step size dt must be a finite number > 0 s")?;
        if !state.is_finite() {
            return Err(Error::Diverged { t: t0, method: "string", dt });
        }
        let l = model.params().length;
        let excess = (state.x.length() - l) / l;
        if excess > TS2_TOLERANCE {
            return Err(Error::InvalidParameter {
                name: "(|x| - l)/l",
                value: excess,
                allowed: "a string pendulum starts on the sphere |x| = l or inside it (slack), not beyond",
            });
        }
        let scheme = Scheme::new(method)?;
        let mut s = state;
        let mut events = Vec::new();
        // the start: on the sphere moving tangentially (taut unless T < 0), inward (flying) or
        // outward (a snap at once); inside the sphere, flying
        let mut phase = if excess.abs() <= TS2_TOLERANCE {
            let radial = s.x.dot(s.v) / (l * s.v.length().max(f64::MIN_POSITIVE));
            if radial.abs() <= TS2_TOLERANCE {
                s = State::projected(model.params(), s.x, s.v)?.0;
                Phase::Taut
            } else if radial < 0.0 {
                model.flight_from(t0, s, 1)
            } else {
                Phase::Slack { t: t0, from: s, arrival: t0 }
            }
        } else {
            model.flight_from(t0, s, 0)
        };
        if let Phase::Taut = phase {
            if model.tension(&s) < 0.0 {
                events.push(StringEvent {
                    t: t0,
                    kind: EventKind::Slack,
                    before: s,
                    after: s,
                    energy_lost: 0.0,
                });
                phase = model.flight_from(t0, s, 2);
            }
        }
        Ok(Self {
            model,
            rod: IdealPendulum::from_params(*model.params()),
            scheme,
            t0,
            dt,
            t: t0,
            s,
            k: 0,
            target: 0,
            on_grid: true,
            phase,
            events,
            stats: Stats::default(),
        })
    }

    /// Time reached [s].
    pub fn t(&self) -> f64 {
        self.t
    }

    /// State reached (x [m], v [m/s]); inside the sphere while slack.
    pub fn state(&self) -> State {
        self.s
    }

    /// True while the string is taut (the bob on the sphere), false while slack (in free flight).
    pub fn is_taut(&self) -> bool {
        matches!(self.phase, Phase::Taut)
    }

    /// The pendulum.
    pub fn model(&self) -> &StringPendulum {
        &self.model
    }

    /// Taut-phase steps and evaluations so far.
    pub fn stats(&self) -> Stats {
        self.stats
    }

    /// The events since the last call (or the start), in order.
    pub fn take_events(&mut self) -> Vec<StringEvent> {
        std::mem::take(&mut self.events)
    }

    /// The string's tension [N] at the state reached: T-2.3 while taut (≥ 0), 0 while slack.
    pub fn tension(&self) -> f64 {
        if self.is_taut() {
            self.model.tension(&self.s)
        } else {
            0.0
        }
    }

    /// The acceleration ẍ [m/s²] at the state reached: the rod's f + λx (T-2.2) while taut, gravity
    /// alone while slack.
    pub fn acceleration(&self) -> DVec3 {
        if self.is_taut() {
            super::acceleration(&self.rod, self.t, self.s.x, self.s.v)
        } else {
            self.rod.applied_acceleration(self.t, self.s.x, self.s.v)
        }
    }

    /// Takes `n` steps of the grid: advances to the grid point t₀ + (K + n)·dt, K the grid index of
    /// the previous target (0 at the start); a taut step is dt, shortened at events.
    pub fn step(&mut self, n: u64) -> Result<()> {
        self.target += n;
        let t_end = self.t0 + self.target as f64 * self.dt;
        self.advance(t_end, u64::MAX, &mut |_, _, _| Ok(()))
    }

    /// Advances to `t_end` [s], calling `push(t, state, taut)` at every `save_every`-th grid point,
    /// after every event and at t_end; nothing when `t_end` is not after the time reached.
    pub fn advance(
        &mut self,
        t_end: f64,
        save_every: u64,
        push: &mut dyn FnMut(f64, State, bool) -> Result<()>,
    ) -> Result<()> {
        self.advance_to(t_end, true, save_every, push)
    }

    /// Advances to `t_stop` [s], calling `push` at every `save_every`-th grid point and after every
    /// event. `end`: t_stop ends the run — pushed, and a snap exactly at t_stop is left undone (the
    /// state there is the one before it), as in [`StringStepper::advance`]. Otherwise t_stop is a
    /// stop on the way (a chunk's end, a save time): pushed only when it is a `save_every`-th grid
    /// point, and a snap exactly at t_stop is done, so that the run goes on as if it had not stopped.
    fn advance_to(
        &mut self,
        t_end: f64,
        end: bool,
        save_every: u64,
        push: &mut dyn FnMut(f64, State, bool) -> Result<()>,
    ) -> Result<()> {
        let (t0, dt) = (self.t0, self.dt);
        let grid = |k: u64| t0 + k as f64 * dt;
        let slack_grid = 1e-9 * dt;
        while self.t < t_end {
            match self.phase {
                Phase::Taut => {
                    // the next grid point (or t_end), reached by a full step dt when on the grid
                    let next = grid(self.k + 1);
                    let t_next = next.min(t_end);
                    let h = if self.on_grid && t_next == next { dt } else { t_next - self.t };
                    // the grid index and whether on the grid once at t_next
                    let (k_next, on_grid_next) =
                        if t_next == next { (self.k + 1, true) } else { (self.k, false) };
                    if h <= slack_grid {
                        (self.t, self.k, self.on_grid) = (t_next, k_next, on_grid_next);
                        continue;
                    }
                    let mut trial = self.scheme.clone();
                    let mut s1 = self.s;
                    trial.step(&self.rod, self.t, &mut s1, h)?;
                    self.stats.steps += 1;
                    self.stats.rhs_evals += trial.evals();
                    if self.model.tension(&s1) >= 0.0 {
                        (self.scheme, self.s, self.t, self.k, self.on_grid) =
                            (trial, s1, t_next, k_next, on_grid_next);
                        if (on_grid_next && self.k % save_every == 0) || (end && self.t >= t_end) {
                            push(self.t, self.s, true)?;
                        }
                        continue;
                    }
                    // T < 0 at the end of the step: shorten it to where T = 0 (to round-off in h)
                    let trials = std::cell::Cell::new(0u64);
                    let (t, s, scheme, rod) = (self.t, self.s, &self.scheme, &self.rod);
                    let at = |h: f64| {
                        trials.set(trials.get() + 1);
                        let (mut sc, mut sh) = (scheme.clone(), s);
                        sc.step(rod, t, &mut sh, h).map(|_| sh)
                    };
                    let h_star = bisect(0.0, h, |h| at(h).map_or(true, |sh| self.model.tension(&sh) < 0.0));
                    let leave = at(h_star)?;
                    self.stats.rhs_evals += trials.get() * trial.evals();
                    self.t += h_star;
                    self.s = leave;
                    self.on_grid = false;
                    self.events.push(StringEvent {
                        t: self.t,
                        kind: EventKind::Slack,
                        before: self.s,
                        after: self.s,
                        energy_lost: 0.0,
                    });
                    push(self.t, self.s, false)?;
                    self.phase = self.model.flight_from(self.t, self.s, 2);
                }
                Phase::Slack { t: te, from, arrival } => {
                    // grid samples along the exact parabola until the arrival or t_end
                    while grid(self.k + 1) < arrival.min(t_end) {
                        self.k += 1;
                        if self.k % save_every == 0 {
                            let gk = grid(self.k);
                            push(gk, self.model.flight(&from, gk - te), false)?;
                        }
                    }
                    if arrival > t_end || (end && arrival == t_end) {
                        let on_grid = grid(self.k + 1) == t_end;
                        if on_grid {
                            self.k += 1;
                        }
                        self.s = self.model.flight(&from, t_end - te);
                        self.t = t_end;
                        if end || (on_grid && self.k % save_every == 0) {
                            push(self.t, self.s, false)?;
                        }
                        break;
                    }
                    let before = self.model.flight(&from, arrival - te);
                    let (after, lost, taut) = self.model.snap(&before);
                    self.t = arrival;
                    self.s = after;
                    self.on_grid = false;
                    self.scheme.reset();
                    self.events.push(StringEvent {
                        t: self.t,
                        kind: EventKind::Taut,
                        before,
                        after,
                        energy_lost: lost,
                    });
                    if taut && self.model.tension(&self.s) < 0.0 {
                        self.events.push(StringEvent {
                            t: self.t,
                            kind: EventKind::Slack,
                            before: self.s,
                            after: self.s,
                            energy_lost: 0.0,
                        });
                        self.phase = self.model.flight_from(self.t, self.s, 2);
                    } else if taut {
                        self.phase = Phase::Taut;
                    } else {
                        self.phase = self.model.flight_from(self.t, self.s, 1);
                    }
                    push(self.t, self.s, self.is_taut())?;
                }
            }
        }
        Ok(())
    }
}
