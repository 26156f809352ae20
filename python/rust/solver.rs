//! The batch solver and the incremental stepper of the rod models as Python classes (`Solver`:
//! advanced in chunks with the GIL released, for progress bars and Ctrl-C; `Stepper`: step / step_to
//! / state, for live viewing), both built from `(spec, state, options)` (`spec.rs`). Conversions only;
//! SI units (m, kg, s).

use crate::convert::{samples_to_numpy, to_py, vec3, Arrays};
use crate::getters::pymethods_with_getters;
use crate::spec::{start, ModelSpec, RunOptions, StateArrays};
use numpy::PyReadonlyArray1;
use pendulab_core::model::registry::AnyModel;
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
        fn new(spec: &ModelSpec, state: StateArrays<'_>, options: &RunOptions) -> PyResult<Self> {
            let m = spec.registry()?;
            let (x0, v0) = start(&state)?;
            let s = State::on_tangent_bundle(m.params(), x0, v0).map_err(to_py)?;
            let o = options;
            let mut inner = Solver::new(m, o.t0, s, o.t_end()?, &o.solve, o.save.clone(), o.max_saved_bytes)
                .map_err(to_py)?;
            inner.stepper_mut().set_invariant_projection(o.conserve);
            inner.stepper_mut().set_arithmetic(o.arithmetic).map_err(to_py)?;
            inner.stepper_mut().set_halved_steps(o.halved_steps);
            inner.stepper_mut().set_steps_on_breaks(o.steps_on_samples);
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
        t_end = self.inner.t_end();
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
        fn new(spec: &ModelSpec, state: StateArrays<'_>, options: &RunOptions) -> PyResult<Self> {
            let m = spec.registry()?;
            let (x0, v0) = start(&state)?;
            let s = State::on_tangent_bundle(m.params(), x0, v0).map_err(to_py)?;
            let mut inner = Stepper::new(m, options.t0, s, &options.solve).map_err(to_py)?;
            inner.set_invariant_projection(options.conserve);
            inner.set_arithmetic(options.arithmetic).map_err(to_py)?;
            inner.set_halved_steps(options.halved_steps);
            inner.set_steps_on_breaks(options.steps_on_samples);
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
