//! One block of [`LANES`] trajectories in structure-of-arrays form and its step loop (T-2.1, T-2.2;
//! the arithmetic of `integrate/rattle_kernel.rs`, operation for operation, so each lane gets the
//! single-trajectory RATTLE numbers bit for bit):
//!
//!   v½ = v₀ − (h/2) g e₃ + μ x₀ (|x₁| = l),  x₁ = x₀ + h v½,  v₁ = v½ − (h/2) g e₃ − x₁ (x₁·u)/l²,
//!
//! with Kahan-compensated updates and, when a lane is damped (c [1/s], T-7.1), the exact damping
//! flow v ↦ e^{−c h/2} v on either side of the step.
//!
//! The block is stored as 48 lanes, but stepped as [`tile_lanes`] lanes at a time (`tile.rs`: the
//! step itself, register blocking, the multiplier's two halves, parameters shared by all lanes held
//! as one number each). The tile's width is chosen per instruction-set level, because what fits in
//! the registers differs (docs/performance.md, "No CPU left behind", *The tile per level*; 4096
//! starts × 2000 steps, one thread, ns per trajectory-step, one pendulum for all starts; measured
//! 2026-11-27 with the frames aligned, `isa::align_frame`, except the baseline row, 2026-11-26):
//!
//! | level (registers) | unfused: tile 4 / 8 / 16 | fused: tile 4 / 8 / 16 | tile chosen |
//! |---|---|---|---|
//! | x86-64-v4 (32 zmm, 8 lanes) | – / – / **2.8–3.4** | – / – / **1.9** | 16 (fused: 24) |
//! | x86-64-v3 (16 ymm, 4 lanes) | 7.2 / **3.7** / 3.8–4.7 | – / 3.6 / **2.7 or 4.1** | 8 (fused: 16) |
//! | baseline SSE2 (16 xmm, 2 lanes) | **7.5** / 13.3 / 13.5 | 80 / 81 / 81 (software fma) | 4 |
//!
//! The table's v3 row was measured on an AMD Zen 4 restricted to AVX2 (`isa::set_max_level`): there
//! the fused 16-lane tile ran at 2.7 ns in some processes and 4.1 in others (the same binary; not the
//! stack's address: also with address randomisation off), the 8-lane one at 3.6 in all, and 8 was
//! taken. On a CPU that has AVX2 and no AVX-512, an AMD Zen 3 (EPYC, family 25 model 1; 2026-11-28,
//! CPU time, fused, one thread), the example `examples/ensemble_forms.rs` ran 16 lanes faster in every
//! form but one, in 4 of 4 processes (one pendulum 4.0–4.1 → 3.3–3.5 ns, lengths per trajectory
//! 3.9–4.2 → 3.35–3.5, damping per trajectory 4.6–4.7 → 3.9–4.1; every parameter a row 4.7–4.9 →
//! 7.4–7.5, its rows spill, `per_lane_tile_lanes`). But through `pl.simulate_ensemble` (one thread,
//! 4096 × 10³ steps, best of 9 per process, 9 processes per build alternating) the 16-lane build ran
//! at 3.4 ns in 2 processes and at 4.8–5.6 in the other 7, where the 8-lane one ran at 4.1–5.1, and
//! 8 was kept. Measured again on the same Zen 3 host (2026-11-28, 23:34–23:36 UTC, load 12–15 from
//! other users' builds) with both widths in one binary, the width chosen at every call (an experiment
//! build, not kept) and the two alternated call by call in each process (CPU time, 4096 × 10³ steps,
//! median of 9 calls each): one thread, one pendulum, 16 lanes at 3.38–3.49 ns against 4.17–4.31 at
//! 8 in 10 processes of 10 (ratio 0.805–0.821); lengths per trajectory 3.48–3.50 against 3.96 (0.88,
//! 3 of 3), one damping rate 3.91–4.02 against 4.58–4.65 (0.85–0.87, 3 of 3), damping per trajectory
//! 4.02–4.14 against 4.56–4.59 (0.88–0.90, 3 of 3); two threads, one pendulum, 0.82–0.93 (4 of 4).
//! No process ran 16 lanes slower: the two speeds by process did not come back when the widths were
//! compared in the same process and minute, so they came from when and beside whom each process
//! ran (a shared virtual machine: docs/performance.md, "The host's own speed moved"), not from the
//! process's addresses (the starts' array was at 0, 16, 32 or 48 mod 64 in fast processes alike).
//! So the fused arithmetic takes 16 lanes at x86-64-v3 (the build with 16 as its constant was not
//! timed again process by process). Unfused, 8 is the faster in the example
//! too (4.6–5.3 ns at 8 lanes, 4.7–5.6 at 16). Before the frames were aligned the unfused 8-lane
//! tile measured 6.6–6.8 there (its spills straddling cache lines), and 4 lanes were taken.
//!
//! 16 lanes are two AVX-512 registers per quantity: two independent dependency chains, so that the
//! step's latency (the division 1/b and the multiply-add chains) overlaps the other chain's work;
//! at AVX2 and SSE2 the same 16 lanes (four and eight registers per quantity) spill to the stack.
//! With the fused arithmetic at x86-64-v4, 24 lanes (three chains) except when every parameter is a
//! row, which then spills: on an Intel Xeon (Emerald Rapids, two 512-bit FMA units; one thread, ns
//! per trajectory-step, 16 → 24 lanes) one pendulum 2.10–2.21 → 1.90–2.01, lengths per trajectory
//! 2.13–2.20 → 1.92–2.02, damping per trajectory 2.33–2.43 → 2.11–2.16, every parameter a row 2.46 →
//! 4.0 (so 16 stays for it), unfused 2.8 → 3.0 (16 stays). Not measured at 24 lanes on the AMD Zen 4
//! of the table above.
//! Lanes are independent, so the width changes no bit (`tests/isa.rs` runs every level's tiles).
//! SI units: \[m\], [m/s], [1/s], [m/s²].

