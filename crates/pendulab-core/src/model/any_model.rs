//! [`AnyModel`]: a model built by name from the registry's named values ([`super::registry`]), and
//! its [`Model`] implementation, which hands every call to the variant (the ideal pendulum stays
//! [`IdealPendulum`], its fast path). Loops over steps dispatch once ([`Model::visit`]), not once per
//! step. Parameters in SI units as the registry lists them.

use super::hoist::Hoisted;
use super::pivot::{MovingPivot, PivotPath};
use super::registry::spec;
use super::spline::PivotSamples;
use super::{Extended, IdealPendulum, Model, ModelVisitor, StringPendulum};
use crate::error::{Error, Result};
use crate::state::{Params, State};
use glam::DVec3;

impl AnyModel {
    /// The pivot path of a moving-pivot model (None for a fixed pivot).
    pub fn pivot(&self) -> Option<&PivotPath> {
        match self {
            AnyModel::Pivot(m) => Some(m.path()),
            AnyModel::Hoisted(m) => Some(m.inner().path()),
            _ => None,
        }
    }
}

/// A model built from the registry: the ideal pendulum stays [`IdealPendulum`] (its fast path).
#[derive(Debug, Clone, PartialEq)]
pub enum AnyModel {
    /// The ideal pendulum.
    Ideal(IdealPendulum),
    /// Any of the extended models.
    Extended(Extended, &'static str),
    /// A moving pivot.
    Pivot(MovingPivot),
    /// A hoisted rope below a pivot (l(t), [`super::hoist`]).
    Hoisted(Hoisted),
    /// A string instead of a rod (hybrid: simulated by [`StringPendulum::simulate`]).
    String(StringPendulum),
}

impl AnyModel {
    /// The `sampled_pivot` model: the pivot on the spline through `times` \[s\] and `positions` \[m\]
    /// ([`PivotSamples`]), with linear damping c ≥ 0 [1/s] relative to the pivot.
    pub fn sampled_pivot(params: Params, times: &[f64], positions: &[DVec3], damping: f64) -> Result<Self> {
        let samples = PivotSamples::new(times, positions)?;
        let path = PivotPath::Samples(std::sync::Arc::new(samples));
        Ok(AnyModel::Pivot(MovingPivot::new(params, path, damping)?))
    }

