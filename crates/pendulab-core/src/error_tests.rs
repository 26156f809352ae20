//! Unit tests of `error`: numbers and times in messages, divergences and their message keys.

use super::*;

#[test]
fn numbers_in_messages_are_written_as_a_user_writes_them() {
    let shown = |x: f64| Shown(x).to_string();
    assert_eq!(shown(-1.0), "-1");
    assert_eq!(shown(0.01), "0.01");
    assert_eq!(shown(1.7453292519943295), "1.7453292519943295");
    assert_eq!(shown(1e-4), "0.0001");
    assert_eq!(shown(1e15), "1e15");
    assert_eq!(shown(1e9), "1e9");
    assert_eq!(shown(123456789.0), "123456789");
    assert_eq!(shown(999999.0), "999999");
    assert_eq!(shown(1e-7), "1e-7");
    assert_eq!(shown(-2.5e20), "-2.5e20");
    assert_eq!(shown(1e-300), "1e-300");
    assert_eq!((shown(0.0), shown(-0.0)), ("0".into(), "-0".into()));
    assert_eq!(
        (shown(f64::NAN), shown(f64::INFINITY), shown(f64::NEG_INFINITY)),
        ("nan".into(), "inf".into(), "-inf".into())
    );
    for x in [0.1 + 0.2, -1e-5, 123456.789, 6.02214076e23, f64::MIN_POSITIVE, f64::MAX] {
        assert_eq!(shown(x).parse::<f64>().unwrap().to_bits(), x.to_bits(), "{x:e} reads back");
    }
    let e = require_non_negative("damping", -1.0, "a finite number >= 0");
    assert_eq!(e.unwrap_err().to_string(), "invalid damping = -1: a finite number >= 0");
    let d = Error::Diverged { t: 20.0, method: "rk4", dt: 0.01 };
    assert!(
        d.to_string().starts_with("the integration diverged after t = 20 s with method 'rk4' (dt = 0.01 s)"),
        "{d}"
    );
    assert!(d
        .to_string()
        .ends_with("reduce dt, or use an adaptive ('dop853') or structure-preserving ('rattle') method"));
    assert_eq!(d.key().unwrap().1[2], ("dt", "0.01".to_string()));
}

/// A time in a message has 12 significant digits: no round-off noise of t + h (0.15000000000000002),
/// but every digit of a time off the step's grid that 12 digits hold.
#[test]
fn times_in_messages_have_twelve_significant_digits() {
    let time = |x: f64| Time(x).to_string();
    assert_eq!(time(0.1 + 0.05), "0.15");
    assert_eq!(time(0.1 + 0.2), "0.3");
    assert_eq!(time(1000.0000001), "1000.0000001");
    assert_eq!(time(123456.7890123456), "123456.789012");
    assert_eq!(
        (time(20.0), time(0.0), time(1e-7), time(2.5e20)),
        ("20".into(), "0".into(), "1e-7".into(), "2.5e20".into())
    );
    assert_eq!((time(f64::NAN), time(f64::INFINITY)), ("nan".into(), "inf".into()));
    let d = Error::Diverged { t: 0.1 + 0.05, method: "rk4_angles", dt: 0.05 };
    assert!(d.to_string().starts_with("the integration diverged after t = 0.15 s "), "{d}");
    let p = Error::PoleSingularity { t: 0.1 + 0.2, theta: 1e-7, sin_theta: 1e-7, limit: 1e-6 };
    assert!(p.to_string().contains("continue at t = 0.3 s:"), "{p}");
}

