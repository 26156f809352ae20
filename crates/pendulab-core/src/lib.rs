//! # pendulab-core
//!
//! Physics and numerics of the spherical pendulum — a point mass on a rigid rod of length l swinging
//! about a fixed pivot under uniform gravity — as a particle on the sphere S² in a linear potential.
//! Pure Rust; the Python package `pendulab` binds it.
//!
//! ## Conventions (docs/theory.md §1)
//! - SI units throughout: m, kg, s, rad, J, N.
//! - z axis up; for g > 0 gravity acts along −z and the bob hangs at rest at z = −l. Any finite g
//!   is allowed (g < 0 pulls up, g = 0 leaves only the rod).
//! - A state is (x, v) ∈ TS²: position x \[m\] relative to the pivot with |x| = l, velocity v [m/s]
//!   with x·v = 0 ([`State`]).
//! - Polar angle θ from the downward vertical, azimuth φ = atan2(y, x).
//!
//! ## Modules
//! - [`limits`]: the table of limits (units, defaults, allowed ranges) every layer checks against.
//! - [`state`]: parameters, states on TS², angles, projection.
//! - [`model`]: models (applied forces) and the constrained equations T-2.2/T-2.4, diagnostics
//!   E, J₃, tension (T-2.3, T-2.6).
//! - [`integrate`]: the integrators and their registry [`Method`].
//! - [`stepper`]: incremental integration (init / step / state).
//! - [`mod@solve`]: batch solving with saving rules, chunked for progress and cancellation.
//! - [`string_run`]: the string pendulum's hybrid stepper and runner (events, free flight, snaps).
//! - [`exact`]: the exact solution by elliptic functions (§4), phases (§5), energy–momentum map (T-6.4).
//! - [`reduce`]: S¹-invariants σ₁…σ₆, Casimir, the reduced (Nambu) flow and reconstruction (§3).
//! - [`quadrature`]: adaptive Gauss–Kronrod quadrature.
//! - [`sensitivity`]: the real pendulum's motion with its derivatives by start and parameters (a
//!   fit's Jacobian, T-10.7).
//! - [`crane`]: cranes: hoisting, hook + payload, wind (§11).
//! - [`elastic`]: the swinging spring (T-7.4) with its own symplectic integrators.
//! - [`ensemble`]: many trajectories at once (SoA blocks, rayon), RATTLE.
//! - [`error`]: the error type.
//! - [`live`]: the lab's live session (pacing, per-tick budget with the time passed in, frame records,
//!   error estimate), shared by the server and the page's WebAssembly engine.
//! - [`isa`]: run-time choice of the instruction set (AVX2/FMA, AVX-512) for the hot loops.

pub mod crane;
pub mod elastic;
pub mod elliptic;
pub mod ensemble;
pub mod error;
pub mod exact;
pub mod integrate;
pub mod isa;
pub mod limits;
pub mod live;
pub mod model;
pub mod quadrature;
pub mod reduce;
pub mod sensitivity;
pub mod solve;
pub mod state;
pub mod stepper;
pub mod string_run;

pub use error::{Error, Result};
pub use glam::DVec3;
pub use integrate::{Method, MethodInfo, Stats};
pub use model::{IdealPendulum, Model};
pub use solve::{solve, Samples, SaveAt, Solver};
pub use state::{Params, State};
pub use stepper::{SolveOptions, Stepper};
