//! `pendulab._core.limits()`: the registry's bounds of states, times, steps, samples, bytes and
//! files ([`pendulab_core::model::registry::LIMITS`]) as dicts, the same shape as a model's
//! parameters (name, unit, default, min, max, description — the reason for the bound —, allowed).

use pendulab_core::model::registry::LIMITS;
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// The limits of everything a run is made of besides the model's parameters.
#[pyfunction]
fn limits(py: Python<'_>) -> PyResult<Vec<Bound<'_, PyDict>>> {
    LIMITS.iter().map(|p| crate::tables::param_dict(py, p)).collect()
}

pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(limits, m)?)
}
