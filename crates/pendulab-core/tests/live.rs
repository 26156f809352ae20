//! The live session (`pendulab_core::live`): its frames are the stepper's states bit for bit, paced by
//! the time passed in, within the budget of the clock passed in; the error estimate; the commands.

use pendulab_core::live::session::StateSpec;
use pendulab_core::live::{Command, LivePendulum, LiveSession, Out, Record, Setup, TICK_BUDGET};
use pendulab_core::model::registry::AnyModel;
use pendulab_core::{DVec3, Method, Params, SolveOptions, Stepper};
use std::cell::Cell;

fn setup(model: &str, method: Method, dt: f64) -> Setup {
    let pendulum = LivePendulum::new(model, 1.0, 1.0, 9.81, &[]).unwrap();
    let state = pendulum.state_from_angles(1.0, 0.0, 0.0, 1.5).unwrap();
    Setup { name: Some("test".into()), ..Setup::new(pendulum, state, method, dt) }
}

fn frames(out: &[Out]) -> Vec<Record> {
    out.iter().filter_map(|o| if let Out::Frames(r) = o { Some(r.clone()) } else { None }).flatten().collect()
}

fn free_clock() -> f64 {
    0.0 // never spent: an unlimited budget
}

#[test]
fn ticks_step_the_same_steps_as_the_stepper() {
    let s = setup("ideal", Method::Rattle, 1e-3);
    let mut session = LiveSession::new(s.clone()).unwrap();
    let mut got = frames(&session.first_messages(&free_clock));
    for _ in 0..60 {
        got.extend(frames(&session.tick(Vec::new(), 1.0 / 60.0, &free_clock, TICK_BUDGET, 0)));
    }
    // one second of simulated time at time scale 1, in whole steps of dt
    let last = got.last().unwrap();
    assert!((last.t() - 1.0).abs() < 1.5e-3, "t = {}", last.t());
    let model = AnyModel::build("ideal", Params::new(1.0, 1.0, 9.81).unwrap(), &[]).unwrap();
    let opts = SolveOptions { method: Method::Rattle, dt: 1e-3, ..Default::default() };
    let mut reference = Stepper::new(model, 0.0, s.state, &opts).unwrap();
    for r in &got[1..] {
        let n = ((r.t() - reference.t()) / 1e-3).round() as u64;
        reference.step_n(n).unwrap();
        assert_eq!(r.t(), reference.t());
        assert_eq!(r.x(), reference.state().x); // bit for bit
                                                // the exact error is small and known (RATTLE's global error at dt = 1 ms, ~1e-6 m)
        let e = r.0[18];
        assert!((0.0..1e-4).contains(&e), "error_x = {e}");
    }
    assert!(got[1..].iter().any(|r| r.0[18] > 0.0));
    assert_eq!(got[0].0[18], 0.0);
}

#[test]
fn an_exhausted_budget_lags_and_never_piles_up_time() {
    // every reading of the clock costs 1 ms: the budget of 6 ms is spent after a few slices
    let now = Cell::new(0.0);
    let clock = || {
        now.set(now.get() + 1e-3);
        now.get()
    };
    let mut session = LiveSession::new(setup("ideal", Method::Rattle8, 1e-5)).unwrap();
    session.time_scale = 100.0;
    let out = session.tick(Vec::new(), 0.1, &clock, TICK_BUDGET, 0);
    assert!(session.lagging);
    let t = session.stepper.t();
    assert!(t > 0.0 && t < 10.0, "t = {t}");
    assert!(
        out.iter().any(|o| matches!(o, Out::Status(v) if v["lagging"] == true)),
        "the status says lagging"
    );
}