    /// Builds model `name` from l, m, g and named extra parameters (unknown names and values outside
    /// the limits are errors naming them; missing ones take their defaults).
    pub fn build(name: &str, params: Params, extra: &[(&str, f64)]) -> Result<Self> {
        let spec = spec(name)?;
        let mut values: Vec<f64> = spec.params.iter().map(|p| p.default).collect();
        let mut given = vec![false; values.len()];
        for &(key, value) in extra {
            let Some(i) = spec.params.iter().position(|p| p.name == key) else {
                return Err(Error::UnknownParameter {
                    model: spec.name,
                    name: key.to_string(),
                    available: spec.params.iter().map(|p| p.name).collect::<Vec<_>>().join(", "),
                });
            };
            let ps = spec.params[i];
            if !(value >= ps.min && value <= ps.max) || value.is_nan() || value.is_infinite() {
                return Err(Error::InvalidParameter { name: ps.name, value, allowed: ps.allowed });
            }
            values[i] = value;
            given[i] = true;
        }
        let index = |k: &str| spec.params.iter().position(|p| p.name == k).unwrap();
        let get = |k: &str| spec.params.iter().position(|p| p.name == k).map(|i| values[i]);
        // A direction given by components: the default vector when no component is given; otherwise
        // exactly the given components, the omitted ones 0 (so forcing_y = 1 alone means e₂, not a
        // diagonal normalised together with the default e₁).
        let vec = |a: &str, b: &str, c: &str| {
            let (i, j, k) = (index(a), index(b), index(c));
            let pick = |n: usize| {
                if given[i] || given[j] || given[k] {
                    if given[n] {
                        values[n]
                    } else {
                        0.0
                    }
                } else {
                    values[n]
                }
            };
            DVec3::new(pick(i), pick(j), pick(k))
        };
        Ok(match spec.name {
            "ideal" => AnyModel::Ideal(IdealPendulum::from_params(params)),
            "damped" => AnyModel::Extended(
                Extended::ideal(params)
                    .with_gravity_direction(vec("gravity_x", "gravity_y", "gravity_z"))?
                    .with_damping(get("damping").unwrap(), get("drag").unwrap())?
                    .with_friction(get("friction").unwrap(), get("friction_speed").unwrap())?
                    .with_forcing(
                        get("forcing_amplitude").unwrap(),
                        get("forcing_omega").unwrap(),
                        get("forcing_phase").unwrap(),
                        vec("forcing_x", "forcing_y", "forcing_z"),
                    )?,
                "damped",
            ),
            "rotating" => AnyModel::Extended(
                Extended::ideal(params)
                    .with_damping(get("damping").unwrap(), 0.0)?
                    .with_latitude_frame(get("frame_rate").unwrap(), get("latitude").unwrap())?,
                "rotating",
            ),
            "slewing" => AnyModel::Pivot(MovingPivot::new(
                params,
                PivotPath::Slewing {
                    radius: get("radius").unwrap(),
                    rate: get("rate").unwrap(),
                    height: get("height").unwrap(),
                },
                get("damping").unwrap(),
            )?),
            "sampled_pivot" => {
                return Err(Error::InvalidPivotSamples {
                    reason: "the 'sampled_pivot' model needs the path: pivot times [s] and positions [m] \
                             (AnyModel::sampled_pivot; Python: Pendulum(pivot_samples=(times, positions)))"
                        .into(),
                })
            }
            "spring" => {
                let k = get("stiffness").unwrap();
                crate::elastic::SwingingSpring::new(k / params.mass, params.length, params.g, params.mass)?;
                return Err(Error::OffSphereModel { model: "spring" });
            }
            "hoisted" => AnyModel::Hoisted(Hoisted::slewing(
                params,
                ["radius", "rate", "height", "damping"].map(|k| get(k).unwrap()),
                ["hoist_rate", "hoist_amplitude", "hoist_frequency"].map(|k| get(k).unwrap()),
            )?),
            "string" => AnyModel::String(StringPendulum::new(params, get("restitution").unwrap())?),
            _ => AnyModel::Pivot(MovingPivot::new(
                params,
                PivotPath::Vertical {
                    amplitude: get("amplitude").unwrap(),
                    frequency: get("frequency").unwrap(),
                },
                get("damping").unwrap(),
            )?),
        })
    }
}

macro_rules! both {
    ($self:expr, $m:ident => $e:expr) => {
        match $self {
            AnyModel::Ideal($m) => $e,
            AnyModel::Extended($m, _) => $e,
            AnyModel::Pivot($m) => $e,
            AnyModel::Hoisted($m) => $e,
            AnyModel::String($m) => $e,
        }
    };
}

impl Model for AnyModel {
    fn name(&self) -> &'static str {
        match self {
            AnyModel::Ideal(_) => "ideal",
            AnyModel::Extended(_, name) => name,
            AnyModel::Pivot(m) => m.name(),
            AnyModel::Hoisted(m) => m.name(),
            AnyModel::String(m) => m.name(),
        }
    }
    fn params(&self) -> &Params {
        both!(self, m => m.params())
    }
    #[inline(always)]
    fn applied_acceleration(&self, t: f64, x: DVec3, v: DVec3) -> DVec3 {
        both!(self, m => m.applied_acceleration(t, x, v))
    }
    fn potential_per_mass(&self, x: DVec3) -> f64 {
        both!(self, m => m.potential_per_mass(x))
    }
    fn potential_change_per_mass(&self, from: DVec3, to: DVec3) -> f64 {
        both!(self, m => m.potential_change_per_mass(from, to))
    }
    fn is_conservative(&self) -> bool {
        both!(self, m => m.is_conservative())
    }
    fn is_axisymmetric(&self) -> bool {
        both!(self, m => m.is_axisymmetric())
    }
    fn is_ideal(&self) -> bool {
        matches!(self, AnyModel::Ideal(_))
    }
    fn is_hybrid(&self) -> bool {
        both!(self, m => m.is_hybrid())
    }
    #[inline(always)]
    fn kick_acceleration(&self, t: f64, x: DVec3) -> DVec3 {
        both!(self, m => m.kick_acceleration(t, x))
    }
    #[inline(always)]
    fn visit<V: ModelVisitor>(&self, visitor: V) -> V::Output {
        both!(self, m => m.visit(visitor))
    }
    fn kick_is_uniform(&self) -> bool {
        both!(self, m => m.kick_is_uniform())
    }
    fn has_velocity_forces(&self) -> bool {
        both!(self, m => m.has_velocity_forces())
    }
    #[inline(always)]
    fn velocity_flow(&self, x: DVec3, v: DVec3, h: f64) -> DVec3 {
        both!(self, m => m.velocity_flow(x, v, h))
    }
    fn power_per_mass(&self, t: f64, x: DVec3, v: DVec3) -> f64 {
        both!(self, m => m.power_per_mass(t, x, v))
    }
    #[inline(always)]
    fn velocity_flow_at(&self, t: f64, x: DVec3, v: DVec3, h: f64) -> DVec3 {
        both!(self, m => m.velocity_flow_at(t, x, v, h))
    }
    fn rope_length(&self, t: f64) -> f64 {
        both!(self, m => m.rope_length(t))
    }
    fn rope_rate(&self, t: f64) -> f64 {
        both!(self, m => m.rope_rate(t))
    }
    fn physical_acceleration(&self, t: f64, s: &State) -> Option<DVec3> {
        both!(self, m => m.physical_acceleration(t, s))
    }
    #[inline(always)]
    fn to_physical(&self, t: f64, s: State) -> State {
        both!(self, m => m.to_physical(t, s))
    }
    #[inline(always)]
    fn integrator_state(&self, t: f64, s: State) -> State {
        both!(self, m => m.integrator_state(t, s))
    }
    fn physical_tension(&self, t: f64, s: &State) -> Option<f64> {
        both!(self, m => m.physical_tension(t, s))
    }
    fn angle_form(&self, t: f64) -> Option<(f64, f64)> {
        both!(self, m => m.angle_form(t))
    }
    fn check_run(&self, t0: f64, t1: f64) -> Result<()> {
        both!(self, m => m.check_run(t0, t1))
    }
    fn next_break(&self, t: f64) -> f64 {
        both!(self, m => m.next_break(t))
    }
}
