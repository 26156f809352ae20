//! The binding layer `pendulab._core`: conversions between numpy and `pendulab-core`, and the
//! mapping of core errors to Python exceptions. No physics lives here.
//!
//! Units are SI throughout (m, kg, s, rad). Arrays of 3-vectors are float64 with shape (N, 3).

mod ensemble;
mod exact;
mod force;
mod slewing;
mod spring;
mod string;

use numpy::ndarray::Array2;
use numpy::{IntoPyArray, PyArray1, PyArray2, PyReadonlyArray1, PyReadonlyArray2};
use pendulab_core::model::registry::{AnyModel, COMMON, MODELS};
use pendulab_core::model::{acceleration, energy, j3, tension};
use pendulab_core::solve::{Samples, DEFAULT_MAX_SAVED_BYTES};
use pendulab_core::{
    DVec3, Error, IdealPendulum, Method, Model, Params, SaveAt, SolveOptions, Solver, State, Stepper,
};
use pyo3::create_exception;
use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyDict;

create_exception!(
    _core,
    InvalidInputError,
    PyValueError,
    "Bad input: the message names the value and what is allowed."
);
create_exception!(
    _core,
    IntegrationError,
    PyRuntimeError,
    "The integration could not continue (diverged, pole, step underflow)."
);

pub(crate) fn to_py(err: Error) -> PyErr {
    match err {
        Error::PoleSingularity { .. }
        | Error::ReducedFlowPole { .. }
        | Error::Diverged { .. }
        | Error::StepSizeUnderflow { .. } => IntegrationError::new_err(err.to_string()),
        _ => InvalidInputError::new_err(err.to_string()),
    }
}

pub(crate) fn vec3(name: &str, a: &PyReadonlyArray1<'_, f64>) -> PyResult<DVec3> {
    let a = a.as_array();
    if a.len() != 3 {
        return Err(InvalidInputError::new_err(format!(
            "{name} must have 3 components (m or m/s), got {}",
            a.len()
        )));
    }
    Ok(DVec3::new(a[0], a[1], a[2]))
}

pub(crate) fn model(length: f64, mass: f64, g: f64) -> PyResult<IdealPendulum> {
    IdealPendulum::new(length, mass, g).map_err(to_py)
}

/// Pivot samples from Python: times [s] (n,) and positions [m] (n, 3).
pub(crate) type PivotArrays<'py> = (PyReadonlyArray1<'py, f64>, PyReadonlyArray2<'py, f64>);

/// A registry model by name with its extra parameters (None: the ideal pendulum); the
/// `sampled_pivot` model takes its path from `pivot` (times, positions).
pub(crate) fn any_model(
    length: f64,
    mass: f64,
    g: f64,
    name: Option<&str>,
    extra: Option<Vec<(String, f64)>>,
    pivot: Option<PivotArrays<'_>>,
) -> PyResult<AnyModel> {
    let params = Params::new(length, mass, g).map_err(to_py)?;
    let extra = extra.unwrap_or_default();
    let pairs: Vec<(&str, f64)> = extra.iter().map(|(k, v)| (k.as_str(), *v)).collect();
    let name = name.unwrap_or("ideal");
    match (name, pivot) {
        ("sampled_pivot", Some((t, p))) => {
            // validates the keys and ranges (and that only damping is given) by building without samples
            if let Some((key, _)) = pairs.iter().find(|(k, _)| *k != "damping") {
                return Err(to_py(Error::UnknownParameter {
                    model: "sampled_pivot",
                    name: key.to_string(),
                    available: "damping".into(),
                }));
            }
            let damping = pairs.iter().find(|(k, _)| *k == "damping").map_or(0.0, |(_, v)| *v);
            let (t, p) = (t.as_array(), p.as_array());
            if p.ncols() != 3 {
                return Err(InvalidInputError::new_err(format!(
                    "pivot positions must have shape (n, 3) in m, got {:?}",
                    p.dim()
                )));
            }
            let times: Vec<f64> = t.iter().copied().collect();
            let positions: Vec<DVec3> = p.rows().into_iter().map(|r| DVec3::new(r[0], r[1], r[2])).collect();
            AnyModel::sampled_pivot(params, &times, &positions, damping).map_err(to_py)
        }
        (_, Some(_)) => Err(InvalidInputError::new_err(format!(
            "pivot samples belong to the 'sampled_pivot' model, not to {name:?}"
        ))),
        (_, None) => AnyModel::build(name, params, &pairs).map_err(to_py),
    }
}

