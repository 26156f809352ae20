//! Moving pivot (docs/theory.md T-7.2): the slewing crane's static offset ω²R/(ω₀² − ω²) and its natural
//! frequencies ω₀ ± ω in the boom frame (spectral peaks of a nonlinear small-amplitude run), the
//! power balance with the pivot's inertial force, and Kapitza's stabilised inverted pendulum for
//! (Aν)² > 2 g l. SI units; l = 1 m, g = 9.81 m/s².

use crate::common;

use common::sampled;
use pendulab_core::model::registry::{power_balance_residual, AnyModel};
use pendulab_core::{DVec3, Method, Model, Params, SolveOptions, State, Stepper};

fn model(name: &str, extra: &[(&str, f64)]) -> AnyModel {
    AnyModel::build(name, Params::new(1.0, 1.0, 9.81).unwrap(), extra).unwrap()
}

fn opts(dt: f64) -> SolveOptions {
    SolveOptions { method: Method::Rattle4, dt, ..SolveOptions::default() }
}

/// (radial, tangential) displacement of the bob in the boom frame at time t [m].
fn boom_frame(x: DVec3, rate: f64, t: f64) -> (f64, f64) {
    let (s, c) = (rate * t).sin_cos();
    (x.x * c + x.y * s, -x.x * s + x.y * c)
}

#[test]
fn slewing_static_offset() {
    let (r, w, w0sq) = (0.02, 0.5, 9.81);
    let m = model("slewing", &[("radius", r), ("rate", w), ("damping", 0.2)]);
    let s0 = State { x: DVec3::new(0.0, 0.0, -1.0), v: DVec3::ZERO };
    let mut st = Stepper::new(m, 0.0, s0, &opts(5e-3)).unwrap();
    st.step_to(150.0).unwrap(); // transients decay like e^{−ct/2}
    let (radial, tangential) = boom_frame(st.state().x, w, st.t());
    // Linear theory in the boom frame, at rest there: the pivot's centripetal acceleration pushes out
    // by ω²R and damping of the velocity relative to the pivot, ω e₃ × (X, Y), couples X and Y:
    //   (ω₀² − ω²) X = ω² R + c ω Y,   (ω₀² − ω²) Y = −c ω X
    // ⇒ X = ω² R (ω₀² − ω²) / ((ω₀² − ω²)² + c² ω²),  Y = −c ω X / (ω₀² − ω²).
    let c = 0.2;
    let d = w0sq - w * w;
    let want = w * w * r * d / (d * d + c * c * w * w);
    let lag = -c * w * want / d;
    eprintln!("static offset {radial:e} m (linear theory {want:e} m), tangential {tangential:e} m ({lag:e})");
    // nonlinear corrections are O((X/l)²) ~ 1e-7 relative, the transient e^{−c t/2} ~ 3e-7
    assert!((radial - want).abs() < 1e-4 * want, "{radial} vs {want}");
    assert!((tangential - lag).abs() < 1e-4 * lag.abs(), "{tangential} vs {lag}");
}

#[test]
fn slewing_natural_frequencies_are_omega0_plus_minus_omega() {
    let (w, w0) = (0.5, 9.81f64.sqrt());
    let m = model("slewing", &[("radius", 0.0), ("rate", w)]);
    let s0 = State::from_angles(m.params(), 0.02, 0.0, 0.0, 0.0).unwrap();
    let (dt, n) = (0.02, 10_000); // 200 s
    let mut st = Stepper::new(m, 0.0, s0, &opts(1e-3)).unwrap();
    let mut xs = Vec::with_capacity(n);
    for k in 0..n {
        st.step_to(k as f64 * dt).unwrap();
        xs.push(boom_frame(st.state().x, w, st.t()).0);
    }
    // power spectrum on a fine grid of angular frequencies
    let power = |f: f64| {
        let (mut re, mut im) = (0.0, 0.0);
        for (k, x) in xs.iter().enumerate() {
            let (s, c) = (f * k as f64 * dt).sin_cos();
            re += x * c;
            im += x * s;
        }
        re * re + im * im
    };
    let grid: Vec<f64> = (0..1200).map(|i| 1.5 + i as f64 * 0.0025).collect();
    let p: Vec<f64> = grid.iter().map(|&f| power(f)).collect();
    let mut peaks: Vec<(f64, f64)> =
        (1..p.len() - 1).filter(|&i| p[i] > p[i - 1] && p[i] > p[i + 1]).map(|i| (p[i], grid[i])).collect();
    peaks.sort_by(|a, b| b.0.total_cmp(&a.0));
    let mut top: Vec<f64> = peaks.iter().take(2).map(|q| q.1).collect();
    top.sort_by(f64::total_cmp);
    eprintln!("spectral peaks at {top:?} rad/s; theory {} and {}", w0 - w, w0 + w);
    let resolution = 2.0 * std::f64::consts::PI / (n as f64 * dt);
    assert!((top[0] - (w0 - w)).abs() < resolution && (top[1] - (w0 + w)).abs() < resolution, "{top:?}");
}

