//! The model registry: every model's name and label, parameters with labels, units, one-line help,
//! defaults and limits, and one builder from named values — what Python, scenario files, the CLI (`pendulab models`) and the web
//! lab's controls are generated from. All models share length l [m], mass m [kg] and gravity g
//! [m/s²]; the extra parameters switch on the terms of [`Extended`] (docs/theory.md §7).

pub use super::any_model::AnyModel;
use super::Model;
use crate::error::{Error, Result};
use crate::state::State;

/// One parameter of a model.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ParamSpec {
    /// Key in Python, TOML and JSON.
    pub name: &'static str,
    /// The words a student reads (the lab's controls, `pendulab models`): no formula numbers.
    pub label: &'static str,
    /// SI unit.
    pub unit: &'static str,
    /// Default value.
    pub default: f64,
    /// Smallest allowed value (−∞ for none).
    pub min: f64,
    /// Largest allowed value (+∞ for none).
    pub max: f64,
    /// What it is, in one line (the lab's tooltip; formula numbers of docs/theory.md go here).
    pub description: &'static str,
    /// The allowed values, in words.
    pub allowed: &'static str,
}

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

impl ParamSpec {
    /// The same parameter with the allowed values `min ..= max` (in words: `allowed`). Every bound is
    /// finite and has a physical reason, given in docs/models.md ("Limits"); a test checks that table
    /// against this registry.
    const fn within(self, min: f64, max: f64, allowed: &'static str) -> ParamSpec {
        ParamSpec { min, max, allowed, ..self }
    }
}

/// Checks `value` against `spec`'s limits: [`Error::InvalidParameter`] naming it and the allowed
/// values when it is not finite or outside `min ..= max`.
pub fn check_limits(spec: &ParamSpec, value: f64) -> Result<f64> {
    if value.is_finite() && value >= spec.min && value <= spec.max {
        Ok(value)
    } else {
        Err(Error::InvalidParameter { name: spec.name, value, allowed: spec.allowed })
    }
}

/// Bounds of a state (any model), in the same form as the parameters: the bob's speed |v| [m/s] and,
/// for the swinging spring whose bob leaves the sphere, its distance |x| from the pivot [m].
pub const STATE: &[ParamSpec] = &[
    ParamSpec {
        name: "speed",
        label: "speed |v|",
        unit: "m/s",
        default: 0.0,
        min: 0.0,
        max: 1e7,
        description: "speed of the bob relative to the pivot",
        allowed: "a speed |v| <= 1e7 m/s",
    },
    ParamSpec {
        name: "distance",
        label: "distance |x|",
        unit: "m",
        default: 1.0,
        min: 0.0,
        max: 1e5,
        description: "distance of the bob from the pivot (the spring; on the sphere it is l)",
        allowed: "a distance |x| in (0, 1e5] m",
    },
];

/// The shared parameters.
pub const COMMON: &[ParamSpec] = &[
    ParamSpec {
        name: "length",
        label: "length l",
        unit: "m",
        default: 1.0,
        min: 1e-6,
        max: 1e4,
        description: "length of the rod from the pivot to the bob (the spring's rest length l₀)",
        allowed: "a number in [1e-6, 1e4] m",
    },
    ParamSpec {
        name: "mass",
        label: "bob mass m",
        unit: "kg",
        default: 1.0,
        min: 1e-6,
        max: 1e6,
        description: "mass of the bob (the rod is massless)",
        allowed: "a number in [1e-6, 1e6] kg",
    },
    ParamSpec {
        name: "g",
        label: "gravity g",
        unit: "m/s^2",
        default: 9.81,
        min: -1e4,
        max: 1e4,
        description: "strength of gravity along its direction (Earth 9.81; any sign, 0 allowed)",
        allowed: "a number in [-1e4, 1e4] m/s^2 (any sign, 0 allowed)",
    },
];

