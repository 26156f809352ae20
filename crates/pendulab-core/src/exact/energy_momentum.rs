//! The energy–momentum map (J₃, E) of the spherical pendulum (T-6.4), dimensionless for g > 0:
//! ε = E/(m g l), j = J₃/(m l² ω₀).
//!
//! - Image: the points with max over u ∈ [−1, 1] of P(u) = 2(ε − u)(1 − u²) − j² ≥ 0 (T-4.1). P has its
//!   local maximum at u* = (ε − √(ε² + 3))/3, the smaller root of P′(u) = 6u² − 4εu − 2.
//! - Boundary: the conical family (P(u) = P′(u) = 0), parametrised by the height u ∈ (−1, 0):
//!   j = ±(1 − u²)/√(−u), ε = u − (1 − u²)/(2u); its vertex is the stable bottom (0, −1).
//! - Critical values inside: the line j = 0 (planar motion) with the unstable top (0, 1), a
//!   focus–focus value.
//! - Rotation number W = Δφ/2π (T-4.5) per z-period; π < |Δφ| < 2π (Puiseux). Carried continuously
//!   once around (0, 1), W changes by exactly ±1 (Hamiltonian monodromy; Duistermaat 1980,
//!   Cushman & Bates 1997): [`monodromy_change`] measures it.

use super::cubic::StartData;
use super::generic::Generic;
use std::f64::consts::PI;

/// A point of the conical boundary at height u ∈ (−1, 0): (j ≥ 0, ε).
pub fn conical_boundary(u: f64) -> (f64, f64) {
    let w = 1.0 - u * u;
    (w / (-u).sqrt(), u - w / (2.0 * u))
}

/// A start on the orbit with energy ε and momentum j ≠ 0 (at the height where ż² = P is largest),
/// or None when (j, ε) is outside the image of the energy–momentum map.
pub fn start_for(eps: f64, j: f64) -> Option<StartData> {
    if !(eps.is_finite() && j.is_finite()) || j == 0.0 {
        return None;
    }
    let u = (eps - (eps * eps + 3.0).sqrt()) / 3.0;
    let rho2 = 1.0 - u * u;
    let kappa = eps - u;
    let p = 2.0 * kappa * rho2 - j * j;
    (p >= 0.0 && kappa >= 0.0 && rho2 > 0.0).then(|| StartData::new(u, rho2, kappa, j, p.sqrt()))
}

/// The rotation number W = Δφ/2π of the orbits with energy ε and momentum j ≠ 0; None outside the
/// image or on the line j = 0.
pub fn rotation_number(eps: f64, j: f64) -> Option<f64> {
    let g = Generic::new(start_for(eps, j)?, 0.0).ok()?;
    Some(g.delta_phi / (2.0 * PI))
}

/// W carried continuously along the circle (j, ε) = (r sin α, 1 + r cos α), α from 0 to 2π in `n`
/// steps, around the top equilibrium (0, 1): crossing j = 0, where W itself jumps, W is continued
/// by the integer shift that keeps it continuous. Returns W(end) − W(start) (±1 by T-6.4), or None
/// when the circle leaves the image (r too large) or n < 8.
pub fn monodromy_change(r: f64, n: usize) -> Option<f64> {
    if n < 8 || r.is_nan() || r <= 0.0 {
        return None;
    }
    // Start just off the axis j = 0 on the upper side and go round; skip the two points on j = 0.
    let offset = PI / n as f64;
    let mut prev: Option<f64> = None;
    let mut shift = 0.0;
    let mut first = None;
    for k in 0..=n {
        let alpha = offset + 2.0 * PI * k as f64 / n as f64;
        let (j, eps) = (r * alpha.sin(), 1.0 + r * alpha.cos());
        let w = rotation_number(eps, j)?;
        if let Some(p) = prev {
            // continue: the integer that brings w + shift closest to the previous value
            shift += (p - (w + shift)).round();
        }
        let cont = w + shift;
        first.get_or_insert(cont);
        prev = Some(cont);
    }
    Some(prev? - first?)
}
