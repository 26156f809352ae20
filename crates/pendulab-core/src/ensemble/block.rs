//! One block of [`LANES`] trajectories in structure-of-arrays form and its step loop (T-2.1, T-2.2;
//! the arithmetic of `integrate/rattle_kernel.rs`, operation for operation, so each lane gets the
//! single-trajectory RATTLE numbers bit for bit):
//!
//!   v½ = v₀ − (h/2) g e₃ + μ x₀ (|x₁| = l),  x₁ = x₀ + h v½,  v₁ = v½ − (h/2) g e₃ − x₁ (x₁·u)/l²,
//!
//! with Kahan-compensated updates and, when a lane is damped (c [1/s], T-7.1), the exact damping
//! flow v ↦ e^{−c h/2} v on either side of the step.
//!
//! The block is stored as 64 lanes, but stepped as [`tile_lanes`] lanes at a time: a tile's state
//! (x, v, their compensations, l², 1/l², g) is loaded once, advanced by a whole chunk of steps in
//! vector registers, and stored once (register blocking: no loads or stores per step, and w, the
//! position quadratic and μ are computed once per step and kept, not recomputed in a second pass over
//! memory).
//! The multiplier μ comes from the Catalan series for every lane of the tile; in the rare step where
//! one lane is outside the series' range (large h|v|), the whole tile's step is recomputed with
//! `PositionQuadratic::multiplier` (the series where it applies, else the closed form), which gives
//! the other lanes the same bits again. The tile's width is chosen per instruction-set level (and
//! arithmetic), because what fits in the registers differs (docs/performance.md, "No CPU left behind",
//! *The tile per level*; 4096 starts × 2000 steps, one thread, CPU time, ns per trajectory-step):
//!
//! | level (registers) | unfused: tile 4 / 8 / 16 | fused: tile 4 / 8 / 16 | tile chosen |
//! |---|---|---|---|
//! | x86-64-v4 (32 zmm, 8 lanes) | 6.8 / 3.65 / **3.0** | 5.9 / 2.9 / **2.1–2.3** | 16 |
//! | x86-64-v3 (16 ymm, 4 lanes) | **5.9** / 6.6–6.8 / 7.3–7.4 | 4.9 / **3.45** / 6.1 | 4 unfused, 8 fused |
//! | baseline SSE2 (16 xmm, 2 lanes) | **7.5** / 13.3 / 13.5 | 80 / 81 / 81 (software fma) | 4 |
//!
//! 16 lanes are two AVX-512 registers per quantity: two independent dependency chains, so that the
//! step's latency (the division 1/b and the multiply-add chains) overlaps the other chain's work;
//! at AVX2 and SSE2 the same 16 lanes (four and eight registers per quantity) spill to the stack.
//! Lanes are independent, so the width changes no bit (`tests/isa.rs` runs every level's tiles).
//! SI units: \[m\], [m/s], [1/s], [m/s²].

use crate::integrate::rattle_kernel::{
    advance_position, advance_velocity, fmadd3, Arithmetic, Fused, MulAdd, PositionQuadratic,
    ProjectionPolynomial,
};
use crate::integrate::rattle_vertical::VerticalField;
use crate::isa::{self, Level};
use crate::state::State;
use glam::DVec3;

use super::LANES;

/// The widest tile: lanes stepped together in registers at x86-64-v4 (module doc; [`LANES`] is a
/// multiple of it).
pub const TILE: usize = 16;

/// Lanes stepped together in registers at instruction-set level `level` with `arithmetic` (module
/// doc: 16 at x86-64-v4, 8 (fused) or 4 (unfused) at x86-64-v3, 4 at the baseline), each a divisor of
/// [`LANES`]. Only the speed depends on it, never a bit of the results.
pub fn tile_lanes(level: Level, arithmetic: Arithmetic) -> usize {
    match (level, arithmetic) {
        (Level::V4, _) => 16,
        (Level::V3, Arithmetic::Fused) => 8,
        _ => 4,
    }
}