/// The advice of a divergence is part of its message key, so that every language gives the advice the
/// English words give for the method that diverged (rattle's own divergence is not told to use rattle).
#[test]
fn a_divergence_is_keyed_by_its_advice() {
    for (method, key, advice) in [
        ("rk4", "diverged", "or use an adaptive ('dop853') or structure-preserving ('rattle') method"),
        ("rk4_angles", "diverged", "or use an adaptive ('dop853') or structure-preserving ('rattle') method"),
        ("rkmk4", "diverged", "or use an adaptive ('dop853') or structure-preserving ('rattle') method"),
        ("rattle", "diverged_rattle", "reduce dt (the step must resolve the fastest motion, dt·ω ≪ 1)"),
        (
            "rattle composition",
            "diverged_rattle",
            "reduce dt (the step must resolve the fastest motion, dt·ω ≪ 1)",
        ),
        ("dop853", "diverged_dop853", "lower rtol and atol, or use the structure-preserving 'rattle'"),
        (
            "dop853 (sensitivities)",
            "diverged_dop853",
            "lower rtol and atol, or use the structure-preserving 'rattle'",
        ),
        ("spring verlet", "diverged_dt", "; reduce dt"),
        ("string", "diverged_dt", "; reduce dt"),
    ] {
        let d = Error::Diverged { t: 1.0, method, dt: 0.01 };
        assert_eq!(d.key().unwrap().0, key, "{method}");
        assert!(d.to_string().ends_with(advice), "{d}");
    }
}

/// A stopped live run is keyed `integration_stopped`, with the cause's words, its key (`why`) and values.
#[test]
fn a_stopped_run_is_keyed_with_its_cause() {
    let cause = Error::Diverged { t: 0.05, method: "rk4_angles", dt: 0.05 };
    let e = Error::Stopped { cause: Box::new(cause.clone()) };
    assert_eq!(e.to_string(), format!("{cause}; paused"));
    let (key, values) = e.key().unwrap();
    assert_eq!(key, "integration_stopped");
    assert_eq!(values[..2], [("detail", cause.to_string()), ("why", "diverged".to_string())]);
    assert_eq!(values[2..], cause.key().unwrap().1[..]);
    let plain = Error::Stopped { cause: Box::new(Error::Crane { reason: "slack".into() }) };
    assert_eq!(plain.key().unwrap().1, vec![("detail", "crane: slack".to_string())]);
}

/// A message key's time is the time of the English words (12 significant digits, [`Time`]), so that a page
/// in another language names the same time: it was rounded to 4 decimals (1000.0000001 s became 1000 s,
/// 1.23456789 s 1.2346 s, 3e-5 s 0).
#[test]
fn a_keys_time_is_the_time_of_the_words() {
    for t in [1000.0000001, 1.23456789, 3e-5, 0.1 + 0.05, 123456.7890123456] {
        let shown = Time(t).to_string();
        let cases = [
            Error::Diverged { t, method: "rattle", dt: 0.01 },
            Error::StepSizeUnderflow { t, h: 1e-15, rtol: 1e-9, atol: 1e-12, off_sphere: None },
            Error::PoleSingularity { t, theta: 1e-7, sin_theta: 1e-7, limit: 1e-6 },
            Error::ReducedFlowPole { t, sigma1: 1.0 },
        ];
        for e in cases {
            let values = e.key().unwrap().1;
            assert_eq!(values.iter().find(|(k, _)| *k == "t").unwrap().1, shown, "{e}");
            assert!(e.to_string().contains(&format!("t = {shown} s")), "{e}");
            let stopped = Error::Stopped { cause: Box::new(e) }.key().unwrap().1;
            assert!(stopped.contains(&("t", shown.clone())), "{stopped:?}");
        }
    }
}

/// A message key's step size (dt, h) and residual are the numbers of the English words ([`Shown`]), so
/// that a page in another language names the same value: they were rounded to 4 significant digits (a
/// dt of 0.0123457 s became 0.01235 s, an h of 1.23456789e-15 s 1.235e-15 s).
#[test]
fn a_keys_step_size_and_residual_are_those_of_the_words() {
    for x in [0.0123457, 1.23456789e-15, 0.1 + 0.2, 1e-3, 2.5e20] {
        let shown = Shown(x).to_string();
        let cases = [
            (Error::Diverged { t: 1.0, method: "rk4", dt: x }, "dt", format!("(dt = {shown} s)")),
            (
                Error::StepSizeUnderflow { t: 1.0, h: x, rtol: 1e-9, atol: 1e-12, off_sphere: None },
                "h",
                format!("h = {shown} s"),
            ),
            (
                Error::NotOnTangentBundle { what: "(|x| - l)/l", value: x, tolerance: 1e-9 },
                "value",
                format!("= {shown} exceeds"),
            ),
            (
                Error::NotOnTangentBundle { what: "(|x| - l)/l", value: 1.0, tolerance: x },
                "tolerance",
                format!("the tolerance {shown};"),
            ),
        ];
        for (e, name, words) in cases {
            let values = e.key().unwrap().1;
            assert_eq!(values.iter().find(|(k, _)| *k == name).unwrap().1, shown, "{e}");
            assert!(e.to_string().contains(&words), "{e}");
            assert_eq!(shown.parse::<f64>().unwrap(), x, "reads back");
        }
    }
}

