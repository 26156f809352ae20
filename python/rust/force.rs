//! A user force given as a Python callable, F(t, x, v) -> (3,) [N] (the slow path): a [`Model`] that
//! adds F/m to a registry model's applied acceleration (T-7.1: only its tangential part acts, the rod
//! takes the rest; dE/dt = F·v + the base model's power), and the batch solver for it. Every
//! evaluation takes the GIL and calls Python, so it costs microseconds, not nanoseconds.
//!
//! The force may depend on v, so the RATTLE family (which kicks with f(t, x, 0)) is refused; DOP853
//! (with projection onto TS²), RKMK4 and RK4 evaluate f(t, x, v) in full. An exception raised by the
//! callable, a result that is not 3 numbers, or a non-finite component stops the run: the first such
//! error is kept, the state is poisoned with NaN so that the core stops at the end of the step, and
//! the error is raised to Python in place of the core's "diverged".

use crate::convert::{samples_to_numpy, to_py, Arrays, InvalidInputError};
use crate::getters::pymethods_with_getters;
use crate::spec::{start, ModelSpec, RunOptions, StateArrays};
use pendulab_core::error::Shown;
use pendulab_core::model::AnyModel;
use pendulab_core::{DVec3, Method, Model, Params, Solver, State};
use pyo3::prelude::*;
use std::sync::{Arc, Mutex};

/// Numbers as the core's messages write them ([`Shown`]: `1`, `nan`, `1e-7`; not `1.0`, `NaN`, `1e0`), in brackets.
fn shown_all(values: &[f64]) -> String {
    format!("[{}]", values.iter().map(|v| Shown(*v).to_string()).collect::<Vec<_>>().join(", "))
}

/// A registry model plus a Python force F(t, x, v) [N].
pub struct PyForce {
    base: AnyModel,
    force: Py<PyAny>,
    error: Mutex<Option<PyErr>>,
}

impl PyForce {
    fn call(&self, t: f64, x: DVec3, v: DVec3) -> DVec3 {
        if self.error.lock().map(|e| e.is_some()).unwrap_or(true) {
            return DVec3::NAN;
        }
        let result = Python::with_gil(|py| -> PyResult<DVec3> {
            let out = self.force.call1(py, (t, x.to_array().to_vec(), v.to_array().to_vec()))?;
            let values: Vec<f64> = out.extract(py).map_err(|_| {
                InvalidInputError::new_err(format!(
                    "the force callable returned {}, not 3 numbers (N), at t = {} s",
                    out.bind(py).repr().map(|r| r.to_string()).unwrap_or_else(|_| "?".into()),
                    Shown(t)
                ))
            })?;
            if values.len() != 3 {
                return Err(InvalidInputError::new_err(format!(
                    "the force callable returned {} numbers at t = {} s; it must return 3 (N)",
                    values.len(),
                    Shown(t)
                )));
            }
            if let Some(k) = values.iter().position(|f| !f.is_finite()) {
                return Err(InvalidInputError::new_err(format!(
                    "the force callable returned F = {} N at t = {} s, x = {} m, v = {} m/s: \
                     component {k} = {} is not a finite number",
                    shown_all(&values),
                    Shown(t),
                    shown_all(&x.to_array()),
                    shown_all(&v.to_array()),
                    Shown(values[k])
                )));
            }
            Ok(DVec3::new(values[0], values[1], values[2]))
        });
        match result {
            Ok(f) => f,
            Err(e) => {
                if let Ok(mut slot) = self.error.lock() {
                    slot.get_or_insert(e);
                }
                DVec3::NAN
            }
        }
    }

    /// The first error the callable raised, if any (taken: reported once).
    fn take_error(&self) -> Option<PyErr> {
        self.error.lock().ok().and_then(|mut e| e.take())
    }
}