fn param_dict<'py>(
    py: Python<'py>,
    p: &pendulab_core::model::registry::ParamSpec,
) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("name", p.name)?;
    d.set_item("label", p.label)?;
    d.set_item("unit", p.unit)?;
    d.set_item("default", p.default)?;
    d.set_item("min", p.min)?;
    d.set_item("max", p.max)?;
    d.set_item("description", p.description)?;
    d.set_item("allowed", p.allowed)?;
    Ok(d)
}

/// Validates a model: l > 0 m, m > 0 kg, finite g, a registered name and its parameters (and the
/// pivot samples of `sampled_pivot`).
#[pyfunction]
#[pyo3(signature = (length, mass, g, model_name=None, extra=None, pivot=None))]
fn check_model(
    length: f64,
    mass: f64,
    g: f64,
    model_name: Option<&str>,
    extra: Option<Vec<(String, f64)>>,
    pivot: Option<PivotArrays<'_>>,
) -> PyResult<()> {
    any_model(length, mass, g, model_name, extra, pivot).map(|_| ())
}

/// The model registry: name, label, summary, and parameters (common ones first) with labels, units,
/// one-line help and limits.
#[pyfunction]
fn models(py: Python<'_>) -> PyResult<Vec<Bound<'_, PyDict>>> {
    MODELS
        .iter()
        .map(|m| {
            let d = PyDict::new(py);
            d.set_item("name", m.name)?;
            d.set_item("label", m.label)?;
            d.set_item("summary", m.summary)?;
            d.set_item("interactive", m.interactive)?;
            let params: PyResult<Vec<_>> = COMMON.iter().chain(m.params).map(|p| param_dict(py, p)).collect();
            d.set_item("params", params?)?;
            Ok(d)
        })
        .collect()
}

pub(crate) fn arr3<'py>(py: Python<'py>, v: DVec3) -> Bound<'py, PyArray1<f64>> {
    v.to_array().to_vec().into_pyarray(py)
}

fn options(method: &str, dt: f64, rtol: f64, atol: f64, project: bool) -> PyResult<SolveOptions> {
    Ok(SolveOptions { method: Method::from_name(method).map_err(to_py)?, dt, rtol, atol, project })
}

type Arrays<'py> = (Bound<'py, PyArray1<f64>>, Bound<'py, PyArray2<f64>>, Bound<'py, PyArray2<f64>>);
/// A state as two numpy vectors (x [m], v [m/s]).
type StatePair<'py> = (Bound<'py, PyArray1<f64>>, Bound<'py, PyArray1<f64>>);

fn samples_to_numpy(py: Python<'_>, s: Samples) -> Arrays<'_> {
    let n = s.t.len();
    let mut x = Array2::<f64>::zeros((n, 3));
    let mut v = Array2::<f64>::zeros((n, 3));
    for (i, st) in s.states.iter().enumerate() {
        for k in 0..3 {
            x[[i, k]] = st.x[k];
            v[[i, k]] = st.v[k];
        }
    }
    (s.t.into_pyarray(py), x.into_pyarray(py), v.into_pyarray(py))
}

/// The registered integrators with their declared order and properties.
#[pyfunction]
fn methods(py: Python<'_>) -> PyResult<Vec<Bound<'_, PyDict>>> {
    Method::ALL
        .iter()
        .map(|m| {
            let i = m.info();
            let d = PyDict::new(py);
            d.set_item("name", i.name)?;
            d.set_item("order", i.order)?;
            d.set_item("symplectic", i.symplectic)?;
            d.set_item("preserves_ts2", i.preserves_ts2)?;
            d.set_item("preserves_j3", i.preserves_j3)?;
            d.set_item("adaptive", i.adaptive)?;
            d.set_item("dense_output", i.dense_output)?;
            d.set_item("default", *m == Method::DEFAULT)?;
            d.set_item("summary", i.summary)?;
            Ok(d)
        })
        .collect()
}

/// Validates the parameters (l > 0 m, m > 0 kg, finite g in m/s²).
#[pyfunction]
fn check_params(length: f64, mass: f64, g: f64) -> PyResult<()> {
    model(length, mass, g).map(|_| ())
}

/// The state (x, v) checked to lie on TS² within the core tolerance.
#[pyfunction]
fn state_on_ts2<'py>(
    py: Python<'py>,
    length: f64,
    mass: f64,
    g: f64,
    x: PyReadonlyArray1<'py, f64>,
    v: PyReadonlyArray1<'py, f64>,
) -> PyResult<StatePair<'py>> {
    let m = model(length, mass, g)?;
    let s = State::on_tangent_bundle(m.params(), vec3("x", &x)?, vec3("v", &v)?).map_err(to_py)?;
    Ok((arr3(py, s.x), arr3(py, s.v)))
}

