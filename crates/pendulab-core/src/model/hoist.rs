//! A hoisted pendulum (docs/theory.md T-11.10): the rope length l(t) changes during the run, the
//! rheonomic constraint |x − P(t)| = l(t) below a pivot path P(t) ([`MovingPivot`]), so that every
//! integrator of the registry (built for the fixed sphere |x| = L) integrates it unchanged.
//!
//! The integrators see the pivot-relative position scaled onto the reference sphere of radius
//! L = l(t₀ = 0) (the model's `length`): u = x / s(t) with s = l(t)/L, |u| = L. From x = s u,
//! ẋ = ṡ u + s u̇, ẍ = s̈ u + 2 ṡ u̇ + s ü and ẍ = F(t, x, ẋ) + Λ x (F: gravity, the pivot's inertial
//! force, damping):
//!
//! ```text
//! ü = F(t, s u, ṡ u + s u̇)/s − 2 (ṡ/s) u̇ − (s̈/s) u + Λ u,     |u| = L, u·u̇ = 0,
//! Λ = (l l̈ + l̇² − |ẋ|² − x·F)/l²   (the same multiplier in both forms),
//! T = −m Λ l                          rope tension [N], with the hoist's m l̈ in it,
//! dE/dt = m(−P̈·ẋ − c|ẋ|²) + m Λ l l̇  (pivot, damping, hoist: P_hoist = −T l̇) [W],
//! ```
//!
//! with E = m(½|ẋ|² + g z) relative to the pivot. Projecting u onto |u| = L at time t is projecting
//! x onto the moving sphere |x| = l(t) (RATTLE's position step), and u·u̇ = 0 is x·ẋ = l l̇ (its
//! velocity step). The term −2(ṡ/s)u̇ (with the damping −c u̇) is RATTLE's velocity flow, exact at
//! the frozen time: u̇ e^{−(2ṡ/s + c)h}. The stepper converts at its boundary: states in and out
//! are physical ([`Hoisted::to_physical`], [`Hoisted::integrator_state`]).
//!
//! The rope length law: l(t) = L + r t + a sin(ν t) (hoist rate r [m/s], amplitude a \[m\],
//! frequency ν [rad/s]; r < 0 hoists up). A run is refused up front when the rope could become
//! shorter than [`MIN_ROPE_FRACTION`]·L ([`Hoisted::check_run`]).

use super::pivot::MovingPivot;
use super::Model;
use crate::error::{Error, Result};
use crate::state::{Params, State};
use glam::DVec3;

/// The shortest rope a run may reach, as a fraction of the reference length L.
pub const MIN_ROPE_FRACTION: f64 = 0.01;

/// The rope length law l(t) = L + r t + a sin(ν t) \[m\].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RopeLaw {
    /// Reference length L = l(0) \[m\].
    pub length: f64,
    /// Hoist rate r [m/s] (negative: the load is hoisted up).
    pub rate: f64,
    /// Amplitude a \[m\] of the periodic part.
    pub amplitude: f64,
    /// Angular frequency ν [rad/s] of the periodic part.
    pub frequency: f64,
}

impl RopeLaw {
    /// (l \[m\], l̇ [m/s], l̈ [m/s²]) at time t \[s\].
    #[inline(always)]
    pub fn eval(&self, t: f64) -> (f64, f64, f64) {
        let (s, c) = (self.frequency * t).sin_cos();
        let a = self.amplitude;
        let nu = self.frequency;
        (self.length + self.rate * t + a * s, self.rate + a * nu * c, -a * nu * nu * s)
    }
    /// A lower bound of l(t) over [t0, t1] \[m\]: L + min(r t0, r t1) − |a|.
    pub fn lower_bound(&self, t0: f64, t1: f64) -> f64 {
        self.length + (self.rate * t0).min(self.rate * t1) - self.amplitude.abs()
    }
}

/// The pendulum on a hoisted rope below a moving pivot (see the module doc).
#[derive(Debug, Clone, PartialEq)]
pub struct Hoisted {
    inner: MovingPivot,
    rope: RopeLaw,
}

