//! One lab session without any I/O (docs/web.md, "Pacing"): a pendulum, its stepper, the start, the
//! pacing by the wall clock × time scale, the commands, and one tick's work within a wall-time budget —
//! the Python server's `pendulab.server.session` and `tick`, once in Rust, so that the page's own
//! engine (WebAssembly in a Web Worker) runs the same session as the server. Time is passed in: the
//! wall-clock seconds elapsed since the last tick, and a [`Clock`] for the budget.
//!
//! Fixed-step methods take whole steps of exactly dt, so a live run is the same sequence of steps as a
//! batch run with that dt; `dop853` lands on the target times. A tick sends up to [`MAX_SUBSAMPLES`]
//! records spread over its simulated interval. Units: SI (s, m, m/s, kg, m/s²).

use super::budget::{Budget, Clock, Slicer, TICK_BUDGET};
use super::crane::{CraneCommand, CRANE};
use super::error::{LiveError, Reference};
use super::frame::{Record, FRAME_FIELDS};
use super::pendulum::{methods_for, LivePendulum, LiveStepper, DEFAULT_METHOD};
use crate::error::{Error, Result};
use crate::integrate::Method;
use crate::state::State;
use crate::stepper::SolveOptions;
use crate::string_run::StringEvent;
use crate::DVec3;
use serde_json::{json, Value};

/// Most steps of `step` commands waiting to be taken.
pub const MAX_PENDING_STEPS: u64 = 1_000_000;
/// Most frame records sent per tick.
pub const MAX_SUBSAMPLES: usize = 16;
/// Longest wall-clock interval \[s\] one tick catches up on.
pub const MAX_ELAPSED: f64 = 0.1;
/// Most `event` notices sent per tick (the latest).
pub const MAX_EVENT_NOTICES: usize = 16;

/// What a session starts from: a scenario's pendulum, start, method and settings.
#[derive(Debug, Clone)]
pub struct Setup {
    /// Scenario name (None: none).
    pub name: Option<String>,
    /// Its title.
    pub title: Option<String>,
    /// The pendulum.
    pub pendulum: LivePendulum,
    /// The start (x \[m\], v [m/s]).
    pub state: State,
    /// The integrator.
    pub method: Method,
    /// Step \[s\] (dop853: initial guess).
    pub dt: f64,
    /// dop853's relative tolerance.
    pub rtol: f64,
    /// dop853's absolute tolerance.
    pub atol: f64,
    /// Start time \[s\].
    pub t0: f64,
}

/// A state as a command gives it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum StateSpec {
    /// x \[m\], v [m/s]; `project` moves them onto TS².
    Cartesian {
        /// Position.
        x: DVec3,
        /// Velocity.
        v: DVec3,
        /// Project onto TS².
        project: bool,
    },
    /// θ, φ \[rad\], θ̇, φ̇ [rad/s].
    Angles([f64; 4]),
}

/// A command, already checked against the lab's limits (the wire's JSON parsing does that).
#[derive(Debug, Clone)]
pub enum Command {
    /// New l \[m\], m \[kg\], g [m/s²] and/or own parameters; the model kept.
    SetParams {
        /// Length.
        length: Option<f64>,
        /// Mass.
        mass: Option<f64>,
        /// Gravity.
        g: Option<f64>,
        /// Own parameters.
        params: Vec<(String, f64)>,
    },
    /// Another model, with own parameters.
    SetModel {
        /// Registry name.
        model: String,
        /// Own parameters.
        params: Vec<(String, f64)>,
    },
    /// A new state and start.
    SetState(StateSpec),
    /// Method and/or dt \[s\].
    SetMethod {
        /// Method.
        method: Option<Method>,
        /// Step.
        dt: Option<f64>,
    },
    /// Simulated seconds per wall-clock second.
    SetTimeScale(f64),
    /// Pause.
    Pause,
    /// Resume.
    Resume,
    /// n steps, paused.
    Step(u64),
    /// Back to the start.
    Reset,
    /// A scenario.
    Load(Box<Setup>),
    /// The crane mode: switch to it, drive or move the trolley, hoist ([`super::crane`]).
    Crane(CraneCommand),
}

