//! Starts at (or within round-off of) a turning point of z, where the exact solution once went
//! wrong: a small spherical swing started at its widest point (u̇₀ = 1e-21, P(u₀) at round-off)
//! came out conical, and a start at rest next to the top lost 1.2e-10 of its argument s₀ to
//! fl(π/2) (see `exact::amplitude_argument`). Reference: RATTLE8 at dt = 1e-3 s, and the
//! Weierstrass form (T-4.7). SI units, l = 1 m, g = 9.81 m/s².

use pendulab_core::exact::ExactSolution;
use pendulab_core::{IdealPendulum, Method, Model, SolveOptions, State, Stepper};

fn rattle8(m: IdealPendulum, s0: State, t: f64) -> State {
    let opts = SolveOptions { method: Method::Rattle8, dt: 1e-3, ..SolveOptions::default() };
    let mut st = Stepper::new(m, 0.0, s0, &opts).unwrap();
    st.step_to(t).unwrap();
    st.state()
}

#[test]
fn a_small_spherical_swing_started_at_its_widest_point_is_not_conical() {
    let m = IdealPendulum::new(1.0, 1.0, 9.81).unwrap();
    for amp in [1e-8, 1e-6, 1e-4, 1e-2, 0.3] {
        // φ̇ below the conical rate √(g/(l cos θ)): the bob falls inwards from its widest point
        let s0 = State::from_angles(m.params(), amp, 0.3, 0.0, 1.5).unwrap();
        let sol = ExactSolution::new(m.params(), &s0).unwrap();
        // the width u₂ − u₁ (dimensionless, anchored: below ulp(l) for the smallest amplitudes)
        let a = sol.generic().unwrap().a;
        assert!(a > 0.1 * (1.0 - amp.cos()), "amplitude {amp}: width {a:e} (conical?)");
        for t in [0.5, 2.0] {
            let (e, r) = (sol.state(t).unwrap(), rattle8(m, s0, t));
            let err = (e.x - r.x).length();
            assert!(
                err < 1e-9 * amp.max(1e-4),
                "amplitude {amp}, t = {t}: exact and RATTLE8 differ by {err:e} m"
            );
        }
    }
}

#[test]
fn a_start_at_rest_next_to_the_top_keeps_its_timing() {
    let m = IdealPendulum::new(1.0, 1.0, 9.81).unwrap();
    let s0 = State::from_angles(m.params(), std::f64::consts::PI - 1e-6, 0.4, 0.0, 0.0).unwrap();
    let sol = ExactSolution::new(m.params(), &s0).unwrap();
    // through the bottom pass (t ≈ 4.8 s), where a timing error shows most
    let t: Vec<f64> = (0..200).map(|i| 4.0 + 0.01 * i as f64).collect();
    let w = sol.height_weierstrass(&t).unwrap().unwrap();
    for (&ti, &(z, _)) in t.iter().zip(&w) {
        let dz = (sol.state(ti).unwrap().x.z - z).abs();
        assert!(dz < 1e-13, "t = {ti}: Jacobi and Weierstrass forms differ by {dz:e} m");
    }
}
