//! The binding layer `pendulab._core`: conversions between numpy and `pendulab-core`, and the
//! mapping of core errors to Python exceptions. No physics lives here.
//!
//! Units are SI throughout (m, kg, s, rad). Arrays of 3-vectors are float64 with shape (N, 3).
//!
//! - `convert.rs`: errors to exceptions, vectors and arrays, models by name, options, samples, stats.
//! - `getters.rs`: the getters the stepping classes share (`t`, `x`, `v`, `stats`, `progress`,
//!   `done`), one macro.
//! - `tables.rs`: the registries of methods and models; `states.rs`: states and diagnostics.
//! - `spec.rs`: `ModelSpec` and `RunOptions`, the run as one description (`(spec, state, options)`).
//! - `solver.rs`: `Solver`, `Stepper`; `force.rs`: `ForceSolver` (a Python force); `ensemble.rs`,
//!   `ensemble_adaptive.rs`, `exact.rs`, `spring.rs`, `string.rs`, `slewing.rs`, `crane.rs`: one binding per core module;
//!   `live.rs`: `LiveSession`, the lab's live session (the server's sessions).
//! - `threads.rs`: the ensembles' worker threads (rayon's pool), each bound to a CPU of its own.

mod background;
mod convert;
mod getters;

mod crane;
mod ensemble;
mod ensemble_adaptive;
mod exact;
mod force;
mod limits;
mod live;
mod sensitivity;
mod slewing;
mod solver;
mod spec;
mod spring;
mod states;
mod string;
mod tables;
mod threads;

use convert::{IntegrationError, InvalidInputError};
use pyo3::prelude::*;

/// The ensembles' worker threads (rust/threads.rs): `(threads, bound)`, the pool's size and whether
/// each worker is bound to a CPU of its own.
#[pyfunction]
fn thread_pool() -> (usize, bool) {
    let info = threads::start_pool();
    (info.threads, info.bound)
}

/// The compiled core of Pendulab (private; use the `pendulab` package).
#[pymodule]
fn _core(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("InvalidInputError", m.py().get_type::<InvalidInputError>())?;
    m.add("IntegrationError", m.py().get_type::<IntegrationError>())?;
    tables::register(m)?;
    states::register(m)?;
    spec::register(m)?;
    solver::register(m)?;
    exact::register(m)?;
    ensemble::register(m)?;
    ensemble_adaptive::register(m)?;
    spring::register(m)?;
    string::register(m)?;
    slewing::register(m)?;
    crane::register(m)?;
    force::register(m)?;
    limits::register(m)?;
    sensitivity::register(m)?;
    live::register(m)?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    // trajectories per block of the RATTLE ensemble (the sweeps' chunks are a multiple of it)
    m.add("ENSEMBLE_LANES", pendulab_core::ensemble::LANES)?;
    m.add_function(wrap_pyfunction!(thread_pool, m)?)?;
    threads::start_pool();
    Ok(())
}
