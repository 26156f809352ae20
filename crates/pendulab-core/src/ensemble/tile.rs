//! A tile: `T` lanes of a block held in local arrays (vector registers) while a whole chunk of steps
//! is taken (register blocking: the state x, v and its compensations are loaded once and stored
//! once per chunk), and one RATTLE step of all its lanes with the arithmetic of
//! `integrate/rattle_kernel.rs` (unfused) or `integrate/rattle_vertical.rs` (fused), operation for
//! operation, so each lane gets the single-trajectory numbers bit for bit (T-2.1, T-2.2):
//!
//!   v½ = v₀ − (h/2) g e₃ + μ x₀ (|x₁| = l),  x₁ = x₀ + h v½,  v₁ = v½ − (h/2) g e₃ − x₁ (x₁·u)/l²,
//!
//! with Kahan-compensated updates and the exact damping flow v ↦ e^{−c h/2} v (T-7.1) on either
//! side when a lane is damped (in place, or where the step reads v₀ and writes v₁: `inline_flow`).
//!
//! A step goes in two halves over the lanes: first every lane's position quadratic and multiplier μ
//! (`Tile::multipliers`: with the fused arithmetic the Catalan series up to y³ for every lane, which
//! applies where |y| ≤ `SHORT_SERIES_LIMIT`, almost every step; in a step where some lane is beyond
//! it, and for the rest of the chunk, the full series, which takes the same short polynomial in the
//! lanes within it; in the rare step where some lane is outside the full series' range, large h|v|,
//! `PositionQuadratic::multiplier` for every lane — each lane gets its single path's bits whichever
//! pass gave them), then the rest of the step, written over the tile's state in place: against one
//! pass, 3.97 → 3.13 ns per trajectory-step unfused, 2.31 → 2.18 fused (docs/performance.md).
//!
//! The parameters l², 1/l², g and e^{−c dt/2} are held per form (`tile_params.rs`): one number each
//! when every lane of the block has the same (`Shared`: one pendulum, many starts, the usual
//! ensemble), rows of the lengths or of the damping factor only (`Lengths`, `Damping`), or every one a
//! row (`PerLane`): the same values, so the same bits, in fewer registers. With the fused arithmetic
//! and every parameter a row the two halves' temporaries and the rows do not fit in the registers,
//! and that form takes the step in one pass instead, its result kept aside and committed when every
//! lane was in range (`Tile::rattle_vertical_one_pass`; 2.3–2.5 ns per trajectory-step against
//! 2.1–2.8 in two halves, depending on the process; in the 8-lane tiles of x86-64-v3 two halves are
//! faster, `TileParams::TWO_HALVES`).
//! SI units: \[m\], [m/s], [1/s], [m/s²].

use crate::integrate::rattle_kernel::{
    advance_position, advance_velocity, fmadd3, Fused, MulAdd, PositionQuadratic, ProjectionPolynomial,
    SeriesTerms,
};
use crate::integrate::rattle_vertical::VerticalField;
use glam::DVec3;

use super::block_state::Block;
use super::tile_params::{row, TileParams};
use super::Lanes;

use super::tile_params::Row;

/// `T` lanes of a block, held in local arrays (registers) while they are stepped, with their
/// parameters as `P` (a row per parameter, or one number each when the lanes share them).
pub(super) struct Tile<const T: usize, P> {
    x: [Row<T>; 3],
    v: [Row<T>; 3],
    cx: [Row<T>; 3],
    cv: [Row<T>; 3],
    params: P,
    /// Whether a lane needed more than the short series (`SeriesTerms::Short`) at an earlier step
    /// of this chunk: then the tile takes the full series first.
    long: bool,
}

/// How a pass over the lanes finds μ: the series with the terms given, or
/// `PositionQuadratic::multiplier` (the series where it applies, the closed form elsewhere).
#[derive(Clone, Copy)]
enum Multiplier {
    Series(SeriesTerms),
    Closed,
}

/// The position quadratics of a tile's lanes, one row per coefficient (the first half of a step
/// hands them to the second).
struct Quads<const T: usize>([Row<T>; 5]);

