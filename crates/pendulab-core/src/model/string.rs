//! The pendulum on a string (rope) instead of a rod: the ideal pendulum (docs/theory.md §2) while the
//! string is taut, a free projectile while it is slack, and an impulsive jerk when it snaps taut.
//! SI units: l \[m\], m \[kg\], g [m/s²], t \[s\], x \[m\], v [m/s], T \[N\], E \[J\].
//!
//! - **Taut** (|x| = l, T ≥ 0): the constrained equations T-2.2, integrated by a method that keeps
//!   TS² (the RATTLE family or RKMK4). The string can only pull: its tension is the rod's (T-2.3),
//!   T = m(|v|² − g z)/l, which with the energy E = m(½|v|² + g z) (T-2.6) is
//!   T = (m/l)(2E/m − 3 g z): it depends on the height only and vanishes at z* = 2E/(3 m g).
//! - **Leave** where T would turn negative: the step in which T changes sign is shortened to the
//!   step length h* with T = 0, found by bisection on h to round-off (the step map is smooth in h).
//! - **Slack**: free flight under gravity, exact and analytic — the parabola
//!   x(τ) = x_e + v_e τ − ½ g τ² e₃, v(τ) = v_e − g τ e₃ (τ = t − t_e).
//! - **Re-taut** at the first τ > 0 with q(τ) = |x(τ)|² − l² = 0, where
//!   q = c₀ + c₁τ + c₂τ² + c₃τ³ + c₄τ⁴, c₀ = |x_e|² − l², c₁ = 2 x_e·v_e, c₂ = |v_e|² − g z_e = l T_e/m,
//!   c₃ = −g v_{e,z}, c₄ = g²/4. Leaving the sphere at T = 0 (c₀ = c₁ = c₂ = 0) gives the closed form
//!   τ* = 4 v_{e,z}/g; in general the known zero roots at τ = 0 are divided out and the first sign
//!   change of the rest is bracketed on a grid and bisected to round-off.
//! - **Snap**: with u = (x·v/l²) x the outward radial velocity on arrival and e ∈ [0, 1] the
//!   restitution, v ← v − (1 + e) u. e = 0 (inelastic, the default) removes u and loses exactly
//!   ½ m |u|²; e = 1 (elastic) reflects it and keeps E; in general ½ m (1 − e²)|u|² is lost. With e > 0
//!   the bob bounces back into the sphere (a new flight); when the rebound speed e|u| falls below
//!   1e-12 (|v| + √(|g| l)) the string is taken as taut (the bounces would otherwise accumulate like a
//!   bouncing ball's, without end).
//!
//! Conserved: E while taut and while slack (exactly in flight); at a snap E drops by the amount above.
//! J₃ is conserved throughout (gravity and the string's pull, along x, have no torque about e₃).
//! Vanishing extra parameters: a motion with T > 0 throughout is the rod pendulum, step for step.
//! The hybrid driver is [`crate::string_run`] (beside the stepper and the solver).

use super::Model;
use crate::error::{Error, Result};
use crate::state::{Params, State};
use glam::DVec3;

/// A pendulum on a string: length l, mass m, gravity g along −e₃ and the restitution e of a snap.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StringPendulum {
    params: Params,
    restitution: f64,
}

impl StringPendulum {
    /// Validated: `restitution` e ∈ [0, 1] (0 inelastic, 1 elastic), dimensionless.
    pub fn new(params: Params, restitution: f64) -> Result<Self> {
        if !(0.0..=1.0).contains(&restitution) {
            return Err(Error::InvalidParameter {
                name: "restitution",
                value: restitution,
                allowed: "a number in [0, 1]: 0 removes the radial velocity at a snap (inelastic), \
                          1 reflects it (elastic)",
            });
        }
        Ok(Self { params, restitution })
    }

    /// The restitution e ∈ [0, 1] of a snap.
    pub fn restitution(&self) -> f64 {
        self.restitution
    }

    /// The string's tension T = m(|v|² − g z)/l \[N\] of a state on the sphere (T-2.3); it is taut
    /// only while T ≥ 0.
    pub fn tension(&self, s: &State) -> f64 {
        let p = &self.params;
        p.mass * (s.v.length_squared() - p.g * s.x.z) / p.length
    }

    /// The height z* = 2E/(3 m g) \[m\] at which T = 0 for energy E \[J\] (g ≠ 0).
    pub fn slack_height(&self, energy: f64) -> f64 {
        2.0 * energy / (3.0 * self.params.mass * self.params.g)
    }

    /// The free-flight state τ \[s\] after (x, v): the exact parabola under gravity.
    pub fn flight(&self, s: &State, tau: f64) -> State {
        let a = DVec3::new(0.0, 0.0, -self.params.g);
        State { x: s.x + s.v * tau + a * (0.5 * tau * tau), v: s.v + a * tau }
    }

