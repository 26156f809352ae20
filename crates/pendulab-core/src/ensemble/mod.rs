//! Many pendulums at once with RATTLE (T-2.1, T-2.2; the same step as `integrate/rattle.rs`, built
//! from the same functions of `integrate/rattle_kernel.rs`, so each trajectory gets the
//! single-trajectory numbers exactly):
//!
//!   v½ = v₀ − (h/2) g e₃ + μ x₀ (|x₁| = l),  x₁ = x₀ + h v½,  v₁ = v½ − (h/2) g e₃ − x₁ (x₁·u)/l²,
//!
//! with Kahan-compensated updates, or its symmetric compositions of order 4, 6 and 8 (T-8.2;
//! [`RattleSettings::method`], `stages.rs`: each step the RATTLE sub-steps w_k·dt, as
//! `integrate/composition.rs` takes them), the multiply-adds unfused by default or fused on request
//! ([`RattleSettings::arithmetic`], as the single-trajectory path with the same choice). Optional linear
//! damping c [1/s] (force −m c v, T-7.1) enters as in the single-trajectory path of the `damped`
//! model: the exact damping flow v ↦ e^{−c h/2} v before and after each step (Strang splitting,
//! conformal symplectic). Optional settle tracking records, per
//! trajectory, the time after which the sway angle from the stable equilibrium −sign(g) e₃ stays at
//! or below a threshold (cos sway = −sign(g) z/l; resolution one step).
//!
//! Layout: blocks of [`LANES`] trajectories in structure-of-arrays form (`block_state.rs`), stepped
//! [`tile_lanes`] lanes at a time (4 to [`TILE`], chosen per instruction-set level; `block.rs`) with
//! the tile's state in vector registers for a whole chunk of steps (`tile.rs`: the step, in two
//! halves over the lanes; shared parameters held as one number each), branch-free over the lanes,
//! compiled for the widest vectors the CPU has ([`crate::isa`]). Each rayon worker
//! (feature `parallel`) builds its blocks from the starts and writes their samples straight into the
//! one result array (`output.rs`: times, summaries, settle times). Per-trajectory length l \[m\]
//! and gravity g [m/s²]. Memory is bounded by what is saved (final state, every n-th step, or a
//! summary), never by trajectories × steps. Progress is a shared step counter and a cancel flag is
//! checked every [`CHECK_EVERY`] steps. SI units throughout.

use crate::error::{Error, Result};
use crate::integrate::rattle_kernel::Arithmetic;
use crate::integrate::Method;
use crate::state::State;
use glam::DVec3;
use std::sync::atomic::{AtomicBool, AtomicU64};

/// Trajectories per block (the unit of parallel work; a multiple of every tile width, 4, 8, 16 and
/// [`TILE`] = 24). 48 since 2026-11-27 (was 64, which 24 does not divide): the fused 24-lane tile
/// is 9–10 % faster on an Intel CPU with two 512-bit FMA units (docs/performance.md, *On an Intel
/// CPU with two 512-bit FMA units*).
pub const LANES: usize = 48;
/// One f64 per lane of a block.
type Lanes = [f64; LANES];
/// Steps between progress updates and cancel checks in each block.
pub const CHECK_EVERY: u64 = 1024;

pub mod adaptive;
pub mod adaptive_lanes;
mod adaptive_settings;
mod block;
mod block_state;
mod output;
mod plan;
mod stages;
mod tile;
mod tile_params;
pub use block::{per_lane_tile_lanes, tile_lanes, TILE};
use block_state::Block;
use output::{sample_count, sample_times, settle_times, summaries};
use plan::{BlockRun, Plan};

/// What an ensemble run keeps.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum EnsembleSave {
    /// The final states only.
    Final,
    /// The initial state, every n-th step and the final state (n ≥ 1).
    Every(u64),
}

