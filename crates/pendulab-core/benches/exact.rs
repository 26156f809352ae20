//! Cost of the exact solution (docs/theory.md §4): set-up per trajectory, one state at t = 1 s and at
//! t = 10⁶ s (the same by construction), 10⁵ states for an array of times (parallel), and 10³ states
//! (one dispatched batch on one thread), also restricted to the baseline instruction set
//! (`isa::set_baseline_only`: what a CPU without AVX2/FMA runs).
//! Rosette start: l = 1 m, g = 9.81 m/s², θ₀ = 60°, φ̇₀ = 2 rad/s.

use criterion::{black_box, criterion_group, criterion_main, Criterion, Throughput};
use pendulab_core::exact::ExactSolution;
use pendulab_core::{isa, IdealPendulum, Model, State};

fn bench(c: &mut Criterion) {
    let m = IdealPendulum::new(1.0, 1.0, 9.81).unwrap();
    let s = State::from_angles(m.params(), 60f64.to_radians(), 0.0, 0.0, 2.0).unwrap();
    let sol = ExactSolution::new(m.params(), &s).unwrap();
    c.bench_function("exact/setup", |b| b.iter(|| ExactSolution::new(m.params(), black_box(&s)).unwrap()));
    c.bench_function("exact/state_t1", |b| b.iter(|| sol.state(black_box(1.0)).unwrap()));
    c.bench_function("exact/state_t1e6", |b| b.iter(|| sol.state(black_box(1.0e6)).unwrap()));
    let times: Vec<f64> = (0..100_000).map(|k| k as f64 * 0.01).collect();
    let mut g = c.benchmark_group("exact_array");
    g.throughput(Throughput::Elements(times.len() as u64));
    g.sample_size(20);
    g.bench_function("states_at_1e5", |b| b.iter(|| sol.states_at(black_box(&times)).unwrap()));
    g.finish();
    let mut g = c.benchmark_group("exact_batch");
    g.throughput(Throughput::Elements(1000));
    for (name, baseline) in [("states_at_1e3", false), ("states_at_1e3_baseline_level", true)] {
        g.bench_function(name, |b| {
            isa::set_baseline_only(baseline);
            b.iter(|| sol.states_at(black_box(&times[..1000])).unwrap());
            isa::set_baseline_only(false);
        });
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