/// An unknown method names the nearest registered one (the same but for case first) and all of them; it
/// said only "unknown method \"RATTLE\"; available: …", unlike the Python layer's message (whose
/// quotes it has now: 'RATTLE').
#[test]
fn an_unknown_method_names_the_nearest_and_the_registered_ones() {
    use crate::integrate::Method;
    let available = "rattle, rattle4, rattle6, rattle8, dop853, rkmk4, rk4, rk4_angles";
    let message = |name: &str| Method::from_name(name).unwrap_err().to_string();
    for (given, hint) in [
        ("RATTLE", Some("rattle")),
        ("Rk4", Some("rk4")), // the same but for case, not the closer-looking 'rkmk4'
        ("ratle", Some("rattle")),
        ("rk5", Some("rk4")),
        ("RK-4", None), // difflib compares the letters as written: no hint, as in Python
        ("dop85", Some("dop853")),
        ("rk4_angle", Some("rk4_angles")),
        ("rattl6", Some("rattle6")),   // as near as 'rattle', and more alike
        ("rattle46", Some("rattle6")), // of equal ratios, the greatest name (difflib's)
        ("rattel4", Some("rattle4")),  // two neighbours swapped: one edit
        ("kr4", Some("rk4")),
        ("euler", None),
        ("zzzz", None),
        ("", None),
    ] {
        let hint = hint.map_or(String::new(), |h| format!(" (did you mean '{h}'?)"));
        assert_eq!(message(given), format!("unknown method '{given}'{hint}; available: {available}"));
    }
    let long = "r".repeat(100_000); // no hint, and no 10⁵-by-10 distance table
    assert_eq!(message(&long), format!("unknown method '{long}'; available: {available}"));
    assert_eq!(did_you_mean("rattle10", ["rattle", "rattle4"]), " (did you mean 'rattle'?)");
    assert_eq!(did_you_mean("x", std::iter::empty()), "");
}

/// Names in the core's refusals are quoted as Python's `repr` quotes them (the Python layer's
/// messages): 'x'; "it's" for a name with a single quote; backslash, quote and control characters
/// escaped. The model, parameter and arithmetic refusals quote so too.
#[test]
fn names_are_quoted_as_python_quotes_them() {
    use super::Quoted;
    for (name, python) in [
        ("rattle", "'rattle'"),
        ("it's", "\"it's\""),
        ("say \"x\" 'y'", "'say \"x\" \\'y\\''"),
        ("a\\b\n\t\u{1}\u{7f}", "'a\\\\b\\n\\t\\x01\\x7f'"),
        ("φ", "'φ'"),
        ("", "''"),
    ] {
        assert_eq!(Quoted(name).to_string(), python, "{name:?}");
    }
    let ideal = crate::state::Params::new(1.0, 1.0, 9.81).unwrap();
    let build = crate::model::any_model::AnyModel::build("ideal", ideal, &[("dampin", 1.0)]);
    let parameter = build.map(|_| ()).unwrap_err().to_string();
    assert_eq!(parameter, "the 'ideal' model has no parameter 'dampin'; its parameters: length, mass, g");
    let model = crate::model::registry::spec("sprung").unwrap_err().to_string();
    assert!(model.starts_with("unknown model 'sprung'; available: ideal, damped"), "{model}");
    let arithmetic =
        crate::integrate::rattle_kernel::Arithmetic::from_name("fast").map(|_| ()).unwrap_err().to_string();
    assert!(arithmetic.starts_with("unknown arithmetic 'fast'; available: unfused"), "{arithmetic}");
}
