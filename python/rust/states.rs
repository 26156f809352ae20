//! States and their diagnostics: a state checked to lie on TS², moved onto it, or built from angles,
//! and the diagnostics along arrays of states (energy T-2.6, J₃, tension T-2.3, the residuals of
//! TS², power, the acceleration of T-2.2, the pivot's path). SI units: x [m], v [m/s], t [s], angles
//! [rad], arrays of 3-vectors (N, 3).

use crate::convert::{arr3, to_py, vec3, InvalidInputError, StatePair};
use crate::spec::ModelSpec;
use numpy::ndarray::Array2;
use numpy::{IntoPyArray, PyReadonlyArray1, PyReadonlyArray2};
use pendulab_core::model::{acceleration, energy, j3, tension};
use pendulab_core::{DVec3, Model, State};
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// The state (x, v) checked to lie on TS² of the spec's model (|x| = l [m], x·v = 0) within the
/// core tolerance.
#[pyfunction]
fn state_on_ts2<'py>(
    py: Python<'py>,
    spec: &ModelSpec,
    x: PyReadonlyArray1<'py, f64>,
    v: PyReadonlyArray1<'py, f64>,
) -> PyResult<StatePair<'py>> {
    let s = State::on_tangent_bundle(&spec.params()?, vec3("x", &x)?, vec3("v", &v)?).map_err(to_py)?;
    Ok((arr3(py, s.x), arr3(py, s.v)))
}

/// (x, v) moved onto TS² of the spec's model, with the distances moved |Δx| [m] and |Δv| [m/s].
#[pyfunction]
fn project_state<'py>(
    py: Python<'py>,
    spec: &ModelSpec,
    x: PyReadonlyArray1<'py, f64>,
    v: PyReadonlyArray1<'py, f64>,
) -> PyResult<(StatePair<'py>, f64, f64)> {
    let (s, p) = State::projected(&spec.params()?, vec3("x", &x)?, vec3("v", &v)?).map_err(to_py)?;
    Ok(((arr3(py, s.x), arr3(py, s.v)), p.dx, p.dv))
}

/// The state of the spec's model at polar angle θ [rad] from the downward vertical, azimuth φ [rad]
/// and their rates (θ̇, φ̇) [rad/s], given as `angles` = (θ, φ, θ̇, φ̇).
#[pyfunction]
fn state_from_angles<'py>(py: Python<'py>, spec: &ModelSpec, angles: [f64; 4]) -> PyResult<StatePair<'py>> {
    let [theta, phi, theta_dot, phi_dot] = angles;
    let s = State::from_angles(&spec.params()?, theta, phi, theta_dot, phi_dot).map_err(to_py)?;
    Ok((arr3(py, s.x), arr3(py, s.v)))
}

/// Diagnostics of the spec's model along arrays x, v of shape (N, 3) at times t [s] (default 0):
/// energy [J], j3 [kg m²/s], tension [N], radius_error = |x| − l(t) [m], tangency = x·v − l l̇
/// [m²/s] (l̇ ≠ 0 only for a hoisted rope), power [W], acceleration (N, 3) [m/s²]; a moving pivot's
/// path (N, 3) [m] when t is given.
#[pyfunction]
#[pyo3(signature = (spec, x, v, t=None))]
fn diagnostics<'py>(
    py: Python<'py>,
    spec: &ModelSpec,
    x: PyReadonlyArray2<'py, f64>,
    v: PyReadonlyArray2<'py, f64>,
    t: Option<PyReadonlyArray1<'py, f64>>,
) -> PyResult<Bound<'py, PyDict>> {
    let m = spec.registry()?;
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
        let ti = times.as_ref().map_or(0.0, |ts| ts[i]);
        // the rope's length l(t) and rate (a hoisted rope: |x| = l(t), x·v = l l̇; else l and 0)
        let (l_t, rate) = (m.rope_length(ti), m.rope_rate(ti));
        let r = s.residuals(l_t);
        out[0][i] = energy(&m, &s);
        out[1][i] = j3(&m, &s);
        out[2][i] = tension(&m, ti, &s);
        out[5][i] = m.params().mass * m.power_per_mass(ti, s.x, s.v);
        out[3][i] = r.length;
        out[4][i] = r.tangency - l_t * rate;
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
        let state = State {
            x: DVec3::new(x[[i, 0]], x[[i, 1]], x[[i, 2]]),
            v: DVec3::new(v[[i, 0]], v[[i, 1]], v[[i, 2]]),
        };
        let a = m.physical_acceleration(ti, &state).unwrap_or_else(|| acceleration(&m, ti, state.x, state.v));
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

/// Registers the functions.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(state_on_ts2, m)?)?;
    m.add_function(wrap_pyfunction!(project_state, m)?)?;
    m.add_function(wrap_pyfunction!(state_from_angles, m)?)?;
    m.add_function(wrap_pyfunction!(diagnostics, m)?)
}