/// Per-trajectory extremes over the run (per unit mass): z \[m\], E/m [J/kg], J₃/m [m²/s].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Summary {
    /// min z, max z.
    pub z: (f64, f64),
    /// min and max of E/m = ½|v|² + g z.
    pub energy_per_mass: (f64, f64),
    /// min and max of J₃/m = (x × v)·e₃.
    pub j3_per_mass: (f64, f64),
    /// Crossings of the horizontal plane through the pivot: the number of steps across which z
    /// changed between ≤ 0 (at or below the pivot) and > 0 (above it), in either direction. For a
    /// planar swing over the top this is two per revolution; it stays 0 for motion below the pivot.
    pub crossings: u64,
}

/// The result of [`run`]: saved states (trajectory-major, one flat array: [`EnsembleResult::trajectory`]),
/// the sample times \[s\], per-trajectory summaries, and whether the run was cancelled.
#[derive(Debug, Clone)]
pub struct EnsembleResult {
    /// Saved times \[s\] (shared by all trajectories).
    pub t: Vec<f64>,
    /// Every trajectory's saved states, trajectory after trajectory: trajectory k's sample j is
    /// `states[k * t.len() + j]` (one allocation, whatever the number of trajectories).
    pub states: Vec<State>,
    /// Per-trajectory extremes (when requested).
    pub summary: Option<Vec<Summary>>,
    /// Per trajectory (with [`RattleSettings::settle_angle`]): the time \[s\] after which the sway stayed at or
    /// below the threshold until the end of the run (0: never above; +∞: above at the last step; to
    /// within one step dt).
    pub settle_time: Option<Vec<f64>>,
    /// True when the cancel flag stopped the run early (states are those reached).
    pub cancelled: bool,
    /// Steps taken by every trajectory.
    pub steps: u64,
}

impl EnsembleResult {
    /// Number of trajectories.
    pub fn len(&self) -> usize {
        self.states.len() / self.t.len().max(1)
    }

    /// True when the run had no trajectory (never: [`run`] needs at least one).
    pub fn is_empty(&self) -> bool {
        self.states.is_empty()
    }

    /// Trajectory k's saved states, one per time of [`EnsembleResult::t`].
    pub fn trajectory(&self, k: usize) -> &[State] {
        let ns = self.t.len();
        &self.states[k * ns..(k + 1) * ns]
    }
}

/// The settings of an ensemble run ([`run`]): everything but the starts, the progress counter and
/// the cancel flag. [`RattleSettings::new`] gives the plain run (final states, no damping, no summary);
/// set the other fields with struct update syntax.
#[derive(Debug, Clone, Copy)]
pub struct RattleSettings<'a> {
    /// Pendulum length l \[m\] per trajectory: one value for all or one per trajectory.
    pub length: &'a [f64],
    /// Gravity g [m/s²] per trajectory: one value for all or one per trajectory.
    pub g: &'a [f64],
    /// Linear damping c [1/s] (force −m c v, T-7.1): empty (undamped), one value for all
    /// trajectories, or one per trajectory; each ≥ 0 and finite.
    pub damping: &'a [f64],
    /// Sway angle \[rad\] in (0, π) from the stable equilibrium at or below which a trajectory counts as
    /// settled; when given, the result holds each trajectory's settle time.
    pub settle_angle: Option<f64>,
    /// The step \[s\] (> 0).
    pub dt: f64,
    /// The number of steps.
    pub n_steps: u64,
    /// What is kept.
    pub save: EnsembleSave,
    /// Per-trajectory extremes ([`Summary`]) in the result.
    pub with_summary: bool,
    /// How the steps round their multiply-adds (default unfused): each trajectory gets the numbers of
    /// the single-trajectory RATTLE with the same [`Arithmetic`] (`Stepper::set_arithmetic`).
    pub arithmetic: Arithmetic,
    /// [`Method::Rattle`] (default) or its symmetric compositions [`Method::Rattle4`], `Rattle6`,
    /// `Rattle8` (`stages.rs`): each trajectory gets the numbers of the single-trajectory method.
    pub method: Method,
}