/// The bounds of everything else a run is made of — states, times, steps, samples, bytes, files —
/// shared by the Python API, scenario and sweep files, the CLI and the lab (`pl.limits()`, `pendulab.validate`,
/// docs "Limits"). The `description` says why each bound is where it is.
pub const LIMITS: &[ParamSpec] = &[
    ParamSpec {
        name: "position",
        label: "position component",
        unit: "m",
        default: 1.0,
        min: -1e9,
        max: 1e9,
        description: "a component of a position x: 10³ × the longest rod, room for a start to project \
                      from while |x|² stays finite",
        allowed: "a finite number in [-1e9, 1e9] m",
    },
    ParamSpec {
        name: "velocity",
        label: "velocity component",
        unit: "m/s",
        default: 0.0,
        min: -1e7,
        max: 1e7,
        description: "a component of a velocity v (and the speed from angle rates): below the speed of \
                      light, so that m|v|² and the tension m|v|²/l stay finite for every allowed l, m",
        allowed: "a finite number in [-1e7, 1e7] m/s",
    },
    ParamSpec {
        name: "angle",
        label: "angle θ or φ",
        unit: "rad",
        default: 0.0,
        min: -1e6,
        max: 1e6,
        description: "an angle θ or φ of a start: sin and cos keep about 10 digits up to 10⁶ rad",
        allowed: "a finite number in [-1e6, 1e6] rad",
    },
    ParamSpec {
        name: "angle_rate",
        label: "angle rate θ̇ or φ̇",
        unit: "rad/s",
        default: 0.0,
        min: -1e9,
        max: 1e9,
        description: "a rate θ̇ or φ̇ of a start; the speed it gives (l·rate) must also be within \
                      the velocity limit",
        allowed: "a finite number in [-1e9, 1e9] rad/s",
    },
    ParamSpec {
        name: "time",
        label: "time",
        unit: "s",
        default: 0.0,
        min: -1e12,
        max: 1e12,
        description: "a time (t0, t_end, save times, the times of the exact solution): about 30 000 \
                      years; past it a time has fewer than 4 digits after the decimal point",
        allowed: "a finite number in [-1e12, 1e12] s",
    },
    ParamSpec {
        name: "dt",
        label: "step size dt",
        unit: "s",
        default: 1e-3,
        min: 1e-12,
        max: 1e6,
        description: "a step size: at t = 10¹² s a smaller step would no longer change t by a \
                      representable amount",
        allowed: "a finite number in [1e-12, 1e6] s",
    },
    ParamSpec {
        name: "steps",
        label: "planned steps",
        unit: "1",
        default: 0.0,
        min: 0.0,
        max: 1e10,
        description: "the steps a fixed-step run plans, (t_end − t0)/dt: 10¹⁰ is about an hour of \
                      RATTLE on one core; more is refused before any work starts",
        allowed: "at most 1e10 steps (t_end - t0)/dt: shorten t_end or raise dt",
    },
    ParamSpec {
        name: "samples",
        label: "saved samples",
        unit: "1",
        default: 0.0,
        min: 1.0,
        max: 1e9,
        description: "the samples a run keeps (save_at times, evaluation times of the exact solution, \
                      sweep points): 10⁹ samples of t, x, v are 56 GB",
        allowed: "at most 1e9 samples",
    },
    ParamSpec {
        name: "saved_bytes",
        label: "memory of saved samples",
        unit: "B",
        default: 4294967296.0,
        min: 56.0,
        max: 68719476736.0,
        description: "the memory a run may fill with saved samples (max_saved_bytes; default 4 GiB, at \
                      most 64 GiB): refused up front for fixed steps, when reached for dop853",
        allowed: "an integer number of bytes in [56, 2**36]",
    },
    ParamSpec {
        name: "file_bytes",
        label: "file size",
        unit: "B",
        default: 1048576.0,
        min: 0.0,
        max: 1048576.0,
        description: "the size of a scenario or sweep file: 1 MiB, checked before parsing (the \
                      largest example is under 4 kB)",
        allowed: "a file of at most 1 MiB",
    },
    ParamSpec {
        name: "file_nesting",
        label: "file nesting",
        unit: "1",
        default: 16.0,
        min: 0.0,
        max: 16.0,
        description: "how deeply arrays and tables of a scenario or sweep file may nest, checked \
                      before parsing (the deepest key in use nests 3 levels)",
        allowed: "at most 16 levels of nested arrays and tables",
    },
];

/// The limit named `name` of [`LIMITS`].
pub fn limit(name: &str) -> &'static ParamSpec {
    LIMITS.iter().find(|l| l.name == name).expect("a registered limit")
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
                  hangs at l = l0 + m g/k; 1:1:2 resonance at k = 3 m g/l0 (default: for l0 = 1 m, m = 1 kg)",
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

/// E(t) − E(0) − m∫P dt along samples (t, state) by the trapezoidal rule [J]: the power-balance
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