impl<const T: usize> Quads<T> {
    #[inline(always)]
    fn new() -> Self {
        Self([[0.0; T]; 5])
    }

    #[inline(always)]
    fn set(&mut self, i: usize, q: &PositionQuadratic) {
        [self.0[0][i], self.0[1][i], self.0[2][i], self.0[3][i], self.0[4][i]] = [q.q, q.b, q.c, q.xw, q.ww];
    }

    #[inline(always)]
    fn get(&self, i: usize) -> PositionQuadratic {
        let r = &self.0;
        PositionQuadratic { q: r[0][i], b: r[1][i], c: r[2][i], xw: r[3][i], ww: r[4][i] }
    }
}

impl<const T: usize, P: TileParams> Tile<T, P> {
    #[inline(always)]
    pub(super) fn load(b: &Block, o: usize) -> Self {
        let rows = |a: &[Lanes; 3]| [row(&a[0], o), row(&a[1], o), row(&a[2], o)];
        let params = P::load(b, o);
        Self { x: rows(&b.x), v: rows(&b.v), cx: rows(&b.cx), cv: rows(&b.cv), params, long: false }
    }

    /// Writes the tile's state back to lanes o…o + T of the block.
    #[inline(always)]
    pub(super) fn store(&self, b: &mut Block, o: usize) {
        for c in 0..3 {
            b.x[c][o..o + T].copy_from_slice(&self.x[c]);
            b.v[c][o..o + T].copy_from_slice(&self.v[c]);
            b.cx[c][o..o + T].copy_from_slice(&self.cx[c]);
            b.cv[c][o..o + T].copy_from_slice(&self.cv[c]);
        }
    }

    /// The damping factors of the block's row `d` for the sub-steps that follow (`stages.rs`).
    #[inline(always)]
    pub(super) fn set_stage(&mut self, b: &Block, o: usize, d: usize) {
        self.params.set_decay_row(b, o, d);
    }

    /// One step of h \[s\] of every lane (identical arithmetic to `Rattle::advance` for f = −g e₃,
    /// with the damping flow on either side when the block has a damped lane); `COMPOSED`: h is a
    /// composition's sub-step, possibly < 0 (`stages.rs`), else RATTLE's dt > 0.
    #[inline(always)]
    pub(super) fn step<A: MulAdd, const COMPOSED: bool>(&mut self, h: f64, damped: bool) {
        if damped {
            self.step_flow::<A, COMPOSED, true>(h);
        } else {
            self.step_flow::<A, COMPOSED, false>(h);
        }
    }

    /// [`Tile::step`] with the damping flow v ↦ e^{−c h/2} v on either side when `DAMPED`: in place
    /// around the step, or where the step reads v₀ and writes v₁ ([`Tile::inline_flow`]).
    #[inline(always)]
    fn step_flow<A: MulAdd, const COMPOSED: bool, const DAMPED: bool>(&mut self, h: f64) {
        if A::FUSED && !P::TWO_HALVES {
            // rows of parameters and the fused step's temporaries do not all fit in the registers
            // at once: one pass, its result kept aside (module doc)
            let short = !self.long
                && self.rattle_vertical_one_pass::<DAMPED>(h, Multiplier::Series(SeriesTerms::Short));
            if !short {
                self.long = true;
                if !self.rattle_vertical_one_pass::<DAMPED>(h, Multiplier::Series(SeriesTerms::Full)) {
                    self.rattle_vertical_one_pass::<DAMPED>(h, Multiplier::Closed);
                }
            }
        } else {
            // two passes over the lanes read v₀ twice: the flow taken in each when its factors are a
            // row, else in place before and after them (`TileParams::DECAY_ROW`)
            let in_place = DAMPED && !Self::inline_flow(DAMPED, A::FUSED);
            if in_place {
                self.decay();
            }
            if A::FUSED {
                self.rattle_vertical::<DAMPED>(h);
            } else {
                self.rattle::<A, COMPOSED, DAMPED>(h);
            }
            if in_place {
                self.decay();
            }
        }
    }

