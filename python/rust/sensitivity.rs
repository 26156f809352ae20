//! `pendulab._core.sensitivities`: the rod models' motion at given times with its exact derivatives
//! by the start angles and the parameters ([`pendulab_core::sensitivity`], docs/theory.md T-10.7) —
//! the Jacobian of `pl.fit` without finite differences. SI units: times [s], x [m], v [m/s].

use crate::convert::{to_py, InvalidInputError};
use crate::spec::{ModelSpec, RunOptions};
use numpy::{PyArray2, PyArray3, PyReadonlyArray1};
use pendulab_core::model::registry::AnyModel;
use pendulab_core::model::Extended;
use pendulab_core::sensitivity::{sensitivities as run, PARAMS};
use pyo3::prelude::*;

type Out<'py> = (
    Bound<'py, PyArray2<f64>>,
    Bound<'py, PyArray2<f64>>,
    Bound<'py, PyArray3<f64>>,
    Bound<'py, PyArray3<f64>>,
);

/// x (n, 3) [m], v (n, 3) [m/s] at `times` [s] (from the start at t = 0) and their derivatives
/// dx, dv (n, 3, 9) by (θ₀, φ₀, θ̇₀, φ̇₀, l, g, damping, drag, friction) — `sensitivity_params()`.
/// The spec's model is "ideal", "damped" or "rotating"; the start is `angles` = (θ₀, φ₀ [rad], θ̇₀,
/// φ̇₀ [rad/s]); the options give the tolerances rtol, atol [m, m/s] of DOP853.
#[pyfunction]
fn sensitivities<'py>(
    py: Python<'py>,
    spec: &ModelSpec,
    angles: [f64; 4],
    times: PyReadonlyArray1<'py, f64>,
    options: &RunOptions,
) -> PyResult<Out<'py>> {
    let m = match spec.registry()? {
        AnyModel::Ideal(p) => Extended::ideal(*pendulab_core::Model::params(&p)),
        AnyModel::Extended(e, _) => e,
        _ => {
            return Err(InvalidInputError::new_err(format!(
                "sensitivities are for the rod models ideal, damped, rotating, not {:?}",
                spec.name()
            )))
        }
    };
    let (rtol, atol) = (options.solve.rtol, options.solve.atol);
    let times: Vec<f64> = times.as_array().iter().copied().collect();
    let s = py.allow_threads(|| run(&m, angles, &times, rtol, atol)).map_err(to_py)?;
    let n = times.len();
    let k = PARAMS.len();
    let rows = |a: &[glam::DVec3]| a.iter().map(|p| p.to_array().to_vec()).collect::<Vec<_>>();
    let x = PyArray2::from_vec2(py, &rows(&s.x))?;
    let v = PyArray2::from_vec2(py, &rows(&s.v))?;
    let cube = |d: &[[glam::DVec3; 9]]| {
        let mut flat = Vec::with_capacity(n * 3 * k);
        for row in d {
            for c in 0..3 {
                flat.extend(row.iter().map(|col| col[c]));
            }
        }
        numpy::ndarray::Array3::from_shape_vec((n, 3, k), flat).expect("n × 3 × k values")
    };
    let dx = PyArray3::from_owned_array(py, cube(&s.dx));
    let dv = PyArray3::from_owned_array(py, cube(&s.dv));
    Ok((x, v, dx, dv))
}

/// The names of the sensitivities' last axis, in order.
#[pyfunction]
fn sensitivity_params() -> Vec<&'static str> {
    PARAMS.to_vec()
}

pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(sensitivities, m)?)?;
    m.add_function(wrap_pyfunction!(sensitivity_params, m)?)
}
