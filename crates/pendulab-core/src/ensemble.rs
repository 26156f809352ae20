//! Many pendulums at once with RATTLE (T-2.1, T-2.2; the same step as `integrate/rattle.rs`, built
//! from the same functions of `integrate/rattle_kernel.rs`, so each trajectory gets the
//! single-trajectory numbers exactly):
//!
//!   v½ = v₀ − (h/2) g e₃ + μ x₀ (|x₁| = l),  x₁ = x₀ + h v½,  v₁ = v½ − (h/2) g e₃ − x₁ (x₁·u)/l²,
//!
//! with Kahan-compensated updates. Optional linear damping c [1/s] (force −m c v, T-7.1) enters as in
//! the single-trajectory path of the `damped` model: the exact damping flow v ↦ e^{−c h/2} v before
//! and after each step (Strang splitting, conformal symplectic). Optional settle tracking records, per
//! trajectory, the time after which the sway angle from the stable equilibrium −sign(g) e₃ stays at
//! or below a threshold (cos sway = −sign(g) z/l; resolution one step). Layout: blocks of [`LANES`] trajectories in structure-of-arrays
//! form (each coordinate a fixed-size array), so the lane loop has no branches and the compiler
//! vectorises it (for the widest vectors the CPU has, chosen at run time: [`crate::isa`]); blocks run in parallel with rayon (feature `parallel`). Per-trajectory length l \[m\]
//! and gravity g [m/s²]. Memory is bounded by what is saved (final state, every n-th step, or a
//! summary), never by trajectories × steps. Progress is a shared step counter and a cancel flag is
//! checked every [`CHECK_EVERY`] steps. SI units throughout.

use crate::error::{Error, Result};
use crate::integrate::rattle_kernel::{
    advance_position, advance_velocity, fmadd3, PositionQuadratic, ProjectionPolynomial,
};
use crate::state::State;
use glam::DVec3;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};

/// Trajectories per block (the vector width the lane loop is written for).
pub const LANES: usize = 64;
/// Steps between progress updates and cancel checks in each block.
pub const CHECK_EVERY: u64 = 1024;

type Lanes = [f64; LANES];

/// One block: positions, velocities, Kahan compensations and parameters of LANES trajectories.
#[derive(Clone)]
struct Block {
    x: [Lanes; 3],
    v: [Lanes; 3],
    cx: [Lanes; 3],
    cv: [Lanes; 3],
    /// l² and 1/l² per lane (as the single path computes them).
    l2: Lanes,
    inv_l2: Lanes,
    g: Lanes,
    /// e^{−c dt/2} per lane (1 without damping) and whether any lane is damped.
    decay_half: Lanes,
    damped: bool,
    /// −sign(g)/l per lane (cos sway = z · down) and cos of the settle threshold (all lanes).
    down: Lanes,
    cos_settle: f64,
    /// Index of the last sample whose sway exceeded the threshold (−1: none).
    last_out: Lanes,
    /// Number of real lanes (the rest repeat lane 0 and are ignored).
    len: usize,
    /// Per-lane summary: min z, max z, min E/m, max E/m, min J₃/m, max J₃/m.
    summary: [Lanes; 6],
    /// Per lane: crossings of the pivot's horizontal plane so far, and the side (1: z > 0) at the
    /// last sample.
    crossings: Lanes,
    above: Lanes,
}

impl Block {
    /// One step of every lane (identical arithmetic to `Rattle::advance` for f = −g e₃, with the
    /// damping flow on either side when a lane is damped).
    #[inline(always)]
    fn step(&mut self, h: f64) {
        if self.damped {
            self.decay();
        }
        self.rattle(h);
        if self.damped {
            self.decay();
        }
    }

    /// The exact flow of linear damping for dt/2: v ↦ e^{−c dt/2} v (the `damped` model's
    /// `velocity_flow` without drag or frame rotation, same arithmetic).
    #[inline(always)]
    fn decay(&mut self) {
        for c in 0..3 {
            for i in 0..LANES {
                self.v[c][i] *= self.decay_half[i];
            }
        }
    }

