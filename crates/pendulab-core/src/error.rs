//! The one error type of the core. Every message names the offending quantity, its value and
//! what is allowed, so that the Python layer and the CLI can show it to a user unchanged.

use thiserror::Error;

mod hint;
pub use hint::{close_match, did_you_mean, nearest, Quoted};

/// Everything that can go wrong in `pendulab-core`.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum Error {
    /// A scalar parameter is outside its allowed range (or not finite).
    #[error("invalid {name} = {}: {allowed}", Shown(*value))]
    InvalidParameter {
        /// Parameter name as the user wrote it (e.g. `"length"`, `"dt"`).
        name: &'static str,
        /// The value that was given.
        value: f64,
        /// Human-readable description of the allowed range, with units.
        allowed: &'static str,
    },
    /// A state is not on TS² (|x| = l, x·v = 0) within the stated tolerance.
    #[error(
        "state is not on TS² (|x| = l, x·v = 0): {what} = {} exceeds the tolerance {}; \
         pass project=True to move it onto TS²",
        Shown(*value),
        Shown(*tolerance)
    )]
    NotOnTangentBundle {
        /// Which residual failed: `"(|x| - l)/l"` or `"x·v/(l·|v|)"`.
        what: &'static str,
        /// The residual's value (dimensionless).
        value: f64,
        /// The tolerance it was compared against (dimensionless).
        tolerance: f64,
    },
    /// A component of a state vector is NaN or infinite.
    #[error("{name}[{index}] = {} is not a finite number", Shown(*value))]
    NonFinite {
        /// `"x"` or `"v"` (or an angle name).
        name: &'static str,
        /// Component index (0, 1, 2).
        index: usize,
        /// The bad value.
        value: f64,
    },
    /// The state cannot be projected onto TS² (x = 0 has no direction).
    #[error("cannot project x = 0 onto the sphere |x| = l: the position has no direction")]
    DegeneratePosition,
    /// An unknown integrator name, with the nearest registered one ([`did_you_mean`]) and all of them.
    #[error("unknown method {}{}; available: {available}", Quoted(name), did_you_mean(name, available.split(", ")))]
    UnknownMethod {
        /// The name that was asked for.
        name: String,
        /// Comma-separated list of registered names.
        available: String,
    },
    /// The spherical-angle integrator came too close to a pole, where T-2.5 is singular.
    #[error(
        "method 'rk4_angles' refuses to continue at t = {} s: sin θ = {} is below {} \
         (θ = {} rad is within reach of a pole, where the angle equations T-2.5 are singular); \
         use a Cartesian method such as 'rattle' or 'dop853'",
        Time(*t),
        Shown(*sin_theta),
        Shown(*limit),
        Shown(*theta)
    )]
    PoleSingularity {
        /// Time of the refusal \[s\]: the start of the step that came within reach of the pole.
        t: f64,
        /// Polar angle from the downward vertical \[rad\].
        theta: f64,
        /// sin θ at that moment.
        sin_theta: f64,
        /// The smallest sin θ the method accepts.
        limit: f64,
    },
    /// The adaptive integrator could not meet the tolerance.
    #[error(
        "step size underflow at t = {} s: h = {} s is too small for rtol = {}, atol = {}{}",
        Time(*t),
        Shown(*h),
        Shown(*rtol),
        Shown(*atol),
        hint::drift_advice(*off_sphere)
    )]
    StepSizeUnderflow {
        /// Time at which it happened \[s\].
        t: f64,
        /// Step size reached \[s\].
        h: f64,
        /// Relative tolerance in force.
        rtol: f64,
        /// Absolute tolerance in force.
        atol: f64,
        /// Unprojected `dop853`: (|x| − l)/l, x·v/(l·|v|) at t when above 100·rtol (T-2.4); else None.
        off_sphere: Option<(f64, f64)>,
    },
    /// The state the integrator computed (not one the user gave) became NaN or infinite, or left the
    /// bounds of a state ([`crate::limits::STATE`]): the integration diverged. `t` is the time of the
    /// last finite state, where the run stands (the start of the step that diverged, or the last saved
    /// sample when a method that does not check its states is found non-finite later).
    #[error(
        "the integration diverged after t = {} s with method '{method}' (dt = {} s): the computed state \
         became non-finite or left the bounds of a state; {}",
        Time(*t),
        Shown(*dt),
        diverged_advice(method).1
    )]
    Diverged {
        /// Time of the last finite state \[s\].
        t: f64,
        /// Method name.
        method: &'static str,
        /// Step size \[s\] (for `dop853`, the step tried).
        dt: f64,
    },
    /// The requested output does not fit in memory.
    #[error("{samples} saved samples would need {bytes} bytes, above the limit of {limit} bytes; save less often (raise save_every) or shorten t_end")]
    TooManySamples {
        /// Number of samples requested.
        samples: u64,
        /// Memory they would need \[bytes\].
        bytes: u64,
        /// The limit \[bytes\].
        limit: u64,
    },
    /// The reduced flow with reconstruction (T-3.4, T-3.6) came too close to a pole.
    #[error(
        "the reduced flow reached a pole at t = {} s (σ₁ = z/l = {}), where the reconstruction \
         φ̇ = J₃/(m(l² − z²)) is singular; use the exact solution or a Cartesian integrator there",
        Time(*t),
        Shown(*sigma1)
    )]
    ReducedFlowPole {
        /// Time \[s\].
        t: f64,
        /// σ₁ = z/l at that time.
        sigma1: f64,
    },
    /// An unknown model name.
    #[error("unknown model {}; available: {available}", Quoted(name))]
    UnknownModel {
        /// The name that was asked for.
        name: String,
        /// The registered names.
        available: String,
    },
    /// A parameter the model does not have.
    #[error(
        "the '{model}' model has no parameter {}; its parameters: length, mass, g{}{available}",
        Quoted(name),
        if available.is_empty() { "" } else { ", " }
    )]
    UnknownParameter {
        /// Model name.
        model: &'static str,
        /// The unknown key.
        name: String,
        /// The model's own parameters ("" when it has none).
        available: String,
    },
    /// An unknown arithmetic name (`integrate::rattle_kernel::Arithmetic`).
    #[error("unknown arithmetic {}; available: unfused (default: the same bits on every CPU and in WebAssembly), fused (f64::mul_add: faster on CPUs with FMA)", Quoted(name))]
    UnknownArithmetic {
        /// The name that was asked for.
        name: String,
    },
    /// Fused arithmetic asked of a method that does not have it.
    #[error("arithmetic 'fused' applies to the RATTLE family (rattle, rattle4, rattle6, rattle8) and the RATTLE ensemble, not to method '{method}'")]
    UnsupportedArithmetic {
        /// Method name.
        method: &'static str,
    },
    /// A method the RATTLE ensemble does not run.
    #[error("the RATTLE ensemble runs method 'rattle' or its compositions 'rattle4', 'rattle6', 'rattle8', not '{method}' (the adaptive ensemble runs 'dop853')")]
    UnsupportedEnsembleMethod {
        /// Method name.
        method: &'static str,
    },
    /// A method that cannot integrate this model.
    #[error("method '{method}' cannot integrate the '{model}' model (it supports only the ideal pendulum and the hoisted rope below a fixed pivot); use 'rattle' or 'dop853'")]
    UnsupportedModel {
        /// Method name.
        method: &'static str,
        /// Model name.
        model: &'static str,
    },
    /// A hybrid model (taut and slack phases) given to the plain stepper.
    #[error(
        "the '{model}' model is hybrid (the string goes slack and snaps taut again): it has its own \
             driver — pendulab.simulate in Python, pendulab run for scenario files, \
             pendulab_core::string_run in Rust — not the incremental stepper"
    )]
    HybridModel {
        /// Model name.
        model: &'static str,
    },
    /// A model whose state is not on TS² (the swinging spring) asked for as a pendulum.
    #[error(
        "the '{model}' model (the swinging spring, T-7.4) leaves the sphere and is not a rod pendulum: \
             use pendulab.SwingingSpring and pendulab.simulate_spring, or a scenario file with \
             model = \"{model}\" (pendulab run)"
    )]
    OffSphereModel {
        /// Model name.
        model: &'static str,
    },
    /// Pivot samples that cannot define a path.
    #[error("invalid pivot samples: {reason}")]
    InvalidPivotSamples {
        /// What is wrong.
        reason: String,
    },
    /// The save times are not usable.
    #[error("invalid save times: {reason}")]
    InvalidSaveTimes {
        /// What is wrong.
        reason: String,
    },
    /// A crane run that cannot go on (a slack rope, a rope length ≤ 0, …).
    #[error("crane: {reason}")]
    Crane {
        /// What happened, with the time.
        reason: String,
    },
    /// A live session's integration stopped ([`crate::live`]): `cause` says why and when; the session
    /// is paused at the last state computed.
    #[error("{cause}; paused")]
    Stopped {
        /// The integrator's error.
        cause: Box<Error>,
    },
    /// A request a live session ([`crate::live`]) cannot carry out, said in full (what was asked and
    /// what is allowed).
    #[error("{0}")]
    Refused(String),
    /// A request a live session cannot carry out, said in full (`words`), with the message key and values
    /// a page words it by in its language (python/pendulab/server/messages.json: an unknown parameter, a
    /// model the lab does not run, too many steps waiting, a method the model does not run, a crane
    /// command outside the crane mode).
    #[error("{words}")]
    RefusedKeyed {
        /// The English words.
        words: String,
        /// The message key.
        key: &'static str,
        /// The values of the key's placeholders.
        values: Vec<(&'static str, String)>,
    },
}

