//! Frame records: one state of a live run as the lab's wire format carries it (docs/web.md, "Frames";
//! the layout is `python/pendulab/server/frame.json`, which a test compares with [`FRAME_FIELDS`]).
//!
//! A record is [`RECORD_LEN`] float64 values: t \[s\], x \[m\], v [m/s] (relative to the pivot), energy E
//! \[J\] (T-2.6; the spring's kinetic + elastic + gravity), J₃ [kg m²/s], the rod's tension T \[N\] (T-2.3;
//! the spring's k(|r| − l₀), the slack string's 0), the power P \[W\] of the non-conservative forces
//! (T-7.1), the acceleration a = ẍ [m/s²] relative to the pivot (T-2.2: m a is the net force there),
//! the pivot's position \[m\] (0 when fixed), taut (1, or 0 while the string is slack) and error_x \[m\],
//! the global position error ([`UNKNOWN`] until the error estimate fills it, [`super::error`]).

use crate::model::registry::AnyModel;
use crate::model::{acceleration, energy, j3, tension, Model};
use crate::state::State;
use crate::DVec3;

/// Names of the values of one record, in wire order (frame.json's `fields`).
pub const FRAME_FIELDS: [&str; RECORD_LEN] = [
    "t", "x1", "x2", "x3", "v1", "v2", "v3", "energy", "j3", "tension", "power", "a1", "a2", "a3", "pivot1",
    "pivot2", "pivot3", "taut", "error_x",
];
/// SI unit of each value (frame.json's `units`).
pub const FRAME_UNITS: [&str; RECORD_LEN] = [
    "s", "m", "m", "m", "m/s", "m/s", "m/s", "J", "kg m^2/s", "N", "W", "m/s^2", "m/s^2", "m/s^2", "m", "m",
    "m", "1", "m",
];
/// Values per record.
pub const RECORD_LEN: usize = 19;
/// `error_x` of a record the estimate has not reached (the page shows "estimate paused").
pub const UNKNOWN: f64 = -1.0;

/// Index of `t`.
pub const T: usize = 0;
/// Index of `x1` (x2, x3 follow).
pub const X: usize = 1;
const V: usize = 4;
const ENERGY: usize = 7;
const J3: usize = 8;
const TENSION: usize = 9;
const POWER: usize = 10;
const A: usize = 11;
const PIVOT: usize = 14;
const TAUT: usize = 17;
/// Index of `error_x`.
pub const ERROR_X: usize = 18;

/// One frame record.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Record(pub [f64; RECORD_LEN]);

impl Record {
    fn put(&mut self, at: usize, v: DVec3) {
        self.0[at..at + 3].copy_from_slice(&v.to_array());
    }

    /// The record of a model with its own stepper (spring, string): power 0 (conservative between the
    /// string's snaps), pivot 0.
    pub fn own(t: f64, s: &State, energy: f64, j3: f64, tension: f64, a: DVec3, taut: bool) -> Self {
        let mut r = Record([0.0; RECORD_LEN]);
        r.0[T] = t;
        r.put(X, s.x);
        r.put(V, s.v);
        r.0[ENERGY] = energy;
        r.0[J3] = j3;
        r.0[TENSION] = tension;
        r.put(A, a);
        r.0[TAUT] = if taut { 1.0 } else { 0.0 };
        r.0[ERROR_X] = UNKNOWN;
        r
    }

    /// The same record with the pivot's position \[m\] and the power \[W\] of the non-conservative forces
    /// (the lab's crane: the trolley and the hoist).
    pub fn with_pivot_power(mut self, pivot: DVec3, power: f64) -> Self {
        self.put(PIVOT, pivot);
        self.0[POWER] = power;
        self
    }

    /// Time \[s\].
    pub fn t(&self) -> f64 {
        self.0[T]
    }

    /// Position x \[m\].
    pub fn x(&self) -> DVec3 {
        DVec3::new(self.0[X], self.0[X + 1], self.0[X + 2])
    }

    /// Names of the values that are not finite (empty when all are).
    pub fn non_finite(&self) -> Vec<&'static str> {
        FRAME_FIELDS.iter().zip(self.0).filter(|(_, v)| !v.is_finite()).map(|(n, _)| *n).collect()
    }
}

/// The record of a rod model's state at time t \[s\]: the core's diagnostics at that time (forcing and a
/// moving pivot depend on it), as the Python server's `state_records` computes them.
pub fn rod_record(model: &AnyModel, t: f64, s: &State) -> Record {
    let mut r = Record([0.0; RECORD_LEN]);
    r.0[T] = t;
    r.put(X, s.x);
    r.put(V, s.v);
    r.0[ENERGY] = energy(model, s);
    r.0[J3] = j3(model, s);
    r.0[TENSION] = tension(model, t, s);
    r.0[POWER] = model.params().mass * model.power_per_mass(t, s.x, s.v);
    r.put(A, acceleration(model, t, s.x, s.v));
    if let Some(path) = model.pivot() {
        r.put(PIVOT, path.position(t));
    }
    r.0[TAUT] = 1.0;
    r.0[ERROR_X] = UNKNOWN;
    r
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The layout is frame.json's, which the Python server and the page read.
    #[test]
    fn fields_and_units_are_frame_json() {
        let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../../python/pendulab/server/frame.json");
        let text = std::fs::read_to_string(path).unwrap();
        let json: serde_json::Value = serde_json::from_str(&text).unwrap();
        let list = |k: &str| -> Vec<String> {
            json[k].as_array().unwrap().iter().map(|v| v.as_str().unwrap().to_string()).collect()
        };
        assert_eq!(list("fields"), FRAME_FIELDS);
        assert_eq!(list("units"), FRAME_UNITS);
        assert_eq!(FRAME_FIELDS[T], "t");
        assert_eq!(FRAME_FIELDS[X], "x1");
        assert_eq!(FRAME_FIELDS[V], "v1");
        assert_eq!(FRAME_FIELDS[ENERGY], "energy");
        assert_eq!(FRAME_FIELDS[J3], "j3");
        assert_eq!(FRAME_FIELDS[TENSION], "tension");
        assert_eq!(FRAME_FIELDS[POWER], "power");
        assert_eq!(FRAME_FIELDS[A], "a1");
        assert_eq!(FRAME_FIELDS[PIVOT], "pivot1");
        assert_eq!(FRAME_FIELDS[TAUT], "taut");
        assert_eq!(FRAME_FIELDS[ERROR_X], "error_x");
    }
}
