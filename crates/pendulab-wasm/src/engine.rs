//! One page's engine: the example scenarios and a [`LiveSession`], driven by JSON command messages and
//! ticks, answering with the same messages a `pendulab serve` WebSocket sends — binary frames of
//! float64 records and JSON notices — packed into one buffer for the Web Worker to unpack
//! ([`pack`]: per message a kind byte, 0 frames or 1 JSON text, its length as u32 little-endian, the
//! bytes). Time is passed in: the seconds elapsed since the last tick and a clock for the budget.
//! A refused command's notice carries the server's message key and values where the server would give
//! them ([`crate::refusal`]), so the page says it in its own language.

use crate::wire::{error_notice, event_notice, keyed_notice, parse_command, setup_from};
use pendulab_core::live::session::Setup;
use pendulab_core::live::{Clock, LiveSession, Out};
use serde_json::Value;

/// A message kind in the packed buffer: binary frame records.
pub const KIND_FRAMES: u8 = 0;
/// A message kind in the packed buffer: a JSON notice.
pub const KIND_JSON: u8 = 1;

/// The scenarios and the session of one page (or one pendulum of two).
pub struct Engine {
    setups: Vec<Value>,
    /// The session.
    pub session: LiveSession,
}

impl Engine {
    /// From `{"scenarios": [... as GET /api/scenarios ...], "scenario": name}`: the session starts with
    /// the named scenario (default: the first that loads).
    pub fn new(config: &str) -> Result<Engine, String> {
        let cfg: Value =
            serde_json::from_str(config).map_err(|e| format!("engine configuration is not JSON: {e}"))?;
        let setups = cfg["scenarios"].as_array().cloned().unwrap_or_default();
        let wanted = cfg["scenario"].as_str();
        let first = setups
            .iter()
            .filter(|d| wanted.is_none() || d["name"].as_str() == wanted)
            .find_map(|d| setup_from(d).ok())
            .ok_or_else(|| format!("no scenario to start from (asked for {wanted:?})"))?;
        let session = LiveSession::new(first).map_err(|e| e.to_string())?;
        Ok(Engine { setups, session })
    }

    fn resolve(setups: &[Value], name: &str) -> Result<Setup, String> {
        match setups.iter().find(|d| d["name"].as_str() == Some(name)) {
            Some(d) => setup_from(d),
            None => {
                let names: Vec<&str> = setups.iter().filter_map(|d| d["name"].as_str()).collect();
                Err(format!("unknown scenario {name:?}; available: {}", names.join(", ")))
            }
        }
    }

    /// What a new connection gets first (status, the current frame), packed.
    pub fn first(&mut self, clock: &dyn Clock) -> Vec<u8> {
        let out = self.session.first_messages(clock);
        pack(&out)
    }

    /// One tick: `messages` are the command texts received since the last tick, `elapsed` \[s\] the wall
    /// clock since then, `budget` \[s\] the stepping time allowed; the messages to send, packed.
    pub fn tick(&mut self, messages: &[String], elapsed: f64, clock: &dyn Clock, budget: f64) -> Vec<u8> {
        let setups = &self.setups;
        let commands: Vec<_> =
            messages.iter().map(|m| parse_command(m, &|n| Self::resolve(setups, n))).collect();
        // the refusals' words and keys, in the order the session reports them
        let keys: Vec<Keyed> = messages
            .iter()
            .zip(&commands)
            .filter_map(|(text, c)| {
                c.as_ref().err().map(|(words, _)| (words.clone(), refusal_key(text, words)))
            })
            .collect();
        let out = self.session.tick(commands, elapsed, clock, budget, 0);
        pack_keyed(&out, keys)
    }
}

/// A refusal's words and its message key and values (`None`: not keyed).
type Keyed = (String, Option<(&'static str, Value)>);

/// The message key of refused command `text` refused with `words`: an unknown method alone, else one
/// problem (no "; " in the words).
fn refusal_key(text: &str, words: &str) -> Option<(&'static str, Value)> {
    if let Some(key) = crate::refusal::unknown_method_key(text, words) {
        return Some(key);
    }
    if words.contains("; ") {
        return None;
    }
    crate::refusal::key_of(text)
}

/// The messages `out` as one buffer (the module doc).
pub fn pack(out: &[Out]) -> Vec<u8> {
    pack_keyed(out, Vec::new())
}

/// [`pack`], with the tick's refusals and their keys: `out` has them as [`Out::Error`]s with the same
/// words, in the commands' order, among the errors of the commands carried out.
fn pack_keyed(out: &[Out], keys: Vec<Keyed>) -> Vec<u8> {
    let mut keys = keys.into_iter().peekable();
    let mut buf = Vec::new();
    let mut put = |kind: u8, bytes: &[u8]| {
        buf.push(kind);
        buf.extend_from_slice(&(bytes.len() as u32).to_le_bytes());
        buf.extend_from_slice(bytes);
    };
    for o in out {
        match o {
            Out::Frames(records) => {
                let bytes: Vec<u8> = records.iter().flat_map(|r| r.0).flat_map(f64::to_le_bytes).collect();
                put(KIND_FRAMES, &bytes);
            }
            Out::Status(v) => put(KIND_JSON, v.to_string().as_bytes()),
            Out::Error(message, command) => {
                let key = keys.next_if(|(words, _)| words == message).and_then(|(_, k)| k);
                let notice = match key {
                    Some((key, values)) => keyed_notice(message, *command, key, &values),
                    None => error_notice(message, *command),
                };
                put(KIND_JSON, notice.to_string().as_bytes())
            }
            Out::Keyed(message, command, key, values) => {
                put(KIND_JSON, keyed_notice(message, *command, key, values).to_string().as_bytes())
            }
            Out::Event(e, epoch, skipped) => {
                put(KIND_JSON, event_notice(e, *epoch, *skipped).to_string().as_bytes())
            }
        }
    }
    buf
}

/// The messages of a packed buffer: (kind, bytes).
pub fn unpack(buf: &[u8]) -> Vec<(u8, &[u8])> {
    let mut out = Vec::new();
    let mut i = 0;
    while i + 5 <= buf.len() {
        let n = u32::from_le_bytes(buf[i + 1..i + 5].try_into().unwrap()) as usize;
        out.push((buf[i], &buf[i + 5..i + 5 + n]));
        i += 5 + n;
    }
    out
}
