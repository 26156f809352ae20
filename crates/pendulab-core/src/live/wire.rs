//! The lab's wire format (docs/web.md, "Commands", "Notices"), for both engines — the page's
//! (`crates/pendulab-wasm`) and the server's (`pendulab._core.LiveSession`): JSON command messages
//! checked against the lab's limits into [`Command`]s (the server checks them first with the
//! pydantic models of `pendulab.server.protocol`, which also give its API schema: their bounds are
//! [`LIMITS`] below, read through `pendulab._core.LiveSession.limits()`, so the two checks cannot
//! drift; `python/tests/test_server_limits.py`), scenarios as `GET /api/scenarios`
//! describes them into [`Setup`]s, and the `status` and `event` notices as JSON. SI units: l \[m\], m \[kg\], g [m/s²], t \[s\].

use super::pendulum::LivePendulum;
use super::session::{Command, LiveSession, Setup, StateSpec};
use crate::error::{did_you_mean, nearest, Quoted, Shown};
use crate::string_run::{EventKind, StringEvent};
use crate::{DVec3, Method};
use serde_json::{json, Map, Value};

/// Longest command message read (a command is a few hundred bytes).
pub const MAX_MESSAGE_BYTES: usize = 4096;
/// The command types, in the server's order.
pub const COMMAND_TYPES: [&str; 11] = [
    "set_params",
    "set_model",
    "set_state",
    "set_method",
    "set_time_scale",
    "pause",
    "resume",
    "step",
    "reset",
    "load_scenario",
    "crane",
];
/// The lab's limits, the one table of them (the server's pydantic models take their bounds from it):
/// name, min, max, unit.
pub const LIMITS: [(&str, f64, f64, &str); 6] = [
    ("length", 1e-3, 1e3, "m"),
    ("mass", 1e-3, 1e5, "kg"),
    ("g", -1e3, 1e3, "m/s²"),
    ("dt", 1e-6, 0.1, "s"),
    ("time_scale", 1e-3, 1e3, ""),
    ("n", 1.0, 1e5, "steps"),
];
/// dop853's default tolerances (scenario files' defaults; [`Setup::new`]'s).
pub use super::session::{DEFAULT_ATOL, DEFAULT_RTOL};

