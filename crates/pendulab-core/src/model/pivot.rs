//! A pendulum whose pivot moves on a prescribed path p(t) (docs/theory.md T-7.2). With the bob at
//! r = p(t) + x and |x| = l, the pivot-relative position x obeys
//!
//!   ẍ = −g e₃ − p̈(t) + λ x  (− c ẋ with optional damping, force −m c ẋ relative to the pivot),
//!
//! i.e. the ideal pendulum plus the uniform, time-dependent inertial force −m p̈(t) of the pivot's
//! (non-rotating) frame. So the state stays (x, v) on TS² and every integrator applies unchanged;
//! the inertial force is position-independent and goes into RATTLE's kicks. Built-in paths:
//!
//! - slewing crane (Perig et al. 2014): p(t) = (R cos ωt, R sin ωt, h), p̈ = −ω² (p − h e₃);
//!   linearised in the boom frame (x radial, y tangential, ω₀² = g/l): ẍ − 2ωẏ + (ω₀² − ω²)x = ω²R,
//!   ÿ + 2ωẋ + (ω₀² − ω²)y = 0, static offset ω²R/(ω₀² − ω²), natural frequencies ω₀ ± ω;
//! - vertical vibration (Kapitza): p(t) = (0, 0, A cos νt), p̈ = −Aν² cos νt e₃; the inverted
//!   pendulum is stable for (Aν)² > 2 g l (to leading order in 1/ν);
//! - any path given as samples (t_i, p_i): ṗ and p̈ from the C² cubic spline through them
//!   ([`super::spline`]; model `sampled_pivot`).
//!
//! Energy per unit mass relative to the pivot, ½|v|² + g z, changes at the rate −p̈·v (minus c|v|²).
//! Units: R, h, A in m; ω, ν in rad/s; c in 1/s; t in s.

use super::spline::PivotSamples;
use super::Model;
use crate::error::{Error, Result};
use crate::state::Params;
use glam::DVec3;
use std::sync::Arc;

/// A prescribed pivot path.
#[derive(Debug, Clone, PartialEq)]
pub enum PivotPath {
    /// p(t) = (R cos ωt, R sin ωt, h).
    Slewing {
        /// Boom radius R \[m\].
        radius: f64,
        /// Slewing rate ω [rad/s].
        rate: f64,
        /// Pivot height h \[m\].
        height: f64,
    },
    /// p(t) = (0, 0, A cos νt).
    Vertical {
        /// Amplitude A \[m\].
        amplitude: f64,
        /// Angular frequency ν [rad/s].
        frequency: f64,
    },
    /// Through samples (t_i, p_i): the C² not-a-knot cubic spline ([`PivotSamples`]).
    Samples(Arc<PivotSamples>),
}

impl PivotPath {
    /// Pivot position p(t) \[m\].
    pub fn position(&self, t: f64) -> DVec3 {
        match *self {
            PivotPath::Slewing { radius, rate, height } => {
                let (s, c) = (rate * t).sin_cos();
                DVec3::new(radius * c, radius * s, height)
            }
            PivotPath::Vertical { amplitude, frequency } => {
                DVec3::new(0.0, 0.0, amplitude * (frequency * t).cos())
            }
            PivotPath::Samples(ref s) => s.position(t),
        }
    }
    /// The slewing crane's boom frame: `x` (pivot-relative \[m\]) at time t \[s\] rotated by −ωt about e₃,
    /// i.e. (radial, tangential, vertical) components with respect to the boom; `None` for other paths.
    pub fn boom_frame(&self, t: f64, x: DVec3) -> Option<DVec3> {
        match *self {
            PivotPath::Slewing { rate, .. } => {
                let (s, c) = (rate * t).sin_cos();
                Some(DVec3::new(x.x * c + x.y * s, -x.x * s + x.y * c, x.z))
            }
            _ => None,
        }
    }
    /// Pivot velocity ṗ(t) [m/s].
    pub fn velocity(&self, t: f64) -> DVec3 {
        match *self {
            PivotPath::Slewing { radius, rate, .. } => {
                let (s, c) = (rate * t).sin_cos();
                DVec3::new(-radius * rate * s, radius * rate * c, 0.0)
            }
            PivotPath::Vertical { amplitude, frequency } => {
                DVec3::new(0.0, 0.0, -amplitude * frequency * (frequency * t).sin())
            }
            PivotPath::Samples(ref s) => s.velocity(t),
        }
    }
    /// Pivot acceleration p̈(t) [m/s²].
    pub fn acceleration(&self, t: f64) -> DVec3 {
        match *self {
            PivotPath::Slewing { radius, rate, .. } => {
                let (s, c) = (rate * t).sin_cos();
                DVec3::new(-radius * rate * rate * c, -radius * rate * rate * s, 0.0)
            }
            PivotPath::Vertical { amplitude, frequency } => {
                DVec3::new(0.0, 0.0, -amplitude * frequency * frequency * (frequency * t).cos())
            }
            PivotPath::Samples(ref s) => s.acceleration(t),
        }
    }
}

