//! Ensemble throughput (trajectory-steps per second) of RATTLE on 4096 ideal pendulums (l = 1 m,
//! g = 9.81 m/s², dt = 1e-3 s), on 1 thread and on all threads: the ratio is the parallel speed-up.

use criterion::{black_box, criterion_group, criterion_main, Criterion, Throughput};
use pendulab_core::ensemble::{run, EnsembleSave};
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
    for threads in [1, rayon::current_num_threads()] {
        let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
        g.bench_function(format!("{threads}_threads"), |b| {
            b.iter(|| {
                pool.install(|| {
                    let (p, cancel) = (AtomicU64::new(0), AtomicBool::new(false));
                    run(
                        black_box(&starts),
                        &[1.0],
                        &[9.81],
                        1e-3,
                        steps,
                        EnsembleSave::Final,
                        false,
                        &p,
                        &cancel,
                    )
                    .unwrap()
                })
            })
        });
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
