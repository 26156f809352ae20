//! Many trajectories of any rod model with an adaptive method (DOP853 on T-2.4 with its own step size
//! per trajectory, T-9.x of docs/theory.md), for the models the RATTLE kernel does not run: drag,
//! periodic forcing, dry friction, a moving pivot, a rotating frame. Each trajectory is exactly the
//! single-trajectory run: the same [`crate::Solver`] (stepper, step-size control, projection, saving
//! at the given times), so the numbers are those of `solve` with the same settings, bit for bit. The
//! trajectories run in parallel (rayon, feature `parallel`), one per task; they are not vectorised
//! across lanes, since their step sizes differ. Progress counts finished trajectories; the cancel flag
//! is read every [`CHECK_STEPS`] steps of every trajectory. SI units: t \[s\], x \[m\], v [m/s].

use crate::error::Result;
use crate::model::Model;
use crate::solve::{SaveAt, Solver};
use crate::state::State;
use crate::stepper::SolveOptions;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};

/// Steps of one trajectory between checks of the cancel flag.
pub const CHECK_STEPS: u64 = 4096;

/// How every trajectory of an adaptive ensemble is run (the settings of one [`Solver`]).
#[derive(Debug, Clone)]
pub struct AdaptiveSettings {
    /// Method, tolerances, projection (as for [`Solver::new`]).
    pub options: SolveOptions,
    /// Start and end time \[s\].
    pub t0: f64,
    pub t_end: f64,
    /// The times \[s\] at which every trajectory is saved (increasing, within [t0, t_end]).
    pub times: Vec<f64>,
    /// Also keep energy and J₃ where the model conserves them (`Stepper::set_invariant_projection`).
    pub conserve: bool,
}

/// The result of [`run_adaptive`]: per trajectory its states at [`AdaptiveSettings::times`]
/// (trajectory-major, `states[k * times.len() + j]`; NaN where a cancelled run did not get to), and
/// whether the run was cancelled.
#[derive(Debug, Clone)]
pub struct AdaptiveResult {
    pub states: Vec<State>,
    /// Accepted steps of each trajectory.
    pub steps: Vec<u64>,
    pub cancelled: bool,
}

/// Integrates every start with `model` and `settings`, in parallel. Fails before any work on
/// settings [`Solver::new`] refuses or a start off TS², and after it when a trajectory fails
/// (diverges, too many steps: the first such error in the order of the starts).
pub fn run_adaptive<M: Model + Clone + Send + Sync>(
    model: &M,
    starts: &[State],
    settings: &AdaptiveSettings,
    progress: &AtomicU64,
    cancel: &AtomicBool,
) -> Result<AdaptiveResult> {
    let ns = settings.times.len();
    let solver = |s: &State| -> Result<Solver<M>> {
        let save = SaveAt::Times(settings.times.clone());
        let bytes = (ns as u64).saturating_mul(crate::solve::BYTES_PER_SAMPLE);
        let mut sv =
            Solver::new(model.clone(), settings.t0, *s, settings.t_end, &settings.options, save, bytes)?;
        sv.stepper_mut().set_invariant_projection(settings.conserve);
        Ok(sv)
    };
    for s in starts {
        State::on_tangent_bundle(model.params(), s.x, s.v)?;
    }
    if let Some(s) = starts.first() {
        solver(s)?; // the settings, checked once before the parallel work
    }
    let mut states = vec![State { x: glam::DVec3::NAN, v: glam::DVec3::NAN }; starts.len() * ns];
    let work = |(s, out): (&State, &mut [State])| -> Result<(u64, bool)> {
        let mut sv = solver(s)?;
        let mut kept = 0;
        let done = loop {
            if cancel.load(Ordering::Relaxed) {
                break false;
            }
            let done = sv.advance(CHECK_STEPS)?;
            for st in sv.take_samples().states {
                out[kept] = st;
                kept += 1;
            }
            if done {
                break true;
            }
        };
        progress.fetch_add(u64::from(done), Ordering::Relaxed);
        Ok((sv.stats().steps, !done))
    };
    #[cfg(feature = "parallel")]
    let outputs: Vec<Result<(u64, bool)>> = {
        use rayon::prelude::*;
        starts.par_iter().zip(states.par_chunks_mut(ns.max(1))).map(work).collect()
    };
    #[cfg(not(feature = "parallel"))]
    let outputs: Vec<Result<(u64, bool)>> =
        starts.iter().zip(states.chunks_mut(ns.max(1))).map(work).collect();
    let mut steps = Vec::with_capacity(starts.len());
    let mut cancelled = false;
    for o in outputs {
        let (n, c) = o?;
        steps.push(n);
        cancelled |= c;
    }
    Ok(AdaptiveResult { states, steps, cancelled })
}
