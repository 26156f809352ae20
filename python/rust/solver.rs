//! The batch solver and the incremental stepper of the rod models as Python classes (`Solver`:
//! advanced in chunks with the GIL released, for progress bars and Ctrl-C; `Stepper`: step / step_to
//! / state, for live viewing). Conversions only; SI units (m, kg, s).

use crate::convert::{any_model, options, samples_to_numpy, save_rule, to_py, vec3, Arrays, PivotArrays};
use crate::getters::pymethods_with_getters;
use numpy::PyReadonlyArray1;
use pendulab_core::model::registry::AnyModel;
use pendulab_core::solve::DEFAULT_MAX_SAVED_BYTES;
use pendulab_core::{Model, Solver, State, Stepper};
use pyo3::prelude::*;

/// A batch solver advanced in chunks from Python (progress bars, Ctrl-C between chunks).
#[pyclass(module = "pendulab._core", name = "Solver")]
struct Solver_ {
    inner: Solver<AnyModel>,
}

pymethods_with_getters! {
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
            let save = save_rule(save_every, save_times)?;
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
    }
    getters(&self) {
        progress = self.inner.progress();
        t = self.inner.stepper().t();
        done = self.inner.is_done();
        stats = self.inner.stats();
    }
}

/// Incremental integration: step / step_to / state, for live viewing.
#[pyclass(module = "pendulab._core", name = "Stepper")]
struct Stepper_ {
    inner: Stepper<AnyModel>,
}

pymethods_with_getters! {
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

        /// Advances to exactly time `t` [s] (not before the current time); with `max_steps`, stops
        /// after that many steps. Returns True once at `t` (False: the cap came first; call again).
        #[pyo3(signature = (t, max_steps=None))]
        fn step_to(&mut self, py: Python<'_>, t: f64, max_steps: Option<u64>) -> PyResult<bool> {
            let inner = &mut self.inner;
            let cap = max_steps.unwrap_or(u64::MAX);
            py.allow_threads(|| {
                let reached = inner.step_to_capped(t, cap)?;
                inner.check_finite().map(|_| reached)
            })
            .map_err(to_py)
        }

        /// Replaces the state (checked to lie on TS²).
        fn set_state(&mut self, x: PyReadonlyArray1<'_, f64>, v: PyReadonlyArray1<'_, f64>) -> PyResult<()> {
            let s = State::on_tangent_bundle(self.inner.model().params(), vec3("x", &x)?, vec3("v", &v)?)
                .map_err(to_py)?;
            self.inner.set_state(s);
            Ok(())
        }
    }
    getters(&self) {
        t = self.inner.t();
        x = self.inner.state().x;
        v = self.inner.state().v;
        stats = self.inner.stats();
    }
}

/// Registers the classes.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<Solver_>()?;
    m.add_class::<Stepper_>()
}