impl Command {
    /// The wire name of the command.
    pub fn name(&self) -> &'static str {
        match self {
            Command::SetParams { .. } => "set_params",
            Command::SetModel { .. } => "set_model",
            Command::SetState(_) => "set_state",
            Command::SetMethod { .. } => "set_method",
            Command::SetTimeScale(_) => "set_time_scale",
            Command::Pause => "pause",
            Command::Resume => "resume",
            Command::Step(_) => "step",
            Command::Reset => "reset",
            Command::Load(_) => "load_scenario",
            Command::Crane(_) => "crane",
        }
    }
}

/// What a tick hands out, in order.
#[derive(Debug, Clone)]
pub enum Out {
    /// Frame records (one binary message).
    Frames(Vec<Record>),
    /// A status notice ([`LiveSession::status`] when it was made).
    Status(Value),
    /// An error notice: message and the command it was about.
    Error(String, Option<&'static str>),
    /// One of the string's events, its epoch and how many earlier ones of the tick were skipped.
    Event(StringEvent, u64, usize),
    /// An error notice a page translates: the English message, the command it was about, the message
    /// key (`python/pendulab/server/messages.json`) and its values.
    Keyed(String, Option<&'static str>, &'static str, Value),
}

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
    /// Step \[s\].
    pub dt: f64,
    /// dop853 tolerances.
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
    stop: Option<Error>,
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
            stop: None,
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

    /// A new stepper (and error estimate) from `state` at `t`; `pendulum` replaces the current one only
    /// once its stepper exists (a method refusing the model leaves the session unchanged).
    fn new_stepper(&mut self, state: State, t: f64, pendulum: Option<LivePendulum>) -> Result<()> {
        self.collect_events();
        let p = pendulum.unwrap_or_else(|| self.pendulum.clone());
        let stepper = make(&p, state, t, self.method, self.dt, self.rtol, self.atol)?;
        let options = solve_options(self.method, self.dt, self.rtol, self.atol);
        self.error = LiveError::new(&p, state, t, &options, self.exact_error);
        self.stepper = stepper;
        self.pendulum = p;
        self.clock = t;
        self.pending_steps = 0;
        self.slicer.reset();
        Ok(())
    }

    fn load(&mut self, s: Setup) -> Result<()> {
        let stepper = make(&s.pendulum, s.state, s.t0, s.method, s.dt, s.rtol, s.atol)?;
        self.collect_events();
        (self.scenario, self.title) = (s.name, s.title);
        (self.method, self.dt, self.rtol, self.atol, self.t0) = (s.method, s.dt, s.rtol, s.atol, s.t0);
        (self.start, self.start_length) = (s.state, s.pendulum.params.length);
        let options = solve_options(s.method, s.dt, s.rtol, s.atol);
        self.error = LiveError::new(&s.pendulum, s.state, s.t0, &options, self.exact_error);
        (self.stepper, self.pendulum) = (stepper, s.pendulum);
        self.clock = s.t0;
        self.pending_steps = 0;
        self.slicer.reset();
        Ok(())
    }

    fn collect_events(&mut self) {
        let epoch = self.epoch;
        self.events.extend(self.stepper.take_events().into_iter().map(|e| (e, epoch)));
    }

    /// Carries out one command; the records to send at once (a discontinuity), or None. On an error
    /// the session is unchanged (an integration error pauses it).
    pub fn apply(&mut self, cmd: Command) -> Result<Option<Record>> {
        self.apply_inner(cmd).map_err(|e| match e {
            Error::Diverged { .. } | Error::StepSizeUnderflow { .. } | Error::PoleSingularity { .. } => {
                self.paused = true;
                self.stop = Some(e.clone());
                Error::Refused(format!("integration stopped: {e}; paused"))
            }
            other => other,
        })
    }

