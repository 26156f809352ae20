//! The crane load as one or two point masses on inextensible ropes (docs/theory.md T-11.5 – T-11.7).
//! Inertial frame, z up, SI units (m, kg, s, N, W). The rope runs from the pivot P(t) (trolley or
//! boom tip, [`Hermite5`]) to body 1 with the prescribed length l(t) (the hoist); with a hook, body 1
//! is the hook (mass m₁) and the payload (m₂) hangs from it on rigging of fixed length l₂:
//!
//!   |x₁ − P(t)| = l(t),   |x₂ − x₁| = l₂                                            (T-11.5)
//!
//!   m₁ẍ₁ = m₁g⃗ + F₁ − μ₁ r₁ + μ₂ r₂,   m₂ẍ₂ = m₂g⃗ + F₂ − μ₂ r₂,   r₁ = x₁ − P, r₂ = x₂ − x₁,
//!
//! rope tension T₁ = μ₁ l, rigging tension T₂ = μ₂ l₂. Differentiating the constraints twice
//! (r₁·(ẍ₁ − P̈) = l̇² + l l̈ − |ṙ₁|², r₂·(ẍ₂ − ẍ₁) = −|ṙ₂|²) gives the 2×2 linear system (T-11.6)
//!
//!   −(|r₁|²/m₁) μ₁ + (r₁·r₂/m₁) μ₂ = l̇² + l l̈ − |ṙ₁|² − r₁·(f₁ − P̈)
//!   (r₁·r₂/m₁) μ₁ − |r₂|²(1/m₁ + 1/m₂) μ₂ = −|ṙ₂|² − r₂·(f₂ − f₁),      f_i = g⃗ + F_i/m_i,
//!
//! so the hoist's l̈ enters the tension. Applied forces per body: wind drag relative to the air
//! F = ½ρ c_W A |w − v|(w − v) with w(t) = w₀ + w_g ½(1 − cos 2π(t − t_g)/T_g) during the gust
//! plus turbulence Σ a_k cos(ω_k t + φ_k) (T-11.7), and linear damping −m c (v − Ṗ) relative to the pivot. Energy E = Σ ½m_i|v_i|² + m_i g z_i
//! changes at the rate (the rigging, rigid, does no work)
//!
//!   dE/dt = −T₁ l̇ (hoist) − T₁ (r₁/l)·Ṗ (pivot) + Σ F_wind,i·v_i (wind) + Σ F_damp,i·v_i (damping),
//!
//! the four works W being integrated beside the motion: y = (x₁, v₁, x₂, v₂, W_hoist, W_pivot,
//! W_wind, W_damp) ∈ R¹⁶. A single load (no hook) uses body 1 only.

use super::hermite::Hermite5;
use crate::error::{Error, Result};
use glam::DVec3;

/// Wind: steady velocity, a (1 − cos) gust, turbulence as a sum of modes and the air density (T-11.7).
#[derive(Debug, Clone, PartialEq)]
pub struct Wind {
    /// Steady wind velocity w₀ [m/s].
    pub steady: DVec3,
    /// Peak gust velocity w_g [m/s] (added to w₀ at the gust's middle).
    pub gust: DVec3,
    /// Gust start t_g \[s\].
    pub gust_start: f64,
    /// Gust duration T_g \[s\] (> 0 when `gust` is nonzero).
    pub gust_duration: f64,
    /// Air density ρ [kg/m³].
    pub air_density: f64,
    /// Turbulence modes (ω_k [rad/s], amplitude a_k [m/s] per axis, phase φ_k \[rad\] per axis):
    /// w_turb(t) = Σ a_k cos(ω_k t + φ_k), component by component.
    pub turbulence: Vec<(f64, DVec3, DVec3)>,
}

impl Wind {
    /// No wind.
    pub const CALM: Wind = Wind {
        steady: DVec3::ZERO,
        gust: DVec3::ZERO,
        gust_start: 0.0,
        gust_duration: 1.0,
        air_density: 1.225,
        turbulence: Vec::new(),
    };

    /// w(t) [m/s].
    pub fn velocity(&self, t: f64) -> DVec3 {
        let s = (t - self.gust_start) / self.gust_duration;
        let mut w = if (0.0..=1.0).contains(&s) {
            self.steady + self.gust * (0.5 * (1.0 - (2.0 * std::f64::consts::PI * s).cos()))
        } else {
            self.steady
        };
        for &(om, a, ph) in &self.turbulence {
            let arg = DVec3::splat(om * t) + ph;
            w += a * DVec3::new(arg.x.cos(), arg.y.cos(), arg.z.cos());
        }
        w
    }
}

