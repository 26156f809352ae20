//! The instruction-set levels of `pendulab_core::isa` give the same numbers bit for bit: every
//! method through the stepper (loop and single steps, DOP853's dense output), the ensemble kernels
//! (RATTLE and its order-4 composition with damping and a summary, both arithmetics; DOP853 vectorised
//! across trajectories), the string stepper,
//! and the exact solution of every kind (single states and batches, the parallel path included),
//! once at the best level of this CPU, once restricted to the baseline (the plain fallback an
//! older CPU runs) and, on a CPU with AVX-512, once capped at x86-64-v3 (`isa::set_max_level`: what
//! an AVX2-only CPU runs; the ensemble's tiles differ per level and arithmetic). One test in its own binary, because the restriction is process-wide. SI units;
//! rosette-like starts.

use pendulab_core::ensemble::adaptive::{run_adaptive, AdaptiveSettings};
use pendulab_core::ensemble::{run, EnsembleSave, RattleSettings, LANES};
use pendulab_core::exact::ExactSolution;
use pendulab_core::integrate::rattle_kernel::Arithmetic;
use pendulab_core::isa::{self, Level};
use pendulab_core::model::{AnyModel, StringPendulum};
use pendulab_core::string_run::StringStepper;
use pendulab_core::{DVec3, IdealPendulum, Method, Params, SolveOptions, State, Stepper};
use std::sync::atomic::{AtomicBool, AtomicU64};

fn start(params: &Params, k: usize) -> State {
    State::from_angles(params, 0.4 + 0.2 * k as f64, 0.1 * k as f64, 0.3, 1.5 - 0.1 * k as f64).unwrap()
}

/// Every result the dispatched loops produce, as bits.
fn everything() -> Vec<u64> {
    let mut out = Vec::new();
    let push = |out: &mut Vec<u64>, s: &State| {
        out.extend([s.x, s.v].iter().flat_map(|w| w.to_array()).map(f64::to_bits))
    };
    let params = Params::new(1.3, 1.0, 9.81).unwrap();
    for method in Method::ALL {
        let opts = SolveOptions { method, dt: 2e-3, rtol: 1e-9, atol: 1e-11, ..SolveOptions::default() };
        let damped = AnyModel::build("damped", params, &[("damping", 0.2)]).unwrap();
        let ideal = IdealPendulum::new(params.length, params.mass, params.g).unwrap();
        let mut a = Stepper::new(ideal, 0.0, start(&params, 1), &opts).unwrap();
        a.step_n(700).unwrap();
        push(&mut out, &a.state());
        a.step_to(a.t() + 0.0123).unwrap();
        push(&mut out, &a.state());
        if method == Method::Dop853 {
            let (t0, t1) = (a.t(), {
                a.step().unwrap();
                a.t()
            });
            push(&mut out, &a.dense_output(0.7 * t0 + 0.3 * t1).unwrap());
        }
        if method != Method::Rk4Angles {
            let mut b = Stepper::new(damped, 0.0, start(&params, 2), &opts).unwrap();
            b.step_n(500).unwrap();
            push(&mut out, &b.state());
        }
    }
    let starts: Vec<State> = (0..LANES + 3).map(|k| start(&params, k % 7)).collect();
    let damping: Vec<f64> = (0..starts.len()).map(|k| 0.01 * (k % 4) as f64).collect();
    let set = RattleSettings {
        damping: &damping,
        settle_angle: Some(0.3),
        save: EnsembleSave::Every(500),
        with_summary: true,
        ..RattleSettings::new(&[1.3], &[9.81], 1e-3, 1500)
    };
    let (p, c) = (AtomicU64::new(0), AtomicBool::new(false));
    // both arithmetics: their tiles differ per level (ensemble::tile_lanes)
    for arithmetic in [Arithmetic::Unfused, Arithmetic::Fused] {
        let res = run(&starts, &RattleSettings { arithmetic, ..set }, &p, &c).unwrap();
        res.states.iter().for_each(|s| push(&mut out, s));
        for s in res.summary.unwrap() {
            out.extend([s.z.0, s.z.1, s.energy_per_mass.0, s.energy_per_mass.1].map(f64::to_bits));
        }
        out.extend(res.settle_time.unwrap().into_iter().map(f64::to_bits));
        // a composition's sub-steps (forward and backward, their own damping factors) in the same tiles
        let set4 = RattleSettings { arithmetic, method: Method::Rattle4, n_steps: 300, ..set };
        run(&starts, &set4, &p, &c).unwrap().states.iter().for_each(|s| push(&mut out, s));
    }
    // the DOP853 ensemble, vectorised across trajectories (ensemble/adaptive_lanes.rs)
    let damped = AnyModel::build("damped", params, &[("damping", 0.2), ("drag", 0.1)]).unwrap();
    let options = SolveOptions { method: Method::Dop853, dt: 0.0, rtol: 1e-9, atol: 1e-11, project: true };
    let set = AdaptiveSettings { options, t0: 0.0, t_end: 2.0, times: vec![0.0, 2.0], conserve: false };
    let res = run_adaptive(&damped, &starts, &set, &p, &c).unwrap();
    res.states.iter().for_each(|s| push(&mut out, s));
    let string = StringPendulum::new(params, 0.0).unwrap();
    let mut st = StringStepper::new(string, 0.0, start(&params, 6), Method::Rattle, 1e-3).unwrap();
    st.step(3000).unwrap();
    push(&mut out, &st.state());
    exact_states(&mut out);
    out
}

