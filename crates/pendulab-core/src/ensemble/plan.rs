//! The plan of an ensemble run (`super::run`): its settings checked once (dt, the per-trajectory
//! arrays' sizes, every start on TS² of its (l, g), damping c ≥ 0 [1/s], the settle angle, the save
//! interval), each block built from the starts, and the block's step loop with its samples, progress
//! counter and cancel checks (the steps themselves: `block.rs`). SI units: \[m\], [m/s], \[s\], [1/s].

use super::block_state::{Block, Track};
use super::stages::{Stages, DISTINCT};
use super::{Checked, EnsembleSave, RattleSettings, CHECK_EVERY, LANES};
use crate::error::{Error, Result};
use crate::integrate::rattle_kernel::{Arithmetic, Fused, Unfused};
use crate::state::State;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};

/// A parameter given once for all trajectories (length 1) or per trajectory: its value for trajectory k.
#[inline]
fn pick(a: &[f64], k: usize) -> f64 {
    if a.len() == 1 {
        a[0]
    } else {
        a[k]
    }
}

/// e^{−c h/2} for damping c [1/s] and a (sub-)step h \[s\] (< 0 for a composition's backward
/// sub-step), as the `damped` model's flow for h/2: exactly 1 (e^{−0}) for c = 0, no exp called.
fn decay_half(c: f64, h: f64) -> f64 {
    if c == 0.0 {
        1.0
    } else {
        (-c * (0.5 * h)).exp()
    }
}

/// The run's damping rates c [1/s]: the settings' own, or one 0 (undamped) when none are given.
fn damping_of<'a>(settings: &RattleSettings<'a>) -> &'a [f64] {
    if settings.damping.is_empty() {
        &[0.0]
    } else {
        settings.damping
    }
}

/// The first of length, g and `damping` whose size is neither 1 nor `n` (the starts), with its size.
fn missized(settings: &RattleSettings<'_>, damping: &[f64], n: usize) -> Option<(&'static str, usize)> {
    [("length", settings.length), ("g", settings.g), ("damping", damping)]
        .into_iter()
        .find(|(_, a)| a.len() != 1 && a.len() != n)
        .map(|(name, a)| (name, a.len()))
}

/// Starts checked per part of [`CHECK_PART`] by `check_from(first index, part)`, on both cores for a
/// large ensemble (each start's check is independent); the error is the first failing start's, as in
/// one pass.
fn check_starts(starts: &[State], check_from: impl Fn(usize, &[State]) -> Result<()> + Sync) -> Result<()> {
    #[cfg(feature = "parallel")]
    if starts.len() > CHECK_PART {
        use rayon::prelude::*;
        let parts: Vec<Result<()>> = starts
            .par_chunks(CHECK_PART)
            .enumerate()
            .map(|(j, part)| check_from(j * CHECK_PART, part))
            .collect();
        return parts.into_iter().collect();
    }
    check_from(0, starts)
}

/// Starts per part of the check (about 10 µs of work each; used only with the `parallel` feature,
/// which the WebAssembly build leaves out).
#[cfg_attr(not(feature = "parallel"), allow(dead_code))]
const CHECK_PART: usize = 512;

/// The checked settings of a run: damping c [1/s] (one value or one per trajectory), the sub-steps
/// of a step, the settle threshold (cos of the angle; −∞ without tracking) and the save interval in
/// steps.
pub(super) struct Plan<'a> {
    pub(super) damping: &'a [f64],
    pub(super) stages: Stages,
    pub(super) cos_settle: f64,
    pub(super) track: bool,
    pub(super) every: u64,
}

impl<'a> Plan<'a> {
    /// The plan of a run [`check`] accepted; refused when the sizes of the starts or the
    /// per-trajectory arrays are not those it checked.
    pub(super) fn from_checked(
        starts: &[State],
        settings: &RattleSettings<'a>,
        checked: Checked,
    ) -> Result<Self> {
        let n = starts.len();
        let damping = damping_of(settings);
        if checked.n != n || missized(settings, damping, n).is_some() {
            return Err(Error::InvalidParameter {
                name: "checked",
                value: checked.n as f64,
                allowed: "the token `check` gave for these starts and settings",
            });
        }
        let track = settings.settle_angle.is_some();
        let stages = Stages::of(settings.method, settings.dt)?;
        Ok(Self { damping, stages, cos_settle: checked.cos_settle, track, every: checked.every })
    }

    /// Checks everything before any work: dt > 0, parameter arrays of length 1 or N, every start on
    /// TS² of its (l, g), damping ≥ 0, the settle angle in (0, π), save_every ≥ 1.
    pub(super) fn checked(starts: &[State], settings: &RattleSettings<'a>) -> Result<Self> {
        let &RattleSettings { length, g, dt, n_steps, save, .. } = settings;
        let n = starts.len();
        crate::error::require_positive("dt", dt, "the step dt must be a finite number > 0 s")?;
        let stages = Stages::of(settings.method, dt)?;
        let damping = damping_of(settings);
        if let Some((name, size)) = missized(settings, damping, n) {
            return Err(Error::InvalidParameter {
                name,
                value: size as f64,
                allowed: "one value for all trajectories or one per trajectory",
            });
        }
        let params = |k: usize| crate::state::Params::new(pick(length, k), 1.0, pick(g, k));
        // one pendulum for all (the usual ensemble): its parameters checked once, not per start
        let shared = if length.len() == 1 && g.len() == 1 { Some(params(0)?) } else { None };
        let check_from = |first: usize, part: &[State]| -> Result<()> {
            for (k, s) in (first..).zip(part) {
                let p = match shared {
                    Some(p) => p,
                    None => params(k)?,
                };
                State::on_tangent_bundle(&p, s.x, s.v)?;
            }
            Ok(())
        };
        check_starts(starts, check_from)?;
        for &c in damping {
            crate::error::require_non_negative("damping", c, "a finite damping rate c >= 0 [1/s]")?;
        }
        let cos_settle = match settings.settle_angle {
            None => f64::NEG_INFINITY,
            Some(a) if a.is_finite() && a > 0.0 && a < std::f64::consts::PI => a.cos(),
            Some(a) => {
                return Err(Error::InvalidParameter {
                    name: "settle_angle",
                    value: a,
                    allowed: "a sway angle in (0, π) rad",
                })
            }
        };
        let every = match save {
            EnsembleSave::Final => n_steps.max(1),
            EnsembleSave::Every(0) => {
                return Err(Error::InvalidParameter {
                    name: "save_every",
                    value: 0.0,
                    allowed: "an integer >= 1",
                })
            }
            EnsembleSave::Every(e) => e,
        };
        Ok(Self { damping, stages, cos_settle, track: settings.settle_angle.is_some(), every })
    }