    /// Whether the damping flow is taken where a step in two halves reads v₀ and writes v₁ (the same
    /// products, so the same bits): with the fused arithmetic and the factors in a row
    /// (`TileParams::DECAY_ROW`); else in place before and after. Counted at x86-64-v3 (cachegrind,
    /// docs/performance.md, "The damping flow in the step"): damping per trajectory 6 % fewer
    /// instructions and 11 % fewer memory accesses; one rate and the unfused tiles 1–3 % more.
    #[inline(always)]
    const fn inline_flow(damped: bool, fused: bool) -> bool {
        damped && fused && P::DECAY_ROW
    }

    /// The damping flow for dt/2 in place over the tile: v ↦ v e^{−c dt/2} ([`Tile::decayed`]).
    #[inline(always)]
    fn decay(&mut self) {
        for c in 0..3 {
            for i in 0..T {
                self.v[c][i] *= self.params.decay_half(i);
            }
        }
    }

    /// v [m/s] after the damping flow for dt/2 when `damped`: v e^{−c dt/2} (the `damped` model's
    /// `velocity_flow` without drag or frame rotation, same arithmetic), else v.
    #[inline(always)]
    fn decayed(&self, i: usize, v: DVec3, damped: bool) -> DVec3 {
        if damped {
            v * self.params.decay_half(i)
        } else {
            v
        }
    }

    /// Lane `i`'s step of h \[s\] in its vertical field: both kicks −g h/2 [m/s] (gravity is
    /// constant over the step), its l² \[m²\] and 1/l² [1/m²] (`integrate/rattle_vertical.rs`).
    #[inline(always)]
    fn vertical_field(&self, i: usize, h: f64) -> VerticalField {
        let kick = -self.params.g(i) * (0.5 * h);
        let (l2, inv_l2) = (self.params.l2(i), self.params.inv_l2(i));
        VerticalField { h, kick0: kick, kick1: kick, l2, inv_l2 }
    }

    /// x₀ [m], v₀ [m/s] of lane `i`, v₀ after the damping flow when `damped`.
    #[inline(always)]
    fn lane(&self, i: usize, damped: bool) -> (DVec3, DVec3) {
        let (x, v) = (&self.x, &self.v);
        let v0 = DVec3::new(v[0][i], v[1][i], v[2][i]);
        (DVec3::new(x[0][i], x[1][i], x[2][i]), self.decayed(i, v0, damped))
    }

    /// The first half of a step: every lane's position quadratic (its rows kept in `quads`) and
    /// multiplier μ [1/s] (returned): the Catalan series, short (`SeriesTerms::Short`, up to y³)
    /// unless an earlier step of the chunk needed more, full where some lane needs it, or, in the
    /// rare step where some lane is outside the full series' range (large h|v|),
    /// `PositionQuadratic::multiplier` for every lane. Each lane gets the bits of the
    /// single-trajectory path's `multiplier`, whichever pass gave them (`rattle_kernel` module doc).
    /// `quadratic` is lane i's (w, quadratic) as the step computes them.
    #[inline(always)]
    fn multipliers<A: MulAdd>(
        &mut self,
        h: f64,
        quads: &mut Quads<T>,
        quadratic: impl Fn(&Self, usize) -> (DVec3, PositionQuadratic),
    ) -> Row<T> {
        if A::FUSED && !self.long {
            if let Some(mu) = self.series_pass::<A>(h, quads, &quadratic, SeriesTerms::Short) {
                return mu;
            }
            self.long = true;
        }
        if let Some(mu) = self.series_pass::<A>(h, quads, &quadratic, SeriesTerms::Full) {
            return mu;
        }
        std::array::from_fn(|i| quadratic(self, i).1.multiplier::<A>(h))
    }

    /// μ [1/s] of every lane from the series with `terms`, the quadratics kept in `quads`; `None`
    /// when it does not apply to some lane.
    #[inline(always)]
    #[allow(clippy::needless_range_loop)] // lane i of several arrays at once: the loop the compiler vectorises
    fn series_pass<A: MulAdd>(
        &self,
        h: f64,
        quads: &mut Quads<T>,
        quadratic: &impl Fn(&Self, usize) -> (DVec3, PositionQuadratic),
        terms: SeriesTerms,
    ) -> Option<Row<T>> {
        let mut mu = [0.0; T];
        let mut ok = true;
        for i in 0..T {
            let (_, quad) = quadratic(self, i);
            let (m, in_range) = quad.multiplier_series_with::<A>(h, terms);
            ok &= in_range;
            mu[i] = m;
            quads.set(i, &quad);
        }
        ok.then_some(mu)
    }

