//! The model registry: every model's name and label, parameters with labels, units, one-line help,
//! defaults and limits, and one builder from named values — what Python, scenario files, the CLI (`pendulab models`) and the web
//! lab's controls are generated from. All models share length l \[m\], mass m \[kg\] and gravity g
//! [m/s²]; the extra parameters switch on the terms of [`Extended`](super::Extended) (docs/theory.md §7).

pub use super::any_model::AnyModel;
use super::Model;
use crate::error::{Error, Result};
pub use crate::limits::{check_limits, common_for, limit, ParamSpec, COMMON, LIMITS, STATE};
use crate::state::State;

/// A registered model.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ModelSpec {
    /// Registry name.
    pub name: &'static str,
    /// The model's name in words (the lab's picker).
    pub label: &'static str,
    /// One line (with formula numbers: the picker's tooltip).
    pub summary: &'static str,
    /// Its parameters beyond length, mass and g.
    pub params: &'static [ParamSpec],
    /// Runs with the incremental [`crate::Stepper`] from its parameters alone (what a live viewer
    /// needs); false for the hybrid string, the off-sphere spring and the sampled pivot (arrays).
    pub interactive: bool,
}

const INF: f64 = f64::INFINITY;

const fn p(
    name: &'static str,
    label: &'static str,
    unit: &'static str,
    default: f64,
    min: f64,
    description: &'static str,
) -> ParamSpec {
    let allowed = if min == 0.0 { "a finite number >= 0" } else { "a finite number" };
    ParamSpec { name, label, unit, default, min, max: INF, description, allowed }
}

const GRAVITY_DIR: [ParamSpec; 3] = [
    p(
        "gravity_x",
        "gravity direction d: x",
        "1",
        0.0,
        -INF,
        "gravity direction d, x component (d normalised; −e₃ if no component is given, else 0 if omitted)",
    )
    .within(-1e6, 1e6, "a number in [-1e6, 1e6] (a direction component)"),
    p(
        "gravity_y",
        "gravity direction d: y",
        "1",
        0.0,
        -INF,
        "gravity direction d, y component (0 if omitted)",
    )
    .within(-1e6, 1e6, "a number in [-1e6, 1e6] (a direction component)"),
    p(
        "gravity_z",
        "gravity direction d: z",
        "1",
        -1.0,
        -INF,
        "gravity direction d, z component (−1 if no component is given, else 0 if omitted)",
    )
    .within(-1e6, 1e6, "a number in [-1e6, 1e6] (a direction component)"),
];

const DAMPED: &[ParamSpec] = &[
    p(
        "damping",
        "friction (linear damping) c",
        "1/s",
        0.0,
        0.0,
        "friction force −m c v, proportional to the velocity (T-7.1)",
    )
    .within(0.0, 1e4, "a number in [0, 1e4] 1/s"),
    p(
        "drag",
        "air drag c_q",
        "1/m",
        0.0,
        0.0,
        "air drag force −m c_q |v| v, growing with the square of the speed (T-7.1)",
    )
    .within(0.0, 1e4, "a number in [0, 1e4] 1/m"),
    p(
        "friction",
        "dry pivot friction",
        "rad/s^2",
        0.0,
        0.0,
        "dry (Coulomb) friction at the pivot: a torque m l² ε_f against the swing, whatever its speed (T-7.6)",
    )
    .within(0.0, 1e4, "a number in [0, 1e4] rad/s^2"),
    p(
        "friction_speed",
        "dry friction smoothing speed",
        "rad/s",
        super::extended::DEFAULT_FRICTION_SPEED,
        0.0,
        "below this angular speed the dry friction fades out smoothly, as tanh(|ω|/ω_ε) (T-7.6)",
    )
    .within(1e-9, 1e3, "a number in [1e-9, 1e3] rad/s"),
    p(
        "forcing_amplitude",
        "driving strength A",
        "m/s^2",
        0.0,
        0.0,
        "periodic driving force per unit mass A cos(ω t + ψ) along e (T-7.1)",
    )
    .within(0.0, 1e4, "a number in [0, 1e4] m/s^2"),
    p("forcing_omega", "driving frequency ω", "rad/s", 0.0, -INF, "angular frequency ω of the driving force")
        .within(-1e4, 1e4, "a number in [-1e4, 1e4] rad/s"),
    p("forcing_phase", "driving phase ψ", "rad", 0.0, -INF, "phase ψ of the driving force at t = 0").within(
        -1e3,
        1e3,
        "a number in [-1e3, 1e3] rad",
    ),
    p(
        "forcing_x",
        "driving direction e: x",
        "1",
        1.0,
        -INF,
        "forcing direction e, x component (e normalised; e₁ if no component is given, else 0 if omitted)",
    )
    .within(-1e6, 1e6, "a number in [-1e6, 1e6] (a direction component)"),
    p(
        "forcing_y",
        "driving direction e: y",
        "1",
        0.0,
        -INF,
        "forcing direction e, y component (0 if omitted)",
    )
    .within(-1e6, 1e6, "a number in [-1e6, 1e6] (a direction component)"),
    p(
        "forcing_z",
        "driving direction e: z",
        "1",
        0.0,
        -INF,
        "forcing direction e, z component (0 if omitted)",
    )
    .within(-1e6, 1e6, "a number in [-1e6, 1e6] (a direction component)"),
    GRAVITY_DIR[0],
    GRAVITY_DIR[1],
    GRAVITY_DIR[2],
];