impl Error {
    /// The message key and values of an error of a common kind, for a page that words it in its
    /// language (the lab server's `messages.json`; docs/web.md, "Languages"), or None (the English
    /// words alone). Every number as the English words write it, so that a page in any language names
    /// the same value: times \[s\] by [`Time`] (12 significant digits), step sizes \[s\], residuals and
    /// the value of a parameter by [`Shown`] (the digits that read back as the same f64; step sizes and
    /// residuals were rounded to 4 significant digits, so de/fr could name another dt or h).
    pub fn key(&self) -> Option<(&'static str, Vec<(&'static str, String)>)> {
        let t = |t: f64| Time(t).to_string();
        let e = |x: f64| Shown(x).to_string();
        Some(match self {
            Error::StepSizeUnderflow { t: at, h, .. } => {
                ("step_too_small", vec![("t", t(*at)), ("h", e(*h))])
            }
            Error::Diverged { t: at, method, dt } => (
                diverged_advice(method).0,
                vec![("t", t(*at)), ("method", method.to_string()), ("dt", e(*dt))],
            ),
            Error::PoleSingularity { t: at, .. } | Error::ReducedFlowPole { t: at, .. } => {
                ("near_pole", vec![("t", t(*at))])
            }
            Error::NonFinite { name, index, value } => (
                "not_finite",
                vec![
                    ("name", name.to_string()),
                    ("index", index.to_string()),
                    ("value", Shown(*value).to_string()),
                ],
            ),
            Error::NotOnTangentBundle { what, value, tolerance } => (
                "off_sphere",
                vec![("what", what.to_string()), ("value", e(*value)), ("tolerance", e(*tolerance))],
            ),
            Error::InvalidParameter { name, value, allowed } => (
                "invalid_parameter",
                vec![
                    ("name", name.to_string()),
                    ("value", Shown(*value).to_string()),
                    ("allowed", allowed.to_string()),
                ],
            ),
            Error::UnknownModel { name, available } => {
                ("unknown_model", vec![("model", name.clone()), ("available", available.clone())])
            }
            Error::RefusedKeyed { key, values, .. } => (*key, values.clone()),
            Error::Stopped { cause } => {
                let mut values = vec![("detail", cause.to_string())];
                if let Some((why, more)) = cause.key() {
                    values.push(("why", why.to_string()));
                    values.extend(more);
                }
                ("integration_stopped", values)
            }
            _ => return None,
        })
    }
}

