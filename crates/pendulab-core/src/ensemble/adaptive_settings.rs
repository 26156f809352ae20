//! The settings of an adaptive ensemble (`adaptive.rs`, `adaptive_lanes.rs`): how every trajectory
//! is run (method, tolerances, t0 and t_end [s], save times [s], invariant projection) and which
//! model each trajectory runs (one for all, or one per distinct parameter set and an index:
//! per-trajectory length l [m], g [m/s²], damping c [1/s]).

use crate::error::{Error, Result};
use crate::stepper::SolveOptions;

/// How every trajectory of an adaptive ensemble is run (the settings of one [`crate::Solver`]).
#[derive(Debug, Clone)]
pub struct AdaptiveSettings {
    /// Method, tolerances, projection (as for [`crate::Solver::new`]).
    pub options: SolveOptions,
    /// Start and end time \[s\].
    pub t0: f64,
    pub t_end: f64,
    /// The times \[s\] at which every trajectory is saved (increasing, within [t0, t_end]).
    pub times: Vec<f64>,
    /// Also keep energy and J₃ where the model conserves them (`Stepper::set_invariant_projection`).
    pub conserve: bool,
}

/// The model of every trajectory: `models[index[k]]` for trajectory k (`index` empty: `models[0]`
/// for all), so that per-trajectory parameters need one model per distinct parameter set.
#[derive(Debug, Clone, Copy)]
pub struct Models<'a, M> {
    pub models: &'a [M],
    pub index: &'a [u32],
}

impl<'a, M> Models<'a, M> {
    /// One model for every trajectory.
    pub fn one(model: &'a M) -> Self {
        Self { models: std::slice::from_ref(model), index: &[] }
    }

    /// Trajectory k's model.
    #[inline(always)]
    pub fn of(&self, k: usize) -> &'a M {
        if self.index.is_empty() {
            &self.models[0]
        } else {
            &self.models[self.index[k] as usize]
        }
    }

    /// Checks the index against the models and the number of trajectories `n`.
    pub(super) fn check(&self, n: usize) -> Result<()> {
        if self.models.is_empty() {
            return Err(Error::InvalidParameter {
                name: "models",
                value: 0.0,
                allowed: "at least one model",
            });
        }
        if !self.index.is_empty() && self.index.len() != n {
            return Err(Error::InvalidParameter {
                name: "model index",
                value: self.index.len() as f64,
                allowed: "one model index per trajectory (or none: the first model for all)",
            });
        }
        if let Some(&i) = self.index.iter().find(|&&i| i as usize >= self.models.len()) {
            return Err(Error::InvalidParameter {
                name: "model index",
                value: f64::from(i),
                allowed: "an index into the list of models",
            });
        }
        Ok(())
    }
}