pub(super) type Lanes = [f64; LANES];
type Row<const T: usize> = [f64; T];

/// One block: positions, velocities, Kahan compensations and parameters of LANES trajectories.
#[derive(Clone)]
pub(super) struct Block {
    pub x: [Lanes; 3],
    pub v: [Lanes; 3],
    pub cx: [Lanes; 3],
    pub cv: [Lanes; 3],
    /// l² and 1/l² per lane (as the single path computes them).
    pub l2: Lanes,
    pub inv_l2: Lanes,
    pub g: Lanes,
    /// e^{−c dt/2} per lane (1 without damping) and whether any lane is damped.
    pub decay_half: Lanes,
    pub damped: bool,
    /// −sign(g)/l per lane (cos sway = z · down) and cos of the settle threshold (all lanes).
    pub down: Lanes,
    pub cos_settle: f64,
    /// Index of the last sample whose sway exceeded the threshold (−1: none).
    pub last_out: Lanes,
    /// Number of real lanes (the rest repeat the last trajectory and are ignored).
    pub len: usize,
    /// Per-lane summary: min z, max z, min E/m, max E/m, min J₃/m, max J₃/m.
    pub summary: [Lanes; 6],
    /// Per lane: crossings of the pivot's horizontal plane so far, and the side (1: z > 0) at the
    /// last sample.
    pub crossings: Lanes,
    pub above: Lanes,
}

/// What is tracked besides the state while stepping.
#[derive(Clone, Copy)]
pub(super) struct Track {
    pub summary: bool,
    pub settle: bool,
}

impl Block {
    /// `chunk` steps of `h` [s] of every lane, the first being step number `first` + 1 of the run
    /// (for the settle tracking), tile by tile (module doc), with the multiply-adds rounded as `A`
    /// (`rattle_kernel::Unfused` or `Fused`, as the single-trajectory path it is compared with).
    #[inline(always)]
    pub fn steps<A: MulAdd>(&mut self, chunk: u64, h: f64, first: u64, track: Track) {
        // the tile for the level this runs at (module doc); the arms of the other levels are
        // compiled into each level's clone too, but never taken there
        let arithmetic = if A::FUSED { Arithmetic::Fused } else { Arithmetic::Unfused };
        match tile_lanes(isa::current(), arithmetic) {
            16 => self.steps_tiled::<A, 16>(chunk, h, first, track),
            8 => self.steps_tiled::<A, 8>(chunk, h, first, track),
            _ => self.steps_tiled::<A, 4>(chunk, h, first, track),
        }
    }

