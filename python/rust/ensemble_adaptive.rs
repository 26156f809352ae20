//! Binding of the adaptive ensemble (`pendulab_core::ensemble::adaptive`): any rod model of the
//! registry, one model for all trajectories or one per trajectory (a list of specs and an index),
//! DOP853 with each trajectory's own step size (vectorised across trajectories when only t0 and t_end
//! are saved), run on a background thread like `EnsembleRun` so that Python can show progress and
//! cancel. Conversions only; SI units.

use crate::background::Background;
use crate::convert::{to_py, InvalidInputError};
use crate::ensemble::{position_velocity_rows, starts};
use crate::spec::{ModelSpec, RunOptions};
use numpy::ndarray::Array3;
use numpy::{IntoPyArray, PyReadonlyArray1, PyReadonlyArray2};
use pendulab_core::ensemble::adaptive::{
    check_adaptive, run_adaptive_any, AdaptiveResult, AdaptiveSettings, Models,
};
use pendulab_core::solve::BYTES_PER_SAMPLE;
use pendulab_core::SaveAt;
use pyo3::exceptions::PyRuntimeError;
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// An adaptive ensemble run in progress.
#[pyclass(module = "pendulab._core", name = "AdaptiveEnsembleRun")]
pub struct AdaptiveEnsembleRun {
    total: u64,
    run: Background<AdaptiveArrays>,
}

/// A run's result laid out as `AdaptiveEnsembleRun.result` hands it to numpy: x, v (N, n_times, 3) in
/// C order, made on the worker that ran it (as `EnsembleRun`'s, `ensemble.rs`), so that the caller
/// holds the GIL only to wrap them.
struct AdaptiveArrays {
    x: Vec<f64>,
    v: Vec<f64>,
    shape: (usize, usize, usize),
    steps: Vec<u64>,
    cancelled: bool,
}

impl AdaptiveArrays {
    /// `res` in numpy's layout: trajectory i's sample j is `states[i * n_times + j]`, the rows of
    /// (N, n_times, 3) in order.
    fn of(res: AdaptiveResult, n_times: usize) -> Self {
        let n = res.states.len() / n_times.max(1);
        let (x, v) = position_velocity_rows(&res.states);
        Self { x, v, shape: (n, n_times, 3), steps: res.steps, cancelled: res.cancelled }
    }
}

#[pymethods]
impl AdaptiveEnsembleRun {
    /// Starts every row of x, v (N, 3) [m, m/s] with the model `spec` and `options` (t0, t_end [s],
    /// method, rtol, atol, project, conserve; `save_times` [s]: the times every trajectory is saved at).
    /// Per-trajectory models: `models` (a list of specs, used instead of `spec`) and `index` (N,), the
    /// entry of `models` each trajectory runs.
    #[new]
    #[pyo3(signature = (spec, x, v, options, models=None, index=None))]
    fn new(
        py: Python<'_>,
        spec: &ModelSpec,
        x: PyReadonlyArray2<'_, f64>,
        v: PyReadonlyArray2<'_, f64>,
        options: &RunOptions,
        models: Option<Vec<PyRef<'_, ModelSpec>>>,
        index: Option<PyReadonlyArray1<'_, i64>>,
    ) -> PyResult<Self> {
        let starts = starts(&x, &v)?;
        let SaveAt::Times(times) = options.save.clone() else {
            return Err(InvalidInputError::new_err(
                "an adaptive ensemble saves every trajectory at the same times: give save_times [s]",
            ));
        };
        // the saved states are allocated up front: bounded like a single run's samples
        let need = (starts.len() as u64).saturating_mul(times.len() as u64).saturating_mul(BYTES_PER_SAMPLE);
        if need > options.max_saved_bytes {
            return Err(InvalidInputError::new_err(format!(
                "{} trajectories × {} save times need {:.3} GiB, more than max_saved_bytes = {} B: save \
                 fewer times or run fewer trajectories at once",
                starts.len(),
                times.len(),
                need as f64 / (1u64 << 30) as f64,
                options.max_saved_bytes
            )));
        }
        let models: Vec<_> = match &models {
            Some(ms) if !ms.is_empty() => ms.iter().map(|m| m.registry()).collect::<PyResult<_>>()?,
            Some(_) => return Err(InvalidInputError::new_err("models must name at least one ModelSpec")),
            None => vec![spec.registry()?],
        };
        let index = model_index(index, starts.len(), models.len())?;
        let settings = AdaptiveSettings {
            options: options.solve,
            t0: options.t0,
            t_end: options.t_end()?,
            times,
            conserve: options.conserve,
        };
        // validate before starting the thread (settings and every start), so bad input raises here;
        // the GIL released while every start is checked
        py.allow_threads(|| check_adaptive(&Models { models: &models, index: &index }, &starts, &settings))
            .map_err(to_py)?;
        let (total, n_times) = (starts.len() as u64, settings.times.len());
        let run = Background::spawn(move |progress, cancel| {
            let models = Models { models: &models, index: &index };
            run_adaptive_any(&models, &starts, &settings, progress, cancel)
                .map(|r| AdaptiveArrays::of(r, n_times))
        });
        Ok(Self { total, run })
    }

    /// Fraction of trajectories finished.
    #[getter]
    fn progress(&self) -> f64 {
        self.run.counted() as f64 / self.total.max(1) as f64
    }

    /// Waits until the run has finished or `timeout` [s] (≥ 0, finite) has passed, with the GIL
    /// released; returns whether it has finished.
    fn wait(&self, py: Python<'_>, timeout: f64) -> PyResult<bool> {
        self.run.wait(py, timeout)
    }

    /// Asks every trajectory to stop within 4096 of its steps.
    fn cancel(&self) {
        self.run.cancel();
    }

    /// Waits for the run and returns a dict: x, v (N, n_times, 3) [m, m/s] (NaN where a cancelled
    /// trajectory did not get to), steps (N,) accepted steps, cancelled.
    fn result<'py>(&mut self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let res = self.run.join(py)?;
        // numpy takes the arrays as they are (no copy)
        let bad_shape = |e: numpy::ndarray::ShapeError| PyRuntimeError::new_err(e.to_string());
        let x = Array3::from_shape_vec(res.shape, res.x).map_err(bad_shape)?;
        let v = Array3::from_shape_vec(res.shape, res.v).map_err(bad_shape)?;
        let d = PyDict::new(py);
        d.set_item("x", x.into_pyarray(py))?;
        d.set_item("v", v.into_pyarray(py))?;
        d.set_item("steps", res.steps.into_pyarray(py))?;
        d.set_item("cancelled", res.cancelled)?;
        Ok(d)
    }
}

/// The checked per-trajectory index into `n_models` models (empty: the first model for all).
fn model_index(index: Option<PyReadonlyArray1<'_, i64>>, n: usize, n_models: usize) -> PyResult<Vec<u32>> {
    let Some(ix) = index else { return Ok(Vec::new()) };
    let ix = ix.as_array();
    if ix.len() != n {
        return Err(InvalidInputError::new_err(format!(
            "index must give one model per trajectory ({n}), got {}",
            ix.len()
        )));
    }
    if let Some(bad) = ix.iter().find(|&&i| i < 0 || i as usize >= n_models) {
        return Err(InvalidInputError::new_err(format!(
            "index = {bad}: must be an entry of models, 0 … {}",
            n_models - 1
        )));
    }
    Ok(ix.iter().map(|&i| i as u32).collect())
}

/// Registers the class.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<AdaptiveEnsembleRun>()
}
