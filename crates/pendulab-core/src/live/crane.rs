//! The lab's crane mode (docs/cranes.md "The lab's crane mode", docs/web.md "Crane mode"): a load on
//! a hoisted rope below a trolley the operator drives, stepped live by the core's crane integrator
//! ([`mod@crate::crane::run`]: adaptive DOP853 with projection onto the rheonomic constraint
//! |x − P(t)| = l(t), T-11.5 – T-11.7, wind drag on the load relative to the air). The trolley P(t)
//! and the rope length l(t) follow acceleration-limited plans ([`super::crane_plan`], T-11.3); the
//! trolley's command is shaped by ZV or ZVD (T-11.2) designed for ω = √(g/l) at the rope length when
//! each change of the command happens. Each tick the plans on [t, t + Δt] become the quintic Hermite
//! motions of the crane system (exact for piecewise-quadratic motions, T-11.4).
//!
//! The load is one point mass (hook and payload together); its parameters are the lab pendulum's
//! l (the rope length the hoist goes to) \[m\], m \[kg\], g [m/s²] (> 0) and [`CRANE_PARAMS`]. The frame
//! record: x, v relative to the trolley, E = ½m|v|² + m g z in the ground frame \[J\], J₃ about the rope's
//! top, the rope tension \[N\] (with the hoist's m l̈), the power of hoist, trolley and wind \[W\], the
//! acceleration relative to the trolley, the trolley's position. SI units throughout.

use super::crane_plan::{plan_position, plan_velocity, residual_sway, shaped, Kinematics, Shaping};
use super::frame::Record;
use crate::crane::dynamics::{v3, Y};
use crate::crane::{run, Body, CraneSystem, Hermite5, Knot, Tolerances, Wind};
use crate::error::{Error, Result};
use crate::limits::ParamSpec;
use crate::state::{Params, State};
use crate::DVec3;
use serde_json::{json, Value};

/// The crane mode's model name.
pub const CRANE: &str = "crane";
/// Shortest and longest rope \[m\] of the lab's crane.
pub const ROPE_RANGE: (f64, f64) = (0.5, 200.0);
/// Air density ρ [kg/m³] of the wind drag.
pub const AIR_DENSITY: f64 = 1.225;
/// Most DOP853 steps of one advance (bounds a tick's work).
pub const MAX_STEPS: u64 = 200_000;
/// Simulated seconds one `step` of the crane advances \[s\].
pub const STEP_SECONDS: f64 = 0.01;

const fn p(
    name: &'static str,
    label: &'static str,
    unit: &'static str,
    default: f64,
    range: (f64, f64),
) -> ParamSpec {
    ParamSpec {
        name,
        label,
        unit,
        default,
        min: range.0,
        max: range.1,
        description: label,
        allowed: "see docs/cranes.md, \"The lab's crane mode\"",
    }
}

/// The crane's own parameters (SI): shaping (0 off, 1 ZV, 2 ZVD), trolley speed and acceleration
/// limits, hoist speed and acceleration limits, the wind's horizontal velocity, the load's c_W·A.
pub const CRANE_PARAMS: [ParamSpec; 8] = [
    p("shaping", "command shaping: 0 off, 1 ZV, 2 ZVD", "", 2.0, (0.0, 2.0)),
    p("v_max", "trolley's top speed", "m/s", 0.5, (0.01, 5.0)),
    p("a_max", "trolley's acceleration", "m/s²", 0.3, (0.01, 5.0)),
    p("hoist_speed", "hoist's top speed", "m/s", 0.5, (0.01, 5.0)),
    p("hoist_accel", "hoist's acceleration", "m/s²", 0.5, (0.01, 5.0)),
    p("wind_x", "wind along x (the trolley's travel)", "m/s", 0.0, (-50.0, 50.0)),
    p("wind_y", "wind along y (across)", "m/s", 0.0, (-50.0, 50.0)),
    p("drag_area", "load's drag coefficient × area c_W·A", "m²", 1.0, (0.0, 100.0)),
];