/// (x, v) moved onto TS², with the distances moved |Δx| [m] and |Δv| [m/s].
#[pyfunction]
fn project_state<'py>(
    py: Python<'py>,
    length: f64,
    mass: f64,
    g: f64,
    x: PyReadonlyArray1<'py, f64>,
    v: PyReadonlyArray1<'py, f64>,
) -> PyResult<(StatePair<'py>, f64, f64)> {
    let m = model(length, mass, g)?;
    let (s, p) = State::projected(m.params(), vec3("x", &x)?, vec3("v", &v)?).map_err(to_py)?;
    Ok(((arr3(py, s.x), arr3(py, s.v)), p.dx, p.dv))
}

/// The state at polar angle θ [rad] from the downward vertical, azimuth φ [rad], rates [rad/s].
#[pyfunction]
#[allow(clippy::too_many_arguments)]
fn state_from_angles(
    py: Python<'_>,
    length: f64,
    mass: f64,
    g: f64,
    theta: f64,
    phi: f64,
    theta_dot: f64,
    phi_dot: f64,
) -> PyResult<StatePair<'_>> {
    let m = model(length, mass, g)?;
    let s = State::from_angles(m.params(), theta, phi, theta_dot, phi_dot).map_err(to_py)?;
    Ok((arr3(py, s.x), arr3(py, s.v)))
}

/// Diagnostics along arrays x, v of shape (N, 3): energy [J], j3 [kg m²/s], tension [N],
/// radius_error = |x| − l [m], tangency = x·v [m²/s], power [W], acceleration (N, 3) [m/s²].
#[pyfunction]
#[pyo3(signature = (length, mass, g, x, v, model_name=None, extra=None, t=None, pivot=None))]
#[allow(clippy::too_many_arguments)]
fn diagnostics<'py>(
    py: Python<'py>,
    length: f64,
    mass: f64,
    g: f64,
    x: PyReadonlyArray2<'py, f64>,
    v: PyReadonlyArray2<'py, f64>,
    model_name: Option<&str>,
    extra: Option<Vec<(String, f64)>>,
    t: Option<PyReadonlyArray1<'py, f64>>,
    pivot: Option<PivotArrays<'py>>,
) -> PyResult<Bound<'py, PyDict>> {
    let m = any_model(length, mass, g, model_name, extra, pivot)?;
    let times = t.map(|t| t.as_array().to_vec());
    let (x, v) = (x.as_array(), v.as_array());
    if x.ncols() != 3 || v.dim() != x.dim() {
        return Err(InvalidInputError::new_err(format!(
            "x and v must both have shape (N, 3), got {:?} and {:?}",
            x.dim(),
            v.dim()
        )));
    }
    let n = x.nrows();
    if let Some(ts) = &times {
        if ts.len() != n {
            return Err(InvalidInputError::new_err(format!(
                "t must have {n} entries (one per state), got {}",
                ts.len()
            )));
        }
    }
    let mut out = [vec![0.0; n], vec![0.0; n], vec![0.0; n], vec![0.0; n], vec![0.0; n], vec![0.0; n]];
    for i in 0..n {
        let s = State {
            x: DVec3::new(x[[i, 0]], x[[i, 1]], x[[i, 2]]),
            v: DVec3::new(v[[i, 0]], v[[i, 1]], v[[i, 2]]),
        };
        let r = s.residuals(length);
        out[0][i] = energy(&m, &s);
        out[1][i] = j3(&m, &s);
        let ti = times.as_ref().map_or(0.0, |ts| ts[i]);
        out[2][i] = tension(&m, ti, &s);
        out[5][i] = m.params().mass * m.power_per_mass(ti, s.x, s.v);
        out[3][i] = r.length;
        out[4][i] = r.tangency;
    }
    let d = PyDict::new(py);
    for (name, values) in
        ["energy", "j3", "tension", "radius_error", "tangency", "power"].into_iter().zip(out)
    {
        d.set_item(name, values.into_pyarray(py))?;
    }
    // The acceleration ẍ = f + λx [m/s²] of T-2.2 (relative to the pivot, in the model's frame):
    // m ẍ is the net force on the bob there (the lab draws it).
    let mut acc = Array2::<f64>::zeros((n, 3));
    for i in 0..n {
        let ti = times.as_ref().map_or(0.0, |ts| ts[i]);
        let a = acceleration(
            &m,
            ti,
            DVec3::new(x[[i, 0]], x[[i, 1]], x[[i, 2]]),
            DVec3::new(v[[i, 0]], v[[i, 1]], v[[i, 2]]),
        );
        for k in 0..3 {
            acc[[i, k]] = a[k];
        }
    }
    d.set_item("acceleration", acc.into_pyarray(py))?;
    // A moving pivot: its position p(t) [m] (the bob is at p + x in the inertial frame).
    if let (Some(path), Some(ts)) = (m.pivot(), &times) {
        let mut p = Array2::<f64>::zeros((n, 3));
        for (i, &ti) in ts.iter().enumerate() {
            let q = path.position(ti);
            for k in 0..3 {
                p[[i, k]] = q[k];
            }
        }
        d.set_item("pivot", p.into_pyarray(py))?;
        // the slewing crane: x in the frame turning with the boom (radial, tangential, vertical)
        if path.boom_frame(0.0, DVec3::ZERO).is_some() {
            let mut b = Array2::<f64>::zeros((n, 3));
            for (i, &ti) in ts.iter().enumerate() {
                let q = path.boom_frame(ti, DVec3::new(x[[i, 0]], x[[i, 1]], x[[i, 2]])).unwrap();
                for k in 0..3 {
                    b[[i, k]] = q[k];
                }
            }
            d.set_item("boom", b.into_pyarray(py))?;
        }
    }
    Ok(d)
}

