//! Hoisting in every method of the registry (docs/theory.md T-11.10, model `hoisted`): the rope
//! length l(t) = L + r t + a sin νt below a fixed or slewing pivot, |x − P(t)| = l(t).
//!
//! Physics/numerics checked, for every method of [`Method::ALL`] (`rk4_angles` below a fixed pivot,
//! the only case its angle form covers):
//! - the constraint: |x| = l(t) and x·ẋ = l l̇ to round-off for the methods that keep TS²;
//! - the energy balance dE/dt = P_hoist + P_pivot (+ damping), E = m(½|ẋ|² + g z) relative to the
//!   pivot, P_hoist = −T l̇, P_pivot = −m P̈·ẋ: E(t) − E(0) − ∫P dt (Boole's rule, order 6, on the
//!   steps) converges at the method's order and reaches round-off (< 1e-10 m g L) for the
//!   8th-order methods;
//! - the observed order of convergence of every method with hoisting;
//! - adiabatic hoisting: each sway amplitude ∝ l^(−3/4) (T-11.8: the action E/ω of each mode is an
//!   adiabatic invariant, E ∝ m g θ² l, ω ∝ l^(−1/2));
//! - the rope's tension includes the hoist's m l̈ (the exact tension of a load hanging at rest);
//! - bad input: a rope that would become too short, `rk4_angles` below a moving pivot.
//!
//! SI units throughout (m, kg, s, rad, J, W).

use pendulab_core::model::registry::AnyModel;
use pendulab_core::model::{energy, tension};
use pendulab_core::{Method, Model, Params, SolveOptions, State, Stepper};

const L: f64 = 5.0;
const G: f64 = 9.81;

fn crane(radius: f64, hoist: (f64, f64, f64), damping: f64) -> AnyModel {
    let params = Params::new(L, 1.0, G).unwrap();
    let (rate, amplitude, frequency) = hoist;
    AnyModel::build(
        "hoisted",
        params,
        &[
            ("radius", radius),
            ("rate", 0.3),
            ("height", 2.0),
            ("hoist_rate", rate),
            ("hoist_amplitude", amplitude),
            ("hoist_frequency", frequency),
            ("damping", damping),
        ],
    )
    .unwrap()
}

/// The cases every method runs: below a slewing pivot (all but `rk4_angles`), below a fixed one.
fn models_for(method: Method) -> Vec<AnyModel> {
    let hoist = (-0.1, 0.3, 1.3);
    let mut out = vec![crane(0.0, hoist, 0.05)];
    if method != Method::Rk4Angles {
        out.push(crane(3.0, hoist, 0.05));
    }
    out
}

fn start(model: &AnyModel) -> State {
    State::from_angles(model.params(), 0.3, 0.5, 0.1, 0.4).unwrap()
}

fn options(method: Method, dt: f64) -> SolveOptions {
    SolveOptions { method, dt, rtol: 1e-13, atol: 1e-14, project: true }
}

/// States on the grid t_k = k dt, k = 0..=n (DOP853 lands on each grid point).
fn run(model: &AnyModel, method: Method, dt: f64, n: usize) -> Vec<State> {
    let mut st = Stepper::new(model.clone(), 0.0, start(model), &options(method, dt)).unwrap();
    let mut out = vec![st.state()];
    for k in 1..=n {
        st.step_to(k as f64 * dt).unwrap();
        out.push(st.state());
    }
    out
}

/// max_k |E(t_k) − E(0) − ∫₀^{t_k} P dt| / (m g L), the work by Boole's rule over blocks of 4 steps.
fn balance_residual(model: &AnyModel, dt: f64, states: &[State]) -> f64 {
    let m = model.params().mass;
    let power: Vec<f64> =
        states.iter().enumerate().map(|(k, s)| m * model.power_per_mass(k as f64 * dt, s.x, s.v)).collect();
    let e0 = energy(model, &states[0]);
    let mut work = 0.0;
    let mut worst: f64 = 0.0;
    for b in (0..states.len() - 1).step_by(4) {
        let p = &power[b..b + 5];
        work += 2.0 * dt / 45.0 * (7.0 * (p[0] + p[4]) + 32.0 * (p[1] + p[3]) + 12.0 * p[2]);
        worst = worst.max((energy(model, &states[b + 4]) - e0 - work).abs());
    }
    worst / (m * G * L)
}