    /// Fills `blk` with block `b`: trajectories b·LANES … (the lanes past the last trajectory
    /// repeat it and are ignored), with its parameters, its summary and settle state at the start.
    /// Every field is written, so one block serves a worker for all its blocks (no block is built
    /// and moved per call: `super::run_checked`).
    pub(super) fn fill(
        &self,
        blk: &mut Block,
        b: usize,
        starts: &[State],
        (length, g): (&[f64], &[f64]),
        summary: bool,
    ) {
        let n = starts.len();
        let damping = self.damping;
        let len = (n - b * LANES).min(LANES);
        // per distinct sub-step h_d: e^{−c h_d/2}, one exp for all lanes when they share c; the rows
        // no sub-step uses hold 1
        let distinct = self.stages.distinct_len();
        let shared_decay: [Option<f64>; DISTINCT] = std::array::from_fn(|d| {
            (damping.len() == 1 && d < distinct).then(|| decay_half(damping[0], self.stages.h(d)))
        });
        for i in 0..LANES {
            let k = (b * LANES + i).min(n - 1);
            let s = &starts[k];
            let (l, gk) = (pick(length, k), pick(g, k));
            for c in 0..3 {
                blk.x[c][i] = s.x[c];
                blk.v[c][i] = s.v[c];
                blk.cx[c][i] = 0.0;
                blk.cv[c][i] = 0.0;
            }
            blk.l2[i] = l * l;
            blk.inv_l2[i] = 1.0 / (l * l);
            blk.g[i] = gk;
            // e^{−c h_d/2}; exactly 1 (e^{−0}) without damping, no exp called
            for (d, row) in blk.decay_half.iter_mut().enumerate() {
                row[i] = match shared_decay[d] {
                    Some(f) => f,
                    None if d < distinct => decay_half(damping[k], self.stages.h(d)),
                    None => 1.0,
                };
            }
            blk.down[i] = -gk.signum() / l;
            blk.last_out[i] = -1.0;
            for (r, row) in blk.summary.iter_mut().enumerate() {
                row[i] = if r % 2 == 0 { f64::INFINITY } else { f64::NEG_INFINITY };
            }
            blk.crossings[i] = 0.0;
            blk.above[i] = if s.x.z > 0.0 { 1.0 } else { 0.0 };
        }
        blk.damped = (0..len).any(|i| pick(damping, b * LANES + i) != 0.0);
        blk.cos_settle = self.cos_settle;
        blk.len = len;
        if summary {
            blk.update_summary();
        }
        if self.track {
            blk.track_settle(0.0);
        }
    }
}

/// How every block is run: `n_steps` steps (each of the sub-steps `stages`, of dt \[s\] in all),
/// saving every `every`-th, with the summary
/// and settle tracking when asked; progress counted and the cancel flag read every [`CHECK_EVERY`]
/// steps.
pub(super) struct BlockRun<'a> {
    pub(super) stages: Stages,
    pub(super) n_steps: u64,
    pub(super) every: u64,
    pub(super) with_summary: bool,
    pub(super) track: bool,
    pub(super) arithmetic: Arithmetic,
    pub(super) progress: &'a AtomicU64,
    pub(super) cancel: &'a AtomicBool,
}

impl BlockRun<'_> {
    /// Runs one block, writing lane i's sample j to `out[i * ns + j]`: the steps taken and whether it
    /// was cancelled.
    #[inline]
    pub(super) fn block(&self, blk: &mut Block, out: &mut [State], ns: usize) -> (u64, bool) {
        let (n_steps, every) = (self.n_steps, self.every);
        let mut sample = 0;
        let mut save = |blk: &Block| {
            for i in 0..blk.len {
                out[i * ns + sample] = blk.state(i);
            }
            sample += 1;
        };
        save(blk);
        let track = Track { summary: self.with_summary, settle: self.track };
        let mut done = 0u64;
        while done < n_steps {
            let chunk = CHECK_EVERY.min(n_steps - done).min(every - done % every);
            // the lane loops compiled for the CPU's widest vectors (AVX-512, AVX2 + FMA; crate::isa)
            match self.arithmetic {
                Arithmetic::Unfused => blk.steps::<Unfused>(chunk, &self.stages, done, track),
                Arithmetic::Fused => blk.steps::<Fused>(chunk, &self.stages, done, track),
            }
            done += chunk;
            self.progress.fetch_add(chunk * blk.len as u64, Ordering::Relaxed);
            if done.is_multiple_of(every) || done == n_steps {
                save(blk);
            }
            if self.cancel.load(Ordering::Relaxed) {
                return (done, true);
            }
        }
        (done, false)
    }
}
