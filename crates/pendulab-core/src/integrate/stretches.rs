//! Fixed steps that land on every break of a model ([`Model::next_break`]: a sampled pivot's samples,
//! where p̈ is kinked), for [`crate::Stepper::set_steps_on_breaks`]: `dt` is then the longest step, and
//! the stretch from the current time to the next break is taken in n = ⌈span/dt⌉ equal steps of
//! span/n. Without it a fixed step that holds a break is split there ([`super::step_across_breaks`]):
//! no accuracy is lost, but on unevenly spaced samples almost every step splits into two of uneven
//! length, which costs steps and makes the error depend on where the grid falls between samples
//! rather than on dt alone. A stretch that the plain grid t_anchor + k·dt already ends on (to
//! 10⁻⁹·dt) keeps that grid: evenly spaced samples on it give the plain run's numbers bit for bit.
//! Times in s.

use crate::model::Model;

/// The grid of fixed steps t = `anchor` + k·`h` from step `k` on.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Grid {
    /// The time \[s\] of step 0.
    pub anchor: f64,
    /// Steps taken since the anchor.
    pub k: u64,
    /// The step \[s\].
    pub h: f64,
}

impl Grid {
    /// The time \[s\] after `j` more steps.
    #[inline(always)]
    pub fn after(&self, j: u64) -> f64 {
        self.anchor + (self.k + j) as f64 * self.h
    }
}

/// The grid and end \[s\] of the stretch that starts at `t` \[s\], the current `grid`'s time, with
/// steps of at most `dt_max` \[s\]: the next break b (one within 10⁻⁹·dt_max of t counts as reached),
/// reached in n = ⌈(b − t)/dt_max⌉ equal steps, on the current grid when its step is dt_max and it
/// lands on b after n steps, else on a new grid anchored at t with step (b − t)/n. Past the last
/// break (b = ∞) the grid of step dt_max, kept or anchored at t.
pub(crate) fn plan<M: Model>(model: &M, t: f64, grid: Grid, dt_max: f64) -> (Grid, f64) {
    let slack = 1e-9 * dt_max;
    let mut b = model.next_break(t);
    while b - t <= slack {
        b = model.next_break(b);
    }
    let fresh = |h: f64| Grid { anchor: t, k: 0, h };
    if b == f64::INFINITY {
        return (if grid.h == dt_max { grid } else { fresh(dt_max) }, b);
    }
    let n = ((b - t - slack) / dt_max).ceil().max(1.0);
    if grid.h == dt_max && (grid.after(n as u64) - b).abs() <= slack {
        (grid, b)
    } else {
        (fresh((b - t) / n), b)
    }
}

/// The steps of `grid` from its current time up to `end` \[s\] (a stretch's end on the grid, to
/// round-off); `u64::MAX` for `end` = ∞.
pub(crate) fn steps_to(grid: Grid, end: f64) -> u64 {
    if end == f64::INFINITY {
        return u64::MAX;
    }
    let total = ((end - grid.anchor) / grid.h).round();
    (total as u64).saturating_sub(grid.k).max(1)
}