fn stats_dict<'py>(py: Python<'py>, s: pendulab_core::Stats) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("steps", s.steps)?;
    d.set_item("rejected", s.rejected)?;
    d.set_item("rhs_evals", s.rhs_evals)?;
    Ok(d)
}

/// A batch solver advanced in chunks from Python (progress bars, Ctrl-C between chunks).
#[pyclass(module = "pendulab._core", name = "Solver")]
struct Solver_ {
    inner: Solver<AnyModel>,
}

#[pymethods]
impl Solver_ {
    #[new]
    #[pyo3(signature = (length, mass, g, x0, v0, t0, t_end, method, dt, rtol, atol, project, save_every=None, save_times=None, max_saved_bytes=None, model_name=None, extra=None, conserve=false, pivot=None))]
    #[allow(clippy::too_many_arguments)]
    fn new(
        length: f64,
        mass: f64,
        g: f64,
        x0: PyReadonlyArray1<'_, f64>,
        v0: PyReadonlyArray1<'_, f64>,
        t0: f64,
        t_end: f64,
        method: &str,
        dt: f64,
        rtol: f64,
        atol: f64,
        project: bool,
        save_every: Option<u64>,
        save_times: Option<PyReadonlyArray1<'_, f64>>,
        max_saved_bytes: Option<u64>,
        model_name: Option<&str>,
        extra: Option<Vec<(String, f64)>>,
        conserve: bool,
        pivot: Option<PivotArrays<'_>>,
    ) -> PyResult<Self> {
        let m = any_model(length, mass, g, model_name, extra, pivot)?;
        let s = State::on_tangent_bundle(m.params(), vec3("x0", &x0)?, vec3("v0", &v0)?).map_err(to_py)?;
        let save = match (save_every, save_times) {
            (Some(_), Some(_)) => {
                return Err(InvalidInputError::new_err("give either save_every or save_times, not both"))
            }
            (_, Some(ts)) => SaveAt::Times(ts.as_array().to_vec()),
            (n, None) => SaveAt::Every(n.unwrap_or(1)),
        };
        let opts = options(method, dt, rtol, atol, project)?;
        let mut inner =
            Solver::new(m, t0, s, t_end, &opts, save, max_saved_bytes.unwrap_or(DEFAULT_MAX_SAVED_BYTES))
                .map_err(to_py)?;
        inner.stepper_mut().set_invariant_projection(conserve);
        Ok(Self { inner })
    }

    /// Advances by about `budget` steps with the GIL released; returns True when t_end is reached.
    fn advance(&mut self, py: Python<'_>, budget: u64) -> PyResult<bool> {
        let inner = &mut self.inner;
        py.allow_threads(|| inner.advance(budget)).map_err(to_py)
    }

