//! `pendulab._core.sensitivities`: the rod models' motion at given times with its exact derivatives
//! by the start angles and the parameters ([`pendulab_core::sensitivity`], docs/theory.md T-10.7) —
//! the Jacobian of `pl.fit` without finite differences; `spring_sensitivities`: the swinging spring's
//! fixed-step run with its tangents ([`pendulab_core::elastic::SwingingSpring::sensitivities`],
//! T-10.8). SI units: times [s], x [m], v [m/s].

use crate::convert::{to_py, InvalidInputError};
use crate::spec::{start, ModelSpec, RunOptions, StateArrays};
use glam::DVec3;
use numpy::{PyArray2, PyArray3, PyReadonlyArray1, PyReadonlyArray2};
use pendulab_core::elastic::{Tangent, SPRING_PARAMS};
use pendulab_core::model::registry::AnyModel;
use pendulab_core::model::Extended;
use pendulab_core::sensitivity::{sensitivities as run, PARAMS};
use pyo3::prelude::*;

type Rows<'py> = Bound<'py, PyArray2<f64>>;
type Cube<'py> = Bound<'py, PyArray3<f64>>;
type Out<'py> = (Rows<'py>, Rows<'py>, Cube<'py>, Cube<'py>);
/// x, v, dx, dv and da of the spring.
type SpringOut<'py> = (Rows<'py>, Rows<'py>, Cube<'py>, Cube<'py>, Cube<'py>);

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
    let x = PyArray2::from_vec2(py, &rows(&s.x))?;
    let v = PyArray2::from_vec2(py, &rows(&s.v))?;
    let dx = PyArray3::from_owned_array(py, cube(s.dx.iter().map(|r| r.as_slice()), n, k));
    let dv = PyArray3::from_owned_array(py, cube(s.dv.iter().map(|r| r.as_slice()), n, k));
    Ok((x, v, dx, dv))
}

fn rows(a: &[DVec3]) -> Vec<Vec<f64>> {
    a.iter().map(|p| p.to_array().to_vec()).collect()
}

/// n rows of k vectors as an (n, 3, k) array: `[i, c, d]` = component c of row i's vector d.
fn cube<'a>(rows: impl Iterator<Item = &'a [DVec3]>, n: usize, k: usize) -> numpy::ndarray::Array3<f64> {
    let mut flat = Vec::with_capacity(n * 3 * k);
    for row in rows {
        for c in 0..3 {
            flat.extend(row.iter().map(|col| col[c]));
        }
    }
    numpy::ndarray::Array3::from_shape_vec((n, 3, k), flat).expect("n × 3 × k values")
}

/// The swinging spring (`ModelSpec.spring_model`) from (x0, v0) [m, m/s] with steps of the options'
/// `dt` [s] of `order` 2 or 4, at the step numbers `keep` (ascending): x, v (n, 3) and their tangents
/// dx, dv (n, 3, m + 3) by the m start quantities whose tangents ∂x₀/∂q, ∂v₀/∂q are the rows of
/// `tangents` = (dx0, dv0), (m, 3) each, then by k/m [1/s²], l₀ [m], g [m/s²] (`spring_sensitivity_params()`, T-10.8),
/// and da (n, 3, m + 3), the acceleration's derivatives there.
#[pyfunction]
fn spring_sensitivities<'py>(
    py: Python<'py>,
    spec: &ModelSpec,
    state: StateArrays<'py>,
    tangents: (PyReadonlyArray2<'py, f64>, PyReadonlyArray2<'py, f64>),
    keep: PyReadonlyArray1<'py, u64>,
    options: &RunOptions,
) -> PyResult<SpringOut<'py>> {
    let sp = spec.spring()?;
    let (x0, v0) = start(&state)?;
    let (dx0, dv0) = (tangents.0.as_array(), tangents.1.as_array());
    if dx0.shape() != dv0.shape() || dx0.ncols() != 3 {
        return Err(InvalidInputError::new_err(format!(
            "dx0 and dv0 must both have the shape (m, 3); got {:?} and {:?}",
            dx0.shape(),
            dv0.shape()
        )));
    }
    let row = |a: &numpy::ndarray::ArrayView2<'_, f64>, i: usize| DVec3::new(a[[i, 0]], a[[i, 1]], a[[i, 2]]);
    let tangents: Vec<Tangent> = (0..dx0.nrows()).map(|i| (row(&dx0, i), row(&dv0, i))).collect();
    let keep: Vec<u64> = keep.as_array().iter().copied().collect();
    let (dt, order) = (options.solve.dt, options.order);
    let s = py
        .allow_threads(|| {
            sp.sensitivities(pendulab_core::State { x: x0, v: v0 }, &tangents, dt, order, &keep)
        })
        .map_err(to_py)?;
    let (n, k) = (s.states.len(), s.directions);
    let xs: Vec<DVec3> = s.states.iter().map(|st| st.x).collect();
    let vs: Vec<DVec3> = s.states.iter().map(|st| st.v).collect();
    let (tx, tv): (Vec<DVec3>, Vec<DVec3>) = s.tangents.iter().copied().unzip();
    let dx = PyArray3::from_owned_array(py, cube(tx.chunks(k), n, k));
    let dv = PyArray3::from_owned_array(py, cube(tv.chunks(k), n, k));
    let da = PyArray3::from_owned_array(py, cube(s.accelerations.chunks(k), n, k));
    Ok((PyArray2::from_vec2(py, &rows(&xs))?, PyArray2::from_vec2(py, &rows(&vs))?, dx, dv, da))
}

/// The names of the spring's parameter tangents after the start quantities', in order.
#[pyfunction]
fn spring_sensitivity_params() -> Vec<&'static str> {
    SPRING_PARAMS.to_vec()
}

/// The names of the sensitivities' last axis, in order.
#[pyfunction]
fn sensitivity_params() -> Vec<&'static str> {
    PARAMS.to_vec()
}

pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(sensitivities, m)?)?;
    m.add_function(wrap_pyfunction!(sensitivity_params, m)?)?;
    m.add_function(wrap_pyfunction!(spring_sensitivities, m)?)?;
    m.add_function(wrap_pyfunction!(spring_sensitivity_params, m)?)
}
