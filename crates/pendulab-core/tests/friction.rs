//! Dry (Coulomb) pivot friction (docs/theory.md T-7.6) beside viscous damping and quadratic drag
//! (T-7.1): the small-amplitude decay laws of a planar swing — viscous → ln A falls at c/2, Coulomb →
//! A falls linearly by 4 ε_f/ω₀² per period, quadratic drag → 1/A grows at (4/3π) c_q l ω₀ — each
//! measured from simulated turning points; the energy lost equals the friction work; the exact
//! friction flow of the RATTLE splitting is a flow; every integrator runs the model, the splitting
//! at its orders. SI units; l = 2 m so that a missing or doubled l in a force would show.

use pendulab_core::model::energy;
use pendulab_core::model::extended::sinh_decay;
use pendulab_core::model::registry::{power_balance_residual, AnyModel};
use pendulab_core::{Method, Model, Params, SaveAt, SolveOptions, Solver, State, Stepper};

const L: f64 = 2.0;
const G: f64 = 9.81;

fn params() -> Params {
    Params::new(L, 1.0, G).unwrap()
}

fn damped(extra: &[(&str, f64)]) -> AnyModel {
    AnyModel::build("damped", params(), extra).unwrap()
}

fn samples(m: &AnyModel, s0: State, t_end: f64, dt: f64) -> (Vec<f64>, Vec<State>) {
    let n = (t_end / dt).round() as usize;
    let times: Vec<f64> = (0..=n).map(|k| k as f64 * dt).collect();
    let opts = SolveOptions { method: Method::Dop853, dt: 0.0, rtol: 1e-11, atol: 1e-13, project: true };
    let mut solver = Solver::new(m.clone(), 0.0, s0, t_end, &opts, SaveAt::Times(times), 1 << 31).unwrap();
    while !solver.advance(1 << 20).unwrap() {}
    let s = solver.take_samples();
    (s.t, s.states)
}

/// The turning points of a planar swing in the x–z plane: times and amplitudes. The amplitude is read
/// off the energy (E/m = g l (1 − cos A) at a turning point), which is smooth, interpolated linearly to
/// the zero of the angular rate θ̇ ∝ (x × v)_y between two samples.
fn turning_points(m: &AnyModel, t: &[f64], states: &[State]) -> (Vec<f64>, Vec<f64>) {
    let amp = |s: &State| {
        let e = energy(m, s) / m.params().mass + G * L; // height measured from the lowest point
        (1.0 - e / (G * L)).clamp(-1.0, 1.0).acos()
    };
    let rate = |s: &State| s.x.cross(s.v).y;
    let (mut tt, mut aa) = (vec![], vec![]);
    for k in 0..states.len() - 1 {
        let (r0, r1) = (rate(&states[k]), rate(&states[k + 1]));
        if r0 != 0.0 && r0.signum() != r1.signum() {
            let w = r0 / (r0 - r1);
            tt.push(t[k] + w * (t[k + 1] - t[k]));
            aa.push(amp(&states[k]) + w * (amp(&states[k + 1]) - amp(&states[k])));
        }
    }
    (tt, aa)
}

/// Least-squares line y = a + b t: (a, b, largest |residual|).
fn line(t: &[f64], y: &[f64]) -> (f64, f64, f64) {
    let n = t.len() as f64;
    let (mt, my) = (t.iter().sum::<f64>() / n, y.iter().sum::<f64>() / n);
    let sxy: f64 = t.iter().zip(y).map(|(a, b)| (a - mt) * (b - my)).sum();
    let sxx: f64 = t.iter().map(|a| (a - mt) * (a - mt)).sum();
    let b = sxy / sxx;
    let a = my - b * mt;
    let worst = t.iter().zip(y).map(|(x, v)| (v - a - b * x).abs()).fold(0.0, f64::max);
    (a, b, worst)
}

fn planar_start(a0: f64) -> State {
    State::from_angles(&params(), a0, 0.0, 0.0, 0.0).unwrap()
}

/// Turning points of a planar swing from 0.05 rad (small: the laws are the small-amplitude ones; the
/// sin θ corrections are O(A²) ≈ 3e-4 relative).
fn decay(extra: &[(&str, f64)], t_end: f64) -> (Vec<f64>, Vec<f64>) {
    let m = damped(extra);
    let (t, s) = samples(&m, planar_start(0.05), t_end, 2e-3);
    turning_points(&m, &t, &s)
}