#[test]
fn richardson_estimate_is_the_scaled_difference_to_the_half_step_companion() {
    let s = setup("damped", Method::Rk4, 1e-2);
    let mut session = LiveSession::new(s.clone()).unwrap();
    let mut got = Vec::new();
    for _ in 0..30 {
        got.extend(frames(&session.tick(Vec::new(), 1.0 / 60.0, &free_clock, 1.0, 0)));
    }
    let model = AnyModel::build("damped", s.pendulum.params, &s.pendulum.own).unwrap();
    let half = SolveOptions { method: Method::Rk4, dt: 5e-3, ..Default::default() };
    let mut fine = Stepper::new(model, 0.0, s.state, &half).unwrap();
    let r = got.last().unwrap();
    fine.step_n((r.t() / 5e-3).round() as u64).unwrap();
    let want = 16.0 / 15.0 * (r.x() - fine.state().x).length();
    assert_eq!(r.0[18], want);
    assert!(want > 0.0);
}

#[test]
fn commands_change_the_session_or_name_what_is_wrong() {
    let mut session = LiveSession::new(setup("ideal", Method::Rk4, 1e-3)).unwrap();
    // a length change keeps the angles
    let before = session.stepper.state();
    session.apply(Command::SetParams { length: Some(2.0), mass: None, g: None, params: vec![] }).unwrap();
    assert_eq!(session.stepper.state().x, before.x * 2.0);
    assert_eq!(session.epoch, 1);
    // an unknown parameter is named, the session unchanged
    let e = session
        .apply(Command::SetParams { length: None, mass: None, g: None, params: vec![("dampin".into(), 1.0)] })
        .unwrap_err()
        .to_string();
    assert!(e.contains("dampin") && e.contains("has no parameter"), "{e}");
    assert_eq!(session.epoch, 1);
    // the spring cannot run rk4: the session switches to rattle
    session
        .apply(Command::SetModel { model: "spring".into(), params: vec![("stiffness".into(), 200.0)] })
        .unwrap();
    assert_eq!(session.method, Method::Rattle);
    assert_eq!(session.pendulum.get("stiffness"), 200.0);
    let e =
        session.apply(Command::SetMethod { method: Some(Method::Dop853), dt: None }).unwrap_err().to_string();
    assert!(e.contains("use one of rattle, rattle4"), "{e}");
    assert_eq!(session.method, Method::Rattle);
    // an offline model is refused
    let e = session.apply(Command::SetModel { model: "sampled_pivot".into(), params: vec![] }).unwrap_err();
    assert!(e.to_string().contains("does not run in the lab"), "{e}");
    // a state off the sphere of the rod
    session.apply(Command::SetModel { model: "ideal".into(), params: vec![] }).unwrap();
    let off = StateSpec::Cartesian { x: DVec3::new(0.0, 0.0, -1.0), v: DVec3::ZERO, project: false };
    assert!(session.apply(Command::SetState(off)).unwrap_err().to_string().contains("not on TS²"));
    // step: n steps, paused, taken in the next tick
    session.apply(Command::Step(5)).unwrap();
    assert!(session.paused);
    let t = session.stepper.t();
    let out = session.tick(Vec::new(), 0.1, &free_clock, TICK_BUDGET, 0);
    assert!((session.stepper.t() - t - 5e-3).abs() < 1e-12);
    assert_eq!(frames(&out).len(), 1);
}

#[test]
fn string_events_reach_the_tick() {
    let mut s = setup("string", Method::Rattle, 1e-3);
    s.state = s.pendulum.state_from_angles(2.0, 0.0, 0.0, 0.0).unwrap(); // above the equator at rest: goes slack
    let mut session = LiveSession::new(s).unwrap();
    let mut events = 0;
    let mut slack = false;
    for _ in 0..120 {
        let out = session.tick(Vec::new(), 1.0 / 60.0, &free_clock, 1.0, 0);
        events += out.iter().filter(|o| matches!(o, Out::Event(..))).count();
        slack |= frames(&out).iter().any(|r| r.0[17] == 0.0);
    }
    assert!(events >= 2 && slack, "{events} events, slack {slack}");
}