const ROTATING: &[ParamSpec] = &[
    p(
        "frame_rate",
        "rotation rate of the frame |Ω|",
        "rad/s",
        7.292e-5,
        -INF,
        "how fast the reference frame turns (the Earth: 7.292e-5 rad/s; T-7.3)",
    )
    .within(-1e3, 1e3, "a number in [-1e3, 1e3] rad/s"),
    ParamSpec {
        name: "latitude",
        label: "latitude λ",
        unit: "rad",
        default: 0.8552113334772214,
        min: -std::f64::consts::FRAC_PI_2,
        max: std::f64::consts::FRAC_PI_2,
        description: "where on the Earth: Ω = |Ω|(0, cos λ, sin λ) in (east, north, up) axes",
        allowed: "a latitude in [-π/2, π/2] rad",
    },
    p(
        "damping",
        "friction (linear damping) c",
        "1/s",
        0.0,
        0.0,
        "friction force −m c v, proportional to the velocity (T-7.1)",
    )
    .within(0.0, 1e4, "a number in [0, 1e4] 1/s"),
];

const SLEWING: &[ParamSpec] = &[
    p(
        "radius",
        "boom radius R",
        "m",
        5.0,
        -INF,
        "distance of the pivot from the crane's slewing axis (the boom tip circle, T-7.2)",
    )
    .within(-1e4, 1e4, "a number in [-1e4, 1e4] m"),
    p(
        "rate",
        "slewing rate ω",
        "rad/s",
        0.1,
        -INF,
        "how fast the boom turns: pivot at (R cos ωt, R sin ωt, h)",
    )
    .within(-1e3, 1e3, "a number in [-1e3, 1e3] rad/s"),
    p(
        "height",
        "height of the boom tip above the origin",
        "m",
        0.0,
        -INF,
        "height of the boom tip above the origin",
    )
    .within(-1e4, 1e4, "a number in [-1e4, 1e4] m"),
    p("damping", "friction (linear damping) c", "1/s", 0.0, 0.0, "linear damping c relative to the pivot")
        .within(0.0, 1e4, "a number in [0, 1e4] 1/s"),
];

const VIBRATING: &[ParamSpec] = &[
    p(
        "amplitude",
        "shaking amplitude A",
        "m",
        0.05,
        -INF,
        "how far the pivot is shaken up and down: pivot at (0, 0, A cos νt) (T-7.2)",
    )
    .within(-1e3, 1e3, "a number in [-1e3, 1e3] m"),
    p(
        "frequency",
        "shaking frequency ν",
        "rad/s",
        200.0,
        -INF,
        "angular frequency ν of the shaking; the inverted pendulum stands when (Aν)² > 2 g l",
    )
    .within(-1e5, 1e5, "a number in [-1e5, 1e5] rad/s"),
    p("damping", "friction (linear damping) c", "1/s", 0.0, 0.0, "linear damping c relative to the pivot")
        .within(0.0, 1e4, "a number in [0, 1e4] 1/s"),
];

const HOISTED: &[ParamSpec] = &[
    p(
        "hoist_rate",
        "hoist rate r",
        "m/s",
        -0.02,
        -INF,
        "rope length l(t) = l + r t + a sin(ν t) (T-11.10); r < 0 hoists the load up, r > 0 lowers it",
    )
    .within(-1e3, 1e3, "a number in [-1e3, 1e3] m/s"),
    p("hoist_amplitude", "hoist amplitude a", "m", 0.0, -INF, "amplitude a of the periodic part of l(t)")
        .within(-1e4, 1e4, "a number in [-1e4, 1e4] m"),
    p("hoist_frequency", "hoist frequency ν", "rad/s", 0.0, -INF, "angular frequency ν of the periodic part of l(t)")
        .within(-1e5, 1e5, "a number in [-1e5, 1e5] rad/s"),
    p(
        "radius",
        "boom radius R",
        "m",
        0.0,
        -INF,
        "the pivot on a slewing boom tip (R cos ωt, R sin ωt, h), as the 'slewing' model; R = 0: a fixed pivot",
    )
    .within(-1e4, 1e4, "a number in [-1e4, 1e4] m"),
    p("rate", "slewing rate ω", "rad/s", 0.0, -INF, "how fast the boom turns")
        .within(-1e3, 1e3, "a number in [-1e3, 1e3] rad/s"),
    p("height", "height of the boom tip above the origin", "m", 0.0, -INF, "height of the pivot above the origin")
        .within(-1e4, 1e4, "a number in [-1e4, 1e4] m"),
    p("damping", "friction (linear damping) c", "1/s", 0.0, 0.0, "linear damping c relative to the pivot")
        .within(0.0, 1e4, "a number in [0, 1e4] 1/s"),
];