    /// Records sample `k` as outside the settle band where the sway exceeds the threshold.
    #[inline(always)]
    fn track_settle(&mut self, k: f64) {
        for i in 0..LANES {
            let out = self.x[2][i] * self.down[i] < self.cos_settle;
            self.last_out[i] = if out { k } else { self.last_out[i] };
        }
    }

    /// One undamped RATTLE step of every lane, with the single-trajectory path's arithmetic
    /// (`integrate::rattle_kernel`, uniform field k = −(h/2) g e₃). Pass 1 finds μ from the series
    /// for all lanes; the rare lanes outside its range (large steps) take the closed form; pass 2
    /// updates x and v. Both passes are branch-free over the lanes.
    #[inline(always)]
    fn rattle(&mut self, h: f64) {
        let half = 0.5 * h;
        let mut mu: Lanes = [0.0; LANES];
        let mut series_ok = true;
        for (i, m) in mu.iter_mut().enumerate() {
            let (x0, w, _) = self.lane(i, half);
            let quad = PositionQuadratic::new(x0, w, h, self.l2[i]);
            let (series, ok) = quad.multiplier_series(h);
            *m = series;
            series_ok &= ok;
        }
        if !series_ok {
            for (i, m) in mu.iter_mut().enumerate() {
                let (x0, w, _) = self.lane(i, half);
                let quad = PositionQuadratic::new(x0, w, h, self.l2[i]);
                *m = quad.multiplier(h);
            }
        }
        // w and the quadratic are recomputed rather than kept from pass 1: a few vectorised
        // multiply-adds per lane, measured 1.4× faster than storing them (an array of structs)
        for (i, &mu) in mu.iter().enumerate() {
            let (x0, w, kick) = self.lane(i, half);
            let quad = PositionQuadratic::new(x0, w, h, self.l2[i]);
            let p = ProjectionPolynomial::new(x0, w, kick, &quad, h, self.inv_l2[i]).at(mu);
            let v0 = DVec3::new(self.v[0][i], self.v[1][i], self.v[2][i]);
            let mut cx = DVec3::new(self.cx[0][i], self.cx[1][i], self.cx[2][i]);
            let mut cv = DVec3::new(self.cv[0][i], self.cv[1][i], self.cv[2][i]);
            let x1 = advance_position(x0, fmadd3(x0, mu, w), h, &mut cx);
            let v1 = advance_velocity(v0, kick + kick, x0, mu, x1, p, &mut cv);
            for c in 0..3 {
                self.x[c][i] = x1[c];
                self.v[c][i] = v1[c];
                self.cx[c][i] = cx[c];
                self.cv[c][i] = cv[c];
            }
        }
    }

    /// Lane `i`'s position x₀, w = v₀ + k and the kick k = (h/2)(−g e₃) (the ideal model's
    /// `kick_acceleration · h/2`, same arithmetic).
    #[inline(always)]
    fn lane(&self, i: usize, half: f64) -> (DVec3, DVec3, DVec3) {
        let x0 = DVec3::new(self.x[0][i], self.x[1][i], self.x[2][i]);
        let v0 = DVec3::new(self.v[0][i], self.v[1][i], self.v[2][i]);
        let kick = DVec3::new(0.0, 0.0, -self.g[i]) * half;
        (x0, v0 + kick, kick)
    }

    #[inline(always)]
    fn update_summary(&mut self) {
        for i in 0..LANES {
            let (x, y, z) = (self.x[0][i], self.x[1][i], self.x[2][i]);
            let (vx, vy, vz) = (self.v[0][i], self.v[1][i], self.v[2][i]);
            let e = 0.5 * (vx * vx + vy * vy + vz * vz) + self.g[i] * z;
            let j = x * vy - y * vx;
            let s = &mut self.summary;
            s[0][i] = s[0][i].min(z);
            s[1][i] = s[1][i].max(z);
            s[2][i] = s[2][i].min(e);
            s[3][i] = s[3][i].max(e);
            s[4][i] = s[4][i].min(j);
            s[5][i] = s[5][i].max(j);
            let above = if z > 0.0 { 1.0 } else { 0.0 };
            self.crossings[i] += (above - self.above[i]).abs();
            self.above[i] = above;
        }
    }

