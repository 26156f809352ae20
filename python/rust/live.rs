//! `LiveSession`: the lab's live session of `pendulab_core::live` for the Python server
//! (`pendulab.server.session`, docs/web.md "Pacing", "Frames", "Error estimate") — the same code the
//! page's WebAssembly engine runs. A scenario's setup and the commands go in as the lab's JSON
//! (`pendulab_core::live::wire`: `GET /api/scenarios`' scenario description with rtol and atol, the
//! WebSocket's command messages), and the messages to send come out as `bytes` (frame records:
//! frame.json's float64 values, little-endian) and `str` (JSON notices). The wall-time budget is read
//! from a monotonic clock here (the core has none); the interpreter lock is released while the session
//! steps. Errors are `InvalidInputError` / `IntegrationError`, never a panic. SI units throughout.

use crate::convert::{arr3, to_py, InvalidInputError};
use numpy::PyArray1;
use pendulab_core::live::session::Command;
use pendulab_core::live::wire::{
    error_notice, event_notice, keyed_notice, parse_command, setup_from_json as setup, COMMAND_TYPES, LIMITS,
    MAX_MESSAGE_BYTES,
};
use pendulab_core::live::{LiveSession, Out, Record};
use pyo3::prelude::*;
use pyo3::types::{PyBytes, PyDict, PyString, PyTuple};
use std::sync::OnceLock;
use std::time::Instant;

/// The server's wall clock \[s\] (monotonic, from the first call).
fn now() -> f64 {
    static START: OnceLock<Instant> = OnceLock::new();
    START.get_or_init(Instant::now).elapsed().as_secs_f64()
}

/// A command or refusal of the tick's list: a command's JSON text, `("setup", json)` (a scenario
/// resolved by the server for `load_scenario`) or `("error", message, command or None)`.
type Item = std::result::Result<Command, (String, Option<&'static str>)>;

fn command_name(name: Option<&str>) -> Option<&'static str> {
    name.and_then(|n| COMMAND_TYPES.iter().copied().find(|t| *t == n))
}

fn item(obj: &Bound<'_, PyAny>) -> PyResult<Item> {
    if let Ok(text) = obj.downcast::<PyString>() {
        let refuse = |name: &str| -> Result<pendulab_core::live::Setup, String> {
            Err(format!("scenario {name:?}: the server resolves scenarios before the tick"))
        };
        return Ok(parse_command(text.to_str()?, &refuse));
    }
    let bad = || {
        InvalidInputError::new_err(
            "a tick's command is a JSON text, (\"setup\", scenario JSON) or (\"error\", message, command)",
        )
    };
    let t = obj.downcast::<PyTuple>().map_err(|_| bad())?;
    let kind: String = t.get_item(0).map_err(|_| bad())?.extract()?;
    match (kind.as_str(), t.len()) {
        ("setup", 2) => {
            let text: String = t.get_item(1)?.extract()?;
            Ok(match setup(&text) {
                Ok(s) => Ok(Command::Load(Box::new(s))),
                Err(e) => Err((e, Some("load_scenario"))),
            })
        }
        ("error", 3) => {
            let message: String = t.get_item(1)?.extract()?;
            let command: Option<String> = t.get_item(2)?.extract()?;
            Ok(Err((message, command_name(command.as_deref()))))
        }
        _ => Err(bad()),
    }
}

fn record_bytes(records: &[Record]) -> Vec<u8> {
    records.iter().flat_map(|r| r.0).flat_map(f64::to_le_bytes).collect()
}

fn records_from(bytes: &[u8]) -> PyResult<Vec<Record>> {
    let n = pendulab_core::live::RECORD_LEN * 8;
    if !bytes.len().is_multiple_of(n) {
        return Err(InvalidInputError::new_err(format!(
            "frame records are a multiple of {n} bytes, got {}",
            bytes.len()
        )));
    }
    Ok(bytes
        .chunks_exact(n)
        .map(|c| {
            let mut r = [0.0; pendulab_core::live::RECORD_LEN];
            for (v, b) in r.iter_mut().zip(c.chunks_exact(8)) {
                *v = f64::from_le_bytes(b.try_into().unwrap_or([0; 8]));
            }
            Record(r)
        })
        .collect())
}

/// One client's lab session of the core (module doc). Not for two threads at once (PyO3 refuses a
/// second borrow with a RuntimeError).
#[pyclass(module = "pendulab._core", name = "LiveSession")]
pub struct PyLiveSession {
    inner: LiveSession,
}

/// The messages of a tick as Python objects: frames as `bytes`, notices as JSON `str`.
fn messages(py: Python<'_>, out: &[Out]) -> Vec<PyObject> {
    out.iter()
        .map(|o| match o {
            Out::Frames(records) => PyBytes::new(py, &record_bytes(records)).into_any().unbind(),
            Out::Status(v) => PyString::new(py, &v.to_string()).into_any().unbind(),
            Out::Error(message, command) => {
                PyString::new(py, &error_notice(message, *command).to_string()).into_any().unbind()
            }
            Out::Keyed(message, command, key, values) => {
                PyString::new(py, &keyed_notice(message, *command, key, values).to_string())
                    .into_any()
                    .unbind()
            }
            Out::Event(e, epoch, skipped) => {
                PyString::new(py, &event_notice(e, *epoch, *skipped).to_string()).into_any().unbind()
            }
        })
        .collect()
}

