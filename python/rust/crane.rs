//! Binding of the crane dynamics (`pendulab_core::crane`, docs/theory.md T-11.4 – T-11.7): the crane
//! as one `CraneSpec` (knots of the prescribed pivot path and rope length, bodies, wind) and a run's
//! `RunOptions` (save times, tolerances, step cap) in, saved states and tensions out. Conversions
//! only; SI units (m, kg, s, N, J). The GIL is released while the core integrates.

use crate::convert::{to_py, InvalidInputError};
use crate::spec::RunOptions;
use numpy::ndarray::Array2;
use numpy::{IntoPyArray, PyReadonlyArray1, PyReadonlyArray2};
use pendulab_core::crane::{
    residual_grid, run, Body, CraneSystem, GridSpec, Hermite5, Knot, Tolerances, Wind,
};
use pendulab_core::{DVec3, SaveAt};
use pyo3::prelude::*;
use pyo3::types::PyDict;

type KnotArrays<'py> = (
    PyReadonlyArray1<'py, f64>,
    PyReadonlyArray2<'py, f64>,
    PyReadonlyArray2<'py, f64>,
    PyReadonlyArray2<'py, f64>,
);

fn knots(name: &str, k: &KnotArrays<'_>) -> PyResult<Hermite5> {
    let t = k.0.as_array();
    let (q, dq, ddq) = (k.1.as_array(), k.2.as_array(), k.3.as_array());
    let n = t.len();
    for (what, a) in [("values", &q), ("rates", &dq), ("second derivatives", &ddq)] {
        if a.shape() != [n, 3] {
            return Err(InvalidInputError::new_err(format!(
                "{name} {what} have shape {:?}; expected ({n}, 3) for {n} knot times",
                a.shape()
            )));
        }
    }
    let v = |a: &numpy::ndarray::ArrayView2<'_, f64>, i: usize| DVec3::new(a[[i, 0]], a[[i, 1]], a[[i, 2]]);
    let list = (0..n).map(|i| Knot { t: t[i], q: v(&q, i), dq: v(&dq, i), ddq: v(&ddq, i) }).collect();
    Hermite5::new(name, list).map_err(to_py)
}

/// Wind as given: steady (3,) [m/s], gust peak (3,) [m/s], gust start [s], duration [s], air density
/// [kg/m³], turbulence modes (ω_k [rad/s] (K,), amplitudes [m/s] (K, 3), phases [rad] (K, 3)).
type WindArgs = ([f64; 3], [f64; 3], f64, f64, f64, (Vec<f64>, Vec<[f64; 3]>, Vec<[f64; 3]>));

/// The bodies as given: the hook or the payload (mass [kg], c_W A [m²]), and the payload under a
/// hook (mass [kg], c_W A [m²], rigging [m]) or None.
type Bodies = ((f64, f64), Option<(f64, f64, f64)>);

/// The crane as one description crossing the border (`pendulab_core::crane::CraneSystem`): `pivot`
/// and `hoist` as knots (t [s] (n,), value, rate, second derivative (n, 3); the rope length in the
/// first column), `bodies` = (hook or payload (mass [kg], c_W A [m²]), the payload under a hook
/// (mass [kg], c_W A [m²], rigging [m]) or None), g [m/s²], damping [1/s] and the wind
/// ([`WindArgs`]). Built and checked once.
#[pyclass(module = "pendulab._core", name = "CraneSpec", frozen)]
pub struct CraneSpec {
    sys: CraneSystem,
}

#[pymethods]
impl CraneSpec {
    #[new]
    fn new(
        pivot: KnotArrays<'_>,
        hoist: KnotArrays<'_>,
        bodies: Bodies,
        g: f64,
        damping: f64,
        wind: WindArgs,
    ) -> PyResult<Self> {
        let (om, amp, ph) = wind.5;
        if amp.len() != om.len() || ph.len() != om.len() {
            return Err(InvalidInputError::new_err(format!(
                "turbulence: {} frequencies, {} amplitudes, {} phases; give as many of each",
                om.len(),
                amp.len(),
                ph.len()
            )));
        }
        let modes =
            (0..om.len()).map(|k| (om[k], DVec3::from_array(amp[k]), DVec3::from_array(ph[k]))).collect();
        let (body1, body2) = bodies;
        let sys = CraneSystem {
            pivot: knots("pivot", &pivot)?,
            hoist: knots("hoist", &hoist)?,
            body1: Body { mass: body1.0, drag_area: body1.1 },
            body2: body2.map(|(m, a, l2)| (Body { mass: m, drag_area: a }, l2)),
            g,
            damping,
            wind: Wind {
                steady: DVec3::from_array(wind.0),
                gust: DVec3::from_array(wind.1),
                gust_start: wind.2,
                gust_duration: wind.3,
                air_density: wind.4,
                turbulence: modes,
            },
        };
        Ok(Self { sys })
    }
}