    fn state(&self, i: usize) -> State {
        State {
            x: DVec3::new(self.x[0][i], self.x[1][i], self.x[2][i]),
            v: DVec3::new(self.v[0][i], self.v[1][i], self.v[2][i]),
        }
    }
}

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

/// The result of [`run`]: saved states per trajectory (trajectory-major: `states[traj][sample]`),
/// the sample times \[s\], per-trajectory summaries, and whether the run was cancelled.
#[derive(Debug, Clone)]
pub struct EnsembleResult {
    /// Saved times \[s\] (shared by all trajectories).
    pub t: Vec<f64>,
    /// `states[k]` holds trajectory k's saved states.
    pub states: Vec<Vec<State>>,
    /// Per-trajectory extremes (when requested).
    pub summary: Option<Vec<Summary>>,
    /// Per trajectory (with [`Extras::settle_angle`]): the time \[s\] after which the sway stayed at or
    /// below the threshold until the end of the run (0: never above; +∞: above at the last step; to
    /// within one step dt).
    pub settle_time: Option<Vec<f64>>,
    /// True when the cancel flag stopped the run early (states are those reached).
    pub cancelled: bool,
    /// Steps taken by every trajectory.
    pub steps: u64,
}

/// Optional per-trajectory extras of an ensemble run ([`run_with`]).
#[derive(Debug, Clone, Copy, Default)]
pub struct Extras<'a> {
    /// Linear damping c [1/s] (force −m c v, T-7.1): empty (undamped), one value for all
    /// trajectories, or one per trajectory; each ≥ 0 and finite.
    pub damping: &'a [f64],
    /// Sway angle \[rad\] in (0, π) from the stable equilibrium at or below which a trajectory counts as
    /// settled; when given, the result holds each trajectory's settle time.
    pub settle_angle: Option<f64>,
}

/// Integrates `starts` (with per-trajectory `length` \[m\] and `g` [m/s²], each of length 1 — broadcast
/// — or of the ensemble's length) by `n_steps` RATTLE steps of `dt` \[s\]. `progress` counts
/// trajectory-steps done; setting `cancel` stops every block at its next check.
#[allow(clippy::too_many_arguments)]
pub fn run(
    starts: &[State],
    length: &[f64],
    g: &[f64],
    dt: f64,
    n_steps: u64,
    save: EnsembleSave,
    with_summary: bool,
    progress: &AtomicU64,
    cancel: &AtomicBool,
) -> Result<EnsembleResult> {
    run_with(starts, length, g, &Extras::default(), dt, n_steps, save, with_summary, progress, cancel)
}

/// [`run`] with damping and settle tracking ([`Extras`]).
#[allow(clippy::too_many_arguments)]
pub fn run_with(
    starts: &[State],
    length: &[f64],
    g: &[f64],
    extras: &Extras<'_>,
    dt: f64,
    n_steps: u64,
    save: EnsembleSave,
    with_summary: bool,
    progress: &AtomicU64,
    cancel: &AtomicBool,
) -> Result<EnsembleResult> {
    let plan = Plan::checked(starts, length, g, extras, dt, n_steps, save)?;
    let mut blocks: Vec<Block> =
        (0..starts.len().div_ceil(LANES)).map(|b| plan.block(b, starts, length, g, dt)).collect();
    let run = BlockRun { dt, n_steps, every: plan.every, with_summary, track: plan.track, progress, cancel };
    let work = |blk: &mut Block| run.block(blk);
    #[cfg(feature = "parallel")]
    let outputs: Vec<_> = {
        use rayon::prelude::*;
        blocks.par_iter_mut().map(work).collect()
    };
    #[cfg(not(feature = "parallel"))]
    let outputs: Vec<_> = blocks.iter_mut().map(work).collect();
    let cancelled = outputs.iter().any(|o| o.2);
    let steps = outputs.iter().map(|o| o.1).min().unwrap_or(0);
    let t = sample_times(steps, plan.every, n_steps, dt);
    let mut states: Vec<Vec<State>> = outputs.into_iter().flat_map(|o| o.0).collect();
    for s in &mut states {
        s.truncate(t.len());
    }
    if states.iter().any(|s| !s.last().is_some_and(State::is_finite)) {
        return Err(Error::Diverged { t: steps as f64 * dt, method: "rattle (ensemble)", dt });
    }
    let summary = with_summary.then(|| summaries(&blocks));
    let settle_time = plan.track.then(|| settle_times(&blocks, steps, dt));
    Ok(EnsembleResult { t, states, summary, settle_time, cancelled, steps })
}