#[test]
fn moving_pivot_power_balance() {
    let m = model("slewing", &[("radius", 1.0), ("rate", 0.8), ("damping", 0.05)]);
    let s0 = State::from_angles(m.params(), 0.4, 0.0, 0.0, 1.0).unwrap();
    let mut st = Stepper::new(m.clone(), 0.0, s0, &opts(1e-3)).unwrap();
    let (mut t, mut s) = (vec![0.0], vec![s0]);
    for k in 1..=10_000 {
        st.step_to(k as f64 * 1e-3).unwrap();
        t.push(st.t());
        s.push(st.state());
    }
    let worst = power_balance_residual(&m, &t, &s).iter().fold(0.0f64, |a, r| a.max(r.abs()));
    assert!(worst < 1e-5, "{worst:e} J");
}

#[test]
fn kapitza_stabilises_the_inverted_pendulum() {
    // (Aν)² = 100 > 2 g l = 19.6: stable near the top; without vibration it falls.
    let s0 = |m: &AnyModel| State::from_angles(m.params(), 170f64.to_radians(), 0.0, 0.0, 0.0).unwrap();
    for (amplitude, stays) in [(0.05, true), (0.0, false)] {
        let m = model("vibrating", &[("amplitude", amplitude), ("frequency", 200.0)]);
        let start = s0(&m);
        let mut st = Stepper::new(m, 0.0, start, &opts(2e-4)).unwrap();
        let mut lowest = f64::INFINITY;
        while st.t() < 10.0 {
            st.step_n(50).unwrap();
            lowest = lowest.min(st.state().x.z);
        }
        eprintln!("A = {amplitude} m: lowest z = {lowest} m");
        assert_eq!(lowest > 0.9, stays, "A = {amplitude}: lowest z {lowest}");
    }
}

#[test]
fn sampled_pivot_follows_the_analytic_path() {
    // The slewing circle sampled every 10 ms over 12 s: the spline's p̈ is O(h²) accurate (2.9e-6 m/s²
    // at most here), and DOP853 at rtol 1e-13 puts the two runs 6e-10 m, 7e-9 m/s apart after 10 s.
    // With rattle4 (dt = 1 ms) the stated tolerance is 1e-8 m and 5e-8 m/s (measured 1.4e-9, 5.7e-9).
    // Regression: a path held still before t₀ cost rattle4 its order (its first step's backward
    // substep evaluates p̈ at t < 0): the end pieces are extrapolated instead (was 7e-5 m/s).
    let (radius, rate) = (5.0, 0.3);
    let exact = model("slewing", &[("radius", radius), ("rate", rate)]);
    let times: Vec<f64> = (0..=1200).map(|k| k as f64 * 0.01).collect();
    let positions: Vec<DVec3> = times
        .iter()
        .map(|&t| DVec3::new(radius * (rate * t).cos(), radius * (rate * t).sin(), 0.0))
        .collect();
    let sampled = AnyModel::sampled_pivot(*exact.params(), &times, &positions, 0.0).unwrap();
    assert_eq!(sampled.name(), "sampled_pivot");
    let s0 = State::from_angles(exact.params(), 0.3, 0.0, 0.0, 0.5).unwrap();
    let run = |m: AnyModel| {
        let mut st = Stepper::new(m, 0.0, s0, &opts(1e-3)).unwrap();
        st.step_to(10.0).unwrap();
        st.state()
    };
    let params = *exact.params();
    let (a, b) = (run(exact), run(sampled));
    let (dx, dv) = ((a.x - b.x).length(), (a.v - b.v).length());
    eprintln!("sampled vs analytic pivot after 10 s: |dx| = {dx:e} m, |dv| = {dv:e} m/s");
    assert!(dx < 1e-8 && dv < 5e-8, "{dx:e} {dv:e}");
    // bad samples are named
    let err = AnyModel::sampled_pivot(params, &times[..3], &positions[..3], 0.0).unwrap_err();
    assert!(err.to_string().contains("at least 4"), "{err}");
    let err = AnyModel::build("sampled_pivot", params, &[]).unwrap_err();
    assert!(err.to_string().contains("pivot times"), "{err}");
}

#[test]
fn dop853_ends_its_steps_on_the_samples_of_a_sampled_pivot() {
    // The spline's p̈ is piecewise linear, its slope steps at every sample: DOP853 stepping across
    // was ~1e4 × its tolerance off. It now lands on every sample (Model::next_break): each accepted
    // step lies inside one sample interval, and the run at rtol 1e-8 agrees with the run at 1e-13 to
    // its tolerance (measured 1.4e-10 m; before, steps crossed the samples).
    let times: Vec<f64> = (0..=300).map(|k| -0.1 + 0.05 * k as f64).collect();
    let (m, s0) = (sampled::path(&times), sampled::start());
    let run = |rtol: f64, check: bool| {
        let o = SolveOptions { method: Method::Dop853, dt: 0.0, rtol, atol: rtol, project: true };
        let mut st = Stepper::new(m.clone(), 0.0, s0, &o).unwrap();
        while st.t() < 10.0 {
            let t0 = st.t();
            st.step_towards(10.0).unwrap();
            if check {
                let i = times.partition_point(|&ti| ti <= t0);
                assert!(
                    st.t() <= times[i],
                    "a step from {t0} s to {} s crossed the sample at {} s",
                    st.t(),
                    times[i]
                );
            }
        }
        st.state()
    };
    let (a, b) = (run(1e-8, true), run(1e-13, false));
    let dx = (a.x - b.x).length();
    eprintln!("sampled pivot, DOP853 rtol 1e-8 vs 1e-13 after 10 s: |dx| = {dx:e} m");
    assert!(dx < 1e-8, "{dx:e}");
}
