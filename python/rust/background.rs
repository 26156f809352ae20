//! A core run on a background thread, written once for the ensemble classes (`EnsembleRun`,
//! `AdaptiveEnsembleRun`): Python shows progress and cancels (Ctrl-C) while it works. The thread
//! counts its work into `progress` and stops at its next check once `cancel` is set; `wait`
//! returns the moment the thread ends (also if it panics), with the GIL released. Times in seconds.
//! No physics.

use crate::convert::{to_py, InvalidInputError};
use pendulab_core::Result as CoreResult;
use pyo3::exceptions::PyRuntimeError;
use pyo3::prelude::*;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::{Arc, Condvar, Mutex};
use std::thread::JoinHandle;
use std::time::Duration;

/// Set (and waiters woken) when the run's thread ends, also if it panics.
#[derive(Default)]
struct Finished {
    done: Mutex<bool>,
    changed: Condvar,
}

/// Marks the run finished when dropped, i.e. when the thread's closure returns or unwinds.
struct FinishOnDrop(Arc<Finished>);

impl Drop for FinishOnDrop {
    fn drop(&mut self) {
        *self.0.done.lock().unwrap_or_else(|e| e.into_inner()) = true;
        self.0.changed.notify_all();
    }
}

/// A run of the core producing `R` on its own thread, with its progress counter and cancel flag.
pub(crate) struct Background<R: Send + 'static> {
    progress: Arc<AtomicU64>,
    cancel: Arc<AtomicBool>,
    finished: Arc<Finished>,
    handle: Option<JoinHandle<CoreResult<R>>>,
}

impl<R: Send + 'static> Background<R> {
    /// Starts `work(progress, cancel)` on a new thread.
    pub(crate) fn spawn<F>(work: F) -> Self
    where
        F: FnOnce(&AtomicU64, &AtomicBool) -> CoreResult<R> + Send + 'static,
    {
        let (progress, cancel) = (Arc::new(AtomicU64::new(0)), Arc::new(AtomicBool::new(false)));
        let finished = Arc::new(Finished::default());
        let (p, c, on_exit) = (progress.clone(), cancel.clone(), FinishOnDrop(finished.clone()));
        let handle = std::thread::spawn(move || {
            let _on_exit = on_exit;
            work(&p, &c)
        });
        Self { progress, cancel, finished, handle: Some(handle) }
    }

    /// The work counted so far (the unit is the run's: trajectory-steps, trajectories).
    pub(crate) fn counted(&self) -> u64 {
        self.progress.load(Ordering::Relaxed)
    }

    /// True when the run has finished (or stopped after a cancel), or its result was taken.
    pub(crate) fn done(&self) -> bool {
        self.handle.is_none() || *self.finished.done.lock().unwrap_or_else(|e| e.into_inner())
    }

    /// Waits until the run has finished or `timeout` [s] (≥ 0, finite; at most an hour) has passed,
    /// with the GIL released; returns `done`.
    pub(crate) fn wait(&self, py: Python<'_>, timeout: f64) -> PyResult<bool> {
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

    /// Asks the run to stop at its next check.
    pub(crate) fn cancel(&self) {
        self.cancel.store(true, Ordering::Relaxed);
    }

    /// Waits for the run (GIL released) and takes its result: a core error as its Python exception,
    /// a second call or a panicked thread as `RuntimeError`.
    pub(crate) fn join(&mut self, py: Python<'_>) -> PyResult<R> {
        let handle =
            self.handle.take().ok_or_else(|| PyRuntimeError::new_err("the result was already taken"))?;
        py.allow_threads(|| handle.join())
            .map_err(|_| PyRuntimeError::new_err("the ensemble thread panicked"))?
            .map_err(to_py)
    }
}

impl<R: Send + 'static> Drop for Background<R> {
    fn drop(&mut self) {
        // never leave a thread running behind a dropped handle
        self.cancel.store(true, Ordering::Relaxed);
        if let Some(h) = self.handle.take() {
            let _ = h.join();
        }
    }
}
