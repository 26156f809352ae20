//! `Stepper::set_halved_steps`: every fixed step (every sub-step on a sampled pivot) taken as two
//! equal halves, the dt/2 Richardson companion of the error estimate (docs/integrators.md, *Sampled
//! pivot*). On a model without breaks it is the run at dt/2 bit for bit; on a sampled pivot with dt
//! above the sample spacing its error is the plain run's / 2ᵖ, where a run at dt/2 is not.
//! SI units: l = 1 m, g = 9.81 m/s², samples every 10 ms.

use crate::common;

use common::fixed;
use common::sampled::{path, start};
use pendulab_core::model::registry::AnyModel;
use pendulab_core::{IdealPendulum, Method, SolveOptions, Stepper};

#[test]
fn halved_steps_are_the_half_step_run_bit_for_bit_without_breaks() {
    let m = IdealPendulum::new(1.0, 1.0, 9.81).unwrap();
    for method in [Method::Rattle, Method::Rattle8, Method::Rk4, Method::Rkmk4] {
        let mut halved = Stepper::new(m, 0.0, start(), &fixed(method, 0.02)).unwrap();
        halved.set_halved_steps(true);
        halved.step_n(100).unwrap();
        let mut half = Stepper::new(m, 0.0, start(), &fixed(method, 0.01)).unwrap();
        half.step_n(200).unwrap();
        assert_eq!(halved.state(), half.state(), "{method:?}");
        assert_eq!(halved.t(), 2.0);
        assert_eq!(halved.stats().steps, 200, "{method:?}: the halves are counted");
        assert_eq!(halved.stats().rhs_evals, half.stats().rhs_evals, "{method:?}");
        // one step at a time (`step_towards`, the save_at path) too
        let mut one = Stepper::new(m, 0.0, start(), &fixed(method, 0.02)).unwrap();
        one.set_halved_steps(true);
        one.step_to(2.0).unwrap();
        assert_eq!(one.state(), half.state(), "{method:?}: step_to");
    }
}

/// The path (0.3 sin 1.3t, 0.2 sin(0.7t + 0.5), 0.1 cos 2t) m sampled every 10 ms, damping 0.03 1/s.
fn sampled() -> AnyModel {
    let times: Vec<f64> = (0..=320).map(|k| -0.1 + 0.01 * k as f64).collect();
    path(&times)
}

#[test]
fn on_a_sampled_pivot_halved_steps_cut_the_error_by_two_to_the_order() {
    // dt = 16 ms on 10-ms samples: every step splits. Halving each (sub-)step divides the error by
    // 2ᵖ; a run at dt/2 splits elsewhere and divides it by Σh^{p+1}/Σh'^{p+1} = 2.9 (rk4), 1.75
    // (rattle): the error estimate that assumed 2ᵖ read 0.70, 0.57 of the truth
    let m = sampled();
    let o = SolveOptions { method: Method::Dop853, dt: 0.0, rtol: 1e-14, atol: 1e-14, project: true };
    let mut reference = Stepper::new(m.clone(), 0.0, start(), &o).unwrap();
    reference.step_to(3.2).unwrap();
    let want = reference.state().x;
    for (method, p) in [(Method::Rk4, 4), (Method::Rattle, 2), (Method::Rattle4, 4)] {
        let error = |dt: f64, halved: bool| {
            let mut st = Stepper::new(m.clone(), 0.0, start(), &fixed(method, dt)).unwrap();
            st.set_halved_steps(halved);
            let n = (3.2 / dt).round() as u64;
            st.step_n(n).unwrap();
            assert_eq!(st.t(), n as f64 * dt);
            (st.state().x - want).length()
        };
        let plain = error(0.016, false);
        let ratio = plain / error(0.016, true);
        let expected = 2f64.powi(p);
        assert!((ratio / expected - 1.0).abs() < 0.05, "{method:?}: plain / halved = {ratio}, not 2^{p}");
        // the run at dt/2 does not halve the sub-steps the samples bound: far from 2ᵖ
        let at_half = plain / error(0.008, false);
        assert!(at_half < 0.75 * expected, "{method:?}: plain / (dt/2 run) = {at_half}");
    }
}
