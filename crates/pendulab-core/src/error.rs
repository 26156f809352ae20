//! The one error type of the core. Every message names the offending quantity, its value and
//! what is allowed, so that the Python layer and the CLI can show it to a user unchanged.

use thiserror::Error;

/// Everything that can go wrong in `pendulab-core`.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum Error {
    /// A scalar parameter is outside its allowed range (or not finite).
    #[error("invalid {name} = {value:e}: {allowed}")]
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
        "state is not on TS² (|x| = l, x·v = 0): {what} = {value:e} exceeds the tolerance {tolerance:e}; \
         pass project=True to move it onto TS²"
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
    #[error("{name}[{index}] = {value} is not a finite number")]
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
    /// An unknown integrator name.
    #[error("unknown method {name:?}; available: {available}")]
    UnknownMethod {
        /// The name that was asked for.
        name: String,
        /// Comma-separated list of registered names.
        available: String,
    },
    /// The spherical-angle integrator came too close to a pole, where T-2.5 is singular.
    #[error(
        "method 'rk4_angles' refuses to continue at t = {t} s: sin θ = {sin_theta:e} is below {limit:e} \
         (θ = {theta} rad is within reach of a pole, where the angle equations T-2.5 are singular); \
         use a Cartesian method such as 'rattle' or 'dop853'"
    )]
    PoleSingularity {
        /// Time of the refusal \[s\].
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
        "step size underflow at t = {t} s: h = {h:e} s is too small for rtol = {rtol:e}, atol = {atol:e}"
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
    },
    /// The state became NaN or infinite during integration.
    #[error(
        "the solution became non-finite at t = {t} s with method '{method}' (dt = {dt:e} s); {}",
        diverged_advice(method)
    )]
    Diverged {
        /// Time \[s\].
        t: f64,
        /// Method name.
        method: &'static str,
        /// Step size \[s\].
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
        "the reduced flow reached a pole at t = {t} s (σ₁ = z/l = {sigma1}), where the reconstruction \
         φ̇ = J₃/(m(l² − z²)) is singular; use the exact solution or a Cartesian integrator there"
    )]
    ReducedFlowPole {
        /// Time \[s\].
        t: f64,
        /// σ₁ = z/l at that time.
        sigma1: f64,
    },
    /// An unknown model name.
    #[error("unknown model {name:?}; available: {available}")]
    UnknownModel {
        /// The name that was asked for.
        name: String,
        /// The registered names.
        available: String,
    },
    /// A parameter the model does not have.
    #[error("the '{model}' model has no parameter {name:?}; its parameters: length, mass, g, {available}")]
    UnknownParameter {
        /// Model name.
        model: &'static str,
        /// The unknown key.
        name: String,
        /// The model's own parameters.
        available: String,
    },
    /// An unknown arithmetic name (`integrate::rattle_kernel::Arithmetic`).
    #[error("unknown arithmetic {name:?}; available: unfused (default: the same bits on every CPU and in WebAssembly), fused (f64::mul_add: faster on CPUs with FMA)")]
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
    /// A request a live session ([`crate::live`]) cannot carry out, said in full (what was asked and
    /// what is allowed).
    #[error("{0}")]
    Refused(String),
}

impl Error {
    /// The message key and values of an error of a common kind, for a page that words it in its
    /// language (the lab server's `messages.json`; docs/web.md, "Languages"), or None (the English
    /// words alone). Times \[s\] to 4 decimals, step sizes \[s\] and residuals in 4 digits, as strings.
    pub fn key(&self) -> Option<(&'static str, Vec<(&'static str, String)>)> {
        let t = |t: f64| format!("{}", (t * 1e4).round() / 1e4);
        let e = |x: f64| format!("{x:.3e}");
        Some(match self {
            Error::StepSizeUnderflow { t: at, h, .. } => {
                ("step_too_small", vec![("t", t(*at)), ("h", e(*h))])
            }
            Error::Diverged { t: at, method, dt } => {
                ("diverged", vec![("t", t(*at)), ("method", method.to_string()), ("dt", e(*dt))])
            }
            Error::PoleSingularity { t: at, .. } | Error::ReducedFlowPole { t: at, .. } => {
                ("near_pole", vec![("t", t(*at))])
            }
            Error::NonFinite { name, index, value } => (
                "not_finite",
                vec![("name", name.to_string()), ("index", index.to_string()), ("value", value.to_string())],
            ),
            Error::NotOnTangentBundle { what, value, tolerance } => (
                "off_sphere",
                vec![("what", what.to_string()), ("value", e(*value)), ("tolerance", e(*tolerance))],
            ),
            Error::InvalidParameter { name, value, allowed } => (
                "invalid_parameter",
                vec![
                    ("name", name.to_string()),
                    ("value", format!("{value}")),
                    ("allowed", allowed.to_string()),
                ],
            ),
            _ => return None,
        })
    }
}

/// What to do after a divergence: a smaller step, and a structure-preserving method unless one is in use.
fn diverged_advice(method: &str) -> &'static str {
    if method.starts_with("rattle") {
        "reduce dt (the step must resolve the fastest motion, dt·ω ≪ 1)"
    } else {
        "reduce dt or use 'rattle'"
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
