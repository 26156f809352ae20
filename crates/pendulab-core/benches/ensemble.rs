//! Ensemble throughput (trajectory-steps per second) of RATTLE on 4096 ideal pendulums (l = 1 m,
//! g = 9.81 m/s², dt = 1e-3 s), on 1 thread and on all threads: the ratio is the parallel speed-up.
//! Also, on all threads, the cost of linear damping c = 0.1 1/s (the exact flow e^{−c dt/2} on either
//! side of each step) with settle tracking, against the undamped run of the same group; and one thread
//! restricted to the baseline instruction set (`isa::set_max_level`: what a CPU without AVX2/FMA runs)
//! and capped at x86-64-v3 (`isa::set_max_level`: what an AVX2-only CPU runs; on a CPU without
//! AVX-512 the same as `1_threads`).

use criterion::{black_box, criterion_group, criterion_main, Criterion, Throughput};
use pendulab_core::ensemble::{run, RattleSettings};
use pendulab_core::isa::{self, Level};
use pendulab_core::{IdealPendulum, Model, State};
use std::sync::atomic::{AtomicBool, AtomicU64};

fn bench(c: &mut Criterion) {
    let m = IdealPendulum::new(1.0, 1.0, 9.81).unwrap();
    let n = 4096;
    let starts: Vec<State> = (0..n)
        .map(|k| State::from_angles(m.params(), 0.1 + 2.8 * k as f64 / n as f64, 0.0, 0.0, 1.0).unwrap())
        .collect();
    let steps = 1000u64;
    let mut g = c.benchmark_group("ensemble_rattle");
    g.throughput(Throughput::Elements(n as u64 * steps));
    g.sample_size(10);
    let all = rayon::current_num_threads();
    let plain = RattleSettings::new(&[1.0], &[9.81], 1e-3, steps);
    let damped = RattleSettings { damping: &[0.1], settle_angle: Some(0.05), ..plain };
    let cases = [
        ("1_threads".to_string(), 1, plain, Level::V4),
        (format!("{all}_threads"), all, plain, Level::V4),
        (format!("{all}_threads_damped_settle"), all, damped, Level::V4),
        ("1_threads_baseline_level".to_string(), 1, plain, Level::Baseline),
        ("1_threads_x86-64-v3_level".to_string(), 1, plain, Level::V3),
    ];
    for (name, threads, settings, level) in cases {
        let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
        isa::set_max_level(level);
        g.bench_function(name, |b| {
            b.iter(|| {
                pool.install(|| {
                    let (p, cancel) = (AtomicU64::new(0), AtomicBool::new(false));
                    run(black_box(&starts), &settings, &p, &cancel).unwrap()
                })
            })
        });
        isa::set_baseline_only(false);
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