#[test]
fn the_status_says_an_adaptive_runs_tolerances() {
    // an exported scenario of a dop853 session carries its tolerances, not the live stepper's first step
    let s = Setup { rtol: 1e-8, atol: 1e-11, ..setup("ideal", Method::Dop853, 1e-3) };
    let status = LiveSession::new(s).unwrap().status();
    assert_eq!(status["adaptive"], true);
    assert_eq!((status["rtol"].as_f64(), status["atol"].as_f64()), (Some(1e-8), Some(1e-11)));
}

/// A method a model does not run in the lab, and a crane command outside the crane mode, are refused
/// keyed (messages.json), with the reason's key for the model, so that a page words them in its
/// language; they were plain English (`Error::Refused`), and the crane was told that "its taut phases need
/// a fixed-step method" (the string's reason).
#[test]
fn a_method_the_model_does_not_run_and_a_crane_command_outside_the_crane_mode_are_keyed() {
    use pendulab_core::live::wire::parse_command;
    let mut session = LiveSession::new(setup("ideal", Method::Rattle, 1e-3)).unwrap();
    let key = |e: pendulab_core::Error| {
        let (key, values) = e.key().expect("keyed");
        (
            key,
            values.into_iter().map(|(k, v)| format!("{k}={v}")).collect::<Vec<_>>().join("; "),
            e.to_string(),
        )
    };
    let crane = parse_command(r#"{"type": "crane", "move": [1, 0]}"#, &|_| Err(String::new())).unwrap();
    let (k, values, words) = key(session.apply(crane.clone()).unwrap_err());
    assert_eq!((k, values.as_str()), ("not_crane", "model=ideal"));
    assert_eq!(
        words,
        r#"not in the crane mode (the session runs the "ideal" model): send {"type": "crane", "on": true} first"#
    );
    let dop853 = Command::SetMethod { method: Some(Method::Dop853), dt: None };
    for (model, expected, reason) in [
        ("spring", "method_not_for_spring", "(it leaves the sphere: "),
        ("string", "method_not_for_string", "(its taut phases need a fixed-step method that keeps TS²)"),
    ] {
        session.apply(Command::SetModel { model: model.into(), params: vec![] }).unwrap();
        let (k, values, words) = key(session.apply(dop853.clone()).unwrap_err());
        let available = pendulab_core::live::methods_for(model).unwrap().join(", ");
        assert_eq!(k, expected);
        assert_eq!(values, format!("method=dop853; model={model}; available={available}"));
        assert!(
            words.starts_with(&format!("method \"dop853\" cannot run the \"{model}\" model {reason}")),
            "{words}"
        );
        assert!(words.ends_with(&format!("; use one of {available}")), "{words}");
        assert_eq!(session.method, Method::Rattle, "unchanged");
    }
    session
        .apply(parse_command(r#"{"type": "crane", "on": true}"#, &|_| Err(String::new())).unwrap())
        .unwrap();
    let (k, values, words) =
        key(session.apply(Command::SetMethod { method: Some(Method::Rattle), dt: None }).unwrap_err());
    assert_eq!(
        (k, values.as_str()),
        ("method_not_for_crane", "method=rattle; model=crane; available=dop853")
    );
    assert!(
        words.contains("crane integrator") && !words.contains("taut") && words.ends_with("; use dop853"),
        "{words}"
    );
    assert!(session.apply(crane).unwrap().is_none(), "in the crane mode the move is taken");
}

/// Every lab model that runs only some methods refuses the others with its own key and reason
/// (`method_not_for_<model>`): the refusal is matched over these models with no catch-all arm, which
/// gave any model but the spring and the crane the string's reason.
#[test]
fn every_model_that_runs_only_some_methods_refuses_the_others_with_its_own_key() {
    use pendulab_core::live::{live_models, methods_for, LiveStepper};
    let mut models = live_models();
    models.push(pendulab_core::live::crane::CRANE);
    let mut restricted = Vec::new();
    for model in models {
        let Some(allowed) = methods_for(model) else { continue };
        let p = LivePendulum::new(model, 1.0, 1.0, 9.81, &[]).unwrap();
        let state = p.state_from_angles(1.0, 0.0, 0.0, 0.0).unwrap();
        for method in Method::ALL.iter().filter(|m| !allowed.contains(&m.info().name)) {
            let e = LiveStepper::new(&p, state, 0.0, *method, 1e-3, 1e-8, 1e-10).unwrap_err();
            assert_eq!(e.key().unwrap().0, format!("method_not_for_{model}"), "{e}");
        }
        restricted.push(model);
    }
    assert_eq!(restricted, ["spring", "string", "crane"]);
}

/// The lab's set_method refuses an unknown method with the words of `Method::from_name` (the name as
/// sent, the nearest registered one: `error::did_you_mean`, and all of them); it had no hint.
#[test]
fn set_method_names_the_nearest_method_as_the_core_does() {
    use pendulab_core::live::wire::parse_command;
    let available = "rattle, rattle4, rattle6, rattle8, dop853, rkmk4, rk4, rk4_angles";
    let refuse = |method: &str| {
        let text = format!(r#"{{"type": "set_method", "method": {method}}}"#);
        parse_command(&text, &|_| Err(String::new())).unwrap_err()
    };
    for (name, hint) in
        [("RATTLE", Some("rattle")), ("ratle", Some("rattle")), ("Rk4", Some("rk4")), ("euler", None)]
    {
        let hint = hint.map_or(String::new(), |h| format!(" (did you mean '{h}'?)"));
        let (words, kind) = refuse(&format!("{name:?}"));
        assert_eq!(words, format!("unknown method '{name}'{hint}; available: {available}"));
        // the name quoted as the core and the Python layer quote it ('RATTLE'; it was JSON, "RATTLE")
        assert_eq!(words, Method::from_name(name).unwrap_err().to_string());
        assert_eq!(kind, Some("set_method"));
    }
    for sent in ["3", "true", "[\"rattle\"]"] {
        assert_eq!(refuse(sent).0, format!("unknown method {sent}; available: {available}"));
    }
}

/// The unknown method of set_method is keyed for a page (`unknown_method`, with the nearest name
/// `unknown_method_hint`): it was the English words alone. A value that is not a string is not keyed.
#[test]
fn an_unknown_method_is_keyed_with_the_nearest_name() {
    use pendulab_core::live::wire::unknown_method;
    use serde_json::{json, Value};
    let available = "rattle, rattle4, rattle6, rattle8, dop853, rkmk4, rk4, rk4_angles";
    let (words, key) = unknown_method(&json!("RATTLE"));
    assert_eq!(words, Method::from_name("RATTLE").unwrap_err().to_string());
    let values = json!({"method": "RATTLE", "nearest": "rattle", "available": available});
    assert_eq!(key, Some(("unknown_method_hint", values)));
    let (words, key) = unknown_method(&json!("euler"));
    assert_eq!(words, format!("unknown method 'euler'; available: {available}"));
    assert_eq!(key, Some(("unknown_method", json!({"method": "euler", "available": available}))));
    assert_eq!(unknown_method(&json!(3)), (format!("unknown method 3; available: {available}"), None));
    // a long name: abbreviated in the words, its middle elided in the value (as the server's)
    let (words, key) = unknown_method(&Value::String("x".repeat(500)));
    let shown = key.unwrap().1["method"].as_str().unwrap().to_string();
    assert_eq!(shown, format!("{} ... {}", "x".repeat(37), "x".repeat(37)));
    assert!(words.starts_with(&format!("unknown method '{}...", "x".repeat(76))), "{words}");
}

/// A parameter of another lab model is refused as the Python layer words it
/// (`pendulab.model.registry.Elsewhere`: `pl.Pendulum`, scenario files, the server's set_model), naming the
/// models that have it, keyed `parameter_of_other_model(s)`; it was "the 'ideal' model has no parameter
/// 'damping'" (the server rewrote it, the one-file lab showed it). Any other key keeps its refusal.
#[test]
fn another_models_parameter_names_the_models_that_have_it() {
    let refuse = |model: &str, key: &str| {
        let e = LivePendulum::new(model, 1.0, 1.0, 9.81, &[(key.to_string(), 0.1)]).unwrap_err();
        let (k, values) = e.key().unwrap();
        let values: Vec<(String, String)> = values.into_iter().map(|(n, v)| (n.to_string(), v)).collect();
        (e.to_string(), k, values)
    };
    let value = |values: &[(String, String)], name: &str| {
        values.iter().find(|(n, _)| n == name).map(|(_, v)| v.clone()).unwrap_or_default()
    };
    let (words, key, values) = refuse("ideal", "damping");
    assert_eq!(
        words,
        "damping is a parameter of model 'damped' (and 'rotating', 'slewing', 'vibrating'), not of 'ideal'; \
         its parameters: length, mass, g"
    );
    assert_eq!(key, "parameter_of_other_models");
    assert_eq!(
        (value(&values, "owner"), value(&values, "others")),
        ("damped".into(), "rotating, slewing, vibrating".into())
    );
    assert_eq!((value(&values, "model"), value(&values, "name")), ("ideal".into(), "damping".into()));
    assert_eq!(value(&values, "available"), "length, mass, g");
    let (words, key, values) = refuse("damped", "latitude");
    assert!(words.starts_with("latitude is a parameter of model 'rotating', not of 'damped'; its parameters: length, mass, g, damping, drag"), "{words}");
    assert_eq!((key, value(&values, "others")), ("parameter_of_other_model", String::new()));
    let (words, key, _) = refuse("spring", "restitution");
    assert!(words.starts_with("restitution is a parameter of model 'string', not of 'spring'; "), "{words}");
    assert_eq!(key, "parameter_of_other_model");
    // another case: the hint first, then the models; the value named is the parameter's own name
    let (words, key, values) = refuse("ideal", "DAMPING");
    assert!(
        words.starts_with(
            "the 'ideal' model has no parameter 'DAMPING' (did you mean 'damping'?); damping is a parameter \
             of model 'damped' (and "
        ),
        "{words}"
    );
    assert_eq!((key, value(&values, "name")), ("parameter_of_other_models", "damping".into()));
    // no other model has it, or the model has one near it, or the crane: the refusals as they were
    assert_eq!(refuse("ideal", "dampling").1, "no_parameters");
    assert_eq!(refuse("damped", "lattitude").1, "unknown_parameter");
    // "near one of the model's own parameters" by the Python layer's rule (`validate.did_you_mean`,
    // difflib; `error::close_match`), as python/tests/test_server_models.py checks the same cases: it
    // was the core's edit distance, which found AMPLITUDE near forcing_amplitude and restitution near
    // nothing, so the lab named the string for restitution on 'damped' and pl.Pendulum did not
    let (words, key, _) = refuse("damped", "restitution");
    assert!(
        words.starts_with("the 'damped' model has no parameter 'restitution'; its parameters: "),
        "{words}"
    );
    assert_eq!(key, "unknown_parameter");
    let (words, key, values) = refuse("damped", "AMPLITUDE");
    assert!(
        words.starts_with(
            "the 'damped' model has no parameter 'AMPLITUDE' (did you mean 'amplitude'?); amplitude is a \
             parameter of model 'vibrating', not of 'damped'; its parameters: length, mass, g, "
        ),
        "{words}"
    );
    assert_eq!((key, value(&values, "name")), ("parameter_of_other_model", "amplitude".into()));
    assert_eq!(refuse("damped", "lenght").1, "unknown_parameter");
    assert_eq!(refuse("damped", "amplitude").1, "unknown_parameter"); // near forcing_amplitude
    assert_eq!(refuse("damped", "stiffness").1, "parameter_of_other_model");
    let (words, key, _) = refuse("crane", "damping");
    assert!(words.starts_with("the crane has no parameter 'damping'; its parameters: "), "{words}");
    assert_eq!(key, "unknown_parameter");
}
