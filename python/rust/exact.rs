//! Bindings of the exact solution (`pendulab_core::exact`), the reduction (`pendulab_core::reduce`)
//! and the energy–momentum map. Conversions only; SI units (m, kg, s, rad) except where a function
//! says it works in Holm's unit-length variables (σ) or dimensionless (ε, j).

use crate::convert::{model, to_py, InvalidInputError};
use crate::spec::{start, ModelSpec, RunOptions, StateArrays};
use numpy::ndarray::{Array1, Array2};
use numpy::{IntoPyArray, PyArray1, PyArray2, PyReadonlyArray1, PyReadonlyArray2};
use pendulab_core::exact::energy_momentum::{conical_boundary, monodromy_change, rotation_number};
use pendulab_core::exact::phases::phases;
use pendulab_core::exact::ExactSolution;
use pendulab_core::{reduce, DVec3, Params, State};
use pyo3::prelude::*;
use pyo3::types::PyDict;

type Xv<'py> = (Bound<'py, PyArray2<f64>>, Bound<'py, PyArray2<f64>>);

/// The l [m], m [kg], g [m/s²] of the spec's model, which must be the ideal pendulum: the exact
/// solution and the reduced flow are its own.
fn ideal(spec: &ModelSpec) -> PyResult<Params> {
    if spec.name() != "ideal" {
        return Err(InvalidInputError::new_err(format!(
            "the exact solution and the reduced flow are the ideal pendulum's, not the {:?} model's",
            spec.name()
        )));
    }
    spec.params()
}

fn states_from(x: &PyReadonlyArray2<'_, f64>, v: &PyReadonlyArray2<'_, f64>) -> PyResult<Vec<State>> {
    let (x, v) = (x.as_array(), v.as_array());
    if x.ncols() != 3 || v.dim() != x.dim() {
        return Err(InvalidInputError::new_err(format!(
            "x and v must both have shape (N, 3), got {:?} and {:?}",
            x.dim(),
            v.dim()
        )));
    }
    Ok((0..x.nrows())
        .map(|i| State {
            x: DVec3::new(x[[i, 0]], x[[i, 1]], x[[i, 2]]),
            v: DVec3::new(v[[i, 0]], v[[i, 1]], v[[i, 2]]),
        })
        .collect())
}

fn to_arrays<'py>(py: Python<'py>, states: &[State]) -> Xv<'py> {
    let n = states.len();
    let (mut x, mut v) = (Array2::<f64>::zeros((n, 3)), Array2::<f64>::zeros((n, 3)));
    for (i, s) in states.iter().enumerate() {
        for k in 0..3 {
            x[[i, k]] = s.x[k];
            v[[i, k]] = s.v[k];
        }
    }
    (x.into_pyarray(py), v.into_pyarray(py))
}

/// The exact solution through a state at t = 0 (docs/theory.md §4), any g.
#[pyclass(module = "pendulab._core", name = "ExactSolution", frozen)]
pub struct Exact {
    inner: ExactSolution,
}

#[pymethods]
impl Exact {
    /// The exact solution of the spec's ideal pendulum through the start `state` = (x0 [m], v0 [m/s]).
    #[new]
    fn new(spec: &ModelSpec, state: StateArrays<'_>) -> PyResult<Self> {
        let params = ideal(spec)?;
        let (x, v) = start(&state)?;
        Ok(Self { inner: ExactSolution::new(&params, &State { x, v }).map_err(to_py)? })
    }