    /// [`Block::steps`] with tiles of `T` lanes.
    #[inline(always)]
    fn steps_tiled<A: MulAdd, const T: usize>(&mut self, chunk: u64, h: f64, first: u64, track: Track) {
        for o in (0..LANES).step_by(T) {
            let mut tile = Tile::<T>::load(self, o);
            for j in 1..=chunk {
                tile.step::<A>(h, self.damped);
                if track.summary {
                    tile.update_summary(&mut self.summary, &mut self.crossings, &mut self.above, o);
                }
                if track.settle {
                    tile.track_settle(&self.down, self.cos_settle, &mut self.last_out, o, (first + j) as f64);
                }
            }
            tile.store(self, o);
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
            Tile::<TILE>::load(self, o).update_summary(
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

/// `T` lanes of a block, held in local arrays (registers) while they are stepped.
struct Tile<const T: usize> {
    x: [Row<T>; 3],
    v: [Row<T>; 3],
    cx: [Row<T>; 3],
    cv: [Row<T>; 3],
    l2: Row<T>,
    inv_l2: Row<T>,
    g: Row<T>,
    decay_half: Row<T>,
}

/// `a[o..o + T]` as a row.
#[inline(always)]
fn row<const T: usize>(a: &Lanes, o: usize) -> Row<T> {
    std::array::from_fn(|i| a[o + i])
}

impl<const T: usize> Tile<T> {
    #[inline(always)]
    fn load(b: &Block, o: usize) -> Self {
        let rows = |a: &[Lanes; 3]| [row(&a[0], o), row(&a[1], o), row(&a[2], o)];
        Self {
            x: rows(&b.x),
            v: rows(&b.v),
            cx: rows(&b.cx),
            cv: rows(&b.cv),
            l2: row(&b.l2, o),
            inv_l2: row(&b.inv_l2, o),
            g: row(&b.g, o),
            decay_half: row(&b.decay_half, o),
        }
    }

    #[inline(always)]
    fn store(&self, b: &mut Block, o: usize) {
        for c in 0..3 {
            b.x[c][o..o + T].copy_from_slice(&self.x[c]);
            b.v[c][o..o + T].copy_from_slice(&self.v[c]);
            b.cx[c][o..o + T].copy_from_slice(&self.cx[c]);
            b.cv[c][o..o + T].copy_from_slice(&self.cv[c]);
        }
    }

    /// One step of every lane (identical arithmetic to `Rattle::advance` for f = −g e₃, with the
    /// damping flow on either side when the block has a damped lane).
    #[inline(always)]
    fn step<A: MulAdd>(&mut self, h: f64, damped: bool) {
        if damped {
            self.decay();
        }
        if !self.rattle::<A>(h, false) {
            // some lane is outside the series' range: the whole tile again, from the same state
            self.rattle::<A>(h, true);
        }
        if damped {
            self.decay();
        }
    }

    /// The exact flow of linear damping for dt/2: v ↦ e^{−c dt/2} v (the `damped` model's
    /// `velocity_flow` without drag or frame rotation, same arithmetic).
    #[inline(always)]
    fn decay(&mut self) {
        for c in 0..3 {
            for i in 0..T {
                self.v[c][i] *= self.decay_half[i];
            }
        }
    }

    /// One undamped RATTLE step of every lane with the single-trajectory path's arithmetic
    /// (`integrate::rattle_kernel`, uniform field k = −(h/2) g e₃). With `closed` false, μ is the
    /// Catalan series for every lane and the step is kept only if every lane is within the series'
    /// range (returns whether it was); with `closed` true, μ is `PositionQuadratic::multiplier`.
    #[inline(always)]
    #[allow(clippy::needless_range_loop)] // lane i of a dozen arrays at once: the loop the compiler vectorises
    fn rattle<A: MulAdd>(&mut self, h: f64, closed: bool) -> bool {
        if A::FUSED {
            return self.rattle_vertical(h, closed);
        }
        let half = 0.5 * h;
        let mut next = [[[0.0; T]; 3]; 4];
        let mut ok = true;
        for i in 0..T {
            let x0 = DVec3::new(self.x[0][i], self.x[1][i], self.x[2][i]);
            let v0 = DVec3::new(self.v[0][i], self.v[1][i], self.v[2][i]);
            // (0, 0, −g)·(h/2) with the zeros written as such: 0·(h/2) = +0 exactly for the dt > 0
            // the run checked, so the lane gets the single path's bits without two multiplications
            let kick = DVec3::new(0.0, 0.0, -self.g[i] * half);
            let w = v0 + kick;
            let quad = PositionQuadratic::new::<A>(x0, w, h, self.l2[i]);
            let mu = if closed {
                quad.multiplier::<A>(h)
            } else {
                let (mu, in_range) = quad.multiplier_series::<A>(h);
                ok &= in_range;
                mu
            };
            let p = ProjectionPolynomial::new::<A>(x0, w, kick, &quad, h, self.inv_l2[i]).at::<A>(mu);
            let mut cx = DVec3::new(self.cx[0][i], self.cx[1][i], self.cx[2][i]);
            let mut cv = DVec3::new(self.cv[0][i], self.cv[1][i], self.cv[2][i]);
            let x1 = advance_position::<A>(x0, fmadd3::<A>(x0, mu, w), h, &mut cx);
            let v1 = advance_velocity::<A>(v0, kick + kick, x0, mu, x1, p, &mut cv);
            for c in 0..3 {
                next[0][c][i] = x1[c];
                next[1][c][i] = v1[c];
                next[2][c][i] = cx[c];
                next[3][c][i] = cv[c];
            }
        }
        if ok {
            [self.x, self.v, self.cx, self.cv] = next;
        }
        ok
    }

    /// [`Tile::rattle`] with the fused arithmetic, in its vertical-field form
    /// (`integrate/rattle_vertical.rs`, as the single path takes it for a vertical field).
    #[inline(always)]
    #[allow(clippy::needless_range_loop)] // lane i of a dozen arrays at once: the loop the compiler vectorises
    fn rattle_vertical(&mut self, h: f64, closed: bool) -> bool {
        let half = 0.5 * h;
        let mut next = [[[0.0; T]; 3]; 4];
        let mut ok = true;
        for i in 0..T {
            let x0 = DVec3::new(self.x[0][i], self.x[1][i], self.x[2][i]);
            let v0 = DVec3::new(self.v[0][i], self.v[1][i], self.v[2][i]);
            let kick = -self.g[i] * half;
            let field = VerticalField { h, kick0: kick, kick1: kick, l2: self.l2[i], inv_l2: self.inv_l2[i] };
            let (w, quad) = field.quadratic(x0, v0);
            let mu = if closed {
                quad.multiplier::<Fused>(h)
            } else {
                let (mu, in_range) = quad.multiplier_series::<Fused>(h);
                ok &= in_range;
                mu
            };
            let cx = DVec3::new(self.cx[0][i], self.cx[1][i], self.cx[2][i]);
            let cv = DVec3::new(self.cv[0][i], self.cv[1][i], self.cv[2][i]);
            let end = field.finish((x0, v0), (w, &quad), mu, (cx, cv));
            for c in 0..3 {
                next[0][c][i] = end.x[c];
                next[1][c][i] = end.v[c];
                next[2][c][i] = end.comp_x[c];
                next[3][c][i] = end.comp_v[c];
            }
        }
        if ok {
            [self.x, self.v, self.cx, self.cv] = next;
        }
        ok
    }

    /// Folds the tile's states into the block's summary at lanes o…o + T.
    #[inline(always)]
    fn update_summary(&self, s: &mut [Lanes; 6], crossings: &mut Lanes, above: &mut Lanes, o: usize) {
        for i in 0..T {
            let (x, y, z) = (self.x[0][i], self.x[1][i], self.x[2][i]);
            let (vx, vy, vz) = (self.v[0][i], self.v[1][i], self.v[2][i]);
            let e = 0.5 * (vx * vx + vy * vy + vz * vz) + self.g[i] * z;
            let j = x * vy - y * vx;
            let k = o + i;
            s[0][k] = s[0][k].min(z);
            s[1][k] = s[1][k].max(z);
            s[2][k] = s[2][k].min(e);
            s[3][k] = s[3][k].max(e);
            s[4][k] = s[4][k].min(j);
            s[5][k] = s[5][k].max(j);
            let up = if z > 0.0 { 1.0 } else { 0.0 };
            crossings[k] += (up - above[k]).abs();
            above[k] = up;
        }
    }

    /// Records sample `k` for the lanes o…o + T whose sway exceeds the threshold.
    #[inline(always)]
    fn track_settle(&self, down: &Lanes, cos_settle: f64, last_out: &mut Lanes, o: usize, k: f64) {
        for i in 0..T {
            let out = self.x[2][i] * down[o + i] < cos_settle;
            last_out[o + i] = if out { k } else { last_out[o + i] };
        }
    }
}
