//! Conversions between Python/numpy and `pendulab-core`: core errors to Python exceptions, vectors
//! and arrays of 3-vectors, models built from the registry's names, saved samples and work counters. SI units throughout (m, kg, s, rad); arrays of 3-vectors are float64 of shape (N, 3).

use numpy::ndarray::Array2;
use numpy::{IntoPyArray, PyArray1, PyArray2, PyReadonlyArray1, PyReadonlyArray2};
use pendulab_core::model::registry::AnyModel;
use pendulab_core::solve::Samples;
use pendulab_core::{DVec3, Error, IdealPendulum, Params, Stats};
use pyo3::create_exception;
use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyDict;

create_exception!(
    _core,
    InvalidInputError,
    PyValueError,
    "Bad input: the message names the value and what is allowed."
);
create_exception!(
    _core,
    IntegrationError,
    PyRuntimeError,
    "The integration could not continue (diverged, pole, step underflow)."
);

/// A core error as a Python exception: `IntegrationError` when the integration could not go on (also
/// a live session's stopped run), `InvalidInputError` for bad input.
///
/// The common kinds also carry `key` and `values` (attributes of the exception): the message key of
/// `pendulab/server/messages.json` and its values, so that the lab server's REST analyses answer in
/// the page's language (docs/web.md, "Languages"); times in s, step sizes in s, residuals
/// dimensionless, as strings of a few digits.
pub(crate) fn to_py(err: Error) -> PyErr {
    let e = match err {
        Error::PoleSingularity { .. }
        | Error::ReducedFlowPole { .. }
        | Error::Diverged { .. }
        | Error::StepSizeUnderflow { .. }
        | Error::Stopped { .. } => IntegrationError::new_err(err.to_string()),
        _ => InvalidInputError::new_err(err.to_string()),
    };
    if let Some((key, values)) = err.key() {
        Python::with_gil(|py| {
            let v = e.value(py);
            let d = PyDict::new(py);
            let keyed = values.iter().try_for_each(|(k, x)| d.set_item(k, x)).is_ok()
                && v.setattr("key", key).is_ok()
                && v.setattr("values", d).is_ok();
            debug_assert!(keyed);
        });
    }
    e
}

/// A 3-vector from a numpy array of 3 components (m or m/s); `name` names it in the error.
pub(crate) fn vec3(name: &str, a: &PyReadonlyArray1<'_, f64>) -> PyResult<DVec3> {
    let a = a.as_array();
    if a.len() != 3 {
        return Err(InvalidInputError::new_err(format!(
            "{name} must have 3 components (m or m/s), got {}",
            a.len()
        )));
    }
    Ok(DVec3::new(a[0], a[1], a[2]))
}

/// A 3-vector as a numpy array of shape (3,).
pub(crate) fn arr3<'py>(py: Python<'py>, v: DVec3) -> Bound<'py, PyArray1<f64>> {
    v.to_array().to_vec().into_pyarray(py)
}

/// The ideal pendulum, validated (l > 0 m, m > 0 kg, finite g in m/s²).
pub(crate) fn model(length: f64, mass: f64, g: f64) -> PyResult<IdealPendulum> {
    IdealPendulum::new(length, mass, g).map_err(to_py)
}

/// Pivot samples from Python: times [s] (n,) and positions [m] (n, 3).
pub(crate) type PivotArrays<'py> = (PyReadonlyArray1<'py, f64>, PyReadonlyArray2<'py, f64>);

/// A registry model by name with its extra parameters (None: the ideal pendulum); the
/// `sampled_pivot` model takes its path from `pivot` (times, positions).
pub(crate) fn any_model(
    length: f64,
    mass: f64,
    g: f64,
    name: Option<&str>,
    extra: Option<Vec<(String, f64)>>,
    pivot: Option<PivotArrays<'_>>,
) -> PyResult<AnyModel> {
    let params = Params::new(length, mass, g).map_err(to_py)?;
    let extra = extra.unwrap_or_default();
    let pairs: Vec<(&str, f64)> = extra.iter().map(|(k, v)| (k.as_str(), *v)).collect();
    let name = name.unwrap_or("ideal");
    match (name, pivot) {
        ("sampled_pivot", Some((t, p))) => {
            // validates the keys and ranges (and that only damping is given) by building without samples
            if let Some((key, _)) = pairs.iter().find(|(k, _)| *k != "damping") {
                return Err(to_py(Error::UnknownParameter {
                    model: "sampled_pivot",
                    name: key.to_string(),
                    available: "damping".into(),
                }));
            }
            let damping = pairs.iter().find(|(k, _)| *k == "damping").map_or(0.0, |(_, v)| *v);
            let (t, p) = (t.as_array(), p.as_array());
            if p.ncols() != 3 {
                return Err(InvalidInputError::new_err(format!(
                    "pivot positions must have shape (n, 3) in m, got {:?}",
                    p.dim()
                )));
            }
            let times: Vec<f64> = t.iter().copied().collect();
            let positions: Vec<DVec3> = p.rows().into_iter().map(|r| DVec3::new(r[0], r[1], r[2])).collect();
            AnyModel::sampled_pivot(params, &times, &positions, damping).map_err(to_py)
        }
        (_, Some(_)) => Err(InvalidInputError::new_err(format!(
            "pivot samples belong to the 'sampled_pivot' model, not to {name:?}"
        ))),
        (_, None) => AnyModel::build(name, params, &pairs).map_err(to_py),
    }
}

/// Saved samples as numpy: t [s] (n,), x [m] (n, 3), v [m/s] (n, 3).
pub(crate) type Arrays<'py> =
    (Bound<'py, PyArray1<f64>>, Bound<'py, PyArray2<f64>>, Bound<'py, PyArray2<f64>>);
/// A state as two numpy vectors (x [m], v [m/s]).
pub(crate) type StatePair<'py> = (Bound<'py, PyArray1<f64>>, Bound<'py, PyArray1<f64>>);

/// Samples as numpy arrays ([`Arrays`]).
pub(crate) fn samples_to_numpy(py: Python<'_>, s: Samples) -> Arrays<'_> {
    let n = s.t.len();
    let mut x = Array2::<f64>::zeros((n, 3));
    let mut v = Array2::<f64>::zeros((n, 3));
    for (i, st) in s.states.iter().enumerate() {
        for k in 0..3 {
            x[[i, k]] = st.x[k];
            v[[i, k]] = st.v[k];
        }
    }
    (s.t.into_pyarray(py), x.into_pyarray(py), v.into_pyarray(py))
}

/// Work counters as a dict: steps, rejected, rhs_evals.
pub(crate) fn stats_dict(py: Python<'_>, s: Stats) -> PyResult<Bound<'_, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("steps", s.steps)?;
    d.set_item("rejected", s.rejected)?;
    d.set_item("rhs_evals", s.rhs_evals)?;
    Ok(d)
}