/// One body: mass \[kg\] and its drag area c_W A \[m²\].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Body {
    /// Mass m \[kg\] (> 0).
    pub mass: f64,
    /// Drag coefficient times area c_W A \[m²\] (≥ 0).
    pub drag_area: f64,
}

/// The crane system (see the module doc).
#[derive(Debug, Clone)]
pub struct CraneSystem {
    /// Pivot path P(t) \[m\].
    pub pivot: Hermite5,
    /// Rope length l(t) \[m\] in the first component.
    pub hoist: Hermite5,
    /// Body 1 (the hook, or the payload when there is no hook).
    pub body1: Body,
    /// Body 2, the payload on rigging of length l₂ \[m\], if there is a hook.
    pub body2: Option<(Body, f64)>,
    /// Gravity g [m/s²] along −z.
    pub g: f64,
    /// Linear damping c [1/s] relative to the pivot.
    pub damping: f64,
    /// The wind.
    pub wind: Wind,
}

/// Length of the state y.
pub const DIM: usize = 16;
/// A state y = (x₁, v₁, x₂, v₂, W_hoist, W_pivot, W_wind, W_damp).
pub type Y = [f64; DIM];

/// Reads 3 components of y at `i`.
#[inline(always)]
pub fn v3(y: &Y, i: usize) -> DVec3 {
    DVec3::new(y[i], y[i + 1], y[i + 2])
}

#[inline(always)]
fn put(y: &mut Y, i: usize, v: DVec3) {
    y[i] = v.x;
    y[i + 1] = v.y;
    y[i + 2] = v.z;
}

/// Everything the right-hand side computes at one (t, y).
#[derive(Debug, Clone, Copy)]
pub struct Eval {
    /// dy/dt.
    pub dy: Y,
    /// Rope tension T₁ \[N\] and rigging tension T₂ \[N\] (0 without a hook).
    pub tension: (f64, f64),
}

fn drag(body: Body, rho: f64, w: DVec3, v: DVec3) -> DVec3 {
    let rel = w - v;
    rel * (0.5 * rho * body.drag_area * rel.length())
}

impl CraneSystem {
    /// Checks the parameters (finite, masses > 0, drag areas ≥ 0, rigging > 0, damping ≥ 0, ρ ≥ 0).
    pub fn validate(&self) -> Result<()> {
        let check = |name: &'static str, v: f64, ok: bool, allowed: &'static str| {
            if v.is_finite() && ok {
                Ok(())
            } else {
                Err(Error::InvalidParameter { name, value: v, allowed })
            }
        };
        check("hook/payload mass", self.body1.mass, self.body1.mass > 0.0, "a mass > 0 kg")?;
        check("drag area", self.body1.drag_area, self.body1.drag_area >= 0.0, "c_W A >= 0 m²")?;
        if let Some((b, l2)) = self.body2 {
            check("payload mass", b.mass, b.mass > 0.0, "a mass > 0 kg")?;
            check("payload drag area", b.drag_area, b.drag_area >= 0.0, "c_W A >= 0 m²")?;
            check("rigging", l2, l2 > 0.0, "a rigging length > 0 m")?;
        }
        check("g", self.g, true, "a finite gravity in m/s²")?;
        check("damping", self.damping, self.damping >= 0.0, "a damping >= 0 1/s")?;
        let w = &self.wind;
        check("air_density", w.air_density, w.air_density >= 0.0, "a density >= 0 kg/m³")?;
        check("wind velocity", w.steady.length_squared(), w.steady.is_finite(), "finite m/s")?;
        check("gust velocity", w.gust.length_squared(), w.gust.is_finite(), "finite m/s")?;
        check("gust start", w.gust_start, true, "a finite time in s")?;
        check("gust duration", w.gust_duration, w.gust_duration > 0.0, "a duration > 0 s")?;
        for &(om, a, ph) in &w.turbulence {
            check("turbulence frequency", om, true, "a finite angular frequency in rad/s")?;
            check(
                "turbulence amplitude",
                a.length_squared(),
                a.is_finite() && ph.is_finite(),
                "finite m/s and rad",
            )?;
        }
        Ok(())
    }

