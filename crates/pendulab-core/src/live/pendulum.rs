//! What a live session runs: a pendulum of any lab model by registry name ([`LivePendulum`]) and its
//! incremental stepper ([`LiveStepper`]) — the rod models through [`Stepper`] over [`AnyModel`], the
//! swinging spring (T-7.4) through [`SpringStepper`], the string through [`StringStepper`] — with the
//! frame record of its current state ([`super::frame`]). SI units: l \[m\], m \[kg\], g [m/s²], t \[s\].

use super::crane::{LiveCrane, CRANE, CRANE_PARAMS};
use super::frame::{rod_record, Record};
use super::kinds::Kind;
pub use super::kinds::{live_models, OWN_STEPPER_MODELS};
use super::methods::{method_refused, Restricted};
pub use super::methods::{SPRING_ORDERS, STRING_METHODS};
use super::no_parameter::no_parameter;
use crate::elastic::{SpringStepper, SwingingSpring};
use crate::error::{Error, Result};
use crate::integrate::Method;
use crate::model::registry::{check_limits, spec, AnyModel};
use crate::model::string::StringPendulum;
use crate::model::{self as model_mod};
use crate::state::{Params, State};
use crate::stepper::{SolveOptions, Stepper};
use crate::string_run::{StringEvent, StringStepper};
use crate::DVec3;

/// The method a session switches to when its method cannot run the spring or the string.
pub const DEFAULT_METHOD: Method = Method::Rattle;