/// A parameter given once for all trajectories (length 1) or per trajectory: its value for trajectory k.
#[inline]
fn pick(a: &[f64], k: usize) -> f64 {
    if a.len() == 1 {
        a[0]
    } else {
        a[k]
    }
}

/// The checked settings of a run: damping c [1/s] (one value or one per trajectory), the settle
/// threshold (cos of the angle; −∞ without tracking) and the save interval in steps.
struct Plan<'a> {
    damping: &'a [f64],
    cos_settle: f64,
    track: bool,
    every: u64,
}

impl<'a> Plan<'a> {
    /// Checks everything before any work: dt > 0, parameter arrays of length 1 or N, every start on
    /// TS² of its (l, g), damping ≥ 0, the settle angle in (0, π), save_every ≥ 1.
    fn checked(
        starts: &[State],
        length: &[f64],
        g: &[f64],
        extras: &Extras<'a>,
        dt: f64,
        n_steps: u64,
        save: EnsembleSave,
    ) -> Result<Self> {
        let n = starts.len();
        crate::error::require_positive("dt", dt, "the step dt must be a finite number > 0 s")?;
        let damping: &[f64] = if extras.damping.is_empty() { &[0.0] } else { extras.damping };
        for (name, a) in [("length", length), ("g", g), ("damping", damping)] {
            if a.len() != 1 && a.len() != n {
                return Err(Error::InvalidParameter {
                    name,
                    value: a.len() as f64,
                    allowed: "one value for all trajectories or one per trajectory",
                });
            }
        }
        for (k, s) in starts.iter().enumerate() {
            let p = crate::state::Params::new(pick(length, k), 1.0, pick(g, k))?;
            State::on_tangent_bundle(&p, s.x, s.v)?;
            crate::error::require_non_negative(
                "damping",
                pick(damping, k),
                "a finite damping rate c >= 0 [1/s]",
            )?;
        }
        let cos_settle = match extras.settle_angle {
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
        Ok(Self { damping, cos_settle, track: extras.settle_angle.is_some(), every })
    }

    /// Block `b`: trajectories b·LANES … (the lanes past the last trajectory repeat it and are
    /// ignored), with its parameters, its summary and settle state at the start.
    fn block(&self, b: usize, starts: &[State], length: &[f64], g: &[f64], dt: f64) -> Block {
        let n = starts.len();
        let damping = self.damping;
        let idx = |i: usize| (b * LANES + i).min(n - 1);
        let len = (n - b * LANES).min(LANES);
        let lanes = |f: &dyn Fn(usize) -> f64| -> Lanes { std::array::from_fn(|i| f(idx(i))) };
        let mut blk = Block {
            x: [0, 1, 2].map(|c| lanes(&|k| starts[k].x[c])),
            v: [0, 1, 2].map(|c| lanes(&|k| starts[k].v[c])),
            cx: [[0.0; LANES]; 3],
            cv: [[0.0; LANES]; 3],
            l2: lanes(&|k| pick(length, k) * pick(length, k)),
            inv_l2: lanes(&|k| 1.0 / (pick(length, k) * pick(length, k))),
            g: lanes(&|k| pick(g, k)),
            decay_half: lanes(&|k| (-pick(damping, k) * (0.5 * dt)).exp()),
            damped: (0..len).any(|i| pick(damping, idx(i)) != 0.0),
            down: lanes(&|k| -pick(g, k).signum() / pick(length, k)),
            cos_settle: self.cos_settle,
            last_out: [-1.0; LANES],
            len,
            summary: std::array::from_fn(|r| {
                [if r % 2 == 0 { f64::INFINITY } else { f64::NEG_INFINITY }; LANES]
            }),
            crossings: [0.0; LANES],
            above: lanes(&|k| if starts[k].x.z > 0.0 { 1.0 } else { 0.0 }),
        };
        blk.update_summary();
        if self.track {
            blk.track_settle(0.0);
        }
        blk
    }
}

/// How every block is run: `n_steps` steps of `dt` [s], saving every `every`-th, with the summary
/// and settle tracking when asked; progress counted and the cancel flag read every [`CHECK_EVERY`]
/// steps.
struct BlockRun<'a> {
    dt: f64,
    n_steps: u64,
    every: u64,
    with_summary: bool,
    track: bool,
    progress: &'a AtomicU64,
    cancel: &'a AtomicBool,
}