/// A time in a message \[s\]: rounded to 12 significant digits, then written by [`Shown`] (`0.15`, `1e-7`,
/// `nan`). A computed time carries the round-off of its sums (0.1 + 0.05 = 0.15000000000000002), which
/// the shortest digits that read back as the same f64 would show; 12 digits are those of the computed
/// time itself (not rounded to the step, so a time off the step's grid still shows as such), with no
/// noise in the last places: the time differs from the one written by at most 5e-12 of it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Time(pub f64);

impl std::fmt::Display for Time {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let x = self.0;
        let rounded = if x.is_finite() { format!("{x:.11e}").parse().unwrap_or(x) } else { x };
        Shown(rounded).fmt(f)
    }
}

/// A number in a message as a user writes it: the shortest digits that read back as the same f64, in
/// plain decimals when 1e-4 ≤ |x| < 1e6 (`-1`, `0.5`, `1234.5`, `0.0001`), beyond that in whichever
/// of the plain and the exponent form is shorter (`1e9`, `123456789`, `1e-7`, `2.5e20`, `-3e-300`);
/// `nan`, `inf`, `-inf` as TOML and Python write them (`pendulab._numbers.shown` is the same in Python). Every number of [`enum@Error`]'s messages and message values is written by it:
/// `{:e}` wrote a damping of −1 as `-1e0` and a step of 0.01 s as `1e-2`, `{}` wrote 1e-300 with 300
/// digits.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Shown(pub f64);

