//! Reduction (docs/theory.md §3) against the full Cartesian flow: the relations T-3.2 on TS², the sign of
//! the reduced flow T-3.4 pinned by the derivative of σ along T-2.2, the Nambu bracket, the
//! oscillator T-3.5, and the reduced flow with reconstruction T-3.6 as a third path to x(t).
//! Units: l = 1 m, g = 9.81 m/s² (rosette: θ₀ = 60°, φ̇₀ = 2 rad/s), σ in units of l.

use crate::common;

use common::rosette;
use pendulab_core::model::acceleration;
use pendulab_core::reduce::*;
use pendulab_core::{DVec3, Error, IdealPendulum, Method, Model, SolveOptions, State, Stepper};

fn trajectory_states(n: usize, dt: f64) -> Vec<(f64, State)> {
    let (m, s0) = rosette();
    let opts = SolveOptions { method: Method::Rattle8, dt: 1e-3, ..SolveOptions::default() };
    let mut st = Stepper::new(m, 0.0, s0, &opts).unwrap();
    (0..n)
        .map(|k| {
            st.step_to(k as f64 * dt).unwrap();
            (st.t(), st.state())
        })
        .collect()
}

#[test]
fn relations_hold_on_ts2() {
    for (_, s) in trajectory_states(50, 0.37) {
        let sig = invariants(1.0, &s);
        for (i, r) in relation_residuals(&sig).iter().enumerate() {
            assert!(r.abs() < 1e-13, "relation {i}: residual {r:e}");
        }
        assert!(sig[3] >= 0.0 && sig[2] >= sig[1] * sig[1]);
        assert!(casimir([sig[0], sig[1], sig[2]], sig[5]).abs() < 1e-13);
    }
}

#[test]
fn reduced_flow_is_the_derivative_along_the_full_flow() {
    // dσ/dt from T-2.2 exactly: σ̇₁ = ż, σ̇₂ = z̈, σ̇₃ = 2 v·a (l = 1). Pins the sign of T-3.4: Holm's
    // printed (H1.19)–(H1.21), the negative of this, must fail.
    let (m, _) = rosette();
    let g = m.params().g;
    for (t, s) in trajectory_states(40, 0.29) {
        let a = acceleration(&m, t, s.x, s.v);
        let along = [s.v.z, a.z, 2.0 * s.v.dot(a)];
        let sig = invariants(1.0, &s);
        let f = reduced_vector_field([sig[0], sig[1], sig[2]], g);
        for i in 0..3 {
            assert!(
                (f[i] - along[i]).abs() < 1e-12 * (1.0 + along[i].abs()),
                "component {i}: {f:?} vs {along:?}"
            );
        }
        let printed = f.map(|c| -c);
        assert!((0..3).any(|i| (printed[i] - along[i]).abs() > 1e-3), "the sign is not pinned at t = {t}");
        // σ̈₁ of the oscillator T-3.5 and its first integral
        let h = hamiltonian([sig[0], sig[1], sig[2]], g);
        assert!((oscillator_acceleration(sig[0], h, g) - a.z).abs() < 1e-12);
        assert!((oscillator_velocity_squared(sig[0], h, sig[5], g) - s.v.z * s.v.z).abs() < 1e-12);
    }
}

#[test]
fn nambu_bracket_generates_the_flow_and_conserves_h_and_c() {
    let g = 9.81;
    let sig = [-0.6, 0.8, 3.1];
    let (dh, dc) = gradients(sig, g);
    let f = reduced_vector_field(sig, g);
    // {σᵢ, H} = σ̇ᵢ
    for (i, e) in [DVec3::X, DVec3::Y, DVec3::Z].into_iter().enumerate() {
        assert!((nambu_bracket(e, sig, g) - f[i]).abs() < 1e-14);
    }
    assert!(nambu_bracket(dh, sig, g).abs() < 1e-14 && nambu_bracket(dc, sig, g).abs() < 1e-14);
}

#[test]
fn reduced_flow_with_reconstruction_reproduces_the_motion() {
    let (m, s0) = rosette();
    let dt = 1e-3;
    let path = reduced_flow(1.0, m.params().g, &s0, dt, 5000).unwrap();
    let reference = trajectory_states(6, 1.0);
    for (t, s) in reference {
        let k = (t / dt).round() as usize;
        let d = (path[k].x - s.x).length().max((path[k].v - s.v).length() / 3.13);
        eprintln!("t = {t}: reduced flow vs rattle8 {d:e}");
        assert!(d < 1e-9, "t = {t}: {d:e}");
    }
    let (h0, c0) =
        (hamiltonian([invariants(1.0, &s0)[0], 0.0, invariants(1.0, &s0)[2]], 9.81), invariants(1.0, &s0)[5]);
    let last = invariants(1.0, path.last().unwrap());
    assert!((hamiltonian([last[0], last[1], last[2]], 9.81) - h0).abs() < 1e-9);
    assert!((last[5] - c0).abs() < 1e-12);
}

#[test]
fn reduced_flow_refuses_a_pole() {
    let m = IdealPendulum::new(1.0, 1.0, 9.81).unwrap();
    let s0 = State::from_angles(m.params(), 0.5, 0.0, 1.0, 0.0).unwrap(); // planar: passes the bottom
    let err = reduced_flow(1.0, 9.81, &s0, 1e-3, 5000).unwrap_err();
    assert!(matches!(err, Error::ReducedFlowPole { .. }), "{err}");
    // a small J₃: the bob skims the bottom, φ̇ peaks near J₃/(m ρ_min²) and the step is refused there
    let skim = State::from_angles(m.params(), 0.5, 0.0, 1.0, 1e-3).unwrap();
    let err = reduced_flow(1.0, 9.81, &skim, 1e-3, 5000).unwrap_err();
    assert!(matches!(err, Error::ReducedFlowPole { t, .. } if t > 0.0), "{err}");
    assert!(err.to_string().contains("pole"));
    assert!(reduced_flow(1.0, 9.81, &s0, -1.0, 5).unwrap_err().to_string().contains("dt"));
}
