//! Binding of the swinging spring (`pendulab_core::elastic`, T-7.4). Conversions only; SI units.

use crate::{to_py, vec3};
use numpy::ndarray::{Array1, Array2};
use numpy::{IntoPyArray, PyArray1, PyArray2, PyReadonlyArray1};
use pendulab_core::elastic::SwingingSpring;
use pendulab_core::State;
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// Integrates the spring (k/m [1/s²], l₀ [m], g [m/s²], m [kg]) from x0, v0 [m, m/s] for `n_steps`
/// steps of `dt` [s] with Störmer–Verlet (order 2) or its triple jump (order 4); returns a dict of
/// t (n,), x, v (n, 3), energy [J], j3 [kg m²/s].
#[pyfunction]
#[pyo3(signature = (k_over_m, rest_length, g, mass, x0, v0, dt, n_steps, save_every=1, order=2))]
#[allow(clippy::too_many_arguments)]
pub fn spring_simulate<'py>(
    py: Python<'py>,
    k_over_m: f64,
    rest_length: f64,
    g: f64,
    mass: f64,
    x0: PyReadonlyArray1<'py, f64>,
    v0: PyReadonlyArray1<'py, f64>,
    dt: f64,
    n_steps: u64,
    save_every: u64,
    order: u32,
) -> PyResult<Bound<'py, PyDict>> {
    let sp = SwingingSpring::new(k_over_m, rest_length, g, mass).map_err(to_py)?;
    let start = State { x: vec3("x0", &x0)?, v: vec3("v0", &v0)? };
    let (t, states) =
        py.allow_threads(|| sp.simulate(start, dt, n_steps, save_every, order)).map_err(to_py)?;
    let n = states.len();
    let (mut x, mut v) = (Array2::<f64>::zeros((n, 3)), Array2::<f64>::zeros((n, 3)));
    for (i, s) in states.iter().enumerate() {
        for k in 0..3 {
            x[[i, k]] = s.x[k];
            v[[i, k]] = s.v[k];
        }
    }
    let e: Vec<f64> = states.iter().map(|s| sp.energy(s)).collect();
    let j: Vec<f64> = states.iter().map(|s| sp.j3(s)).collect();
    let d = PyDict::new(py);
    d.set_item("t", Array1::from(t).into_pyarray(py))?;
    let (xs, vs): (Bound<'py, PyArray2<f64>>, Bound<'py, PyArray2<f64>>) =
        (x.into_pyarray(py), v.into_pyarray(py));
    d.set_item("x", xs)?;
    d.set_item("v", vs)?;
    let (es, js): (Bound<'py, PyArray1<f64>>, Bound<'py, PyArray1<f64>>) =
        (Array1::from(e).into_pyarray(py), Array1::from(j).into_pyarray(py));
    d.set_item("energy", es)?;
    d.set_item("j3", js)?;
    d.set_item("equilibrium_length", sp.equilibrium_length())?;
    Ok(d)
}

/// Registers the function.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(spring_simulate, m)?)
}