/// A pendulum of a lab model: the registry name, l, m, g ([`Params`]; for the spring l is the rest
/// length l₀) and every own parameter of the model (the given ones, else the registry's defaults).
#[derive(Debug, Clone, PartialEq)]
pub struct LivePendulum {
    /// Registry name.
    pub model: &'static str,
    /// Length \[m\], mass \[kg\], g [m/s²].
    pub params: Params,
    /// The model's own parameters in the registry's order (SI units).
    pub own: Vec<(&'static str, f64)>,
}

/// The refusal of `model`, a model of the registry that runs only in `pendulab run` ([`Kind::Offline`]).
fn not_lab_model(model: &str) -> Error {
    let available = live_models().join(", ");
    Error::RefusedKeyed {
        words: format!(
            "model {model:?} does not run in the lab (use pendulab run); the lab's models: {available}"
        ),
        key: "not_lab_model",
        values: vec![("model", model.to_string()), ("available", available)],
    }
}

/// The refusal of a pendulum whose model runs in no lab, or is no model ([`Kind::of`] None).
fn not_in_lab(model: &str) -> Error {
    spec(model).map_or_else(|e| e, |_| not_lab_model(model))
}

impl LivePendulum {
    /// Model `name` with l \[m\], m \[kg\], g [m/s²] and own parameters by name (defaults for the rest);
    /// errors name an unknown model, an unknown parameter or a value outside the registry's limits.
    pub fn new(name: &str, length: f64, mass: f64, g: f64, given: &[(String, f64)]) -> Result<Self> {
        if name == CRANE {
            return Self::crane(length, mass, g, given);
        }
        let ms = spec(name)?;
        if !live_models().contains(&ms.name) {
            return Err(not_lab_model(ms.name));
        }
        let params = Params::new(length, mass, g)?;
        let mut own: Vec<(&'static str, f64)> = ms.params.iter().map(|p| (p.name, p.default)).collect();
        for (key, value) in given {
            let Some(i) = ms.params.iter().position(|p| p.name == key) else {
                let own: Vec<&str> = ms.params.iter().map(|p| p.name).collect();
                return Err(no_parameter(ms.name, key, &own));
            };
            own[i].1 = check_limits(&ms.params[i], *value)?;
        }
        let p = Self { model: ms.name, params, own };
        p.check()?;
        Ok(p)
    }

    /// The lab crane's load (the crane mode, [`super::crane`]): rope l \[m\], m \[kg\], g [m/s²] and
    /// the crane's own parameters ([`CRANE_PARAMS`]).
    fn crane(length: f64, mass: f64, g: f64, given: &[(String, f64)]) -> Result<Self> {
        let mut own: Vec<(&'static str, f64)> = CRANE_PARAMS.iter().map(|p| (p.name, p.default)).collect();
        for (key, value) in given {
            let Some(i) = CRANE_PARAMS.iter().position(|p| p.name == key) else {
                let names: Vec<&str> = CRANE_PARAMS.iter().map(|p| p.name).collect();
                return Err(no_parameter(CRANE, key, &names));
            };
            own[i].1 = check_limits(&CRANE_PARAMS[i], *value)?;
        }
        let p = Self { model: CRANE, params: Params::new(length, mass, g)?, own };
        p.check()?;
        Ok(p)
    }

    /// The model's own check of l, m, g and its parameters, by how the lab runs it ([`Kind`]: every
    /// model of the registry and the crane, no catch-all).
    fn check(&self) -> Result<()> {
        match Kind::of(self.model) {
            Some(Kind::Crane) => super::crane::check(&self.params),
            Some(Kind::Spring) => self.spring().map(|_| ()),
            Some(Kind::String) => StringPendulum::new(self.params, self.get("restitution")).map(|_| ()),
            Some(Kind::Rod) => self.rod_model().map(|_| ()),
            Some(Kind::Offline) | None => Err(not_in_lab(self.model)),
        }
    }

    /// The own parameter `name` (0 when the model has none of that name).
    pub fn get(&self, name: &str) -> f64 {
        self.own.iter().find(|(n, _)| *n == name).map_or(0.0, |(_, v)| *v)
    }

    /// The same model with some of l, m, g and own parameters changed, or another model (`model`;
    /// its own parameters start from the registry's defaults, overridden by `given`).
    pub fn rebuild(
        &self,
        model: Option<&str>,
        length: Option<f64>,
        mass: Option<f64>,
        g: Option<f64>,
        given: &[(String, f64)],
    ) -> Result<Self> {
        let name = model.unwrap_or(self.model);
        let mut all: Vec<(String, f64)> = if name == self.model {
            self.own.iter().map(|(n, v)| (n.to_string(), *v)).collect()
        } else {
            Vec::new()
        };
        all.extend(given.iter().cloned());
        let p = &self.params;
        Self::new(name, length.unwrap_or(p.length), mass.unwrap_or(p.mass), g.unwrap_or(p.g), &all)
    }

    /// The rod model (every model but the spring and the string).
    pub fn rod_model(&self) -> Result<AnyModel> {
        AnyModel::build(self.model, self.params, &self.own)
    }

    fn spring(&self) -> Result<SwingingSpring> {
        let p = &self.params;
        SwingingSpring::new(self.get("stiffness") / p.mass, p.length, p.g, p.mass)
    }

    /// A state (x \[m\], v [m/s]) of this pendulum: on TS² (or moved there with `project`); the spring
    /// takes any finite state with x ≠ 0; the string also a slack one strictly inside the sphere.
    pub fn state(&self, x: DVec3, v: DVec3, project: bool) -> Result<State> {
        let finite = x.is_finite() && v.is_finite();
        if self.model == "spring" {
            if !finite || x == DVec3::ZERO {
                return Err(Error::InvalidParameter {
                    name: "(x, v)",
                    value: x.length(),
                    allowed: "the spring's state must be finite with x ≠ 0 (m, m/s)",
                });
            }
            return Ok(State { x, v });
        }
        if self.model == "string" && finite && x.length() < self.params.length * (1.0 - 1e-9) {
            return Ok(State { x, v });
        }
        if project {
            Ok(State::projected(&self.params, x, v)?.0)
        } else {
            State::on_tangent_bundle(&self.params, x, v)
        }
    }

    /// The state at polar angle θ \[rad\] from the downward vertical, azimuth φ, rates θ̇, φ̇ [rad/s]; the
    /// spring's on the sphere of its equilibrium length l₀ + m |g|/k.
    pub fn state_from_angles(&self, theta: f64, phi: f64, theta_dot: f64, phi_dot: f64) -> Result<State> {
        let mut params = self.params;
        if self.model == "spring" {
            let ell = self.spring()?.equilibrium_length();
            if ell.is_finite() && ell > 0.0 {
                params.length = ell;
            }
        }
        State::from_angles(&params, theta, phi, theta_dot, phi_dot)
    }

    /// The state for this pendulum after a change of model or parameters: kept for the spring and the
    /// slack string, else moved onto TS².
    pub fn carry(&self, s: &State) -> Result<State> {
        self.state(s.x, s.v, true)
    }
}

/// A stepper of a [`LivePendulum`], whichever kind its model needs.
#[derive(Debug, Clone)]
pub enum LiveStepper {
    /// A rod model through the incremental [`Stepper`] (every method).
    Rod(Box<Stepper<AnyModel>>),
    /// The swinging spring: whole steps of dt of Störmer–Verlet or its triple jump.
    Spring(SpringStepper),
    /// The string: the grid t₀ + k·dt, its taut/slack mode inside.
    String(Box<StringStepper>),
    /// The crane mode's load below the driven trolley ([`super::crane`]).
    Crane(Box<LiveCrane>),
}

impl LiveStepper {
    /// A stepper of `p` from `state` at `t0` \[s\] with `method`, step `dt` \[s\] (0 for `dop853`: automatic)
    /// and, for `dop853`, `rtol`, `atol`: the one of how the lab runs its model (`live::kinds`: every model
    /// of the registry and the crane, no catch-all).
    pub fn new(
        p: &LivePendulum,
        state: State,
        t0: f64,
        method: Method,
        dt: f64,
        rtol: f64,
        atol: f64,
    ) -> Result<Self> {
        let name = method.info().name;
        if let Some(which) = Restricted::of(p.model) {
            let allowed = which.methods();
            if !allowed.contains(&name) {
                return Err(method_refused(which, p.model, name, &allowed));
            }
        }
        Ok(match Kind::of(p.model) {
            Some(Kind::Crane) => {
                LiveStepper::Crane(Box::new(LiveCrane::new(p.params, &p.own, state, t0, rtol, atol)?))
            }
            Some(Kind::Spring) => {
                let order = SPRING_ORDERS.iter().find(|(m, _)| *m == name).map_or(2, |(_, o)| *o);
                LiveStepper::Spring(SpringStepper::new(p.spring()?, state, t0, dt, order)?)
            }
            Some(Kind::String) => {
                let model = StringPendulum::new(p.params, p.get("restitution"))?;
                LiveStepper::String(Box::new(StringStepper::new(model, t0, state, method, dt)?))
            }
            Some(Kind::Rod) => {
                let options = SolveOptions { method, dt, rtol, atol, project: true };
                LiveStepper::Rod(Box::new(Stepper::new(p.rod_model()?, t0, state, &options)?))
            }
            Some(Kind::Offline) | None => return Err(not_in_lab(p.model)),
        })
    }

    /// The Richardson companion of a fixed-step run of `p` from `state` at `t0` \[s\] with `method` and
    /// step `dt` \[s\] ([`super::error`]): a stepper whose every (sub-)step is half of one of the run's,
    /// and how many of its steps make one step of the run. The rod models: the run itself with every
    /// step, and every sub-step a break splits it into, taken as two halves
    /// ([`Stepper::set_halved_steps`]; a run at dt/2 splits on breaks elsewhere, and its errors are then
    /// not the run's / 2ᵖ); without breaks (no lab model has any) it is the run at dt/2, bit for bit
    /// where the model does not depend on t, else to the round-off of the step times. The spring (whole steps
    /// of dt) and the string (a step shortened only at its own leave and snap events, a few per swing):
    /// the run at dt/2, two steps per step.
    pub fn halved(p: &LivePendulum, state: State, t0: f64, method: Method, dt: f64) -> Result<(Self, u64)> {
        let SolveOptions { rtol, atol, .. } = SolveOptions::default(); // fixed step: not used
        Ok(match Self::new(p, state, t0, method, dt, rtol, atol)? {
            LiveStepper::Rod(mut s) => {
                s.set_halved_steps(true);
                (LiveStepper::Rod(s), 1)
            }
            LiveStepper::Spring(_) | LiveStepper::String(_) | LiveStepper::Crane(_) => {
                (Self::new(p, state, t0, method, 0.5 * dt, rtol, atol)?, 2)
            }
        })
    }

    /// Time reached \[s\].
    pub fn t(&self) -> f64 {
        match self {
            LiveStepper::Rod(s) => s.t(),
            LiveStepper::Spring(s) => s.t(),
            LiveStepper::String(s) => s.t(),
            LiveStepper::Crane(c) => c.t(),
        }
    }

    /// State reached (x \[m\], v [m/s]).
    pub fn state(&self) -> State {
        match self {
            LiveStepper::Rod(s) => s.state(),
            LiveStepper::Spring(s) => s.state(),
            LiveStepper::String(s) => s.state(),
            LiveStepper::Crane(c) => c.state(),
        }
    }

    /// `n` steps (`dop853`: n accepted steps).
    pub fn step(&mut self, n: u64) -> Result<()> {
        match self {
            LiveStepper::Rod(s) => s.step_n(n),
            LiveStepper::Spring(s) => s.step(n),
            LiveStepper::String(s) => s.step(n),
            LiveStepper::Crane(c) => c.step_to(c.t() + n as f64 * super::crane::STEP_SECONDS),
        }
    }

    /// Towards `t` \[s\] with at most `cap` steps; true once exactly there (`dop853` lands on `t`).
    pub fn step_to_capped(&mut self, t: f64, cap: u64) -> Result<bool> {
        match self {
            LiveStepper::Rod(s) => s.step_to_capped(t, cap),
            LiveStepper::Crane(c) => c.step_to(t).map(|()| true),
            _ => unreachable!("only the rod models run the adaptive method"),
        }
    }

    /// The string's events since the last call (empty for the other models).
    pub fn take_events(&mut self) -> Vec<StringEvent> {
        match self {
            LiveStepper::String(s) => s.take_events(),
            _ => Vec::new(),
        }
    }

    /// The frame record of the current state (`error_x` unknown).
    pub fn record(&self) -> Record {
        match self {
            LiveStepper::Rod(s) => rod_record(s.model(), s.t(), &s.state()),
            LiveStepper::Spring(s) => {
                let (sp, st) = (s.spring(), s.state());
                Record::own(
                    s.t(),
                    &st,
                    sp.energy(&st),
                    sp.j3(&st),
                    sp.tension(&st),
                    sp.acceleration(st.x),
                    true,
                )
            }
            LiveStepper::Crane(c) => c.record(),
            LiveStepper::String(s) => {
                let (m, st) = (s.model(), s.state());
                let (e, j) = (model_mod::energy(m, &st), model_mod::j3(m, &st));
                Record::own(s.t(), &st, e, j, s.tension(), s.acceleration(), s.is_taut())
            }
        }
    }
}
