//! The adaptive ensemble (`ensemble::adaptive`): every trajectory of a damped, dragged and driven
//! pendulum is, bit for bit, the single-trajectory DOP853 run with the same settings; cancellation
//! and bad input. SI units.

use pendulab_core::ensemble::adaptive::{
    run_adaptive, run_adaptive_models, run_adaptive_serial, AdaptiveSettings, Models,
};
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

/// The single run of `start` with `m`, saved at `times` (as `simulate(..., save_at=times)`).
fn single(m: &AnyModel, start: &State, set: &AdaptiveSettings) -> (Vec<State>, u64, u64) {
    let save = SaveAt::Times(set.times.clone());
    let mut one = Solver::new(m.clone(), set.t0, *start, set.t_end, &set.options, save, 1 << 20).unwrap();
    one.stepper_mut().set_invariant_projection(set.conserve);
    while !one.advance(1000).unwrap() {}
    (one.take_samples().states, one.stats().steps, one.stats().rejected)
}

fn final_only(conserve: bool) -> AdaptiveSettings {
    let mut set = settings(conserve);
    set.times = vec![0.0, 5.0];
    set
}

#[test]
fn vectorised_lanes_are_the_single_runs_bit_for_bit() {
    // 37 starts: lanes refilled as trajectories finish and masked at the end of the chunk
    let m = model();
    let s = starts(&m, 37);
    for set in
        [final_only(false), final_only(true), AdaptiveSettings { times: vec![5.0], ..final_only(false) }]
    {
        let (p, c) = (AtomicU64::new(0), AtomicBool::new(false));
        let res = run_adaptive(&m, &s, &set, &p, &c).unwrap();
        assert!(!res.cancelled && p.load(Ordering::Relaxed) == 37);
        let ns = set.times.len();
        let mut rejected = 0;
        for (k, start) in s.iter().enumerate() {
            let (states, steps, rej) = single(&m, start, &set);
            assert_eq!(&res.states[k * ns..(k + 1) * ns], &states[..], "trajectory {k}");
            assert_eq!(res.steps[k], steps, "trajectory {k}");
            rejected += rej;
        }
        // the lanes had different step counts and rejections to handle
        assert!(res.steps.iter().min() != res.steps.iter().max() && rejected > 0, "{rejected}");
        // the serial path (one Solver per trajectory) agrees
        let serial = run_adaptive_serial(&Models::one(&m), &s, &set, &p, &c).unwrap();
        assert_eq!(serial.states, res.states);
    }
}

#[test]
fn per_trajectory_models_and_a_moving_pivot() {
    // three parameter sets (l, g, damping) and the index naming each trajectory's
    let build = |l: f64, g: f64, c: f64| {
        let p = Params::new(l, 1.0, g).unwrap();
        AnyModel::build("damped", p, &[("damping", c), ("drag", 0.2), ("forcing_amplitude", 0.5)]).unwrap()
    };
    let models = [build(0.8, 9.81, 0.05), build(1.7, 3.7, 0.0), build(0.5, 24.8, 0.4)];
    let index: Vec<u32> = (0..21).map(|k| (k * 7 % 3) as u32).collect();
    let s: Vec<State> = (0..21)
        .map(|k| {
            let m = &models[index[k] as usize];
            State::from_angles(m.params(), 0.1 + 0.13 * k as f64, 0.0, 0.4, 1.0 - 0.1 * k as f64).unwrap()
        })
        .collect();
    let set = final_only(false);
    let (p, c) = (AtomicU64::new(0), AtomicBool::new(false));
    let res = run_adaptive_models(&Models { models: &models, index: &index }, &s, &set, &p, &c).unwrap();
    for k in 0..21 {
        let (states, _, _) = single(&models[index[k] as usize], &s[k], &set);
        assert_eq!(&res.states[2 * k..2 * k + 2], &states[..], "trajectory {k}");
    }
    // a start on the wrong model's sphere and a bad index are refused before any work
    let mut wrong = index.clone();
    wrong[0] = 1;
    let err = run_adaptive_models(&Models { models: &models, index: &wrong }, &s, &set, &p, &c).unwrap_err();
    assert!(err.to_string().contains("length") || err.to_string().contains("|x|"), "{err}");
    wrong[0] = 3;
    let err = run_adaptive_models(&Models { models: &models, index: &wrong }, &s, &set, &p, &c).unwrap_err();
    assert!(err.to_string().contains("model index"), "{err}");
    let err =
        run_adaptive_models(&Models { models: &models, index: &index[1..] }, &s, &set, &p, &c).unwrap_err();
    assert!(err.to_string().contains("model index"), "{err}");
    // a moving pivot (time-dependent force, physical states differ from the integrator's)
    let pv = Params::new(1.0, 1.0, 9.81).unwrap();
    let vib = AnyModel::build("vibrating", pv, &[("amplitude", 0.02), ("frequency", 30.0)]).unwrap();
    let s = starts(&vib, 11);
    let res = run_adaptive(&vib, &s, &final_only(true), &p, &c).unwrap();
    for (k, start) in s.iter().enumerate() {
        assert_eq!(&res.states[2 * k..2 * k + 2], &single(&vib, start, &final_only(true)).0[..], "{k}");
    }
}