    /// The right-hand side at (t, y); `t_piece` picks the piece of the prescribed motions at jumps.
    pub fn eval(&self, t: f64, t_piece: f64, y: &Y) -> Eval {
        let (p, dp, ddp) = self.pivot.eval_on(t, t_piece);
        let (lq, ldq, lddq) = self.hoist.eval_on(t, t_piece);
        let (l, dl, ddl) = (lq.x, ldq.x, lddq.x);
        let gv = DVec3::new(0.0, 0.0, -self.g);
        let w = self.wind.velocity(t);
        let rho = self.wind.air_density;
        let (x1, v1) = (v3(y, 0), v3(y, 3));
        let m1 = self.body1.mass;
        let fw1 = drag(self.body1, rho, w, v1);
        let fd1 = (v1 - dp) * (-m1 * self.damping);
        let f1 = gv + (fw1 + fd1) / m1;
        let (r1, dr1) = (x1 - p, v1 - dp);
        let rhs1 = dl * dl + l * ddl - dr1.length_squared() - r1.dot(f1 - ddp);
        let mut dy = [0.0; DIM];
        put(&mut dy, 0, v1);
        let (mu1, mu2, p_wind, p_damp);
        if let Some((b2, _)) = self.body2 {
            let (x2, v2) = (v3(y, 6), v3(y, 9));
            let m2 = b2.mass;
            let fw2 = drag(b2, rho, w, v2);
            let fd2 = (v2 - dp) * (-m2 * self.damping);
            let f2 = gv + (fw2 + fd2) / m2;
            let (r2, dr2) = (x2 - x1, v2 - v1);
            let a = r1.length_squared() / m1;
            let b = r1.dot(r2) / m1;
            let c = r2.length_squared() * (1.0 / m1 + 1.0 / m2);
            let rhs2 = -dr2.length_squared() - r2.dot(f2 - f1);
            // [−a b; b −c] (μ₁, μ₂) = (rhs1, rhs2)
            let det = a * c - b * b;
            mu1 = (-c * rhs1 - b * rhs2) / det;
            mu2 = (-b * rhs1 - a * rhs2) / det;
            put(&mut dy, 3, f1 - r1 * (mu1 / m1) + r2 * (mu2 / m1));
            put(&mut dy, 6, v2);
            put(&mut dy, 9, f2 - r2 * (mu2 / m2));
            p_wind = fw1.dot(v1) + fw2.dot(v2);
            p_damp = fd1.dot(v1) + fd2.dot(v2);
        } else {
            mu1 = -rhs1 / (r1.length_squared() / m1);
            mu2 = 0.0;
            put(&mut dy, 3, f1 - r1 * (mu1 / m1));
            p_wind = fw1.dot(v1);
            p_damp = fd1.dot(v1);
        }
        dy[12] = -mu1 * l * dl;
        dy[13] = -mu1 * r1.dot(dp);
        dy[14] = p_wind;
        dy[15] = p_damp;
        let l2 = self.body2.map_or(0.0, |(_, l2)| l2);
        Eval { dy, tension: (mu1 * l, mu2 * l2) }
    }

    /// Projects y onto the constraints at t (positions onto the spheres, then the velocity
    /// components along r₁, r₂ to l l̇ and 0). `None` when a rope has collapsed to a point.
    pub fn project(&self, t: f64, t_piece: f64, y: &mut Y) -> Option<()> {
        let (p, dp, _) = self.pivot.eval_on(t, t_piece);
        let (lq, ldq, _) = self.hoist.eval_on(t, t_piece);
        let (l, dl) = (lq.x, ldq.x);
        let r1 = v3(y, 0) - p;
        let n1 = r1.length();
        if !(n1 > 0.0 && n1.is_finite()) {
            return None;
        }
        let u1 = r1 / n1;
        let x1 = p + u1 * l;
        let v1 = v3(y, 3);
        let v1 = v1 - u1 * (u1.dot(v1 - dp) - dl);
        put(y, 0, x1);
        put(y, 3, v1);
        if let Some((_, l2)) = self.body2 {
            let r2 = v3(y, 6) - x1;
            let n2 = r2.length();
            if !(n2 > 0.0 && n2.is_finite()) {
                return None;
            }
            let u2 = r2 / n2;
            let v2 = v3(y, 9);
            put(y, 6, x1 + u2 * l2);
            put(y, 9, v2 - u2 * u2.dot(v2 - v1));
        }
        Some(())
    }

    /// The mechanical energy E = Σ ½ m|v|² + m g z \[J\] of y.
    pub fn energy(&self, y: &Y) -> f64 {
        let m1 = self.body1.mass;
        let mut e = 0.5 * m1 * v3(y, 3).length_squared() + m1 * self.g * y[2];
        if let Some((b2, _)) = self.body2 {
            e += 0.5 * b2.mass * v3(y, 9).length_squared() + b2.mass * self.g * y[8];
        }
        e
    }
}
