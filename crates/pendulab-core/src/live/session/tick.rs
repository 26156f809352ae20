//! One tick of a session ([`LiveSession::tick`], [`LiveSession::tick_fair`]): the commands within the
//! budget, the waiting steps, the advance by the wall-clock time passed in, the error estimate, the
//! frames (never a non-finite one), the string's events and status notices; and what a new
//! connection gets first. Units: SI (s, m, m/s, kg, m/s²).

use super::{Command, LiveSession, Out, MAX_EVENT_NOTICES};
use crate::error::Error;
use crate::live::budget::{Budget, Clock, TICK_BUDGET};
use crate::live::frame::Record;
use serde_json::json;

impl LiveSession {
    /// What a new connection gets first: the status and the current state's frame.
    pub fn first_messages(&mut self, clock: &dyn Clock) -> Vec<Out> {
        let budget = Budget::new(clock, TICK_BUDGET);
        let mut rec = vec![self.record()];
        self.error.fill(&mut rec, &budget);
        let mut out = vec![Out::Status(self.status())];
        self.finite(rec, &mut out);
        out
    }

    /// One tick: the commands in order (`Err`: a message refused before it became a command, with its
    /// text and command name), the waiting steps, the advance by `elapsed` \[s\], the error estimate in
    /// what is left of `budget_seconds`, the frames, the string's events, and status notices where
    /// something changed. `dropped`: messages thrown away (throttling). [`LiveSession::tick_fair`]
    /// with every command carried out.
    pub fn tick(
        &mut self,
        commands: Vec<std::result::Result<Command, (String, Option<&'static str>)>>,
        elapsed: f64,
        clock: &dyn Clock,
        budget_seconds: f64,
        dropped: u64,
    ) -> Vec<Out> {
        self.tick_fair(commands, elapsed, clock, budget_seconds, dropped, None).0
    }

    /// [`LiveSession::tick`], with the commands inside the budget when `debt` \[s\] is given (a server
    /// with many sessions): at least one command, more only while the budget lasts; the wall time the
    /// commands took beyond `budget_seconds` is added to `debt`, and while in debt the tick carries out
    /// none (stepping and frames go on) and pays off `budget_seconds`. So a page that floods
    /// `load_scenario` gets about its share of the room, not a tick's worth of commands per tick.
    /// Returns the messages and how many of `commands` were carried out (the rest wait for the caller
    /// to hand them in again; they are counted in `commands` then).
    pub fn tick_fair(
        &mut self,
        commands: Vec<std::result::Result<Command, (String, Option<&'static str>)>>,
        elapsed: f64,
        clock: &dyn Clock,
        budget_seconds: f64,
        dropped: u64,
        mut debt: Option<&mut f64>,
    ) -> (Vec<Out>, usize) {
        let budget = Budget::new(clock, budget_seconds);
        let started = budget.now();
        let mut out = Vec::new();
        let mut changed = !commands.is_empty() || dropped > 0;
        self.commands += dropped;
        let mut taken = 0;
        let mut parts: [Vec<Record>; 3] = [Vec::new(), Vec::new(), Vec::new()];
        if let Some(d) = debt.as_deref_mut().filter(|d| **d > 0.0) {
            *d = (*d - budget_seconds).max(0.0); // paying for earlier commands: none this tick
            changed = dropped > 0;
        } else {
            let fair = debt.is_some();
            for item in commands {
                if fair && taken > 0 && budget.spent() {
                    break;
                }
                taken += 1;
                self.commands += 1;
                match item {
                    Err((message, command)) => out.push(Out::Error(message, command)),
                    Ok(cmd) => {
                        let name = cmd.name();
                        match self.apply(cmd) {
                            Ok(Some(r)) => parts[0] = vec![r], // only the last discontinuity matters
                            Ok(None) => {}
                            Err(e) => out.push(self.error_out(e, Some(name))),
                        }
                    }
                }
            }
            if let Some(d) = debt.filter(|_| taken > 0) {
                *d += (budget.now() - started - budget_seconds).max(0.0);
            }
        }
        let was_lagging = self.lagging;
        match self.take_pending_steps(&budget) {
            Ok(Some(r)) => {
                parts[1] = vec![r];
                changed |= self.pending_steps == 0;
            }
            Ok(None) => {}
            Err(e) => {
                out.push(self.error_out(e, Some("step")));
                changed = true;
            }
        }
        if changed {
            out.push(Out::Status(self.status()));
        }
        match self.advance(elapsed, &budget) {
            Ok(r) => parts[2] = r,
            Err(e) => {
                out.push(self.error_out(e, None));
                out.push(Out::Status(self.status()));
            }
        }
        let how = self.error.how;
        for part in parts.iter_mut() {
            self.error.fill(part, &budget);
        }
        if self.error.how != how {
            out.push(Out::Status(self.status()));
        }
        for part in parts {
            if !self.finite(part, &mut out) {
                break;
            }
        }
        out.extend(self.take_event_notices());
        if self.lagging != was_lagging {
            out.push(Out::Status(self.status()));
        }
        (out, taken)
    }

    /// The string's events since the last call as `event` notices, oldest first: at most
    /// [`MAX_EVENT_NOTICES`], the latest, each counting the earlier ones skipped (empty for the other
    /// models). Each keeps the epoch it happened in.
    pub fn take_event_notices(&mut self) -> Vec<Out> {
        self.collect_events();
        let events = std::mem::take(&mut self.events);
        let skipped = events.len().saturating_sub(MAX_EVENT_NOTICES);
        events.into_iter().skip(skipped).map(|(e, epoch)| Out::Event(e, epoch, skipped)).collect()
    }

    /// The notice of an error of a command, a step or the advance, keyed by its kind when it is of a
    /// common one ([`Error::key`]: a parameter out of range, a state off the sphere, an unknown model or
    /// parameter, …), else plain. A stopped integration ([`Error::Stopped`]) is keyed
    /// `integration_stopped`, with the integrator's words as `detail`, and when its cause is of a common
    /// kind, `why` names the cause's key and the cause's values are beside `detail` (flat: a page words
    /// the detail in its language too).
    fn error_out(&mut self, e: Error, command: Option<&'static str>) -> Out {
        match e.key() {
            Some((key, values)) => {
                let values = values.into_iter().map(|(k, v)| (k.to_string(), json!(v))).collect();
                Out::Keyed(e.to_string(), command, key, serde_json::Value::Object(values))
            }
            None => Out::Error(e.to_string(), command),
        }
    }

    /// Appends `records` up to the first one holding a non-finite value; if there is one, pauses, adds
    /// an error notice naming the quantities and the time and a status, and returns false.
    fn finite(&mut self, records: Vec<Record>, out: &mut Vec<Out>) -> bool {
        if records.is_empty() {
            return true;
        }
        let Some(first) = records.iter().position(|r| !r.non_finite().is_empty()) else {
            out.push(Out::Frames(records));
            return true;
        };
        let bad = records[first].non_finite();
        let t = records[first].t();
        if first > 0 {
            out.push(Out::Frames(records[..first].to_vec()));
        }
        let when = if t.is_finite() { short(t) } else { format!("≈ {}", short(self.stepper.t())) };
        let fields = bad.iter().take(6).cloned().collect::<Vec<_>>().join(", ");
        self.paused = true;
        self.pending_steps = 0;
        out.push(Out::Keyed(
            format!(
                "the motion left floating point at t = {when} s ({fields} not finite): parameters or a start \
                 this extreme; paused — reset, or change the parameters"
            ),
            None,
            "nonfinite_motion",
            json!({ "t": when, "fields": fields }),
        ));
        out.push(Out::Status(self.status()));
        false
    }
}

/// `x` with 6 significant digits, trailing zeros dropped (Python's `{:.6g}` for the lab's times).
fn short(x: f64) -> String {
    if x == 0.0 || !x.is_finite() {
        return format!("{x}");
    }
    let digits = (5 - x.abs().log10().floor() as i32).clamp(0, 17) as usize;
    let s = format!("{x:.digits$}");
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::integrate::Method;
    use crate::live::frame::FRAME_FIELDS;
    use crate::live::pendulum::LivePendulum;
    use crate::live::session::Setup;

    /// No frame carries a non-finite number: the records up to the first bad one are sent, the session
    /// pauses and an error names the quantities and the time.
    #[test]
    fn a_non_finite_record_is_never_sent_the_session_pauses_and_names_the_cause() {
        let p = LivePendulum::new("ideal", 1.0, 1.0, 9.81, &[]).unwrap();
        let state = p.state_from_angles(1.0, 0.0, 0.0, 2.0).unwrap();
        let mut s = LiveSession::new(Setup::new(p, state, Method::Rattle, 1e-3)).unwrap();
        let mut bad = s.record();
        let at = |name: &str| FRAME_FIELDS.iter().position(|f| *f == name).unwrap();
        bad.0[at("energy")] = f64::INFINITY;
        bad.0[at("tension")] = f64::NAN;
        let mut out = Vec::new();
        assert!(!s.finite(vec![s.record(), bad, s.record()], &mut out));
        assert!(matches!(&out[0], Out::Frames(r) if r.len() == 1), "the first record only");
        let Out::Keyed(message, None, "nonfinite_motion", values) = &out[1] else { panic!("{:?}", out[1]) };
        assert!(message.contains("(energy, tension not finite)"), "{message}");
        assert!(message.contains("t = 0 s") && message.contains("paused"), "{message}");
        assert_eq!(values, &json!({ "t": "0", "fields": "energy, tension" }));
        assert_eq!(
            (short(1.5), short(0.016), short(123.4567891), short(1e-7)),
            ("1.5".into(), "0.016".into(), "123.457".into(), "0.0000001".into())
        );
        assert!(matches!(&out[2], Out::Status(v) if v["paused"] == true) && s.paused && out.len() == 3);
        let mut good = Vec::new();
        assert!(s.finite(vec![s.record()], &mut good) && matches!(&good[..], [Out::Frames(_)]));
    }

    /// A stopped integration's notice carries the integrator's error kind and values beside its words.
    #[test]
    fn a_stopped_integration_names_why_with_its_values() {
        let p = LivePendulum::new("ideal", 1.0, 1.0, 9.81, &[]).unwrap();
        let state = p.state_from_angles(1.0, 0.0, 0.0, 2.0).unwrap();
        let mut s = LiveSession::new(Setup::new(p, state, Method::Rattle, 1e-3)).unwrap();
        let diverged = Error::Diverged { t: 2.5, method: "rk4", dt: 0.05 };
        let stopped = s.stopped(diverged.clone());
        assert!(s.paused);
        let Out::Keyed(message, None, "integration_stopped", values) = s.error_out(stopped, None) else {
            panic!("not keyed")
        };
        assert_eq!(message, format!("{diverged}; paused"));
        let expected = json!({ "detail": diverged.to_string(), "why": "diverged", "t": "2.5", "method": "rk4", "dt": "0.05" });
        assert_eq!(values, expected);
        assert!(matches!(s.error_out(Error::Refused("x".into()), None), Out::Error(..)), "plain");
    }

    /// A command the core refuses for a common reason (a state off the sphere, a parameter out of its
    /// range) is keyed by that reason, so that a page words it in its language; a rarer one is plain.
    #[test]
    fn a_command_the_core_refuses_is_keyed_by_its_kind() {
        use crate::live::session::StateSpec;
        let p = LivePendulum::new("ideal", 1.0, 1.0, 9.81, &[]).unwrap();
        let state = p.state_from_angles(1.0, 0.0, 0.0, 2.0).unwrap();
        let mut s = LiveSession::new(Setup::new(p, state, Method::Rattle, 1e-3)).unwrap();
        let (x, v) = (glam::DVec3::new(0.5, 0.0, -0.5), glam::DVec3::ZERO);
        let e = s.apply(Command::SetState(StateSpec::Cartesian { x, v, project: false })).unwrap_err();
        let Out::Keyed(message, Some("set_state"), "off_sphere", values) = s.error_out(e, Some("set_state"))
        else {
            panic!("not keyed")
        };
        assert!(message.starts_with("state is not on TS²"), "{message}");
        assert!(message.contains("(|x| - l)/l = -0.2928932188134524 exceeds"), "{message}"); // the words' value
        assert_eq!(
            values,
            json!({ "what": "(|x| - l)/l", "value": "-0.2928932188134524", "tolerance": "1e-9" })
        );
        let damped = Command::SetModel { model: "damped".into(), params: vec![("damping".into(), -1.0)] };
        let e = s.apply(damped).unwrap_err();
        let Out::Keyed(_, _, "invalid_parameter", values) = s.error_out(e, Some("set_model")) else {
            panic!("not keyed")
        };
        assert_eq!((&values["name"], &values["value"]), (&json!("damping"), &json!("-1")));
        let e = s.apply(Command::SetModel { model: "sprung".into(), params: vec![] }).unwrap_err();
        let Out::Keyed(message, _, "unknown_model", values) = s.error_out(e, Some("set_model")) else {
            panic!("not keyed")
        };
        assert!(message.starts_with("unknown model 'sprung'"), "{message}");
        assert_eq!(values["model"], json!("sprung"));
    }
}
