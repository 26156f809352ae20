//! Parameters and the state (x, v) on the tangent bundle TS² of the sphere of radius l.
//!
//! Conventions (docs/theory.md §1): SI units, z axis up, gravity along −z for g > 0. The polar angle θ
//! is measured from the *downward* vertical and the azimuth φ = atan2(y, x) counter-clockwise
//! about +z, so that
//!
//! ```text
//! x = l (sin θ cos φ, sin θ sin φ, −cos θ)
//! v = l (θ̇ cos θ cos φ − φ̇ sin θ sin φ,  θ̇ cos θ sin φ + φ̇ sin θ cos φ,  θ̇ sin θ)
//! ```
//!
//! A state is on TS² when |x| = l and x·v = 0 (T-3.2 on TS², with unit length). Constructors check
//! this within [`TS2_TOLERANCE`] (relative), or project explicitly and report by how much.

use crate::error::{require_finite, Error, Result};
use crate::limits::check_limits;
use glam::DVec3;

/// Relative tolerance of the TS² check: |(|x| − l)/l| and |x·v|/(l·|v|) must not exceed it.
pub const TS2_TOLERANCE: f64 = 1e-9;

/// Physical parameters of the ideal pendulum.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Params {
    /// Rod length l \[m\], l > 0.
    pub length: f64,
    /// Bob mass m \[kg\], m > 0.
    pub mass: f64,
    /// Gravitational acceleration g [m/s²], any finite sign: g > 0 pulls along −z, g < 0 along +z.
    pub g: f64,
}

impl Params {
    /// Validated parameters within the limits of the model registry
    /// ([`crate::limits::COMMON`]: l ∈ [1e-6, 1e4] m, m ∈ [1e-6, 1e6] kg, g ∈ [−1e4, 1e4]
    /// m/s², negative and zero allowed).
    pub fn new(length: f64, mass: f64, g: f64) -> Result<Self> {
        let [l, m, gravity] = [0, 1, 2].map(|i| &crate::limits::COMMON[i]);
        check_limits(l, length)?;
        check_limits(m, mass)?;
        check_limits(gravity, g)?;
        Ok(Self { length, mass, g })
    }

    /// Small-oscillation angular frequency ω₀ = √(|g|/l) [rad/s] (0 for g = 0).
    pub fn omega0(&self) -> f64 {
        (self.g.abs() / self.length).sqrt()
    }
}

/// A point (x, v) of TS²: position x \[m\] of the bob relative to the pivot, velocity v [m/s].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct State {
    /// Position \[m\], |x| = l.
    pub x: DVec3,
    /// Velocity [m/s], x·v = 0.
    pub v: DVec3,
}

/// How far [`State::projected`] moved a state: the norms of the changes in x \[m\] and v [m/s].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Projection {
    /// |x_projected − x| \[m\].
    pub dx: f64,
    /// |v_projected − v| [m/s].
    pub dv: f64,
}

/// Residuals of the constraints: (|x| − l) \[m\] and x·v [m²/s].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ConstraintResiduals {
    /// |x| − l \[m\].
    pub length: f64,
    /// x·v [m²/s].
    pub tangency: f64,
}

/// The bob's speed |v| within the registry's bound ([`crate::limits::STATE`]: 1e7 m/s).
pub fn check_speed(v: DVec3) -> Result<()> {
    check_limits(&crate::limits::STATE[0], v.length()).map(|_| ())
}

fn check_finite(name: &'static str, a: DVec3) -> Result<()> {
    for (index, value) in a.to_array().into_iter().enumerate() {
        if !value.is_finite() {
            return Err(Error::NonFinite { name, index, value });
        }
    }
    Ok(())
}

impl State {
    /// A state from Cartesian position x \[m\] and velocity v [m/s], checked to lie on TS² within
    /// [`TS2_TOLERANCE`] (relative). Errors name the failing residual.
    pub fn on_tangent_bundle(params: &Params, x: DVec3, v: DVec3) -> Result<Self> {
        check_finite("x", x)?;
        check_finite("v", v)?;
        check_speed(v)?;
        let l = params.length;
        let r = (x.length() - l) / l;
        if r.abs() > TS2_TOLERANCE {
            return Err(Error::NotOnTangentBundle {
                what: "(|x| - l)/l",
                value: r,
                tolerance: TS2_TOLERANCE,
            });
        }
        let speed = v.length();
        if speed > 0.0 {
            let c = x.dot(v) / (l * speed);
            if c.abs() > TS2_TOLERANCE {
                return Err(Error::NotOnTangentBundle {
                    what: "x·v/(l·|v|)",
                    value: c,
                    tolerance: TS2_TOLERANCE,
                });
            }
        }
        Ok(Self { x, v })
    }

