//! The real-pendulum models (docs/theory.md §7): reduction to the ideal pendulum when the extra
//! parameters are zero, the power balance T-7.1, the exact J₃ decay e^{−ct} of linear damping kept by
//! the RATTLE splitting (conformal structure), the splitting's observed orders, tilted gravity as a
//! rotated ideal pendulum, Foucault's precession −Ω sin λ (T-7.3), and bad parameters. SI units.

use crate::common;

use common::rosette;
use pendulab_core::model::registry::{power_balance_residual, AnyModel};
use pendulab_core::model::{energy, j3};
use pendulab_core::{DVec3, Method, Model, Params, SaveAt, SolveOptions, Solver, State, Stepper};

fn params() -> Params {
    Params::new(1.0, 1.0, 9.81).unwrap()
}

fn build(name: &str, extra: &[(&str, f64)]) -> AnyModel {
    AnyModel::build(name, params(), extra).unwrap()
}

fn run<M: Model>(m: M, s0: State, t: f64, opts: &SolveOptions) -> State {
    let mut st = Stepper::new(m, 0.0, s0, opts).unwrap();
    st.step_to(t).unwrap();
    st.state()
}

fn opts(method: Method, dt: f64) -> SolveOptions {
    SolveOptions { method, dt, rtol: 1e-12, atol: 1e-14, project: true }
}

#[test]
fn zero_extras_reduce_to_the_ideal_pendulum() {
    let (ideal, s0) = rosette();
    for name in ["damped", "rotating"] {
        let m = if name == "rotating" { build(name, &[("frame_rate", 0.0)]) } else { build(name, &[]) };
        assert!(m.is_conservative() && m.is_axisymmetric() && !m.has_velocity_forces(), "{name}");
        for method in Method::ALL.into_iter().filter(|&m| m != Method::Rk4Angles) {
            let a = run(ideal, s0, 3.0, &opts(method, 1e-3));
            let b = run(m.clone(), s0, 3.0, &opts(method, 1e-3));
            let d = (a.x - b.x).length() + (a.v - b.v).length();
            assert!(d < 1e-13, "{name} with {}: {d:e} from the ideal pendulum", method.info().name);
        }
    }
}

#[test]
fn power_balance_holds() {
    // E(t) − E(0) = m ∫ (A cos(ωt + ψ) e·v − c|v|² − c_q|v|³) dt, with the work integrated by the
    // trapezoidal rule over dense DOP853 output (rtol 1e-12): the residual is the rule's O(Δt²) error,
    // so halving the sampling step must divide it by ≈ 4 — a physics error would not shrink.
    let (_, s0) = rosette();
    let m = build(
        "damped",
        &[
            ("damping", 0.05),
            ("drag", 0.02),
            ("forcing_amplitude", 0.8),
            ("forcing_omega", 2.7),
            ("forcing_y", 1.0),
        ],
    );
    let worst = |dt: f64| {
        let n = (20.0 / dt).round() as usize;
        let times: Vec<f64> = (0..=n).map(|k| k as f64 * dt).collect();
        let opts = opts(Method::Dop853, 0.0);
        let mut solver = Solver::new(m.clone(), 0.0, s0, 20.0, &opts, SaveAt::Times(times), 1 << 30).unwrap();
        while !solver.advance(1 << 20).unwrap() {}
        let samples = solver.take_samples();
        let lost = energy(&m, &samples.states[0]) - energy(&m, samples.states.last().unwrap());
        assert!(lost.abs() > 0.1, "the test needs a real energy change, got {lost} J");
        power_balance_residual(&m, &samples.t, &samples.states).iter().fold(0.0f64, |a, r| a.max(r.abs()))
    };
    let (coarse, fine) = (worst(2e-3), worst(1e-3));
    eprintln!("power balance residual: {coarse:e} J (Δt = 2 ms), {fine:e} J (Δt = 1 ms)");
    assert!(fine < 2e-6, "power balance off by {fine:e} J");
    assert!(coarse / fine > 3.5, "residual does not shrink like Δt²: {coarse:e} → {fine:e}");
}