impl<'a> RattleSettings<'a> {
    /// `n_steps` steps of `dt` \[s\] with per-trajectory `length` \[m\] and `g` [m/s²]: final states
    /// only, undamped, no summary, no settle tracking, unfused arithmetic.
    pub fn new(length: &'a [f64], g: &'a [f64], dt: f64, n_steps: u64) -> Self {
        Self {
            length,
            g,
            damping: &[],
            settle_angle: None,
            dt,
            n_steps,
            save: EnsembleSave::Final,
            with_summary: false,
            arithmetic: Arithmetic::Unfused,
            method: Method::Rattle,
        }
    }
}

/// Integrates `starts` by RATTLE as `settings` say (per-trajectory `length` \[m\], `g` [m/s²] and
/// damping, each of length 1 — broadcast — or of the ensemble's length; `n_steps` steps of `dt` \[s\]).
/// `progress` counts trajectory-steps done; setting `cancel` stops every block at its next check.
pub fn run(
    starts: &[State],
    settings: &RattleSettings<'_>,
    progress: &AtomicU64,
    cancel: &AtomicBool,
) -> Result<EnsembleResult> {
    let checked = check(starts, settings)?;
    run_checked(starts, settings, checked, progress, cancel)
}

/// [`run`] with its input already checked by [`check`] (of the same starts and settings; for
/// callers that check before handing the run to another thread, so that the starts are not checked
/// twice). The sizes are checked again (O(1)): a token of other starts or settings is refused.
pub fn run_checked(
    starts: &[State],
    settings: &RattleSettings<'_>,
    checked: Checked,
    progress: &AtomicU64,
    cancel: &AtomicBool,
) -> Result<EnsembleResult> {
    let &RattleSettings { length, g, dt, n_steps, with_summary, .. } = settings;
    let plan = Plan::from_checked(starts, settings, checked)?;
    let (n, ns) = (starts.len(), sample_count(n_steps, plan.every));
    let mut states = vec![State { x: DVec3::NAN, v: DVec3::NAN }; n * ns];
    let run = BlockRun {
        stages: plan.stages,
        n_steps,
        every: plan.every,
        with_summary,
        track: plan.track,
        arithmetic: settings.arithmetic,
        progress,
        cancel,
    };
    // each worker builds its blocks from the starts and writes their samples into its part of
    // `states`: both cores work from the first block on, and nothing is copied afterwards; a block
    // hands back only what the result needs of it (its summaries, its settle records)
    let work = |blk: &mut Box<Block>, (b, out): (usize, &mut [State])| {
        plan.fill(blk, b, starts, (length, g), with_summary);
        let (steps, cancelled) = run.block(blk, out, ns);
        let summary = if with_summary { summaries(blk) } else { Vec::new() };
        let last_out = if plan.track { blk.last_out[..blk.len].to_vec() } else { Vec::new() };
        BlockEnd { summary, last_out, steps, cancelled }
    };
    #[cfg(feature = "parallel")]
    let outputs: Vec<BlockEnd> = {
        use rayon::prelude::*;
        // every block its own task (with_max_len(1)), so that an idle core steals one block at a time:
        // rayon's own split stops at pieces of up to a quarter of the blocks, which only their thread
        // runs (on 2 cores, 1.68 of them were busy over a 4096 × 10⁴-step run); one Block per task,
        // filled anew for its block
        let blocks = states.par_chunks_mut(LANES * ns).enumerate().with_max_len(1);
        blocks.map_init(Block::boxed, work).collect()
    };
    #[cfg(not(feature = "parallel"))]
    let outputs: Vec<BlockEnd> = {
        let mut blk = Block::boxed();
        states.chunks_mut(LANES * ns).enumerate().map(|item| work(&mut blk, item)).collect()
    };
    let cancelled = outputs.iter().any(|o| o.cancelled);
    let steps = outputs.iter().map(|o| o.steps).min().unwrap_or(0);
    let t = sample_times(steps, plan.every, n_steps, dt);
    let nt = t.len();
    if nt < ns {
        // stopped early: every trajectory keeps the samples all of them reached
        for k in 1..n {
            states.copy_within(k * ns..k * ns + nt, k * nt);
        }
        states.truncate(n * nt);
    }
    // a trajectory whose last sample is not finite diverged (the first such in the order of the
    // starts): named, as a single run names it, by the time of its last finite state, not by where
    // the run stopped
    if let Some(k) = (0..n).find(|&k| !states[k * nt + nt - 1].is_finite()) {
        let first_bad = states[k * nt..(k + 1) * nt].iter().position(|s| !s.is_finite()).unwrap_or(nt - 1);
        let method = match settings.method {
            Method::Rattle4 => "rattle4 (ensemble)",
            Method::Rattle6 => "rattle6 (ensemble)",
            Method::Rattle8 => "rattle8 (ensemble)",
            _ => "rattle (ensemble)",
        };
        let last_saved = t[first_bad.saturating_sub(1)];
        let t = single_divergence(starts[k], settings, k, (t[first_bad] / dt).round() as u64)
            .unwrap_or(last_saved);
        return Err(Error::Diverged { t, method, dt });
    }
    let summary = with_summary.then(|| outputs.iter().flat_map(|o| o.summary.iter().copied()).collect());
    let settle_time = plan.track.then(|| {
        let last_out: Vec<f64> = outputs.iter().flat_map(|o| o.last_out.iter().copied()).collect();
        settle_times(&last_out, steps, dt)
    });
    Ok(EnsembleResult { t, states, summary, settle_time, cancelled, steps })
}

