//! The commands carried out on a session ([`LiveSession::apply`]): new parameters, model, state,
//! method, time scale, pause/resume/step/reset, a scenario, the crane mode; each either changes the
//! session or leaves it as it was. Units: SI (s, m, m/s, kg, m/s²).

use super::{make, solve_options, Command, LiveSession, Setup, StateSpec, MAX_PENDING_STEPS};
use crate::error::{Error, Result};
use crate::integrate::Method;
use crate::live::crane::{CraneCommand, CRANE};
use crate::live::error::LiveError;
use crate::live::frame::Record;
use crate::live::methods_for;
use crate::live::pendulum::{LivePendulum, LiveStepper, DEFAULT_METHOD};
use crate::state::State;

impl LiveSession {
    /// A new stepper (and error estimate) from `state` at `t`; `pendulum` replaces the current one only
    /// once its stepper exists (a method refusing the model leaves the session unchanged).
    pub(super) fn new_stepper(&mut self, state: State, t: f64, pendulum: Option<LivePendulum>) -> Result<()> {
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

    pub(super) fn collect_events(&mut self) {
        let epoch = self.epoch;
        self.events.extend(self.stepper.take_events().into_iter().map(|e| (e, epoch)));
    }

    /// Carries out one command; the records to send at once (a discontinuity), or None. On an error
    /// the session is unchanged (an integration error pauses it).
    pub fn apply(&mut self, cmd: Command) -> Result<Option<Record>> {
        self.apply_inner(cmd).map_err(|e| match e {
            Error::Diverged { .. } | Error::StepSizeUnderflow { .. } | Error::PoleSingularity { .. } => {
                self.stopped(e)
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
                    return Err(Error::RefusedKeyed {
                        words: format!(
                            "still stepping: {} steps are waiting to be taken (at most {MAX_PENDING_STEPS}); \
                             wait for the frame, or pause",
                            self.pending_steps
                        ),
                        key: "still_stepping",
                        values: vec![
                            ("waiting", self.pending_steps.to_string()),
                            ("most", MAX_PENDING_STEPS.to_string()),
                        ],
                    });
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
            let model = self.pendulum.model;
            return Err(Error::RefusedKeyed {
                words: format!(
                    "not in the crane mode (the session runs the {model:?} model): send \
                     {{\"type\": \"crane\", \"on\": true}} first"
                ),
                key: "not_crane",
                values: vec![("model", model.to_string())],
            });
        };
        crane.apply(&c)?;
        if let Some(rope) = c.rope {
            self.pendulum.params.length = rope;
        }
        Ok(switched)
    }
}
