//! The incremental stepper: one integrator, one model, one state, advanced step by step
//! (init / step / state), as a live viewer or the batch solver in [`mod@crate::solve`] needs it.
//!
//! Fixed-step methods take steps of `dt` on the grid t = t_anchor + k·dt (computed by
//! multiplication, so 10⁸ steps accumulate no round-off in t); [`Stepper::step_to`] shortens the
//! last step to land exactly on a requested time and re-anchors the grid there; with
//! [`Stepper::set_steps_on_breaks`] dt is the longest step and the steps land on a sampled pivot's
//! samples (`integrate/stretches.rs`). The adaptive `dop853` takes one accepted step per call
//! and interpolates with its dense output.

use crate::error::{require_positive, Error, Result};
use crate::integrate::composition::Composition;
use crate::integrate::dop853::Dop853;
use crate::integrate::rattle::Rattle;
use crate::integrate::rattle_kernel::Arithmetic;
use crate::integrate::rk4::Rk4;
use crate::integrate::rk4_angles::Rk4Angles;
use crate::integrate::rkmk4::Rkmk4;
use crate::integrate::{fixed_steps, one_step, FixedStep, Halved, Method, Stats};
use crate::model::Model;
use crate::state::State;

mod breaks;

/// How to integrate: the method and its step-size or tolerance settings.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SolveOptions {
    /// The integrator (default: RATTLE).
    pub method: Method,
    /// Step size \[s\] of fixed-step methods; for `dop853` the initial step guess (0 = automatic).
    pub dt: f64,
    /// Relative tolerance of `dop853` (ignored by fixed-step methods).
    pub rtol: f64,
    /// Absolute tolerance of `dop853` [m and m/s] (ignored by fixed-step methods).
    pub atol: f64,
    /// `dop853` only: project onto TS² after every step (recommended; T-2.4 is unstable off TS²).
    pub project: bool,
}

impl Default for SolveOptions {
    fn default() -> Self {
        Self { method: Method::DEFAULT, dt: 1e-3, rtol: 1e-10, atol: 1e-12, project: true }
    }
}

#[derive(Debug, Clone)]
enum Scheme {
    Rk4(Rk4),
    Rattle(Rattle),
    Composition(Composition),
    Rkmk4(Rkmk4),
    Rk4Angles(Rk4Angles),
    Dop853(Box<Dop853>),
}

/// Runs `$body` with `$s` bound to the fixed-step scheme inside `$scheme` (monomorphised per method).
macro_rules! with_fixed {
    ($scheme:expr, $s:ident => $body:expr, $adaptive:expr) => {
        match $scheme {
            Scheme::Rk4($s) => $body,
            Scheme::Rattle($s) => $body,
            Scheme::Composition($s) => $body,
            Scheme::Rkmk4($s) => $body,
            Scheme::Rk4Angles($s) => $body,
            Scheme::Dop853(_) => $adaptive,
        }
    };
}

/// Incremental integration of one trajectory.
#[derive(Debug, Clone)]
pub struct Stepper<M: Model> {
    model: M,
    scheme: Scheme,
    method: Method,
    /// The grid's step \[s\]: `dt`, or a stretch's with [`Stepper::set_steps_on_breaks`].
    h: f64,
    t_anchor: f64,
    k: u64,
    t: f64,
    state: State,
    stats: Stats,
    /// The time \[s\] the state was last known finite (the start, a new state, the last
    /// [`Stepper::check_finite`] passed): the time a divergence found later names.
    finite_at: f64,
    /// Every fixed step taken as two halves ([`Stepper::set_halved_steps`]).
    halved: bool,
    /// The dt given \[s\] (the longest step with [`Stepper::set_steps_on_breaks`]).
    dt: f64,
    /// Steps land on the model's breaks ([`Stepper::set_steps_on_breaks`]).
    on_breaks: bool,
    /// With `on_breaks`: the end \[s\] of the stretch the grid is planned for (−∞: plan again).
    stretch_end: f64,
}

