//! The ensemble kernel: each trajectory gets exactly the numbers of the single-trajectory RATTLE
//! (same operations, so bit-for-bit), per-trajectory l and g, saving rules, summaries, cancellation
//! and bad input. SI units; ideal pendulum.

use pendulab_core::ensemble::{run, EnsembleSave, LANES};
use pendulab_core::model::energy;
use pendulab_core::{IdealPendulum, Method, Model, SolveOptions, State, Stepper};
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};

fn starts(n: usize, length: f64) -> Vec<State> {
    let m = IdealPendulum::new(length, 1.0, 9.81).unwrap();
    (0..n)
        .map(|k| {
            let f = k as f64 / n as f64;
            State::from_angles(m.params(), 0.2 + 2.5 * f, 0.3 * k as f64, 0.5 - f, 2.0 * f - 0.7).unwrap()
        })
        .collect()
}

#[test]
fn every_trajectory_matches_the_single_path_bit_for_bit() {
    let n = 2 * LANES + 7; // a partial last block too
    let s = starts(n, 1.0);
    let lengths: Vec<f64> = (0..n).map(|k| 0.5 + k as f64 / n as f64).collect();
    let gs: Vec<f64> = (0..n).map(|k| 9.81 - 3.0 * k as f64 / n as f64).collect();
    // rescale starts onto each length
    let s: Vec<State> = s.iter().zip(&lengths).map(|(st, &l)| State { x: st.x * l, v: st.v * l }).collect();
    let (p, c) = (AtomicU64::new(0), AtomicBool::new(false));
    let res = run(&s, &lengths, &gs, 1e-3, 3000, EnsembleSave::Every(1000), true, &p, &c).unwrap();
    assert_eq!(res.t, vec![0.0, 1.0, 2.0, 3.0]);
    assert_eq!(p.load(Ordering::Relaxed), 3000 * n as u64);
    for k in [0, 1, LANES - 1, LANES, n - 1] {
        let m = IdealPendulum::new(lengths[k], 1.0, gs[k]).unwrap();
        let opts = SolveOptions { method: Method::Rattle, dt: 1e-3, ..SolveOptions::default() };
        let mut st = Stepper::new(m, 0.0, s[k], &opts).unwrap();
        for (j, &t) in res.t.iter().enumerate() {
            st.step_to(t).unwrap();
            assert_eq!(res.states[k][j], *st.state(), "trajectory {k} at t = {t}");
        }
        let sum = res.summary.as_ref().unwrap()[k];
        let e = energy(&m, st.state());
        assert!(sum.energy_per_mass.0 <= e && e <= sum.energy_per_mass.1);
        assert!(sum.z.0 >= -lengths[k] - 1e-12 && sum.z.1 <= lengths[k] + 1e-12);
        assert!(sum.j3_per_mass.1 - sum.j3_per_mass.0 < 1e-13, "J₃ not conserved: {sum:?}");
    }
}

#[test]
fn final_only_and_cancellation() {
    let s = starts(100, 1.0);
    let (p, c) = (AtomicU64::new(0), AtomicBool::new(false));
    let res = run(&s, &[1.0], &[9.81], 1e-3, 2500, EnsembleSave::Final, false, &p, &c).unwrap();
    assert_eq!(res.t, vec![0.0, 2.5]);
    assert!(res.states.iter().all(|t| t.len() == 2) && res.summary.is_none() && !res.cancelled);
    c.store(true, Ordering::Relaxed);
    let res = run(&s, &[1.0], &[9.81], 1e-3, 1_000_000, EnsembleSave::Final, false, &p, &c).unwrap();
    assert!(res.cancelled && res.steps < 1_000_000);
}

#[test]
fn bad_input_is_named() {
    let s = starts(3, 1.0);
    let (p, c) = (AtomicU64::new(0), AtomicBool::new(false));
    let e = |r: Result<_, pendulab_core::Error>| {
        r.map(|_: pendulab_core::ensemble::EnsembleResult| ()).unwrap_err().to_string()
    };
    assert!(e(run(&s, &[1.0, 2.0], &[9.81], 1e-3, 10, EnsembleSave::Final, false, &p, &c)).contains("length"));
    assert!(e(run(&s, &[1.0], &[9.81], -1.0, 10, EnsembleSave::Final, false, &p, &c)).contains("dt"));
    assert!(
        e(run(&s, &[1.0], &[9.81], 1e-3, 10, EnsembleSave::Every(0), false, &p, &c)).contains("save_every")
    );
    assert!(e(run(&s, &[2.0], &[9.81], 1e-3, 10, EnsembleSave::Final, false, &p, &c)).contains("TS"));
    assert!(e(run(&s, &[1.0], &[9.81], 50.0, 10, EnsembleSave::Final, false, &p, &c)).contains("non-finite"));
}