/// The time the single run of trajectory `k` (its model, method and arithmetic: the ensemble's numbers
/// bit for bit) names for its divergence within its first `steps` steps, checked after every step as
/// [`crate::Solver`] checks it: the start of the step whose state was not finite. `None` when that run
/// does not diverge there (the caller then names the last finite sample).
fn single_divergence(start: State, settings: &RattleSettings<'_>, k: usize, steps: u64) -> Option<f64> {
    let pick = |v: &[f64], default: f64| v.get(k.min(v.len().max(1) - 1)).copied().unwrap_or(default);
    let params = crate::Params::new(pick(settings.length, 1.0), 1.0, pick(settings.g, 9.81)).ok()?;
    let model =
        crate::model::AnyModel::build("damped", params, &[("damping", pick(settings.damping, 0.0))]).ok()?;
    let options =
        crate::SolveOptions { method: settings.method, dt: settings.dt, ..crate::SolveOptions::default() };
    let mut single = crate::Stepper::new(model, 0.0, start, &options).ok()?;
    single.set_arithmetic(settings.arithmetic).ok()?;
    for _ in 0..steps {
        match single.step().and_then(|_| single.check_finite()) {
            Ok(()) => {}
            Err(Error::Diverged { t, .. }) => return Some(t),
            Err(_) => return Some(single.t()),
        }
    }
    None
}

/// What a worker keeps of a block after running it: its trajectories' summaries and settle records
/// (`Block::last_out`; each empty when not asked for), the steps it took and whether it was cancelled.
struct BlockEnd {
    summary: Vec<Summary>,
    last_out: Vec<f64>,
    steps: u64,
    cancelled: bool,
}

/// Checks the input of [`run`] as the run would (and fails with the same error), without running or
/// allocating anything: for callers that start the run elsewhere (a background thread).
pub fn check(starts: &[State], settings: &RattleSettings<'_>) -> Result<Checked> {
    Plan::checked(starts, settings).map(|p| Checked {
        n: starts.len(),
        cos_settle: p.cos_settle,
        every: p.every,
    })
}

/// Proof that [`check`] accepted a run's starts and settings ([`run_checked`]): the number of
/// starts, the settle threshold (cos of the angle; −∞ without tracking) and the save interval in
/// steps.
#[derive(Debug, Clone, Copy)]
pub struct Checked {
    n: usize,
    cos_settle: f64,
    every: u64,
}
