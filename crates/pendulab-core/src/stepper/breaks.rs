//! The [`Stepper`]'s settings for models with breaks (a sampled pivot's samples): every step as two
//! halves, the steps landing on the breaks ([`crate::integrate::stretches`]).

use super::Stepper;
use crate::error::Result;
use crate::integrate::stretches::{self, Grid};
use crate::model::Model;

impl<M: Model> Stepper<M> {
    /// Takes every fixed step (each sub-step on a model with breaks, each shortened step) as two equal
    /// halves ([`crate::integrate::Halved`]) when `on`: the run whose steps are exactly half of those of
    /// the same run without, for a Richardson error estimate on a sampled pivot, whose steps split on
    /// its samples. `stats.steps` counts the halves. No effect on `dop853`. Off by default.
    pub fn set_halved_steps(&mut self, on: bool) {
        self.halved = on;
    }

    /// With `on`, dt is the longest fixed step and the steps land on every break of the model (a
    /// sampled pivot's samples): the stretch between two is taken in ⌈span/dt⌉ equal steps
    /// (`integrate/stretches.rs`); a stretch the plain grid ends on keeps it, so evenly spaced
    /// samples on the grid give the plain run bit for bit. No effect without breaks, nor on `dop853`
    /// (whose steps end on them anyway). Off by default: a step that holds a break is split there.
    pub fn set_steps_on_breaks(&mut self, on: bool) {
        self.on_breaks = on;
        self.stretch_end = f64::NEG_INFINITY;
        if !on && self.h != self.dt {
            (self.t_anchor, self.k, self.h) = (self.t, 0, self.dt);
        }
    }

    /// With steps on the breaks: a new stretch's grid once the last one is done (fixed steps only).
    #[inline(always)]
    pub(super) fn plan_stretch(&mut self) {
        if self.on_breaks && self.t >= self.stretch_end - 1e-9 * self.dt {
            let grid = Grid { anchor: self.t_anchor, k: self.k, h: self.h };
            let (g, end) = stretches::plan(&self.model, self.t, grid, self.dt);
            (self.t_anchor, self.k, self.h, self.stretch_end) = (g.anchor, g.k, g.h, end);
        }
    }

    /// `n` full steps with the steps on the breaks: one stretch at a time, the grid's steps up to its
    /// end, then the next stretch's grid.
    #[inline(always)]
    pub(super) fn stretch_steps(&mut self, n: u64) -> Result<()> {
        let mut left = n;
        while left > 0 {
            self.plan_stretch();
            let grid = Grid { anchor: self.t_anchor, k: self.k, h: self.h };
            let now = left.min(stretches::steps_to(grid, self.stretch_end));
            self.grid_steps(now)?;
            left -= now;
        }
        Ok(())
    }
}
