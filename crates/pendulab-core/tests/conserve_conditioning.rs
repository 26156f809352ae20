//! DOP853's invariant projection (`conserve`) next to the poles: the kinetic energy it imposes,
//! ½|v₀|² − (V(x) − V(x₀)), is formed from heights measured from the nearer pole (`model::heights`),
//! so tiny swings about the bottom and starts next to the top lose no digits to it. Reference: the
//! exact solution (T-4.x). SI units; l = 1 m, g = 9.81 m/s² unless stated.

use pendulab_core::exact::ExactSolution;
use pendulab_core::model::heights::gravity_potential_change;
use pendulab_core::{IdealPendulum, Method, Model, SolveOptions, State, Stepper};

/// Position error [m] relative to l of DOP853 (rtol 1e-12) at `t_end`, with and without `conserve`.
fn errors(l: f64, g: f64, s0: State, t_end: f64) -> (f64, f64) {
    let m = IdealPendulum::new(l, 1.0, g).unwrap();
    let exact = ExactSolution::new(m.params(), &s0).unwrap().state(t_end).unwrap();
    let run = |conserve: bool| {
        let opts = SolveOptions { method: Method::Dop853, dt: 0.0, rtol: 1e-12, atol: 1e-14, project: true };
        let mut st = Stepper::new(m, 0.0, s0, &opts).unwrap();
        st.set_invariant_projection(conserve);
        st.step_to(t_end).unwrap();
        (st.state().x - exact.x).length() / l
    };
    (run(false), run(true))
}

/// "Never more than 2× worse", with the float64 floor of a position, 4 ulp of l, as the least error
/// that counts (both runs are at round-off there and the ratio of two round-off errors means nothing).
fn check(label: &str, (off, on): (f64, f64)) {
    eprintln!("{label}: error without conserve {off:.2e}, with {on:.2e} (relative to l)");
    let floor = 4.0 * f64::EPSILON;
    assert!(on <= 2.0 * off.max(floor), "{label}: conserve made it worse: {on:e} vs {off:e}");
}

#[test]
fn small_swings_about_the_bottom_are_not_spoilt_by_conserve() {
    for amp in [1e-8, 1e-7, 1e-6, 1e-4, 1e-2] {
        let m = IdealPendulum::new(1.0, 1.0, 9.81).unwrap();
        // planar, and spherical (a small ellipse: φ̇ gives J₃ ≠ 0)
        let planar = State::from_angles(m.params(), amp, 0.3, 0.0, 0.0).unwrap();
        check(&format!("planar swing {amp:e} rad"), errors(1.0, 9.81, planar, 20.0));
        let ellipse = State::from_angles(m.params(), amp, 0.3, 0.0, 1.5).unwrap();
        check(&format!("elliptic swing {amp:e} rad"), errors(1.0, 9.81, ellipse, 20.0));
    }
}

#[test]
fn starts_next_to_the_top_are_not_spoilt_by_conserve() {
    let pi = std::f64::consts::PI;
    for (off_top, phi_dot) in [(1e-6, 0.0), (1e-6, 1e-3), (1e-4, 0.0), (1e-3, 0.02)] {
        let m = IdealPendulum::new(1.0, 1.0, 9.81).unwrap();
        let s0 = State::from_angles(m.params(), pi - off_top, 0.2, 0.0, phi_dot).unwrap();
        check(&format!("{off_top:e} rad from the top, φ̇ = {phi_dot}"), errors(1.0, 9.81, s0, 3.0));
    }
    // g < 0: the mirror image; a small swing about the top pole (now the lowest point)
    let m = IdealPendulum::new(1.0, 1.0, -9.81).unwrap();
    let s0 = State::from_angles(m.params(), pi - 1e-6, 0.2, 0.0, 0.0).unwrap();
    check("g < 0, 1e-6 rad from z = +l", errors(1.0, -9.81, s0, 20.0));
}

#[test]
fn the_potential_change_keeps_its_digits_where_the_plain_difference_does_not() {
    // V(to) − V(from) between two points 1e-7 and 2e-7 rad from the bottom: g(cos θ₁ − cos θ₂)
    let (t1, t2) = (1e-7f64, 2e-7f64);
    let from = glam::DVec3::new(t1.sin(), 0.0, -t1.cos());
    let to = glam::DVec3::new(0.0, t2.sin(), -t2.cos());
    let want = 9.81 * 2.0 * ((0.5 * t2).sin().powi(2) - (0.5 * t1).sin().powi(2));
    let g = glam::DVec3::new(0.0, 0.0, -9.81);
    let got = gravity_potential_change(g, 1.0, from, to);
    assert!((got - want).abs() < 1e-14 * want, "{got:e} vs {want:e}");
    let m = IdealPendulum::new(1.0, 1.0, 9.81).unwrap();
    let plain = m.potential_per_mass(to) - m.potential_per_mass(from);
    assert!((plain - want).abs() > 1e-6 * want, "the plain difference is expected to lose digits here");
    assert!((m.potential_change_per_mass(from, to) - want).abs() < 1e-14 * want);
}