/// Checks the crane's l \[m\] and g [m/s²] (its own parameters are checked against [`CRANE_PARAMS`]).
pub fn check(p: &Params) -> Result<()> {
    let l = p.length;
    if !(ROPE_RANGE.0..=ROPE_RANGE.1).contains(&l) {
        return Err(Error::InvalidParameter {
            name: "length",
            value: l,
            allowed: "a crane rope of 0.5 to 200 m",
        });
    }
    if p.g.is_nan() || p.g <= 0.0 {
        return Err(Error::InvalidParameter {
            name: "g",
            value: p.g,
            allowed: "g > 0 m/s² for the crane (the load hangs below the trolley)",
        });
    }
    Ok(())
}

/// A command of the crane mode (the wire's `crane` message), already checked.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct CraneCommand {
    /// Switch the session to the crane mode (from the current l, m, g and state).
    pub on: bool,
    /// Drive the trolley at this velocity (x, y) [m/s] (|each| ≤ v_max).
    pub drive: Option<[f64; 2]>,
    /// Move the trolley by (x, y) \[m\] and stop.
    pub move_by: Option<[f64; 2]>,
    /// Hoist to this rope length \[m\].
    pub rope: Option<f64>,
}

/// The last `move`: its start \[s\], distance \[m\], the design ω [rad/s] and the linear residual sway \[rad\]
/// of its command unshaped and shaped (module doc of [`super::crane_plan`]).
#[derive(Debug, Clone, PartialEq)]
pub struct MoveReport {
    t: f64,
    distance: [f64; 2],
    omega: f64,
    shaping: Shaping,
    unshaped: f64,
    shaped: f64,
    rope: f64,
    end: f64,
}

/// The live crane (module doc).
#[derive(Debug, Clone)]
pub struct LiveCrane {
    t: f64,
    y: Y,
    tension: f64,
    /// The operator's command (unshaped).
    pub reference: Kinematics,
    /// The trolley (the shaped command).
    pub trolley: Kinematics,
    /// The rope length (first component).
    pub hoist: Kinematics,
    settings: Settings,
    tol: Tolerances,
    last_move: Option<MoveReport>,
}