/// The batch solver with a Python force (same interface as `Solver`).
#[pyclass(module = "pendulab._core", name = "ForceSolver")]
pub struct ForceSolver {
    inner: Solver<Handle>,
    model: Arc<PyForce>,
}

/// A shared handle on [`PyForce`]: the solver owns one, the binding keeps one to read errors.
#[derive(Clone)]
pub struct Handle(Arc<PyForce>);

impl Model for Handle {
    fn name(&self) -> &'static str {
        self.0.base.name()
    }
    fn params(&self) -> &Params {
        self.0.base.params()
    }
    fn applied_acceleration(&self, t: f64, x: DVec3, v: DVec3) -> DVec3 {
        self.0.base.applied_acceleration(t, x, v) + self.0.call(t, x, v) / self.0.base.params().mass
    }
    fn potential_per_mass(&self, x: DVec3) -> f64 {
        self.0.base.potential_per_mass(x)
    }
    fn is_conservative(&self) -> bool {
        false
    }
    fn is_axisymmetric(&self) -> bool {
        false
    }
    fn is_hybrid(&self) -> bool {
        self.0.base.is_hybrid()
    }
    fn next_break(&self, t: f64) -> f64 {
        self.0.base.next_break(t)
    }
    fn power_per_mass(&self, t: f64, x: DVec3, v: DVec3) -> f64 {
        self.0.base.power_per_mass(t, x, v) + self.0.call(t, x, v).dot(v) / self.0.base.params().mass
    }
}

pymethods_with_getters! {
    impl ForceSolver {
        #[new]
        fn new(spec: &ModelSpec, state: StateArrays<'_>, options: &RunOptions, force: Py<PyAny>) -> PyResult<Self> {
            let base = spec.registry()?;
            let o = options;
            if !matches!(o.solve.method, Method::Dop853 | Method::Rkmk4 | Method::Rk4) {
                return Err(InvalidInputError::new_err(format!(
                    "method {:?} cannot integrate a force given as a Python callable: it may depend on \
                     v, which the RATTLE family's kicks f(t, x, 0) leave out (and rk4_angles is for the ideal \
                     pendulum only); use 'dop853' (recommended, with projection onto TS²), 'rkmk4' or 'rk4'",
                    o.solve.method.info().name
                )));
            }
            let (x0, v0) = start(&state)?;
            let s = State::on_tangent_bundle(base.params(), x0, v0).map_err(to_py)?;
            let model = Arc::new(PyForce { base, force, error: Mutex::new(None) });
            let mut inner = Solver::new(Handle(model.clone()), o.t0, s, o.t_end()?, &o.solve, o.save.clone(), o.max_saved_bytes)
                .map_err(to_py)?;
            inner.stepper_mut().set_halved_steps(o.halved_steps);
            inner.stepper_mut().set_steps_on_breaks(o.steps_on_samples);
            if let Some(e) = model.take_error() {
                return Err(e);
            }
            Ok(Self { inner, model })
        }

        /// Advances by about `budget` steps (the GIL is released between force calls); returns True at
        /// t_end. An error of the force callable is raised as it was raised (or as InvalidInputError).
        fn advance(&mut self, py: Python<'_>, budget: u64) -> PyResult<bool> {
            let inner = &mut self.inner;
            let result = py.allow_threads(|| inner.advance(budget));
            if let Some(e) = self.model.take_error() {
                return Err(e);
            }
            result.map_err(to_py)
        }

        /// Samples saved since the last call: (t [s] (n,), x [m] (n, 3), v [m/s] (n, 3)).
        fn take_samples<'py>(&mut self, py: Python<'py>) -> Arrays<'py> {
            samples_to_numpy(py, self.inner.take_samples())
        }
    }
    getters(&self) {
        progress = self.inner.progress();
        t = self.inner.stepper().t();
        t_end = self.inner.t_end();
        done = self.inner.is_done();
        stats = self.inner.stats();
    }
}

/// Registers the class.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<ForceSolver>()
}
