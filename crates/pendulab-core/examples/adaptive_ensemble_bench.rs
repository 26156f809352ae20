//! The DOP853 ensemble vectorised across trajectories (`ensemble/adaptive_lanes.rs`) against one
//! `Solver` per trajectory (`run_adaptive_serial`, the path before it), same process, interleaved:
//! for each model, `rounds` rounds of (serial, lanes) in alternating order, each timed in CPU time
//! (all threads, `CLOCK_PROCESS_CPUTIME_ID`) and wall time; printed per round and as the median of the
//! per-round ratios serial / lanes (> 1: the lanes are faster). The results of both are compared
//! bit for bit. On a shared machine read the CPU-time ratio and note the load.
//!
//! Workload: `n` starts (θ₀ from 0.2 to 2.8 rad, φ̇₀ from −1.5 to 1.5 rad/s), t_end = 10 s, rtol =
//! 10⁻¹⁰, atol = 10⁻¹², final states only; models `ideal` (l = 1 m, g = 9.81 m/s²), `damped` with
//! linear damping 0.1 /s, and `damped` with drag 0.3 /m and forcing 0.8 m/s² at 3.1 rad/s (sin/cos
//! of time in every evaluation).
//!
//! Run: `cargo run --release -p pendulab-core --example adaptive_ensemble_bench -- [n] [rounds] [threads]`.
//! SI units throughout.

use pendulab_core::ensemble::adaptive::{run_adaptive_any, run_adaptive_serial, AdaptiveSettings, Models};
use pendulab_core::model::AnyModel;
use pendulab_core::{Method, Model, Params, SolveOptions, State};
use std::sync::atomic::{AtomicBool, AtomicU64};
use std::time::Instant;
use timing::cpu_seconds;

mod timing;

fn median(mut a: Vec<f64>) -> f64 {
    a.sort_by(f64::total_cmp);
    let n = a.len();
    if n % 2 == 1 {
        a[n / 2]
    } else {
        0.5 * (a[n / 2 - 1] + a[n / 2])
    }
}

fn main() {
    let args: Vec<usize> = std::env::args().skip(1).filter_map(|a| a.parse().ok()).collect();
    let (n, rounds, threads) = (
        args.first().copied().unwrap_or(2048),
        args.get(1).copied().unwrap_or(5),
        args.get(2).copied().unwrap_or(1),
    );
    let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
    let p = Params::new(1.0, 1.0, 9.81).unwrap();
    let models = [
        ("ideal", AnyModel::build("ideal", p, &[]).unwrap()),
        ("damped (c = 0.1)", AnyModel::build("damped", p, &[("damping", 0.1)]).unwrap()),
        (
            "driven (drag, forcing)",
            AnyModel::build(
                "damped",
                p,
                &[("damping", 0.05), ("drag", 0.3), ("forcing_amplitude", 0.8), ("forcing_omega", 3.1)],
            )
            .unwrap(),
        ),
    ];
    let options = SolveOptions { method: Method::Dop853, dt: 0.0, rtol: 1e-10, atol: 1e-12, project: true };
    let set = AdaptiveSettings { options, t0: 0.0, t_end: 10.0, times: vec![0.0, 10.0], conserve: false };
    println!("{n} trajectories, t_end = 10 s, rtol 1e-10, {threads} thread(s), {rounds} interleaved rounds");
    for (name, m) in &models {
        let starts: Vec<State> = (0..n)
            .map(|k| {
                let f = k as f64 / n as f64;
                State::from_angles(m.params(), 0.2 + 2.6 * f, 0.0, 0.0, 3.0 * f - 1.5).unwrap()
            })
            .collect();
        let ms = Models::one(m);
        let (mut cpu_ratio, mut wall_ratio) = (Vec::new(), Vec::new());
        let mut steps = 0u64;
        for r in 0..rounds {
            let time = |lanes: bool| {
                let (pr, c) = (AtomicU64::new(0), AtomicBool::new(false));
                let (t, c0) = (Instant::now(), cpu_seconds());
                let res = pool.install(|| {
                    if lanes {
                        run_adaptive_any(&ms, &starts, &set, &pr, &c)
                    } else {
                        run_adaptive_serial(&ms, &starts, &set, &pr, &c)
                    }
                });
                let res = res.unwrap();
                (t.elapsed().as_secs_f64(), cpu_seconds() - c0, res)
            };
            let (a, b) = if r % 2 == 0 {
                let a = time(false);
                (a, time(true))
            } else {
                let b = time(true);
                (time(false), b)
            };
            assert_eq!(a.2.states, b.2.states, "the two paths must give the same bits");
            steps = a.2.steps.iter().sum();
            cpu_ratio.push(a.1 / b.1);
            wall_ratio.push(a.0 / b.0);
            println!(
                "  {name}: round {r}: serial {:.3} s CPU ({:.3} wall), lanes {:.3} s CPU ({:.3} wall)",
                a.1, a.0, b.1, b.0
            );
        }
        println!(
            "{name}: {:.3e} accepted steps; serial / lanes, median of {rounds} rounds: CPU time {:.2} \
             (rounds {:.2}-{:.2}), wall {:.2}",
            steps as f64,
            median(cpu_ratio.clone()),
            cpu_ratio.iter().copied().fold(f64::INFINITY, f64::min),
            cpu_ratio.iter().copied().fold(0.0, f64::max),
            median(wall_ratio)
        );
    }
}
