//! Binding of the ensemble kernel (`pendulab_core::ensemble`): `EnsembleSpec` (the models: l [m],
//! g [m/s²], damping c [1/s] per trajectory), and `EnsembleRun(spec, x, v, options, n_steps)` on a
//! background thread (`background.rs`) so that Python can show progress and cancel (Ctrl-C) while it
//! works (rayon's pool: no thread is started per run). Each array crosses the border once: the
//! models' arrays are copied when the spec is made (shared by its runs, not copied again), the starts
//! into the core's states, the saved states into the result's arrays in one pass (handed to numpy
//! as they are); the starts are checked with the GIL released. Conversions only; SI units.

use crate::background::Background;
use crate::convert::{to_py, InvalidInputError};
use crate::spec::RunOptions;
use numpy::ndarray::{Array1, Array3};
use numpy::{IntoPyArray, PyArray1, PyArray3, PyReadonlyArray1, PyReadonlyArray2};
use pendulab_core::ensemble::{check, run_checked, EnsembleResult, EnsembleSave, RattleSettings, Summary};
use pendulab_core::{DVec3, State};
use pyo3::exceptions::PyRuntimeError;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::sync::Arc;

/// The ensemble's models: the ideal pendulum with optional linear damping (T-7.1), its length l
/// [m], gravity g [m/s²] and damping c [1/s] each one value for all trajectories or one per
/// trajectory (damping may also be empty: undamped). Checked with the starts when a run begins.
/// Copied once from numpy; its runs share the copies.
#[pyclass(module = "pendulab._core", name = "EnsembleSpec", frozen)]
pub struct EnsembleSpec {
    length: Arc<[f64]>,
    g: Arc<[f64]>,
    damping: Arc<[f64]>,
}

/// A numpy vector's values, copied once.
fn shared(a: &PyReadonlyArray1<'_, f64>) -> Arc<[f64]> {
    match a.as_slice() {
        Ok(s) => Arc::from(s),
        Err(_) => a.as_array().iter().copied().collect(),
    }
}

#[pymethods]
impl EnsembleSpec {
    #[new]
    #[pyo3(signature = (length, g, damping=None))]
    fn new(
        length: PyReadonlyArray1<'_, f64>,
        g: PyReadonlyArray1<'_, f64>,
        damping: Option<PyReadonlyArray1<'_, f64>>,
    ) -> Self {
        Self {
            length: shared(&length),
            g: shared(&g),
            damping: damping.map_or_else(|| Arc::from([]), |d| shared(&d)),
        }
    }
}

/// An ensemble run in progress (RATTLE; ideal pendulum with optional linear damping; per-trajectory
/// l, g and damping c).
#[pyclass(module = "pendulab._core", name = "EnsembleRun")]
pub struct EnsembleRun {
    total: u64,
    run: Background<Arrays>,
}

/// A run's result laid out as `EnsembleRun.result` hands it to numpy (x, v rows (N, n_save, 3), the
/// summary's columns), made on the worker that ran it, whose cache still holds the states and
/// summaries; the core's result is freed there too, after this was handed over.
struct Arrays {
    t: Vec<f64>,
    /// (N, n_save, 3), C order, and their shape.
    x: Vec<f64>,
    v: Vec<f64>,
    shape: (usize, usize, usize),
    columns: Option<[Vec<f64>; 7]>,
    settle_time: Option<Vec<f64>>,
    cancelled: bool,
    steps: u64,
}

/// The core's buffers of a run up to this size [B] are freed after its result is handed over (a free
/// on the caller's thread trims the worker's heap, and the next run faults its pages back in); larger
/// ones before, so that a next run's memory never overlaps them by more than this (the size below
/// which `pendulab.ensemble` asks the system for no memory check either).
const FREE_LATER_BYTES: usize = 1 << 26;