    fn apply_inner(&mut self, cmd: Command) -> Result<Option<Record>> {
        match cmd {
            Command::SetParams { length, mass, g, params } => {
                let new = self.pendulum.rebuild(None, length, mass, g, &params)?;
                if let LiveStepper::Crane(c) = &mut self.stepper {
                    c.update(new.params, &new.own)?; // in place: a new length hoists, the rest applies at once
                    self.pendulum = new;
                    return Ok(None);
                }
                let (s, k) = (self.stepper.state(), new.params.length / self.pendulum.params.length);
                let state = new.state(s.x * k, s.v * k, true)?;
                self.new_stepper(state, self.stepper.t(), Some(new))?;
            }
            Command::SetModel { model, params } => {
                let new = self.pendulum.rebuild(Some(&model), None, None, None, &params)?;
                let state = new.carry(&self.stepper.state())?;
                let old = self.method;
                if let Some(allowed) = methods_for(new.model) {
                    if !allowed.contains(&self.method.info().name) {
                        // the spring and the string run the RATTLE family, the crane its DOP853
                        self.method = Method::from_name(allowed[0]).unwrap_or(DEFAULT_METHOD);
                    }
                }
                if let Err(e) = self.new_stepper(state, self.stepper.t(), Some(new)) {
                    self.method = old;
                    return Err(e);
                }
            }
            Command::SetState(spec) => {
                let state = match spec {
                    StateSpec::Cartesian { x, v, project } => self.pendulum.state(x, v, project)?,
                    StateSpec::Angles([th, ph, thd, phd]) => {
                        self.pendulum.state_from_angles(th, ph, thd, phd)?
                    }
                };
                self.new_stepper(state, self.stepper.t(), None)?;
                (self.start, self.start_length) = (state, self.pendulum.params.length);
            }
            Command::SetMethod { method, dt } => {
                let old = (self.method, self.dt);
                self.method = method.unwrap_or(self.method);
                self.dt = dt.unwrap_or(self.dt);
                if let Err(e) = self.new_stepper(self.stepper.state(), self.stepper.t(), None) {
                    (self.method, self.dt) = old;
                    return Err(e);
                }
                return Ok(None);
            }
            Command::SetTimeScale(s) => {
                self.time_scale = s;
                return Ok(None);
            }
            Command::Pause => {
                self.paused = true;
                return Ok(None);
            }
            Command::Resume => {
                self.paused = false;
                self.pending_steps = 0;
                self.clock = self.stepper.t();
                return Ok(None);
            }
            Command::Step(n) => {
                if self.pending_steps + n > MAX_PENDING_STEPS {
                    return Err(Error::Refused(format!(
                        "still stepping: {} steps are waiting to be taken (at most {MAX_PENDING_STEPS}); wait \
                         for the frame, or pause",
                        self.pending_steps
                    )));
                }
                self.paused = true;
                self.pending_steps += n;
                return Ok(None);
            }
            Command::Reset => self.new_stepper(self.start_state(), self.t0, None)?,
            Command::Load(setup) => self.load(*setup)?,
            Command::Crane(c) => return self.crane(c),
        }
        self.epoch += 1;
        Ok(Some(self.record()))
    }

    /// The crane mode's command: `on` switches to the crane (a discontinuity: the current record is
    /// returned), the motions go to the crane; refused outside the crane mode without `on`.
    fn crane(&mut self, c: CraneCommand) -> Result<Option<Record>> {
        let mut switched = None;
        if c.on && self.pendulum.model != CRANE {
            self.apply_inner(Command::SetModel { model: CRANE.into(), params: Vec::new() })?;
            switched = Some(self.record());
        }
        let LiveStepper::Crane(crane) = &mut self.stepper else {
            return Err(Error::Refused(
                "not in the crane mode: send {\"type\": \"crane\", \"on\": true} first".into(),
            ));
        };
        crane.apply(&c)?;
        if let Some(rope) = c.rope {
            self.pendulum.params.length = rope;
        }
        Ok(switched)
    }

