//! Instruction-count probe of the core's hot paths (`bench/instructions.py`): runs one path a given
//! number of times and nothing else, so that the difference of two runs' instruction counts under
//! valgrind, divided by the difference of their counts, is the cost of one unit of the path without
//! start-up. Copied by the script into each measured tree as the example `instr_probe` (with the
//! `api.rs` that fits that tree's ensemble signature) and built there in release.
//!
//! Paths (rosette start: l = 1 m, g = 9.81 m/s², θ₀ = 60°, φ̇₀ = 2 rad/s; unit of COUNT in brackets):
//! `rattle_step` (`Stepper::step`, dt = 1 ms) [step], `rattle_step_n` (`Stepper::step_n`) [step],
//! `dop853_step` (`Stepper::step`, rtol 1e-10, atol 1e-12) [accepted step], `ensemble_block` (192
//! starts: whole blocks both of 64 lanes, before 2026-11-27, and of 48, since; θ₀ from 0.1 to 2.9
//! rad, φ̇₀ = 1 rad/s, RATTLE dt = 1 ms, final states, one thread) [step of the 192], `exact_setup` (`ExactSolution::new`) [call], `exact_state`
//! (`ExactSolution::state`) [call], `exact_states_at` (`states_at`, one thread) [time].
//! A trailing `baseline` runs at the baseline instruction set (`isa::set_baseline_only`).
//! Usage: `instr_probe PATH COUNT [baseline]`. SI units throughout.

mod api;

use pendulab_core::exact::ExactSolution;
use pendulab_core::{isa, IdealPendulum, Method, Model, SolveOptions, State, Stepper};
use std::hint::black_box;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let path = args.first().expect("usage: instr_probe PATH COUNT [baseline]");
    let count: u64 = args.get(1).and_then(|c| c.parse().ok()).expect("COUNT: a whole number");
    isa::set_baseline_only(args.get(2).is_some_and(|b| b == "baseline"));
    let model = IdealPendulum::new(1.0, 1.0, 9.81).unwrap();
    let s0 = State::from_angles(model.params(), 60f64.to_radians(), 0.0, 0.0, 2.0).unwrap();
    let rattle = SolveOptions { method: Method::Rattle, dt: 1e-3, ..SolveOptions::default() };
    let dop = SolveOptions { method: Method::Dop853, dt: 0.0, rtol: 1e-10, atol: 1e-12, project: true };
    let pool = rayon::ThreadPoolBuilder::new().num_threads(1).build().unwrap();
    match path.as_str() {
        "rattle_step" => {
            let mut st = Stepper::new(model, 0.0, s0, &rattle).unwrap();
            for _ in 0..count {
                st.step().unwrap();
            }
            black_box(st.state().x);
        }
        "rattle_step_n" => {
            let mut st = Stepper::new(model, 0.0, s0, &rattle).unwrap();
            st.step_n(black_box(count)).unwrap();
            black_box(st.state().x);
        }
        "dop853_step" => {
            let mut st = Stepper::new(model, 0.0, s0, &dop).unwrap();
            for _ in 0..count {
                st.step().unwrap();
            }
            black_box(st.state().x);
        }
        "ensemble_block" => {
            let n = 192;
            let starts: Vec<State> = (0..n)
                .map(|k| State::from_angles(model.params(), 0.1 + 2.8 * k as f64 / n as f64, 0.0, 0.0, 1.0).unwrap())
                .collect();
            pool.install(|| api::ensemble_final(black_box(&starts), 1e-3, count));
        }
        "exact_setup" => {
            for k in 0..count {
                let s = State::from_angles(model.params(), 60f64.to_radians(), 0.0, 0.0, 2.0 + 1e-9 * k as f64);
                black_box(ExactSolution::new(model.params(), &s.unwrap()).unwrap());
            }
        }
        "exact_state" => {
            let sol = ExactSolution::new(model.params(), &s0).unwrap();
            for k in 0..count {
                black_box(sol.state(black_box(0.37 * k as f64)).unwrap());
            }
        }
        "exact_states_at" => {
            let sol = ExactSolution::new(model.params(), &s0).unwrap();
            let times: Vec<f64> = (0..count).map(|k| k as f64 * 0.01).collect();
            black_box(pool.install(|| sol.states_at(black_box(&times)).unwrap()));
        }
        other => panic!("unknown path {other}"),
    }
    eprintln!("isa {}", isa::selected());
}