impl<M: Model> Stepper<M> {
    /// A stepper at time `t0` \[s\] in `state`, validated: dt > 0 for fixed-step methods, valid
    /// tolerances for `dop853`, a finite t0.
    pub fn new(model: M, t0: f64, state: State, options: &SolveOptions) -> Result<Self> {
        if !t0.is_finite() {
            return Err(Error::InvalidParameter {
                name: "t0",
                value: t0,
                allowed: "the start time must be finite (s)",
            });
        }
        let info = options.method.info();
        if model.is_hybrid() {
            return Err(Error::HybridModel { model: model.name() });
        }
        if options.method == Method::Rk4Angles && model.angle_form(t0).is_none() {
            return Err(Error::UnsupportedModel { method: info.name, model: model.name() });
        }
        let scheme = match options.method {
            Method::Rk4 => Scheme::Rk4(Rk4),
            Method::Rattle => Scheme::Rattle(Rattle::default()),
            Method::Rattle4 => Scheme::Composition(Composition::of_order(4)),
            Method::Rattle6 => Scheme::Composition(Composition::of_order(6)),
            Method::Rattle8 => Scheme::Composition(Composition::of_order(8)),
            Method::Rkmk4 => Scheme::Rkmk4(Rkmk4::default()),
            Method::Rk4Angles => Scheme::Rk4Angles(Rk4Angles::default()),
            Method::Dop853 => {
                let h_init = if options.dt > 0.0 && options.dt.is_finite() { Some(options.dt) } else { None };
                Scheme::Dop853(Box::new(Dop853::new(
                    options.rtol,
                    options.atol,
                    options.project,
                    f64::INFINITY,
                    h_init,
                )?))
            }
        };
        if !info.adaptive {
            require_positive("dt", options.dt, "the step size dt must be a finite number > 0 s")?;
        }
        let state = model.integrator_state(t0, state);
        Ok(Self {
            model,
            scheme,
            method: options.method,
            h: options.dt,
            t_anchor: t0,
            k: 0,
            t: t0,
            state,
            stats: Stats::default(),
            finite_at: t0,
            halved: false,
            dt: options.dt,
            on_breaks: false,
            stretch_end: f64::NEG_INFINITY,
        })
    }

    /// Current time \[s\].
    pub fn t(&self) -> f64 {
        self.t
    }
    /// Current state (physical: for a hoisted rope on |x| = l(t), [`Model::to_physical`]).
    pub fn state(&self) -> State {
        self.model.to_physical(self.t, self.state)
    }
    /// The model.
    pub fn model(&self) -> &M {
        &self.model
    }
    /// The method.
    pub fn method(&self) -> Method {
        self.method
    }
    /// Work counters so far.
    pub fn stats(&self) -> Stats {
        self.stats
    }
    /// Fixed step size \[s\] as given (the longest with [`Stepper::set_steps_on_breaks`]; for
    /// `dop853`: the initial step guess).
    pub fn dt(&self) -> f64 {
        self.dt
    }

    /// Replaces the state (e.g. after a user drags the bob); the grid is re-anchored at the current time.
    pub fn set_state(&mut self, state: State) {
        self.state = self.model.integrator_state(self.t, state);
        self.t_anchor = self.t;
        self.k = 0;
        self.finite_at = self.t;
        self.stretch_end = f64::NEG_INFINITY;
        with_fixed!(&mut self.scheme, s => s.reset(), {
            let Scheme::Dop853(d) = &mut self.scheme else { unreachable!() };
            d.reset()
        });
    }

    /// One step: `dt` for fixed-step methods, one accepted step for `dop853`.
    pub fn step(&mut self) -> Result<()> {
        self.step_towards(f64::INFINITY)
    }