#[test]
fn linear_damping_decays_j3_exactly_as_exp_minus_ct() {
    // dJ₃/dt = −c J₃ for axisymmetric forces plus −m c v: J₃(t) = J₃(0) e^{−ct}. The splitting
    // applies e^{−ch/2} twice per step and RATTLE keeps J₃, so this holds to round-off.
    let (_, s0) = rosette();
    let c = 0.3;
    let m = build("damped", &[("damping", c)]);
    // "Round-off": each step applies 2 rounded factors per RATTLE substep (1, 3, 15 substeps), the
    // same ones every step, so their rounding adds up linearly: bound 2·s·N·ε with N = 10⁴ steps.
    for (method, substeps) in [(Method::Rattle, 1.0), (Method::Rattle4, 3.0), (Method::Rattle8, 15.0)] {
        let s = run(m.clone(), s0, 10.0, &opts(method, 1e-3));
        let want = j3(&m, &s0) * (-c * 10.0f64).exp();
        let rel = (j3(&m, &s) - want).abs() / want.abs();
        eprintln!("{}: J₃ relative error {rel:e}", method.info().name);
        assert!(
            rel < 2.0 * substeps * 1e4 * f64::EPSILON,
            "{}: J₃ relative error {rel:e}",
            method.info().name
        );
    }
}

#[test]
fn the_splitting_keeps_its_orders() {
    // Damping, drag, forcing and a rotating frame at once; reference: DOP853 at rtol 1e-13.
    let (_, s0) = rosette();
    let m = AnyModel::build(
        "damped",
        params(),
        &[("damping", 0.2), ("drag", 0.1), ("forcing_amplitude", 1.0), ("forcing_omega", 3.0)],
    )
    .unwrap();
    let rot =
        AnyModel::build("rotating", params(), &[("frame_rate", 0.7), ("latitude", 0.6), ("damping", 0.1)])
            .unwrap();
    for model in [m, rot] {
        let reference = run(
            model.clone(),
            s0,
            2.0,
            &SolveOptions { rtol: 1e-13, atol: 1e-15, ..opts(Method::Dop853, 0.0) },
        );
        for (method, order, dt) in
            [(Method::Rattle, 2.0, 4e-3), (Method::Rattle4, 4.0, 2e-2), (Method::Rattle6, 6.0, 5e-2)]
        {
            let err = |dt: f64| (run(model.clone(), s0, 2.0, &opts(method, dt)).x - reference.x).length();
            let observed = (err(dt) / err(dt / 2.0)).log2();
            eprintln!("{} {}: observed order {observed:.2}", model.name(), method.info().name);
            assert!(
                (observed - order).abs() < 0.3,
                "{} {}: order {observed}",
                model.name(),
                method.info().name
            );
        }
    }
}

#[test]
fn tilted_gravity_is_a_rotated_ideal_pendulum() {
    // Gravity along d = R(−e₃): the solution is R applied to the ideal solution from R⁻¹(start).
    let (ideal, s0) = rosette();
    let axis = DVec3::new(1.0, 2.0, 0.5).normalize();
    let rot = glam::DQuat::from_axis_angle(axis, 0.7);
    let d = rot * DVec3::NEG_Z;
    let m = build("damped", &[("gravity_x", d.x), ("gravity_y", d.y), ("gravity_z", d.z)]);
    assert!(!m.is_axisymmetric());
    let start = State { x: rot * s0.x, v: rot * s0.v };
    for method in [Method::Rattle8, Method::Dop853] {
        let a = run(m.clone(), start, 5.0, &opts(method, 2e-3));
        let b = run(ideal, s0, 5.0, &opts(method, 2e-3));
        let d = (a.x - rot * b.x).length();
        assert!(d < 1e-9, "{}: {d:e}", method.info().name);
    }
}

#[test]
fn foucault_plane_turns_at_minus_omega_sin_latitude() {
    // T-7.3 with an exaggerated rate: a small planar swing; the plane's azimuth after t is −Ω sin λ t
    // to first order in Ω/ω₀ (here 0.01).
    let (rate, lat) = (0.03, 1.0f64);
    let m = build("rotating", &[("frame_rate", rate), ("latitude", lat)]);
    let s0 = State::from_angles(m.params(), 0.05, 0.0, 0.0, 0.0).unwrap();
    let t_end = 60.0;
    let mut st = Stepper::new(m, 0.0, s0, &opts(Method::Rattle4, 2e-3)).unwrap();
    // the swing direction: the horizontal position at the turning point nearest t_end
    let (mut best, mut dir) = (0.0, DVec3::ZERO);
    while st.t() < t_end + 2.1 {
        st.step().unwrap();
        let x = st.state().x;
        let rho = x.x.hypot(x.y);
        if st.t() > t_end - 1.0 && rho > best {
            best = rho;
            dir = x;
        }
    }
    let plane = dir.y.atan2(dir.x);
    // the plane is a line: fold the angle into (−π/2, π/2]
    let plane = if plane > std::f64::consts::FRAC_PI_2 {
        plane - std::f64::consts::PI
    } else if plane <= -std::f64::consts::FRAC_PI_2 {
        plane + std::f64::consts::PI
    } else {
        plane
    };
    let t_turn = t_end; // within a swing period; the rate is small
    let want = -rate * lat.sin() * t_turn;
    eprintln!("Foucault: plane turned {plane:.5} rad, first order {want:.5} rad");
    assert!((plane - want).abs() < 0.05 * want.abs() + rate * 1.1, "{plane} vs {want}");
}

