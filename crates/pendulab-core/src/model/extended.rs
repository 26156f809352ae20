//! The real pendulum on a rigid rod (docs/theory.md §7, T-7.1 and T-7.3, and any gravity): the ideal
//! pendulum plus, each switched on by a non-zero parameter,
//!
//! - gravity g along any unit direction d (default d = −e₃): f_g = g d, potential −g d·x;
//! - linear viscous damping (force −m c v, c in 1/s) and quadratic drag (−m c_q |v| v, c_q in 1/m);
//! - dry (Coulomb) pivot friction (T-7.6): a torque of constant size τ_f = m l² ε_f against the rod's
//!   angular velocity ω = x×v/l², i.e. the force −m ε_f l tanh(|ω|/ω_ε) v/|v| on the bob (ε_f in
//!   rad/s², |ω| = |v|/l on TS²), the sign function regularised by tanh with the speed ω_ε [rad/s];
//! - a periodic force per unit mass A cos(ω_f t + ψ) e (A in m/s², ω_f in rad/s, e a unit vector);
//! - a rotating frame with angular velocity Ω [rad/s] (Foucault, T-7.3): Coriolis −2Ω×v and
//!   centrifugal −Ω×(Ω×x) about the pivot, with potential −½|Ω×x|². For the Earth at latitude λ
//!   in local (east, north, up) axes, Ω = |Ω|(0, cos λ, sin λ), |Ω| = 7.292e-5 rad/s.
//!
//! Only the tangential part of these forces acts (the rod takes the rest, T-2.2). The energy
//! E = m(½|v|² − g d·x − ½|Ω×x|²) obeys the power balance dE/dt = m(A cos(ω_f t + ψ) e·v − c|v|²
//! − c_q|v|³ − ε_f l |v| tanh(|v|/(l ω_ε))) (T-7.1, T-7.6): Coriolis does no work.
//!
//! **Structure-preserving splitting.** The velocity-dependent forces have an exact flow at fixed x
//! that keeps v tangent: with n = x/|x| and s = |v|,
//!   - Coriolis, tangential part −2(Ω·n) n×v: a rotation of v about n by the angle −2(Ω·n)h;
//!   - damping and drag together, v̇ = −(c + c_q|v|) v: the direction is kept and
//!     s(h) = s e^{−ch} / (1 + c_q s (1 − e^{−ch})/c)   (→ s/(1 + c_q s h) as c → 0).
//!
//!   - dry friction, ṡ = −ε_f l tanh(s/s_ε) with s_ε = l ω_ε: exactly
//!     sinh(s(h)/s_ε) = sinh(s/s_ε) e^{−ε_f h/ω_ε} (T-7.6), taken in the symmetric order
//!     friction(h/2) ∘ damping-and-drag(h) ∘ friction(h/2) (the two speed maps do not commute; the
//!     composition is symmetric and of order 2, which is all RATTLE's splitting needs).
//!
//! The rotation commutes with the speed maps. RATTLE then runs as the Strang splitting flow(h/2) ∘ RATTLE(h) ∘ flow(h/2), with
//! the position- and time-dependent forces in RATTLE's kicks: second order, and for linear damping
//! conformal symplectic (the symplectic form contracts by exactly e^{−ch} per step).

use super::Model;
use crate::error::{require_non_negative, Error, Result};
use crate::state::Params;
use glam::DVec3;

/// The default regularisation speed ω_ε of dry friction [rad/s] (T-7.6): 1e-3 rad/s, well below the
/// angular speeds of a swing that can be seen (0.1° amplitude at ω₀ = 3 rad/s is 5e-3 rad/s).
pub const DEFAULT_FRICTION_SPEED: f64 = 1e-3;