    /// The flight time τ* > 0 \[s\] until |x| = l again, from `s` with |x| ≤ l; `None` if the bob
    /// never reaches the sphere (g = 0 and v = 0). `zeros` is how many leading coefficients are zero
    /// by construction: 2 after a leave at T = 0 (c₀ = c₁ = 0, and c₂ = lT/m ≤ 0), 1 after an inward
    /// rebound (c₀ = 0), 0 from inside the sphere; they are divided out so that the root at τ = 0 is
    /// not found again.
    pub fn flight_time(&self, s: &State, zeros: usize) -> Option<f64> {
        let (l, g) = (self.params.length, self.params.g);
        let c = [
            s.x.length_squared() - l * l,
            2.0 * s.x.dot(s.v),
            s.v.length_squared() - g * s.x.z,
            -g * s.v.z,
            0.25 * g * g,
        ];
        let zeros = zeros.min(2);
        if zeros == 2 && c[2] <= 0.0 && c[3] < 0.0 {
            // left at T = 0: q/τ² = c₂ + c₃τ + c₄τ², the larger root without cancellation (c₃ < 0);
            // τ* = 4 v_z / g when c₂ = 0.
            return Some((-c[3] + (c[3] * c[3] - 4.0 * c[4] * c[2]).sqrt()) / (2.0 * c[4]));
        }
        // r(τ) = q(τ)/τ^zeros, negative just after τ = 0 while the bob is inside
        let r = |tau: f64| c[zeros..].iter().rev().fold(0.0, |acc, &ck| acc * tau + ck);
        // |x(τ)| ≥ ½|g|τ² − |v|τ − |x| > l beyond this bound
        let (speed, radius) = (s.v.length(), s.x.length());
        let bound = if g != 0.0 {
            (speed + (speed * speed + 2.0 * g.abs() * (radius + l)).sqrt()) / g.abs()
        } else if speed > 0.0 {
            (radius + l) / speed
        } else {
            return None;
        };
        const GRID: usize = 512;
        let mut lo = 0.0;
        for i in 1..=GRID {
            let hi = bound * i as f64 / GRID as f64;
            if r(hi) > 0.0 {
                return Some(bisect(lo, hi, |tau| r(tau) > 0.0));
            }
            lo = hi;
        }
        Some(bound)
    }

    /// The snap at arrival on the sphere: x is put on it exactly, and v ← v − (1 + e)u with u the
    /// outward radial velocity. Returns the new state, the energy lost \[J\] and whether the string is
    /// taut afterwards (no rebound, or one below the chatter limit of the module doc).
    pub fn snap(&self, s: &State) -> (State, f64, bool) {
        let (l, m) = (self.params.length, self.params.mass);
        let x = s.x * (l / s.x.length());
        let u = x * (x.dot(s.v) / (l * l));
        let u = if x.dot(s.v) > 0.0 { u } else { DVec3::ZERO };
        let e = self.restitution;
        let chatter = 1e-12 * (s.v.length() + (self.params.g.abs() * l).sqrt());
        let taut = e * u.length() <= chatter;
        let factor = if taut { 1.0 } else { 1.0 + e };
        let v = s.v - u * factor;
        // the tangential part is untouched: the loss is the radial kinetic energy's, ½m(1 − e²)|u|²
        // (½m|u|² when taut), computed from u itself rather than as a difference of |v|²
        let kept = if taut { 0.0 } else { e * e };
        let lost = 0.5 * m * (1.0 - kept) * u.length_squared();
        (State { x, v }, lost, taut)
    }
}

/// The smallest τ in (lo, hi] with `above(τ)`, to round-off, given `above(hi)` and not `above(lo)`.
pub(crate) fn bisect(mut lo: f64, mut hi: f64, above: impl Fn(f64) -> bool) -> f64 {
    loop {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            return hi;
        }
        if above(mid) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
}

impl Model for StringPendulum {
    fn name(&self) -> &'static str {
        "string"
    }
    fn params(&self) -> &Params {
        &self.params
    }
    #[inline(always)]
    fn applied_acceleration(&self, _t: f64, _x: DVec3, _v: DVec3) -> DVec3 {
        DVec3::new(0.0, 0.0, -self.params.g)
    }
    fn potential_per_mass(&self, x: DVec3) -> f64 {
        self.params.g * x.z
    }
    fn is_conservative(&self) -> bool {
        true
    }
    fn is_axisymmetric(&self) -> bool {
        true
    }
    fn is_hybrid(&self) -> bool {
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn flight_time_after_a_tangential_leave_is_four_vz_over_g() {
        // at T = 0 (|v|² = g z) the parabola meets the sphere again after τ* = 4 v_z/g
        let sp = StringPendulum::new(Params::new(1.0, 1.0, 9.81).unwrap(), 0.0).unwrap();
        let th = 2.0f64; // rad from the downward vertical, above the horizontal
        let x = DVec3::new(th.sin(), 0.0, -th.cos());
        let speed = (9.81 * x.z).sqrt();
        let v = DVec3::new(th.cos(), 0.0, th.sin()) * speed;
        let s = State { x, v };
        let tau = sp.flight_time(&s, 2).unwrap();
        assert!((tau - 4.0 * v.z / 9.81).abs() < 1e-15, "{tau}");
        let end = sp.flight(&s, tau);
        assert!((end.x.length() - 1.0).abs() < 1e-15);
        // the general path (no zeros divided out beyond τ = 0's double root) agrees
        let general = sp.flight_time(&State { x, v }, 1).unwrap();
        assert!((general - tau).abs() < 1e-9, "{general} vs {tau}");
    }
}