impl Arrays {
    /// `res` in numpy's layout: one pass over the states, one per summary column.
    fn of(res: EnsembleResult) -> Self {
        let (n, ns) = (res.len(), res.t.len());
        // trajectory k's sample j is states[k * ns + j]: the rows of (n, ns, 3) in order
        let (x, v) = position_velocity_rows(&res.states);
        let columns = res.summary.as_deref().map(summary_columns);
        let EnsembleResult { t, settle_time, cancelled, steps, states, summary } = res;
        let bytes =
            std::mem::size_of_val(states.as_slice()) + summary.as_deref().map_or(0, std::mem::size_of_val);
        if bytes <= FREE_LATER_BYTES {
            // freed by the pool once this run's outcome is out (off the caller's path)
            rayon::spawn(move || drop((states, summary)));
        } else {
            drop((states, summary)); // before the hand-over
        }
        Self { t, x, v, shape: (n, ns, 3), columns, settle_time, cancelled, steps }
    }
}

#[pymethods]
impl EnsembleRun {
    /// Starts `n_steps` steps of the options' `dt` [s] of the `spec`'s models from x, v (N, 3) [m,
    /// m/s]; saves every `save_every` steps of the options (None: the final state only); `summary`:
    /// extremes of z, E/m and J₃/m per trajectory; `settle_angle` [rad]: track each trajectory's
    /// settle time; the options' `method` ("rattle", or its compositions "rattle4", "rattle6",
    /// "rattle8") and `arithmetic` ("unfused" or "fused") as the single-trajectory method.
    #[new]
    #[pyo3(signature = (spec, x, v, options, n_steps, summary=true, settle_angle=None))]
    #[allow(clippy::too_many_arguments)]
    fn new(
        py: Python<'_>,
        spec: &EnsembleSpec,
        x: PyReadonlyArray2<'_, f64>,
        v: PyReadonlyArray2<'_, f64>,
        options: &RunOptions,
        n_steps: u64,
        summary: bool,
        settle_angle: Option<f64>,
    ) -> PyResult<Self> {
        let starts = starts(&x, &v)?;
        // the spec's arrays, shared (not copied) with the run
        let (length, g, damping) = (spec.length.clone(), spec.g.clone(), spec.damping.clone());
        let (dt, save) =
            (options.solve.dt, options.save_every.map_or(EnsembleSave::Final, EnsembleSave::Every));
        let total = n_steps.saturating_mul(starts.len() as u64);
        // Validate before starting the thread, so bad input raises here and not later.
        // the run's settings but the per-trajectory arrays (owned by the thread below)
        let rest = RattleSettings {
            settle_angle,
            save,
            with_summary: summary,
            arithmetic: options.arithmetic,
            method: options.solve.method,
            ..RattleSettings::new(&[], &[], dt, n_steps)
        };
        let settings = RattleSettings { length: &length, g: &g, damping: &damping, ..rest };
        let checked = py.allow_threads(|| check(&starts, &settings)).map_err(to_py)?;
        let run = Background::spawn(move |progress, cancel| {
            let settings = RattleSettings { length: &length, g: &g, damping: &damping, ..rest };
            run_checked(&starts, &settings, checked, progress, cancel).map(Arrays::of)
        });
        Ok(Self { total, run })
    }

    /// Fraction of trajectory-steps done.
    #[getter]
    fn progress(&self) -> f64 {
        if self.total == 0 {
            1.0
        } else {
            self.run.counted() as f64 / self.total as f64
        }
    }

    /// True when the run has finished (or stopped after a cancel).
    #[getter]
    fn done(&self) -> bool {
        self.run.done()
    }

    /// Waits until the run has finished or `timeout` [s] (≥ 0, finite) has passed, with the GIL
    /// released; returns `done`. Returns at once when the run ends, so a progress loop
    /// `while not run.wait(0.05)` costs a finished run no poll interval.
    fn wait(&self, py: Python<'_>, timeout: f64) -> PyResult<bool> {
        self.run.wait(py, timeout)
    }

    /// Asks every block to stop at its next check (within 1024 steps).
    fn cancel(&self) {
        self.run.cancel();
    }