/// asinh(sinh(u) e^{−k}) for u ≥ 0, k ≥ 0 without overflow (the dimensionless speed after the
/// friction flow of T-7.6): for large u, in logarithms, ln sinh u = u + ln(1 − e^{−2u}) − ln 2.
#[inline]
pub fn sinh_decay(u: f64, k: f64) -> f64 {
    if u < 20.0 {
        return (u.sinh() * (-k).exp()).asinh();
    }
    let ln_y = u + (-(-2.0 * u).exp()).ln_1p() - std::f64::consts::LN_2 - k;
    if ln_y > 20.0 {
        // asinh y = ln y + ln 2 + ln((1 + √(1 + y⁻²))/2), the last term < 1e-18 here
        ln_y + std::f64::consts::LN_2
    } else {
        ln_y.exp().asinh()
    }
}

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
    /// Dry pivot friction ε_f = τ_f/(m l²) [rad/s²], ≥ 0 (T-7.6).
    friction: f64,
    /// Regularisation speed ω_ε [rad/s] > 0 of the friction's sign function (T-7.6).
    friction_speed: f64,
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
            friction: 0.0,
            friction_speed: DEFAULT_FRICTION_SPEED,
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

    /// Dry (Coulomb) pivot friction ε_f ≥ 0 [rad/s²] (the friction torque over m l²) with the
    /// regularisation speed ω_ε > 0 [rad/s] (T-7.6).
    pub fn with_friction(mut self, friction: f64, friction_speed: f64) -> Result<Self> {
        self.friction = require_non_negative(
            "friction",
            friction,
            "the dry friction ε_f must be a finite number >= 0 rad/s²",
        )?;
        if !(friction_speed.is_finite() && friction_speed > 0.0) {
            return Err(Error::InvalidParameter {
                name: "friction_speed",
                value: friction_speed,
                allowed: "the friction's regularisation speed ω_ε must be a finite number > 0 rad/s",
            });
        }
        self.friction_speed = friction_speed;
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
    /// Quadratic drag coefficient c_q [1/m].
    pub fn drag(&self) -> f64 {
        self.drag
    }
    /// Dry pivot friction ε_f [rad/s²] and its regularisation speed ω_ε [rad/s] (T-7.6).
    pub fn friction(&self) -> (f64, f64) {
        (self.friction, self.friction_speed)
    }
    /// Frame angular velocity Ω [rad/s].
    pub fn frame(&self) -> DVec3 {
        self.frame
    }
    /// Unit direction of gravity.
    pub fn gravity_direction(&self) -> DVec3 {
        self.gravity_direction
    }

    /// The friction's acceleration per unit velocity at speed s [1/s]: ε_f l tanh(s/s_ε)/s with
    /// s_ε = l ω_ε (→ ε_f/ω_ε as s → 0), so that the force per mass is −this·v (T-7.6).
    #[inline(always)]
    fn friction_factor(&self, speed: f64) -> f64 {
        let l = self.params.length;
        let s_eps = l * self.friction_speed;
        if speed > 0.0 {
            self.friction * l * (speed / s_eps).tanh() / speed
        } else {
            self.friction / self.friction_speed
        }
    }

    /// The exact flow over `h` [s] of the friction alone, v̇ = −ε_f l tanh(|v|/s_ε) v/|v|: the direction
    /// is kept and sinh(s(h)/s_ε) = sinh(s/s_ε) e^{−ε_f h/ω_ε} (T-7.6).
    #[inline]
    fn friction_flow(&self, v: DVec3, h: f64) -> DVec3 {
        let speed = v.length();
        if speed == 0.0 {
            return v;
        }
        let s_eps = self.params.length * self.friction_speed;
        let u = speed / s_eps;
        let k = self.friction * h / self.friction_speed;
        v * (sinh_decay(u, k) / u)
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
        let f = if self.friction != 0.0 { f - v * self.friction_factor(v.length()) } else { f };
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
        self.damping == 0.0 && self.drag == 0.0 && self.friction == 0.0 && self.forcing.is_none()
    }
    fn is_axisymmetric(&self) -> bool {
        let vertical = |d: DVec3| d.x == 0.0 && d.y == 0.0;
        (self.params.g == 0.0 || vertical(self.gravity_direction))
            && self.forcing.as_ref().is_none_or(|f| vertical(f.direction))
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
        self.damping != 0.0 || self.drag != 0.0 || self.friction != 0.0 || self.frame != DVec3::ZERO
    }
    #[inline]
    fn velocity_flow(&self, x: DVec3, v: DVec3, h: f64) -> DVec3 {
        let mut v = v;
        if self.frame != DVec3::ZERO {
            let n = x / x.length();
            let (s, c) = (-2.0 * self.frame.dot(n) * h).sin_cos();
            v = v * c + n.cross(v) * s;
        }
        if self.friction != 0.0 {
            v = self.friction_flow(v, 0.5 * h);
        }
        if self.damping != 0.0 || self.drag != 0.0 {
            let speed = v.length();
            let decay = (-self.damping * h).exp();
            // (1 − e^{−ch})/c, → h as c → 0
            let span = if self.damping == 0.0 { h } else { -(-self.damping * h).exp_m1() / self.damping };
            v *= decay / (1.0 + self.drag * speed * span);
        }
        if self.friction != 0.0 {
            v = self.friction_flow(v, 0.5 * h);
        }
        v
    }
    fn power_per_mass(&self, t: f64, _x: DVec3, v: DVec3) -> f64 {
        let forced =
            self.forcing.map_or(0.0, |f| f.amplitude * (f.omega * t + f.phase).cos() * f.direction.dot(v));
        let s2 = v.length_squared();
        let friction = if self.friction != 0.0 { self.friction_factor(s2.sqrt()) * s2 } else { 0.0 };
        forced - self.damping * s2 - self.drag * s2 * s2.sqrt() - friction
    }
}