#[test]
fn viscous_damping_decays_exponentially() {
    // T-7.6: ln A falls at c/2 (exact for the linear oscillator at its extrema)
    let c = 0.02;
    let (t, a) = decay(&[("damping", c)], 60.0);
    let ln_a: Vec<f64> = a.iter().map(|x| x.ln()).collect();
    let (_, slope, worst) = line(&t, &ln_a);
    eprintln!("viscous: d ln A/dt = {slope:.6} (law {:.6}), worst residual {worst:e}", -c / 2.0);
    assert!(t.len() > 30);
    assert!((slope / (-c / 2.0) - 1.0).abs() < 1e-3, "slope {slope}");
    assert!(worst < 1e-3 * (ln_a[0] - ln_a.last().unwrap()), "ln A not linear in t: {worst:e}");
}

#[test]
fn coulomb_friction_decays_linearly() {
    // T-7.6: A falls by 4 ε_f/ω₀² = 4 τ_f/(m g l) per period, i.e. at dA/dt = −2 ε_f/(π ω₀); here
    // 0.001 rad per period (2 % of the start), so the swing dies in ~50 periods.
    let w0 = (G / L).sqrt();
    let eps = 0.001 * w0 * w0 / 4.0;
    let (t, a) = decay(&[("friction", eps)], 85.0);
    let law = -2.0 * eps / (std::f64::consts::PI * w0);
    let (_, slope, worst) = line(&t, &a);
    eprintln!("coulomb: dA/dt = {slope:.4e} (law {law:.4e}), worst residual {worst:e} rad");
    assert!(a.last().unwrap() < &0.025 && t.len() > 30);
    assert!((slope / law - 1.0).abs() < 1e-3, "slope {slope:e}, law {law:e}");
    assert!(worst < 2e-3 * (a[0] - a.last().unwrap()), "A not linear in t: {worst:e}");
    // half a period takes exactly 2 ε_f/ω₀² off (the linear oscillator with Coulomb friction)
    let half: Vec<f64> = a.windows(2).map(|w| w[0] - w[1]).collect();
    let mean = half.iter().sum::<f64>() / half.len() as f64;
    assert!((mean / (2.0 * eps / (w0 * w0)) - 1.0).abs() < 5e-3, "per half swing {mean:e}");
    // and not exponential: the relative decay rate rises as the swing dies down (issue 24's signature)
    let (_, _, worst_ln) = line(&t, &a.iter().map(|x| x.ln()).collect::<Vec<_>>());
    let (_, _, worst_a) = line(&t, &a);
    assert!(worst_ln / (a[0].ln() - a.last().unwrap().ln()) > 10.0 * worst_a / (a[0] - a.last().unwrap()));
}

#[test]
fn quadratic_drag_decays_hyperbolically() {
    // T-7.6: 1/A grows at (4/3π) c_q l ω₀ (8 c_q l/3 per period)
    let w0 = (G / L).sqrt();
    let cq = 0.0375;
    let (t, a) = decay(&[("drag", cq)], 170.0);
    let inv: Vec<f64> = a.iter().map(|x| 1.0 / x).collect();
    let law = 4.0 / (3.0 * std::f64::consts::PI) * cq * L * w0;
    let (_, slope, worst) = line(&t, &inv);
    eprintln!("drag: d(1/A)/dt = {slope:.6} (law {law:.6}), worst residual {worst:e} 1/rad");
    assert!((slope / law - 1.0).abs() < 1e-3, "slope {slope}, law {law}");
    assert!(worst < 2e-3 * (inv.last().unwrap() - inv[0]), "1/A not linear in t: {worst:e}");
}

