//! The real pendulum on a rigid rod (docs/theory.md §7, T-7.1 and T-7.3, and any gravity): the ideal
//! pendulum plus, each switched on by a non-zero parameter,
//!
//! - gravity g along any unit direction d (default d = −e₃): f_g = g d, potential −g d·x;
//! - linear viscous damping (force −m c v, c in 1/s) and quadratic drag (−m c_q |v| v, c_q in 1/m);
//! - a periodic force per unit mass A cos(ω_f t + ψ) e (A in m/s², ω_f in rad/s, e a unit vector);
//! - a rotating frame with angular velocity Ω [rad/s] (Foucault, T-7.3): Coriolis −2Ω×v and
//!   centrifugal −Ω×(Ω×x) about the pivot, with potential −½|Ω×x|². For the Earth at latitude λ
//!   in local (east, north, up) axes, Ω = |Ω|(0, cos λ, sin λ), |Ω| = 7.292e-5 rad/s.
//!
//! Only the tangential part of these forces acts (the rod takes the rest, T-2.2). The energy
//! E = m(½|v|² − g d·x − ½|Ω×x|²) obeys the power balance dE/dt = m(A cos(ω_f t + ψ) e·v − c|v|²
//! − c_q|v|³) (T-7.1): Coriolis does no work.
//!
//! **Structure-preserving splitting.** The velocity-dependent forces have an exact flow at fixed x
//! that keeps v tangent: with n = x/|x| and s = |v|,
//!   - Coriolis, tangential part −2(Ω·n) n×v: a rotation of v about n by the angle −2(Ω·n)h;
//!   - damping and drag together, v̇ = −(c + c_q|v|) v: the direction is kept and
//!     s(h) = s e^{−ch} / (1 + c_q s (1 − e^{−ch})/c)   (→ s/(1 + c_q s h) as c → 0).
//!
//! The two commute. RATTLE then runs as the Strang splitting flow(h/2) ∘ RATTLE(h) ∘ flow(h/2), with
//! the position- and time-dependent forces in RATTLE's kicks: second order, and for linear damping
//! conformal symplectic (the symplectic form contracts by exactly e^{−ch} per step).

use super::Model;
use crate::error::{require_non_negative, Error, Result};
use crate::state::Params;
use glam::DVec3;

/// A periodic force per unit mass A cos(ω t + ψ) e.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Forcing {
    /// Amplitude A [m/s²] (force per unit mass).
    pub amplitude: f64,
    /// Angular frequency ω [rad/s].
    pub omega: f64,
    /// Phase ψ \[rad\].
    pub phase: f64,
    /// Direction e (unit vector).
    pub direction: DVec3,
}

/// The extended pendulum (see the module doc). [`Extended::ideal`] gives the ideal pendulum.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Extended {
    params: Params,
    /// Unit direction d of gravity (g d is the gravitational acceleration).
    gravity_direction: DVec3,
    /// Linear damping rate c [1/s], ≥ 0.
    damping: f64,
    /// Quadratic drag coefficient c_q [1/m], ≥ 0.
    drag: f64,
    forcing: Option<Forcing>,
    /// Frame angular velocity Ω [rad/s].
    frame: DVec3,
}

fn unit(name: &'static str, d: DVec3) -> Result<DVec3> {
    let n = d.length();
    if n.is_finite() && n > 0.0 {
        Ok(d / n)
    } else {
        Err(Error::InvalidParameter {
            name,
            value: n,
            allowed: "a direction: finite components, not all zero (only the direction counts; the length, \
                      printed here, is ignored)",
        })
    }
}

impl Extended {
    /// The ideal pendulum with these parameters (gravity along −e₃, nothing else).
    pub fn ideal(params: Params) -> Self {
        Self {
            params,
            gravity_direction: DVec3::NEG_Z,
            damping: 0.0,
            drag: 0.0,
            forcing: None,
            frame: DVec3::ZERO,
        }
    }

    /// Gravity along the unit direction `d` (normalised here; g from the parameters, any sign).
    pub fn with_gravity_direction(mut self, d: DVec3) -> Result<Self> {
        self.gravity_direction = unit("gravity_x/y/z (the gravity direction)", d)?;
        Ok(self)
    }

    /// Linear damping c ≥ 0 [1/s] and quadratic drag c_q ≥ 0 [1/m].
    pub fn with_damping(mut self, damping: f64, drag: f64) -> Result<Self> {
        self.damping =
            require_non_negative("damping", damping, "the damping rate c must be a finite number >= 0 1/s")?;
        self.drag =
            require_non_negative("drag", drag, "the quadratic drag c_q must be a finite number >= 0 1/m")?;
        Ok(self)
    }

    /// A periodic force A cos(ω t + ψ) e per unit mass (A ≥ 0 in m/s², ω in rad/s, ψ in rad).
    pub fn with_forcing(mut self, amplitude: f64, omega: f64, phase: f64, direction: DVec3) -> Result<Self> {
        let amplitude = require_non_negative("forcing_amplitude", amplitude, "a finite amplitude >= 0 m/s²")?;
        crate::error::require_finite("forcing_omega", omega, "a finite angular frequency in rad/s")?;
        crate::error::require_finite("forcing_phase", phase, "a finite phase in rad")?;
        let direction = unit("forcing_x/y/z (the forcing direction)", direction)?;
        self.forcing = (amplitude > 0.0).then_some(Forcing { amplitude, omega, phase, direction });
        Ok(self)
    }

