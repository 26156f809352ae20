//! Changes of the gravitational potential between two points of the sphere |x| = l, without the
//! cancellation of V(x) = −g⃗·x near the poles of g⃗.
//!
//! With d = g⃗/|g⃗| the direction of gravity, the height above the lowest point l·d is
//!
//!   h(x) = l − d·x = |d × x|² / (l + d·x)      (lower hemisphere, d·x > 0),
//!
//! and the depth below the highest point −l·d is
//!
//!   q(x) = l + d·x = |d × x|² / (l − d·x)      (upper hemisphere, d·x < 0),
//!
//! both identities on the sphere (T-2.6 with the energy measured from the lowest point; for the
//! ideal pendulum d = −e₃ and h = z + l = (x² + y²)/(l − z)). The right-hand sides are formed from
//! |d × x|², whose relative accuracy does not depend on how close x is to a pole, whereas l ∓ d·x
//! carries the absolute round-off of the coordinate along d, ulp(l) ≈ 2e-16 l: for a swing of
//! 1e-6 rad the height is 5e-13 l and the direct form would lose four digits of it, and with them
//! the kinetic energy ½|v|² = E − V that `conserve=True` (DOP853's invariant projection) imposes.
//!
//! V(to) − V(from) = |g⃗| (h(to) − h(from)) = |g⃗| (q(from) − q(to)): both points are measured from the
//! same pole (the lower one when both lie below the equator of d, the upper one when both lie above
//! it); across the equator the plain difference has no cancellation worth avoiding.

use glam::DVec3;

/// Height above the lowest point, h = l − d·x \[m\], for x on the sphere of radius `length` and a unit
/// direction `d` of gravity; accurate to a few ulp of h itself on the lower hemisphere.
pub fn height_above_lowest(length: f64, d: DVec3, x: DVec3) -> f64 {
    let along = d.dot(x);
    if along > 0.0 {
        d.cross(x).length_squared() / (length + along)
    } else {
        length - along
    }
}

/// Depth below the highest point, q = l + d·x \[m\]; accurate to a few ulp of q on the upper hemisphere.
pub fn depth_below_highest(length: f64, d: DVec3, x: DVec3) -> f64 {
    let along = d.dot(x);
    if along < 0.0 {
        d.cross(x).length_squared() / (length - along)
    } else {
        length + along
    }
}

/// V(to) − V(from) [J/kg] for the uniform field g⃗ = `g_vec` [m/s²] (V = −g⃗·x), both points on the
/// sphere of radius `length` \[m\], measured from the pole nearer to both (see the module doc).
pub fn gravity_potential_change(g_vec: DVec3, length: f64, from: DVec3, to: DVec3) -> f64 {
    let g = g_vec.length();
    if g == 0.0 {
        return 0.0;
    }
    let d = g_vec / g;
    let (a, b) = (d.dot(from), d.dot(to));
    if a > 0.0 && b > 0.0 {
        g * (height_above_lowest(length, d, to) - height_above_lowest(length, d, from))
    } else if a < 0.0 && b < 0.0 {
        g * (depth_below_highest(length, d, from) - depth_below_highest(length, d, to))
    } else {
        -g * (b - a)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_height_near_the_bottom_keeps_its_digits() {
        // x at angle θ from the bottom of a 1 m sphere: h = 1 − cos θ = 2 sin²(θ/2) exactly
        for theta in [1e-8f64, 1e-6, 1e-3, 0.5] {
            let x = DVec3::new(theta.sin(), 0.0, -theta.cos());
            let h = height_above_lowest(1.0, DVec3::NEG_Z, x);
            let want = 2.0 * (0.5 * theta).sin().powi(2);
            assert!((h - want).abs() <= 4.0 * f64::EPSILON * want, "θ = {theta}: {h} vs {want}");
            let q = depth_below_highest(1.0, DVec3::Z, x);
            assert!((q - want).abs() <= 4.0 * f64::EPSILON * want, "θ = {theta}: {q} vs {want}");
        }
    }

    #[test]
    fn potential_changes_agree_with_the_plain_difference_away_from_the_poles() {
        let g = DVec3::new(0.0, 0.0, -9.81);
        let (a, b) = (DVec3::new(0.6, 0.0, -0.8), DVec3::new(0.0, 0.8, 0.6));
        let plain = -g.dot(b) + g.dot(a);
        assert!((gravity_potential_change(g, 1.0, a, b) - plain).abs() < 1e-14);
        let (c, e) = (DVec3::new(0.6, 0.0, -0.8), DVec3::new(0.0, 0.8, -0.6));
        let plain = -g.dot(e) + g.dot(c);
        assert!((gravity_potential_change(g, 1.0, c, e) - plain).abs() < 1e-14);
        assert_eq!(gravity_potential_change(DVec3::ZERO, 1.0, a, b), 0.0);
    }
}
