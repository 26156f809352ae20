//! Binding of the linearised slewing crane (`pendulab_core::model::slewing_linear`, T-7.2): the
//! closed-form boom-frame sway. Conversions only; SI units.

use crate::convert::{to_py, InvalidInputError};
use crate::spec::ModelSpec;
use numpy::{IntoPyArray, PyReadonlyArray1};
use pendulab_core::model::registry::AnyModel;
use pendulab_core::model::slewing_linear::{LinearSlewing, Sway};
use pendulab_core::model::PivotPath;
use pendulab_core::Model;
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// The small-sway response of the spec's `slewing` model (l [m], g [m/s²], boom radius R [m], rate
/// ω [rad/s], damping c [1/s]; the pivot height does not enter) from the boom-frame `start` (x₀,
/// y₀ [m], ẋ₀, ẏ₀ [m/s]) at t = 0, at times t [s]: a dict of arrays x, y, vx, vy (radial,
/// tangential) and static_offset (radial, tangential) [m], frequencies (|Ω − ω|, Ω + ω) [rad/s].
#[pyfunction]
pub fn slewing_linear<'py>(
    py: Python<'py>,
    spec: &ModelSpec,
    start: [f64; 4],
    t: PyReadonlyArray1<'py, f64>,
) -> PyResult<Bound<'py, PyDict>> {
    let model = spec.registry()?;
    let (Some(&PivotPath::Slewing { radius, rate, .. }), AnyModel::Pivot(pivot)) = (model.pivot(), &model)
    else {
        return Err(InvalidInputError::new_err(format!(
            "the linearised sway is the slewing crane's, not the {:?} model's",
            spec.name()
        )));
    };
    let m = LinearSlewing::new(model.params(), radius, rate, pivot.damping()).map_err(to_py)?;
    let s0 = Sway { x: start[0], y: start[1], vx: start[2], vy: start[3] };
    if let Some(bad) = start.iter().find(|v| !v.is_finite()) {
        return Err(InvalidInputError::new_err(format!("the start {start:?} has a non-finite value {bad}")));
    }
    let ts = t.as_array();
    if let Some(bad) = ts.iter().find(|v| !v.is_finite()) {
        return Err(InvalidInputError::new_err(format!("t contains the non-finite time {bad} s")));
    }
    let track: Vec<Sway> = ts.iter().map(|&ti| m.sway(s0, ti)).collect();
    let d = PyDict::new(py);
    d.set_item("x", track.iter().map(|s| s.x).collect::<Vec<_>>().into_pyarray(py))?;
    d.set_item("y", track.iter().map(|s| s.y).collect::<Vec<_>>().into_pyarray(py))?;
    d.set_item("vx", track.iter().map(|s| s.vx).collect::<Vec<_>>().into_pyarray(py))?;
    d.set_item("vy", track.iter().map(|s| s.vy).collect::<Vec<_>>().into_pyarray(py))?;
    d.set_item("static_offset", m.static_offset())?;
    d.set_item("frequencies", m.frequencies())?;
    Ok(d)
}

/// Registers the function.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(slewing_linear, m)?)
}