#[test]
fn the_energy_balance_with_hoist_and_pivot_converges_at_every_methods_order() {
    let mut failures = Vec::new();
    for method in Method::ALL {
        let order = method.info().order as f64;
        for model in models_for(method) {
            let t_end = 4.0;
            let steps = [0.02, 0.01, 0.005];
            let r: Vec<f64> = steps
                .iter()
                .map(|&dt| {
                    balance_residual(&model, dt, &run(&model, method, dt, (t_end / dt).round() as usize))
                })
                .collect();
            let p = (r[1] / r[2]).log2();
            let name = method.info().name;
            eprintln!("{name:>11} radius {:?}: residuals {r:?}, order {p:.2}", model.pivot());
            let at_round_off = r[2] < 1e-10;
            if method == Method::Dop853 || order >= 8.0 {
                if !at_round_off {
                    failures.push(format!("{name}: balance {} above round-off", r[2]));
                }
            } else if !(at_round_off || (p - order).abs() < 0.5) {
                failures.push(format!("{name}: balance residuals {r:?} converge at {p:.2}, not {order}"));
            }
            if method.info().order <= 4 && r[2] > 1e-4 {
                failures.push(format!("{name}: balance residual {} too large", r[2]));
            }
        }
    }
    assert!(failures.is_empty(), "{failures:#?}");
}

#[test]
fn every_method_keeps_the_moving_sphere_and_converges_at_its_order() {
    let mut failures = Vec::new();
    for method in Method::ALL {
        let info = method.info();
        for model in models_for(method) {
            // the constraint, at every step
            let dt = 0.01;
            for (k, s) in run(&model, method, dt, 300).iter().enumerate() {
                let t = k as f64 * dt;
                let l = model.rope_length(t);
                let ld = (model.rope_length(t + 1e-6) - model.rope_length(t - 1e-6)) / 2e-6;
                let radius = (s.x.length() - l).abs() / l;
                let rate = (s.x.dot(s.v) - l * ld).abs() / (l * (s.v.length() + ld.abs()));
                if (info.preserves_ts2 || method == Method::Dop853) && (radius > 1e-13 || rate > 1e-8) {
                    failures.push(format!(
                        "{}: off the moving sphere at t = {t}: {radius:e}, {rate:e}",
                        info.name
                    ));
                    break;
                }
            }
            if info.adaptive {
                continue;
            }
            // the order, from successive differences at t = 1 s
            let h = match info.order {
                2 => 0.02,
                4 => 0.04,
                6 => 0.1,
                _ => 0.25,
            };
            let ends: Vec<State> = (0..4)
                .map(|k| {
                    let dt = h / 2f64.powi(k);
                    *run(&model, method, dt, (1.0 / dt).round() as usize).last().unwrap()
                })
                .collect();
            let speed = L * (G / L).sqrt();
            let d: Vec<f64> = ends
                .windows(2)
                .map(|w| ((w[0].x - w[1].x).length() / L).max((w[0].v - w[1].v).length() / speed))
                .collect();
            let p = (d[1] / d[2]).log2();
            eprintln!("{:>11}: differences {d:?}, observed order {p:.2}", info.name);
            if d[2] < 1e-13 || (p - info.order as f64).abs() > 0.3 {
                failures
                    .push(format!("{}: observed order {p:.2} ({d:?}), declared {}", info.name, info.order));
            }
        }
    }
    assert!(failures.is_empty(), "{failures:#?}");
}

#[test]
fn adiabatic_hoisting_grows_each_sway_amplitude_as_l_to_the_minus_three_quarters() {
    // l from 10 m to 2.5 m in 300 s (l̇/(l ω) ≤ 0.005): both semi-axes of the small elliptical
    // swing grow by 4^(3/4) = 2.83 (E/ω and J₃ both invariant); the ellipse (0.06 rad, 0.03 rad)
    // stays off the poles.
    let params = Params::new(10.0, 1.0, G).unwrap();
    let t_end = 300.0;
    let model = AnyModel::build("hoisted", params, &[("hoist_rate", -7.5 / t_end)]).unwrap();
    let omega0 = (G / 10.0f64).sqrt();
    let (a0, b0) = (0.06, 0.03);
    let s0 = State::from_angles(model.params(), a0, 0.0, 0.0, b0 / a0 * omega0).unwrap();
    for method in Method::ALL {
        let dt = if method.info().order == 2 { 0.005 } else { 0.02 };
        let mut st = Stepper::new(model.clone(), 0.0, s0, &options(method, dt)).unwrap();
        st.step_to(t_end).unwrap();
        // the ellipse's semi-axes (a, b) [rad] from the sway energy, ½ g l (a² + b²) per unit mass
        // (height above the lowest point g (l + z), the velocity across the rope), and from
        // J₃ = l² a b ω per unit mass: it precesses, so its extremes in x and y are not a and b
        let (s, l) = (st.state(), model.rope_length(t_end));
        let e = s.x / l;
        let v_across = s.v - e * e.dot(s.v);
        let sum = 2.0 * (0.5 * v_across.length_squared() + G * (l + s.x.z)) / (G * l);
        let product = (s.x.x * v_across.y - s.x.y * v_across.x) / (l * l * (G / l).sqrt());
        let (p, m) = ((sum + 2.0 * product).sqrt(), (sum - 2.0 * product).max(0.0).sqrt());
        let (a, b) = (0.5 * (p + m), 0.5 * (p - m));
        let want = (l / 10.0).powf(-0.75);
        let (ga, gb) = (a / a0, b / b0);
        let name = method.info().name;
        eprintln!("{name:>11}: amplitude gains {ga:.4}, {gb:.4}; l^(-3/4) law {want:.4}");
        assert!((ga / want - 1.0).abs() < 0.01, "{name}: gain of a {ga} vs {want}");
        assert!((gb / want - 1.0).abs() < 0.01, "{name}: gain of b {gb} vs {want}");
    }
}

