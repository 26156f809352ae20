//! The registries as Python tables: the integrators (`methods`: declared order and properties) and
//! the models (`models`: names, parameters with units, defaults and limits), and the checks of a
//! model against them (`check_params`; a model is checked by building its `ModelSpec`), and the RATTLE
//! arithmetics' facts (`fused_is_fast`, `arithmetic_version`). SI units as the registries list them.

use crate::convert::{model, to_py};
use pendulab_core::integrate::rattle_kernel::Arithmetic;
use pendulab_core::model::registry::{common_for, ParamSpec, MODELS};
use pendulab_core::Method;
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// One parameter of the model registry as a dict: name, label, unit, default, min, max, description, allowed.
pub(crate) fn param_dict<'py>(py: Python<'py>, p: &ParamSpec) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("name", p.name)?;
    d.set_item("label", p.label)?;
    d.set_item("unit", p.unit)?;
    d.set_item("default", p.default)?;
    d.set_item("min", p.min)?;
    d.set_item("max", p.max)?;
    d.set_item("description", p.description)?;
    d.set_item("allowed", p.allowed)?;
    Ok(d)
}

/// Validates the parameters (l > 0 m, m > 0 kg, finite g in m/s²).
#[pyfunction]
fn check_params(length: f64, mass: f64, g: f64) -> PyResult<()> {
    model(length, mass, g).map(|_| ())
}

/// The model registry: name, label, summary, and parameters (common ones first) with labels, units,
/// one-line help and limits.
#[pyfunction]
fn models(py: Python<'_>) -> PyResult<Vec<Bound<'_, PyDict>>> {
    MODELS
        .iter()
        .map(|m| {
            let d = PyDict::new(py);
            d.set_item("name", m.name)?;
            d.set_item("label", m.label)?;
            d.set_item("summary", m.summary)?;
            d.set_item("interactive", m.interactive)?;
            let common = common_for(m.name);
            let params: PyResult<Vec<_>> = common.iter().chain(m.params).map(|p| param_dict(py, p)).collect();
            d.set_item("params", params?)?;
            Ok(d)
        })
        .collect()
}

/// The registered integrators with their declared order and properties.
#[pyfunction]
fn methods(py: Python<'_>) -> PyResult<Vec<Bound<'_, PyDict>>> {
    Method::ALL
        .iter()
        .map(|m| {
            let i = m.info();
            let d = PyDict::new(py);
            d.set_item("name", i.name)?;
            d.set_item("order", i.order)?;
            d.set_item("symplectic", i.symplectic)?;
            d.set_item("preserves_ts2", i.preserves_ts2)?;
            d.set_item("preserves_j3", i.preserves_j3)?;
            d.set_item("adaptive", i.adaptive)?;
            d.set_item("dense_output", i.dense_output)?;
            d.set_item("default", *m == Method::DEFAULT)?;
            d.set_item("summary", i.summary)?;
            Ok(d)
        })
        .collect()
}

/// Whether a fused multiply-add is one instruction at the level the core's hot loops run at on this
/// CPU (x86-64-v3/v4, aarch64): what `arithmetic="auto"` resolves by (`isa::fused_is_fast`).
#[pyfunction]
fn fused_is_fast() -> bool {
    pendulab_core::isa::fused_is_fast()
}

/// The version of the bits of the RATTLE arithmetic `arithmetic` ("unfused" or "fused"; the core's
/// `Arithmetic::version`): the same arithmetic and version, the same numbers; bumped whenever any
/// bit of that arithmetic's results changes (sweeps record it and refuse to mix versions).
#[pyfunction]
fn arithmetic_version(arithmetic: &str) -> PyResult<u32> {
    Ok(Arithmetic::from_name(arithmetic).map_err(to_py)?.version())
}

/// Registers the tables and checks.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(arithmetic_version, m)?)?;
    m.add_function(wrap_pyfunction!(fused_is_fast, m)?)?;
    m.add_function(wrap_pyfunction!(methods, m)?)?;
    m.add_function(wrap_pyfunction!(models, m)?)?;
    m.add_function(wrap_pyfunction!(check_params, m)?)
}