    /// One step, but never past `t_stop` \[s\]; a fixed step that would pass it is shortened to land on it.
    pub fn step_towards(&mut self, t_stop: f64) -> Result<()> {
        // compiled for the CPU's best instruction set (crate::isa; the numbers are the same at every level)
        crate::isa::fastest(
            #[inline(always)]
            || self.step_towards_here(t_stop),
        )
    }

    #[inline(always)]
    fn step_towards_here(&mut self, t_stop: f64) -> Result<()> {
        if !matches!(self.scheme, Scheme::Dop853(_)) {
            self.plan_stretch();
        }
        let (model, state, stats) = (&self.model, &mut self.state, &mut self.stats);
        let (t, halved) = (self.t, self.halved);
        with_fixed!(&mut self.scheme, s => {
            // Full steps are exactly dt (as in `step_n`, so both paths give identical numbers); only
            // a step that would pass t_stop is shortened, and a grid point within 1e-9 dt of t_stop
            // counts as t_stop.
            let t_next = self.t_anchor + (self.k + 1) as f64 * self.h;
            let slack = 1e-9 * self.h;
            if t_stop - t <= slack {
                // Already there up to round-off of the grid: a step this short would only add noise.
                self.t = t_stop;
                self.t_anchor = t_stop;
                self.k = 0;
                self.stretch_end = f64::NEG_INFINITY;
                return Ok(());
            }
            let full = t_next <= t_stop + slack;
            let h = if full { self.h } else { t_stop - t };
            let (taken, per_step) = if halved {
                let mut halves = Halved(s);
                (one_step(&mut halves, model, t, state, h)?, halves.evals_per_step())
            } else {
                (one_step(s, model, t, state, h)?, s.evals_per_step())
            };
            if full {
                self.k += 1;
                self.t = if (t_next - t_stop).abs() <= slack { t_stop } else { t_next };
            } else {
                self.t = t_stop;
                self.t_anchor = t_stop;
                self.k = 0;
                self.stretch_end = f64::NEG_INFINITY;
            }
            stats.steps += taken * (1 + u64::from(halved));
            stats.rhs_evals += taken * per_step;
            Ok(())
        }, {
            let Scheme::Dop853(d) = &mut self.scheme else { unreachable!() };
            let mut t = self.t;
            d.step(model, &mut t, state, t_stop, stats)?;
            self.t = t;
            Ok(())
        })
    }

    /// Takes `n` full steps (fixed-step methods) in a tight loop; for `dop853`, `n` accepted steps.
    pub fn step_n(&mut self, n: u64) -> Result<()> {
        // the loop compiled for the CPU's best instruction set (crate::isa)
        crate::isa::fastest(
            #[inline(always)]
            || self.step_n_here(n),
        )
    }

    #[inline(always)]
    fn step_n_here(&mut self, n: u64) -> Result<()> {
        if !self.on_breaks || matches!(self.scheme, Scheme::Dop853(_)) {
            return self.grid_steps(n);
        }
        self.stretch_steps(n)
    }

    /// `n` full steps on the current grid (`step_n`'s loop).
    #[inline(always)]
    fn grid_steps(&mut self, n: u64) -> Result<()> {
        let (model, state, halved) = (&self.model, &mut self.state, self.halved);
        with_fixed!(&mut self.scheme, s => {
            let (k0, mut splits) = (self.k, 0);
            let grid = (self.t_anchor, self.h);
            let (result, per_step) = if halved {
                let mut halves = Halved(s);
                let r = fixed_steps(model, &mut halves, grid, n, (&mut self.k, &mut splits), state);
                (r, halves.evals_per_step())
            } else {
                (fixed_steps(model, s, grid, n, (&mut self.k, &mut splits), state), s.evals_per_step())
            };
            let taken = self.k - k0 + splits;
            self.t = self.t_anchor + self.k as f64 * self.h;
            self.stats.steps += taken * (1 + u64::from(halved));
            self.stats.rhs_evals += taken * per_step;
            result
        }, {
            // dop853: its step is inlined into this dispatched body (not `self.step()`, which
            // would dispatch again and keep the stages out of line)
            for _ in 0..n {
                self.step_towards_here(f64::INFINITY)?;
            }
            Ok(())
        })
    }