use crate::integrate::rattle_kernel::{Arithmetic, MulAdd};
use crate::isa::{self, Level};
use crate::state::State;
use glam::DVec3;

use super::block_state::{Block, Track};
use super::stages::Stages;
use super::tile::Tile;
use super::tile_params::{Damping, Lengths, PerLane, Shared, TileParams};
use super::{Lanes, LANES};

/// The widest tile: lanes stepped together in registers at x86-64-v4 with the fused arithmetic
/// (module doc; [`LANES`] is a multiple of it).
pub const TILE: usize = 24;

/// Which of a block's parameters all its lanes share (`Block::steps` picks the tile's form by it).
enum Sharing {
    All,
    AllButLengths,
    AllButDamping,
    Some,
}

/// Lanes stepped together in registers at instruction-set level `level` with `arithmetic` (module
/// doc: 24 fused and 16 unfused at x86-64-v4, 16 fused and 8 unfused at x86-64-v3, 4 at the
/// baseline), each a divisor of [`LANES`]. A block whose every parameter is a row takes
/// [`per_lane_tile_lanes`] instead. Only the speed depends on it, never a bit of the results.
pub fn tile_lanes(level: Level, arithmetic: Arithmetic) -> usize {
    match (level, arithmetic) {
        (Level::V4, Arithmetic::Fused) => 24,
        (Level::V4, Arithmetic::Unfused) => 16,
        (Level::V3, Arithmetic::Fused) => 16,
        (Level::V3, Arithmetic::Unfused) => 8,
        (Level::Baseline, _) => 4,
    }
}

/// [`tile_lanes`] for a block whose lanes share neither their lengths nor their g or damping (every
/// parameter a row, `PerLane`): its rows take registers the state needs, so 16 lanes at x86-64-v4
/// (24 spill), 8 at x86-64-v3 (16 spill: 7.4 ns per trajectory-step against 4.7 on an AMD Zen 3,
/// module doc) and 4 at the baseline.
pub fn per_lane_tile_lanes(level: Level) -> usize {
    match level {
        Level::V4 => 16,
        Level::V3 => 8,
        Level::Baseline => 4,
    }
}

