//! DOP853 across trajectories: [`LANES`] trajectories stepped together in structure-of-arrays form,
//! each with its own time, step size and accept/reject decision (T-2.4 with Hairer's DOP853 and its
//! controller, `integrate/dop853.rs` and `integrate/dop853_control.rs`):
//!
//!   kᵢ = f(t + cᵢh, y + h Σⱼ aᵢⱼ kⱼ),  y₁ = y + h Σ bᵢ kᵢ,
//!   err = |h| ‖e₅‖² / √(6 (‖e₅‖² + 0.01 ‖e₃‖²)),  h_new = h / clamp(err^{1/8}/0.9, 1/6, 1/0.333).
//!
//! One pass of the loop is one *attempt* of every lane, each with its own h: the stage sums, the
//! 8th-order solution and the error estimate run as loops over the lanes (vectorised: one AVX-512
//! register holds a component of 8 lanes), the right-hand side is evaluated lane by lane with the
//! lane's own model (per-trajectory parameters), and the decision is per lane: a lane whose attempt
//! is rejected retries with its smaller h in the next pass while its neighbours go on. A lane whose
//! trajectory has reached t_end is refilled with the next trajectory of its chunk at once (so lanes
//! never wait for a slower neighbour); at the end of a chunk the empty lanes are masked out (their
//! arithmetic runs on zeros and is thrown away, their right-hand sides are not evaluated).
//!
//! **Bit for bit the single run.** Every lane does, operation for operation, what
//! [`crate::integrate::dop853::Dop853::step`] does in [`crate::Solver`] with `SaveAt::Times([t0,
//! t_end])`: the same first step (`initial_step`), the same order of the sums (zeros of the tableau
//! included), the same comparisons (glam's `max` is `a > b ? a : b`), the same controller
//! (`StepControl`), the same projection (`project_accepted`). Elementwise IEEE operations do not
//! depend on the vector width, and no multiply-add is fused (docs/performance.md, *No CPU left
//! behind*), so a lane's numbers are those of its single run at every instruction-set level.
//! SI units: t \[s\], x \[m\], v \[m/s\].

use super::adaptive_settings::{AdaptiveSettings, Models};
use crate::error::{Error, Result};
use crate::integrate::dop853::{initial_step, project_accepted, rhs, step_end, Y6};
use crate::integrate::dop853_control::{off_sphere, StepControl};
use crate::integrate::dop853_tableau::{A, B, C, E3, E5, STAGES};
use crate::integrate::Stats;
use crate::model::Model;
use crate::state::State;
use glam::DVec3;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};

/// Trajectories stepped together (one AVX-512 register, two AVX2 registers per component).
pub const LANES: usize = 8;
/// Attempts between checks of the cancel flag.
const CHECK_EVERY: u32 = 256;

type Row = [f64; LANES];
/// Six components (x, y, z, vx, vy, vz) of every lane.
type Rows = [Row; 6];

/// Lane l of `r` as a point of the first-order system.
#[inline(always)]
fn get(r: &Rows, l: usize) -> Y6 {
    Y6 { x: DVec3::new(r[0][l], r[1][l], r[2][l]), v: DVec3::new(r[3][l], r[4][l], r[5][l]) }
}

/// Writes `y` into lane l of `r`.
#[inline(always)]
fn put(r: &mut Rows, l: usize, y: Y6) {
    for c in 0..3 {
        r[c][l] = y.x[c];
        r[c + 3][l] = y.v[c];
    }
}

/// What one chunk of trajectories hands back: per trajectory of the chunk its accepted steps and its
/// error (if it failed), and whether the chunk stopped on the cancel flag.
pub(super) struct ChunkOut {
    pub steps: Vec<u64>,
    pub errors: Vec<Option<Error>>,
    pub cancelled: bool,
}