impl BlockRun<'_> {
    /// Runs one block: its saved states per lane, the steps taken and whether it was cancelled.
    #[inline]
    fn block(&self, blk: &mut Block) -> (Vec<Vec<State>>, u64, bool) {
        let (n_steps, every) = (self.n_steps, self.every);
        let mut saved: Vec<Vec<State>> = (0..blk.len).map(|i| vec![blk.state(i)]).collect();
        let mut done = 0u64;
        while done < n_steps {
            let chunk = CHECK_EVERY.min(n_steps - done).min(every - done % every);
            // the lane loops compiled for the CPU's widest vectors (AVX-512, AVX2 + FMA; crate::isa)
            crate::isa::fastest(
                #[inline(always)]
                || {
                    for j in 1..=chunk {
                        blk.step(self.dt);
                        if self.with_summary {
                            blk.update_summary();
                        }
                        if self.track {
                            blk.track_settle((done + j) as f64);
                        }
                    }
                },
            );
            done += chunk;
            self.progress.fetch_add(chunk * blk.len as u64, Ordering::Relaxed);
            if done % every == 0 || done == n_steps {
                for (i, s) in saved.iter_mut().enumerate() {
                    s.push(blk.state(i));
                }
            }
            if self.cancel.load(Ordering::Relaxed) {
                return (saved, done, true);
            }
        }
        (saved, done, false)
    }
}

/// The sample times [s] of a run that took `steps` of `n_steps` steps of `dt`, saving every `every`-th
/// step and the last: 0, then every multiple of `every` (and n_steps) up to `steps`.
fn sample_times(steps: u64, every: u64, n_steps: u64, dt: f64) -> Vec<f64> {
    let mut t: Vec<f64> = vec![0.0];
    let mut k = 0;
    while k < steps {
        k = (k + every - k % every).min(n_steps);
        if k > steps {
            break;
        }
        t.push(k as f64 * dt);
    }
    t
}

/// Every trajectory's extremes and plane crossings, in order.
fn summaries(blocks: &[Block]) -> Vec<Summary> {
    blocks
        .iter()
        .flat_map(|b| {
            (0..b.len).map(|i| Summary {
                z: (b.summary[0][i], b.summary[1][i]),
                energy_per_mass: (b.summary[2][i], b.summary[3][i]),
                j3_per_mass: (b.summary[4][i], b.summary[5][i]),
                crossings: b.crossings[i] as u64,
            })
        })
        .collect()
}

/// Every trajectory's settle time [s] after `steps` steps of `dt` (+∞: outside at the last sample).
fn settle_times(blocks: &[Block], steps: u64, dt: f64) -> Vec<f64> {
    blocks
        .iter()
        .flat_map(|b| {
            (0..b.len).map(|i| {
                let k = b.last_out[i];
                // outside at the last sample: not settled within the run
                if k >= steps as f64 {
                    f64::INFINITY
                } else {
                    (k + 1.0) * dt
                }
            })
        })
        .collect()
}
