//! What a session is told: its [`Setup`] (a scenario's pendulum, start and settings), the [`Command`]s
//! (already checked against the lab's limits by the wire), the [`StateSpec`] of a command's state, and
//! what a tick hands out ([`Out`]). Units: SI (s, m, m/s, kg, m/s²).

use crate::integrate::Method;
use crate::live::crane::CraneCommand;
use crate::live::frame::Record;
use crate::live::pendulum::LivePendulum;
use crate::state::State;
use crate::string_run::StringEvent;
use crate::DVec3;
use serde_json::Value;

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

/// dop853's default relative tolerance (scenario files' default).
pub const DEFAULT_RTOL: f64 = 1e-10;
/// dop853's default absolute tolerance [m, m/s].
pub const DEFAULT_ATOL: f64 = 1e-12;

impl Setup {
    /// `pendulum` from `state` at t0 = 0 s with `method` and step `dt` \[s\], the default tolerances,
    /// no scenario name or title.
    pub fn new(pendulum: LivePendulum, state: State, method: Method, dt: f64) -> Self {
        Setup {
            name: None,
            title: None,
            pendulum,
            state,
            method,
            dt,
            rtol: DEFAULT_RTOL,
            atol: DEFAULT_ATOL,
            t0: 0.0,
        }
    }
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
    /// The crane mode: switch to it, drive or move the trolley, hoist ([`crate::live::crane`]).
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
    /// A status notice ([`LiveSession::status`](crate::live::LiveSession::status) when it was made).
    Status(Value),
    /// An error notice: message and the command it was about.
    Error(String, Option<&'static str>),
    /// One of the string's events, its epoch and how many earlier ones of the tick were skipped.
    Event(StringEvent, u64, usize),
    /// An error notice a page translates: the English message, the command it was about, the message
    /// key (`python/pendulab/server/messages.json`) and its values.
    Keyed(String, Option<&'static str>, &'static str, Value),
}
