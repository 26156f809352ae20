//! Binding of the ensemble kernel (`pendulab_core::ensemble`): the run goes on a background thread
//! so that Python can show progress and cancel (Ctrl-C) while it works. Conversions only; SI units.

use crate::convert::{to_py, InvalidInputError};
use numpy::ndarray::{Array1, Array3};
use numpy::{IntoPyArray, PyArray1, PyArray3, PyReadonlyArray1, PyReadonlyArray2};
use pendulab_core::ensemble::{check, run_with, EnsembleResult, EnsembleSave, Extras};
use pendulab_core::{DVec3, Result as CoreResult, State};
use pyo3::exceptions::PyRuntimeError;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::{Arc, Condvar, Mutex};
use std::thread::JoinHandle;
use std::time::Duration;

/// Set (and waiters woken) when the run's thread ends, also if it panics: [`EnsembleRun::wait`]
/// returns the moment the run is done instead of at the next poll.
#[derive(Default)]
pub(crate) struct Finished {
    pub(crate) done: Mutex<bool>,
    pub(crate) changed: Condvar,
}

/// Marks the run finished when dropped, i.e. when the thread's closure returns or unwinds.
pub(crate) struct FinishOnDrop(pub(crate) Arc<Finished>);

impl Drop for FinishOnDrop {
    fn drop(&mut self) {
        *self.0.done.lock().unwrap_or_else(|e| e.into_inner()) = true;
        self.0.changed.notify_all();
    }
}

/// An ensemble run in progress (RATTLE; ideal pendulum with optional linear damping; per-trajectory
/// l, g and damping c).
#[pyclass(module = "pendulab._core", name = "EnsembleRun")]
pub struct EnsembleRun {
    progress: Arc<AtomicU64>,
    cancel: Arc<AtomicBool>,
    total: u64,
    finished: Arc<Finished>,
    handle: Option<JoinHandle<CoreResult<EnsembleResult>>>,
}

#[pymethods]
impl EnsembleRun {
    /// Starts `n_steps` steps of `dt` [s] from x, v (N, 3) [m, m/s] with length and g arrays of
    /// length 1 or N; saves every `save_every` steps (None: final only); `summary`: extremes of z,
    /// E/m and J₃/m per trajectory; `damping`: c [1/s] (length 0, 1 or N); `settle_angle` [rad]:
    /// track each trajectory's settle time.
    #[new]
    #[pyo3(signature = (x, v, length, g, dt, n_steps, save_every=None, summary=true, damping=None, settle_angle=None))]
    #[allow(clippy::too_many_arguments)]
    fn new(
        x: PyReadonlyArray2<'_, f64>,
        v: PyReadonlyArray2<'_, f64>,
        length: PyReadonlyArray1<'_, f64>,
        g: PyReadonlyArray1<'_, f64>,
        dt: f64,
        n_steps: u64,
        save_every: Option<u64>,
        summary: bool,
        damping: Option<PyReadonlyArray1<'_, f64>>,
        settle_angle: Option<f64>,
    ) -> PyResult<Self> {
        let (xa, va) = (x.as_array(), v.as_array());
        if xa.ncols() != 3 || va.dim() != xa.dim() || xa.nrows() == 0 {
            return Err(InvalidInputError::new_err(format!(
                "x and v must both have shape (N, 3) with N >= 1, got {:?} and {:?}",
                xa.dim(),
                va.dim()
            )));
        }
        let starts: Vec<State> = (0..xa.nrows())
            .map(|i| State {
                x: DVec3::new(xa[[i, 0]], xa[[i, 1]], xa[[i, 2]]),
                v: DVec3::new(va[[i, 0]], va[[i, 1]], va[[i, 2]]),
            })
            .collect();
        let (length, g) = (length.as_array().to_vec(), g.as_array().to_vec());
        let damping: Vec<f64> = damping.map_or_else(Vec::new, |d| d.as_array().to_vec());
        let save = save_every.map_or(EnsembleSave::Final, EnsembleSave::Every);
        let progress = Arc::new(AtomicU64::new(0));
        let cancel = Arc::new(AtomicBool::new(false));
        let total = n_steps.saturating_mul(starts.len() as u64);
        // Validate before starting the thread, so bad input raises here and not later.
        let extras = Extras { damping: &damping, settle_angle };
        check(&starts, &length, &g, &extras, dt, n_steps, save).map_err(to_py)?;
        let (p, c) = (progress.clone(), cancel.clone());
        let finished = Arc::new(Finished::default());
        let on_exit = FinishOnDrop(finished.clone());
        let handle = std::thread::spawn(move || {
            let _on_exit = on_exit;
            let extras = Extras { damping: &damping, settle_angle };
            run_with(&starts, &length, &g, &extras, dt, n_steps, save, summary, &p, &c)
        });
        Ok(Self { progress, cancel, total, finished, handle: Some(handle) })
    }