/// The per-lane bookkeeping of the controller (scalar, as in `Dop853::step`).
#[derive(Clone, Copy, Default)]
struct Control {
    /// The trajectory (index in the chunk) this lane integrates, if any.
    traj: Option<usize>,
    t: f64,
    /// The step to try next, whether the last attempt was rejected, the proposal kept after the
    /// last accepted step (`Dop853::h_next`).
    h: f64,
    rejected: bool,
    h_next: Option<f64>,
    /// The start \[s\] of the last accepted step: the last time the state was known finite.
    t_before: f64,
    /// The start's x₀, ½|v₀|² and J₃/m (invariant projection).
    targets: Option<(DVec3, f64, f64)>,
    steps: u64,
}

/// What every chunk of a lanes run shares: the models, the starts, the settings, the samples per
/// trajectory `ns` (1 or 2: t_end, or t0 and t_end), the progress counter and the cancel flag.
pub(super) struct Job<'a, M: Model> {
    pub models: &'a Models<'a, M>,
    pub starts: &'a [State],
    pub settings: &'a AdaptiveSettings,
    pub ns: usize,
    pub progress: &'a AtomicU64,
    pub cancel: &'a AtomicBool,
}

/// Runs trajectories `first..first + out.len() / ns` of `job` (their samples `out`) with [`LANES`]
/// lanes, refilling lanes as trajectories finish.
pub(super) fn run_chunk<M: Model>(job: &Job<'_, M>, first: usize, out: &mut [State]) -> ChunkOut {
    let &Job { models, starts, settings, ns, progress, cancel } = job;
    let n = out.len() / ns;
    let mut res = ChunkOut { steps: vec![0; n], errors: (0..n).map(|_| None).collect(), cancelled: false };
    let mut run = Lanes::new(settings, ns);
    let mut next = 0;
    let mut passes = 0u32;
    loop {
        // refill the free lanes
        for l in 0..LANES {
            while run.ctl[l].traj.is_none() && next < n {
                let k = next;
                next += 1;
                let m = models.of(first + k);
                if let Err(e) = run.load(l, k, m, starts[first + k], &mut out[k * ns..(k + 1) * ns]) {
                    res.errors[k] = Some(e);
                    progress.fetch_add(1, Ordering::Relaxed);
                }
            }
        }
        if run.ctl.iter().all(|c| c.traj.is_none()) {
            return res;
        }
        passes += 1;
        if passes % CHECK_EVERY == 1 && cancel.load(Ordering::Relaxed) {
            res.cancelled = true;
            return res;
        }
        let ended = crate::isa::fastest(
            #[inline(always)]
            || run.attempt(models, first),
        );
        for (l, e) in ended.into_iter().enumerate() {
            let Some(result) = e else { continue };
            let k = run.ctl[l].traj.take().expect("an ended lane had a trajectory");
            res.steps[k] = run.ctl[l].steps;
            match result {
                Ok(y) => {
                    let m = models.of(first + k);
                    let s = m.to_physical(settings.t_end, State { x: y.x, v: y.v });
                    if s.is_finite() {
                        out[k * ns + ns - 1] = s;
                    } else {
                        // named by the last state known finite, the final step's start (its
                        // integrator state passed the error test), not t_end
                        res.errors[k] = Some(diverged(settings, run.ctl[l].t_before));
                    }
                }
                Err(err) => res.errors[k] = Some(err),
            }
            progress.fetch_add(1, Ordering::Relaxed);
        }
    }
}

/// The error a single run reports for a non-finite saved state ([`crate::Solver`]'s `push`).
fn diverged(settings: &AdaptiveSettings, t: f64) -> Error {
    Error::Diverged { t, method: "dop853", dt: settings.options.dt }
}

/// The lanes: state, stages and per-lane controller.
struct Lanes<'s> {
    settings: &'s AdaptiveSettings,
    control: StepControl,
    h_init: Option<f64>,
    ns: usize,
    y: Rows,
    /// Stages 0‥11 (stage 0: f at the current point, "first same as last").
    k: [Rows; STAGES],
    ctl: [Control; LANES],
}