    /// Waits for the run and returns a dict: t (n_save,), x, v (N, n_save, 3), cancelled, steps and,
    /// with a summary, z_min, z_max, e_min, e_max (per unit mass, J/kg), j3_min, j3_max (m²/s),
    /// crossings (of the pivot's horizontal plane, a count as float64); with a
    /// settle angle, settle_time [s] (0: never outside, inf: outside at the end).
    fn result<'py>(&mut self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let res = self.run.join(py)?;
        // numpy takes the arrays as they are (no copy)
        let bad_shape = |e: numpy::ndarray::ShapeError| PyRuntimeError::new_err(e.to_string());
        let x = Array3::from_shape_vec(res.shape, res.x).map_err(bad_shape)?;
        let v = Array3::from_shape_vec(res.shape, res.v).map_err(bad_shape)?;
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
        for (key, column) in SUMMARY_KEYS.iter().zip(res.columns.into_iter().flatten()) {
            let column: Bound<'py, PyArray1<f64>> = column.into_pyarray(py);
            d.set_item(key, column)?;
        }
        Ok(d)
    }
}

/// The keys of the summary's columns in `EnsembleRun.result` (per unit mass: z [m], E/m [J/kg], J₃/m
/// [m²/s], crossings a count), in the order of [`summary_columns`].
const SUMMARY_KEYS: [&str; 7] = ["z_min", "z_max", "e_min", "e_max", "j3_min", "j3_max", "crossings"];

/// The x and v [m, m/s] of `states` as rows of three, in their order (numpy's C order of an
/// (N, n_times, 3) array when trajectory k's sample j is `states[k * n_times + j]`).
pub(crate) fn position_velocity_rows(states: &[State]) -> (Vec<f64>, Vec<f64>) {
    let (mut x, mut v) = (vec![0.0; 3 * states.len()], vec![0.0; 3 * states.len()]);
    for ((xr, vr), s) in x.chunks_exact_mut(3).zip(v.chunks_exact_mut(3)).zip(states) {
        xr.copy_from_slice(&s.x.to_array());
        vr.copy_from_slice(&s.v.to_array());
    }
    (x, v)
}

/// The per-trajectory summaries as the columns of [`SUMMARY_KEYS`] (each read in one pass).
fn summary_columns(s: &[Summary]) -> [Vec<f64>; 7] {
    fn column(s: &[Summary], f: impl Fn(&Summary) -> f64) -> Vec<f64> {
        s.iter().map(f).collect()
    }
    [
        column(s, |q| q.z.0),
        column(s, |q| q.z.1),
        column(s, |q| q.energy_per_mass.0),
        column(s, |q| q.energy_per_mass.1),
        column(s, |q| q.j3_per_mass.0),
        column(s, |q| q.j3_per_mass.1),
        column(s, |q| q.crossings as f64),
    ]
}

/// The start states of rows x, v (N, 3) [m, m/s], N ≥ 1.
pub(crate) fn starts(x: &PyReadonlyArray2<'_, f64>, v: &PyReadonlyArray2<'_, f64>) -> PyResult<Vec<State>> {
    let (xa, va) = (x.as_array(), v.as_array());
    if xa.ncols() != 3 || va.dim() != xa.dim() || xa.nrows() == 0 {
        return Err(InvalidInputError::new_err(format!(
            "x and v must both have shape (N, 3) with N >= 1, got {:?} and {:?}",
            xa.dim(),
            va.dim()
        )));
    }
    if let (Some(xs), Some(vs)) = (xa.as_slice(), va.as_slice()) {
        // contiguous rows (what pendulab passes): read straight through
        return Ok(xs
            .chunks_exact(3)
            .zip(vs.chunks_exact(3))
            .map(|(x, v)| State { x: DVec3::from_slice(x), v: DVec3::from_slice(v) })
            .collect());
    }
    Ok((0..xa.nrows())
        .map(|i| State {
            x: DVec3::new(xa[[i, 0]], xa[[i, 1]], xa[[i, 2]]),
            v: DVec3::new(va[[i, 0]], va[[i, 1]], va[[i, 2]]),
        })
        .collect())
}

/// Registers the classes.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<EnsembleSpec>()?;
    m.add_class::<EnsembleRun>()
}
