//! Criterion benchmarks: one step of every registered method on the rosette state
//! (l = 1 m, g = 9.81 m/s², θ₀ = 60°, φ̇₀ = 2 rad/s), and RATTLE throughput over 10⁵ steps
//! (steps/s = 10⁵ / time), also restricted to the baseline instruction set (`isa::set_baseline_only`:
//! what a CPU without AVX2/FMA runs, here with the C library's `fma` behind a call). Run with
//! `cargo bench -p pendulab-core` or `make bench`. DOP853 throughput: 10³ accepted steps at
//! rtol = 10⁻¹⁰, atol = 10⁻¹² (`Stepper::step_n`), at the best level and at the baseline.

use criterion::{black_box, criterion_group, criterion_main, Criterion, Throughput};
use pendulab_core::{isa, IdealPendulum, Method, Model, SolveOptions, State, Stepper};

fn rosette() -> (IdealPendulum, State) {
    let model = IdealPendulum::new(1.0, 1.0, 9.81).unwrap();
    let s = State::from_angles(model.params(), 60f64.to_radians(), 0.0, 0.0, 2.0).unwrap();
    (model, s)
}

fn one_step(c: &mut Criterion) {
    let (model, s0) = rosette();
    let mut group = c.benchmark_group("one_step");
    for method in Method::ALL {
        let options = SolveOptions { method, dt: 1e-3, rtol: 1e-10, atol: 1e-12, project: true };
        let mut stepper = Stepper::new(model, 0.0, s0, &options).unwrap();
        group.bench_function(method.info().name, |b| {
            b.iter(|| {
                stepper.step().unwrap();
                if method == Method::Rk4Angles || method == Method::Rk4 {
                    // keep the teaching methods on their valid domain
                    stepper.set_state(s0);
                }
                black_box(stepper.state().x)
            })
        });
    }
    group.finish();
}

fn rattle_throughput(c: &mut Criterion) {
    let (model, s0) = rosette();
    let mut group = c.benchmark_group("rattle_throughput");
    let n = 100_000u64;
    group.throughput(Throughput::Elements(n));
    let options = SolveOptions { method: Method::Rattle, dt: 1e-3, ..SolveOptions::default() };
    group.bench_function("rattle_1e5_steps", |b| {
        let mut stepper = Stepper::new(model, 0.0, s0, &options).unwrap();
        b.iter(|| {
            stepper.step_n(black_box(n)).unwrap();
            black_box(stepper.state().x)
        })
    });
    group.bench_function("rattle_1e5_steps_baseline_level", |b| {
        let mut stepper = Stepper::new(model, 0.0, s0, &options).unwrap();
        isa::set_baseline_only(true);
        b.iter(|| {
            stepper.step_n(black_box(n)).unwrap();
            black_box(stepper.state().x)
        });
        isa::set_baseline_only(false);
    });
    group.finish();
}

fn dop853_throughput(c: &mut Criterion) {
    let (model, s0) = rosette();
    let mut group = c.benchmark_group("dop853_throughput");
    let n = 1000u64;
    group.throughput(Throughput::Elements(n));
    let options = SolveOptions { method: Method::Dop853, dt: 0.0, rtol: 1e-10, atol: 1e-12, project: true };
    for (name, baseline) in [("dop853_1e3_steps", false), ("dop853_1e3_steps_baseline_level", true)] {
        group.bench_function(name, |b| {
            let mut stepper = Stepper::new(model, 0.0, s0, &options).unwrap();
            isa::set_baseline_only(baseline);
            b.iter(|| {
                stepper.step_n(black_box(n)).unwrap();
                black_box(stepper.state().x)
            });
            isa::set_baseline_only(false);
        });
    }
    group.finish();
}

criterion_group!(benches, one_step, rattle_throughput, dop853_throughput);
criterion_main!(benches);