    /// A frame rotating with angular velocity Ω [rad/s] (finite components).
    pub fn with_frame(mut self, omega: DVec3) -> Result<Self> {
        if !omega.is_finite() {
            return Err(Error::InvalidParameter {
                name: "frame_rate",
                value: omega.length(),
                allowed: "a finite angular velocity in rad/s",
            });
        }
        self.frame = omega;
        Ok(self)
    }

    /// The Earth-like frame: rate |Ω| [rad/s] at latitude λ \[rad\], axes (east, north, up).
    pub fn with_latitude_frame(self, rate: f64, latitude: f64) -> Result<Self> {
        crate::error::require_finite("frame_rate", rate, "a finite rate in rad/s")?;
        if latitude.is_nan() || latitude.abs() > std::f64::consts::FRAC_PI_2 {
            return Err(Error::InvalidParameter {
                name: "latitude",
                value: latitude,
                allowed: "a latitude in [-π/2, π/2] rad ([-90°, 90°])",
            });
        }
        self.with_frame(DVec3::new(0.0, latitude.cos(), latitude.sin()) * rate)
    }

    /// Linear damping rate c [1/s].
    pub fn damping(&self) -> f64 {
        self.damping
    }
    /// Frame angular velocity Ω [rad/s].
    pub fn frame(&self) -> DVec3 {
        self.frame
    }
    /// Unit direction of gravity.
    pub fn gravity_direction(&self) -> DVec3 {
        self.gravity_direction
    }

    #[inline(always)]
    fn position_acceleration(&self, t: f64, x: DVec3) -> DVec3 {
        let mut f = self.gravity_direction * self.params.g;
        if let Some(fo) = &self.forcing {
            f += fo.direction * (fo.amplitude * (fo.omega * t + fo.phase).cos());
        }
        if self.frame != DVec3::ZERO {
            f -= self.frame.cross(self.frame.cross(x));
        }
        f
    }
}

impl Model for Extended {
    fn name(&self) -> &'static str {
        "extended"
    }
    fn params(&self) -> &Params {
        &self.params
    }
    #[inline(always)]
    fn applied_acceleration(&self, t: f64, x: DVec3, v: DVec3) -> DVec3 {
        let f = self.position_acceleration(t, x) - v * (self.damping + self.drag * v.length());
        f - self.frame.cross(v) * 2.0
    }
    fn potential_per_mass(&self, x: DVec3) -> f64 {
        -self.params.g * self.gravity_direction.dot(x) - 0.5 * self.frame.cross(x).length_squared()
    }
    fn potential_change_per_mass(&self, from: DVec3, to: DVec3) -> f64 {
        let g_vec = self.gravity_direction * self.params.g;
        let centrifugal =
            0.5 * (self.frame.cross(from).length_squared() - self.frame.cross(to).length_squared());
        super::heights::gravity_potential_change(g_vec, self.params.length, from, to) + centrifugal
    }
    fn is_conservative(&self) -> bool {
        self.damping == 0.0 && self.drag == 0.0 && self.forcing.is_none()
    }
    fn is_axisymmetric(&self) -> bool {
        let vertical = |d: DVec3| d.x == 0.0 && d.y == 0.0;
        (self.params.g == 0.0 || vertical(self.gravity_direction))
            && self.forcing.as_ref().map_or(true, |f| vertical(f.direction))
            && vertical(self.frame)
    }
    #[inline(always)]
    fn kick_acceleration(&self, t: f64, x: DVec3) -> DVec3 {
        self.position_acceleration(t, x)
    }
    fn kick_is_uniform(&self) -> bool {
        // gravity and forcing are uniform; only the centrifugal force depends on x
        self.frame == DVec3::ZERO
    }
    fn has_velocity_forces(&self) -> bool {
        self.damping != 0.0 || self.drag != 0.0 || self.frame != DVec3::ZERO
    }
    #[inline]
    fn velocity_flow(&self, x: DVec3, v: DVec3, h: f64) -> DVec3 {
        let mut v = v;
        if self.frame != DVec3::ZERO {
            let n = x / x.length();
            let (s, c) = (-2.0 * self.frame.dot(n) * h).sin_cos();
            v = v * c + n.cross(v) * s;
        }
        if self.damping != 0.0 || self.drag != 0.0 {
            let speed = v.length();
            let decay = (-self.damping * h).exp();
            // (1 − e^{−ch})/c, → h as c → 0
            let span = if self.damping == 0.0 { h } else { -(-self.damping * h).exp_m1() / self.damping };
            v *= decay / (1.0 + self.drag * speed * span);
        }
        v
    }
    fn power_per_mass(&self, t: f64, _x: DVec3, v: DVec3) -> f64 {
        let forced =
            self.forcing.map_or(0.0, |f| f.amplitude * (f.omega * t + f.phase).cos() * f.direction.dot(v));
        let s2 = v.length_squared();
        forced - self.damping * s2 - self.drag * s2 * s2.sqrt()
    }
}