    /// Samples saved since the last call: (t [s] (n,), x [m] (n, 3), v [m/s] (n, 3)).
    fn take_samples<'py>(&mut self, py: Python<'py>) -> Arrays<'py> {
        samples_to_numpy(py, self.inner.take_samples())
    }

    /// Fraction of [t0, t_end] done.
    #[getter]
    fn progress(&self) -> f64 {
        self.inner.progress()
    }
    /// Current time [s].
    #[getter]
    fn t(&self) -> f64 {
        self.inner.stepper().t()
    }
    /// True when t_end is reached.
    #[getter]
    fn done(&self) -> bool {
        self.inner.is_done()
    }
    /// Work counters: steps, rejected, rhs_evals.
    #[getter]
    fn stats<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        stats_dict(py, self.inner.stats())
    }
}

/// Incremental integration: step / step_to / state, for live viewing.
#[pyclass(module = "pendulab._core", name = "Stepper")]
struct Stepper_ {
    inner: Stepper<AnyModel>,
}

#[pymethods]
impl Stepper_ {
    #[new]
    #[pyo3(signature = (length, mass, g, x0, v0, t0, method, dt, rtol, atol, project, model_name=None, extra=None, conserve=false, pivot=None))]
    #[allow(clippy::too_many_arguments)]
    fn new(
        length: f64,
        mass: f64,
        g: f64,
        x0: PyReadonlyArray1<'_, f64>,
        v0: PyReadonlyArray1<'_, f64>,
        t0: f64,
        method: &str,
        dt: f64,
        rtol: f64,
        atol: f64,
        project: bool,
        model_name: Option<&str>,
        extra: Option<Vec<(String, f64)>>,
        conserve: bool,
        pivot: Option<PivotArrays<'_>>,
    ) -> PyResult<Self> {
        let m = any_model(length, mass, g, model_name, extra, pivot)?;
        let s = State::on_tangent_bundle(m.params(), vec3("x0", &x0)?, vec3("v0", &v0)?).map_err(to_py)?;
        let opts = options(method, dt, rtol, atol, project)?;
        let mut inner = Stepper::new(m, t0, s, &opts).map_err(to_py)?;
        inner.set_invariant_projection(conserve);
        Ok(Self { inner })
    }

    /// Takes `n` steps (dt each; accepted steps for dop853).
    #[pyo3(signature = (n=1))]
    fn step(&mut self, py: Python<'_>, n: u64) -> PyResult<()> {
        let inner = &mut self.inner;
        py.allow_threads(|| inner.step_n(n).and_then(|_| inner.check_finite())).map_err(to_py)
    }

    /// Advances to exactly time `t` [s] (not before the current time).
    fn step_to(&mut self, py: Python<'_>, t: f64) -> PyResult<()> {
        let inner = &mut self.inner;
        py.allow_threads(|| inner.step_to(t).and_then(|_| inner.check_finite())).map_err(to_py)
    }

    /// Replaces the state (checked to lie on TS²).
    fn set_state(&mut self, x: PyReadonlyArray1<'_, f64>, v: PyReadonlyArray1<'_, f64>) -> PyResult<()> {
        let s = State::on_tangent_bundle(self.inner.model().params(), vec3("x", &x)?, vec3("v", &v)?)
            .map_err(to_py)?;
        self.inner.set_state(s);
        Ok(())
    }

    /// Current time [s].
    #[getter]
    fn t(&self) -> f64 {
        self.inner.t()
    }
    /// Current position [m].
    #[getter]
    fn x<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        arr3(py, self.inner.state().x)
    }
    /// Current velocity [m/s].
    #[getter]
    fn v<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        arr3(py, self.inner.state().v)
    }
    /// Work counters: steps, rejected, rhs_evals.
    #[getter]
    fn stats<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        stats_dict(py, self.inner.stats())
    }
}

/// The compiled core of Pendulab (private; use the `pendulab` package).
#[pymodule]
fn _core(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("InvalidInputError", m.py().get_type::<InvalidInputError>())?;
    m.add("IntegrationError", m.py().get_type::<IntegrationError>())?;
    m.add_function(wrap_pyfunction!(methods, m)?)?;
    m.add_function(wrap_pyfunction!(models, m)?)?;
    m.add_function(wrap_pyfunction!(check_model, m)?)?;
    m.add_function(wrap_pyfunction!(check_params, m)?)?;
    m.add_function(wrap_pyfunction!(state_on_ts2, m)?)?;
    m.add_function(wrap_pyfunction!(project_state, m)?)?;
    m.add_function(wrap_pyfunction!(state_from_angles, m)?)?;
    m.add_function(wrap_pyfunction!(diagnostics, m)?)?;
    m.add_class::<Solver_>()?;
    m.add_class::<Stepper_>()?;
    exact::register(m)?;
    ensemble::register(m)?;
    spring::register(m)?;
    string::register(m)?;
    slewing::register(m)?;
    force::register(m)?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
