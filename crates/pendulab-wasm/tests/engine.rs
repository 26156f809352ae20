//! The page's engine natively (the same code runs as WebAssembly): scenarios, commands as JSON text
//! checked as the server checks them, the packed messages (status, frames, errors).

use pendulab_wasm::engine::{unpack, Engine, KIND_FRAMES, KIND_JSON};
use serde_json::Value;

const CONFIG: &str = r#"{"scenarios": [
  {"name": "rosette", "title": "A rosette", "params": {"length": 1.0, "mass": 1.0, "g": 9.81}, "model": "ideal",
   "model_params": {}, "start": {"x": [0.8414709848078965, 0.0, -0.5403023058681398], "v": [0.0, 2.0, 0.0]},
   "method": "rattle", "dt": 0.001, "t0": 0.0},
  {"name": "damped_swing", "title": "Damped", "params": {"length": 2.0, "mass": 1.0, "g": 9.81}, "model": "damped",
   "model_params": {"damping": 0.5}, "start": {"x": [0.0, 0.0, -2.0], "v": [1.0, 0.0, 0.0]},
   "method": "rk4", "dt": 0.002, "t0": 1.0}
]}"#;

fn clock() -> f64 {
    0.0
}

fn messages(buf: &[u8]) -> (Vec<Value>, usize) {
    let mut notices = Vec::new();
    let mut records = 0;
    for (kind, bytes) in unpack(buf) {
        if kind == KIND_JSON {
            notices.push(serde_json::from_slice(bytes).unwrap());
        } else {
            assert_eq!(kind, KIND_FRAMES);
            assert_eq!(bytes.len() % 152, 0);
            records += bytes.len() / 152;
        }
    }
    (notices, records)
}

#[test]
fn first_messages_are_the_status_and_a_frame() {
    let mut e = Engine::new(CONFIG).unwrap();
    let (notices, records) = messages(&e.first(&clock));
    assert_eq!(records, 1);
    let s = &notices[0];
    assert_eq!(s["type"], "status");
    assert_eq!(s["scenario"], "rosette");
    assert_eq!(s["method"], "rattle");
    assert_eq!(s["error_estimate"]["how"], "exact");
    assert_eq!(s["frame_fields"].as_array().unwrap().len(), 19);
}

#[test]
fn commands_are_checked_as_the_server_checks_them() {
    let mut e = Engine::new(CONFIG).unwrap();
    let sent = [
        "not json",
        r#"{"type": "fly"}"#,
        r#"{"type": "pause", "extra": 1}"#,
        r#"{"type": "set_params", "length": 5000}"#,
        r#"{"type": "set_method", "method": "euler"}"#,
        r#"{"type": "load_scenario", "name": "nowhere"}"#,
        r#"{"type": "step", "n": 0}"#,
        r#"{"type": "set_model", "model": "damped", "params": {"damping": -1}}"#,
    ];
    let (notices, _) = messages(&e.tick(&sent.map(String::from), 0.0, &clock, 1.0));
    let errors: Vec<String> = notices
        .iter()
        .filter(|n| n["type"] == "error")
        .map(|n| n["message"].as_str().unwrap().to_string())
        .collect();
    assert_eq!(errors.len(), sent.len(), "{errors:?}");
    for (got, want) in errors.iter().zip([
        "not JSON",
        "unknown command type 'fly'",
        "unknown key 'extra'",
        "length = 5000: must be between 0.001 and 1000 m",
        "unknown method 'euler'",
        "unknown scenario \"nowhere\"; available: rosette, damped_swing",
        "n = 0: an integer from 1 to 100000",
        "invalid damping",
    ]) {
        assert!(got.contains(want), "{got:?} lacks {want:?}");
    }
    let status = notices.iter().rfind(|n| n["type"] == "status").unwrap();
    assert_eq!(status["commands"], sent.len());
    assert_eq!(status["epoch"], 0, "nothing changed");
}

