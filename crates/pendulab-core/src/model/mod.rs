//! Models: what acts on the bob besides the rod. A model supplies the *applied* acceleration
//! f(t, x, v) (force per unit mass); the rod's constraint force is added here, once, for all
//! models and integrators.
//!
//! Equations (docs/theory.md):
//! - T-2.2 Newton with multiplier: ẍ = f + λx with λ = −(|v|² + x·f)/l², the unique λ that keeps
//!   d²(|x|²)/dt² = 0 on TS². For the ideal pendulum f = −g e₃, so λ = (g z − |v|²)/l².
//! - T-2.4 Hamiltonian form on T*R³ (y = ẋ): ẋ = y, ẏ = f + λ(x, y) x, the same vector field
//!   extended off TS² (TS² is invariant but unstable, so unprojected methods drift away).
//! - T-2.3 Rod tension T = −m λ l = m(|v|² + x·f)/l \[N\], positive when the rod pulls.
//! - T-2.6 Energy E = m(½|v|² + V(x)) \[J\] and vertical angular momentum J₃ = m (x × v)·e₃ [kg m²/s].
//!
//! Models: [`IdealPendulum`] (§2), [`Extended`] (damping, drag, periodic force, any gravity
//! direction, rotating frame; §7), [`MovingPivot`] (T-7.2) and the hybrid [`StringPendulum`] (a
//! string that goes slack where the tension T-2.3 would be negative). The registry of names and parameters is [`registry`].

pub mod any_model;
pub mod extended;
pub mod heights;
pub mod hoist;
pub mod ideal;
pub mod pivot;
pub mod registry;
pub mod slewing_linear;
pub mod spline;
pub mod string;

pub use extended::Extended;
pub use hoist::{Hoisted, RopeLaw};
pub use ideal::IdealPendulum;
pub use pivot::{MovingPivot, PivotPath};
pub use registry::AnyModel;
pub use string::StringPendulum;

use crate::state::{Params, State};
use glam::DVec3;

