//! The wire's `crane` command (docs/web.md "Crane mode"): `{"type": "crane", "on": true, "drive":
//! [vx, vy], "move": [dx, dy], "stop": true, "rope": l}`, every key optional — `on` switches the
//! session to the crane mode, `drive` sets the trolley's commanded velocity [m/s] (x along the girder,
//! y across), `move` moves it by a distance \[m\] and stops, `stop` is `drive` [0, 0], `rope` hoists to
//! a rope length \[m\]. The values are checked here for their form; the crane checks them against its
//! limits (v_max, the rope's range).

use super::crane::CraneCommand;
use serde_json::{Map, Value};

/// The keys of a `crane` command.
pub const KEYS: [&str; 5] = ["on", "drive", "move", "stop", "rope"];

fn pair(o: &Map<String, Value>, key: &str, problems: &mut Vec<String>) -> Option<[f64; 2]> {
    let v = o.get(key).filter(|v| !v.is_null())?;
    match v.as_array().map(|a| a.iter().map(Value::as_f64).collect::<Option<Vec<_>>>()) {
        Some(Some(c)) if c.len() == 2 && c.iter().all(|x| x.is_finite()) => Some([c[0], c[1]]),
        _ => {
            problems.push(format!("{key} = {v}: 2 finite numbers (x, y)"));
            None
        }
    }
}

fn flag(o: &Map<String, Value>, key: &str, problems: &mut Vec<String>) -> bool {
    match o.get(key) {
        None | Some(Value::Null) => false,
        Some(Value::Bool(b)) => *b,
        Some(v) => {
            problems.push(format!("{key} = {v}: true or false"));
            false
        }
    }
}

/// The crane command of a message's object `o` (the problems appended to `problems`).
pub fn parse(o: &Map<String, Value>, problems: &mut Vec<String>) -> CraneCommand {
    let mut c = CraneCommand {
        on: flag(o, "on", problems),
        drive: pair(o, "drive", problems),
        move_by: pair(o, "move", problems),
        rope: None,
    };
    if flag(o, "stop", problems) {
        c.drive = Some([0.0, 0.0]);
    }
    if let Some(v) = o.get("rope").filter(|v| !v.is_null()) {
        match v.as_f64().filter(|x| x.is_finite()) {
            Some(x) => c.rope = Some(x),
            None => problems.push(format!("rope = {v}: a rope length in m")),
        }
    }
    if c.drive.is_some() && c.move_by.is_some() {
        problems.push("give drive (or stop) or move, not both".into());
    }
    if problems.is_empty() && c == CraneCommand::default() {
        problems.push("give at least one of on, drive [m/s], move [m], stop, rope [m]".into());
    }
    c
}
