//! Integrators, one file per method family, and the one registry [`Method`] that every test and
//! every front end iterates. Each method declares its order and its structural properties up front.
//!
//! | name | order | what it keeps |
//! |---|---|---|
//! | `rk4` | 4 | nothing: classic RK4 on T-2.4, drifts off TS² (the baseline) |
//! | `dop853` | 8 (adaptive) | optionally TS² by projection after each step; dense output of order 7 |
//! | `rattle` | 2 | TS² and J₃ to round-off; symplectic (the default) |
//! | `rattle4`, `rattle6`, `rattle8` | 4, 6, 8 | symmetric compositions of RATTLE: TS², J₃, symplectic |
//! | `rkmk4` | 4 | the sphere exactly (Lie-group RKMK with the SO(3) exponential) and x·v = 0 |
//! | `rk4_angles` | 4 | RK4 in (θ, φ), T-2.5; refuses to go near a pole |

pub mod composition;
pub mod dop853;
pub(crate) mod dop853_control;
pub(crate) mod dop853_tableau;
pub mod rattle;
pub mod rattle_kernel;
pub mod rattle_vertical;
pub mod rk4;
pub mod rk4_angles;
pub mod rkmk4;
pub(crate) mod stretches;

use crate::error::{Error, Result};
use crate::model::{Model, ModelVisitor};
use crate::state::State;

/// Work counters owned by the framework, not by the methods.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Stats {
    /// Accepted steps.
    pub steps: u64,
    /// Rejected steps (adaptive methods only).
    pub rejected: u64,
    /// Evaluations of the applied acceleration / right-hand side.
    pub rhs_evals: u64,
}

/// A fixed-step one-step method on TS² (everything except `dop853`).
pub trait FixedStep {
    /// Advances `s` from time `t` \[s\] by `dt` \[s\] (dt may be negative for symmetric methods).
    fn step<M: Model>(&mut self, model: &M, t: f64, s: &mut State, dt: f64) -> Result<()>;
    /// Right-hand-side evaluations per step (for [`Stats::rhs_evals`]).
    fn evals_per_step(&self) -> u64;
    /// Forgets internal state carried between steps (called when the state is replaced).
    fn reset(&mut self) {}
}

/// Takes `n` fixed steps of `dt` \[s\] with `scheme` on the grid t = `t_anchor` + k·dt from step `*k`
/// on, advancing `*k` with every step taken: the one fixed-step loop, which every driver
/// ([`crate::Stepper::step_n`], hence [`crate::Solver`]) runs. A wrapped model (`AnyModel`) chooses
/// its variant once, through [`Model::visit`], so the loop is monomorphised per variant. On a model
/// with breaks ahead ([`Model::next_break`]: a sampled pivot's kinks) each step is
/// [`step_across_breaks`]; `*splits` counts the extra sub-steps that took. Without (a fixed pivot,
/// an analytic path, or past the last break) the loop is the plain one, numbers unchanged.
#[inline(always)]
pub fn fixed_steps<M: Model, S: FixedStep>(
    model: &M,
    scheme: &mut S,
    (t_anchor, dt): (f64, f64),
    n: u64,
    (k, splits): (&mut u64, &mut u64),
    state: &mut State,
) -> Result<()> {
    model.visit(FixedSteps { scheme, t_anchor, dt, n, k, splits, state })
}

/// The loop of [`fixed_steps`] as a [`ModelVisitor`].
struct FixedSteps<'a, S> {
    scheme: &'a mut S,
    t_anchor: f64,
    dt: f64,
    n: u64,
    k: &'a mut u64,
    splits: &'a mut u64,
    state: &'a mut State,
}

impl<S: FixedStep> ModelVisitor for FixedSteps<'_, S> {
    type Output = Result<()>;
    #[inline(always)]
    fn visit<M: Model>(self, model: &M) -> Result<()> {
        // +∞ for every model without breaks at compile time (the default next_break), so their loop
        // is the plain one below
        if model.next_break(self.t_anchor + *self.k as f64 * self.dt) != f64::INFINITY {
            for _ in 0..self.n {
                let t = self.t_anchor + *self.k as f64 * self.dt;
                *self.splits += step_across_breaks(self.scheme, model, t, self.state, self.dt)? - 1;
                *self.k += 1;
            }
            return Ok(());
        }
        for _ in 0..self.n {
            self.scheme.step(model, self.t_anchor + *self.k as f64 * self.dt, self.state, self.dt)?;
            *self.k += 1;
        }
        Ok(())
    }
}