#[pymethods]
impl PyLiveSession {
    /// Wall-clock seconds one session may step per tick \[s\] (`live::budget::TICK_BUDGET`).
    #[classattr]
    const TICK_BUDGET: f64 = pendulab_core::live::TICK_BUDGET;
    /// Steps of the first slice of a new stepper.
    #[classattr]
    const FIRST_SLICE: u64 = pendulab_core::live::budget::FIRST_SLICE;
    /// Most frame records sent per tick.
    #[classattr]
    const MAX_SUBSAMPLES: usize = pendulab_core::live::session::MAX_SUBSAMPLES;
    /// Longest wall-clock interval \[s\] one tick catches up on.
    #[classattr]
    const MAX_ELAPSED: f64 = pendulab_core::live::session::MAX_ELAPSED;
    /// Most `event` notices sent per tick.
    #[classattr]
    const MAX_EVENT_NOTICES: usize = pendulab_core::live::session::MAX_EVENT_NOTICES;
    /// Most steps of `step` commands waiting.
    #[classattr]
    const MAX_PENDING_STEPS: u64 = pendulab_core::live::session::MAX_PENDING_STEPS;
    /// Longest command message read \[characters\] (`live::wire::MAX_MESSAGE_BYTES`).
    #[classattr]
    const MAX_MESSAGE_BYTES: usize = MAX_MESSAGE_BYTES;

    /// The command types, in the lab's order (`live::wire::COMMAND_TYPES`).
    #[staticmethod]
    fn command_types(py: Python<'_>) -> PyResult<Bound<'_, PyTuple>> {
        PyTuple::new(py, COMMAND_TYPES)
    }

    /// The lab's command limits (`live::wire::LIMITS`, the one table both engines and the server's
    /// pydantic models check against): name → `{"min", "max", "unit"}`, SI units (`n`: steps of one
    /// `step` command).
    #[staticmethod]
    fn limits(py: Python<'_>) -> PyResult<Bound<'_, PyDict>> {
        let out = PyDict::new(py);
        for (name, lo, hi, unit) in LIMITS {
            let d = PyDict::new(py);
            d.set_item("min", lo)?;
            d.set_item("max", hi)?;
            d.set_item("unit", unit)?;
            out.set_item(name, d)?;
        }
        Ok(out)
    }

    /// A session from a scenario's JSON description (`GET /api/scenarios`' entry, with `rtol`, `atol`);
    /// `exact_error=False` estimates the ideal pendulum's error with a companion too.
    #[new]
    #[pyo3(signature = (setup_json, exact_error = true))]
    fn new(setup_json: &str, exact_error: bool) -> PyResult<Self> {
        let s = setup(setup_json).map_err(InvalidInputError::new_err)?;
        let mut inner = LiveSession::new(s).map_err(to_py)?;
        if !exact_error {
            inner.set_exact_error(false).map_err(to_py)?;
        }
        Ok(Self { inner })
    }

    /// What a new connection gets first: the status (str) and the current frame (bytes).
    fn first_messages(&mut self, py: Python<'_>) -> PyResult<Vec<PyObject>> {
        let inner = &mut self.inner;
        let out = py.allow_threads(|| inner.first_messages(&now));
        Ok(messages(py, &out))
    }

    /// One tick: `commands` (module doc) in order, the waiting steps, the advance by `elapsed` wall
    /// seconds, the error estimate, within `budget` seconds of wall time; `dropped` messages thrown
    /// away since the last tick. With `debt` \[s\] the commands are carried out within the budget
    /// (`LiveSession::tick_fair`). Returns (messages, commands carried out, debt).
    #[pyo3(signature = (commands, elapsed, budget, dropped = 0, debt = None))]
    fn tick(
        &mut self,
        py: Python<'_>,
        commands: Vec<Bound<'_, PyAny>>,
        elapsed: f64,
        budget: f64,
        dropped: u64,
        debt: Option<f64>,
    ) -> PyResult<(Vec<PyObject>, usize, Option<f64>)> {
        let items = commands.iter().map(item).collect::<PyResult<Vec<_>>>()?;
        let mut debt = debt;
        let inner = &mut self.inner;
        let (out, taken) =
            py.allow_threads(|| inner.tick_fair(items, elapsed, &now, budget, dropped, debt.as_mut()));
        Ok((messages(py, &out), taken, debt))
    }

    /// Carries out one command (module doc's forms); the record to send at once (a discontinuity) or
    /// None. `InvalidInputError` when it cannot be carried out (the session is unchanged).
    fn apply<'py>(
        &mut self,
        py: Python<'py>,
        command: Bound<'py, PyAny>,
    ) -> PyResult<Option<Bound<'py, PyBytes>>> {
        let cmd = item(&command)?.map_err(|(message, _)| InvalidInputError::new_err(message))?;
        let inner = &mut self.inner;
        let r = py.allow_threads(|| inner.apply(cmd)).map_err(to_py)?;
        Ok(r.map(|r| PyBytes::new(py, &record_bytes(&[r]))))
    }