    /// States at times `t` [s] (1-D): (x [m] (N, 3), v [m/s] (N, 3), φ [rad] (N,), continuous).
    #[allow(clippy::type_complexity)]
    fn states<'py>(
        &self,
        py: Python<'py>,
        t: PyReadonlyArray1<'py, f64>,
    ) -> PyResult<(Bound<'py, PyArray2<f64>>, Bound<'py, PyArray2<f64>>, Bound<'py, PyArray1<f64>>)> {
        let t = t.as_array().to_vec();
        if let Some((i, bad)) = t.iter().enumerate().find(|(_, v)| !v.is_finite()) {
            return Err(InvalidInputError::new_err(format!("t[{i}] = {bad} is not a finite time (s)")));
        }
        let inner = &self.inner;
        let pairs: Vec<(State, f64)> = py.allow_threads(|| inner.states_at(&t)).map_err(to_py)?;
        let (states, phi): (Vec<State>, Vec<f64>) = pairs.into_iter().unzip();
        let (x, v) = to_arrays(py, &states);
        Ok((x, v, Array1::from(phi).into_pyarray(py)))
    }

    /// "generic", "conical", "planar", "planar_rotating", "separatrix", "rest" or "great_circle".
    #[getter]
    fn kind(&self) -> &'static str {
        self.inner.kind().name()
    }
    /// (z₁, z₂, z₃ or None) [m].
    #[getter]
    fn turning_heights(&self) -> (f64, f64, Option<f64>) {
        self.inner.turning_heights()
    }
    /// Parameter m = k² of the Jacobi functions.
    #[getter]
    fn modulus(&self) -> Option<f64> {
        self.inner.modulus()
    }
    /// Period of z [s] (swing period for planar motion).
    #[getter]
    fn period_z(&self) -> Option<f64> {
        self.inner.period_z()
    }
    /// Azimuthal advance per z-period Δφ [rad] (generic and conical orbits).
    #[getter]
    fn azimuth_advance(&self) -> Option<f64> {
        self.inner.azimuth_advance()
    }
    /// ω₀ = √(|g|/l) [1/s].
    #[getter]
    fn omega0(&self) -> f64 {
        self.inner.omega0()
    }

    /// Phases per z-period (T-5.1) of a generic orbit: (total, dynamic, geometric) [rad], else None.
    fn phases(&self) -> PyResult<Option<(f64, f64, f64)>> {
        let Some(g) = self.inner.generic() else { return Ok(None) };
        let p = phases(g).map_err(to_py)?;
        Ok(Some((p.total, p.dynamic, p.geometric)))
    }

    /// The dimensionless constants of a generic orbit (u₁, u₂, u₃, m, λ, n±, K, ε, j), else None.
    fn constants<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyDict>>> {
        let Some(g) = self.inner.generic() else { return Ok(None) };
        let d = PyDict::new(py);
        let [r1, r2, r3] = g.roots;
        d.set_item("u1", g.start.value(r1))?;
        d.set_item("u2", g.start.value(r2))?;
        d.set_item("u3", g.start.value(r3))?;
        d.set_item("m", g.m)?;
        d.set_item("lambda", g.lambda)?;
        d.set_item("n_plus", g.n_plus)?;
        d.set_item("n_minus", g.n_minus)?;
        d.set_item("K", g.k)?;
        d.set_item("epsilon", g.start.epsilon())?;
        d.set_item("j", g.start.j)?;
        Ok(Some(d))
    }

    /// The Weierstrass form (T-4.7), dimensionless: g2, g3, e (e₁ ≥ e₂ ≥ e₃), omega1 (the real
    /// half-period in τ = ω₀t, inf on the separatrix), shift (ε/3 in u = 2℘ + ε/3). None at rest and for
    /// g = 0.
    fn weierstrass<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyDict>>> {
        let Some(w) = self.inner.weierstrass() else { return Ok(None) };
        let d = PyDict::new(py);
        d.set_item("g2", w.g2)?;
        d.set_item("g3", w.g3)?;
        d.set_item("e", w.e.to_vec())?;
        d.set_item("omega1", w.omega1)?;
        d.set_item("shift", w.shift)?;
        Ok(Some(d))
    }

    /// z(t) [m] and ż(t) [m/s] at times `t` [s] (1-D) through the Weierstrass form; None where
    /// `weierstrass` is None.
    #[allow(clippy::type_complexity)]
    fn heights_weierstrass<'py>(
        &self,
        py: Python<'py>,
        t: PyReadonlyArray1<'py, f64>,
    ) -> PyResult<Option<(Bound<'py, PyArray1<f64>>, Bound<'py, PyArray1<f64>>)>> {
        let t = t.as_array().to_vec();
        if let Some((i, bad)) = t.iter().enumerate().find(|(_, v)| !v.is_finite()) {
            return Err(InvalidInputError::new_err(format!("t[{i}] = {bad} is not a finite time (s)")));
        }
        let inner = &self.inner;
        let out = py.allow_threads(|| inner.height_weierstrass(&t)).map_err(to_py)?;
        Ok(out.map(|pairs| {
            let (z, zdot): (Vec<f64>, Vec<f64>) = pairs.into_iter().unzip();
            (Array1::from(z).into_pyarray(py), Array1::from(zdot).into_pyarray(py))
        }))
    }
}

/// σ₁ … σ₆ (T-3.1, units of l) along x, v of shape (N, 3): shape (N, 6).
#[pyfunction]
pub fn invariants<'py>(
    py: Python<'py>,
    length: f64,
    x: PyReadonlyArray2<'py, f64>,
    v: PyReadonlyArray2<'py, f64>,
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    model(length, 1.0, 0.0)?;
    let states = states_from(&x, &v)?;
    let mut out = Array2::<f64>::zeros((states.len(), 6));
    for (i, s) in states.iter().enumerate() {
        for (k, val) in reduce::invariants(length, s).into_iter().enumerate() {
            out[[i, k]] = val;
        }
    }
    Ok(out.into_pyarray(py))
}