#[test]
fn a_load_at_rest_on_an_accelerated_hoist_feels_m_times_g_minus_l_double_dot() {
    // hanging straight down, l̈ = −a ν² sin νt: T = m (g − l̈) (the load, at z = −l, accelerates
    // with the rope: m z̈ = −m l̈ = T − m g)
    // (not `rk4_angles`: straight down is its chart's pole, which it refuses)
    let model = crane(0.0, (0.0, 0.4, 2.0), 0.0);
    for method in Method::ALL.into_iter().filter(|m| *m != Method::Rk4Angles) {
        let mut st = Stepper::new(
            model.clone(),
            0.0,
            State { x: -L * pendulab_core::DVec3::Z, v: pendulab_core::DVec3::ZERO },
            &options(method, 0.01),
        )
        .unwrap();
        st.step_to(1.0).unwrap();
        let ldd = -0.4 * 4.0 * 2.0f64.sin();
        let t = tension(&model, 1.0, &st.state());
        assert!(
            (t - (G - ldd)).abs() < 1e-9 * G,
            "{}: T = {t} vs m(g − l̈) = {}",
            method.info().name,
            G - ldd
        );
        assert!((st.state().x.z + model.rope_length(1.0)).abs() < 1e-9, "{}", method.info().name);
    }
}

#[test]
fn without_hoisting_the_hoisted_model_is_the_slewing_crane() {
    let params = Params::new(L, 1.0, G).unwrap();
    let pivot = [("radius", 3.0), ("rate", 0.3), ("height", 2.0), ("damping", 0.05)];
    let slewing = AnyModel::build("slewing", params, &pivot).unwrap();
    let mut still = pivot.to_vec();
    still.push(("hoist_rate", 0.0));
    let hoisted = AnyModel::build("hoisted", params, &still).unwrap();
    for method in Method::ALL.into_iter().filter(|m| *m != Method::Rk4Angles) {
        let a = run(&slewing, method, 0.01, 200);
        let b = run(&hoisted, method, 0.01, 200);
        let d = (a[200].x - b[200].x).length() + (a[200].v - b[200].v).length();
        assert!(d < 1e-11, "{}: {d}", method.info().name);
    }
}

#[test]
fn the_solvers_first_sample_is_the_physical_start_with_the_ropes_rate() {
    let model = crane(0.0, (-0.1, 0.3, 1.3), 0.0);
    let s0 = start(&model);
    let save = pendulab_core::SaveAt::Every(1);
    let mut solver = pendulab_core::Solver::new(
        model.clone(),
        0.0,
        s0,
        1.0,
        &options(Method::Rattle, 0.01),
        save,
        1 << 30,
    )
    .unwrap();
    while !solver.advance(1000).unwrap() {}
    let samples = solver.take_samples();
    let ld = -0.1 + 0.3 * 1.3;
    for (t, s) in samples.t.iter().zip(&samples.states).take(2) {
        let l = model.rope_length(*t);
        assert!((s.x.length() - l).abs() < 1e-12 * l, "t = {t}");
        let rate = if *t == 0.0 { ld } else { model.rope_rate(*t) };
        assert!((s.x.dot(s.v) - l * rate).abs() < 1e-12 * l, "t = {t}: {}", s.x.dot(s.v));
    }
}

#[test]
fn bad_hoists_are_refused_with_the_reason() {
    let params = Params::new(L, 1.0, G).unwrap();
    let model = AnyModel::build("hoisted", params, &[("hoist_rate", -1.0)]).unwrap();
    let s0 = start(&model);
    let err = pendulab_core::Solver::new(
        model.clone(),
        0.0,
        s0,
        10.0,
        &options(Method::Rattle, 0.01),
        pendulab_core::SaveAt::Every(10),
        1 << 30,
    )
    .err()
    .unwrap()
    .to_string();
    assert!(err.contains("may fall to -5 m") && err.contains("hoist more slowly"), "{err}");
    let moving = crane(3.0, (-0.1, 0.0, 0.0), 0.0);
    let err =
        Stepper::new(moving.clone(), 0.0, start(&moving), &options(Method::Rk4Angles, 0.01)).err().unwrap();
    assert!(err.to_string().contains("hoisted rope below a fixed pivot"), "{err}");
    let err = AnyModel::build("hoisted", params, &[("hoist_rate", f64::NAN)]).err().unwrap().to_string();
    assert!(err.contains("hoist_rate"), "{err}");
}
