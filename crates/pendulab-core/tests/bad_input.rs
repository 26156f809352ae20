//! Every public entry point validates: the error names the parameter, its value and what is allowed.

use crate::common;

use common::{fixed, rosette};
use pendulab_core::error::Time;
use pendulab_core::solve::DEFAULT_MAX_SAVED_BYTES;
use pendulab_core::{DVec3, Error, IdealPendulum, Method, SaveAt, SolveOptions, Solver, State, Stepper};

fn message(e: Error) -> String {
    e.to_string()
}

#[test]
fn parameters_out_of_range_are_named() {
    for (l, m, g, name) in [
        (0.0, 1.0, 9.81, "length"),
        (-1.0, 1.0, 9.81, "length"),
        (f64::NAN, 1.0, 9.81, "length"),
        (1.0, 0.0, 9.81, "mass"),
        (1.0, 1.0, f64::INFINITY, "g"),
    ] {
        let e = message(IdealPendulum::new(l, m, g).unwrap_err());
        assert!(e.contains(name), "{e}");
    }
}

#[test]
fn states_off_ts2_or_not_finite_are_rejected() {
    let (model, _) = rosette();
    let p = pendulab_core::Model::params(&model);
    let e = message(State::on_tangent_bundle(p, DVec3::new(0.0, 0.0, -1.1), DVec3::ZERO).unwrap_err());
    assert!(e.contains("|x| - l") && e.contains("project"), "{e}");
    let e = message(
        State::on_tangent_bundle(p, DVec3::new(0.0, 0.0, -1.0), DVec3::new(0.0, 0.0, 1.0)).unwrap_err(),
    );
    assert!(e.contains("x·v"), "{e}");
    let e = message(State::on_tangent_bundle(p, DVec3::new(f64::NAN, 0.0, -1.0), DVec3::ZERO).unwrap_err());
    assert!(e.contains("x[0]") && e.contains("= nan is not a finite number"), "{e}");
    assert!(matches!(State::projected(p, DVec3::ZERO, DVec3::ZERO), Err(Error::DegeneratePosition)));
    assert!(State::from_angles(p, f64::NAN, 0.0, 0.0, 0.0).is_err());
}

#[test]
fn solver_settings_are_validated() {
    let (model, s0) = rosette();
    let solver = |opts: SolveOptions, t_end: f64, save: SaveAt| {
        Solver::new(model, 0.0, s0, t_end, &opts, save, DEFAULT_MAX_SAVED_BYTES).map(|_| ()).map_err(message)
    };
    let ok = fixed(Method::Rattle, 1e-3);
    assert!(solver(ok, 1.0, SaveAt::Every(1)).is_ok());
    for dt in [0.0, -1e-3, f64::NAN] {
        assert!(solver(fixed(Method::Rattle, dt), 1.0, SaveAt::Every(1)).unwrap_err().contains("dt"));
    }
    for t_end in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        assert!(solver(ok, t_end, SaveAt::Every(1)).unwrap_err().contains("t_end"));
    }
    assert!(solver(ok, 1.0, SaveAt::Every(0)).unwrap_err().contains("save_every"));
    assert!(solver(ok, 1e6, SaveAt::Every(1)).unwrap_err().contains("bytes"));
    // more than 1e10 planned steps: refused before any work, whatever is saved (the registry's limit)
    assert!(solver(ok, 1e9, SaveAt::Every(1 << 40)).unwrap_err().contains("(t_end - t0)/dt"));
    assert!(solver(ok, 1.0, SaveAt::Times(vec![0.5, 0.2])).unwrap_err().contains("increasing"));
    assert!(solver(ok, 1.0, SaveAt::Times(vec![2.0])).unwrap_err().contains("within"));
    let dop = SolveOptions { method: Method::Dop853, rtol: -1.0, ..ok };
    assert!(solver(dop, 1.0, SaveAt::Every(1)).unwrap_err().contains("rtol"));
    let e = message(Method::from_name("euler").unwrap_err());
    assert!(e.contains("euler") && e.contains("rattle"), "{e}");
    let mut st = Stepper::new(model, 0.0, s0, &ok).unwrap();
    st.step_to(1.0).unwrap();
    assert!(message(st.step_to(0.5).unwrap_err()).contains("t_target"));
}

#[test]
fn a_run_that_blows_up_is_an_error_not_a_nan() {
    // A step of 2 s is absurd for a 2 s period: RATTLE's position equation has no root.
    let (model, s0) = rosette();
    let mut st = Stepper::new(model, 0.0, s0, &fixed(Method::Rattle, 2.0)).unwrap();
    let mut result = Ok(());
    for _ in 0..100 {
        result = st.step().and_then(|_| st.check_finite());
        if result.is_err() {
            break;
        }
    }
    if let Err(e) = result {
        assert!(matches!(e, Error::Diverged { .. }), "{e}");
    } else {
        assert!(st.state().is_finite());
    }
}

#[test]
fn a_blow_up_of_the_angle_method_is_a_divergence_not_a_refused_speed() {
    // g = 1000 m/s² at dt = 0.05 s: the angles' RK4 blows up; the speed it rebuilt from still-finite
    // angles (|v| > 1e7 m/s) was refused as "invalid speed = …", as if the user had given it
    let model = IdealPendulum::new(1.0, 1.0, 1000.0).unwrap();
    for theta in [0.5, 1.0, 2.0, 2.5] {
        let s0 = State::from_angles(pendulab_core::Model::params(&model), theta, 0.0, 0.0, 2.0).unwrap();
        let run =
            Solver::new(model, 0.0, s0, 5.0, &fixed(Method::Rk4Angles, 0.05), SaveAt::Every(1), 1 << 30)
                .and_then(|mut s| s.advance(u64::MAX).map(|_| ()));
        let e = run.unwrap_err();
        assert!(
            matches!(e, Error::Diverged { method: "rk4_angles", dt, .. } if dt == 0.05),
            "θ₀ = {theta}: {e}"
        );
        // the time named is the last state computed, a step-grid time to 12 digits (t + h was named:
        // 0.15000000000000002 s), where a run stands and a lab run pauses
        let Error::Diverged { t, .. } = e else { unreachable!() };
        let steps = t / 0.05;
        assert!((steps - steps.round()).abs() < 1e-9, "θ₀ = {theta}: t = {t} is not a step's start");
        let mut rerun = Stepper::new(model, 0.0, s0, &fixed(Method::Rk4Angles, 0.05)).unwrap();
        rerun.step_to(t).unwrap(); // the state there is finite and within bounds
        assert!(rerun.state().is_finite() && rerun.step().is_err(), "θ₀ = {theta}: t = {t}");
        let words = e.to_string();
        assert!(
            words.starts_with(&format!("the integration diverged after t = {} s ", Time(t)))
                && words.contains("(dt = 0.05 s)")
                && !words.contains("0000000"),
            "{words}"
        );
        assert!(words
            .ends_with("reduce dt, or use an adaptive ('dop853') or structure-preserving ('rattle') method"));
    }
    // the same speed given by the user is refused as input
    let p = pendulab_core::Model::params(&model);
    let e = State::from_angles(p, 1.0, 0.0, 2e7, 0.0).unwrap_err();
    assert_eq!(e.to_string(), "invalid speed = 2e7: a speed |v| <= 1e7 m/s");
}