    /// Advances by `elapsed` wall-clock seconds × time scale within `budget` \[s\]; the records reached
    /// (bytes, error_x unknown).
    fn advance<'py>(&mut self, py: Python<'py>, elapsed: f64, budget: f64) -> PyResult<Bound<'py, PyBytes>> {
        let inner = &mut self.inner;
        let r = py
            .allow_threads(|| inner.advance(elapsed, &pendulab_core::live::Budget::new(&now, budget)))
            .map_err(to_py)?;
        Ok(PyBytes::new(py, &record_bytes(&r)))
    }

    /// Takes the waiting steps of `step` commands within `budget` \[s\]; the record reached or None.
    fn take_pending_steps<'py>(
        &mut self,
        py: Python<'py>,
        budget: f64,
    ) -> PyResult<Option<Bound<'py, PyBytes>>> {
        let inner = &mut self.inner;
        let r = py
            .allow_threads(|| inner.take_pending_steps(&pendulab_core::live::Budget::new(&now, budget)))
            .map_err(to_py)?;
        Ok(r.map(|r| PyBytes::new(py, &record_bytes(&[r]))))
    }

    /// The records (bytes, this stepper's, in time order) with `error_x` \[m\] filled within `budget` \[s\].
    fn fill_errors<'py>(
        &mut self,
        py: Python<'py>,
        records: &[u8],
        budget: f64,
    ) -> PyResult<Bound<'py, PyBytes>> {
        let mut recs = records_from(records)?;
        let inner = &mut self.inner;
        py.allow_threads(|| inner.error.fill(&mut recs, &pendulab_core::live::Budget::new(&now, budget)));
        Ok(PyBytes::new(py, &record_bytes(&recs)))
    }

    /// The string's leaves and snaps since the last call as `event` notices (JSON texts; at most
    /// `MAX_EVENT_NOTICES`, the latest).
    fn take_event_notices(&mut self, py: Python<'_>) -> Vec<PyObject> {
        let out = self.inner.take_event_notices();
        messages(py, &out)
    }

    /// The current state as one record (bytes; error_x unknown).
    fn record<'py>(&self, py: Python<'py>) -> Bound<'py, PyBytes> {
        PyBytes::new(py, &record_bytes(&[self.inner.record()]))
    }

    /// The `status` notice (JSON text).
    fn status(&self) -> String {
        self.inner.status().to_string()
    }

    /// Paused (settable: a pause without a command).
    #[getter]
    fn paused(&self) -> bool {
        self.inner.paused
    }

    #[setter]
    fn set_paused(&mut self, value: bool) {
        self.inner.paused = value;
    }

    /// Discontinuities so far (reset, new state, parameters, model, scenario).
    #[getter]
    fn epoch(&self) -> u64 {
        self.inner.epoch
    }

    /// Out of budget in the last advance.
    #[getter]
    fn lagging(&self) -> bool {
        self.inner.lagging
    }

    /// Steps of `step` commands waiting.
    #[getter]
    fn pending_steps(&self) -> u64 {
        self.inner.pending_steps
    }

    /// Command messages handled (applied, refused or dropped).
    #[getter]
    fn commands(&self) -> u64 {
        self.inner.commands
    }

    /// Time reached \[s\].
    #[getter]
    fn t(&self) -> f64 {
        self.inner.stepper.t()
    }

    /// The simulated time the pacing aims at \[s\].
    #[getter]
    fn clock(&self) -> f64 {
        self.inner.clock()
    }

    /// Position reached \[m\] (relative to the pivot).
    #[getter]
    fn x<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        arr3(py, self.inner.stepper.state().x)
    }

    /// Velocity reached \[m/s\].
    #[getter]
    fn v<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        arr3(py, self.inner.stepper.state().v)
    }

    /// The start the session's error estimate counts from: (t0 \[s\], x \[m\], v \[m/s\]).
    #[getter]
    fn error_start<'py>(
        &self,
        py: Python<'py>,
    ) -> (f64, Bound<'py, PyArray1<f64>>, Bound<'py, PyArray1<f64>>) {
        let (t0, s) = (self.inner.error.t0, self.inner.error.start);
        (t0, arr3(py, s.x), arr3(py, s.v))
    }

    /// Scenario name (None: none).
    #[getter]
    fn scenario(&self) -> Option<String> {
        self.inner.scenario.clone()
    }

    /// The model's registry name.
    #[getter]
    fn model(&self) -> &'static str {
        self.inner.pendulum.model
    }

    /// The method's name.
    #[getter]
    fn method(&self) -> &'static str {
        self.inner.method.info().name
    }

    /// Step \[s\].
    #[getter]
    fn dt(&self) -> f64 {
        self.inner.dt
    }

    /// Simulated seconds per wall-clock second.
    #[getter]
    fn time_scale(&self) -> f64 {
        self.inner.time_scale
    }
}

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<PyLiveSession>()?;
    Ok(())
}