impl<'s> Lanes<'s> {
    fn new(settings: &'s AdaptiveSettings, ns: usize) -> Self {
        let o = &settings.options;
        // as `Stepper::new` builds its Dop853: no step cap, dt > 0 the first step
        let h_init = (o.dt > 0.0 && o.dt.is_finite()).then_some(o.dt);
        Self {
            settings,
            control: StepControl { h_max: f64::INFINITY, rtol: o.rtol, atol: o.atol },
            h_init,
            ns,
            y: [[0.0; LANES]; 6],
            k: [[[0.0; LANES]; 6]; STAGES],
            ctl: [Control::default(); LANES],
        }
    }

    /// Puts trajectory `k` (start `s`, model `m`) into lane `l`: its t0 sample (when saved), f at the
    /// start and the first step, as `Solver::new` and the first `Dop853::step` do.
    fn load<M: Model>(&mut self, l: usize, k: usize, m: &M, s: State, out: &mut [State]) -> Result<()> {
        let set = self.settings;
        let s = m.integrator_state(set.t0, s);
        if self.ns == 2 {
            let p = m.to_physical(set.t0, s);
            if !p.is_finite() {
                return Err(diverged(set, set.t0));
            }
            out[0] = p;
        }
        let y0 = Y6 { x: s.x, v: s.v };
        let f0 = rhs(m, set.t0, y0);
        let o = &set.options;
        let h = match self.h_init {
            Some(h) => h.min(f64::INFINITY),
            None => {
                let span = set.t_end - set.t0;
                initial_step(o.atol, o.rtol, f64::INFINITY, m, (set.t0, y0, f0), span, &mut Stats::default())
            }
        };
        put(&mut self.y, l, y0);
        put(&mut self.k[0], l, f0);
        let targets = set.conserve.then(|| (s.x, 0.5 * s.v.length_squared(), s.x.x * s.v.y - s.x.y * s.v.x));
        self.ctl[l] = Control {
            traj: Some(k),
            t: set.t0,
            h,
            rejected: false,
            h_next: None,
            t_before: set.t0,
            targets,
            steps: 0,
        };
        Ok(())
    }

    /// One attempt of every busy lane; per lane, `Some` when its trajectory ended (its state at
    /// t_end, or its error).
    #[inline(always)]
    #[allow(clippy::needless_range_loop)] // lane l of several arrays at once: the loops that vectorise
    fn attempt<M: Model>(&mut self, models: &Models<'_, M>, first: usize) -> [Option<Result<Y6>>; LANES] {
        let t_end = self.settings.t_end;
        let mut ended: [Option<Result<Y6>>; LANES] = Default::default();
        // the trial steps (free lanes: h = 0 on zeros, thrown away)
        let mut h: Row = [0.0; LANES];
        let mut last = [false; LANES];
        let mut busy = [false; LANES];
        let trajs = self.ctl.map(|c| c.traj.unwrap_or(0));
        let model = |l: usize| models.of(first + trajs[l]);
        // where each lane's step ends at the latest: t_end, or its model's next break (`Dop853::step`)
        let mut stop: Row = [t_end; LANES];
        for l in 0..LANES {
            if self.ctl[l].traj.is_none() {
                continue;
            }
            stop[l] = step_end(model(l), self.ctl[l].t, t_end);
            match self.control.trial(self.ctl[l].h, self.ctl[l].t, stop[l]) {
                Ok((hl, la)) => (h[l], last[l], busy[l]) = (hl, la, true),
                Err(e) => {
                    let (y, length) = (get(&self.y, l), model(l).params().length);
                    ended[l] = Some(Err(off_sphere(e, self.settings.options.project, (y.x, y.v), length)));
                }
            }
        }
        // stages 1‥11: yᵢ = y + Σⱼ kⱼ (h aᵢⱼ) in the order of `Dop853::attempt`, then f per lane
        let mut yi: Rows = [[0.0; LANES]; 6];
        for i in 1..STAGES {
            for c in 0..6 {
                let mut acc = self.y[c];
                for (j, &a) in A[i][..i].iter().enumerate() {
                    for l in 0..LANES {
                        acc[l] += self.k[j][c][l] * (h[l] * a);
                    }
                }
                yi[c] = acc;
            }
            for l in 0..LANES {
                let f = if busy[l] {
                    rhs(model(l), self.ctl[l].t + C[i] * h[l], get(&yi, l))
                } else {
                    Y6::default()
                };
                put(&mut self.k[i], l, f);
            }
        }
        let (y1, err) = self.solution(&h);
        // the decision, lane by lane (`Dop853::step`)
        for l in 0..LANES {
            if !busy[l] {
                continue;
            }
            let root = StepControl::error_root(err[l]);
            let ctl = &mut self.ctl[l];
            if err[l] <= 1.0 {
                let m = model(l);
                let h_new = StepControl::after_accept(h[l], root, ctl.rejected);
                let t1 = if last[l] { stop[l] } else { ctl.t + h[l] };
                let flags = (self.settings.options.project, self.settings.conserve, m.params().length);
                match project_accepted(m, flags, ctl.targets, (ctl.t, get(&y1, l)), h[l]) {
                    Ok(y) => {
                        put(&mut self.y, l, y);
                        put(&mut self.k[0], l, rhs(m, t1, y));
                        let keep = if last[l] && !ctl.rejected { ctl.h_next } else { None };
                        let h_next = keep.map_or(h_new, |p| p.max(h_new));
                        ctl.h_next = Some(h_next);
                        (ctl.t_before, ctl.t, ctl.h, ctl.rejected) = (ctl.t, t1, h_next, false);
                        ctl.steps += 1;
                        if t1 >= t_end {
                            ended[l] = Some(Ok(y));
                        }
                    }
                    Err(e) => ended[l] = Some(Err(e)),
                }
            } else {
                ctl.h = StepControl::after_reject(h[l], root);
                ctl.rejected = true;
            }
        }
        ended
    }

