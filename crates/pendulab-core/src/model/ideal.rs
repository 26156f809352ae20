//! The ideal spherical pendulum: a point mass m on a massless rigid rod of length l in uniform
//! gravity g along −e₃ (any sign of g, zero included).
//!
//! - Applied acceleration f = −g e₃, potential per unit mass V = g z (T-2.1, T-2.6).
//! - Cartesian equations: T-2.2 / T-2.4 via [`crate::model::acceleration`].
//! - Angle form T-2.5 (θ from the downward vertical, φ the azimuth), from
//!   L = ½ m l²(θ̇² + φ̇² sin²θ) + m g l cos θ:
//!   θ̈ = φ̇² sin θ cos θ − (g/l) sin θ,   φ̈ = −2 θ̇ φ̇ cos θ / sin θ,
//!   singular at the poles sin θ = 0 (used only by the teaching method `rk4_angles`).

use super::Model;
use crate::error::Result;
use crate::state::Params;
use glam::DVec3;

/// The ideal pendulum (docs/theory.md §2).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct IdealPendulum {
    params: Params,
}

impl IdealPendulum {
    /// Validated model: length l > 0 \[m\], mass m > 0 \[kg\], gravity g [m/s²] of any sign.
    pub fn new(length: f64, mass: f64, g: f64) -> Result<Self> {
        Ok(Self { params: Params::new(length, mass, g)? })
    }

    /// Model from already validated parameters.
    pub fn from_params(params: Params) -> Self {
        Self { params }
    }

    /// Right-hand side of the angle equations T-2.5 for y = (θ, φ, θ̇, φ̇) [rad, rad/s]:
    /// returns (θ̇, φ̇, θ̈, φ̈). Not defined at the poles (sin θ = 0).
    #[inline]
    pub fn angle_rhs(&self, y: [f64; 4]) -> [f64; 4] {
        let [theta, _phi, theta_dot, phi_dot] = y;
        let (s, c) = theta.sin_cos();
        let g_over_l = self.params.g / self.params.length;
        [theta_dot, phi_dot, phi_dot * phi_dot * s * c - g_over_l * s, -2.0 * theta_dot * phi_dot * c / s]
    }
}

impl Model for IdealPendulum {
    fn name(&self) -> &'static str {
        "ideal"
    }
    fn params(&self) -> &Params {
        &self.params
    }
    #[inline(always)]
    fn applied_acceleration(&self, _t: f64, _x: DVec3, _v: DVec3) -> DVec3 {
        DVec3::new(0.0, 0.0, -self.params.g)
    }
    #[inline(always)]
    fn potential_per_mass(&self, x: DVec3) -> f64 {
        self.params.g * x.z
    }
    fn potential_change_per_mass(&self, from: DVec3, to: DVec3) -> f64 {
        let g_vec = DVec3::new(0.0, 0.0, -self.params.g);
        super::heights::gravity_potential_change(g_vec, self.params.length, from, to)
    }
    fn is_conservative(&self) -> bool {
        true
    }
    fn is_axisymmetric(&self) -> bool {
        true
    }
    fn is_ideal(&self) -> bool {
        true
    }
    fn angle_form(&self, _t: f64) -> Option<(f64, f64)> {
        Some((self.params().g / self.params().length, 0.0))
    }
    fn kick_is_uniform(&self) -> bool {
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{acceleration, energy, j3, tension};
    use crate::state::State;

    #[test]
    fn tension_at_rest_at_the_bottom_is_weight() {
        // T-2.3: T = m g at rest at the bottom.
        let m = IdealPendulum::new(1.5, 2.0, 9.81).unwrap();
        let s = State { x: DVec3::new(0.0, 0.0, -1.5), v: DVec3::ZERO };
        assert!((tension(&m, 0.0, &s) - 2.0 * 9.81).abs() < 1e-12);
        // zero up to the rounding of g + λz with |g| = |λ z| = 9.81 m/s²
        assert!(acceleration(&m, 0.0, s.x, s.v).length() <= 4.0 * f64::EPSILON * 9.81);
        assert!((energy(&m, &s) + 2.0 * 9.81 * 1.5).abs() < 1e-12);
    }

    #[test]
    fn cartesian_and_angle_forms_agree() {
        // T-2.2 projected on the angle directions must equal T-2.5.
        let m = IdealPendulum::new(1.3, 1.0, 9.81).unwrap();
        let (th, ph, thd, phd) = (0.9, 0.4, 0.3, 1.7);
        let s = State::from_angles(m.params(), th, ph, thd, phd).unwrap();
        let a = acceleration(&m, 0.0, s.x, s.v);
        let [_, _, thdd, phdd] = m.angle_rhs([th, ph, thd, phd]);
        // Differentiate x(θ, φ) twice numerically along the angle solution.
        let h = 1e-5;
        let at = |dt: f64| {
            let th2 = th + thd * dt + 0.5 * thdd * dt * dt;
            let ph2 = ph + phd * dt + 0.5 * phdd * dt * dt;
            State::from_angles(m.params(), th2, ph2, 0.0, 0.0).unwrap().x
        };
        let a_num = (at(h) - 2.0 * at(0.0) + at(-h)) / (h * h);
        assert!((a - a_num).length() < 1e-4, "{a} vs {a_num}");
        assert!((j3(&m, &s) - 1.3 * 1.3 * phd * th.sin().powi(2)).abs() < 1e-12);
    }
}