/// A pendulum model: the rod (length l, mass m) plus applied forces.
pub trait Model: Send + Sync {
    /// Name used in the registry and in files (e.g. `"ideal"`).
    fn name(&self) -> &'static str;
    /// Length, mass and gravity.
    fn params(&self) -> &Params;
    /// Applied acceleration f(t, x, v) [m/s²]: every force per unit mass except the rod's.
    fn applied_acceleration(&self, t: f64, x: DVec3, v: DVec3) -> DVec3;
    /// Potential energy per unit mass V(x) [J/kg] of the conservative part of f.
    fn potential_per_mass(&self, x: DVec3) -> f64;
    /// V(to) − V(from) [J/kg] for two points on the sphere. Models with gravity override this to
    /// measure heights from the nearer pole ([`heights`]), which keeps the digits that V(to) − V(from)
    /// loses near the bottom and the top. Default: the plain difference.
    fn potential_change_per_mass(&self, from: DVec3, to: DVec3) -> f64 {
        self.potential_per_mass(to) - self.potential_per_mass(from)
    }
    /// True when f = −∇V(x) only (no t or v dependence): RATTLE is then symplectic.
    fn is_conservative(&self) -> bool;
    /// True when f commutes with rotations about e₃, so that J₃ is conserved.
    fn is_axisymmetric(&self) -> bool;
    /// True only for the ideal pendulum (the angle form T-2.5 exists only for it).
    fn is_ideal(&self) -> bool {
        false
    }
    /// The part of f that depends on (t, x) only: what RATTLE kicks with. The rest of f, if any,
    /// must be given by [`Model::velocity_flow`]. Default: f(t, x, 0).
    #[inline(always)]
    fn kick_acceleration(&self, t: f64, x: DVec3) -> DVec3 {
        self.applied_acceleration(t, x, DVec3::ZERO)
    }
    /// True when [`Model::kick_acceleration`] does not depend on x (a uniform field, possibly varying
    /// in time: gravity in any direction, a moving pivot, uniform forcing). RATTLE then evaluates the
    /// end-of-step kick before the new position is known (see `integrate::rattle_kernel`); the
    /// results agree with the general path to round-off. Default: false (always correct).
    fn kick_is_uniform(&self) -> bool {
        false
    }
    /// True when f depends on v; then [`Model::velocity_flow`] must be its exact flow.
    fn has_velocity_forces(&self) -> bool {
        false
    }
    /// The exact flow over `h` \[s\] of v̇ = P(x)(f(t, x, v) − kick) at fixed x, taking tangent
    /// vectors to tangent vectors (used by RATTLE's Strang splitting). Default: identity.
    #[inline(always)]
    fn velocity_flow(&self, _x: DVec3, v: DVec3, _h: f64) -> DVec3 {
        v
    }
    /// [`Model::velocity_flow`] with the time `t` \[s\] at which the flow is frozen (RATTLE calls it at
    /// the start and at the end of a step); for models whose velocity forces change with time (the
    /// hoisted rope, [`hoist`]). Default: [`Model::velocity_flow`].
    #[inline(always)]
    fn velocity_flow_at(&self, _t: f64, x: DVec3, v: DVec3, h: f64) -> DVec3 {
        self.velocity_flow(x, v, h)
    }
    /// The rope length l(t) \[m\] at time t \[s\]. Default: the constant `params().length`.
    fn rope_length(&self, _t: f64) -> f64 {
        self.params().length
    }
    /// The rope's rate l̇(t) [m/s] at time t \[s\]. Default: 0 (a constant length).
    fn rope_rate(&self, _t: f64) -> f64 {
        0.0
    }
    /// The acceleration ẍ [m/s²] at a physical state when T-2.2 on the fixed sphere does not apply
    /// (the hoisted rope: ẍ = F + Λx); None for the models on a fixed sphere.
    fn physical_acceleration(&self, _t: f64, _s: &State) -> Option<DVec3> {
        None
    }
    /// The physical state of the integrators' state `s` at time t \[s\] (the hoisted rope integrates
    /// a state scaled onto |x| = l, [`hoist`]). Default: `s` itself.
    #[inline(always)]
    fn to_physical(&self, _t: f64, s: State) -> State {
        s
    }
    /// The integrators' state of the physical state `s` at time t \[s\] (inverse of
    /// [`Model::to_physical`]). Default: `s` itself.
    #[inline(always)]
    fn integrator_state(&self, _t: f64, s: State) -> State {
        s
    }
    /// The rod's or rope's tension \[N\] at a physical state when T-2.3 does not apply (the hoisted
    /// rope); None for the models on a fixed sphere.
    fn physical_tension(&self, _t: f64, _s: &State) -> Option<f64> {
        None
    }
    /// (g/l [1/s²], γ [1/s]) of the angle form T-2.5 at time t with the extra term −γ·(θ̇, φ̇), for the
    /// models that have one (`rk4_angles`): the ideal pendulum (γ = 0), the hoisted rope below a fixed
    /// pivot. Default: None.
    fn angle_form(&self, _t: f64) -> Option<(f64, f64)> {
        None
    }
    /// Refuses a run over [t0, t1] \[s\] the model cannot make (a hoisted rope that would become too
    /// short), before any step. Default: every run.
    fn check_run(&self, _t0: f64, _t1: f64) -> crate::error::Result<()> {
        Ok(())
    }
    /// The first time after `t` \[s\] at which f(t, ·) is not smooth in t — a sampled pivot's sample
    /// times, where the spline's p̈ has a kink — or +∞ (default: none). Every method ends a step
    /// there instead of stepping across (a step across a kink is accurate to a low order only): the
    /// adaptive `dop853` by its step control, the fixed-step methods by splitting the step that
    /// straddles it into sub-steps ending on it (`integrate::fixed_steps`; the outputs stay on the
    /// grid t₀ + k·dt).
    fn next_break(&self, _t: f64) -> f64 {
        f64::INFINITY
    }
    /// For a model with breaks ([`Model::next_break`]): the same model with its f(t, ·) restricted to
    /// the smooth piece between breaks that holds `t` \[s\] and continued past its ends (a sampled
    /// pivot's spline cubic on that sample interval), so that a fixed step between two breaks sees one
    /// smooth force even where its stages reach beyond them (the RATTLE compositions' substeps of
    /// weight > 1 or < 0). Inside the piece the forces are the model's own, bit for bit. Default:
    /// None (f is smooth in t).
    fn smooth_piece(&self, _t: f64) -> Option<Self>
    where
        Self: Sized,
    {
        None
    }
    /// True for hybrid models (the string pendulum: taut and slack phases with events), which the
    /// plain [`crate::Stepper`] refuses; they have their own driver ([`crate::string_run`]).
    fn is_hybrid(&self) -> bool {
        false
    }
    /// Runs `visitor` on the concrete model behind `self` (the visitor pattern): a model that wraps
    /// others (the registry's `AnyModel`) overrides this to hand over its variant, so that a loop
    /// inside the visitor (the fixed-step loop of `integrate::fixed_steps`) is monomorphised per
    /// variant and dispatches once per loop, not once per step. Default: the model itself.
    #[inline(always)]
    fn visit<V: ModelVisitor>(&self, visitor: V) -> V::Output
    where
        Self: Sized,
    {
        visitor.visit(self)
    }
    /// Power per unit mass of the non-conservative forces at (t, x, v) [W/kg]: dE/dt = m·this.
    fn power_per_mass(&self, _t: f64, _x: DVec3, _v: DVec3) -> f64 {
        0.0
    }
}