    /// Moves (x, v) onto TS²: x ← l x/|x|, then v ← v − (x·v/l²) x (the tangential part), and
    /// reports how far each moved. Fails for non-finite input, x = 0, or a result that overflows.
    pub fn projected(params: &Params, x: DVec3, v: DVec3) -> Result<(Self, Projection)> {
        check_finite("x", x)?;
        check_finite("v", v)?;
        // x·x of a tiny x (components ≈ 1e-159) is subnormal and keeps only a few bits, which left
        // |x| − l at 1e-7 l after the projection (found by fuzz_props): x is first scaled by a power
        // of two (exact; the projection depends only on its direction) to a largest component in [1, 2).
        let big = x.abs().max_element();
        let xs = if big > 0.0 && big.is_finite() {
            let k = -(big.log2().floor() as i32); // |k| ≤ 1074: two factors, neither overflows
            x * 2f64.powi(k / 2) * 2f64.powi(k - k / 2)
        } else {
            x
        };
        let s = project_onto_tangent_bundle(params.length, xs, v).ok_or(Error::DegeneratePosition)?;
        let moved = Projection { dx: (s.x - x).length(), dv: (s.v - v).length() };
        if !(s.is_finite() && moved.dx.is_finite() && moved.dv.is_finite()) {
            return Err(Error::InvalidParameter {
                name: "(x, v)",
                value: x.length().max(v.length()),
                allowed: "a position and velocity whose projection onto TS² is finite (docs/limits.md)",
            });
        }
        Ok((s, moved))
    }

    /// The state at polar angle θ \[rad\] from the downward vertical, azimuth φ \[rad\], and their
    /// rates θ̇, φ̇ [rad/s] (see the module doc for the formula). Always on TS².
    pub fn from_angles(params: &Params, theta: f64, phi: f64, theta_dot: f64, phi_dot: f64) -> Result<Self> {
        require_finite("theta", theta, "the polar angle θ must be a finite number of radians")?;
        require_finite("phi", phi, "the azimuth φ must be a finite number of radians")?;
        require_finite("theta_dot", theta_dot, "θ̇ must be a finite number of rad/s")?;
        require_finite("phi_dot", phi_dot, "φ̇ must be a finite number of rad/s")?;
        let l = params.length;
        let (st, ct) = theta.sin_cos();
        let (sp, cp) = phi.sin_cos();
        let x = DVec3::new(l * st * cp, l * st * sp, -l * ct);
        let v = DVec3::new(
            l * (theta_dot * ct * cp - phi_dot * st * sp),
            l * (theta_dot * ct * sp + phi_dot * st * cp),
            l * theta_dot * st,
        );
        check_speed(v)?;
        Ok(Self { x, v })
    }

    /// Polar angle θ ∈ [0, π] from the downward vertical and azimuth φ ∈ (−π, π] \[rad\].
    pub fn angles(&self) -> (f64, f64) {
        let rho = self.x.truncate().length();
        ((rho).atan2(-self.x.z), self.x.y.atan2(self.x.x))
    }

    /// Constraint residuals |x| − l \[m\] and x·v [m²/s] (both 0 on TS²).
    pub fn residuals(&self, length: f64) -> ConstraintResiduals {
        ConstraintResiduals { length: self.x.length() - length, tangency: self.x.dot(self.v) }
    }

    /// True when every component of x and v is finite.
    pub fn is_finite(&self) -> bool {
        self.x.is_finite() && self.v.is_finite()
    }
}

/// The projection onto TS² used by [`State::projected`] and by integrators that project after
/// each step: x ← l x/|x|, v ← v − (x·v/l²) x. `None` when x = 0 or non-finite.
#[inline(always)]
pub fn project_onto_tangent_bundle(length: f64, x: DVec3, v: DVec3) -> Option<State> {
    let r = x.length();
    if !(r > 0.0 && r.is_finite()) {
        return None;
    }
    let x = x * (length / r);
    let v = v - x * (x.dot(v) / (length * length));
    Some(State { x, v })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn angles_round_trip_and_lie_on_ts2() {
        let p = Params::new(2.0, 1.0, 9.81).unwrap();
        let s = State::from_angles(&p, 1.0, 0.3, 0.7, -1.1).unwrap();
        assert!((s.x.length() - 2.0).abs() < 1e-15);
        assert!(s.x.dot(s.v).abs() < 1e-14);
        let (th, ph) = s.angles();
        assert!((th - 1.0).abs() < 1e-15 && (ph - 0.3).abs() < 1e-15);
    }

    #[test]
    fn rejects_states_off_ts2_and_projects_on_request() {
        let p = Params::new(1.0, 1.0, 9.81).unwrap();
        let x = DVec3::new(0.0, 0.0, -1.01);
        let v = DVec3::new(1.0, 0.0, 0.5);
        assert!(matches!(State::on_tangent_bundle(&p, x, v), Err(Error::NotOnTangentBundle { .. })));
        let (s, pr) = State::projected(&p, x, v).unwrap();
        assert!((pr.dx - 0.01).abs() < 1e-15 && (pr.dv - 0.5).abs() < 1e-15);
        assert!(State::on_tangent_bundle(&p, s.x, s.v).is_ok());
    }

    #[test]
    fn rejects_bad_parameters() {
        assert!(Params::new(0.0, 1.0, 9.81).is_err());
        assert!(Params::new(1.0, -1.0, 9.81).is_err());
        assert!(Params::new(1.0, 1.0, f64::NAN).is_err());
        assert!(Params::new(1.0, 1.0, -9.81).is_ok());
    }
}
