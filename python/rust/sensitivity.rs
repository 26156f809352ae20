//! `pendulab._core.sensitivities`: the rod models' motion at given times with its exact derivatives
//! by the start angles and the parameters ([`pendulab_core::sensitivity`], docs/theory.md T-10.7) —
//! the Jacobian of `pl.fit` without finite differences. SI units: times [s], x [m], v [m/s].

use crate::convert::{any_model, to_py, InvalidInputError};
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
/// `model` is "ideal", "damped" or "rotating" with its registry parameters `params`.
#[pyfunction]
#[pyo3(signature = (length, mass, g, model, params, angles, times, rtol=1e-12, atol=1e-14))]
#[allow(clippy::too_many_arguments)]
fn sensitivities<'py>(
    py: Python<'py>,
    length: f64,
    mass: f64,
    g: f64,
    model: &str,
    params: Vec<(String, f64)>,
    angles: [f64; 4],
    times: PyReadonlyArray1<'py, f64>,
    rtol: f64,
    atol: f64,
) -> PyResult<Out<'py>> {
    let m = match any_model(length, mass, g, Some(model), Some(params), None)? {
        AnyModel::Ideal(p) => Extended::ideal(*pendulab_core::Model::params(&p)),
        AnyModel::Extended(e, _) => e,
        _ => {
            return Err(InvalidInputError::new_err(format!(
                "sensitivities are for the rod models ideal, damped, rotating, not {model:?}"
            )))
        }
    };
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