    /// One undamped RATTLE step of every lane with the single-trajectory path's arithmetic
    /// (`integrate::rattle_kernel`, uniform field k = −(h/2) g e₃, the unfused arithmetic): μ for
    /// every lane first ([`Tile::multipliers`]), then the rest of the step in place.
    #[inline(always)]
    #[allow(clippy::needless_range_loop)] // lane i of a dozen arrays at once: the loop the compiler vectorises
    fn rattle<A: MulAdd, const COMPOSED: bool, const DAMPED: bool>(&mut self, h: f64) {
        let half = 0.5 * h;
        let flow = Self::inline_flow(DAMPED, A::FUSED);
        // (0, 0, −g)·(h/2) as the single path computes it: 0·(h/2) is +0 for RATTLE's dt > 0 (the
        // constant, which the compiler folds: 8 % fewer instructions than the product at
        // x86-64-v3), and −0 for a composition's backward sub-steps. That −0 never shows in a
        // result: a composition begins with a forward sub-step (stages.rs, tested), whose +0 kick
        // makes every zero component of the state +0, and +0 + (−0) = +0 + (+0) = +0, so a
        // mutation of it to +0 is not observable; it is kept to mirror `Composition::step`
        let zero = if COMPOSED { 0.0 * half } else { 0.0 };
        let kick = |t: &Self, i: usize| DVec3::new(zero, zero, -t.params.g(i) * half);
        let mut quads = Quads::new();
        let mu = self.multipliers::<A>(h, &mut quads, |t, i| {
            let (x0, v0) = t.lane(i, flow);
            let w = v0 + kick(t, i);
            (w, PositionQuadratic::new::<A>(x0, w, h, t.params.l2(i)))
        });
        for i in 0..T {
            let (x0, v0) = self.lane(i, flow);
            let k = kick(self, i);
            let w = v0 + k;
            let quad = quads.get(i);
            let p = ProjectionPolynomial::new::<A>(x0, w, k, &quad, h, self.params.inv_l2(i)).at::<A>(mu[i]);
            let mut cx = DVec3::new(self.cx[0][i], self.cx[1][i], self.cx[2][i]);
            let mut cv = DVec3::new(self.cv[0][i], self.cv[1][i], self.cv[2][i]);
            let x1 = advance_position::<A>(x0, fmadd3::<A>(x0, mu[i], w), h, &mut cx);
            let v1 = advance_velocity::<A>(v0, k + k, x0, mu[i], x1, p, &mut cv);
            self.set(flow, i, [x1, v1, cx, cv]);
        }
    }

    /// [`Tile::rattle`] with the fused arithmetic, in its vertical-field form
    /// (`integrate/rattle_vertical.rs`, as the single path takes it for a vertical field).
    #[inline(always)]
    #[allow(clippy::needless_range_loop)] // lane i of several arrays at once: the loop the compiler vectorises
    fn rattle_vertical<const DAMPED: bool>(&mut self, h: f64) {
        let flow = Self::inline_flow(DAMPED, true);
        let mut quads = Quads::new();
        let mu = self.multipliers::<Fused>(h, &mut quads, |t, i| {
            let (x0, v0) = t.lane(i, flow);
            t.vertical_field(i, h).quadratic(x0, v0)
        });
        for i in 0..T {
            let (x0, v0) = self.lane(i, flow);
            let f = self.vertical_field(i, h);
            let w = DVec3::new(v0.x, v0.y, v0.z + f.kick0); // as VerticalField::quadratic
            let cx = DVec3::new(self.cx[0][i], self.cx[1][i], self.cx[2][i]);
            let cv = DVec3::new(self.cv[0][i], self.cv[1][i], self.cv[2][i]);
            let end = f.finish((x0, v0), (w, &quads.get(i)), mu[i], (cx, cv));
            self.set(flow, i, [end.x, end.v, end.comp_x, end.comp_v]);
        }
    }

