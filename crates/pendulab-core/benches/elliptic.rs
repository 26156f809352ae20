//! Criterion benchmarks of the elliptic layer: `jacobi` (one call, K recomputed), the
//! precomputed `JacobiParam::eval`, and `ellippi_inc` with φ beyond π/2 and n < 0, at the
//! parameters of the `rosette` scenario's exact solution (m ≈ 0.29) and near m = 1.
//! Run with `cargo bench -p pendulab-core --bench elliptic`.

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use pendulab_core::elliptic::{ellippi_inc, jacobi, JacobiParam};

fn jacobi_bench(c: &mut Criterion) {
    let mut group = c.benchmark_group("jacobi");
    for (name, m) in [("m=0.29", 0.29), ("m=1-1e-12", 1.0 - 1e-12)] {
        group.bench_function(format!("jacobi {name}"), |b| {
            let mut u = 0.0;
            b.iter(|| {
                u = if u > 50.0 { 0.0 } else { u + 0.37 };
                black_box(jacobi(black_box(u), m).unwrap())
            })
        });
        let param = JacobiParam::new(m).unwrap();
        group.bench_function(format!("JacobiParam::eval {name}"), |b| {
            let mut u = 0.0;
            b.iter(|| {
                u = if u > 50.0 { 0.0 } else { u + 0.37 };
                black_box(param.eval(black_box(u)).unwrap())
            })
        });
    }
    group.finish();
}

fn ellippi_bench(c: &mut Criterion) {
    let mut group = c.benchmark_group("ellippi_inc");
    for (name, n) in [("n=0.6", 0.6), ("n=-0.4", -0.4), ("n=-1e10", -1e10)] {
        group.bench_function(name, |b| {
            let mut phi = 0.0;
            b.iter(|| {
                phi = if phi > 20.0 { 0.0 } else { phi + 0.37 };
                black_box(ellippi_inc(n, black_box(phi), 0.29).unwrap())
            })
        });
    }
    group.finish();
}

criterion_group!(benches, jacobi_bench, ellippi_bench);
criterion_main!(benches);