#[test]
fn a_scenario_loads_and_runs_paced_by_the_time_passed_in() {
    let mut e = Engine::new(CONFIG).unwrap();
    let cmds = [r#"{"type": "load_scenario", "name": "damped_swing"}"#.to_string()];
    let (notices, records) = messages(&e.tick(&cmds, 0.0, &clock, 1.0));
    assert_eq!(records, 1);
    let s = notices.iter().find(|n| n["type"] == "status").unwrap();
    assert_eq!(s["model"], "damped");
    assert_eq!(s["model_params"]["damping"], 0.5);
    assert_eq!(s["t0"], 1.0);
    assert_eq!(s["error_estimate"]["how"], "richardson");
    assert_eq!(s["error_estimate"]["reference"]["dt"], 0.001);
    for _ in 0..30 {
        e.tick(&[], 1.0 / 60.0, &clock, 1.0);
    }
    // half a second of simulated time in whole steps of 2 ms
    assert!((e.session.stepper.t() - 1.5).abs() < 2.5e-3, "{}", e.session.stepper.t());
    let set = [r#"{"type": "set_time_scale", "time_scale": 4}"#.to_string()];
    let (_, records) = messages(&e.tick(&set, 1.0 / 60.0, &clock, 1.0));
    assert_eq!(records, 4, "four records per tick at time scale 4");
}

#[test]
fn the_exact_solution_answered_in_the_page_has_the_small_swing_period() {
    use pendulab_wasm::analyses::request;
    // a planar swing of 0.1 rad: T = 2π√(l/g)(1 + θ₀²/16 + 11θ₀⁴/3072 + …) (the swing period)
    let (l, g, th) = (1.3f64, 9.81f64, 0.1f64);
    let (status, a) = request(&format!(
        r#"{{"path": "api/exact", "body": {{"length": {l}, "mass": 2.0, "g": {g}, "theta": {th}}}}}"#
    ));
    assert_eq!(status, 200, "{a}");
    assert_eq!(a["kind"], "planar");
    let t = a["period_z"].as_f64().unwrap();
    let series =
        2.0 * std::f64::consts::PI * (l / g).sqrt() * (1.0 + th * th / 16.0 + 11.0 * th.powi(4) / 3072.0);
    assert!((t / series - 1.0).abs() < 1e-7, "{t} vs {series}");
    assert!(a["phases"].is_null() && a["phases_note"].as_str().unwrap().contains("planar"));
    // bad input: named, 422
    let (status, a) = request(r#"{"path": "api/exact", "body": {"length": -1, "theta": 1}}"#);
    assert_eq!(status, 422);
    assert!(a["detail"].as_str().unwrap().contains("length = -1"), "{a}");
    assert_eq!(request(r#"{"path": "api/fit", "body": {}}"#).0, 404);
}

#[test]
fn v_eff_has_its_minimum_at_the_conical_orbit() {
    use pendulab_wasm::analyses::request;
    // the conical orbit at θc: φ̇² = g/(l cos θc), J₃ = m l² sin²θc φ̇ — V_eff's minimum (T-2.5)
    let (l, m, g, tc) = (0.8, 1.5, 9.81, 0.7f64);
    let j3 = m * l * l * tc.sin().powi(2) * (g / (l * tc.cos())).sqrt();
    let n = 2000;
    let (status, a) = request(&format!(
        r#"{{"path": "api/effective_potential", "body": {{"length": {l}, "mass": {m}, "g": {g}, "j3": {j3}, "n": {n}}}}}"#
    ));
    assert_eq!(status, 200, "{a}");
    let at = a["minimum"]["theta"].as_f64().unwrap();
    assert!((at - tc).abs() <= std::f64::consts::PI / (n + 1) as f64, "{at} vs {tc}");
    assert_eq!(a["theta"].as_array().unwrap().len(), n);
}

fn nums(v: &Value) -> Vec<f64> {
    v.as_array().unwrap().iter().map(|x| x.as_f64().unwrap()).collect()
}

#[test]
fn a_conical_orbit_lies_on_the_energy_momentum_boundary() {
    use pendulab_wasm::analyses::request;
    let (l, m, g, tc) = (1.2f64, 0.5f64, 9.81f64, 1.0f64);
    let phi_dot = (g / (l * tc.cos())).sqrt();
    let (status, a) = request(&format!(
        r#"{{"path": "api/em_map", "body": {{"length": {l}, "mass": {m}, "g": {g}, "theta": {tc}, "phi_dot": {phi_dot}, "n": 4001}}}}"#
    ));
    assert_eq!(status, 200, "{a}");
    let (j, e) = (nums(&a["boundary"]["j3"]), nums(&a["boundary"]["energy"]));
    let (pj, pe) = (a["point"]["j3"].as_f64().unwrap(), a["point"]["energy"].as_f64().unwrap());
    assert!((pj - m * l * l * tc.sin().powi(2) * phi_dot).abs() < 1e-12);
    // the vertex is the bottom, and the conical point is on the curve (to its sampling)
    let w = m * g * l;
    assert!(j.iter().zip(&e).any(|(a, b)| *a == 0.0 && (*b + w).abs() < 1e-12));
    let (ju, eu) = (m * l * l * (g / l).sqrt(), w);
    let d = j.iter().zip(&e).map(|(a, b)| ((a - pj) / ju).hypot((b - pe) / eu)).fold(f64::INFINITY, f64::min);
    assert!(d < 2e-3, "{d}");
    assert_eq!(request(r#"{"path": "api/em_map", "body": {"g": 0, "theta": 1}}"#).0, 422);
}

#[test]
fn the_reduced_orbit_keeps_the_casimir_and_the_energy_plane() {
    use pendulab_wasm::analyses::request;
    let (status, a) = request(
        r#"{"path": "api/reduced", "body": {"length": 1.5, "mass": 1, "g": 9.81, "theta": 1.2, "theta_dot": 0.4, "phi_dot": 2.0}}"#,
    );
    assert_eq!(status, 200, "{a}");
    let (s1, s2, s3) =
        (nums(&a["orbit"]["sigma1"]), nums(&a["orbit"]["sigma2"]), nums(&a["orbit"]["sigma3"]));
    let (j, h, gamma) =
        (a["j"].as_f64().unwrap(), a["plane"]["h"].as_f64().unwrap(), a["plane"]["gamma"].as_f64().unwrap());
    assert_eq!(s1.len(), 400);
    for i in 0..s1.len() {
        // T-3.2/T-3.3: C = σ₃(1 − σ₁²) − σ₂² − j² = 0 and H = ½σ₃ + γσ₁ = h along the orbit
        let c = s3[i] * (1.0 - s1[i] * s1[i]) - s2[i] * s2[i] - j * j;
        assert!(c.abs() < 1e-9 * s3[i].max(1.0), "C = {c} at {i}");
        assert!((0.5 * s3[i] + gamma * s1[i] - h).abs() < 1e-9 * h.abs().max(1.0), "H at {i}");
    }
    // the orbit spans one z-period: σ₁ comes back to where it started
    assert!((s1[0] - s1[s1.len() - 1]).abs() < 1e-9);
}

/// The refusals carry the server's message keys and values (python/pendulab/server/messages.json; the
/// server's pydantic check keys exactly one problem of these kinds), so the page translates them; two
/// problems, or one of another kind, carry none (the page shows the English words), as on the server.
/// The registered methods as a refusal lists them.
fn methods() -> String {
    pendulab_core::integrate::all().iter().map(|m| m.name).collect::<Vec<_>>().join(", ")
}

#[test]
fn refusals_carry_the_servers_message_keys() {
    let messages_json: Value =
        serde_json::from_str(include_str!("../../../python/pendulab/server/messages.json")).unwrap();
    let mut e = Engine::new(CONFIG).unwrap();
    let cases: [(&str, Option<(&str, Value)>); 19] = [
        (
            r#"{"type": "set_params", "length": 5000}"#,
            Some(("too_large", serde_json::json!({"name": "length", "value": "5000", "limit": 1000.0}))),
        ),
        (
            r#"{"type": "set_params", "length": 5000.0}"#,
            Some(("too_large", serde_json::json!({"name": "length", "value": "5000.0", "limit": 1000.0}))),
        ),
        (
            r#"{"type": "set_params", "mass": 0}"#,
            Some(("too_small", serde_json::json!({"name": "mass", "value": "0", "limit": 0.001}))),
        ),
        (
            r#"{"type": "set_params", "g": -1e4, "length": 1}"#,
            Some(("too_small", serde_json::json!({"name": "g", "value": "-10000.0", "limit": -1000.0}))),
        ),
        (r#"{"type": "pause", "extra": 1}"#, Some(("unknown_key", serde_json::json!({"name": "extra"})))),
        (
            r#"{"type": "set_method", "dt": 1}"#,
            Some(("too_large", serde_json::json!({"name": "dt", "value": "1", "limit": 0.1}))),
        ),
        (r#"{"type": "set_time_scale"}"#, Some(("missing", serde_json::json!({"name": "time_scale"})))),
        (
            r#"{"type": "set_time_scale", "time_scale": 1e6}"#,
            Some((
                "too_large",
                serde_json::json!({"name": "time_scale", "value": "1000000.0", "limit": 1000.0}),
            )),
        ),
        (
            r#"{"type": "step", "n": 0}"#,
            Some(("too_small", serde_json::json!({"name": "n", "value": "0", "limit": 1}))),
        ),
        (
            r#"{"type": "step", "n": 200000}"#,
            Some(("too_large", serde_json::json!({"name": "n", "value": "200000", "limit": 100000}))),
        ),
        (r#"{"type": "load_scenario"}"#, Some(("missing", serde_json::json!({"name": "name"})))),
        (
            r#"{"type": "crane", "on": true, "speed": 1}"#,
            Some(("unknown_key", serde_json::json!({"name": "speed"}))),
        ),
        // two problems, or a problem the server does not key: no key
        (r#"{"type": "set_params", "length": 5000, "mass": 0}"#, None),
        (r#"{"type": "set_params", "length": "a"}"#, None),
        (r#"{"type": "set_method", "method": "euler", "dt": 1}"#, None),
        (r#"{"type": "set_method", "method": 3}"#, None),
        (r#"{"type": "step", "n": 2.5}"#, None),
        // an unknown method, with the nearest name when there is one (was the English words alone)
        (
            r#"{"type": "set_method", "method": "euler"}"#,
            Some(("unknown_method", serde_json::json!({"method": "euler", "available": methods()}))),
        ),
        (
            r#"{"type": "set_method", "method": "RATTLE", "dt": 0.01}"#,
            Some((
                "unknown_method_hint",
                serde_json::json!({"method": "RATTLE", "nearest": "rattle", "available": methods()}),
            )),
        ),
    ];
    let sent: Vec<String> = cases.iter().map(|(c, _)| c.to_string()).collect();
    let (notices, _) = messages(&e.tick(&sent, 0.0, &clock, 1.0));
    let errors: Vec<&Value> = notices.iter().filter(|n| n["type"] == "error").collect();
    assert_eq!(errors.len(), cases.len(), "{errors:?}");
    for ((text, want), got) in cases.iter().zip(errors) {
        match want {
            Some((key, values)) => {
                assert_eq!(got["key"], *key, "{text}: {got}");
                assert_eq!(got["values"], *values, "{text}: {got}");
                assert!(messages_json[key].is_string(), "{key} is not in messages.json");
                assert!(got["message"].is_string() && got["command"].is_string(), "{got}");
            }
            None => assert!(got.get("key").is_none(), "{text}: {got}"),
        }
    }
}

/// A command that is carried out but fails (an error of the core, keyed by its kind) between two
/// refusals leaves each refusal its own key.
#[test]
fn a_failing_command_between_refusals_keeps_their_keys_apart() {
    let mut e = Engine::new(CONFIG).unwrap();
    let sent = [
        r#"{"type": "step", "n": 0}"#,
        r#"{"type": "set_model", "model": "damped", "params": {"damping": -1}}"#,
        r#"{"type": "pause", "extra": 1}"#,
    ]
    .map(String::from);
    let (notices, _) = messages(&e.tick(&sent, 0.0, &clock, 1.0));
    let errors: Vec<&Value> = notices.iter().filter(|n| n["type"] == "error").collect();
    assert_eq!(errors.len(), 3, "{errors:?}");
    assert_eq!(errors[0]["key"], "too_small");
    assert!(errors[1]["message"].as_str().unwrap().contains("invalid damping = -1: "), "{}", errors[1]);
    assert_eq!(errors[1]["key"], "invalid_parameter");
    assert_eq!(
        (&errors[1]["values"]["name"], &errors[1]["values"]["value"]),
        (&"damping".into(), &"-1".into())
    );
    assert_eq!(errors[1]["command"], "set_model");
    assert_eq!(errors[2]["key"], "unknown_key");
}
