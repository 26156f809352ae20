//! Binding of the swinging spring (`pendulab_core::elastic`, T-7.4). Conversions only; SI units.

use crate::convert::{arr3, to_py, InvalidInputError};
use crate::getters::pymethods_with_getters;
use crate::spec::{start, ModelSpec, RunOptions, StateArrays};
use numpy::ndarray::{Array1, Array2};
use numpy::{IntoPyArray, PyArray1, PyArray2, PyReadonlyArray1};
use pendulab_core::elastic::SpringStepper;
use pendulab_core::{SaveAt, State};
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// Integrates the spring (`ModelSpec.spring_model`: k/m [1/s²], l₀ [m], g [m/s²], m [kg]) from the
/// state (x0, v0) [m, m/s] for `n_steps` steps of the options' `dt` [s], keeping every `save_every`-th,
/// with Störmer–Verlet (`order` 2) or its triple jump (order 4); returns a dict of
/// t (n,), x, v (n, 3), energy [J], j3 [kg m²/s].
#[pyfunction]
pub fn spring_simulate<'py>(
    py: Python<'py>,
    spec: &ModelSpec,
    state: StateArrays<'py>,
    options: &RunOptions,
    n_steps: u64,
) -> PyResult<Bound<'py, PyDict>> {
    let sp = spec.spring()?;
    let (x, v) = start(&state)?;
    let SaveAt::Every(save_every) = options.save else {
        return Err(InvalidInputError::new_err(
            "spring_simulate saves every n-th step: give save_every, not save_times",
        ));
    };
    let (dt, order) = (options.solve.dt, options.order);
    let (t, states) =
        py.allow_threads(|| sp.simulate(State { x, v }, dt, n_steps, save_every, order)).map_err(to_py)?;
    let (x, v) = positions_and_velocities(&states);
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

/// An (n, 3) array of vectors.
type Rows<'py> = Bound<'py, PyArray2<f64>>;

/// The states x, v (n, 3) [m, m/s] after the step numbers `keep` (ascending) of the run of the spring
/// (`ModelSpec.spring_model`) from (x0, v0) with steps of the options' `dt` [s] of `order` 2 or 4:
/// `spring_simulate`'s states without keeping every step (a fit's forward model).
#[pyfunction]
pub fn spring_states_at<'py>(
    py: Python<'py>,
    spec: &ModelSpec,
    state: StateArrays<'py>,
    keep: PyReadonlyArray1<'py, u64>,
    options: &RunOptions,
) -> PyResult<(Rows<'py>, Rows<'py>)> {
    let sp = spec.spring()?;
    let (x, v) = start(&state)?;
    let keep: Vec<u64> = keep.as_array().iter().copied().collect();
    let (dt, order) = (options.solve.dt, options.order);
    let states = py.allow_threads(|| sp.states_at(State { x, v }, dt, order, &keep)).map_err(to_py)?;
    let (xs, vs) = positions_and_velocities(&states);
    Ok((xs.into_pyarray(py), vs.into_pyarray(py)))
}

/// The positions x [m] and velocities v [m/s] of `states` as two (n, 3) arrays.
fn positions_and_velocities(states: &[State]) -> (Array2<f64>, Array2<f64>) {
    let n = states.len();
    let (mut x, mut v) = (Array2::<f64>::zeros((n, 3)), Array2::<f64>::zeros((n, 3)));
    for (i, s) in states.iter().enumerate() {
        for k in 0..3 {
            x[[i, k]] = s.x[k];
            v[[i, k]] = s.v[k];
        }
    }
    (x, v)
}

/// The swinging spring stepped incrementally (the lab): the spring's spec, the start x0, v0 [m, m/s],
/// the options' t0 [s], step dt [s] and order 2 (Störmer–Verlet) or 4 (triple jump).
#[pyclass(module = "pendulab._core", name = "SpringStepper")]
struct SpringStepper_ {
    inner: SpringStepper,
}

pymethods_with_getters! {
    impl SpringStepper_ {
        #[new]
        fn new(spec: &ModelSpec, state: StateArrays<'_>, options: &RunOptions) -> PyResult<Self> {
            let sp = spec.spring()?;
            let (x, v) = start(&state)?;
            let o = options;
            Ok(Self { inner: SpringStepper::new(sp, State { x, v }, o.t0, o.solve.dt, o.order).map_err(to_py)? })
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
    m.add_function(wrap_pyfunction!(spring_states_at, m)?)?;
    m.add_class::<SpringStepper_>()
}
