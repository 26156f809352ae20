//! A core run in the background, written once for the ensemble classes (`EnsembleRun`,
//! `AdaptiveEnsembleRun`): Python shows progress and cancels (Ctrl-C) while it works. The run is
//! handed to rayon's pool (`rayon::spawn`: its threads exist already, so a short run pays no thread
//! start, and the run's own parallel loops start on a pool thread, both cores at once). It counts its
//! work into `progress` and stops at its next check once `cancel` is set; `wait` returns the moment
//! it ends (also if it panics: the panic is caught and reported as `RuntimeError`), with the GIL
//! released. Times in seconds. No physics.

use crate::convert::{to_py, InvalidInputError};
use pendulab_core::Result as CoreResult;
use pyo3::exceptions::PyRuntimeError;
use pyo3::prelude::*;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::{Arc, Condvar, Mutex, MutexGuard};
use std::time::Duration;

/// The run's outcome once it has ended: its result, or `Err` if it panicked.
type Outcome<R> = std::thread::Result<CoreResult<R>>;

/// Filled (and waiters woken) when the run ends, also if it panics.
struct Finished<R> {
    outcome: Mutex<Option<Outcome<R>>>,
    changed: Condvar,
}

impl<R> Finished<R> {
    fn lock(&self) -> MutexGuard<'_, Option<Outcome<R>>> {
        self.outcome.lock().unwrap_or_else(|e| e.into_inner())
    }

    /// Waits up to `timeout` for the outcome; the guard holds it if the run has ended.
    fn wait(&self, timeout: Duration) -> MutexGuard<'_, Option<Outcome<R>>> {
        let guard = self.lock();
        self.changed.wait_timeout_while(guard, timeout, |o| o.is_none()).unwrap_or_else(|e| e.into_inner()).0
    }
}

/// A run of the core producing `R` on rayon's pool, with its progress counter and cancel flag.
pub(crate) struct Background<R: Send + 'static> {
    progress: Arc<AtomicU64>,
    cancel: Arc<AtomicBool>,
    finished: Arc<Finished<R>>,
    taken: bool,
}

impl<R: Send + 'static> Background<R> {
    /// Starts `work(progress, cancel)` on rayon's pool.
    pub(crate) fn spawn<F>(work: F) -> Self
    where
        F: FnOnce(&AtomicU64, &AtomicBool) -> CoreResult<R> + Send + 'static,
    {
        let (progress, cancel) = (Arc::new(AtomicU64::new(0)), Arc::new(AtomicBool::new(false)));
        let finished = Arc::new(Finished { outcome: Mutex::new(None), changed: Condvar::new() });
        let (p, c, f) = (progress.clone(), cancel.clone(), finished.clone());
        rayon::spawn(move || {
            // a panic stays here (rayon would abort the process): it is the run's outcome
            let outcome = catch_unwind(AssertUnwindSafe(|| work(&p, &c)));
            *f.lock() = Some(outcome);
            f.changed.notify_all();
        });
        Self { progress, cancel, finished, taken: false }
    }

    /// The work counted so far (the unit is the run's: trajectory-steps, trajectories).
    pub(crate) fn counted(&self) -> u64 {
        self.progress.load(Ordering::Relaxed)
    }

    /// True when the run has finished (or stopped after a cancel), or its result was taken.
    pub(crate) fn done(&self) -> bool {
        self.taken || self.finished.lock().is_some()
    }

    /// Waits until the run has finished or `timeout` [s] (≥ 0, finite; at most an hour) has passed,
    /// with the GIL released; returns `done`.
    pub(crate) fn wait(&self, py: Python<'_>, timeout: f64) -> PyResult<bool> {
        if !(timeout.is_finite() && timeout >= 0.0) {
            return Err(InvalidInputError::new_err(format!(
                "timeout = {timeout}: must be a finite number of seconds >= 0"
            )));
        }
        if self.taken {
            return Ok(true);
        }
        let finished = &self.finished;
        Ok(py.allow_threads(|| finished.wait(Duration::from_secs_f64(timeout.min(3600.0))).is_some()))
    }

    /// Asks the run to stop at its next check.
    pub(crate) fn cancel(&self) {
        self.cancel.store(true, Ordering::Relaxed);
    }

    /// Waits for the run (GIL released) and takes its result: a core error as its Python exception,
    /// a second call or a panicked run as `RuntimeError`.
    pub(crate) fn join(&mut self, py: Python<'_>) -> PyResult<R> {
        if self.taken {
            return Err(PyRuntimeError::new_err("the result was already taken"));
        }
        self.taken = true;
        let finished = &self.finished;
        let outcome = py.allow_threads(|| loop {
            if let Some(o) = finished.wait(Duration::from_secs(3600)).take() {
                break o;
            }
        });
        outcome.map_err(|_| PyRuntimeError::new_err("the ensemble thread panicked"))?.map_err(to_py)
    }
}

impl<R: Send + 'static> Drop for Background<R> {
    fn drop(&mut self) {
        // never leave a run working behind a dropped handle
        self.cancel.store(true, Ordering::Relaxed);
        if !self.taken {
            while self.finished.wait(Duration::from_secs(3600)).is_none() {}
        }
    }
}
