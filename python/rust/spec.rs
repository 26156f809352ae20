//! The run as one description crossing the border: `ModelSpec` (the model, built and checked once:
//! a registry model by name with l [m], m [kg], g [m/s²], its extra parameters and pivot samples, or
//! the swinging spring) and `RunOptions` (t0, t_end [s], the method, dt [s], rtol, atol [m and m/s],
//! projection, conserve, the save rule, the saved-bytes cap, the spring's order, a step cap). Every stepping
//! class takes `(spec, state, options)` with the state a pair (x0 [m], v0 [m/s]). Conversions only.

use crate::convert::{any_model, to_py, vec3, InvalidInputError, PivotArrays};
use numpy::PyReadonlyArray1;
use pendulab_core::elastic::SwingingSpring;
use pendulab_core::integrate::rattle_kernel::Arithmetic;
use pendulab_core::model::registry::AnyModel;
use pendulab_core::model::StringPendulum;
use pendulab_core::solve::DEFAULT_MAX_SAVED_BYTES;
use pendulab_core::{DVec3, Method, Model, Params, SaveAt, SolveOptions};
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyTuple};

/// The model a spec holds.
#[derive(Clone)]
enum Built {
    /// A registry model on the sphere (rods, moving pivots, the string).
    Registry(AnyModel),
    /// The swinging spring (off the sphere).
    Spring(SwingingSpring),
}

/// A model built once and checked (`Pendulum`, `SwingingSpring`, the string and pivot models build
/// it): `ModelSpec(length, mass, g, model_name=None, extra=None, pivot=None)` for the registry's
/// models, `ModelSpec.spring(k_over_m, rest_length, g, mass)` for the swinging spring. Pickled by
/// its arguments.
#[pyclass(module = "pendulab._core", name = "ModelSpec", frozen)]
pub(crate) struct ModelSpec {
    built: Built,
    args: Py<PyTuple>,
}

impl ModelSpec {
    /// The registry model (a copy: every run owns its model).
    pub(crate) fn registry(&self) -> PyResult<AnyModel> {
        match &self.built {
            Built::Registry(m) => Ok(m.clone()),
            Built::Spring(_) => Err(InvalidInputError::new_err(
                "the swinging spring runs off the sphere: use its own classes (SpringStepper, spring_simulate)",
            )),
        }
    }

    /// The registry model's l [m], m [kg], g [m/s²] (what a state on TS² is checked against).
    pub(crate) fn params(&self) -> PyResult<Params> {
        match &self.built {
            Built::Registry(m) => Ok(*m.params()),
            Built::Spring(_) => Err(InvalidInputError::new_err(
                "the swinging spring runs off the sphere: its states are not on TS²",
            )),
        }
    }

    /// The string pendulum (the registry's `string` model).
    pub(crate) fn string(&self) -> PyResult<StringPendulum> {
        match &self.built {
            Built::Registry(AnyModel::String(sp)) => Ok(*sp),
            _ => Err(InvalidInputError::new_err(format!(
                "the string pendulum's classes take the 'string' model, not {:?}",
                self.name()
            ))),
        }
    }

    /// The swinging spring.
    pub(crate) fn spring(&self) -> PyResult<SwingingSpring> {
        match &self.built {
            Built::Spring(sp) => Ok(*sp),
            Built::Registry(m) => Err(InvalidInputError::new_err(format!(
                "the spring's classes take ModelSpec.spring(...), not the model {:?}",
                m.name()
            ))),
        }
    }
}

