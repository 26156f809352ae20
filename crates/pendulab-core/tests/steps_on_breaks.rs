//! `Stepper::set_steps_on_breaks`: dt the longest fixed step, the steps landing on every sample of a
//! sampled pivot (each interval between samples in ⌈span/dt⌉ equal steps), as `accuracy=` runs them
//! (docs/integrators.md, *Sampled pivot*). SI units: l = 1 m, g = 9.81 m/s², samples about 10 ms apart.

use crate::common;

use common::fixed;
use common::sampled::{path as sampled, start};
use pendulab_core::model::registry::AnyModel;
use pendulab_core::{DVec3, Method, SolveOptions, Stepper};

/// Samples 10 ms ± 30 % apart (7 … 13 ms, golden-ratio sequence) from −0.05 s past 3.3 s, with one at
/// t = 0 (the runs' start, as `accuracy=` starts on a sample when one is there).
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

fn reference(m: &AnyModel, t_end: f64) -> DVec3 {
    let o = SolveOptions { method: Method::Dop853, dt: 0.0, rtol: 1e-14, atol: 1e-14, project: true };
    let mut st = Stepper::new(m.clone(), 0.0, start(), &o).unwrap();
    st.step_to(t_end).unwrap();
    st.state().x
}

#[test]
fn every_step_ends_on_a_sample_or_inside_an_interval_in_equal_steps_of_at_most_dt() {
    let times = uneven();
    let m = sampled(&times);
    let dt = 0.004;
    let mut st = Stepper::new(m, 0.0, start(), &fixed(Method::Rattle4, dt)).unwrap();
    st.set_steps_on_breaks(true);
    let mut ends = vec![0.0];
    while st.t() < 3.0 {
        st.step_towards(3.0).unwrap();
        ends.push(st.t());
    }
    let inner: Vec<f64> = times.iter().copied().filter(|&t| t > 0.0 && t < 3.0).collect();
    let mut planned = 0;
    for w in times.windows(2).filter(|w| w[0] >= 0.0 && w[0] < 3.0) {
        // the interval that holds t_end = 3 s too (its last step shortened to land there)
        let (a, b) = (w[0], w[1]);
        let n = ((b - a) / dt).ceil() as usize;
        let i = ends.iter().position(|&t| (t - a).abs() <= 1e-12).expect("a step ends on every sample");
        for j in 1..=n {
            let want = (a + j as f64 * (b - a) / n as f64).min(3.0);
            assert!((ends[i + j] - want).abs() <= 1e-12, "[{a}, {b}]: step {j} ends at {}", ends[i + j]);
            planned += 1;
            if want == 3.0 {
                break;
            }
        }
    }
    assert_eq!(ends.len() - 1, planned, "{} samples inside the run", inner.len());
    assert_eq!(st.stats().steps, planned as u64, "no step split");
}

#[test]
fn evenly_spaced_samples_on_the_grid_give_the_plain_run_bit_for_bit() {
    // samples every 10 ms, dt = 10/4 ms: the grid ends on every sample, as accuracy= chooses it
    let times: Vec<f64> = (0..=330).map(|k| -0.1 + 0.01 * k as f64).collect();
    let m = sampled(&times);
    for method in [Method::Rattle8, Method::Rk4] {
        for halved in [false, true] {
            let run = |on: bool, by_n: bool| {
                let mut st = Stepper::new(m.clone(), 0.0, start(), &fixed(method, 0.0025)).unwrap();
                st.set_halved_steps(halved);
                st.set_steps_on_breaks(on);
                if by_n {
                    st.step_n(1200).unwrap();
                } else {
                    st.step_to(2.999).unwrap(); // the last step shortened
                }
                (st.t(), st.state(), st.stats())
            };
            assert_eq!(run(true, true), run(false, true), "{method:?} halved {halved}: step_n");
            assert_eq!(run(true, false), run(false, false), "{method:?} halved {halved}: step_to");
        }
    }
}

#[test]
fn halving_dt_halves_every_step_and_the_error_falls_at_the_methods_order() {
    // dt = 13 ms ≥ every interval: one step per interval; dt/2 = 6.5 ms < every interval: two. The
    // observed order is the method's. The plain grid splits its steps on the samples instead; at
    // these dt its steps do not shrink with dt, and its observed order was 2.2 (rk4), 1.1 (rattle)
    let times = uneven();
    let m = sampled(&times);
    let want = reference(&m, 3.0);
    for (method, p) in [(Method::Rk4, 4.0), (Method::Rattle, 2.0), (Method::Rattle4, 4.0)] {
        let error = |dt: f64, on: bool| {
            let mut st = Stepper::new(m.clone(), 0.0, start(), &fixed(method, dt)).unwrap();
            st.set_steps_on_breaks(on);
            st.step_to(3.0).unwrap();
            (st.state().x - want).length()
        };
        let order = |on: bool| (error(0.013, on) / error(0.0065, on)).log2();
        let (on, plain) = (order(true), order(false));
        assert!((on - p).abs() < 0.15, "{method:?}: observed order {on} with steps on the samples");
        assert!(plain < p - 0.5, "{method:?}: observed order {plain} on the split grid");
    }
}
