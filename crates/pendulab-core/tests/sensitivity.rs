//! Forward sensitivities (docs/theory.md T-10.7): the state agrees with the plain DOP853 run, and every
//! derivative column agrees with central differences of the run itself (rotating frame, damping, drag,
//! dry friction all on). SI units.

use pendulab_core::model::extended::Extended;
use pendulab_core::sensitivity::{sensitivities, PARAMS};
use pendulab_core::{DVec3, Method, Params, SaveAt, SolveOptions, Solver, State};

fn model(v: &[f64; 9]) -> Extended {
    Extended::ideal(Params::new(v[4], 1.0, v[5]).unwrap())
        .with_damping(v[6], v[7])
        .unwrap()
        .with_friction(v[8], 1e-2)
        .unwrap()
        .with_frame(DVec3::new(0.0, 0.3, 0.4))
        .unwrap()
}

const BASE: [f64; 9] = [1.0, 0.2, 0.1, 0.7, 0.8, 9.81, 0.05, 0.1, 0.2];

fn times() -> Vec<f64> {
    (0..=400).map(|i| i as f64 * 0.01).collect()
}

fn run(v: &[f64; 9]) -> pendulab_core::sensitivity::Sensitivities {
    sensitivities(&model(v), [v[0], v[1], v[2], v[3]], &times(), 1e-12, 1e-14).unwrap()
}

#[test]
fn the_state_is_the_plain_dop853_run() {
    let m = model(&BASE);
    let s0 = State::from_angles(&Params::new(0.8, 1.0, 9.81).unwrap(), 1.0, 0.2, 0.1, 0.7).unwrap();
    let opts = SolveOptions { method: Method::Dop853, dt: 0.0, rtol: 1e-12, atol: 1e-14, project: true };
    let mut solver = Solver::new(m, 0.0, s0, 4.0, &opts, SaveAt::Times(times()), 1 << 30).unwrap();
    while !solver.advance(1 << 20).unwrap() {}
    let plain = solver.take_samples();
    let s = run(&BASE);
    let worst = plain.states.iter().zip(&s.x).map(|(a, b)| (a.x - *b).length()).fold(0.0, f64::max);
    assert!(worst < 1e-9, "{worst:e} m from the plain run");
}

#[test]
fn every_column_is_the_difference_quotient() {
    let s = run(&BASE);
    for (k, name) in PARAMS.iter().enumerate() {
        let h = 1e-6 * BASE[k].abs().max(1e-2);
        let (mut up, mut down) = (BASE, BASE);
        up[k] += h;
        down[k] -= h;
        let (a, b) = (run(&up), run(&down));
        let mut worst: f64 = 0.0;
        let mut size: f64 = 0.0;
        for i in 0..s.x.len() {
            let fd = (a.x[i] - b.x[i]) / (2.0 * h);
            let fdv = (a.v[i] - b.v[i]) / (2.0 * h);
            size = size.max(fd.length()).max(fdv.length());
            worst = worst.max((fd - s.dx[i][k]).length()).max((fdv - s.dv[i][k]).length());
        }
        eprintln!("{name}: |column| {size:.3e}, difference {worst:.2e}");
        assert!(size > 1e-3 && worst < 1e-5 * size, "{name}: {worst:e} of {size:e}");
    }
}

#[test]
fn bad_times_and_tolerances_are_named() {
    let m = model(&BASE);
    let e = sensitivities(&m, [1.0, 0.0, 0.0, 0.0], &[0.0, 2.0, 1.0], 1e-12, 1e-14).unwrap_err();
    assert!(e.to_string().contains("save times"), "{e}");
    let e = sensitivities(&m, [1.0, 0.0, 0.0, 0.0], &[f64::NAN], 1e-12, 1e-14).unwrap_err();
    assert!(e.to_string().contains("save times"), "{e}");
    let e = sensitivities(&m, [1.0, 0.0, 0.0, 0.0], &[1.0], -1.0, 1e-14).unwrap_err();
    assert!(e.to_string().contains("rtol"), "{e}");
}