const SAMPLED: &[ParamSpec] = &[p(
    "damping",
    "friction (linear damping) c",
    "1/s",
    0.0,
    0.0,
    "linear damping c relative to the pivot (the path: pivot samples)",
)
.within(0.0, 1e4, "a number in [0, 1e4] 1/s")];

const SPRING: &[ParamSpec] = &[ParamSpec {
    name: "stiffness",
    label: "spring constant k",
    unit: "N/m",
    default: 29.43,
    min: 1e-6,
    max: 1e8,
    description: "swinging spring (T-7.4): spring constant k; length is the rest length l0, the bob \
                  rests at l = l0 + m|g|/k (below the pivot for g > 0, above it for g < 0); 1:1:2 \
                  resonance at k = 3 m|g|/l0 (default: for l0 = 1 m, m = 1 kg)",
    allowed: "a number in [1e-6, 1e8] N/m",
}];

const STRING: &[ParamSpec] = &[ParamSpec {
    name: "restitution",
    label: "bounciness (restitution) e",
    unit: "1",
    default: 0.0,
    min: 0.0,
    max: 1.0,
    description: "restitution e of the snap when the slack string goes taut: v_radial -> -e v_radial \
                  (0 inelastic, 1 elastic)",
    allowed: "a number in [0, 1]",
}];

/// Every registered model.
pub const MODELS: &[ModelSpec] = &[
    ModelSpec {
        name: "ideal",
        label: "Ideal pendulum",
        summary: "the ideal spherical pendulum (docs/theory.md §2)",
        interactive: true,
        params: &[],
    },
    ModelSpec {
        name: "damped",
        label: "Damped and driven",
        summary: "damping, quadratic drag, periodic forcing, any gravity direction (T-7.1)",
        interactive: true,
        params: DAMPED,
    },
    ModelSpec {
        name: "rotating",
        label: "On the turning Earth (Foucault)",
        summary: "in a rotating frame (Foucault, T-7.3), optionally damped",
        interactive: true,
        params: ROTATING,
    },
    ModelSpec {
        name: "slewing",
        label: "Slewing crane",
        summary: "pivot on a slewing crane's boom tip (T-7.2)",
        interactive: true,
        params: SLEWING,
    },
    ModelSpec {
        name: "vibrating",
        label: "Shaken pivot (Kapitza)",
        summary: "vertically vibrated pivot (Kapitza's inverted pendulum, T-7.2)",
        interactive: true,
        params: VIBRATING,
    },
    ModelSpec {
        name: "hoisted",
        label: "Hoisted rope (crane)",
        summary: "the rope length l(t) changes during the run: |x − P(t)| = l(t) below a fixed or slewing pivot (T-11.10)",
        interactive: false,
        params: HOISTED,
    },
    ModelSpec {
        name: "sampled_pivot",
        label: "Pivot on a given path",
        summary: "pivot on a path given as samples (times, positions; C² cubic spline), T-7.2",
        interactive: false,
        params: SAMPLED,
    },
    ModelSpec {
        name: "spring",
        label: "Swinging spring",
        summary:
            "swinging spring: an elastic rod, off the sphere (T-7.4); scenario files and pl.SwingingSpring",
        interactive: false,
        params: SPRING,
    },
    ModelSpec {
        name: "string",
        label: "Pendulum on a string",
        summary: "a string instead of a rod: slack (free flight) where the tension T-2.3 would be < 0",
        interactive: false,
        params: STRING,
    },
];

/// The spec of model `name`, or an error listing the models.
pub fn spec(name: &str) -> Result<&'static ModelSpec> {
    MODELS.iter().find(|m| m.name == name).ok_or_else(|| Error::UnknownModel {
        name: name.to_string(),
        available: MODELS.iter().map(|m| m.name).collect::<Vec<_>>().join(", "),
    })
}

/// E(t) − E(0) − m∫P dt along samples (t, state) by the trapezoidal rule \[J\]: the power-balance
/// residual of T-7.1 (zero to quadrature and integration error).
pub fn power_balance_residual<M: Model>(model: &M, t: &[f64], states: &[State]) -> Vec<f64> {
    let mass = model.params().mass;
    let e0 = super::energy(model, &states[0]);
    let mut work = 0.0;
    let mut out = vec![0.0];
    for k in 1..states.len() {
        let p0 = model.power_per_mass(t[k - 1], states[k - 1].x, states[k - 1].v);
        let p1 = model.power_per_mass(t[k], states[k].x, states[k].v);
        work += 0.5 * (t[k] - t[k - 1]) * (p0 + p1) * mass;
        out.push(super::energy(model, &states[k]) - e0 - work);
    }
    out
}