#[pymethods]
impl ModelSpec {
    #[new]
    #[pyo3(signature = (length, mass, g, model_name=None, extra=None, pivot=None))]
    fn new(
        py: Python<'_>,
        length: f64,
        mass: f64,
        g: f64,
        model_name: Option<&str>,
        extra: Option<Vec<(String, f64)>>,
        pivot: Option<PivotArrays<'_>>,
    ) -> PyResult<Self> {
        let pivot_args = pivot.as_ref().map(|(t, p)| (t.as_any().clone(), p.as_any().clone()));
        let args = PyTuple::new(
            py,
            [
                length.into_pyobject(py)?.into_any(),
                mass.into_pyobject(py)?.into_any(),
                g.into_pyobject(py)?.into_any(),
                model_name.into_pyobject(py)?.into_any(),
                extra.clone().into_pyobject(py)?.into_any(),
                pivot_args.into_pyobject(py)?.into_any(),
            ],
        )?;
        let built = Built::Registry(any_model(length, mass, g, model_name, extra, pivot)?);
        Ok(Self { built, args: args.unbind() })
    }

    /// The swinging spring: k/m [1/s²], rest length l₀ [m], g [m/s²], m [kg].
    #[staticmethod]
    fn spring_model(py: Python<'_>, k_over_m: f64, rest_length: f64, g: f64, mass: f64) -> PyResult<Self> {
        let sp = SwingingSpring::new(k_over_m, rest_length, g, mass).map_err(to_py)?;
        let args = PyTuple::new(py, [k_over_m, rest_length, g, mass])?;
        Ok(Self { built: Built::Spring(sp), args: args.unbind() })
    }

    /// The model's registry name (`spring` for the swinging spring).
    #[getter]
    pub(crate) fn name(&self) -> &'static str {
        match &self.built {
            Built::Registry(m) => m.name(),
            Built::Spring(_) => "spring",
        }
    }

    /// Length l [m] (the spring: its rest length l₀).
    #[getter]
    fn length(&self) -> f64 {
        match &self.built {
            Built::Registry(m) => m.params().length,
            Built::Spring(sp) => sp.rest_length,
        }
    }

    /// Mass m [kg].
    #[getter]
    fn mass(&self) -> f64 {
        match &self.built {
            Built::Registry(m) => m.params().mass,
            Built::Spring(sp) => sp.mass,
        }
    }

    /// Gravity g [m/s²].
    #[getter]
    fn g(&self) -> f64 {
        match &self.built {
            Built::Registry(m) => m.params().g,
            Built::Spring(sp) => sp.g,
        }
    }

    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyTuple>)> {
        let py = slf.py();
        let me = slf.get();
        let ctor = match me.built {
            Built::Registry(_) => slf.get_type().into_any(),
            Built::Spring(_) => slf.get_type().getattr("spring_model")?,
        };
        Ok((ctor, me.args.bind(py).clone()))
    }

    fn __repr__(&self) -> String {
        format!(
            "ModelSpec({:?}, l={} m, m={} kg, g={} m/s²)",
            self.name(),
            self.length(),
            self.mass(),
            self.g()
        )
    }
}

/// How to run: the start time t0 [s], the end t_end [s] (batch runs), the method and its dt [s],
/// rtol, atol [m and m/s] and projection onto TS² (defaults: the core's `SolveOptions`), conserve
/// (E and J₃ imposed after each step), the save rule (every `save_every`-th step, or exactly
/// `save_times` [s]), the cap on saved bytes, the spring's order (2 or 4) and a cap on steps
/// (`max_steps`, the crane's runs).
#[pyclass(module = "pendulab._core", name = "RunOptions", frozen)]
pub(crate) struct RunOptions {
    pub(crate) t0: f64,
    t_end: Option<f64>,
    pub(crate) solve: SolveOptions,
    pub(crate) conserve: bool,
    pub(crate) save: SaveAt,
    /// `save_every` as given (the ensemble keeps only the final state without one).
    pub(crate) save_every: Option<u64>,
    pub(crate) max_saved_bytes: u64,
    pub(crate) order: u32,
    /// Cap on the steps of a run that takes one (the crane's).
    pub(crate) max_steps: Option<u64>,
    /// The RATTLE family's multiply-adds: unfused (default) or fused (`Solver`, `Stepper`).
    pub(crate) arithmetic: Arithmetic,
    /// Every fixed step taken as two halves (`Stepper::set_halved_steps`: the error estimate's dt/2
    /// companion on a sampled pivot; `Solver`, `ForceSolver`, `Stepper`).
    pub(crate) halved_steps: bool,
    /// A sampled pivot's fixed steps land on every sample, dt the longest (`Stepper::set_steps_on_breaks`;
    /// `Solver`, `ForceSolver`, `Stepper`).
    pub(crate) steps_on_samples: bool,
}

