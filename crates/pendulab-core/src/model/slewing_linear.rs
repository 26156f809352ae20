//! The linearised slewing crane (docs/theory.md T-7.2) in closed form: small sway of the payload under a
//! boom tip moving on the circle p(t) = R(cos ωt, sin ωt, h), in the boom frame (x radial, y
//! tangential, both the bob's horizontal displacement from the pivot \[m\]; ω₀² = g/l):
//!
//!   ẍ − 2ωẏ + (ω₀² − ω²)x = ω²R,   ÿ + 2ωẋ + (ω₀² − ω²)y = 0            (T-7.2)
//!
//! plus, with the `slewing` model's damping c [1/s] relative to the (non-rotating) pivot frame, the
//! force −c(ż + iωz) per unit mass. In complex form z = x + i y:
//!
//!   z̈ + (2iω + c) ż + (ω₀² − ω² + icω) z = ω²R.
//!
//! - Static offset (particular solution): z_s = ω²R/(ω₀² − ω² + icω); for c = 0 the radial offset
//!   ω²R/(ω₀² − ω²) of T-7.2, for small c the lag y_s ≈ −cω x_s/(ω₀² − ω²).
//! - Free sway: z = z_s + e^{−ct/2} e^{−iωt}(A e^{iΩt} + B e^{−iΩt}), Ω = √(ω₀² − c²/4): in the boom
//!   frame the two natural frequencies |Ω − ω| and Ω + ω (ω₀ ∓ ω for c = 0, derived), with
//!   A = (ż₀ − iλ₋ d)/(2iΩ), B = d − A, d = z₀ − z_s, λ± = −ω + ic/2 ± Ω.
//!
//! Refused: g ≤ 0 (no hanging equilibrium to linearise about), c ≥ 2ω₀ (not oscillatory), and the
//! resonance ω = ω₀ without damping (|ω₀² − ω² + icω| ≤ 1e-9 ω₀²), where the offset is infinite and
//! the linear response grows without bound. Valid while the sway is small against l (and R ω² small
//! against g). Units: l, R \[m\]; g [m/s²]; ω, ω₀, Ω [rad/s]; c [1/s]; t \[s\].

use crate::error::{Error, Result};
use crate::state::Params;

/// Minimal complex arithmetic (re, im) for the closed form.
#[derive(Debug, Clone, Copy, PartialEq)]
struct C(f64, f64);

impl C {
    fn mul(self, o: C) -> C {
        C(self.0 * o.0 - self.1 * o.1, self.0 * o.1 + self.1 * o.0)
    }
    fn div(self, o: C) -> C {
        let n = o.0 * o.0 + o.1 * o.1;
        C((self.0 * o.0 + self.1 * o.1) / n, (self.1 * o.0 - self.0 * o.1) / n)
    }
    fn add(self, o: C) -> C {
        C(self.0 + o.0, self.1 + o.1)
    }
    fn sub(self, o: C) -> C {
        C(self.0 - o.0, self.1 - o.1)
    }
    /// e^{iλt} for complex λ.
    fn expi(l: C, t: f64) -> C {
        let m = (-l.1 * t).exp();
        let (s, c) = (l.0 * t).sin_cos();
        C(m * c, m * s)
    }
}

const I: C = C(0.0, 1.0);

/// The closed-form small-sway response of a uniformly slewing crane (see the module doc).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LinearSlewing {
    omega0: f64,
    rate: f64,
    radius: f64,
    damping: f64,
}

/// The boom-frame sway at one time: displacement (x radial, y tangential) \[m\] and its rates [m/s].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sway {
    /// Radial displacement x \[m\].
    pub x: f64,
    /// Tangential displacement y \[m\].
    pub y: f64,
    /// ẋ [m/s] (rate in the rotating boom frame).
    pub vx: f64,
    /// ẏ [m/s].
    pub vy: f64,
}