    /// Takes the waiting steps of `step` commands within `budget`; the record reached (None when none
    /// were waiting).
    pub fn take_pending_steps(&mut self, budget: &Budget<'_>) -> Result<Option<Record>> {
        if self.pending_steps == 0 {
            return Ok(None);
        }
        let stepper = &mut self.stepper;
        match self.slicer.steps(|k| stepper.step(k), self.pending_steps, budget) {
            Ok(n) => self.pending_steps -= n.min(self.pending_steps),
            Err(e) => {
                self.pending_steps = 0;
                self.paused = true;
                self.stop = Some(e.clone());
                return Err(Error::Refused(format!(
                    "integration stopped at t = {} s: {e}; paused",
                    self.stepper.t()
                )));
            }
        }
        self.clock = self.stepper.t();
        Ok(Some(self.record()))
    }

    /// Advances by `elapsed` wall-clock seconds × time_scale within `budget`; the records reached. Out
    /// of budget it stops where it got to and sets `lagging`.
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
            self.paused = true;
            self.stop = Some(e.clone());
            return Err(Error::Refused(format!(
                "integration stopped at t = {} s: {e}; paused",
                self.stepper.t()
            )));
        }
        self.lagging = !done;
        if !done {
            self.clock = self.stepper.t();
        }
        Ok(out)
    }

    /// What a new connection gets first: the status and the current state's frame.
    pub fn first_messages(&mut self, clock: &dyn Clock) -> Vec<Out> {
        let budget = Budget::new(clock, TICK_BUDGET);
        let mut rec = vec![self.record()];
        self.error.fill(&mut rec, &budget);
        let mut out = vec![Out::Status(self.status())];
        self.finite(rec, &mut out);
        out
    }

    /// One tick: the commands in order (`Err`: a message refused before it became a command, with its
    /// text and command name), the waiting steps, the advance by `elapsed` \[s\], the error estimate in
    /// what is left of `budget_seconds`, the frames, the string's events, and status notices where
    /// something changed. `dropped`: messages thrown away (throttling). [`LiveSession::tick_fair`]
    /// with every command carried out.
    pub fn tick(
        &mut self,
        commands: Vec<std::result::Result<Command, (String, Option<&'static str>)>>,
        elapsed: f64,
        clock: &dyn Clock,
        budget_seconds: f64,
        dropped: u64,
    ) -> Vec<Out> {
        self.tick_fair(commands, elapsed, clock, budget_seconds, dropped, None).0
    }

    /// [`LiveSession::tick`], with the commands inside the budget when `debt` \[s\] is given (a server
    /// with many sessions): at least one command, more only while the budget lasts; the wall time the
    /// commands took beyond `budget_seconds` is added to `debt`, and while in debt the tick carries out
    /// none (stepping and frames go on) and pays off `budget_seconds`. So a page that floods
    /// `load_scenario` gets about its share of the room, not a tick's worth of commands per tick.
    /// Returns the messages and how many of `commands` were carried out (the rest wait for the caller
    /// to hand them in again; they are counted in `commands` then).
    pub fn tick_fair(
        &mut self,
        commands: Vec<std::result::Result<Command, (String, Option<&'static str>)>>,
        elapsed: f64,
        clock: &dyn Clock,
        budget_seconds: f64,
        dropped: u64,
        mut debt: Option<&mut f64>,
    ) -> (Vec<Out>, usize) {
        let budget = Budget::new(clock, budget_seconds);
        let started = budget.now();
        let mut out = Vec::new();
        let mut changed = !commands.is_empty() || dropped > 0;
        self.commands += dropped;
        let mut taken = 0;
        let mut parts: [Vec<Record>; 3] = [Vec::new(), Vec::new(), Vec::new()];
        if let Some(d) = debt.as_deref_mut().filter(|d| **d > 0.0) {
            *d = (*d - budget_seconds).max(0.0); // paying for earlier commands: none this tick
            changed = dropped > 0;
        } else {
            let fair = debt.is_some();
            for item in commands {
                if fair && taken > 0 && budget.spent() {
                    break;
                }
                taken += 1;
                self.commands += 1;
                match item {
                    Err((message, command)) => out.push(Out::Error(message, command)),
                    Ok(cmd) => {
                        let name = cmd.name();
                        match self.apply(cmd) {
                            Ok(Some(r)) => parts[0] = vec![r], // only the last discontinuity matters
                            Ok(None) => {}
                            Err(e) => out.push(self.error_out(e, Some(name))),
                        }
                    }
                }
            }
            if let Some(d) = debt.filter(|_| taken > 0) {
                *d += (budget.now() - started - budget_seconds).max(0.0);
            }
        }
        let was_lagging = self.lagging;
        match self.take_pending_steps(&budget) {
            Ok(Some(r)) => {
                parts[1] = vec![r];
                changed |= self.pending_steps == 0;
            }
            Ok(None) => {}
            Err(e) => {
                out.push(self.error_out(e, Some("step")));
                changed = true;
            }
        }
        if changed {
            out.push(Out::Status(self.status()));
        }
        match self.advance(elapsed, &budget) {
            Ok(r) => parts[2] = r,
            Err(e) => {
                out.push(self.error_out(e, None));
                out.push(Out::Status(self.status()));
            }
        }
        let how = self.error.how;
        for part in parts.iter_mut() {
            self.error.fill(part, &budget);
        }
        if self.error.how != how {
            out.push(Out::Status(self.status()));
        }
        for part in parts {
            if !self.finite(part, &mut out) {
                break;
            }
        }
        out.extend(self.take_event_notices());
        if self.lagging != was_lagging {
            out.push(Out::Status(self.status()));
        }
        (out, taken)
    }

    /// The string's events since the last call as `event` notices, oldest first: at most
    /// [`MAX_EVENT_NOTICES`], the latest, each counting the earlier ones skipped (empty for the other
    /// models). Each keeps the epoch it happened in.
    pub fn take_event_notices(&mut self) -> Vec<Out> {
        self.collect_events();
        let events = std::mem::take(&mut self.events);
        let skipped = events.len().saturating_sub(MAX_EVENT_NOTICES);
        events.into_iter().skip(skipped).map(|(e, epoch)| Out::Event(e, epoch, skipped)).collect()
    }

    /// The notice of an error of a command, a step or the advance: keyed `integration_stopped` (with
    /// the integrator's words as `detail`) when the integration stopped, else plain. When the
    /// integrator's error is of a common kind ([`Error::key`]), `why` names its key and its values
    /// are beside `detail` (flat: a page words the detail in its language too).
    fn error_out(&mut self, e: Error, command: Option<&'static str>) -> Out {
        match self.stop.take() {
            Some(stop) => {
                let mut values = json!({ "detail": stop.to_string() });
                if let Some((why, more)) = stop.key() {
                    values["why"] = json!(why);
                    for (name, value) in more {
                        values[name] = json!(value);
                    }
                }
                Out::Keyed(e.to_string(), command, "integration_stopped", values)
            }
            None => Out::Error(e.to_string(), command),
        }
    }

    /// Appends `records` up to the first one holding a non-finite value; if there is one, pauses, adds
    /// an error notice naming the quantities and the time and a status, and returns false.
    fn finite(&mut self, records: Vec<Record>, out: &mut Vec<Out>) -> bool {
        if records.is_empty() {
            return true;
        }
        let Some(first) = records.iter().position(|r| !r.non_finite().is_empty()) else {
            out.push(Out::Frames(records));
            return true;
        };
        let bad = records[first].non_finite();
        let t = records[first].t();
        if first > 0 {
            out.push(Out::Frames(records[..first].to_vec()));
        }
        let when = if t.is_finite() { short(t) } else { format!("≈ {}", short(self.stepper.t())) };
        let fields = bad.iter().take(6).cloned().collect::<Vec<_>>().join(", ");
        self.paused = true;
        self.pending_steps = 0;
        out.push(Out::Keyed(
            format!(
                "the motion left floating point at t = {when} s ({fields} not finite): parameters or a start \
                 this extreme; paused — reset, or change the parameters"
            ),
            None,
            "nonfinite_motion",
            json!({ "t": when, "fields": fields }),
        ));
        out.push(Out::Status(self.status()));
        false
    }
}

/// `x` with 6 significant digits, trailing zeros dropped (Python's `{:.6g}` for the lab's times).
fn short(x: f64) -> String {
    if x == 0.0 || !x.is_finite() {
        return format!("{x}");
    }
    let digits = (5 - x.abs().log10().floor() as i32).clamp(0, 17) as usize;
    let s = format!("{x:.digits$}");
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::live::frame::FRAME_FIELDS;

    /// No frame carries a non-finite number: the records up to the first bad one are sent, the session
    /// pauses and an error names the quantities and the time.
    #[test]
    fn a_non_finite_record_is_never_sent_the_session_pauses_and_names_the_cause() {
        let p = LivePendulum::new("ideal", 1.0, 1.0, 9.81, &[]).unwrap();
        let state = p.state_from_angles(1.0, 0.0, 0.0, 2.0).unwrap();
        let setup = Setup {
            name: None,
            title: None,
            pendulum: p,
            state,
            method: Method::Rattle,
            dt: 1e-3,
            rtol: 1e-10,
            atol: 1e-12,
            t0: 0.0,
        };
        let mut s = LiveSession::new(setup).unwrap();
        let mut bad = s.record();
        let at = |name: &str| FRAME_FIELDS.iter().position(|f| *f == name).unwrap();
        bad.0[at("energy")] = f64::INFINITY;
        bad.0[at("tension")] = f64::NAN;
        let mut out = Vec::new();
        assert!(!s.finite(vec![s.record(), bad, s.record()], &mut out));
        assert!(matches!(&out[0], Out::Frames(r) if r.len() == 1), "the first record only");
        let Out::Keyed(message, None, "nonfinite_motion", values) = &out[1] else { panic!("{:?}", out[1]) };
        assert!(message.contains("(energy, tension not finite)"), "{message}");
        assert!(message.contains("t = 0 s") && message.contains("paused"), "{message}");
        assert_eq!(values, &json!({ "t": "0", "fields": "energy, tension" }));
        assert_eq!(
            (short(1.5), short(0.016), short(123.4567891), short(1e-7)),
            ("1.5".into(), "0.016".into(), "123.457".into(), "0.0000001".into())
        );
        assert!(matches!(&out[2], Out::Status(v) if v["paused"] == true) && s.paused && out.len() == 3);
        let mut good = Vec::new();
        assert!(s.finite(vec![s.record()], &mut good) && matches!(&good[..], [Out::Frames(_)]));
    }

    /// A stopped integration's notice carries the integrator's error kind and values beside its words.
    #[test]
    fn a_stopped_integration_names_why_with_its_values() {
        let p = LivePendulum::new("ideal", 1.0, 1.0, 9.81, &[]).unwrap();
        let state = p.state_from_angles(1.0, 0.0, 0.0, 2.0).unwrap();
        let setup = Setup {
            name: None,
            title: None,
            pendulum: p,
            state,
            method: Method::Rattle,
            dt: 1e-3,
            rtol: 1e-10,
            atol: 1e-12,
            t0: 0.0,
        };
        let mut s = LiveSession::new(setup).unwrap();
        let diverged = Error::Diverged { t: 2.5, method: "rk4", dt: 0.05 };
        s.stop = Some(diverged.clone());
        let Out::Keyed(_, None, "integration_stopped", values) =
            s.error_out(Error::Refused("x".into()), None)
        else {
            panic!("not keyed")
        };
        let expected = json!({ "detail": diverged.to_string(), "why": "diverged", "t": "2.5", "method": "rk4", "dt": "5.000e-2" });
        assert_eq!(values, expected);
        assert!(matches!(s.error_out(Error::Refused("x".into()), None), Out::Error(..)), "once");
    }
}