/// The run's tolerances rtol, atol [m, m/s] and step cap (`max_steps`, required) of `options`.
fn tolerances(options: &RunOptions) -> PyResult<Tolerances> {
    let max_steps = options
        .max_steps
        .ok_or_else(|| InvalidInputError::new_err("a crane run needs max_steps in its RunOptions"))?;
    Ok(Tolerances { rtol: options.solve.rtol, atol: options.solve.atol, max_steps })
}

/// Integrates the crane `spec` (`pendulab_core::crane::run`) from the start y0 (16,) at the first
/// of the options' `save_times` [s] through all of them, at the options' rtol, atol and max_steps.
/// Returns a dict: t (N,), y (N, 16), tension (N, 2) [N], steps, rejected.
#[pyfunction]
pub fn crane_simulate<'py>(
    py: Python<'py>,
    spec: &CraneSpec,
    y0: [f64; 16],
    options: &RunOptions,
) -> PyResult<Bound<'py, PyDict>> {
    let SaveAt::Times(save) = options.save.clone() else {
        return Err(InvalidInputError::new_err("a crane run saves at given times: give save_times [s]"));
    };
    let t0 = save.first().copied().unwrap_or(0.0);
    let tol = tolerances(options)?;
    let sys = &spec.sys;
    let out = py.allow_threads(|| run(sys, t0, y0, &save, tol)).map_err(to_py)?;
    let n = out.t.len();
    let mut y = Array2::<f64>::zeros((n, 16));
    let mut ten = Array2::<f64>::zeros((n, 2));
    for i in 0..n {
        for k in 0..16 {
            y[[i, k]] = out.y[i][k];
        }
        ten[[i, 0]] = out.tension[i].0;
        ten[[i, 1]] = out.tension[i].1;
    }
    let d = PyDict::new(py);
    d.set_item("t", out.t.into_pyarray(py))?;
    d.set_item("y", y.into_pyarray(py))?;
    d.set_item("tension", ten.into_pyarray(py))?;
    d.set_item("steps", out.steps.0)?;
    d.set_item("rejected", out.steps.1)?;
    Ok(d)
}

/// The residual sway [m] of hook + payload cranes (`pendulab_core::crane::grid`) for every
/// (move, rope [m], ratio m₂/m₁): `moves` as (knots, move end [s]); `crane` = (hook mass [kg],
/// rigging [m], g [m/s²]); `settle` [s] after the move; the options' dt [s] (the save interval),
/// rtol, atol and max_steps. Returns (n_moves·n_ropes·n_ratios,) in that order. Runs in parallel
/// with the GIL released.
#[pyfunction]
pub fn crane_residual_grid<'py>(
    py: Python<'py>,
    moves: Vec<(KnotArrays<'py>, f64)>,
    ropes: Vec<f64>,
    ratios: Vec<f64>,
    crane: (f64, f64, f64),
    settle: f64,
    options: &RunOptions,
) -> PyResult<Bound<'py, numpy::PyArray1<f64>>> {
    let paths = moves.iter().map(|(k, end)| Ok((knots("pivot", k)?, *end))).collect::<PyResult<Vec<_>>>()?;
    let (hook_mass, rigging, g) = crane;
    let spec = GridSpec { hook_mass, rigging, g, settle, dt: options.solve.dt, tol: tolerances(options)? };
    let out = py.allow_threads(|| residual_grid(&paths, &ropes, &ratios, &spec)).map_err(to_py)?;
    Ok(out.into_pyarray(py))
}

/// Registers the functions.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<CraneSpec>()?;
    m.add_function(wrap_pyfunction!(crane_simulate, m)?)?;
    m.add_function(wrap_pyfunction!(crane_residual_grid, m)?)
}