/// Exact states of every kind of motion (T-4.6) at single times and in batches (serial and
/// parallel), as bits: positions, velocities and azimuths.
fn exact_states(out: &mut Vec<u64>) {
    let params = Params::new(1.3, 1.0, 9.81).unwrap();
    let w0 = params.omega0();
    let x = |theta: f64| DVec3::new(1.3 * theta.sin(), 0.0, -1.3 * theta.cos());
    let starts = [
        State { x: x(1.0), v: DVec3::new(0.3, 2.1, 0.4) }, // generic
        State { x: x(2.4), v: DVec3::new(0.0, 0.9, 0.0) }, // generic, above the equator
        State { x: x(0.7), v: DVec3::new(0.0, 1.3 * w0 * 0.7f64.sin() * 1.2, 0.0) }, // near conical
        State { x: x(0.9), v: DVec3::new(0.5 * 0.9f64.cos(), 0.0, 0.5 * 0.9f64.sin()) }, // planar
        State { x: x(0.2), v: DVec3::new(9.0 * 0.2f64.cos(), 0.0, 9.0 * 0.2f64.sin()) }, // over the top
        State { x: x(1e-3), v: DVec3::new(1e-6, 0.0, 0.0) }, // small swing
        State { x: DVec3::new(0.0, 0.0, -1.3), v: DVec3::new(2.0 * 1.3 * w0, 0.0, 0.0) }, // separatrix
    ];
    let times: Vec<f64> = (0..5000).map(|k| -37.0 + 0.0173 * k as f64 + 1e-3 * (k % 7) as f64).collect();
    for s0 in starts {
        let s0 = State::projected(&params, s0.x, s0.v).unwrap().0;
        let sol = ExactSolution::new(&params, &s0).unwrap();
        let mut push = |(s, phi): (State, f64)| {
            out.extend([s.x, s.v].iter().flat_map(|w| w.to_array()).map(f64::to_bits));
            out.push(phi.to_bits());
        };
        for t in [0.0, 0.31, -2.7, 1e3, 1e7] {
            push(sol.state_and_azimuth(t).unwrap());
        }
        sol.states_at(&times[..100]).unwrap().into_iter().for_each(&mut push);
        sol.states_at(&times).unwrap().into_iter().for_each(&mut push);
    }
}

#[test]
fn every_instruction_set_level_gives_the_same_bits() {
    let best_level = isa::detected();
    assert_eq!(isa::selected(), best_level.name());
    let best = everything();
    isa::set_baseline_only(true);
    assert_eq!((isa::current(), isa::selected()), (Level::Baseline, "baseline"));
    let baseline = everything();
    // x86-64-v3 on a CPU with AVX-512 too (set_max_level): the AVX2 loops an AVX2-only CPU runs
    let mut capped = vec![];
    if best_level > Level::V3 {
        isa::set_max_level(Level::V3);
        assert_eq!((isa::current(), isa::selected()), (Level::V3, "x86-64-v3"));
        capped.push((Level::V3, everything()));
    }
    isa::set_baseline_only(false);
    assert_eq!(isa::current(), best_level);
    for (level, bits) in [(best_level, &best)].into_iter().chain(capped.iter().map(|(l, b)| (*l, b))) {
        assert_eq!(bits.len(), baseline.len());
        let differ = bits.iter().zip(&baseline).filter(|(a, b)| a != b).count();
        let name = level.name();
        assert_eq!(differ, 0, "{differ} of {} numbers differ between {name} and the baseline", bits.len());
        eprintln!("{name} and baseline agree on {} numbers", bits.len());
    }
}
