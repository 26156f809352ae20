//! The adaptive ensemble (`ensemble::adaptive`): every trajectory of a damped, dragged and driven
//! pendulum is, bit for bit, the single-trajectory DOP853 run with the same settings; cancellation
//! and bad input. SI units.

use pendulab_core::ensemble::adaptive::{run_adaptive, AdaptiveSettings};
use pendulab_core::model::AnyModel;
use pendulab_core::{Method, Model, Params, SaveAt, SolveOptions, Solver, State};
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};

fn model() -> AnyModel {
    let p = Params::new(0.8, 1.0, 9.81).unwrap();
    let extra = [("damping", 0.05), ("drag", 0.3), ("forcing_amplitude", 0.8), ("forcing_omega", 3.1)];
    AnyModel::build("damped", p, &extra).unwrap()
}

fn starts(m: &AnyModel, n: usize) -> Vec<State> {
    (0..n)
        .map(|k| {
            let f = k as f64 / n as f64;
            State::from_angles(m.params(), 0.2 + 2.5 * f, 0.3 * k as f64, 0.5 - f, 2.0 * f - 0.7).unwrap()
        })
        .collect()
}

fn settings(conserve: bool) -> AdaptiveSettings {
    let options = SolveOptions { method: Method::Dop853, dt: 0.0, rtol: 1e-9, atol: 1e-11, project: true };
    AdaptiveSettings { options, t0: 0.0, t_end: 5.0, times: vec![0.0, 1.5, 5.0], conserve }
}

#[test]
fn every_trajectory_is_the_single_dop853_run_bit_for_bit() {
    let m = model();
    let s = starts(&m, 37);
    let set = settings(false);
    let (p, c) = (AtomicU64::new(0), AtomicBool::new(false));
    let res = run_adaptive(&m, &s, &set, &p, &c).unwrap();
    assert!(!res.cancelled && p.load(Ordering::Relaxed) == 37);
    for (k, start) in s.iter().enumerate() {
        let save = SaveAt::Times(set.times.clone());
        let mut one = Solver::new(m.clone(), 0.0, *start, 5.0, &set.options, save, 1 << 20).unwrap();
        while !one.advance(1000).unwrap() {}
        let single = one.take_samples();
        assert_eq!(single.t, set.times);
        assert_eq!(&res.states[k * 3..k * 3 + 3], &single.states[..], "trajectory {k}");
        assert_eq!(res.steps[k], one.stats().steps);
    }
    // the trajectories differ (the forcing and drag act): not one answer repeated
    assert!(res.states[2] != res.states[5]);
}

#[test]
fn cancelled_runs_stop_and_bad_input_is_named() {
    let m = model();
    let s = starts(&m, 8);
    let (p, c) = (AtomicU64::new(0), AtomicBool::new(true));
    let mut set = settings(false);
    set.t_end = 1e6;
    set.times = vec![0.0, 1e6];
    let res = run_adaptive(&m, &s, &set, &p, &c).unwrap();
    assert!(res.cancelled && res.states[1].x.is_nan() && p.load(Ordering::Relaxed) == 0);
    let c = AtomicBool::new(false);
    let mut bad = settings(false);
    bad.options.rtol = -1.0;
    let err = run_adaptive(&m, &s, &bad, &p, &c).unwrap_err().to_string();
    assert!(err.contains("rtol"), "{err}");
    let off = [State { x: s[0].x * 1.1, v: s[0].v }];
    let err = run_adaptive(&m, &off, &settings(false), &p, &c).unwrap_err().to_string();
    assert!(err.contains("length") || err.contains("sphere") || err.contains("|x|"), "{err}");
}