impl Hoisted {
    /// `inner` (pivot path, damping, with l = L) on a rope of length law `rope` (rope.length = L).
    pub fn new(inner: MovingPivot, rope: RopeLaw) -> Result<Self> {
        for (name, v) in [("hoist_rate", rope.rate), ("hoist_amplitude", rope.amplitude)] {
            crate::error::require_finite(name, v, "a finite number")?;
        }
        crate::error::require_finite("hoist_frequency", rope.frequency, "a finite number")?;
        if rope.length != inner.params().length {
            return Err(Error::Crane {
                reason: format!(
                    "the rope's reference length {} m differs from the pendulum's length {} m",
                    rope.length,
                    inner.params().length
                ),
            });
        }
        Ok(Self { inner, rope })
    }

    /// The registry's `hoisted` model: below the slewing boom tip `pivot` = (radius \[m\], rate
    /// [rad/s], height \[m\], damping [1/s]) (a fixed pivot for radius or rate 0) on the rope
    /// `hoist` = (rate [m/s], amplitude \[m\], frequency [rad/s]) of the law l + r t + a sin νt.
    pub fn slewing(params: Params, pivot: [f64; 4], hoist: [f64; 3]) -> Result<Self> {
        let [radius, rate, height, damping] = pivot;
        let path = super::pivot::PivotPath::Slewing { radius, rate, height };
        let [r, amplitude, frequency] = hoist;
        let rope = RopeLaw { length: params.length, rate: r, amplitude, frequency };
        Self::new(MovingPivot::new(params, path, damping)?, rope)
    }

    /// The rope length law.
    pub fn rope(&self) -> &RopeLaw {
        &self.rope
    }

    /// The pendulum on the pivot, without the hoist.
    pub fn inner(&self) -> &MovingPivot {
        &self.inner
    }

    /// (s, ṡ, s̈) = (l, l̇, l̈)/L at time t.
    #[inline(always)]
    fn scale(&self, t: f64) -> (f64, f64, f64) {
        let (l, ld, ldd) = self.rope.eval(t);
        let inv = 1.0 / self.rope.length;
        (l * inv, ld * inv, ldd * inv)
    }

    /// The physical state (x on |x| = l(t), ẋ) of the integrators' state (u, u̇) at time t \[s\].
    #[inline]
    pub fn to_physical(&self, t: f64, s: State) -> State {
        let (sc, sd, _) = self.scale(t);
        State { x: s.x * sc, v: s.x * sd + s.v * sc }
    }

    /// The integrators' state (u, u̇) of a physical state at time t \[s\]: the rope's direction x/|x|
    /// and the velocity across the rope; the rope's length and rate come from the law.
    #[inline]
    pub fn integrator_state(&self, t: f64, s: State) -> State {
        let (sc, _, _) = self.scale(t);
        let r = s.x.length();
        let e = s.x / r;
        State { x: e * self.rope.length, v: (s.v - e * e.dot(s.v)) / sc }
    }

    /// Refuses a run over [t0, t1] \[s\] in which the rope could become shorter than
    /// [`MIN_ROPE_FRACTION`]·L.
    pub fn check_run(&self, t0: f64, t1: f64) -> Result<()> {
        let low = self.rope.lower_bound(t0, t1);
        let floor = MIN_ROPE_FRACTION * self.rope.length;
        if low.is_finite() && low >= floor {
            return Ok(());
        }
        let RopeLaw { length, rate, amplitude, frequency } = self.rope;
        Err(Error::Crane {
            reason: format!(
                "the rope l(t) = {length} m + ({rate} m/s) t + ({amplitude} m) sin({frequency} rad/s · t) \
                 may fall to {low} m within [{t0}, {t1}] s; it must stay >= {floor} m ({MIN_ROPE_FRACTION} of l): \
                 hoist more slowly, shorten the run or lengthen the rope"
            ),
        })
    }

    /// The multiplier Λ [1/s²] of the module doc at a physical state.
    #[inline]
    fn physical_multiplier(&self, t: f64, x: DVec3, v: DVec3) -> f64 {
        let (l, ld, ldd) = self.rope.eval(t);
        let f = self.inner.applied_acceleration(t, x, v);
        (l * ldd + ld * ld - v.length_squared() - x.dot(f)) / (l * l)
    }

    /// Rope tension T = −m Λ l \[N\] at a physical state at time t \[s\].
    pub fn tension(&self, t: f64, s: &State) -> f64 {
        -self.inner.params().mass * self.physical_multiplier(t, s.x, s.v) * self.rope.eval(t).0
    }

