//! The message keys of refused commands, as the server gives them (docs/web.md, "Languages"), so that
//! the page translates the in-page engine's refusals too: `python/pendulab/server/messages.json`'s
//! `too_small`, `too_large`, `missing` and `unknown_key`, with their `values` (`name`, and for a limit
//! the number as sent, `value`, and the bound, `limit`). The server keys a refusal when pydantic found
//! exactly one problem and of one of these kinds (`pendulab.server.protocol.validation_key`); this
//! module finds the same one problem in the command's JSON (the core's `wire::parse_command` has already
//! refused it, with the English words the notice keeps as its `message`). Limits are the lab's
//! (`wire::LIMITS`, the server's `LIMITS`: inclusive, so never the `_strict` keys): length \[m\], mass
//! \[kg\], g [m/s²], dt \[s\], time_scale (a ratio), step's n (steps). And `set_method`'s unknown method
//! ([`unknown_method_key`]), keyed as the server keys its own check of it: `unknown_method`,
//! `unknown_method_hint` (method, available, and the nearest name).

use crate::wire::{unknown_method, LIMITS};
use pendulab_core::Method;
use serde_json::{json, Map, Value};

/// The fields each command may carry, and the one it must carry (the server's pydantic models).
fn fields(kind: &str) -> Option<(&'static [&'static str], Option<&'static str>)> {
    Some(match kind {
        "set_params" => (&["length", "mass", "g", "params"], None),
        "set_model" => (&["model", "params"], Some("model")),
        "set_state" => (&["x", "v", "project", "theta", "phi", "theta_dot", "phi_dot"], None),
        "set_method" => (&["method", "dt"], None),
        "set_time_scale" => (&["time_scale"], Some("time_scale")),
        "step" => (&["n"], None),
        "load_scenario" => (&["name"], Some("name")),
        "crane" => (&pendulab_core::live::crane_wire::KEYS, None),
        "pause" | "resume" | "reset" => (&[], None),
        _ => return None,
    })
}

/// A field's limits (min, max) and whether it is a whole number (step's n).
fn limits(kind: &str, field: &str) -> Option<(f64, f64, bool)> {
    if (kind == "step") != (field == "n") {
        return None; // n is step's alone, and step has no other
    }
    LIMITS.iter().find(|(n, ..)| *n == field).map(|(_, lo, hi, _)| (*lo, *hi, field == "n"))
}

/// How the server shows a value sent (Python's `json.dumps`, at most 80 characters).
fn show(v: &Value) -> String {
    let t = v.to_string();
    if t.chars().count() <= 80 {
        t
    } else {
        t.chars().take(77).collect::<String>() + "..."
    }
}

/// One problem of a command: keyed (the key and values) or not.
type Problem = Option<(&'static str, Value)>;

/// The problem of `field` = `v` of command `kind`, if any (`None`: no problem).
fn field_problem(kind: &str, field: &str, v: &Value) -> Option<Problem> {
    let (lo, hi, whole) = limits(kind, field)?;
    if v.is_null() && !whole {
        return None; // an optional number left out
    }
    let Some(x) = v.as_f64().filter(|_| v.is_number()) else {
        return Some(None); // not a number: the server's words are its own (not keyed)
    };
    if whole && v.as_i64().is_none() && v.as_u64().is_none() {
        return Some(None);
    }
    // the limit as the server's model states it: a whole number for n, else the float
    let limit = |b: f64| if whole { json!(b as i64) } else { json!(b) };
    let value = json!({ "name": field, "value": show(v) });
    if x < lo {
        Some(Some(("too_small", merge(value, "limit", limit(lo)))))
    } else if x > hi {
        Some(Some(("too_large", merge(value, "limit", limit(hi)))))
    } else {
        None
    }
}

fn merge(mut v: Value, key: &str, x: Value) -> Value {
    v[key] = x;
    v
}

/// The message key and values of the refused command `text`, when the server would key it: exactly one
/// problem, and of a kind the page translates; `None` otherwise (the page shows the English words).
pub fn key_of(text: &str) -> Option<(&'static str, Value)> {
    let Ok(Value::Object(o)) = serde_json::from_str::<Value>(text) else {
        return None;
    };
    let kind = o.get("type")?.as_str()?;
    let (allowed, required) = fields(kind)?;
    let mut problems: Vec<Problem> = Vec::new();
    for (k, v) in &o {
        if k == "type" {
            continue;
        }
        if !allowed.contains(&k.as_str()) {
            problems.push(Some(("unknown_key", json!({ "name": k }))));
        } else if let Some(p) = field_problem(kind, k, v) {
            problems.push(p);
        }
    }
    if let Some(r) = required.filter(|r| !o.contains_key(*r)) {
        problems.push(Some(("missing", json!({ "name": r }))));
    }
    params_problems(&o, &mut problems);
    match problems.as_slice() {
        [Some((key, values))] => Some((key, values.clone())),
        _ => None,
    }
}

/// `params` that is not an object of numbers is a problem the server does not key.
fn params_problems(o: &Map<String, Value>, problems: &mut Vec<Problem>) {
    match o.get("params") {
        None | Some(Value::Null) => {}
        Some(Value::Object(m)) => {
            problems
                .extend(m.values().filter(|v| !matches!(v.as_f64(), Some(x) if x.is_finite())).map(|_| None));
        }
        Some(_) => problems.push(None),
    }
}

/// The message key and values of the `set_method` command `text` refused with `words` for its `method`
/// alone, a string that names no registered method (`wire::unknown_method`: `unknown_method`, or
/// `unknown_method_hint` with the nearest name); `None` for any other refusal, or when another problem
/// was found besides (the words are then more than that refusal's).
pub fn unknown_method_key(text: &str, words: &str) -> Option<(&'static str, Value)> {
    let Ok(Value::Object(o)) = serde_json::from_str::<Value>(text) else {
        return None;
    };
    let v = o.get("method").filter(|_| o.get("type").and_then(Value::as_str) == Some("set_method"))?;
    if v.as_str().is_none_or(|m| Method::from_name(m).is_ok()) {
        return None; // not a string (not keyed), or a method: refused for something else
    }
    let (own, key) = unknown_method(v);
    key.filter(|_| own == words)
}
