//! A tile's parameters l² \[m²\], 1/l² [1/m²], g [m/s²] and e^{−c dt/2} (`tile.rs`): a row of `T`
//! values each ([`PerLane`]: lengths, g or damping per trajectory), rows of the lengths only
//! ([`Lengths`]: g and damping shared), or one number each ([`Shared`]: one pendulum, many starts).
//! The same values in every form, so the same bits; the forms differ in how many vector registers
//! they take, which decides how the fused step is taken (`TileParams::TWO_HALVES`, module doc of
//! `tile.rs`). SI units.

use super::block_state::Block;
use super::Lanes;

/// `T` values, one per lane.
pub(super) type Row<const T: usize> = [f64; T];

/// `a[o..o + T]` as a row.
#[inline(always)]
pub(super) fn row<const T: usize>(a: &Lanes, o: usize) -> Row<T> {
    std::array::from_fn(|i| a[o + i])
}

/// A tile's parameters: l² \[m²\], 1/l² [1/m²], g [m/s²] and e^{−c dt/2} of lane `i`.
pub(super) trait TileParams: Copy {
    /// Whether the fused step goes in two halves (module doc): true when the parameters take few
    /// registers.
    const TWO_HALVES: bool;
    /// Lanes o…o + T of the block's parameters.
    fn load(b: &Block, o: usize) -> Self;
    fn l2(&self, i: usize) -> f64;
    fn inv_l2(&self, i: usize) -> f64;
    fn g(&self, i: usize) -> f64;
    fn decay_half(&self, i: usize) -> f64;
}

/// One row per parameter (lanes with their own lengths, g or damping).
#[derive(Clone, Copy)]
pub(super) struct PerLane<const T: usize> {
    l2: Row<T>,
    inv_l2: Row<T>,
    g: Row<T>,
    decay_half: Row<T>,
}

impl<const T: usize> TileParams for PerLane<T> {
    const TWO_HALVES: bool = false;
    #[inline(always)]
    fn load(b: &Block, o: usize) -> Self {
        Self {
            l2: row(&b.l2, o),
            inv_l2: row(&b.inv_l2, o),
            g: row(&b.g, o),
            decay_half: row(&b.decay_half, o),
        }
    }
    #[inline(always)]
    fn l2(&self, i: usize) -> f64 {
        self.l2[i]
    }
    #[inline(always)]
    fn inv_l2(&self, i: usize) -> f64 {
        self.inv_l2[i]
    }
    #[inline(always)]
    fn g(&self, i: usize) -> f64 {
        self.g[i]
    }
    #[inline(always)]
    fn decay_half(&self, i: usize) -> f64 {
        self.decay_half[i]
    }
}

/// Rows of l² and 1/l² (lengths per trajectory), one number for g and e^{−c dt/2} shared by every lane.
#[derive(Clone, Copy)]
pub(super) struct Lengths<const T: usize> {
    l2: Row<T>,
    inv_l2: Row<T>,
    g: f64,
    decay_half: f64,
}

impl<const T: usize> TileParams for Lengths<T> {
    const TWO_HALVES: bool = true;
    #[inline(always)]
    fn load(b: &Block, o: usize) -> Self {
        Self { l2: row(&b.l2, o), inv_l2: row(&b.inv_l2, o), g: b.g[o], decay_half: b.decay_half[o] }
    }
    #[inline(always)]
    fn l2(&self, i: usize) -> f64 {
        self.l2[i]
    }
    #[inline(always)]
    fn inv_l2(&self, i: usize) -> f64 {
        self.inv_l2[i]
    }
    #[inline(always)]
    fn g(&self, _: usize) -> f64 {
        self.g
    }
    #[inline(always)]
    fn decay_half(&self, _: usize) -> f64 {
        self.decay_half
    }
}

/// One number per parameter, shared by every lane (`Block::sharing`): the same values as
/// the rows would hold, so the same bits, in fewer registers.
#[derive(Clone, Copy)]
pub(super) struct Shared {
    l2: f64,
    inv_l2: f64,
    g: f64,
    decay_half: f64,
}

impl TileParams for Shared {
    const TWO_HALVES: bool = true;
    #[inline(always)]
    fn load(b: &Block, o: usize) -> Self {
        Self { l2: b.l2[o], inv_l2: b.inv_l2[o], g: b.g[o], decay_half: b.decay_half[o] }
    }
    #[inline(always)]
    fn l2(&self, _: usize) -> f64 {
        self.l2
    }
    #[inline(always)]
    fn inv_l2(&self, _: usize) -> f64 {
        self.inv_l2
    }
    #[inline(always)]
    fn g(&self, _: usize) -> f64 {
        self.g
    }
    #[inline(always)]
    fn decay_half(&self, _: usize) -> f64 {
        self.decay_half
    }
}
