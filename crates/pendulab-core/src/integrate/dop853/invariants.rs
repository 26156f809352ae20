//! `conserve=True` (docs/theory.md T-8.5, T-2.6): after DOP853's step and its projection onto TS²,
//! the velocity is moved within the tangent plane so that the kinetic energy per mass ½|v|² [J/kg]
//! and J₃/m = (x × v)·e₃ [m²/s] take the values the conserved E and J₃ give at x,
//!
//!   ½|v|² = ½|v₀|² − (V(x) − V(x₀))/m,   (x × v)·e₃ = J₃/m,
//!
//! by two Gauss–Newton steps of the minimal-norm correction along v and e₃ × x.

use glam::DVec3;

/// Moves a tangent velocity v at x (along v and e₃ × x, both tangent) so that ½|v|² = `kinetic`
/// [J/kg] and (x × v)·e₃ = `j3` [m²/s] (each only when given), by two Gauss–Newton steps of the
/// minimal-norm correction. Where v ∥ e₃ × x (the turning points of z) the two conditions are
/// dependent and only J₃ is imposed there.
#[inline(always)]
pub fn project_invariants(x: DVec3, v: DVec3, kinetic: Option<f64>, j3: Option<f64>) -> DVec3 {
    let w = DVec3::new(-x.y, x.x, 0.0);
    let mut v = v;
    for _ in 0..2 {
        let r1 = kinetic.map(|k| k - 0.5 * v.length_squared());
        let r2 = j3.map(|j| j - w.dot(v));
        let (vv, vw, ww) = (v.length_squared(), v.dot(w), w.length_squared());
        let dv = match (r1, r2) {
            (Some(r1), Some(r2)) => {
                let det = vv * ww - vw * vw;
                if det > 1e-8 * vv * ww {
                    let a = (r1 * ww - r2 * vw) / det;
                    let b = (r2 * vv - r1 * vw) / det;
                    v * a + w * b
                } else if ww > 0.0 {
                    w * (r2 / ww)
                } else {
                    DVec3::ZERO
                }
            }
            (Some(r1), None) if vv > 0.0 => v * (r1 / vv),
            (None, Some(r2)) if ww > 0.0 => w * (r2 / ww),
            _ => DVec3::ZERO,
        };
        v += dv;
    }
    v
}
