//! Published values and limits of the ideal pendulum, measured from simulation.
//!
//! - T-6.2: planar period / (2π√(l/g)) against the Encyclopaedia Britannica 1911 table
//!   ("Mechanics", the pendulum), and against 2K(sin(θ₀/2))/π computed here by the AGM.
//! - T-6.1: a conical start (φ̇² = g/(l cos α)) stays on its circle.
//! - §1 / T-4.6: g < 0 is the mirror image z → −z of g > 0.
//! - T-4.6: g = 0 moves along a great circle at constant speed.
//! - T-2.5: the angle method refuses near a pole instead of returning garbage.

use crate::common;

use common::{fixed, rosette};
use pendulab_core::{DVec3, Error, IdealPendulum, Method, Model, State, Stepper};
use std::f64::consts::PI;

/// K(k) = π / (2 AGM(1, √(1 − k²))), the complete elliptic integral of the first kind.
fn elliptic_k(k: f64) -> f64 {
    let (mut a, mut b) = (1.0f64, (1.0 - k * k).sqrt());
    // Quadratic convergence: 40 rounds are far more than enough (and cannot loop for ever on a
    // last-ulp oscillation).
    for _ in 0..40 {
        (a, b) = (0.5 * (a + b), (a * b).sqrt());
    }
    PI / (2.0 * a)
}

/// Time of the first downward crossing of x = 0 after release at rest at x > 0, by cubic Hermite
/// interpolation between steps (position and velocity at both ends). A quarter of the period.
fn quarter_period(model: IdealPendulum, theta0: f64, dt: f64) -> f64 {
    let s0 = State::from_angles(model.params(), theta0, 0.0, 0.0, 0.0).unwrap();
    let mut st = Stepper::new(model, 0.0, s0, &fixed(Method::Rattle8, dt)).unwrap();
    loop {
        let (t0, a) = (st.t(), st.state());
        st.step().unwrap();
        let b = st.state();
        if b.x.x <= 0.0 {
            // Solve the Hermite cubic p(s) = 0 on s ∈ [0, 1] by bisection.
            let (p0, p1, m0, m1) = (a.x.x, b.x.x, a.v.x * dt, b.v.x * dt);
            let p = |s: f64| {
                let (s2, s3) = (s * s, s * s * s);
                (2.0 * s3 - 3.0 * s2 + 1.0) * p0
                    + (s3 - 2.0 * s2 + s) * m0
                    + (-2.0 * s3 + 3.0 * s2) * p1
                    + (s3 - s2) * m1
            };
            let (mut lo, mut hi) = (0.0, 1.0);
            for _ in 0..60 {
                let mid = 0.5 * (lo + hi);
                if p(mid) > 0.0 {
                    lo = mid
                } else {
                    hi = mid
                }
            }
            return t0 + 0.5 * (lo + hi) * dt;
        }
    }
}

#[test]
fn planar_period_matches_the_britannica_1911_table() {
    // T-6.2: amplitude θ₀/π → period / (2π √(l/g)), printed to 4-5 digits.
    let table = [
        (0.1, 1.0062),
        (0.2, 1.0253),
        (0.3, 1.0585),
        (0.4, 1.1087),
        (0.5, 1.1804),
        (0.6, 1.2817),
        (0.7, 1.4283),
        (0.8, 1.6551),
        (0.9, 2.0724),
    ];
    let model = IdealPendulum::new(1.0, 1.0, 9.81).unwrap();
    let t_small = 2.0 * PI / model.params().omega0();
    for (fraction, printed) in table {
        let theta0 = fraction * PI;
        let measured = 4.0 * quarter_period(model, theta0, 1e-3) / t_small;
        let exact = 2.0 * elliptic_k((theta0 / 2.0).sin()) / PI;
        eprintln!("θ₀ = {fraction}π: measured {measured:.8}, 2K/π {exact:.8}, EB1911 {printed}");
        assert!((measured - exact).abs() < 1e-9, "θ₀ = {fraction}π: simulation {measured} vs 2K/π {exact}");
        assert!(
            (measured - printed).abs() <= 0.6e-4,
            "θ₀ = {fraction}π: simulation {measured} vs EB1911 {printed}"
        );
    }
}