/// The pendulum on a moving pivot (see the module doc).
#[derive(Debug, Clone, PartialEq)]
pub struct MovingPivot {
    params: Params,
    path: PivotPath,
    damping: f64,
    name: &'static str,
    /// `Some(i)`: a sampled path's p̈ is piece i's, continued past its ends ([`Model::smooth_piece`]).
    piece: Option<usize>,
}

impl MovingPivot {
    /// A pendulum on `path` with linear damping c ≥ 0 [1/s] relative to the pivot.
    pub fn new(params: Params, path: PivotPath, damping: f64) -> Result<Self> {
        let finite = |name: &'static str, v: f64| crate::error::require_finite(name, v, "a finite number");
        let name = match &path {
            PivotPath::Slewing { radius, rate, height } => {
                finite("radius", *radius)?;
                finite("rate", *rate)?;
                finite("height", *height)?;
                "slewing"
            }
            PivotPath::Vertical { amplitude, frequency } => {
                finite("amplitude", *amplitude)?;
                finite("frequency", *frequency)?;
                "vibrating"
            }
            PivotPath::Samples(_) => "sampled_pivot",
        };
        if !(damping >= 0.0 && damping.is_finite()) {
            return Err(Error::InvalidParameter {
                name: "damping",
                value: damping,
                allowed: "a finite number >= 0 1/s",
            });
        }
        Ok(Self { params, path, damping, name, piece: None })
    }

    /// The pivot path.
    pub fn path(&self) -> &PivotPath {
        &self.path
    }

    /// p̈(t) [m/s²] of the path, or of the spline piece the model is restricted to
    /// ([`Model::smooth_piece`]).
    #[inline(always)]
    fn pivot_acceleration(&self, t: f64) -> DVec3 {
        match (&self.path, self.piece) {
            (PivotPath::Samples(s), Some(i)) => s.acceleration_on_piece(t, i),
            (path, _) => path.acceleration(t),
        }
    }

    /// Linear damping c [1/s] relative to the pivot.
    pub fn damping(&self) -> f64 {
        self.damping
    }

    /// True when the pivot does not move (a slewing path of radius 0 or rate 0, a vibration of
    /// amplitude 0 or frequency 0).
    pub fn path_is_fixed(&self) -> bool {
        match self.path {
            PivotPath::Slewing { radius, rate, .. } => radius == 0.0 || rate == 0.0,
            PivotPath::Vertical { amplitude, frequency } => amplitude == 0.0 || frequency == 0.0,
            PivotPath::Samples(_) => false,
        }
    }
}

impl Model for MovingPivot {
    fn name(&self) -> &'static str {
        self.name
    }
    fn params(&self) -> &Params {
        &self.params
    }
    #[inline(always)]
    fn applied_acceleration(&self, t: f64, _x: DVec3, v: DVec3) -> DVec3 {
        self.kick_acceleration(t, DVec3::ZERO) - v * self.damping
    }
    fn potential_per_mass(&self, x: DVec3) -> f64 {
        self.params.g * x.z
    }
    fn is_conservative(&self) -> bool {
        false
    }
    fn is_axisymmetric(&self) -> bool {
        matches!(self.path, PivotPath::Vertical { .. })
    }
    #[inline(always)]
    fn kick_acceleration(&self, t: f64, _x: DVec3) -> DVec3 {
        DVec3::new(0.0, 0.0, -self.params.g) - self.pivot_acceleration(t)
    }
    fn kick_is_uniform(&self) -> bool {
        true
    }
    fn has_velocity_forces(&self) -> bool {
        self.damping != 0.0
    }
    #[inline]
    fn velocity_flow(&self, _x: DVec3, v: DVec3, h: f64) -> DVec3 {
        v * (-self.damping * h).exp()
    }
    fn power_per_mass(&self, t: f64, _x: DVec3, v: DVec3) -> f64 {
        -self.pivot_acceleration(t).dot(v) - self.damping * v.length_squared()
    }
    fn next_break(&self, t: f64) -> f64 {
        match self.path {
            PivotPath::Samples(ref s) => s.next_kink_after(t),
            _ => f64::INFINITY,
        }
    }
    fn smooth_piece(&self, t: f64) -> Option<Self> {
        match self.path {
            PivotPath::Samples(ref s) => Some(Self { piece: Some(s.piece_at(t)), ..self.clone() }),
            _ => None,
        }
    }
}