/// One fixed step of `h` > 0 \[s\] from `t` \[s\] on a model with breaks ([`Model::next_break`]): a
/// step that straddles breaks is split into sub-steps ending exactly on each (the break nearest the
/// step's end within round-off is skipped, as `dop853` does: `dop853::step_end`), and every
/// (sub-)step runs on the model's smooth piece between breaks ([`Model::smooth_piece`]), so that
/// stages reaching past a break (the RATTLE compositions') still see one smooth force. A step
/// with no break inside is exactly `h`, as on a smooth model. Returns the number of sub-steps (≥ 1).
pub fn step_across_breaks<M: Model, S: FixedStep>(
    scheme: &mut S,
    model: &M,
    t: f64,
    state: &mut State,
    h: f64,
) -> Result<u64> {
    let t_end = t + h;
    let (mut tau, mut taken) = (t, 0u64);
    loop {
        let end = dop853::step_end(model, tau, t_end);
        let last = end == t_end;
        let step = if last && taken == 0 { h } else { end - tau };
        let piece = model.smooth_piece(tau + 0.5 * step);
        scheme.step(piece.as_ref().unwrap_or(model), tau, state, step)?;
        taken += 1;
        if last {
            return Ok(taken);
        }
        tau = end;
    }
}

/// `S` taking every step as two equal halves, one after the other (`0.5·h` each, from `t` and
/// `t + 0.5·h`): the dt/2 Richardson companion of a run whose steps are not all dt. On a model with
/// breaks ([`step_across_breaks`]) each sub-step of the plain run is halved, so the companion's
/// every step is exactly half of one of the plain run's and the global errors are in the ratio
/// 2ᵖ (a run at dt/2 splits on the breaks elsewhere: its sub-steps next to a break are not halves of
/// the plain run's, and the ratio falls to 1.8 … 7 for p = 2 … 8 with dt = 1.6× the break spacing).
/// [`crate::Stepper::set_halved_steps`] turns it on.
pub struct Halved<'a, S>(pub &'a mut S);

impl<S: FixedStep> FixedStep for Halved<'_, S> {
    #[inline(always)]
    fn step<M: Model>(&mut self, model: &M, t: f64, s: &mut State, dt: f64) -> Result<()> {
        let half = 0.5 * dt;
        self.0.step(model, t, s, half)?;
        self.0.step(model, t + half, s, half)
    }
    fn evals_per_step(&self) -> u64 {
        2 * self.0.evals_per_step()
    }
    fn reset(&mut self) {
        self.0.reset()
    }
}

/// One fixed step of `h` \[s\] from `t` \[s\] with `scheme`; a model with breaks ahead splits it on
/// them ([`step_across_breaks`]). Returns the (sub-)steps taken.
#[inline(always)]
pub(crate) fn one_step<M: Model, S: FixedStep>(
    scheme: &mut S,
    model: &M,
    t: f64,
    state: &mut State,
    h: f64,
) -> Result<u64> {
    if model.next_break(t) != f64::INFINITY {
        model.visit(StepAcrossBreaks { scheme, t, h, state })
    } else {
        scheme.step(model, t, state, h)?;
        Ok(1)
    }
}

/// [`step_across_breaks`] through [`Model::visit`] (a wrapped model's variant chosen once); the
/// single step of [`crate::Stepper::step_towards`].
pub(crate) struct StepAcrossBreaks<'a, S> {
    pub scheme: &'a mut S,
    pub t: f64,
    pub h: f64,
    pub state: &'a mut State,
}

impl<S: FixedStep> ModelVisitor for StepAcrossBreaks<'_, S> {
    type Output = Result<u64>;
    #[inline(always)]
    fn visit<M: Model>(self, model: &M) -> Result<u64> {
        step_across_breaks(self.scheme, model, self.t, self.state, self.h)
    }
}

/// Declared order and structural properties of a method.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct MethodInfo {
    /// Registry name (lower case, as used in Python, TOML and the CLI).
    pub name: &'static str,
    /// Classical order of convergence.
    pub order: u32,
    /// Symplectic on T*S² for conservative models.
    pub symplectic: bool,
    /// Keeps |x| = l and x·v = 0 to round-off.
    pub preserves_ts2: bool,
    /// Keeps J₃ to round-off for axisymmetric models.
    pub preserves_j3: bool,
    /// Chooses its own step size from rtol/atol.
    pub adaptive: bool,
    /// Can interpolate between steps (save at arbitrary times without shortening steps).
    pub dense_output: bool,
    /// One-line description.
    pub summary: &'static str,
}