/// A refused message: its text and the command type when it could be read.
pub type Refusal = (String, Option<&'static str>);

/// A value of a command in a refusal: a string quoted as the Python layer quotes it ([`Quoted`]: `'RATTLE'`,
/// as the server and the core's own errors say), any other value as JSON; at most 80 characters.
fn show(v: &Value) -> String {
    let t = v.as_str().map_or_else(|| v.to_string(), |s| Quoted(s).to_string());
    if t.chars().count() <= 80 {
        t
    } else {
        t.chars().take(77).collect::<String>() + "..."
    }
}

fn number(o: &Map<String, Value>, key: &'static str, problems: &mut Vec<String>) -> Option<f64> {
    let v = o.get(key)?;
    if v.is_null() {
        return None;
    }
    let Some(x) = v.as_f64().filter(|_| v.is_number()) else {
        problems.push(format!("{key} = {}: input should be a number", show(v)));
        return None;
    };
    if let Some((_, lo, hi, unit)) = LIMITS.iter().find(|(n, ..)| *n == key) {
        if !(x >= *lo && x <= *hi) {
            problems.push(format!(
                "{key} = {}: must be between {} and {} {unit}",
                show(v),
                Shown(*lo),
                Shown(*hi)
            ));
            return None;
        }
    }
    Some(x)
}

fn vec3(o: &Map<String, Value>, key: &'static str, problems: &mut Vec<String>) -> Option<DVec3> {
    let v = o.get(key)?;
    match v.as_array().map(|a| a.iter().map(|c| c.as_f64()).collect::<Option<Vec<_>>>()) {
        Some(Some(c)) if c.len() == 3 => Some(DVec3::new(c[0], c[1], c[2])),
        _ => {
            problems.push(format!("{key} = {}: 3 numbers", show(v)));
            None
        }
    }
}

fn params(o: &Map<String, Value>, problems: &mut Vec<String>) -> Vec<(String, f64)> {
    match o.get("params") {
        None | Some(Value::Null) => Vec::new(),
        Some(Value::Object(m)) => m
            .iter()
            .filter_map(|(k, v)| match v.as_f64() {
                Some(x) if x.is_finite() => Some((k.clone(), x)),
                _ => {
                    problems.push(format!("params.{k} = {}: input should be a finite number", show(v)));
                    None
                }
            })
            .collect(),
        Some(v) => {
            problems.push(format!("params = {}: an object {{name: value}}", show(v)));
            Vec::new()
        }
    }
}

/// The refusal of `set_method`'s `method` = `v`, no registered method: the words of
/// [`crate::Error::UnknownMethod`] (the name [`Quoted`], abbreviated; another value as JSON) with the
/// nearest registered name ([`crate::error::did_you_mean`]), and for a string the message key and values
/// a page words it by (python/pendulab/server/messages.json, as the server keys its own check of the
/// command): `unknown_method` (method: the name, at most 80 characters; available) or
/// `unknown_method_hint` (the same and nearest); a value that is not a string gets no key and no hint.
pub fn unknown_method(v: &Value) -> (String, Option<(&'static str, Value)>) {
    let names: Vec<_> = crate::integrate::all().iter().map(|m| m.name).collect();
    let available = names.join(", ");
    let Some(name) = v.as_str() else {
        return (format!("unknown method {}; available: {available}", show(v)), None);
    };
    let near = nearest(name, names.iter().copied());
    let hint = did_you_mean(name, names.iter().copied());
    // over 80 characters, the middle elided as the server's value (`pendulab.validate.abbreviate`)
    let chars: Vec<char> = name.chars().collect();
    let shown = if chars.len() <= 80 {
        name.to_string()
    } else {
        let (head, tail): (String, String) =
            (chars[..37].iter().collect(), chars[chars.len() - 37..].iter().collect());
        format!("{head} ... {tail}")
    };
    let words = format!("unknown method {}{hint}; available: {available}", show(v));
    let key = match near {
        Some(o) => ("unknown_method_hint", json!({ "method": shown, "nearest": o, "available": available })),
        None => ("unknown_method", json!({ "method": shown, "available": available })),
    };
    (words, Some(key))
}

/// A command from one message, or what is wrong with it; `resolve` finds a scenario by name.
// One flat match with an arm per command of the protocol (the exception listed in Cargo.toml).
#[allow(clippy::too_many_lines)]
pub fn parse_command(
    text: &str,
    resolve: &dyn Fn(&str) -> Result<Setup, String>,
) -> Result<Command, Refusal> {
    if text.len() > MAX_MESSAGE_BYTES {
        return Err((
            format!("message of {} characters is too long (at most {MAX_MESSAGE_BYTES})", text.len()),
            None,
        ));
    }
    let raw: Value = serde_json::from_str(text).map_err(|e| (format!("not JSON: {e}"), None))?;
    let Value::Object(o) = raw else {
        return Err((format!("a command is a JSON object with a 'type', got {}", show(&raw)), None));
    };
    let kind = match o.get("type") {
        Some(Value::String(s)) if COMMAND_TYPES.contains(&s.as_str()) => {
            COMMAND_TYPES.iter().find(|t| *t == s).unwrap()
        }
        other => {
            let what =
                other.map_or("missing 'type'".to_string(), |v| format!("unknown command type {}", show(v)));
            return Err((format!("{what}; expected one of: {}", COMMAND_TYPES.join(", ")), None));
        }
    };
    let keys: &[&str] = match *kind {
        "set_params" => &["length", "mass", "g", "params"],
        "set_model" => &["model", "params"],
        "set_state" => &["x", "v", "project", "theta", "phi", "theta_dot", "phi_dot"],
        "set_method" => &["method", "dt"],
        "set_time_scale" => &["time_scale"],
        "step" => &["n"],
        "load_scenario" => &["name"],
        "crane" => &super::crane_wire::KEYS,
        _ => &[],
    };
    let mut problems: Vec<String> = o
        .keys()
        .filter(|k| *k != "type" && !keys.contains(&k.as_str()))
        .map(|k| format!("unknown key '{k}'"))
        .collect();
    let cmd = match *kind {
        "set_params" => {
            let (length, mass, g) = (
                number(&o, "length", &mut problems),
                number(&o, "mass", &mut problems),
                number(&o, "g", &mut problems),
            );
            let params = params(&o, &mut problems);
            if problems.is_empty() && length.is_none() && mass.is_none() && g.is_none() && params.is_empty() {
                problems.push(
                    "give at least one of length (m), mass (kg), g (m/s²), params {name: value}".into(),
                );
            }
            Command::SetParams { length, mass, g, params }
        }
        "set_model" => {
            let model = o.get("model").and_then(Value::as_str).unwrap_or_default().to_string();
            if model.is_empty() || model.len() > 40 {
                problems.push("model: a model name of 1 to 40 characters".into());
            }
            Command::SetModel { model, params: params(&o, &mut problems) }
        }
        "set_state" => {
            let has = |k: &str| o.get(k).is_some_and(|v| !v.is_null());
            let cart = has("x") || has("v");
            let angles = ["theta", "phi", "theta_dot", "phi_dot"].iter().any(|k| has(k));
            if cart && angles {
                problems
                    .push("give either x and v or angles (theta, phi, theta_dot, phi_dot), not both".into());
                Command::Pause
            } else if cart {
                let (x, v) = (vec3(&o, "x", &mut problems), vec3(&o, "v", &mut problems));
                let project = o.get("project").and_then(Value::as_bool).unwrap_or(false);
                match (x, v) {
                    (Some(x), Some(v)) => Command::SetState(StateSpec::Cartesian { x, v, project }),
                    _ => {
                        problems.push(
                            "a Cartesian state needs both x (3 numbers, m) and v (3 numbers, m/s)".into(),
                        );
                        Command::Pause
                    }
                }
            } else {
                let mut a = [0.0; 4];
                for (i, k) in ["theta", "phi", "theta_dot", "phi_dot"].into_iter().enumerate() {
                    if let Some(v) = o.get(k).filter(|v| !v.is_null()) {
                        match v.as_f64().filter(|x| x.is_finite()) {
                            Some(x) => a[i] = x,
                            None => {
                                problems.push(format!("{k} = {}: input should be a finite number", show(v)))
                            }
                        }
                    }
                }
                if !has("theta") {
                    problems.push(
                        "give x and v (m, m/s), or at least theta (rad) with phi, theta_dot, phi_dot".into(),
                    );
                }
                Command::SetState(StateSpec::Angles(a))
            }
        }
        "set_method" => {
            let method = match o.get("method").filter(|v| !v.is_null()) {
                None => None,
                Some(v) => match v.as_str().map(Method::from_name) {
                    Some(Ok(m)) => Some(m),
                    _ => {
                        problems.push(unknown_method(v).0);
                        None
                    }
                },
            };
            let dt = number(&o, "dt", &mut problems);
            if problems.is_empty() && method.is_none() && dt.is_none() {
                problems.push("give method, dt (s) or both".into());
            }
            Command::SetMethod { method, dt }
        }
        "set_time_scale" => match number(&o, "time_scale", &mut problems) {
            Some(s) => Command::SetTimeScale(s),
            None => {
                if problems.is_empty() {
                    problems.push("time_scale is missing".into());
                }
                Command::Pause
            }
        },
        "step" => {
            let n = o.get("n").map_or(Some(1.0), |v| v.as_u64().map(|n| n as f64));
            match n {
                Some(n) if (1.0..=1e5).contains(&n) => Command::Step(n as u64),
                _ => {
                    problems.push(format!(
                        "n = {}: an integer from 1 to 100000",
                        show(o.get("n").unwrap_or(&Value::Null))
                    ));
                    Command::Pause
                }
            }
        }
        "load_scenario" => match o.get("name").and_then(Value::as_str) {
            Some(name) if !name.is_empty() && name.len() <= 100 && problems.is_empty() => match resolve(name)
            {
                Ok(s) => Command::Load(Box::new(s)),
                Err(e) => return Err((e, Some("load_scenario"))),
            },
            _ => {
                problems.push("name: a scenario name of 1 to 100 characters".into());
                Command::Pause
            }
        },
        "crane" => Command::Crane(super::crane_wire::parse(&o, &mut problems)),
        "pause" => Command::Pause,
        "resume" => Command::Resume,
        _ => Command::Reset,
    };
    if problems.is_empty() {
        Ok(cmd)
    } else {
        Err((problems.join("; "), Some(kind)))
    }
}

/// A setup from one entry of `GET /api/scenarios` (name, title, params, model, model_params, start,
/// method, dt, t0, and the one-file lab's rtol, atol: their defaults when absent).
pub fn setup_from(d: &Value) -> Result<Setup, String> {
    let name = d["name"].as_str().unwrap_or("?");
    let bad = |what: &str| format!("scenario {name:?}: {what}");
    if let Some(e) = d.get("error").and_then(Value::as_str) {
        return Err(bad(e));
    }
    let num = |v: &Value, k: &str| v[k].as_f64().ok_or_else(|| bad(&format!("{k} is not a number")));
    let p = &d["params"];
    let own: Vec<(String, f64)> = d["model_params"]
        .as_object()
        .map(|m| m.iter().filter_map(|(k, v)| v.as_f64().map(|x| (k.clone(), x))).collect())
        .unwrap_or_default();
    let model = d["model"].as_str().unwrap_or("ideal");
    let pendulum = LivePendulum::new(model, num(p, "length")?, num(p, "mass")?, num(p, "g")?, &own)
        .map_err(|e| bad(&e.to_string()))?;
    let v3 = |v: &Value| -> Result<DVec3, String> {
        let a: Vec<f64> =
            v.as_array().map(|a| a.iter().filter_map(Value::as_f64).collect()).unwrap_or_default();
        if a.len() == 3 {
            Ok(DVec3::new(a[0], a[1], a[2]))
        } else {
            Err(bad("start is not 3 numbers"))
        }
    };
    let (x, v) = (v3(&d["start"]["x"])?, v3(&d["start"]["v"])?);
    let state = pendulum
        .state(x, v, false)
        .or_else(|_| pendulum.state(x, v, true))
        .map_err(|e| bad(&e.to_string()))?;
    let method =
        Method::from_name(d["method"].as_str().unwrap_or("rattle")).map_err(|e| bad(&e.to_string()))?;
    Ok(Setup {
        name: Some(name.to_string()),
        title: d["title"].as_str().map(str::to_string),
        pendulum,
        state,
        method,
        dt: num(d, "dt")?,
        rtol: d["rtol"].as_f64().unwrap_or(DEFAULT_RTOL),
        atol: d["atol"].as_f64().unwrap_or(DEFAULT_ATOL),
        t0: num(d, "t0").unwrap_or(0.0),
    })
}

/// A setup from the JSON text of one scenario description ([`setup_from`]).
pub fn setup_from_json(text: &str) -> Result<Setup, String> {
    let value: Value = serde_json::from_str(text).map_err(|e| format!("the scenario is not JSON: {e}"))?;
    setup_from(&value)
}

/// The `status` notice (the same as [`LiveSession::status`]).
pub fn status(s: &LiveSession) -> Value {
    s.status()
}

/// The `error` notice.
pub fn error_notice(message: &str, command: Option<&str>) -> Value {
    json!({ "type": "error", "message": message, "command": command })
}

/// The `error` notice of a message a page translates: `key` (`python/pendulab/server/messages.json`)
/// and its `values` beside the English `message`.
pub fn keyed_notice(message: &str, command: Option<&str>, key: &str, values: &Value) -> Value {
    json!({ "type": "error", "message": message, "command": command, "key": key, "values": values })
}

/// The `event` notice of one of the string's leaves or snaps.
pub fn event_notice(e: &StringEvent, epoch: u64, skipped: usize) -> Value {
    json!({
        "type": "event",
        "kind": if e.kind == EventKind::Slack { "slack" } else { "taut" },
        "t": e.t,
        "energy_lost": e.energy_lost,
        "x": e.after.x.to_array(),
        "epoch": epoch,
        "skipped": skipped,
    })
}