    /// The 8th-order solution y₁ of every lane's attempt of `h` [s] and the blended error estimate
    /// (`Dop853::attempt`: the same sums in the same order, the weights of `error_scale`).
    #[inline(always)]
    #[allow(clippy::needless_range_loop)] // lane l of several arrays at once: the loops that vectorise
    fn solution(&self, h: &Row) -> (Rows, Row) {
        let (mut y1, mut err) = ([[0.0; LANES]; 6], [0.0; LANES]);
        let (mut n5, mut n3) = ([0.0; LANES], [0.0; LANES]);
        let (atol, rtol) = (self.control.atol, self.control.rtol);
        for c in 0..6 {
            let (mut incr, mut e5, mut e3) = ([0.0; LANES], [0.0; LANES], [0.0; LANES]);
            for i in 0..STAGES {
                for l in 0..LANES {
                    incr[l] += self.k[i][c][l] * B[i];
                    e5[l] += self.k[i][c][l] * E5[i];
                    e3[l] += self.k[i][c][l] * E3[i];
                }
            }
            for l in 0..LANES {
                let (a, b) = (self.y[c][l], self.y[c][l] + incr[l] * h[l]);
                y1[c][l] = b;
                let (p, q) = (a.abs(), b.abs());
                let sk = atol + (if p > q { p } else { q }) * rtol;
                // `Y6::scaled_norm2`: a zero weight counts a zero as 0 and anything else as ∞
                let w = |d: f64| {
                    if sk > 0.0 {
                        d / sk
                    } else if d == 0.0 {
                        0.0
                    } else {
                        f64::INFINITY
                    }
                };
                let (q5, q3) = (w(e5[l]), w(e3[l]));
                // the sums of squares in component order, from +0 (as `Iterator::sum`)
                n5[l] = if c == 0 { q5 * q5 } else { n5[l] + q5 * q5 };
                n3[l] = if c == 0 { q3 * q3 } else { n3[l] + q3 * q3 };
            }
        }
        for l in 0..LANES {
            err[l] = if n5[l] == 0.0 && n3[l] == 0.0 {
                0.0
            } else {
                h[l] * n5[l] / (6.0 * (n5[l] + 0.01 * n3[l])).sqrt()
            };
        }
        (y1, err)
    }
}