impl Block {
    /// `chunk` steps of `h` [s] of every lane, the first being step number `first` + 1 of the run
    /// (for the settle tracking), tile by tile (module doc), with the multiply-adds rounded as `A`
    /// (`rattle_kernel::Unfused` or `Fused`, as the single-trajectory path it is compared with), the
    /// loops compiled for the CPU's widest vectors (`crate::isa`).
    ///
    /// The tile's width and parameter form are chosen here, and each choice runs in its own clone
    /// of `isa::fastest` (one function per width, form and level): the loops of one form are
    /// compiled and register-allocated alone, not as one arm of a function holding all of them.
    #[inline(always)]
    pub fn steps<A: MulAdd>(&mut self, chunk: u64, stages: &Stages, first: u64, track: Track) {
        // RATTLE's loop and a composition's are compiled apart, so that the former stays as it was
        if stages.len() == 1 {
            self.steps_as::<A, false>(chunk, stages, first, track);
        } else {
            self.steps_as::<A, true>(chunk, stages, first, track);
        }
    }

    /// [`Block::steps`] for one step of dt (`COMPOSED` false) or a composition's sub-steps (true).
    #[inline(always)]
    fn steps_as<A: MulAdd, const COMPOSED: bool>(
        &mut self,
        chunk: u64,
        stages: &Stages,
        first: u64,
        track: Track,
    ) {
        let arithmetic = if A::FUSED { Arithmetic::Fused } else { Arithmetic::Unfused };
        let level = isa::current();
        match (tile_lanes(level, arithmetic), self.sharing()) {
            // every parameter a row: its own width (`per_lane_tile_lanes`)
            (_, Sharing::Some) => match per_lane_tile_lanes(level) {
                16 => self.steps_at::<A, 16, PerLane<16>, COMPOSED>(chunk, stages, first, track),
                8 => self.steps_at::<A, 8, PerLane<8>, COMPOSED>(chunk, stages, first, track),
                _ => self.steps_at::<A, 4, PerLane<4>, COMPOSED>(chunk, stages, first, track),
            },
            (24, Sharing::All) => self.steps_at::<A, 24, Shared<24>, COMPOSED>(chunk, stages, first, track),
            (24, Sharing::AllButLengths) => {
                self.steps_at::<A, 24, Lengths<24>, COMPOSED>(chunk, stages, first, track)
            }
            (24, Sharing::AllButDamping) => {
                self.steps_at::<A, 24, Damping<24>, COMPOSED>(chunk, stages, first, track)
            }
            (16, Sharing::All) => self.steps_at::<A, 16, Shared<16>, COMPOSED>(chunk, stages, first, track),
            (16, Sharing::AllButLengths) => {
                self.steps_at::<A, 16, Lengths<16>, COMPOSED>(chunk, stages, first, track)
            }
            (16, Sharing::AllButDamping) => {
                self.steps_at::<A, 16, Damping<16>, COMPOSED>(chunk, stages, first, track)
            }
            (8, Sharing::All) => self.steps_at::<A, 8, Shared<8>, COMPOSED>(chunk, stages, first, track),
            (8, Sharing::AllButLengths) => {
                self.steps_at::<A, 8, Lengths<8>, COMPOSED>(chunk, stages, first, track)
            }
            (8, Sharing::AllButDamping) => {
                self.steps_at::<A, 8, PerLane<8>, COMPOSED>(chunk, stages, first, track)
            }
            (_, Sharing::All) => self.steps_at::<A, 4, Shared<4>, COMPOSED>(chunk, stages, first, track),
            (_, _) => self.steps_at::<A, 4, PerLane<4>, COMPOSED>(chunk, stages, first, track),
        }
    }

    /// [`Block::steps_tiled`] in its own clone of `isa::fastest` (the closure's type is distinct
    /// for each `A`, `T`, `P`, `COMPOSED`).
    #[inline(always)]
    fn steps_at<A: MulAdd, const T: usize, P: TileParams, const COMPOSED: bool>(
        &mut self,
        chunk: u64,
        stages: &Stages,
        first: u64,
        track: Track,
    ) {
        isa::fastest(
            #[inline(always)]
            || self.steps_tiled::<A, T, P, COMPOSED>(chunk, stages, first, track),
        )
    }