/// The crane's l \[m\] (where the hoist goes), m \[kg\], g [m/s²] and own parameters ([`CRANE_PARAMS`]).
#[derive(Debug, Clone)]
struct Settings {
    params: Params,
    own: Vec<(&'static str, f64)>,
}

impl Settings {
    fn get(&self, name: &str) -> f64 {
        self.own.iter().find(|(n, _)| *n == name).map_or(0.0, |(_, v)| *v)
    }
}

fn knots(samples: Vec<(f64, DVec3, DVec3, DVec3, DVec3)>) -> Vec<Knot> {
    let mut out = Vec::new();
    for (i, (t, q, dq, left, right)) in samples.into_iter().enumerate() {
        if i > 0 && left != right {
            out.push(Knot { t, q, dq, ddq: left });
        }
        out.push(Knot { t, q, dq, ddq: right });
    }
    out
}

impl LiveCrane {
    /// The crane of `params` and its own parameters `own` from `state` (x relative to the trolley \[m\], v [m/s]) at `t0` \[s\]: the trolley
    /// at rest at the origin, the rope as long as |x| (the hoist then goes to l), DOP853 at rtol, atol.
    pub fn new(
        params: Params,
        own: &[(&'static str, f64)],
        state: State,
        t0: f64,
        rtol: f64,
        atol: f64,
    ) -> Result<Self> {
        check(&params)?;
        let rope = state.x.length();
        if !(rope >= ROPE_RANGE.0 * 0.5 && rope.is_finite()) {
            return Err(Error::InvalidParameter {
                name: "rope",
                value: rope,
                allowed: "a rope of at least 0.25 m",
            });
        }
        let mut y = [0.0; crate::crane::dynamics::DIM];
        y[0..3].copy_from_slice(&state.x.to_array());
        y[3..6].copy_from_slice(&state.v.to_array());
        let mut c = LiveCrane {
            t: t0,
            y,
            tension: 0.0,
            reference: Kinematics::at_rest(t0, DVec3::ZERO),
            trolley: Kinematics::at_rest(t0, DVec3::ZERO),
            hoist: Kinematics::at_rest(t0, DVec3::new(rope, 0.0, 0.0)),
            settings: Settings { params, own: own.to_vec() },
            tol: Tolerances { rtol: rtol.max(1e-14), atol, max_steps: MAX_STEPS },
            last_move: None,
        };
        c.hoist_to(params.length);
        c.tension = c.system(t0 + 1.0)?.eval(t0, t0, &c.y).tension.0;
        Ok(c)
    }

    /// Time reached \[s\].
    pub fn t(&self) -> f64 {
        self.t
    }

    /// The load's state relative to the trolley (x \[m\], v [m/s]).
    pub fn state(&self) -> State {
        State { x: v3(&self.y, 0) - self.trolley.q, v: v3(&self.y, 3) - self.trolley.dq }
    }

    fn omega(&self) -> f64 {
        (self.settings.params.g / self.hoist.q.x).sqrt()
    }

    fn shaping(&self) -> Shaping {
        Shaping::from_code(self.settings.get("shaping"))
    }

    fn system(&self, t1: f64) -> Result<CraneSystem> {
        let s = &self.settings;
        Ok(CraneSystem {
            pivot: Hermite5::new("trolley", knots(self.trolley.samples(t1)))?,
            hoist: Hermite5::new("hoist", knots(self.hoist.samples(t1)))?,
            body1: Body { mass: s.params.mass, drag_area: s.get("drag_area") },
            body2: None,
            g: s.params.g,
            damping: 0.0,
            wind: Wind {
                steady: DVec3::new(s.get("wind_x"), s.get("wind_y"), 0.0),
                air_density: AIR_DENSITY,
                ..Wind::CALM
            },
        })
    }

    /// The reference's changes up to `t1` \[s\] handed to the trolley through the shaper.
    fn emit(&mut self, t1: f64) {
        let impulses = self.shaping().impulses(self.omega());
        while let Some(&(tau, da)) = self.reference.steps.first().filter(|s| s.0 <= t1) {
            for &(ti, ai) in &impulses {
                self.trolley.add_step(tau + ti, da * ai);
            }
            self.reference.advance_to(tau);
        }
        self.reference.advance_to(t1);
    }

    /// Advances to `t1` \[s\]; the crane's errors (a slack rope, too many steps) leave it unchanged.
    pub fn step_to(&mut self, t1: f64) -> Result<()> {
        if t1.is_nan() || t1 <= self.t {
            return Ok(());
        }
        let mut next = self.clone();
        next.emit(t1);
        let out = run(&next.system(t1)?, self.t, self.y, &[t1], self.tol)?;
        next.trolley.advance_to(t1);
        next.hoist.advance_to(t1);
        (next.t, next.y, next.tension) = (t1, out.y[0], out.tension[0].0);
        *self = next;
        Ok(())
    }

    /// New parameters of the same crane (mass, g, own parameters) at once; a new l hoists to it.
    pub fn update(&mut self, params: Params, own: &[(&'static str, f64)]) -> Result<()> {
        check(&params)?;
        let length = params.length;
        self.settings = Settings { params, own: own.to_vec() };
        self.hoist_to(length);
        Ok(())
    }

    fn hoist_to(&mut self, rope: f64) {
        let s = &self.settings;
        let (h, t) = (&self.hoist, self.t);
        let plan = plan_position(t, h.q.x, h.dq.x, rope, s.get("hoist_speed"), s.get("hoist_accel"));
        self.hoist.replan([plan, Vec::new(), Vec::new()]);
        self.settings.params.length = rope;
    }

    /// Carries out a crane command's motions (drive, move, rope); errors name the bad value.
    pub fn apply(&mut self, c: &CraneCommand) -> Result<()> {
        let (v_max, a_max) = (self.settings.get("v_max"), self.settings.get("a_max"));
        if let Some(rope) = c.rope {
            if !(ROPE_RANGE.0..=ROPE_RANGE.1).contains(&rope) {
                return Err(Error::InvalidParameter {
                    name: "rope",
                    value: rope,
                    allowed: "a rope of 0.5 to 200 m",
                });
            }
            self.hoist_to(rope);
        }
        let (q, dq, t) = (self.reference.q, self.reference.dq, self.t);
        if let Some(v) = c.drive {
            if let Some(bad) = v.iter().find(|x| x.abs() > v_max) {
                return Err(Error::InvalidParameter {
                    name: "drive",
                    value: *bad,
                    allowed: "a trolley velocity within ± v_max m/s on each axis",
                });
            }
            let plan = |i: usize| plan_velocity(t, dq[i], v[i], a_max);
            let plans = [plan(0), plan(1), Vec::new()];
            self.reference.replan(plans);
            self.last_move = None;
        }
        if let Some(d) = c.move_by {
            if let Some(bad) = d.iter().find(|x| x.abs() > 1e3) {
                return Err(Error::InvalidParameter {
                    name: "move",
                    value: *bad,
                    allowed: "a move of at most 1000 m per axis",
                });
            }
            let plan = |i: usize| {
                if d[i] == 0.0 {
                    plan_velocity(t, dq[i], 0.0, a_max)
                } else {
                    plan_position(t, q[i], dq[i], q[i] + d[i], v_max, a_max)
                }
            };
            let plans = [plan(0), plan(1), Vec::new()];
            self.reference.replan(plans);
            self.report_move(d);
        }
        Ok(())
    }

    fn report_move(&mut self, distance: [f64; 2]) {
        let (omega, g, shaping) = (self.omega(), self.settings.params.g, self.shaping());
        let impulses = shaping.impulses(omega);
        let steps = &self.reference.steps;
        let end = steps.last().map_or(self.t, |s| s.0) + impulses.last().map_or(0.0, |i| i.0);
        self.last_move = Some(MoveReport {
            t: self.t,
            distance,
            omega,
            shaping,
            unshaped: residual_sway(steps, omega, g),
            shaped: residual_sway(&shaped(steps, &impulses), omega, g),
            rope: self.hoist.q.x,
            end,
        });
    }

    /// The frame record of the current state (module doc; `error_x` unknown).
    pub fn record(&self) -> Record {
        let m = self.settings.params.mass;
        let st = self.state();
        let (energy, power, acc) = match self.system(self.t + 1.0) {
            Ok(sys) => {
                let e = sys.eval(self.t, self.t, &self.y);
                (sys.energy(&self.y), e.dy[12..16].iter().sum(), v3(&e.dy, 3) - self.trolley.ddq)
            }
            Err(_) => (f64::NAN, f64::NAN, DVec3::NAN),
        };
        let j3 = m * st.x.cross(st.v).z;
        Record::own(self.t, &st, energy, j3, self.tension, acc, true).with_pivot_power(self.trolley.q, power)
    }

    /// The `crane` object of the status notice: rope, trolley, shaper, wind, limits, the last move.
    pub fn status(&self) -> Value {
        let s = &self.settings;
        let omega = self.omega();
        let imp = self.shaping().impulses(omega);
        let last = self.last_move.as_ref().map(|m| {
            json!({
                "t": m.t, "distance": m.distance, "omega": m.omega, "shaping": m.shaping.name(),
                "residual_unshaped": m.unshaped, "residual_shaped": m.shaped, "rope": m.rope, "end": m.end,
            })
        });
        json!({
            "rope": self.hoist.q.x,
            "rope_rate": self.hoist.dq.x,
            "rope_target": s.params.length,
            "trolley": self.trolley.q.to_array(),
            "trolley_velocity": self.trolley.dq.to_array(),
            "command_velocity": self.reference.dq.to_array(),
            "moving": !(self.trolley.resting() && self.reference.resting()),
            "hoisting": !self.hoist.resting(),
            "shaping": self.shaping().name(),
            "shaper": { "times": imp.iter().map(|i| i.0).collect::<Vec<_>>(),
                        "amplitudes": imp.iter().map(|i| i.1).collect::<Vec<_>>(), "omega": omega },
            "wind": [s.get("wind_x"), s.get("wind_y"), 0.0],
            "drag_area": s.get("drag_area"),
            "air_density": AIR_DENSITY,
            "v_max": s.get("v_max"), "a_max": s.get("a_max"),
            "hoist_speed": s.get("hoist_speed"), "hoist_accel": s.get("hoist_accel"),
            "last_move": last,
        })
    }
}
