//! Binding of the string pendulum (`pendulab_core::model::string`, `string_run`): the hybrid run
//! (taut phases, leave and snap events, analytic free flight) as numpy arrays. Conversions only;
//! SI units.

use crate::{to_py, vec3};
use numpy::ndarray::{Array1, Array2};
use numpy::{IntoPyArray, PyReadonlyArray1};
use pendulab_core::model::string_run::EventKind;
use pendulab_core::model::StringPendulum;
use pendulab_core::solve::DEFAULT_MAX_SAVED_BYTES;
use pendulab_core::{Method, Params, State};
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

/// Simulates the string pendulum (l [m], m [kg], g [m/s²], restitution e ∈ [0, 1]) from x0, v0
/// [m, m/s] at t0 [s] to t_end [s] with `method` (rattle, rattle4, rattle6, rattle8, rkmk4) and step
/// dt [s]; returns a dict of t (n,), x, v (n, 3), taut (n,) bool, stats, and events: a dict of
/// arrays t (k,), kind (k,) str ("slack" or "taut"), x, v_before, v_after (k, 3), energy_lost (k,) [J].
#[pyfunction]
#[pyo3(signature = (length, mass, g, restitution, x0, v0, t0, t_end, method, dt, save_every=1, max_saved_bytes=None))]
#[allow(clippy::too_many_arguments)]
pub fn string_simulate<'py>(
    py: Python<'py>,
    length: f64,
    mass: f64,
    g: f64,
    restitution: f64,
    x0: PyReadonlyArray1<'py, f64>,
    v0: PyReadonlyArray1<'py, f64>,
    t0: f64,
    t_end: f64,
    method: &str,
    dt: f64,
    save_every: u64,
    max_saved_bytes: Option<u64>,
) -> PyResult<Bound<'py, PyDict>> {
    let sp = StringPendulum::new(Params::new(length, mass, g).map_err(to_py)?, restitution).map_err(to_py)?;
    let method = Method::from_name(method).map_err(to_py)?;
    let start = State { x: vec3("x0", &x0)?, v: vec3("v0", &v0)? };
    let limit = max_saved_bytes.unwrap_or(DEFAULT_MAX_SAVED_BYTES);
    let run =
        py.allow_threads(|| sp.simulate(t0, start, t_end, method, dt, save_every, limit)).map_err(to_py)?;
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
    let st = PyDict::new(py);
    st.set_item("steps", run.stats.steps)?;
    st.set_item("rejected", run.stats.rejected)?;
    st.set_item("rhs_evals", run.stats.rhs_evals)?;
    d.set_item("stats", st)?;
    Ok(d)
}

/// Registers the function.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(string_simulate, m)?)
}
