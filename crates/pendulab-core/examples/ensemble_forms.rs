//! The ensemble kernel per tile form (`ensemble/tile_params.rs`), for A/B comparisons of two builds:
//! ns per trajectory-step and core of `ensemble::run`, 4096 starts (θ₀ from 0.1 to 2.8 rad, φ̇₀ = 1
//! rad/s, scaled onto each trajectory's sphere) × `steps` steps of dt = 1 ms, final states only, best of
//! 5 wall-clock runs, printed as one line `name=ns …`:
//!
//! - `shared`: one pendulum (l = 1 m, g = 9.81 m/s²) for all starts (`Shared`);
//! - `len`: lengths 0.8–1.2 m per trajectory (`Lengths`);
//! - `c1`: one damping rate c = 0.1 /s (`Shared`, damped);
//! - `cN`: c from 0.05 to 0.45 /s per trajectory (`Damping`);
//! - `lc`: lengths and c per trajectory (`PerLane`).
//!
//! The kernel's speed depends on the build (docs/performance.md, *The frame's alignment*); compare two
//! builds by running their binaries alternately, several times each, in separate processes.
//!
//! Run: `cargo run --release -p pendulab-core --example ensemble_forms -- [steps] [name]` (only the
//! case `name`). Environment: `THREADS` (default 1), `ARITH=unfused` (default fused), `LEVEL=v3`
//! (the AVX2 loops on an AVX-512 CPU), `SUMMARY=1` (each trajectory's extremes and crossings tracked
//! at every step, as `pl.simulate_ensemble` does by default), `METHOD=rattle4` (or `rattle6`,
//! `rattle8`: a composition; the figure is then per RATTLE sub-step). SI units throughout.

use pendulab_core::ensemble::{run, RattleSettings};
use pendulab_core::integrate::rattle_kernel::Arithmetic;
use pendulab_core::isa::{set_max_level, Level};
use pendulab_core::{IdealPendulum, Method, Model, State};
use std::hint::black_box;
use std::sync::atomic::{AtomicBool, AtomicU64};
use std::time::Instant;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let steps: u64 = args.first().and_then(|a| a.parse().ok()).unwrap_or(2000);
    let only = args.get(1).cloned();
    let env = |k: &str| std::env::var(k).unwrap_or_default();
    if env("LEVEL") == "v3" {
        set_max_level(Level::V3);
    }
    let arithmetic = if env("ARITH") == "unfused" { Arithmetic::Unfused } else { Arithmetic::Fused };
    let with_summary = env("SUMMARY") == "1";
    let method =
        if env("METHOD").is_empty() { Method::Rattle } else { Method::from_name(&env("METHOD")).unwrap() };
    let substeps = match method {
        Method::Rattle4 => 3.0,
        Method::Rattle6 => 7.0,
        Method::Rattle8 => 15.0,
        _ => 1.0,
    };
    let threads: usize = env("THREADS").parse().unwrap_or(1);
    let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
    let model = IdealPendulum::new(1.0, 1.0, 9.81).unwrap();
    let n = 4096;
    let ones = vec![1.0; n];
    let lengths: Vec<f64> = (0..n).map(|k| 0.8 + 0.4 * k as f64 / n as f64).collect();
    let damping: Vec<f64> = (0..n).map(|k| 0.05 + 0.4 * k as f64 / n as f64).collect();
    let cases: [(&str, &[f64], &[f64]); 5] = [
        ("shared", &[1.0], &[]),
        ("len", &lengths, &[]),
        ("c1", &[1.0], &[0.1]),
        ("cN", &[1.0], &damping),
        ("lc", &lengths, &damping),
    ];
    let mut out = Vec::new();
    for (name, ls, damp) in cases {
        if only.as_deref().is_some_and(|o| o != name) {
            continue;
        }
        let scale = if ls.len() == 1 { &ones } else { &lengths };
        let starts: Vec<State> = (0..n)
            .map(|k| {
                let th = 0.1 + 2.8 * k as f64 / n as f64;
                let s = State::from_angles(model.params(), th, 0.0, 0.0, 1.0).unwrap();
                State { x: s.x * scale[k], v: s.v * scale[k] }
            })
            .collect();
        let settings = RattleSettings {
            arithmetic,
            damping: damp,
            with_summary,
            method,
            ..RattleSettings::new(ls, &[9.81], 1e-3, steps)
        };
        let mut best = f64::INFINITY;
        for _ in 0..5 {
            let t = Instant::now();
            pool.install(|| {
                let (progress, cancel) = (AtomicU64::new(0), AtomicBool::new(false));
                black_box(run(&starts, &settings, &progress, &cancel).unwrap());
            });
            best = best.min(t.elapsed().as_secs_f64());
        }
        out.push(format!("{name}={:.3}", best * threads as f64 / (n as f64 * steps as f64 * substeps) * 1e9));
    }
    println!("{}", out.join(" "));
}
