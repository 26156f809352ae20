//! Many trajectories of any rod model with an adaptive method (DOP853 on T-2.4 with its own step size
//! per trajectory, T-9.x of docs/theory.md), for the models the RATTLE kernel does not run: drag,
//! periodic forcing, dry friction, a moving pivot, a rotating frame; each trajectory may have its own
//! model (per-trajectory length, g, damping: [`Models`]). Each trajectory is exactly the
//! single-trajectory run: the same steps, step-size control and projection as [`crate::Solver`] with
//! the same settings, bit for bit. When every trajectory is saved at t_end only (and at t0), the
//! trajectories run vectorised, [`adaptive_lanes::LANES`] at a time with a step size and an
//! accept/reject decision per lane (`adaptive_lanes.rs`); with other save times (dense output) each
//! runs its own [`Solver`] ([`run_adaptive_serial`]). Chunks of trajectories run in parallel (rayon,
//! feature `parallel`). Progress counts finished trajectories; the cancel flag is read every
//! [`CHECK_STEPS`] steps of every trajectory (every 256 attempts of the lanes). SI units: t \[s\],
//! x \[m\], v [m/s].

use super::adaptive_lanes;
pub use super::adaptive_settings::{AdaptiveSettings, Models};
use crate::error::{Error, Result};
use crate::model::{AnyModel, Extended, IdealPendulum, Model};
use crate::solve::{SaveAt, Solver};
use crate::state::State;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};

/// Steps of one trajectory between checks of the cancel flag.
pub const CHECK_STEPS: u64 = 4096;

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

/// Integrates every start with `model` and `settings`, in parallel ([`run_adaptive_models`] with one
/// model for all).
pub fn run_adaptive<M: Model + Clone + Send + Sync>(
    model: &M,
    starts: &[State],
    settings: &AdaptiveSettings,
    progress: &AtomicU64,
    cancel: &AtomicBool,
) -> Result<AdaptiveResult> {
    run_adaptive_models(&Models::one(model), starts, settings, progress, cancel)
}

/// [`run_adaptive_models`] for registry models, with the lanes' right-hand side compiled for the
/// concrete model when every model is the ideal pendulum or every one an [`Extended`] model (no
/// dispatch on the variant in the lane loop; the numbers are the same as through [`AnyModel`],
/// whose calls hand over to the variant unchanged).
pub fn run_adaptive_any(
    models: &Models<'_, AnyModel>,
    starts: &[State],
    settings: &AdaptiveSettings,
    progress: &AtomicU64,
    cancel: &AtomicBool,
) -> Result<AdaptiveResult> {
    let ideal: Option<Vec<IdealPendulum>> =
        models.models.iter().map(|m| if let AnyModel::Ideal(p) = m { Some(*p) } else { None }).collect();
    if let Some(ms) = ideal {
        let ms = Models { models: &ms, index: models.index };
        return run_adaptive_models(&ms, starts, settings, progress, cancel);
    }
    let extended: Option<Vec<Extended>> = models
        .models
        .iter()
        .map(|m| if let AnyModel::Extended(e, _) = m { Some(*e) } else { None })
        .collect();
    if let Some(ms) = extended {
        let ms = Models { models: &ms, index: models.index };
        return run_adaptive_models(&ms, starts, settings, progress, cancel);
    }
    run_adaptive_models(models, starts, settings, progress, cancel)
}

/// Trajectories per parallel task of the vectorised path.
const CHUNK: usize = 16 * adaptive_lanes::LANES;

