//! The kernel side of the roofline (`bench/roofline/run.py`): wall-clock rates of the hot kernels,
//! without Python in the way, printed as one JSON object. Every figure is the best of `reps` timed
//! runs (the least disturbed one on a shared machine; the caller notes the load):
//!
//! - `rattle_steps_per_s`: one trajectory, `Stepper::step_n` of RATTLE (ideal pendulum, l = 1 m,
//!   g = 9.81 m/s², dt = 1 ms, θ₀ = 60°, φ̇₀ = 2 rad/s);
//! - `dop853_steps_per_s`, `dop853_evals_per_step`: the same start with DOP853 at rtol = 10⁻¹⁰,
//!   atol = 10⁻¹² (accepted steps; rejected ones are in the evaluations per step);
//! - `ensemble_1_thread`, `ensemble_2_threads`: trajectory-steps/s of `ensemble::run`, 4096 starts
//!   (θ₀ from 0.1 to 2.9 rad, φ̇₀ = 1 rad/s) × `steps` steps of 1 ms, final states only; the same
//!   with the opt-in fused arithmetic (`RattleSettings::arithmetic`): `ensemble_1_thread_fused`,
//!   `ensemble_2_threads_fused` (the two arithmetics timed alternately);
//! - `exact_states_per_s`: `ExactSolution::states_at` on one thread, 10⁵ times over 100 s;
//! - `isa`: the instruction-set level the hot loops ran at (`isa::selected`).
//!
//! Run: `cargo run --release -p pendulab-core --example roofline_kernels -- [reps] [steps]`.
//! SI units throughout.

use pendulab_core::ensemble::{run, RattleSettings};
use pendulab_core::exact::ExactSolution;
use pendulab_core::integrate::rattle_kernel::Arithmetic;
use pendulab_core::{isa, IdealPendulum, Method, Model, SolveOptions, State, Stepper};
use std::hint::black_box;
use std::sync::atomic::{AtomicBool, AtomicU64};
use std::time::Instant;
use timing::cpu_seconds;

mod timing;

/// The least wall time [s] of `reps` calls of `f`, and the least CPU time [s] (all threads; on a
/// loaded machine the CPU time is what the work costs, the wall time includes waiting for a core).
fn best(reps: usize, mut f: impl FnMut()) -> (f64, f64) {
    (0..reps)
        .map(|_| {
            let (t, c) = (Instant::now(), cpu_seconds());
            f();
            (t.elapsed().as_secs_f64(), cpu_seconds() - c)
        })
        .fold((f64::INFINITY, f64::INFINITY), |a, b| (a.0.min(b.0), a.1.min(b.1)))
}

fn main() {
    let args: Vec<u64> = std::env::args().skip(1).filter_map(|a| a.parse().ok()).collect();
    let reps = args.first().copied().unwrap_or(20) as usize;
    let steps = args.get(1).copied().unwrap_or(1000);
    let model = IdealPendulum::new(1.0, 1.0, 9.81).unwrap();
    let s0 = State::from_angles(model.params(), 60f64.to_radians(), 0.0, 0.0, 2.0).unwrap();
    // (name, units of work per timed call, (wall, cpu) [s])
    let mut out: Vec<(&str, f64, (f64, f64))> = Vec::new();

    let rattle = SolveOptions { method: Method::Rattle, dt: 1e-3, ..SolveOptions::default() };
    let mut st = Stepper::new(model, 0.0, s0, &rattle).unwrap();
    let n1 = 200_000u64;
    let w = best(reps, || {
        st.step_n(black_box(n1)).unwrap();
        black_box(st.state().x);
    });
    out.push(("rattle_steps", n1 as f64, w));

    let dop = SolveOptions { method: Method::Dop853, dt: 0.0, rtol: 1e-10, atol: 1e-12, project: true };
    let mut sd = Stepper::new(model, 0.0, s0, &dop).unwrap();
    let nd = 5000u64;
    let w = best(reps, || {
        sd.step_n(black_box(nd)).unwrap();
        black_box(sd.state().x);
    });
    let stats = sd.stats();
    out.push(("dop853_steps", nd as f64, w));

    let n = 4096;
    let starts: Vec<State> = (0..n)
        .map(|k| State::from_angles(model.params(), 0.1 + 2.8 * k as f64 / n as f64, 0.0, 0.0, 1.0).unwrap())
        .collect();
    for (threads, name) in [(1usize, "ensemble_1_thread"), (2, "ensemble_2_threads")] {
        let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
        let once = |arithmetic: Arithmetic| {
            pool.install(|| {
                let (p, c) = (AtomicU64::new(0), AtomicBool::new(false));
                let set = RattleSettings { arithmetic, ..RattleSettings::new(&[1.0], &[9.81], 1e-3, steps) };
                let r = run(&starts, &set, &p, &c);
                black_box(r.unwrap());
            })
        };
        // alternately, so that both arithmetics see the same load
        let (mut plain, mut fused) = ((f64::INFINITY, f64::INFINITY), (f64::INFINITY, f64::INFINITY));
        for _ in 0..reps {
            let a = best(1, || once(Arithmetic::Unfused));
            let b = best(1, || once(Arithmetic::Fused));
            plain = (plain.0.min(a.0), plain.1.min(a.1));
            fused = (fused.0.min(b.0), fused.1.min(b.1));
        }
        let work = (n as u64 * steps) as f64;
        out.push((name, work, plain));
        out.push((
            if threads == 1 { "ensemble_1_thread_fused" } else { "ensemble_2_threads_fused" },
            work,
            fused,
        ));
    }

    let exact = ExactSolution::new(model.params(), &s0).unwrap();
    let times: Vec<f64> = (0..100_000).map(|k| k as f64 * 1e-3).collect();
    let pool = rayon::ThreadPoolBuilder::new().num_threads(1).build().unwrap();
    let w = best(reps.div_ceil(4), || {
        pool.install(|| black_box(exact.states_at(&times).unwrap()));
    });
    out.push(("exact_states", times.len() as f64, w));

    let rates: Vec<String> = out
        .iter()
        .map(|(name, units, (wall, cpu))| {
            format!(
                "\"{name}\": {{\"per_wall_s\": {:.6e}, \"per_cpu_s\": {:.6e}}}",
                units / wall,
                units / cpu
            )
        })
        .collect();
    println!(
        "{{\"isa\": \"{}\", \"reps\": {reps}, \"ensemble_steps\": {steps}, \"dop853_evals_per_step\": {:.4}, {}}}",
        isa::selected(),
        stats.rhs_evals as f64 / stats.steps as f64,
        rates.join(", ")
    );
}