/// The registry: every integrator Pendulab has.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Method {
    /// Classic RK4 on the Cartesian ODE T-2.4, no projection.
    Rk4,
    /// Dormand–Prince 8(5,3), adaptive, dense output, optional projection onto TS².
    Dop853,
    /// RATTLE (constrained Störmer–Verlet), order 2.
    Rattle,
    /// Triple-jump composition of RATTLE, order 4.
    Rattle4,
    /// Yoshida composition of RATTLE, order 6.
    Rattle6,
    /// Yoshida composition of RATTLE, order 8.
    Rattle8,
    /// Runge–Kutta–Munthe-Kaas of order 4 on S² with the SO(3) exponential.
    Rkmk4,
    /// Classic RK4 in spherical angles (T-2.5), for teaching: fails at the poles.
    Rk4Angles,
}

impl Method {
    /// Every registered method, in display order.
    pub const ALL: [Method; 8] = [
        Method::Rattle,
        Method::Rattle4,
        Method::Rattle6,
        Method::Rattle8,
        Method::Dop853,
        Method::Rkmk4,
        Method::Rk4,
        Method::Rk4Angles,
    ];

    /// The default method: RATTLE.
    pub const DEFAULT: Method = Method::Rattle;

    /// Order and properties.
    pub fn info(self) -> MethodInfo {
        let base = MethodInfo {
            name: "",
            order: 0,
            symplectic: false,
            preserves_ts2: false,
            preserves_j3: false,
            adaptive: false,
            dense_output: false,
            summary: "",
        };
        let geometric = MethodInfo { symplectic: true, preserves_ts2: true, preserves_j3: true, ..base };
        match self {
            Method::Rk4 => MethodInfo {
                name: "rk4",
                order: 4,
                summary: "classic Runge-Kutta 4 on the Cartesian ODE T-2.4, no projection: drifts off TS2 (baseline)",
                ..base
            },
            Method::Dop853 => MethodInfo {
                name: "dop853",
                order: 8,
                adaptive: true,
                dense_output: true,
                summary: "Dormand-Prince 8(5,3), adaptive, dense output of order 7; project=True keeps TS2",
                ..base
            },
            Method::Rattle => MethodInfo {
                name: "rattle",
                order: 2,
                summary: "RATTLE, constrained Stormer-Verlet: symplectic, keeps TS2 and J3 to round-off (default)",
                ..geometric
            },
            Method::Rattle4 => MethodInfo {
                name: "rattle4",
                order: 4,
                summary: "symmetric triple-jump composition of RATTLE (Yoshida 1990, Suzuki 1990)",
                ..geometric
            },
            Method::Rattle6 => MethodInfo {
                name: "rattle6",
                order: 6,
                summary: "symmetric 7-stage composition of RATTLE (Yoshida 1990, solution A)",
                ..geometric
            },
            Method::Rattle8 => MethodInfo {
                name: "rattle8",
                order: 8,
                summary: "symmetric 15-stage composition of RATTLE (Yoshida 1990, solution D)",
                ..geometric
            },
            Method::Rkmk4 => MethodInfo {
                name: "rkmk4",
                order: 4,
                preserves_ts2: true,
                summary: "Runge-Kutta-Munthe-Kaas 4 on S2 with the SO(3) exponential: keeps TS2 exactly",
                ..base
            },
            Method::Rk4Angles => MethodInfo {
                name: "rk4_angles",
                order: 4,
                preserves_ts2: true,
                summary: "classic RK4 in spherical angles (T-2.5): singular at the poles, refuses near them (teaching)",
                ..base
            },
        }
    }

    /// Looks a method up by its registry name.
    pub fn from_name(name: &str) -> Result<Method> {
        Method::ALL.iter().copied().find(|m| m.info().name == name).ok_or_else(|| Error::UnknownMethod {
            name: name.to_string(),
            available: Method::ALL.iter().map(|m| m.info().name).collect::<Vec<_>>().join(", "),
        })
    }
}

/// Order and properties of every registered method.
pub fn all() -> Vec<MethodInfo> {
    Method::ALL.iter().map(|m| m.info()).collect()
}