    /// [`Tile::rattle_vertical`] in one pass over the lanes with μ as `how` gives it, the new state
    /// kept aside and committed only if every lane was within the series' range (always with
    /// `Multiplier::Closed`): the same bits, faster than two halves when the parameters are rows
    /// (module doc).
    #[inline(always)]
    #[allow(clippy::needless_range_loop)] // lane i of a dozen arrays at once: the loop the compiler vectorises
    fn rattle_vertical_one_pass<const DAMPED: bool>(&mut self, h: f64, how: Multiplier) -> bool {
        let mut next = [[[0.0; T]; 3]; 4];
        let mut ok = true;
        for i in 0..T {
            let (x0, v0) = self.lane(i, DAMPED);
            let field = self.vertical_field(i, h);
            let (w, quad) = field.quadratic(x0, v0);
            let mu = match how {
                Multiplier::Closed => quad.multiplier::<Fused>(h),
                Multiplier::Series(terms) => {
                    let (mu, in_range) = quad.multiplier_series_with::<Fused>(h, terms);
                    ok &= in_range;
                    mu
                }
            };
            let cx = DVec3::new(self.cx[0][i], self.cx[1][i], self.cx[2][i]);
            let cv = DVec3::new(self.cv[0][i], self.cv[1][i], self.cv[2][i]);
            let end = field.finish((x0, v0), (w, &quad), mu, (cx, cv));
            let v1 = self.decayed(i, end.v, DAMPED);
            for c in 0..3 {
                next[0][c][i] = end.x[c];
                next[1][c][i] = v1[c];
                next[2][c][i] = end.comp_x[c];
                next[3][c][i] = end.comp_v[c];
            }
        }
        if ok {
            [self.x, self.v, self.cx, self.cv] = next;
        }
        ok
    }

    /// Lane `i`'s new x₁ [m], v₁ [m/s] (after the damping flow when `damped`) and their compensations.
    #[inline(always)]
    fn set(&mut self, damped: bool, i: usize, [x, v, cx, cv]: [DVec3; 4]) {
        let v = self.decayed(i, v, damped);
        for c in 0..3 {
            self.x[c][i] = x[c];
            self.v[c][i] = v[c];
            self.cx[c][i] = cx[c];
            self.cv[c][i] = cv[c];
        }
    }

    /// Folds the tile's states into the block's summary at lanes o…o + T.
    #[inline(always)]
    pub(super) fn update_summary(
        &self,
        s: &mut [Lanes; 6],
        crossings: &mut Lanes,
        above: &mut Lanes,
        o: usize,
    ) {
        for i in 0..T {
            let (x, y, z) = (self.x[0][i], self.x[1][i], self.x[2][i]);
            let (vx, vy, vz) = (self.v[0][i], self.v[1][i], self.v[2][i]);
            let e = 0.5 * (vx * vx + vy * vy + vz * vz) + self.params.g(i) * z;
            let j = x * vy - y * vx;
            let k = o + i;
            // one comparison each (vminpd/vmaxpd): the rows start at ±∞ and never hold NaN, and a
            // NaN z, E or J₃ leaves them as `f64::min`/`max` would
            s[0][k] = if z < s[0][k] { z } else { s[0][k] };
            s[1][k] = if z > s[1][k] { z } else { s[1][k] };
            s[2][k] = if e < s[2][k] { e } else { s[2][k] };
            s[3][k] = if e > s[3][k] { e } else { s[3][k] };
            s[4][k] = if j < s[4][k] { j } else { s[4][k] };
            s[5][k] = if j > s[5][k] { j } else { s[5][k] };
            let up = if z > 0.0 { 1.0 } else { 0.0 };
            crossings[k] += (up - above[k]).abs();
            above[k] = up;
        }
    }

    /// Records sample `k` for the lanes o…o + T whose sway exceeds the threshold.
    #[inline(always)]
    pub(super) fn track_settle(&self, down: &Lanes, cos_settle: f64, last_out: &mut Lanes, o: usize, k: f64) {
        for i in 0..T {
            let out = self.x[2][i] * down[o + i] < cos_settle;
            last_out[o + i] = if out { k } else { last_out[o + i] };
        }
    }
}