/// Integrates every start with its model and `settings`, in parallel: vectorised across
/// trajectories when the save times are \[t0, t_end\] or \[t_end\], else one [`Solver`] per trajectory.
/// Fails before any work on settings [`Solver::new`] refuses or a start off TS² of its model, and
/// after it when a trajectory fails (diverges, step size underflow: the first such error in the order
/// of the starts).
pub fn run_adaptive_models<M: Model + Clone + Send + Sync>(
    models: &Models<'_, M>,
    starts: &[State],
    settings: &AdaptiveSettings,
    progress: &AtomicU64,
    cancel: &AtomicBool,
) -> Result<AdaptiveResult> {
    let t = &settings.times;
    let lanes = t == &[settings.t0, settings.t_end] || t == &[settings.t_end];
    if !lanes {
        return run_adaptive_serial(models, starts, settings, progress, cancel);
    }
    check_adaptive(models, starts, settings)?;
    let ns = t.len();
    let mut states = vec![State { x: glam::DVec3::NAN, v: glam::DVec3::NAN }; starts.len() * ns];
    let job = adaptive_lanes::Job { models, starts, settings, ns, progress, cancel };
    let work = |(c, out): (usize, &mut [State])| adaptive_lanes::run_chunk(&job, c * CHUNK, out);
    #[cfg(feature = "parallel")]
    let outputs: Vec<_> = {
        use rayon::prelude::*;
        // every chunk its own task: their costs differ (adaptive steps), and an idle core steals one
        // chunk at a time (rayon's own split leaves pieces only their thread runs)
        states.par_chunks_mut(CHUNK * ns).enumerate().with_max_len(1).map(work).collect()
    };
    #[cfg(not(feature = "parallel"))]
    let outputs: Vec<_> = states.chunks_mut(CHUNK * ns).enumerate().map(work).collect();
    let mut steps = Vec::with_capacity(starts.len());
    let mut cancelled = false;
    for o in outputs {
        if let Some(e) = o.errors.into_iter().flatten().next() {
            return Err(e);
        }
        steps.extend(o.steps);
        cancelled |= o.cancelled;
    }
    Ok(AdaptiveResult { states, steps, cancelled })
}

/// The checks made before any work: the models' index, every start on TS² of its model, and the
/// settings as [`Solver::new`] makes them (for every distinct model). For callers that start the run
/// elsewhere (a background thread): the run fails with the same error.
pub fn check_adaptive<M: Model + Clone>(
    models: &Models<'_, M>,
    starts: &[State],
    settings: &AdaptiveSettings,
) -> Result<()> {
    models.check(starts.len())?;
    for (k, s) in starts.iter().enumerate() {
        let p = models.of(k).params();
        State::on_tangent_bundle(p, s.x, s.v).map_err(|e| match e {
            Error::NotOnTangentBundle { .. } => {
                Error::Refused(format!("start {k} (its length l = {} m): {e}", p.length))
            }
            e => e,
        })?;
    }
    if let Some(s) = starts.first() {
        for m in models.models {
            solver(m, s, settings)?;
        }
    }
    Ok(())
}

/// The single run of start `s` with model `m`.
fn solver<M: Model + Clone>(m: &M, s: &State, settings: &AdaptiveSettings) -> Result<Solver<M>> {
    let ns = settings.times.len();
    let save = SaveAt::Times(settings.times.clone());
    let bytes = (ns as u64).saturating_mul(crate::solve::BYTES_PER_SAMPLE);
    let mut sv = Solver::new(m.clone(), settings.t0, *s, settings.t_end, &settings.options, save, bytes)?;
    sv.stepper_mut().set_invariant_projection(settings.conserve);
    Ok(sv)
}

/// [`run_adaptive_models`] with one [`Solver`] per trajectory (any save times; not vectorised), one
/// trajectory per parallel task.
pub fn run_adaptive_serial<M: Model + Clone + Send + Sync>(
    models: &Models<'_, M>,
    starts: &[State],
    settings: &AdaptiveSettings,
    progress: &AtomicU64,
    cancel: &AtomicBool,
) -> Result<AdaptiveResult> {
    check_adaptive(models, starts, settings)?;
    let ns = settings.times.len();
    let mut states = vec![State { x: glam::DVec3::NAN, v: glam::DVec3::NAN }; starts.len() * ns];
    let work = |(k, (s, out)): (usize, (&State, &mut [State]))| -> Result<(u64, bool)> {
        let mut sv = solver(models.of(k), s, settings)?;
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
        let each = starts.par_iter().zip(states.par_chunks_mut(ns.max(1))).enumerate();
        each.with_max_len(1).map(work).collect() // every trajectory its own task (costs differ)
    };
    #[cfg(not(feature = "parallel"))]
    let outputs: Vec<Result<(u64, bool)>> =
        starts.iter().zip(states.chunks_mut(ns.max(1))).enumerate().map(work).collect();
    let mut steps = Vec::with_capacity(starts.len());
    let mut cancelled = false;
    for o in outputs {
        let (n, c) = o?;
        steps.push(n);
        cancelled |= c;
    }
    Ok(AdaptiveResult { states, steps, cancelled })
}
