//! Binding of the string pendulum (`pendulab_core::model::string`, `pendulab_core::string_run`): the hybrid run
//! (taut phases, leave and snap events, analytic free flight) as numpy arrays. Conversions only;
//! SI units.

use crate::convert::{arr3, stats_dict, to_py, InvalidInputError};
use crate::getters::pymethods_with_getters;
use crate::spec::{start, ModelSpec, RunOptions, StateArrays};
use numpy::ndarray::{Array1, Array2};
use numpy::{IntoPyArray, PyArray1};
use pendulab_core::string_run::{
    EventKind, StringEvent, StringRun, StringRunner, StringSettings, StringStepper,
};
use pendulab_core::{SaveAt, State};
use pyo3::prelude::*;
use pyo3::types::PyDict;

fn rows(states: impl ExactSizeIterator<Item = pendulab_core::DVec3>) -> Array2<f64> {
    let mut a = Array2::<f64>::zeros((states.len(), 3));
    for (i, v) in states.enumerate() {
        for k in 0..3 {
            a[[i, k]] = v[k];
        }
    }
    a
}

/// Simulates the string pendulum (the spec's `string` model: l [m], m [kg], g [m/s²], restitution
/// e ∈ [0, 1]) from the state (x0, v0) [m, m/s] at the options' t0 [s] to t_end [s] with their
/// `method` (rattle, rattle4, rattle6, rattle8, rkmk4), step dt [s] and `save_every`; returns a dict of t (n,), x, v (n, 3), taut (n,) bool, stats, and events: a dict of
/// arrays t (k,), kind (k,) str ("slack" or "taut"), x, v_before, v_after (k, 3), energy_lost (k,) [J].
#[pyfunction]
pub fn string_simulate<'py>(
    py: Python<'py>,
    spec: &ModelSpec,
    state: StateArrays<'py>,
    options: &RunOptions,
) -> PyResult<Bound<'py, PyDict>> {
    let sp = spec.string()?;
    let (x, v) = start(&state)?;
    let o = options;
    let SaveAt::Every(save_every) = o.save else {
        return Err(InvalidInputError::new_err(
            "string_simulate saves every n-th step: give save_every, not save_times",
        ));
    };
    let settings = StringSettings {
        save_every,
        max_saved_bytes: o.max_saved_bytes,
        ..StringSettings::new(o.solve.method, o.solve.dt)
    };
    let t_end = o.t_end()?;
    let run = py.allow_threads(|| sp.simulate(o.t0, State { x, v }, t_end, &settings)).map_err(to_py)?;
    run_dict(py, run)
}

/// A run's samples, events and stats as the dict of [`string_simulate`].
fn run_dict(py: Python<'_>, run: StringRun) -> PyResult<Bound<'_, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("t", Array1::from(run.t).into_pyarray(py))?;
    d.set_item("x", rows(run.states.iter().map(|s| s.x)).into_pyarray(py))?;
    d.set_item("v", rows(run.states.iter().map(|s| s.v)).into_pyarray(py))?;
    d.set_item("taut", Array1::from(run.taut).into_pyarray(py))?;
    let ev = PyDict::new(py);
    let kinds: Vec<&str> = run
        .events
        .iter()
        .map(|e| match e.kind {
            EventKind::Slack => "slack",
            EventKind::Taut => "taut",
        })
        .collect();
    ev.set_item("t", Array1::from_iter(run.events.iter().map(|e| e.t)).into_pyarray(py))?;
    ev.set_item("kind", kinds)?;
    ev.set_item("x", rows(run.events.iter().map(|e| e.after.x)).into_pyarray(py))?;
    ev.set_item("v_before", rows(run.events.iter().map(|e| e.before.v)).into_pyarray(py))?;
    ev.set_item("v_after", rows(run.events.iter().map(|e| e.after.v)).into_pyarray(py))?;
    ev.set_item("energy_lost", Array1::from_iter(run.events.iter().map(|e| e.energy_lost)).into_pyarray(py))?;
    d.set_item("events", ev)?;
    d.set_item("stats", stats_dict(py, run.stats)?)?;
    Ok(d)
}

/// A batch run of the string pendulum in chunks (`pl.simulate` drives it: progress bar, Ctrl-C):
/// the spec, state and options as for [`string_simulate`]; keeping every `save_every`-th grid point,
/// the events and t_end (default), or exactly the times `save_times` [s]. A run in chunks is `string_simulate`'s run
/// bit for bit.
#[pyclass(module = "pendulab._core", name = "StringRunner")]
struct StringRunner_ {
    inner: StringRunner,
}