    /// Fraction of trajectory-steps done.
    #[getter]
    fn progress(&self) -> f64 {
        if self.total == 0 {
            1.0
        } else {
            self.progress.load(Ordering::Relaxed) as f64 / self.total as f64
        }
    }

    /// True when the run has finished (or stopped after a cancel).
    #[getter]
    fn done(&self) -> bool {
        self.handle.is_none() || *self.finished.done.lock().unwrap_or_else(|e| e.into_inner())
    }

    /// Waits until the run has finished or `timeout` [s] (≥ 0, finite) has passed, with the GIL
    /// released; returns `done`. Returns at once when the run ends, so a progress loop
    /// `while not run.wait(0.05)` costs a finished run no poll interval.
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

    /// Asks every block to stop at its next check (within 1024 steps).
    fn cancel(&self) {
        self.cancel.store(true, Ordering::Relaxed);
    }

    /// Waits for the run and returns a dict: t (n_save,), x, v (N, n_save, 3), cancelled, steps and,
    /// with a summary, z_min, z_max, e_min, e_max (per unit mass, J/kg), j3_min, j3_max (m²/s),
    /// crossings (of the pivot's horizontal plane, a count as float64); with a
    /// settle angle, settle_time [s] (0: never outside, inf: outside at the end).
    fn result<'py>(&mut self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let handle =
            self.handle.take().ok_or_else(|| PyRuntimeError::new_err("the result was already taken"))?;
        let res = py
            .allow_threads(|| handle.join())
            .map_err(|_| PyRuntimeError::new_err("the ensemble thread panicked"))?
            .map_err(to_py)?;
        let (n, ns) = (res.len(), res.t.len());
        let (x, v) = py.allow_threads(|| {
            let x = Array3::from_shape_fn((n, ns, 3), |(i, j, k)| res.states[i * ns + j].x[k]);
            let v = Array3::from_shape_fn((n, ns, 3), |(i, j, k)| res.states[i * ns + j].v[k]);
            (x, v)
        });
        let d = PyDict::new(py);
        d.set_item("t", Array1::from(res.t).into_pyarray(py))?;
        let (xs, vs): (Bound<'py, PyArray3<f64>>, Bound<'py, PyArray3<f64>>) =
            (x.into_pyarray(py), v.into_pyarray(py));
        d.set_item("x", xs)?;
        d.set_item("v", vs)?;
        d.set_item("cancelled", res.cancelled)?;
        d.set_item("steps", res.steps)?;
        if let Some(ts) = res.settle_time {
            d.set_item("settle_time", Array1::from(ts).into_pyarray(py))?;
        }
        if let Some(s) = res.summary {
            let col = |f: &dyn Fn(&pendulab_core::ensemble::Summary) -> f64| -> Bound<'py, PyArray1<f64>> {
                Array1::from(s.iter().map(f).collect::<Vec<_>>()).into_pyarray(py)
            };
            d.set_item("z_min", col(&|q| q.z.0))?;
            d.set_item("z_max", col(&|q| q.z.1))?;
            d.set_item("e_min", col(&|q| q.energy_per_mass.0))?;
            d.set_item("e_max", col(&|q| q.energy_per_mass.1))?;
            d.set_item("j3_min", col(&|q| q.j3_per_mass.0))?;
            d.set_item("j3_max", col(&|q| q.j3_per_mass.1))?;
            d.set_item("crossings", col(&|q| q.crossings as f64))?;
        }
        Ok(d)
    }
}

impl Drop for EnsembleRun {
    fn drop(&mut self) {
        // Never leave a thread running behind a dropped handle.
        self.cancel.store(true, Ordering::Relaxed);
        if let Some(h) = self.handle.take() {
            let _ = h.join();
        }
    }
}

/// Registers the class.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<EnsembleRun>()
}