impl LinearSlewing {
    /// From l \[m\] and g [m/s²] of `params`, boom radius R \[m\], slewing rate ω [rad/s] and damping c
    /// [1/s] (≥ 0), with the refusals of the module doc.
    pub fn new(params: &Params, radius: f64, rate: f64, damping: f64) -> Result<Self> {
        crate::error::require_finite("radius", radius, "a finite boom radius R in m")?;
        crate::error::require_finite("rate", rate, "a finite slewing rate ω in rad/s")?;
        if !(damping.is_finite() && damping >= 0.0) {
            return Err(Error::InvalidParameter {
                name: "damping",
                value: damping,
                allowed: "a finite number >= 0 1/s",
            });
        }
        if params.g <= 0.0 {
            return Err(Error::InvalidParameter {
                name: "g",
                value: params.g,
                allowed:
                    "g > 0 m/s²: the linear sway is about the hanging equilibrium, which needs gravity down",
            });
        }
        let omega0 = params.omega0();
        if damping >= 2.0 * omega0 {
            return Err(Error::InvalidParameter {
                name: "damping",
                value: damping,
                allowed: "c < 2ω₀ = 2√(g/l) 1/s: the closed form is for oscillating (underdamped) sway",
            });
        }
        let den = C(omega0 * omega0 - rate * rate, damping * rate);
        if den.0.hypot(den.1) <= 1e-9 * omega0 * omega0 {
            return Err(Error::InvalidParameter {
                name: "rate",
                value: rate,
                allowed:
                    "a slewing rate ω away from the resonance ω = ω₀ = √(g/l) (without damping the static \
                          offset ω²R/(ω₀² − ω²) is infinite and the linear sway grows without bound)",
            });
        }
        Ok(Self { omega0, rate, radius, damping })
    }

    fn static_c(&self) -> C {
        let w = self.rate;
        C(w * w * self.radius, 0.0).div(C(self.omega0 * self.omega0 - w * w, self.damping * w))
    }

    /// The static offset (radial, tangential) \[m\] in the boom frame: ω²R/(ω₀² − ω² + icω).
    pub fn static_offset(&self) -> (f64, f64) {
        let z = self.static_c();
        (z.0, z.1)
    }

    /// Ω = √(ω₀² − c²/4) [rad/s], the damped sway frequency in the pivot's non-rotating frame.
    pub fn omega_damped(&self) -> f64 {
        (self.omega0 * self.omega0 - 0.25 * self.damping * self.damping).sqrt()
    }

    /// The two natural sway frequencies in the boom frame, (|Ω − ω|, Ω + ω) [rad/s] (ω₀ ∓ ω for c = 0).
    pub fn frequencies(&self) -> (f64, f64) {
        let om = self.omega_damped();
        ((om - self.rate).abs(), om + self.rate)
    }

    /// The sway at time t \[s\] from the boom-frame start (x₀, y₀) \[m\] with rates (ẋ₀, ẏ₀) [m/s] at t = 0.
    pub fn sway(&self, start: Sway, t: f64) -> Sway {
        let om = self.omega_damped();
        let (lp, lm) = (C(-self.rate + om, 0.5 * self.damping), C(-self.rate - om, 0.5 * self.damping));
        let zs = self.static_c();
        let d = C(start.x, start.y).sub(zs);
        let a = C(start.vx, start.vy).sub(I.mul(lm).mul(d)).div(C(0.0, 2.0 * om));
        let b = d.sub(a);
        let (ep, em) = (C::expi(lp, t), C::expi(lm, t));
        let z = zs.add(a.mul(ep)).add(b.mul(em));
        let zdot = I.mul(lp).mul(a).mul(ep).add(I.mul(lm).mul(b).mul(em));
        Sway { x: z.0, y: z.1, vx: zdot.0, vy: zdot.1 }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn satisfies_the_linear_equations_and_the_start() {
        let p = Params::new(2.0, 1.0, 9.81).unwrap();
        let m = LinearSlewing::new(&p, 3.0, 0.7, 0.1).unwrap();
        let start = Sway { x: 0.01, y: -0.02, vx: 0.03, vy: 0.005 };
        let s0 = m.sway(start, 0.0);
        assert!((s0.x - start.x).abs() + (s0.y - start.y).abs() + (s0.vx - start.vx).abs() < 1e-15);
        // the ODE by central differences at t = 1.3 s
        let (t, h) = (1.3, 1e-4);
        let (a, b, c) = (m.sway(start, t - h), m.sway(start, t), m.sway(start, t + h));
        let (xdd, ydd) = ((a.x - 2.0 * b.x + c.x) / (h * h), (a.y - 2.0 * b.y + c.y) / (h * h));
        let (w, w0sq, cd) = (0.7, 9.81 / 2.0, 0.1);
        // with damping −c(ż + iωz): x: −c(ẋ − ω y), y: −c(ẏ + ω x)
        let rx = xdd - 2.0 * w * b.vy + (w0sq - w * w) * b.x + cd * (b.vx - w * b.y) - w * w * 3.0;
        let ry = ydd + 2.0 * w * b.vx + (w0sq - w * w) * b.y + cd * (b.vy + w * b.x);
        assert!(rx.abs() < 1e-6 && ry.abs() < 1e-6, "{rx} {ry}");
        assert!(((c.x - a.x) / (2.0 * h) - b.vx).abs() < 1e-8);
    }
}