pymethods_with_getters! {
    impl StringRunner_ {
        #[new]
        fn new(spec: &ModelSpec, state: StateArrays<'_>, options: &RunOptions) -> PyResult<Self> {
            let sp = spec.string()?;
            let (x, v) = start(&state)?;
            let o = options;
            let stepper = StringStepper::new(sp, o.t0, State { x, v }, o.solve.method, o.solve.dt).map_err(to_py)?;
            Ok(Self { inner: StringRunner::new(stepper, o.t_end()?, o.save.clone(), o.max_saved_bytes).map_err(to_py)? })
        }

        /// Advances by about `max_steps` grid steps (GIL released); True once t_end is reached.
        fn advance(&mut self, py: Python<'_>, max_steps: u64) -> PyResult<bool> {
            let inner = &mut self.inner;
            py.allow_threads(|| inner.advance(max_steps)).map_err(to_py)
        }

        /// The samples and events since the last call, as the dict of `string_simulate` (stats: so far).
        /// Until t_end the last sample is held back (an event at its time replaces it); `all`: included
        /// (for a run stopped early).
        #[pyo3(signature = (all=false))]
        fn take_samples<'py>(&mut self, py: Python<'py>, all: bool) -> PyResult<Bound<'py, PyDict>> {
            run_dict(py, if all { self.inner.take_all() } else { self.inner.take() })
        }
    }
    getters(&self) {
        progress = self.inner.progress();
        t = self.inner.stepper().t();
        t_end = self.inner.t_end();
        stats = self.inner.stepper().stats();
    }
}

/// The string pendulum stepped incrementally (the lab): the spec's `string` model, the start x0, v0
/// [m, m/s] (on the sphere or inside it: slack) at the options' t0 [s], their `method` (rattle,
/// rattle4, rattle6, rattle8, rkmk4) and step dt [s] of the taut phases. Its mode (taut, or slack on a
/// flight) is part of its state: stepping on continues the same hybrid run.
#[pyclass(module = "pendulab._core", name = "StringStepper")]
struct StringStepper_ {
    inner: StringStepper,
}

pymethods_with_getters! {
    impl StringStepper_ {
        #[new]
        fn new(spec: &ModelSpec, state: StateArrays<'_>, options: &RunOptions) -> PyResult<Self> {
            let sp = spec.string()?;
            let (x, v) = start(&state)?;
            let o = options;
            Ok(Self { inner: StringStepper::new(sp, o.t0, State { x, v }, o.solve.method, o.solve.dt).map_err(to_py)? })
        }

        /// Takes `n` steps of the grid t0 + k·dt (to the n-th grid point after the last one reached).
        #[pyo3(signature = (n=1))]
        fn step(&mut self, py: Python<'_>, n: u64) -> PyResult<()> {
            let inner = &mut self.inner;
            py.allow_threads(|| inner.step(n)).map_err(to_py)
        }

        /// True while the string is taut, false while slack (free flight).
        #[getter]
        fn taut(&self) -> bool {
            self.inner.is_taut()
        }

        /// Diagnostics of the current state: energy [J], j3 [kg m²/s], tension [N] (T-2.3 while taut, 0
        /// while slack), acceleration ẍ (3,) [m/s²], taut.
        fn diagnostics<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
            let (m, s) = (self.inner.model(), self.inner.state());
            let d = PyDict::new(py);
            d.set_item("energy", pendulab_core::model::energy(m, &s))?;
            d.set_item("j3", pendulab_core::model::j3(m, &s))?;
            d.set_item("tension", self.inner.tension())?;
            d.set_item("acceleration", arr3(py, self.inner.acceleration()))?;
            d.set_item("taut", self.inner.is_taut())?;
            Ok(d)
        }

        /// The events since the last call: a list of dicts t [s], kind ("slack" or "taut"), x [m],
        /// v_before, v_after [m/s], energy_lost [J].
        fn take_events<'py>(&mut self, py: Python<'py>) -> PyResult<Vec<Bound<'py, PyDict>>> {
            self.inner.take_events().iter().map(|e| event_dict(py, e)).collect()
        }
    }
    getters(&self) {
        t = self.inner.t();
        x = self.inner.state().x;
        v = self.inner.state().v;
    }
}

fn event_dict<'py>(py: Python<'py>, e: &StringEvent) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("t", e.t)?;
    d.set_item(
        "kind",
        match e.kind {
            EventKind::Slack => "slack",
            EventKind::Taut => "taut",
        },
    )?;
    for (key, v) in [("x", e.after.x), ("v_before", e.before.v), ("v_after", e.after.v)] {
        let a: Bound<'py, PyArray1<f64>> = arr3(py, v);
        d.set_item(key, a)?;
    }
    d.set_item("energy_lost", e.energy_lost)?;
    Ok(d)
}

/// Registers the function and the classes.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(string_simulate, m)?)?;
    m.add_class::<StringStepper_>()?;
    m.add_class::<StringRunner_>()
}