/// A computation generic over the concrete model type, run by [`Model::visit`] (the hook through
/// which code outside `model/`, such as the step loops of `integrate/`, reaches a wrapped model's
/// variant; `model/` itself names no integrator).
pub trait ModelVisitor {
    /// What the computation returns.
    type Output;
    /// Runs on the concrete model `model`.
    fn visit<M: Model>(self, model: &M) -> Self::Output;
}

/// The rod's multiplier λ [1/s²] of T-2.2 for applied acceleration `f`.
#[inline(always)]
pub fn multiplier(length: f64, x: DVec3, v: DVec3, f: DVec3) -> f64 {
    // times 1/l² rather than divided by l²: the reciprocal is loop-invariant, so a caller's loop
    // (every stage of DOP853, RK4) computes it once instead of dividing on each evaluation
    let inv_l2 = 1.0 / (length * length);
    -(v.length_squared() + x.dot(f)) * inv_l2
}

/// Acceleration ẍ = f + λx of T-2.2 / T-2.4 [m/s²].
#[inline(always)]
pub fn acceleration<M: Model + ?Sized>(model: &M, t: f64, x: DVec3, v: DVec3) -> DVec3 {
    let f = model.applied_acceleration(t, x, v);
    f + x * multiplier(model.params().length, x, v, f)
}

/// Total energy E = m(½|v|² + V(x)) \[J\] (T-2.6).
pub fn energy<M: Model + ?Sized>(model: &M, s: &State) -> f64 {
    model.params().mass * (0.5 * s.v.length_squared() + model.potential_per_mass(s.x))
}

/// Vertical angular momentum J₃ = m (x × v)·e₃ [kg m²/s] (T-2.6).
pub fn j3<M: Model + ?Sized>(model: &M, s: &State) -> f64 {
    model.params().mass * (s.x.x * s.v.y - s.x.y * s.v.x)
}

/// Rod tension T = m(|v|² + x·f)/l \[N\] (T-2.3); T < 0 means the rod pushes (a string would go slack).
pub fn tension<M: Model + ?Sized>(model: &M, t: f64, s: &State) -> f64 {
    if let Some(tension) = model.physical_tension(t, s) {
        return tension;
    }
    let p = model.params();
    let f = model.applied_acceleration(t, s.x, s.v);
    -p.mass * multiplier(p.length, s.x, s.v, f) * p.length
}
