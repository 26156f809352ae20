//! Binding of the adaptive ensemble (`pendulab_core::ensemble::adaptive`): any rod model of the
//! registry, one `Solver` per trajectory (DOP853 by default), run on a background thread like
//! `EnsembleRun` so that Python can show progress and cancel. Conversions only; SI units.

use crate::convert::{to_py, InvalidInputError};
use crate::ensemble::{FinishOnDrop, Finished};
use crate::spec::{ModelSpec, RunOptions};
use numpy::ndarray::Array3;
use numpy::{IntoPyArray, PyReadonlyArray2};
use pendulab_core::ensemble::adaptive::{run_adaptive, AdaptiveResult, AdaptiveSettings};
use pendulab_core::solve::BYTES_PER_SAMPLE;
use pendulab_core::{DVec3, Result as CoreResult, SaveAt, State};
use pyo3::exceptions::PyRuntimeError;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::Arc;
use std::thread::JoinHandle;
use std::time::Duration;

/// An adaptive ensemble run in progress.
#[pyclass(module = "pendulab._core", name = "AdaptiveEnsembleRun")]
pub struct AdaptiveEnsembleRun {
    progress: Arc<AtomicU64>,
    cancel: Arc<AtomicBool>,
    total: u64,
    n_times: usize,
    finished: Arc<Finished>,
    handle: Option<JoinHandle<CoreResult<AdaptiveResult>>>,
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
        let (xa, va) = (x.as_array(), v.as_array());
        if xa.ncols() != 3 || va.dim() != xa.dim() || xa.nrows() == 0 {
            return Err(InvalidInputError::new_err(format!(
                "x and v must both have shape (N, 3) with N >= 1, got {:?} and {:?}",
                xa.dim(),
                va.dim()
            )));
        }
        let SaveAt::Times(times) = options.save.clone() else {
            return Err(InvalidInputError::new_err(
                "an adaptive ensemble saves every trajectory at the same times: give save_times [s]",
            ));
        };
        // the saved states are allocated up front: bounded like a single run's samples
        let need = (xa.nrows() as u64).saturating_mul(times.len() as u64).saturating_mul(BYTES_PER_SAMPLE);
        if need > options.max_saved_bytes {
            return Err(InvalidInputError::new_err(format!(
                "{} trajectories × {} save times need {:.3} GiB, more than max_saved_bytes = {} B: save \
                 fewer times or run fewer trajectories at once",
                xa.nrows(),
                times.len(),
                need as f64 / (1u64 << 30) as f64,
                options.max_saved_bytes
            )));
        }
        let model = spec.registry()?;
        let starts: Vec<State> = (0..xa.nrows())
            .map(|i| State {
                x: DVec3::new(xa[[i, 0]], xa[[i, 1]], xa[[i, 2]]),
                v: DVec3::new(va[[i, 0]], va[[i, 1]], va[[i, 2]]),
            })
            .collect();
        let settings = AdaptiveSettings {
            options: options.solve,
            t0: options.t0,
            t_end: options.t_end()?,
            times,
            conserve: options.conserve,
        };
        let (progress, cancel) = (Arc::new(AtomicU64::new(0)), Arc::new(AtomicBool::new(false)));
        // validate before starting the thread (settings and every start), so bad input raises here
        let stop = AtomicBool::new(true);
        run_adaptive(&model, &starts, &settings, &AtomicU64::new(0), &stop).map_err(to_py)?;
        let (total, n_times) = (starts.len() as u64, settings.times.len());
        let (p, c) = (progress.clone(), cancel.clone());
        let finished = Arc::new(Finished::default());
        let on_exit = FinishOnDrop(finished.clone());
        let handle = std::thread::spawn(move || {
            let _on_exit = on_exit;
            run_adaptive(&model, &starts, &settings, &p, &c)
        });
        Ok(Self { progress, cancel, total, n_times, finished, handle: Some(handle) })
    }

    /// Fraction of trajectories finished.
    #[getter]
    fn progress(&self) -> f64 {
        self.progress.load(Ordering::Relaxed) as f64 / self.total.max(1) as f64
    }

    /// Waits until the run has finished or `timeout` [s] (≥ 0, finite) has passed, with the GIL
    /// released; returns whether it has finished.
    fn wait(&self, py: Python<'_>, timeout: f64) -> PyResult<bool> {
        if !(timeout.is_finite() && timeout >= 0.0) {
            return Err(InvalidInputError::new_err(format!(
                "timeout = {timeout}: must be a finite number of seconds >= 0"
            )));
        }
        if self.handle.is_none() {
            return Ok(true);
        }
        let finished = &self.finished;
        Ok(py.allow_threads(|| {
            let done = finished.done.lock().unwrap_or_else(|e| e.into_inner());
            let (done, _) = finished
                .changed
                .wait_timeout_while(done, Duration::from_secs_f64(timeout.min(3600.0)), |d| !*d)
                .unwrap_or_else(|e| e.into_inner());
            *done
        }))
    }

    /// Asks every trajectory to stop within 4096 of its steps.
    fn cancel(&self) {
        self.cancel.store(true, Ordering::Relaxed);
    }

    /// Waits for the run and returns a dict: x, v (N, n_times, 3) [m, m/s] (NaN where a cancelled
    /// trajectory did not get to), steps (N,) accepted steps, cancelled.
    fn result<'py>(&mut self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let handle =
            self.handle.take().ok_or_else(|| PyRuntimeError::new_err("the result was already taken"))?;
        let res = py
            .allow_threads(|| handle.join())
            .map_err(|_| PyRuntimeError::new_err("the ensemble thread panicked"))?
            .map_err(to_py)?;
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

impl Drop for AdaptiveEnsembleRun {
    fn drop(&mut self) {
        // never leave a thread running behind a dropped handle
        self.cancel.store(true, Ordering::Relaxed);
        if let Some(h) = self.handle.take() {
            let _ = h.join();
        }
    }
}

/// Registers the class.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<AdaptiveEnsembleRun>()
}
