//! A `Stepper` with `set_steps_on_breaks` driven by hand, as `pl.Stepper(..., steps_on_samples=True)`
//! drives it: any mix of `step`, `step_n` and `step_to` gives the `Solver`'s run saved at the times it
//! reached bit for bit (so the Python `Stepper` reproduces `pl.simulate`), and after `set_state` the
//! stretch to the next sample is planned again from there: every step still ends on a sample or
//! inside an interval between samples, in ⌈span/dt⌉ equal steps (docs/integrators.md, *Sampled
//! pivot*). SI units: l = 1 m, g = 9.81 m/s², samples 7 … 13 ms apart.

use crate::common;

use common::fixed;
use common::sampled::{params, path, start};
use pendulab_core::model::registry::AnyModel;
use pendulab_core::solve::DEFAULT_MAX_SAVED_BYTES;
use pendulab_core::{Method, SaveAt, Solver, State, Stepper};

/// Samples 10 ms ± 30 % apart (7 … 13 ms, golden-ratio sequence) from −0.05 s past 3.3 s, one at t = 0.
fn uneven() -> Vec<f64> {
    let mut times = vec![-0.05, 0.0];
    for k in 1.. {
        let last = times[times.len() - 1];
        if last > 3.3 {
            break;
        }
        times.push(last + 0.01 * (1.0 + 0.6 * ((k as f64 * 0.618_033_988_749_895).fract() - 0.5)));
    }
    times
}

/// A stepper on the samples of `m` at the longest step `dt` [s].
fn on_samples(m: &AnyModel, method: Method, dt: f64) -> Stepper<AnyModel> {
    let mut st = Stepper::new(m.clone(), 0.0, start(), &fixed(method, dt)).unwrap();
    st.set_steps_on_breaks(true);
    st
}

#[test]
fn steps_by_hand_give_the_solvers_run_saved_at_the_times_reached_bit_for_bit() {
    let times = uneven();
    let m = path(&times);
    let dt = 0.004;
    for method in [Method::Rk4, Method::Rattle, Method::Rattle4, Method::Rattle8] {
        let mut st = on_samples(&m, method, dt);
        let (mut reached, mut states) = (vec![0.0], vec![st.state()]);
        for round in 0..60 {
            match round % 3 {
                0 => st.step_n(7).unwrap(),
                1 => st.step_to(st.t() + 0.0123).unwrap(), // its last step shortened, between samples
                _ => st.step().unwrap(),
            }
            reached.push(st.t());
            states.push(st.state());
        }
        let t_end = reached[reached.len() - 1];
        let save = SaveAt::Times(reached.clone());
        let mut solver =
            Solver::new(m.clone(), 0.0, start(), t_end, &fixed(method, dt), save, DEFAULT_MAX_SAVED_BYTES)
                .unwrap();
        solver.stepper_mut().set_steps_on_breaks(true);
        while !solver.advance(1 << 20).unwrap() {}
        let saved = solver.take_samples();
        assert_eq!(saved.t, reached, "{method:?}: the times");
        assert_eq!(saved.states, states, "{method:?}: the states, bit for bit");
        assert_eq!(solver.stats(), st.stats(), "{method:?}: the same steps");
    }
}

/// The ends of `st`'s steps (`step`) from its time until `t_stop` [s] or past it, its time first.
fn step_ends(st: &mut Stepper<AnyModel>, t_stop: f64) -> Vec<f64> {
    let mut ends = vec![st.t()];
    while st.t() < t_stop {
        st.step().unwrap();
        ends.push(st.t());
    }
    ends
}

/// Every interval from `ends[0]` or a sample to the next sample, up to the last end, is taken in
/// n = ⌈span/dt⌉ equal steps (to 1e-12 s), as `stretches::plan` plans it.
fn assert_on_the_samples(ends: &[f64], times: &[f64], dt: f64) {
    let last = ends[ends.len() - 1];
    let mut marks = vec![ends[0]];
    marks.extend(times.iter().copied().filter(|&t| t > ends[0] + 1e-9 * dt && t <= last + 1e-12));
    let mut i = 0;
    for w in marks.windows(2) {
        let (a, b) = (w[0], w[1]);
        assert!((ends[i] - a).abs() <= 1e-12, "a step ends on {a}: {}", ends[i]);
        let n = ((b - a - 1e-9 * dt) / dt).ceil() as usize;
        for j in 1..=n {
            let want = a + j as f64 * (b - a) / n as f64;
            assert!((ends[i + j] - want).abs() <= 1e-12, "[{a}, {b}]: step {j} ends at {}", ends[i + j]);
        }
        i += n;
    }
}

#[test]
fn after_set_state_the_steps_land_on_every_sample_again() {
    // set_state between samples (after a shortened step_to), on the grid inside an interval (after
    // step_n) and on a sample: each time the steps go on to the next sample in equal steps of at
    // most dt, and on from there
    let times = uneven();
    let m = path(&times);
    let dt = 0.004;
    for method in [Method::Rk4, Method::Rattle4] {
        let mut st = on_samples(&m, method, dt);
        st.step_to(1.0047).unwrap();
        for t_stop in [1.5, 2.0, 2.5] {
            let dragged = State::from_angles(&params(), 0.7, -0.3, 0.2, 1.0).unwrap();
            st.set_state(dragged);
            let ends = step_ends(&mut st, t_stop);
            assert_on_the_samples(&ends, &times, dt);
            st.step_n(2).unwrap(); // to a grid point inside an interval, or onto a sample
        }
        let on_a_sample = times.iter().copied().find(|&t| t > st.t() + dt).unwrap();
        st.step_to(on_a_sample).unwrap();
        st.set_state(start());
        assert_on_the_samples(&step_ends(&mut st, 3.0), &times, dt);
    }
}
