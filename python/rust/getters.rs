//! The getters that the stepping classes share (`Solver`, `Stepper`, `ForceSolver`, `StringRunner`,
//! `StringStepper`, `SpringStepper`), written once: [`pymethods_with_getters!`] emits
//! a class's `#[pymethods]` block with its own methods and, for each getter it lists, the property
//! computed by the given expression of `self`:
//!
//! | getter | Python value |
//! |---|---|
//! | `t` | current time [s] (float) |
//! | `x`, `v` | current position [m], velocity [m/s]: numpy (3,) from a `DVec3` |
//! | `stats` | work counters so far: dict steps, rejected, rhs_evals, from `Stats` |
//! | `progress` | fraction of [t0, t_end] done, in [0, 1] (float) |
//! | `t_end` | the end of the run [s] (float) |
//! | `done` | True once t_end is reached (bool) |
//!
//! ```ignore
//! pymethods_with_getters! {
//!     impl Stepper_ { /* #[new] fn new(..), fn step(..), .. */ }
//!     getters(&self) { t = self.inner.t(); x = self.inner.state().x; stats = self.inner.stats(); }
//! }
//! ```
//! (One `#[pymethods]` block per class: pyo3 sees the getters only if they are inside it, so the
//! macro takes the class's methods too.)

/// See the module documentation.
macro_rules! pymethods_with_getters {
    (impl $class:ident { $($item:tt)* } getters(&$this:ident) { $($getters:tt)* }) => {
        pymethods_with_getters!(@munch $class, $this, [$($item)*], $($getters)*);
    };
    (@munch $class:ident, $this:ident, [$($acc:tt)*], ) => {
        #[::pyo3::pymethods]
        impl $class {
            $($acc)*
        }
    };
    (@munch $class:ident, $this:ident, [$($acc:tt)*], t = $e:expr; $($rest:tt)*) => {
        pymethods_with_getters!(@munch $class, $this, [$($acc)*
            /// Current time [s].
            #[getter]
            fn t(&$this) -> f64 {
                $e
            }
        ], $($rest)*);
    };
    (@munch $class:ident, $this:ident, [$($acc:tt)*], x = $e:expr; $($rest:tt)*) => {
        pymethods_with_getters!(@munch $class, $this, [$($acc)*
            /// Current position [m] (relative to the pivot).
            #[getter]
            fn x<'py>(&$this, py: ::pyo3::Python<'py>) -> ::pyo3::Bound<'py, ::numpy::PyArray1<f64>> {
                $crate::convert::arr3(py, $e)
            }
        ], $($rest)*);
    };
    (@munch $class:ident, $this:ident, [$($acc:tt)*], v = $e:expr; $($rest:tt)*) => {
        pymethods_with_getters!(@munch $class, $this, [$($acc)*
            /// Current velocity [m/s].
            #[getter]
            fn v<'py>(&$this, py: ::pyo3::Python<'py>) -> ::pyo3::Bound<'py, ::numpy::PyArray1<f64>> {
                $crate::convert::arr3(py, $e)
            }
        ], $($rest)*);
    };
    (@munch $class:ident, $this:ident, [$($acc:tt)*], stats = $e:expr; $($rest:tt)*) => {
        pymethods_with_getters!(@munch $class, $this, [$($acc)*
            /// Work counters so far: steps, rejected, rhs_evals.
            #[getter]
            fn stats<'py>(
                &$this,
                py: ::pyo3::Python<'py>,
            ) -> ::pyo3::PyResult<::pyo3::Bound<'py, ::pyo3::types::PyDict>> {
                $crate::convert::stats_dict(py, $e)
            }
        ], $($rest)*);
    };
    (@munch $class:ident, $this:ident, [$($acc:tt)*], progress = $e:expr; $($rest:tt)*) => {
        pymethods_with_getters!(@munch $class, $this, [$($acc)*
            /// Fraction of the run done, in [0, 1].
            #[getter]
            fn progress(&$this) -> f64 {
                $e
            }
        ], $($rest)*);
    };
    (@munch $class:ident, $this:ident, [$($acc:tt)*], t_end = $e:expr; $($rest:tt)*) => {
        pymethods_with_getters!(@munch $class, $this, [$($acc)*
            /// The end of the run, t_end [s].
            #[getter]
            fn t_end(&$this) -> f64 {
                $e
            }
        ], $($rest)*);
    };
    (@munch $class:ident, $this:ident, [$($acc:tt)*], done = $e:expr; $($rest:tt)*) => {
        pymethods_with_getters!(@munch $class, $this, [$($acc)*
            /// True once the run has finished.
            #[getter]
            fn done(&$this) -> bool {
                $e
            }
        ], $($rest)*);
    };
}

pub(crate) use pymethods_with_getters;
