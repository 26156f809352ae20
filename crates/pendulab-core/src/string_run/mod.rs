//! The hybrid simulation of the string pendulum ([`crate::model::StringPendulum`], see its module for the physics
//! and equations): taut phases with a fixed-step method that keeps TS² (T-2.2), the leave event where
//! the tension T-2.3 reaches 0 (bisection on the step length), analytic free flight, the re-taut
//! event on the exact parabola, and the snap. A driver beside [`crate::stepper`] and
//! [`mod@crate::solve`], built on the model (`model::string`) and the integrators; `model/` does not
//! know it.
//!
//! - [`StringStepper`] (`stepper.rs`): the incremental stepper (what the lab runs), its mode carried
//!   as state.
//! - [`StringRunner`] (`runner.rs`): a stepper run to t_end in chunks, keeping samples by a
//!   [`crate::SaveAt`] rule; [`crate::model::StringPendulum::simulate`] is one such run.
//! - This file: what both report, the events ([`EventKind`], [`StringEvent`]) and a run's samples
//!   ([`StringRun`]).
//!
//! Times \[s\] lie on the grid t₀ + k·dt as in [`crate::Stepper`]: full steps are exactly dt, so a
//! motion that never goes slack is the rod pendulum's, bit for bit. SI units throughout.

mod runner;
mod stepper;

pub use runner::{StringRunner, StringSettings};
pub use stepper::StringStepper;

use crate::integrate::Stats;
use crate::state::State;

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
    /// Time \[s\].
    pub t: f64,
    /// Leave or snap.
    pub kind: EventKind,
    /// State just before (for a leave: the state where T = 0).
    pub before: State,
    /// State just after (equal to `before` for a leave).
    pub after: State,
    /// Kinetic energy lost in the event \[J\] (0 for a leave; ½m(1 − e²)|u|² for a snap).
    pub energy_lost: f64,
}

/// The result of [`crate::model::StringPendulum::simulate`] (and what [`StringRunner::take`] hands out).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct StringRun {
    /// Times \[s\].
    pub t: Vec<f64>,
    /// States (x \[m\], v [m/s]); off the sphere while slack.
    pub states: Vec<State>,
    /// Whether the string is taut at each sample.
    pub taut: Vec<bool>,
    /// Every leave and snap, in order.
    pub events: Vec<StringEvent>,
    /// Taut-phase steps and evaluations.
    pub stats: Stats,
}
