//! Binding of the adaptive ensemble (`pendulab_core::ensemble::adaptive`): any rod model of the
//! registry, one `Solver` per trajectory (DOP853 by default), run on a background thread like
//! `EnsembleRun` so that Python can show progress and cancel. Conversions only; SI units.

use crate::background::Background;
use crate::convert::{to_py, InvalidInputError};
use crate::ensemble::starts;
use crate::spec::{ModelSpec, RunOptions};
use numpy::ndarray::Array3;
use numpy::{IntoPyArray, PyReadonlyArray2};
use pendulab_core::ensemble::adaptive::{run_adaptive, AdaptiveResult, AdaptiveSettings};
use pendulab_core::solve::BYTES_PER_SAMPLE;
use pendulab_core::SaveAt;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::sync::atomic::{AtomicBool, AtomicU64};

/// An adaptive ensemble run in progress.
#[pyclass(module = "pendulab._core", name = "AdaptiveEnsembleRun")]
pub struct AdaptiveEnsembleRun {
    total: u64,
    n_times: usize,
    run: Background<AdaptiveResult>,
}

#[pymethods]
impl AdaptiveEnsembleRun {
    /// Starts every row of x, v (N, 3) [m, m/s] with the model `spec` and `options` (t0, t_end [s],
    /// method, rtol, atol, project, conserve; `save_times` [s]: the times every trajectory is saved at).
    #[new]
    fn new(
        spec: &ModelSpec,
        x: PyReadonlyArray2<'_, f64>,
        v: PyReadonlyArray2<'_, f64>,
        options: &RunOptions,
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
        let model = spec.registry()?;
        let settings = AdaptiveSettings {
            options: options.solve,
            t0: options.t0,
            t_end: options.t_end()?,
            times,
            conserve: options.conserve,
        };
        // validate before starting the thread (settings and every start), so bad input raises here
        let stop = AtomicBool::new(true);
        run_adaptive(&model, &starts, &settings, &AtomicU64::new(0), &stop).map_err(to_py)?;
        let (total, n_times) = (starts.len() as u64, settings.times.len());
        let run = Background::spawn(move |progress, cancel| {
            run_adaptive(&model, &starts, &settings, progress, cancel)
        });
        Ok(Self { total, n_times, run })
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
        let ns = self.n_times;
        let n = res.states.len() / ns.max(1);
        let x = Array3::from_shape_fn((n, ns, 3), |(i, j, k)| res.states[i * ns + j].x[k]);
        let v = Array3::from_shape_fn((n, ns, 3), |(i, j, k)| res.states[i * ns + j].v[k]);
        let d = PyDict::new(py);
        d.set_item("x", x.into_pyarray(py))?;
        d.set_item("v", v.into_pyarray(py))?;
        d.set_item("steps", res.steps.into_pyarray(py))?;
        d.set_item("cancelled", res.cancelled)?;
        Ok(d)
    }
}

/// Registers the class.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<AdaptiveEnsembleRun>()
}
