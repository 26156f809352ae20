//! The table of limits shared by every layer (docs/limits.md): [`ParamSpec`] (a named value with its
//! unit \[SI\], default and allowed range), [`check_limits`], the bounds of a state ([`STATE`]: speed
//! [m/s], distance \[m\]), the parameters every model shares ([`COMMON`]: l \[m\], m \[kg\], g [m/s²]) and
//! the bounds of everything else a run is made of ([`LIMITS`]: positions, times, steps, samples, bytes).
//!
//! It sits just above [`crate::error`] and below [`crate::state`]: `state`, `elastic`, `solve` and the
//! model registry ([`crate::model::registry`], which re-exports these names) all check against it,
//! and it imports nothing but the error type.

use crate::error::{Error, Result};

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

impl ParamSpec {
    /// The same parameter with the allowed values `min ..= max` (in words: `allowed`). Every bound is
    /// finite and has a physical reason, given in docs/models.md ("Limits"); a test checks that table
    /// against this registry.
    pub(crate) const fn within(self, min: f64, max: f64, allowed: &'static str) -> ParamSpec {
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
/// for the swinging spring whose bob leaves the sphere, its distance |x| from the pivot \[m\].
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
        description: "length of the rod from the pivot to the bob",
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

/// The shared parameters as `model` (a registry name) reads them: [`COMMON`], with length and mass
/// described for what holds its bob — a rod, the hoisted model's rope (l at t = 0, T-11.10), the
/// swinging spring (its rest length l₀, T-7.4) or the string (the bob's largest distance) — for
/// `pendulab models`, `pl.models()` and the lab's tooltips. Any other name: [`COMMON`] as it is.
pub fn common_for(model: &str) -> [ParamSpec; 3] {
    let [mut length, mut mass, g] = [COMMON[0], COMMON[1], COMMON[2]];
    let (l, m) = match model {
        "hoisted" => (
            "rope length at t = 0: the rope is l(t) = l + r t + a sin(ν t) long (T-11.10)",
            "mass of the bob (the rope is massless)",
        ),
        "spring" => (
            "rest length l₀ of the spring (T-7.4): the bob rests at l₀ + m|g|/k from the pivot",
            "mass of the bob (the spring is massless)",
        ),
        "string" => (
            "length of the string: the bob's largest distance from the pivot (slack when closer)",
            "mass of the bob (the string is massless)",
        ),
        _ => (length.description, mass.description),
    };
    (length.description, mass.description) = (l, m);
    [length, mass, g]
}

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