impl RunOptions {
    /// The end time t_end [s]; an error for a batch run without one.
    pub(crate) fn t_end(&self) -> PyResult<f64> {
        self.t_end.ok_or_else(|| InvalidInputError::new_err("a batch run needs t_end [s] in its RunOptions"))
    }
}

/// The keywords `RunOptions` takes, in the order of its signature (`_core.pyi`).
const KEYWORDS: [&str; 16] = [
    "t0",
    "t_end",
    "method",
    "dt",
    "rtol",
    "atol",
    "project",
    "conserve",
    "save_every",
    "save_times",
    "max_saved_bytes",
    "order",
    "max_steps",
    "arithmetic",
    "halved_steps",
    "steps_on_samples",
];

/// `RunOptions`' keywords as given (None: not given or None), read once from the call's keywords.
#[derive(Default)]
struct Keywords<'py> {
    t0: Option<f64>,
    t_end: Option<f64>,
    method: Option<String>,
    dt: Option<f64>,
    rtol: Option<f64>,
    atol: Option<f64>,
    project: Option<bool>,
    conserve: Option<bool>,
    save_every: Option<u64>,
    save_times: Option<PyReadonlyArray1<'py, f64>>,
    max_saved_bytes: Option<u64>,
    order: Option<u32>,
    max_steps: Option<u64>,
    arithmetic: Option<String>,
    halved_steps: Option<bool>,
    steps_on_samples: Option<bool>,
}

impl<'py> Keywords<'py> {
    /// Reads `given`; an unknown keyword or a value of the wrong type is a TypeError naming it (as
    /// for a Python function; t0, conserve, order and arithmetic take no None).
    fn read(given: Option<&Bound<'py, PyDict>>) -> PyResult<Self> {
        let mut k = Self::default();
        for (key, value) in given.map(|d| d.iter()).into_iter().flatten() {
            let name: String = key.extract()?;
            let v = &value;
            match name.as_str() {
                "t0" => k.t0 = Some(keyword(v, "t0")?),
                "t_end" => k.t_end = optional(v, "t_end")?,
                "method" => k.method = optional(v, "method")?,
                "dt" => k.dt = optional(v, "dt")?,
                "rtol" => k.rtol = optional(v, "rtol")?,
                "atol" => k.atol = optional(v, "atol")?,
                "project" => k.project = optional(v, "project")?,
                "conserve" => k.conserve = Some(keyword(v, "conserve")?),
                "save_every" => k.save_every = optional(v, "save_every")?,
                "save_times" => k.save_times = optional(v, "save_times")?,
                "max_saved_bytes" => k.max_saved_bytes = optional(v, "max_saved_bytes")?,
                "order" => k.order = Some(keyword(v, "order")?),
                "max_steps" => k.max_steps = optional(v, "max_steps")?,
                "arithmetic" => k.arithmetic = Some(keyword(v, "arithmetic")?),
                "halved_steps" => k.halved_steps = Some(keyword(v, "halved_steps")?),
                "steps_on_samples" => k.steps_on_samples = Some(keyword(v, "steps_on_samples")?),
                _ => {
                    return Err(PyTypeError::new_err(format!(
                        "RunOptions() got an unexpected keyword argument '{name}' (it takes {})",
                        KEYWORDS.join(", ")
                    )))
                }
            }
        }
        Ok(k)
    }
}

/// The value of keyword `name`; a TypeError names the keyword (other errors, e.g. OverflowError for
/// a negative count, pass as they are).
fn keyword<'py, T: FromPyObject<'py>>(v: &Bound<'py, PyAny>, name: &str) -> PyResult<T> {
    v.extract().map_err(|e| {
        if e.is_instance_of::<PyTypeError>(v.py()) {
            PyTypeError::new_err(format!("argument '{name}': {}", e.value(v.py())))
        } else {
            e
        }
    })
}

