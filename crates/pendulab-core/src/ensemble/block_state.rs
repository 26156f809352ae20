//! The data of one block of [`LANES`](super::LANES) trajectories in structure-of-arrays form: state,
//! Kahan compensations, parameters, summaries and settle records, one array of 48 lanes each (the
//! step loop that advances it is `block.rs`, the tile that holds a part of it in registers
//! `tile.rs`). SI units: \[m\], [m/s], [1/s], [m/s²].

use super::stages::DISTINCT;
use super::Lanes;

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
    /// e^{−c h_k/2} per lane (1 without damping), one row per distinct sub-step size h_k of a step
    /// (`stages.rs`; row 0 alone for RATTLE, h = dt), and whether any lane is damped.
    pub decay_half: [Lanes; DISTINCT],
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

impl Block {
    /// A block of zeros on the heap, for [`super::plan::Plan::fill`] to fill (one per worker).
    pub fn boxed() -> Box<Self> {
        let z = [0.0; super::LANES];
        Box::new(Self {
            x: [z; 3],
            v: [z; 3],
            cx: [z; 3],
            cv: [z; 3],
            l2: z,
            inv_l2: z,
            g: z,
            decay_half: [z; DISTINCT],
            damped: false,
            down: z,
            cos_settle: 0.0,
            last_out: z,
            len: 0,
            summary: [z; 6],
            crossings: z,
            above: z,
        })
    }
}

/// What is tracked besides the state while stepping.
#[derive(Clone, Copy)]
pub(super) struct Track {
    pub summary: bool,
    pub settle: bool,
}
