//! The lab's live session, once for every front end (docs/web.md, "Pacing", "Error estimate",
//! "Frames"): a pendulum of any lab model stepped in slices within a per-tick wall-time budget, the
//! frame records of its states (energy T-2.6, J₃, tension T-2.3, power T-7.1, acceleration T-2.2), the
//! error estimate that travels with them (exact T-4.x for the ideal pendulum, else a companion run),
//! the commands and one tick's messages. No threads and no clock of its own: the caller passes in the
//! wall-clock time elapsed and a [`budget::Clock`], so the same code runs in the Python server's worker
//! threads (`pendulab._core.LiveSession`) and in a browser's Web Worker as WebAssembly (`crates/pendulab-wasm`). SI units throughout.
//!
//! - [`budget`]: [`budget::Clock`], [`budget::Budget`], [`budget::Slicer`].
//! - [`frame`]: the record layout (`frame.json`) and the records of states.
//! - [`pendulum`]: [`pendulum::LivePendulum`] (a lab model by registry name) and [`pendulum::LiveStepper`];
//!   `kinds`: how the lab runs each model (one table of the registry's models and the crane);
//!   `methods`: [`methods_for`] a model and the keyed refusal of the others; `no_parameter`: the
//!   refusal of a parameter the model does not have (another lab model's: the models that have it).
//! - [`error`]: [`error::LiveError`], the `error_x` column.
//! - [`session`]: [`session::LiveSession`]: commands, pacing, ticks.
//! - [`crane_plan`], [`crane`]: the crane mode (the trolley's shaped, acceleration-limited command, the
//!   hoist, wind; [`crane::LiveCrane`] steps the core's crane integrator).
//! - [`wire`]: JSON commands, scenarios and notices (the page's and the server's wire format).

pub mod budget;
pub mod crane;
pub mod crane_plan;
pub mod crane_wire;
pub mod error;
pub mod frame;
mod kinds;
mod methods;
mod no_parameter;
pub mod pendulum;
pub mod session;
pub mod wire;

#[cfg(test)]
mod crane_tests;

pub use budget::{Budget, Clock, Slicer, TICK_BUDGET};
pub use frame::{Record, FRAME_FIELDS, RECORD_LEN, UNKNOWN};
pub use methods::methods_for;
pub use pendulum::{live_models, LivePendulum, LiveStepper};
pub use session::{Command, LiveSession, Out, Setup, StateSpec};
