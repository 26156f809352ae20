//! Binding of the swinging spring (`pendulab_core::elastic`, T-7.4). Conversions only; SI units.

use crate::convert::{arr3, to_py, vec3};
use crate::getters::pymethods_with_getters;
use numpy::ndarray::{Array1, Array2};
use numpy::{IntoPyArray, PyArray1, PyArray2, PyReadonlyArray1};
use pendulab_core::elastic::{SpringStepper, SwingingSpring};
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

/// The swinging spring stepped incrementally (the lab): k/m [1/s²], l₀ [m], g [m/s²], m [kg], the
/// start x0, v0 [m, m/s] at t0 [s], step dt [s], order 2 (Störmer–Verlet) or 4 (triple jump).
#[pyclass(module = "pendulab._core", name = "SpringStepper")]
struct SpringStepper_ {
    inner: SpringStepper,
}

pymethods_with_getters! {
    impl SpringStepper_ {
        #[new]
        #[pyo3(signature = (k_over_m, rest_length, g, mass, x0, v0, t0, dt, order=2))]
        #[allow(clippy::too_many_arguments)]
        fn new(
            k_over_m: f64,
            rest_length: f64,
            g: f64,
            mass: f64,
            x0: PyReadonlyArray1<'_, f64>,
            v0: PyReadonlyArray1<'_, f64>,
            t0: f64,
            dt: f64,
            order: u32,
        ) -> PyResult<Self> {
            let sp = SwingingSpring::new(k_over_m, rest_length, g, mass).map_err(to_py)?;
            let start = State { x: vec3("x0", &x0)?, v: vec3("v0", &v0)? };
            Ok(Self { inner: SpringStepper::new(sp, start, t0, dt, order).map_err(to_py)? })
        }

        /// Takes `n` steps of dt.
        #[pyo3(signature = (n=1))]
        fn step(&mut self, py: Python<'_>, n: u64) -> PyResult<()> {
            let inner = &mut self.inner;
            py.allow_threads(|| inner.step(n)).map_err(to_py)
        }


        /// Diagnostics of the current state: energy [J] (kinetic + elastic + gravity), j3 [kg m²/s],
        /// tension k(|r| − l₀) [N], acceleration r̈ (3,) [m/s²].
        fn diagnostics<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
            let (sp, s) = (self.inner.spring(), self.inner.state());
            let d = PyDict::new(py);
            d.set_item("energy", sp.energy(&s))?;
            d.set_item("j3", sp.j3(&s))?;
            d.set_item("tension", sp.tension(&s))?;
            d.set_item("acceleration", arr3(py, sp.acceleration(s.x)))?;
            Ok(d)
        }
    }
    getters(&self) {
        t = self.inner.t();
        x = self.inner.state().x;
        v = self.inner.state().v;
    }
}

/// Registers the function and the class.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(spring_simulate, m)?)?;
    m.add_class::<SpringStepper_>()
}