impl std::fmt::Display for Shown {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let x = self.0;
        if x.is_nan() {
            f.write_str("nan")
        } else if x.is_infinite() {
            f.write_str(if x > 0.0 { "inf" } else { "-inf" })
        } else {
            let (plain, exponent) = (format!("{x}"), format!("{x:e}"));
            let everyday = (1e-4..1e6).contains(&x.abs());
            f.write_str(if everyday || plain.len() <= exponent.len() { &plain } else { &exponent })
        }
    }
}

/// The message key of a divergence of `method` and what to do, the same advice in every language (one
/// key per advice: messages.json's `diverged`, `diverged_rattle`, `diverged_dop853`, `diverged_dt`): a
/// smaller step (tighter tolerances for `dop853`), and an adaptive or structure-preserving method unless
/// one is in use (the spring's and the string's drivers have one method each).
pub fn diverged_advice(method: &str) -> (&'static str, &'static str) {
    if method.starts_with("rattle") {
        ("diverged_rattle", "reduce dt (the step must resolve the fastest motion, dt·ω ≪ 1)")
    } else if method.starts_with("dop853") {
        ("diverged_dop853", "lower rtol and atol, or use the structure-preserving 'rattle'")
    } else if method.starts_with("spring") || method.starts_with("string") {
        ("diverged_dt", "reduce dt")
    } else {
        ("diverged", "reduce dt, or use an adaptive ('dop853') or structure-preserving ('rattle') method")
    }
}

/// Result alias of the core.
pub type Result<T> = std::result::Result<T, Error>;

/// Checks that `value` is finite and strictly positive.
pub fn require_positive(name: &'static str, value: f64, allowed: &'static str) -> Result<f64> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(Error::InvalidParameter { name, value, allowed })
    }
}

/// Checks that `value` is finite and ≥ 0.
pub fn require_non_negative(name: &'static str, value: f64, allowed: &'static str) -> Result<f64> {
    if value.is_finite() && value >= 0.0 {
        Ok(value)
    } else {
        Err(Error::InvalidParameter { name, value, allowed })
    }
}

/// Checks that `value` is finite.
#[inline(always)]
pub fn require_finite(name: &'static str, value: f64, allowed: &'static str) -> Result<f64> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(Error::InvalidParameter { name, value, allowed })
    }
}

#[cfg(test)]
#[path = "error_tests.rs"]
mod tests;