#[test]
fn bad_parameters_are_named() {
    let e =
        |name: &str, extra: &[(&str, f64)]| AnyModel::build(name, params(), extra).unwrap_err().to_string();
    assert!(e("damped", &[("damping", -1.0)]).contains("damping"));
    assert!(e("damped", &[("drag", f64::NAN)]).contains("drag"));
    // the user's own names: gravity_x/y/z (and forcing_x/y/z), with what is allowed
    let g0 = e("damped", &[("gravity_x", 0.0), ("gravity_y", 0.0), ("gravity_z", 0.0)]);
    assert!(g0.contains("gravity_x/y/z") && g0.contains("not all zero"), "{g0}");
    let f0 = e(
        "damped",
        &[("forcing_amplitude", 1.0), ("forcing_x", 0.0), ("forcing_y", 0.0), ("forcing_z", 0.0)],
    );
    assert!(f0.contains("forcing_x/y/z"), "{f0}");
    assert!(e("rotating", &[("latitude", 2.0)]).contains("latitude"));
    let unknown = e("damped", &[("dampnig", 0.1)]);
    assert!(unknown.contains("dampnig") && unknown.contains("damping"), "{unknown}");
    // a model without parameters of its own lists l, m, g alone (no trailing comma)
    let ideal = e("ideal", &[("damping", 0.1)]);
    assert!(ideal.ends_with("its parameters: length, mass, g"), "{ideal}");
    assert!(unknown.contains("its parameters: length, mass, g, damping"), "{unknown}");
    assert!(e("springy", &[]).contains("ideal"));
    let (_, s0) = rosette();
    let angles = Stepper::new(build("damped", &[("damping", 0.1)]), 0.0, s0, &opts(Method::Rk4Angles, 1e-3));
    assert!(angles.unwrap_err().to_string().contains("rk4_angles"));
}

#[test]
fn direction_components_default_only_when_none_is_given() {
    // Regression: forcing_y = 1 alone used to be normalised together with the default forcing_x = 1
    // into a diagonal force (e₁ + e₂)/√2. Now the default direction applies only when no component is
    // given; otherwise omitted components are 0.
    let force = |extra: &[(&str, f64)]| {
        let mut all = vec![("forcing_amplitude", 2.0), ("forcing_omega", 0.0)];
        all.extend_from_slice(extra);
        let m = build("damped", &all);
        let bottom = DVec3::new(0.0, 0.0, -1.0);
        m.applied_acceleration(0.0, bottom, DVec3::ZERO) - DVec3::new(0.0, 0.0, -9.81)
    };
    assert_eq!(force(&[]), DVec3::new(2.0, 0.0, 0.0));
    assert_eq!(force(&[("forcing_y", 1.0)]), DVec3::new(0.0, 2.0, 0.0));
    assert_eq!(force(&[("forcing_z", -3.0)]), DVec3::new(0.0, 0.0, -2.0));
    let diagonal = force(&[("forcing_x", 1.0), ("forcing_y", 1.0)]);
    assert!((diagonal - DVec3::new(2.0, 2.0, 0.0) / 2f64.sqrt()).length() < 1e-15);
    // the same rule for gravity: gravity_x alone is gravity along +e₁, not (e₁ − e₃)/√2
    let g = |extra: &[(&str, f64)]| build("damped", extra).applied_acceleration(0.0, DVec3::X, DVec3::ZERO);
    assert_eq!(g(&[]), DVec3::new(0.0, 0.0, -9.81));
    assert_eq!(g(&[("gravity_x", 1.0)]), DVec3::new(9.81, 0.0, 0.0));
    assert!(AnyModel::build("damped", params(), &[("forcing_x", 0.0)]).is_err(), "zero direction");
}