#[test]
fn energy_lost_is_the_friction_work() {
    // E(t) − E(0) = −m ∫ ε_f l |v| tanh(|v|/(l ω_ε)) dt (with damping and drag too), the work by the
    // trapezoidal rule on dense output: the residual is the rule's O(Δt²) error (halving Δt divides it
    // by ≈ 4; a wrong force would leave a residual that does not shrink).
    let m = damped(&[("friction", 0.3), ("damping", 0.01), ("drag", 0.01)]);
    let s0 = State::from_angles(&params(), 1.2, 0.0, 0.0, 0.8).unwrap();
    let worst = |dt: f64| {
        let (t, s) = samples(&m, s0, 20.0, dt);
        let lost = energy(&m, &s[0]) - energy(&m, s.last().unwrap());
        assert!(lost > 1.0, "the test needs a real energy loss, got {lost} J");
        power_balance_residual(&m, &t, &s).iter().fold(0.0f64, |a, r| a.max(r.abs()))
    };
    let (coarse, fine) = (worst(2e-3), worst(1e-3));
    eprintln!("friction power balance: {coarse:e} J (2 ms), {fine:e} J (1 ms)");
    assert!(fine < 1e-5, "power balance off by {fine:e} J");
    assert!(coarse / fine > 3.5, "residual does not shrink like Δt²: {coarse:e} → {fine:e}");
}

#[test]
fn the_friction_flow_is_exact() {
    // u' = asinh(sinh(u) e^{−k}) solves du/dk = −tanh u: a flow (k₁ then k₂ is k₁ + k₂), its
    // derivative at k = 0 is −tanh u, and the large-u branch (logarithms) joins the direct one.
    for u in [1e-8f64, 0.3, 5.0, 19.9, 20.1, 40.0, 1e3, 1e12] {
        for k in [1e-3, 0.7, 30.0] {
            let once = sinh_decay(u, 2.0 * k);
            let twice = sinh_decay(sinh_decay(u, k), k);
            assert!((once - twice).abs() <= 1e-13 * once.max(1e-300), "u={u} k={k}: {once} vs {twice}");
        }
        let h = 1e-6 * u.max(1.0); // a step the digits of u resolve
        let d = (sinh_decay(u, h) - u) / h;
        assert!((d + u.tanh()).abs() < 1e-5, "u={u}: du/dk = {d}, want {}", -u.tanh());
    }
    let (a, b) = (sinh_decay(20.0 - 1e-12, 0.5), sinh_decay(20.0 + 1e-12, 0.5));
    assert!((a - b).abs() < 1e-11);
}

#[test]
fn every_integrator_runs_friction_and_the_splitting_keeps_its_orders() {
    // a rosette (|v| never near 0, where tanh(|ω|/ω_ε) turns sharply) with friction, damping and drag;
    // reference: DOP853 at rtol 1e-13
    let m = damped(&[("friction", 0.5), ("damping", 0.1), ("drag", 0.05)]);
    assert!(!m.is_conservative() && m.has_velocity_forces());
    let s0 = State::from_angles(&params(), 1.0, 0.0, 0.0, 1.5).unwrap();
    let run = |method: Method, dt: f64| {
        let opts = SolveOptions { method, dt, rtol: 1e-13, atol: 1e-15, project: true };
        let mut st = Stepper::new(m.clone(), 0.0, s0, &opts).unwrap();
        st.step_to(2.0).unwrap();
        st.state()
    };
    let reference = run(Method::Dop853, 0.0);
    for method in Method::ALL.into_iter().filter(|&k| k != Method::Rk4Angles && k != Method::Dop853) {
        let err = (run(method, 1e-3).x - reference.x).length();
        eprintln!("{}: error {err:e} m at dt = 1 ms", method.info().name);
        assert!(err < 1e-5, "{}: {err:e}", method.info().name);
    }
    for (method, order, dt) in
        [(Method::Rattle, 2.0, 4e-3), (Method::Rattle4, 4.0, 2e-2), (Method::Rattle6, 6.0, 5e-2)]
    {
        let err = |dt: f64| (run(method, dt).x - reference.x).length();
        let observed = (err(dt) / err(dt / 2.0)).log2();
        eprintln!("{}: observed order {observed:.2}", method.info().name);
        assert!((observed - order).abs() < 0.3, "{}: order {observed}", method.info().name);
    }
}

#[test]
fn bad_friction_is_named() {
    for (key, value) in [("friction", -1.0), ("friction", f64::NAN), ("friction_speed", 0.0)] {
        let e = AnyModel::build("damped", params(), &[(key, value)]).unwrap_err().to_string();
        assert!(e.contains(key), "{e}");
    }
}