    /// Advances to exactly `t_target` \[s\] (≥ the current time): fixed-step methods take full steps
    /// and shorten the last; `dop853` steps past nothing and lands on `t_target`.
    pub fn step_to(&mut self, t_target: f64) -> Result<()> {
        self.step_to_capped(t_target, u64::MAX).map(|_| ())
    }

    /// [`Stepper::step_to`] taking at most `max_steps` steps: `Ok(true)` once exactly at `t_target`,
    /// `Ok(false)` when the cap came first (the state is then that of the last step taken, before
    /// `t_target`; calling again goes on with the same steps, so a run cut into capped calls is the
    /// uncapped run). Bounds the work of one call, which an adaptive method cannot bound by the
    /// length of time asked for (a fast forcing needs many steps per second): a live viewer calls it
    /// in slices and stops at its time budget.
    pub fn step_to_capped(&mut self, t_target: f64, max_steps: u64) -> Result<bool> {
        if t_target.is_nan() || t_target < self.t {
            return Err(Error::InvalidParameter {
                name: "t_target",
                value: t_target,
                allowed: "the target time must be finite and not before the stepper's current time (s)",
            });
        }
        let mut taken = 0u64;
        while self.t < t_target {
            if taken == max_steps {
                return Ok(false);
            }
            self.step_towards(t_target)?;
            taken += 1;
        }
        Ok(true)
    }

    /// Dense output of `dop853` at `t_out` \[s\] inside its last step; `None` for other methods.
    /// The three extra stages are computed on the first call after a step, hence `&mut self`.
    pub fn dense_output(&mut self, t_out: f64) -> Option<State> {
        match &mut self.scheme {
            Scheme::Dop853(d) => {
                let (a, b) = d.last_step_interval();
                let model = &self.model;
                // the interpolant's stages compiled for the CPU's best instruction set (crate::isa)
                (a <= t_out && t_out <= b).then(|| {
                    crate::isa::fastest(
                        #[inline(always)]
                        || model.to_physical(t_out, d.dense_output(model, t_out)),
                    )
                })
            }
            _ => None,
        }
    }

    /// The RATTLE family only (rattle, rattle4/6/8): how the step rounds its multiply-adds, from the
    /// next step on ([`Arithmetic`]; default unfused). `Fused` on another method is an error
    /// ([`Error::UnsupportedArithmetic`]); `Unfused` is accepted by every method (their arithmetic).
    pub fn set_arithmetic(&mut self, arithmetic: Arithmetic) -> Result<()> {
        match &mut self.scheme {
            Scheme::Rattle(r) => r.set_arithmetic(arithmetic),
            Scheme::Composition(c) => c.set_arithmetic(arithmetic),
            _ if arithmetic == Arithmetic::Unfused => {}
            _ => return Err(Error::UnsupportedArithmetic { method: self.method.info().name }),
        }
        Ok(())
    }

    /// `dop853` only: also keep E (conservative models) and J₃ (axisymmetric ones) at their values at
    /// the current state by projecting v after every step. No effect on other methods (the RATTLE
    /// family keeps J₃ exactly and E without drift by itself).
    pub fn set_invariant_projection(&mut self, on: bool) {
        if let Scheme::Dop853(d) = &mut self.scheme {
            d.set_invariant_projection(on);
        }
    }

    /// Fails with [`Error::Diverged`] when the state is not finite, naming the time it was last known
    /// finite (methods that do not check every step, such as `rk4`, are found out here).
    pub fn check_finite(&mut self) -> Result<()> {
        if self.state.is_finite() {
            self.finite_at = self.t;
            Ok(())
        } else {
            Err(Error::Diverged { t: self.finite_at, method: self.method.info().name, dt: self.dt })
        }
    }
}