/// Residuals of the relations T-3.2 for σ of shape (N, 6): shape (N, 4).
#[pyfunction]
pub fn relation_residuals<'py>(
    py: Python<'py>,
    sigma: PyReadonlyArray2<'py, f64>,
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let s = sigma.as_array();
    if s.ncols() != 6 {
        return Err(InvalidInputError::new_err(format!("sigma must have shape (N, 6), got {:?}", s.dim())));
    }
    let mut out = Array2::<f64>::zeros((s.nrows(), 4));
    for i in 0..s.nrows() {
        let row: [f64; 6] = std::array::from_fn(|k| s[[i, k]]);
        for (k, r) in reduce::relation_residuals(&row).into_iter().enumerate() {
            out[[i, k]] = r;
        }
    }
    Ok(out.into_pyarray(py))
}

/// The reduced flow T-3.4 with reconstruction T-3.6 by RK4 for the spec's ideal pendulum from
/// `state` = (x0 [m], v0 [m/s]): `n_steps` steps of the options' dt [s] → (x, v) (n + 1, 3).
#[pyfunction]
pub fn reduced_flow<'py>(
    py: Python<'py>,
    spec: &ModelSpec,
    state: StateArrays<'py>,
    options: &RunOptions,
    n_steps: usize,
) -> PyResult<Xv<'py>> {
    let params = ideal(spec)?;
    let (x, v) = start(&state)?;
    let s = State::on_tangent_bundle(&params, x, v).map_err(to_py)?;
    let dt = options.solve.dt;
    let states =
        py.allow_threads(|| reduce::reduced_flow(params.length, params.g, &s, dt, n_steps)).map_err(to_py)?;
    Ok(to_arrays(py, &states))
}

/// Rotation numbers W = Δφ/2π on arrays ε (dimensionless energy E/(m g l)) and j (J₃/(m l² ω₀)) of
/// equal shape (flattened); NaN outside the image of the energy–momentum map and on j = 0.
#[pyfunction]
pub fn rotation_numbers<'py>(
    py: Python<'py>,
    eps: PyReadonlyArray1<'py, f64>,
    j: PyReadonlyArray1<'py, f64>,
) -> PyResult<Bound<'py, PyArray1<f64>>> {
    let (e, jj) = (eps.as_array().to_vec(), j.as_array().to_vec());
    if e.len() != jj.len() {
        return Err(InvalidInputError::new_err(format!(
            "eps and j must have the same length, got {} and {}",
            e.len(),
            jj.len()
        )));
    }
    let w: Vec<f64> = py.allow_threads(|| {
        e.iter().zip(&jj).map(|(&e, &j)| rotation_number(e, j).unwrap_or(f64::NAN)).collect()
    });
    Ok(Array1::from(w).into_pyarray(py))
}

/// The conical boundary of the energy–momentum image at heights u ∈ (−1, 0): (j, ε) arrays.
#[pyfunction]
pub fn conical_curve<'py>(
    py: Python<'py>,
    u: PyReadonlyArray1<'py, f64>,
) -> (Bound<'py, PyArray1<f64>>, Bound<'py, PyArray1<f64>>) {
    let (j, e): (Vec<f64>, Vec<f64>) = u.as_array().iter().map(|&u| conical_boundary(u)).unzip();
    (Array1::from(j).into_pyarray(py), Array1::from(e).into_pyarray(py))
}

/// Change of W carried once around the top value (0, 1) on a circle of radius r in (j, ε) (T-6.4).
#[pyfunction]
#[pyo3(signature = (r=0.5, n=720))]
pub fn monodromy(r: f64, n: usize) -> PyResult<f64> {
    monodromy_change(r, n).ok_or_else(|| {
        InvalidInputError::new_err(format!(
            "the circle of radius r = {r} around (j, ε) = (0, 1) must lie inside the image \
             (0 < r < 1.5) and have n >= 8 points (got n = {n})"
        ))
    })
}

/// Registers the functions and classes of this file.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<Exact>()?;
    m.add_function(wrap_pyfunction!(invariants, m)?)?;
    m.add_function(wrap_pyfunction!(relation_residuals, m)?)?;
    m.add_function(wrap_pyfunction!(reduced_flow, m)?)?;
    m.add_function(wrap_pyfunction!(rotation_numbers, m)?)?;
    m.add_function(wrap_pyfunction!(conical_curve, m)?)?;
    m.add_function(wrap_pyfunction!(monodromy, m)?)?;
    Ok(())
}
