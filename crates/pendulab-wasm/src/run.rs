//! A plain trajectory of any lab model (no pacing, no budget): what the parity test and the benchmark
//! compare between the native build and WebAssembly. Input JSON: `model`, `length` \[m\], `mass` \[kg\],
//! `g` [m/s²], `params` (own, SI), the start as `theta`, `phi` \[rad\], `theta_dot`, `phi_dot` [rad/s],
//! `method`, `dt` \[s\], `steps` (per record; `dop853` lands on the records' times k·steps·dt) and `records`; output: the records' float64 values
//! (frame.json's layout, error_x unknown) — `records + 1` of them, the start first.

use pendulab_core::live::{LivePendulum, LiveStepper, Record};
use pendulab_core::Method;
use serde_json::Value;

/// Most steps of one run (bounds the work of one call).
pub const MAX_STEPS: f64 = 1e9;
/// Most records of one run (bounds the memory: 152 bytes each).
pub const MAX_RECORDS: f64 = 1e6;

/// The trajectory described by `spec` (the module doc), or what is wrong with the spec.
pub fn run(spec: &str) -> Result<Vec<Record>, String> {
    let s: Value = serde_json::from_str(spec).map_err(|e| format!("run: not JSON: {e}"))?;
    let num = |k: &str, default: f64| {
        s.get(k).map_or(Some(default), Value::as_f64).ok_or(format!("run: {k} is not a number"))
    };
    let own: Vec<(String, f64)> = s["params"]
        .as_object()
        .map(|m| m.iter().filter_map(|(k, v)| v.as_f64().map(|x| (k.clone(), x))).collect())
        .unwrap_or_default();
    let model = s["model"].as_str().unwrap_or("ideal");
    let p = LivePendulum::new(model, num("length", 1.0)?, num("mass", 1.0)?, num("g", 9.81)?, &own)
        .map_err(|e| e.to_string())?;
    let start = p
        .state_from_angles(num("theta", 1.0)?, num("phi", 0.0)?, num("theta_dot", 0.0)?, num("phi_dot", 0.0)?)
        .map_err(|e| e.to_string())?;
    let method = Method::from_name(s["method"].as_str().unwrap_or("rattle")).map_err(|e| e.to_string())?;
    let (steps, records) = (num("steps", 1.0)?, num("records", 1.0)?);
    if !(steps >= 1.0 && (1.0..=MAX_RECORDS).contains(&records) && steps * records <= MAX_STEPS) {
        return Err(format!(
            "run: steps = {steps}, records = {records}: whole numbers >= 1 with records <= {MAX_RECORDS:e} and \
             steps × records <= {MAX_STEPS:e}"
        ));
    }
    let dt = if method.info().adaptive { 0.0 } else { num("dt", 1e-3)? };
    let mut st = LiveStepper::new(&p, start, 0.0, method, dt, 1e-10, 1e-12).map_err(|e| e.to_string())?;
    let mut out = vec![st.record()];
    for k in 1..=records as u64 {
        if method.info().adaptive {
            // dop853: the records at k·steps·dt [s] (it lands on each), whatever its own steps
            let t = k as f64 * steps * num("dt", 1e-3)?;
            st.step_to_capped(t, MAX_STEPS as u64).map_err(|e| e.to_string())?;
        } else {
            st.step(steps as u64).map_err(|e| e.to_string())?;
        }
        out.push(st.record());
    }
    Ok(out)
}