    /// Which parameters every lane shares (bit for bit): all of l², 1/l², g and the damping factor
    /// (the usual ensemble: one pendulum, many starts), all but the length, or fewer. The tiles keep
    /// shared parameters as one number each instead of a row (`tile.rs`).
    fn sharing(&self) -> Sharing {
        let same = |a: &Lanes| a.iter().all(|&y| y.to_bits() == a[0].to_bits());
        let lengths = same(&self.l2) && same(&self.inv_l2);
        match (lengths, same(&self.g), self.decay_half.iter().all(same)) {
            (true, true, true) => Sharing::All,
            (false, true, true) => Sharing::AllButLengths,
            (true, true, false) => Sharing::AllButDamping,
            _ => Sharing::Some,
        }
    }

    /// `Block::steps` with tiles of `T` lanes and the parameters held as `P`: each step one RATTLE
    /// step of dt, or the composition's sub-steps h_k with their damping factors (`stages.rs`).
    #[inline(always)]
    fn steps_tiled<A: MulAdd, const T: usize, P: TileParams, const COMPOSED: bool>(
        &mut self,
        chunk: u64,
        stages: &Stages,
        first: u64,
        track: Track,
    ) {
        for o in (0..LANES).step_by(T) {
            let mut tile = Tile::<T, P>::load(self, o);
            if !COMPOSED {
                let h = stages.h(0);
                // tracked inline, not through `track_tile`: with it, the one-pendulum form with the
                // summary executes 2 % more instructions per step (cachegrind, x86-64-v3,
                // examples/ensemble_forms.rs SUMMARY=1; the same for the damped form)
                for j in 1..=chunk {
                    tile.step::<A, false>(h, self.damped);
                    if track.summary {
                        tile.update_summary(&mut self.summary, &mut self.crossings, &mut self.above, o);
                    }
                    if track.settle {
                        tile.track_settle(
                            &self.down,
                            self.cos_settle,
                            &mut self.last_out,
                            o,
                            (first + j) as f64,
                        );
                    }
                }
            } else {
                for j in 1..=chunk {
                    for k in 0..stages.len() {
                        tile.set_stage(self, o, stages.distinct(k));
                        tile.step::<A, true>(stages.h(k), self.damped);
                    }
                    self.track_tile(&tile, track, o, first + j);
                }
            }
            tile.store(self, o);
        }
    }

    /// After step number `step` of the run: the tile's lanes folded into the summary and the settle
    /// records, as `track` asks.
    #[inline(always)]
    fn track_tile<const T: usize, P: TileParams>(
        &mut self,
        tile: &Tile<T, P>,
        track: Track,
        o: usize,
        step: u64,
    ) {
        if track.summary {
            tile.update_summary(&mut self.summary, &mut self.crossings, &mut self.above, o);
        }
        if track.settle {
            tile.track_settle(&self.down, self.cos_settle, &mut self.last_out, o, step as f64);
        }
    }

    /// Records sample `k` as outside the settle band where the sway exceeds the threshold.
    pub fn track_settle(&mut self, k: f64) {
        for i in 0..LANES {
            let out = self.x[2][i] * self.down[i] < self.cos_settle;
            self.last_out[i] = if out { k } else { self.last_out[i] };
        }
    }

    /// Folds the current states into the summary (extremes, plane crossings).
    pub fn update_summary(&mut self) {
        for o in (0..LANES).step_by(TILE) {
            Tile::<TILE, PerLane<TILE>>::load(self, o).update_summary(
                &mut self.summary,
                &mut self.crossings,
                &mut self.above,
                o,
            );
        }
    }

    /// Lane `i`'s state.
    pub fn state(&self, i: usize) -> State {
        State {
            x: DVec3::new(self.x[0][i], self.x[1][i], self.x[2][i]),
            v: DVec3::new(self.v[0][i], self.v[1][i], self.v[2][i]),
        }
    }
}
