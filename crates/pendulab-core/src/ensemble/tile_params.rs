//! A tile's parameters l² \[m²\], 1/l² [1/m²], g [m/s²] and e^{−c h/2} (`tile.rs`; h = dt, or the
//! sub-step of a composition: `stages.rs`), each held as a
//! row of `T` values (it differs from lane to lane) or as one number (every lane of the block has
//! the same one, bit for bit): [`Params`] over a [`Lane`] per parameter. The forms the tiles take
//! are [`Shared`] (one pendulum, many starts: the usual ensemble), [`Lengths`] (lengths per
//! trajectory), [`Damping`] (damping per trajectory) and [`PerLane`] (everything else). The same
//! values in every form, so the same bits; the forms differ in how many vector registers they take,
//! which decides how the fused step is taken ([`TileParams::TWO_HALVES`], module doc of `tile.rs`).
//! SI units.

use super::block_state::Block;
use super::Lanes;

/// `T` values, one per lane.
pub(super) type Row<const T: usize> = [f64; T];

/// `a[o..o + T]` as a row.
#[inline(always)]
pub(super) fn row<const T: usize>(a: &Lanes, o: usize) -> Row<T> {
    std::array::from_fn(|i| a[o + i])
}

/// One parameter of the `T` lanes of a tile: a row, or one number shared by every lane.
pub(super) trait Lane<const T: usize>: Copy {
    /// How many rows (vector registers per `T` lanes) it takes: 1 for a row, 0 for one number.
    const ROWS: usize;
    /// Lanes o…o + T of the block's values `a`.
    fn load(a: &Lanes, o: usize) -> Self;
    /// Lane `i`'s value.
    fn at(&self, i: usize) -> f64;
}

impl<const T: usize> Lane<T> for Row<T> {
    const ROWS: usize = 1;
    #[inline(always)]
    fn load(a: &Lanes, o: usize) -> Self {
        row(a, o)
    }
    #[inline(always)]
    fn at(&self, i: usize) -> f64 {
        self[i]
    }
}

/// One number for every lane (the block's lanes share it bit for bit, `Block::sharing`).
#[derive(Clone, Copy)]
pub(super) struct One(f64);

impl<const T: usize> Lane<T> for One {
    const ROWS: usize = 0;
    #[inline(always)]
    fn load(a: &Lanes, o: usize) -> Self {
        One(a[o])
    }
    #[inline(always)]
    fn at(&self, _: usize) -> f64 {
        self.0
    }
}

/// A tile's parameters: l² \[m²\], 1/l² [1/m²], g [m/s²] and e^{−c dt/2} of lane `i`.
pub(super) trait TileParams: Copy {
    /// Whether the fused step goes in two halves (module doc of `tile.rs`): true when the parameters
    /// take few registers (at most two rows), and in tiles of 8 lanes (x86-64-v3's width for every
    /// parameter a row, `block::per_lane_tile_lanes`), where four rows fit too: on an AMD Zen 3, one
    /// thread, CPU time, 3 interleaved process runs, 5.24–5.32 ns per trajectory-step in one pass
    /// against 4.92–4.95 in two halves (2026-11-28); through `pl.simulate_ensemble` (one thread, 4096
    /// × 10³ steps, 9 processes per build alternating) 19.99–23.16 ms → 18.79–21.20 ms (medians 22.1
    /// and 21.0). Only the speed depends on it, never a bit.
    const TWO_HALVES: bool;
    /// Whether e^{−c dt/2} is a row (damping per lane): then a step taken in two halves applies the
    /// damping flow to v₀ where each half reads it; one number is applied once, in place, before
    /// them (`Tile::step_flow`). Only the speed depends on it, never a bit.
    const DECAY_ROW: bool;
    /// Lanes o…o + T of the block's parameters (the damping factors of the first sub-step size).
    fn load(b: &Block, o: usize) -> Self;
    /// Takes the damping factors of the block's row `d` (sub-step sizes: `stages.rs`).
    fn set_decay_row(&mut self, b: &Block, o: usize, d: usize);
    fn l2(&self, i: usize) -> f64;
    fn inv_l2(&self, i: usize) -> f64;
    fn g(&self, i: usize) -> f64;
    fn decay_half(&self, i: usize) -> f64;
}

/// The parameters of `T` lanes: the lengths (l² and 1/l²) as `L`, g as `G`, e^{−c dt/2} as `D`.
#[derive(Clone, Copy)]
pub(super) struct Params<const T: usize, L, G, D> {
    l2: L,
    inv_l2: L,
    g: G,
    decay_half: D,
}

impl<const T: usize, L: Lane<T>, G: Lane<T>, D: Lane<T>> TileParams for Params<T, L, G, D> {
    const TWO_HALVES: bool = 2 * L::ROWS + G::ROWS + D::ROWS <= 2 || T == 8;
    const DECAY_ROW: bool = D::ROWS == 1;
    #[inline(always)]
    fn load(b: &Block, o: usize) -> Self {
        Self {
            l2: L::load(&b.l2, o),
            inv_l2: L::load(&b.inv_l2, o),
            g: G::load(&b.g, o),
            decay_half: D::load(&b.decay_half[0], o),
        }
    }
    #[inline(always)]
    fn set_decay_row(&mut self, b: &Block, o: usize, d: usize) {
        self.decay_half = D::load(&b.decay_half[d], o);
    }
    #[inline(always)]
    fn l2(&self, i: usize) -> f64 {
        self.l2.at(i)
    }
    #[inline(always)]
    fn inv_l2(&self, i: usize) -> f64 {
        self.inv_l2.at(i)
    }
    #[inline(always)]
    fn g(&self, i: usize) -> f64 {
        self.g.at(i)
    }
    #[inline(always)]
    fn decay_half(&self, i: usize) -> f64 {
        self.decay_half.at(i)
    }
}

/// Every parameter shared by all lanes (one pendulum, many starts).
pub(super) type Shared<const T: usize> = Params<T, One, One, One>;
/// Lengths per lane; g and damping shared.
pub(super) type Lengths<const T: usize> = Params<T, Row<T>, One, One>;
/// Damping per lane; lengths and g shared.
pub(super) type Damping<const T: usize> = Params<T, One, One, Row<T>>;
/// Every parameter a row (lengths, g or damping per lane in another combination).
pub(super) type PerLane<const T: usize> = Params<T, Row<T>, Row<T>, Row<T>>;