/// [`keyword`], None for None.
fn optional<'py, T: FromPyObject<'py>>(v: &Bound<'py, PyAny>, name: &str) -> PyResult<Option<T>> {
    if v.is_none() {
        Ok(None)
    } else {
        keyword(v, name).map(Some)
    }
}

#[pymethods]
impl RunOptions {
    /// Keywords only (see [`KEYWORDS`]); the method's dt, rtol, atol and projection default to the
    /// core's `SolveOptions`, save_every to 1, max_saved_bytes to the core's cap, arithmetic to
    /// "unfused".
    #[new]
    #[pyo3(signature = (**keywords))]
    #[pyo3(
        text_signature = "(*, t0=0.0, t_end=None, method=None, dt=None, rtol=None, atol=None, project=None, conserve=False, save_every=None, save_times=None, max_saved_bytes=None, order=2, max_steps=None, arithmetic='unfused', halved_steps=False, steps_on_samples=False)"
    )]
    fn new(keywords: Option<&Bound<'_, PyDict>>) -> PyResult<Self> {
        let k = Keywords::read(keywords)?;
        let d = SolveOptions::default();
        let solve = SolveOptions {
            method: match &k.method {
                Some(name) => Method::from_name(name).map_err(to_py)?,
                None => d.method,
            },
            dt: k.dt.unwrap_or(d.dt),
            rtol: k.rtol.unwrap_or(d.rtol),
            atol: k.atol.unwrap_or(d.atol),
            project: k.project.unwrap_or(d.project),
        };
        let save = match (k.save_every, k.save_times) {
            (Some(_), Some(_)) => {
                return Err(InvalidInputError::new_err("give either save_every or save_times, not both"))
            }
            (_, Some(ts)) => SaveAt::Times(ts.as_array().to_vec()),
            (n, None) => SaveAt::Every(n.unwrap_or(1)),
        };
        let arithmetic =
            Arithmetic::from_name(k.arithmetic.as_deref().unwrap_or("unfused")).map_err(to_py)?;
        Ok(Self {
            t0: k.t0.unwrap_or(0.0),
            t_end: k.t_end,
            solve,
            conserve: k.conserve.unwrap_or(false),
            save,
            save_every: k.save_every,
            max_saved_bytes: k.max_saved_bytes.unwrap_or(DEFAULT_MAX_SAVED_BYTES),
            order: k.order.unwrap_or(2),
            max_steps: k.max_steps,
            arithmetic,
            halved_steps: k.halved_steps.unwrap_or(false),
            steps_on_samples: k.steps_on_samples.unwrap_or(false),
        })
    }

    /// The RATTLE family's arithmetic: "unfused" (default) or "fused".
    #[getter]
    fn arithmetic(&self) -> &'static str {
        self.arithmetic.name()
    }

    /// The method's name.
    #[getter]
    fn method(&self) -> &'static str {
        self.solve.method.info().name
    }
    #[getter]
    fn t0(&self) -> f64 {
        self.t0
    }
    #[getter(t_end)]
    fn t_end_getter(&self) -> Option<f64> {
        self.t_end
    }
    #[getter]
    fn dt(&self) -> f64 {
        self.solve.dt
    }
}

/// A start state as given: x0 [m], v0 [m/s] (3 components each; the classes check it on TS²).
pub(crate) type StateArrays<'py> = (PyReadonlyArray1<'py, f64>, PyReadonlyArray1<'py, f64>);

/// The start vectors of a [`StateArrays`] pair, named x0 and v0 in errors.
pub(crate) fn start(state: &StateArrays<'_>) -> PyResult<(DVec3, DVec3)> {
    Ok((vec3("x0", &state.0)?, vec3("v0", &state.1)?))
}

/// Registers the classes.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<ModelSpec>()?;
    m.add_class::<RunOptions>()
}