    /// Power of the hoist on the load per unit mass, Λ l l̇ = −T l̇ / m [W/kg].
    pub fn hoist_power_per_mass(&self, t: f64, x: DVec3, v: DVec3) -> f64 {
        let (l, ld, _) = self.rope.eval(t);
        self.physical_multiplier(t, x, v) * l * ld
    }

    /// (g/l, γ) of the angle form T-2.5 with hoisting, θ̈ = φ̇² sin θ cos θ − (g/l) sin θ − γ θ̇,
    /// φ̈ = −2 θ̇ φ̇ cot θ − γ φ̇, γ = 2 l̇/l + c; only below a fixed pivot.
    pub fn angle_form(&self, t: f64) -> Option<(f64, f64)> {
        if !self.inner.path_is_fixed() {
            return None;
        }
        let (l, ld, _) = self.rope.eval(t);
        Some((self.inner.params().g / l, 2.0 * ld / l + self.inner.damping()))
    }
}

impl Model for Hoisted {
    fn name(&self) -> &'static str {
        "hoisted"
    }
    fn params(&self) -> &Params {
        self.inner.params()
    }
    #[inline(always)]
    fn applied_acceleration(&self, t: f64, u: DVec3, w: DVec3) -> DVec3 {
        let (s, sd, sdd) = self.scale(t);
        let inv = 1.0 / s;
        let f = self.inner.applied_acceleration(t, u * s, u * sd + w * s);
        f * inv - w * (2.0 * sd * inv) - u * (sdd * inv)
    }
    fn potential_per_mass(&self, x: DVec3) -> f64 {
        self.inner.potential_per_mass(x)
    }
    fn is_conservative(&self) -> bool {
        false
    }
    fn is_axisymmetric(&self) -> bool {
        self.inner.is_axisymmetric()
    }
    /// The pivot's uniform field over s; the radial −(s̈/s) u is left out (RATTLE projects radial
    /// forces out: they change only its multipliers).
    #[inline(always)]
    fn kick_acceleration(&self, t: f64, u: DVec3) -> DVec3 {
        let (s, _, _) = self.scale(t);
        self.inner.kick_acceleration(t, u * s) / s
    }
    fn kick_is_uniform(&self) -> bool {
        self.inner.kick_is_uniform()
    }
    fn has_velocity_forces(&self) -> bool {
        true
    }
    #[inline]
    fn velocity_flow_at(&self, t: f64, _x: DVec3, v: DVec3, h: f64) -> DVec3 {
        let (s, sd, _) = self.scale(t);
        v * (-(2.0 * sd / s + self.inner.damping()) * h).exp()
    }
    fn power_per_mass(&self, t: f64, x: DVec3, v: DVec3) -> f64 {
        self.inner.power_per_mass(t, x, v) + self.hoist_power_per_mass(t, x, v)
    }
    fn rope_length(&self, t: f64) -> f64 {
        self.rope.eval(t).0
    }
    fn rope_rate(&self, t: f64) -> f64 {
        self.rope.eval(t).1
    }
    fn physical_acceleration(&self, t: f64, s: &State) -> Option<DVec3> {
        let f = self.inner.applied_acceleration(t, s.x, s.v);
        Some(f + s.x * self.physical_multiplier(t, s.x, s.v))
    }
    fn to_physical(&self, t: f64, s: State) -> State {
        Hoisted::to_physical(self, t, s)
    }
    fn integrator_state(&self, t: f64, s: State) -> State {
        Hoisted::integrator_state(self, t, s)
    }
    fn physical_tension(&self, t: f64, s: &State) -> Option<f64> {
        Some(self.tension(t, s))
    }
    fn angle_form(&self, t: f64) -> Option<(f64, f64)> {
        Hoisted::angle_form(self, t)
    }
    fn check_run(&self, t0: f64, t1: f64) -> Result<()> {
        Hoisted::check_run(self, t0, t1)
    }
    fn next_break(&self, t: f64) -> f64 {
        self.inner.next_break(t)
    }
    fn smooth_piece(&self, t: f64) -> Option<Self> {
        self.inner.smooth_piece(t).map(|inner| Self { inner, rope: self.rope })
    }
}