#[test]
fn conical_start_stays_conical() {
    // T-6.1: Ω² = g / (l cos α) keeps θ = α for ever.
    let model = IdealPendulum::new(1.0, 1.0, 9.81).unwrap();
    let alpha = 45f64.to_radians();
    let omega = (9.81 / alpha.cos()).sqrt();
    let s0 = State::from_angles(model.params(), alpha, 0.0, 0.0, omega).unwrap();
    let mut st = Stepper::new(model, 0.0, s0, &fixed(Method::Rattle8, 1e-2)).unwrap();
    let mut max_dev: f64 = 0.0;
    for _ in 0..10_000 {
        st.step().unwrap();
        max_dev = max_dev.max((st.state().angles().0 - alpha).abs());
    }
    eprintln!("conical: max |θ − α| over 100 s = {max_dev:e} rad");
    assert!(max_dev < 1e-9, "conical orbit left its circle by {max_dev} rad");
    // and it really went round: φ advanced by Ω t
    assert!((st.t() - 100.0).abs() < 1e-9);
}

#[test]
fn negative_gravity_mirrors_positive_gravity() {
    // g → −g together with z → −z maps solutions onto solutions.
    let (up, s0) = rosette();
    let down = IdealPendulum::new(1.0, 1.0, -9.81).unwrap();
    let mirror =
        |s: &State| State { x: s.x * DVec3::new(1.0, 1.0, -1.0), v: s.v * DVec3::new(1.0, 1.0, -1.0) };
    for method in [Method::Rattle, Method::Rattle4, Method::Rkmk4, Method::Dop853] {
        let mut a = Stepper::new(up, 0.0, s0, &fixed(method, 1e-3)).unwrap();
        let mut b = Stepper::new(down, 0.0, mirror(&s0), &fixed(method, 1e-3)).unwrap();
        a.step_to(10.0).unwrap();
        b.step_to(10.0).unwrap();
        let (sa, sb) = (a.state(), mirror(&b.state()));
        let d = (sa.x - sb.x).length() + (sa.v - sb.v).length();
        assert!(d < 1e-12, "{}: mirror images differ by {d:e}", method.info().name);
        assert!(sb.x.z < 0.0 || sa.x.z < 0.0 || d < 1e-12);
    }
}

#[test]
fn zero_gravity_follows_a_great_circle_at_constant_speed() {
    // g = 0: x(t) = x₀ cos ωt + (v₀/ω) sin ωt with ω = |v₀|/l.
    let model = IdealPendulum::new(1.5, 1.0, 0.0).unwrap();
    let s0 = State::from_angles(model.params(), 1.0, 0.5, 0.7, 1.3).unwrap();
    let w = s0.v.length() / 1.5;
    let normal = s0.x.cross(s0.v).normalize();
    for (method, dt, tol) in
        [(Method::Rattle8, 1e-2, 1e-9), (Method::Rattle, 1e-3, 1e-4), (Method::Dop853, 0.0, 1e-9)]
    {
        let opts = pendulab_core::SolveOptions { method, dt, rtol: 1e-12, atol: 1e-14, project: true };
        let mut st = Stepper::new(model, 0.0, s0, &opts).unwrap();
        st.step_to(10.0).unwrap();
        let exact = s0.x * (w * 10.0).cos() + s0.v / w * (w * 10.0).sin();
        let s = st.state();
        let err = (s.x - exact).length() / 1.5;
        eprintln!("g = 0, {}: error at t = 10 s: {err:e}", method.info().name);
        assert!(err < tol, "{}: {err:e}", method.info().name);
        assert!(s.x.dot(normal).abs() < 1e-12, "left the plane of the great circle");
        assert!((s.v.length() - s0.v.length()).abs() < 1e-9, "speed changed");
    }
}

#[test]
fn angle_method_refuses_near_the_poles() {
    // A planar swing passes through the bottom pole θ = 0, where φ is undefined (T-2.5).
    let model = IdealPendulum::new(1.0, 1.0, 9.81).unwrap();
    let planar = State::from_angles(model.params(), 0.5, 0.0, 0.0, 0.0).unwrap();
    let mut st = Stepper::new(model, 0.0, planar, &fixed(Method::Rk4Angles, 1e-3)).unwrap();
    match st.step_to(2.0) {
        Err(Error::PoleSingularity { t, sin_theta, .. }) => {
            assert!(t > 0.3 && t < 0.6, "refused at t = {t}, the swing reaches the bottom near T/4 = 0.5 s");
            assert!(sin_theta < 1e-2);
        }
        other => panic!("expected a refusal at the pole, got {other:?}"),
    }
    // Starting at the top is refused at once, with a message that names the way out.
    let top = State::from_angles(model.params(), PI - 1e-3, 0.0, 0.0, 0.5).unwrap();
    let err = Stepper::new(model, 0.0, top, &fixed(Method::Rk4Angles, 1e-3)).unwrap().step().unwrap_err();
    assert!(err.to_string().contains("rattle"), "{err}");
}