#[test]
fn a_sampled_pivot_ends_the_steps_on_its_samples_in_the_lanes_too() {
    // The spline's p̈ kinks at every sample: DOP853 ends a step on each (Model::next_break), in the
    // single run and in the vectorised lanes alike, bit for bit. Samples 0.07 s apart from t = −0.1 s,
    // with one a rounding error before t_end (skipped: a sliver of a step would underflow).
    let pv = Params::new(1.0, 1.0, 9.81).unwrap();
    let mut times: Vec<f64> = (0..73).map(|k| -0.1 + 0.07 * k as f64).collect();
    times.push(5.0 - 4e-15);
    times.extend([5.3, 5.6]);
    let positions: Vec<_> = times
        .iter()
        .map(|&t| pendulab_core::DVec3::new(0.3 * (1.3 * t).sin(), 0.2 * (0.7 * t).cos(), 0.05 * t * t))
        .collect();
    let m = AnyModel::sampled_pivot(pv, &times, &positions, 0.02).unwrap();
    assert_eq!(m.next_break(0.0), times[2]);
    assert_eq!(m.next_break(times[2]), times[3]);
    assert_eq!(m.next_break(times[2] - 1e-17), times[3], "a sample within round-off counts as reached");
    assert_eq!(m.next_break(5.6), f64::INFINITY, "the last sample is no kink (the end piece goes on)");
    // a pivot at rest has no kinks: its runs are the fixed pivot's, step for step
    let rest =
        AnyModel::sampled_pivot(pv, &times, &vec![pendulab_core::DVec3::ZERO; times.len()], 0.0).unwrap();
    assert_eq!(rest.next_break(0.0), f64::INFINITY);
    let s = starts(&m, 9);
    let set = AdaptiveSettings {
        options: SolveOptions { rtol: 1e-6, ..settings(false).options },
        ..final_only(false)
    };
    let (p, c) = (AtomicU64::new(0), AtomicBool::new(false));
    let res = run_adaptive(&m, &s, &set, &p, &c).unwrap();
    for (k, start) in s.iter().enumerate() {
        let (states, steps, _) = single(&m, start, &set);
        assert_eq!(&res.states[2 * k..2 * k + 2], &states[..], "trajectory {k}");
        assert_eq!(res.steps[k], steps, "trajectory {k}");
        // at rtol 1e-6 the free steps would be longer than 0.07 s: at least one per sample interval
        assert!(steps >= 72, "{steps} steps for 72 sample intervals in (0, 5)");
    }
}
