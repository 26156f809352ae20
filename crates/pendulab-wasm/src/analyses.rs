//! The server's quick analyses answered in the page (docs/lab.md): `POST /api/exact` — the exact
//! solution's quantities of the ideal pendulum's orbit through a state (T-4.1–T-4.6, phases T-5.1) — and
//! `POST /api/effective_potential` — V_eff(θ) = −m g l cos θ + J₃²/(2 m l² sin²θ) \[J\] (T-2.5) — with the
//! same request bodies, limits and answers as `pendulab.server.rest`. SI units: l \[m\], m \[kg\], g [m/s²],
//! J₃ [kg m²/s], θ \[rad\], periods \[s\].

use crate::wire::LIMITS;
use pendulab_core::error::Shown;
use pendulab_core::exact::energy_momentum::conical_boundary;
use pendulab_core::exact::phases::phases;
use pendulab_core::exact::ExactSolution;
use pendulab_core::model::{energy, j3, IdealPendulum};
use pendulab_core::reduce::invariants;
use pendulab_core::state::Params;
use pendulab_core::{DVec3, State};
use serde_json::{json, Value};
use std::f64::consts::PI;

/// An answer: HTTP status and JSON body (errors as `{"detail": …}`).
pub type Answer = (u16, Value);

fn unprocessable(message: String) -> Answer {
    (422, json!({ "detail": message }))
}

fn finite(v: f64) -> Value {
    if v.is_finite() {
        json!(v)
    } else {
        Value::Null
    }
}

fn field(body: &Value, key: &str, default: f64) -> Result<f64, String> {
    match body.get(key) {
        None | Some(Value::Null) => Ok(default),
        Some(v) => {
            let x = v
                .as_f64()
                .filter(|x| x.is_finite())
                .ok_or(format!("{key} = {v}: input should be a finite number"))?;
            if let Some((_, lo, hi, unit)) = LIMITS.iter().find(|(n, ..)| *n == key) {
                if !(x >= *lo && x <= *hi) {
                    return Err(format!(
                        "{key} = {v}: must be between {} and {} {unit}",
                        Shown(*lo),
                        Shown(*hi)
                    ));
                }
            }
            Ok(x)
        }
    }
}

fn params(body: &Value) -> Result<Params, String> {
    let (l, m, g) = (field(body, "length", 1.0)?, field(body, "mass", 1.0)?, field(body, "g", 9.81)?);
    Params::new(l, m, g).map_err(|e| e.to_string())
}

fn state(body: &Value, p: &Params) -> Result<State, String> {
    let vec = |k: &str| -> Option<DVec3> {
        let a: Vec<f64> = body.get(k)?.as_array()?.iter().filter_map(Value::as_f64).collect();
        (a.len() == 3).then(|| DVec3::new(a[0], a[1], a[2]))
    };
    if let (Some(x), Some(v)) = (vec("x"), vec("v")) {
        let project = body.get("project").and_then(Value::as_bool).unwrap_or(false);
        return if project {
            State::projected(p, x, v).map(|s| s.0)
        } else {
            State::on_tangent_bundle(p, x, v)
        }
        .map_err(|e| e.to_string());
    }
    let a = |k: &str| body.get(k).and_then(Value::as_f64).unwrap_or(0.0);
    if body.get("theta").is_none() {
        return Err("give x and v (m, m/s), or at least theta (rad) with phi, theta_dot, phi_dot".into());
    }
    State::from_angles(p, a("theta"), a("phi"), a("theta_dot"), a("phi_dot")).map_err(|e| e.to_string())
}

/// `POST /api/exact`.
pub fn exact_quantities(body: &Value) -> Answer {
    let result = (|| -> Result<Value, String> {
        let p = params(body)?;
        let s = state(body, &p)?;
        let sol = ExactSolution::new(&p, &s).map_err(|e| e.to_string())?;
        let model = IdealPendulum::new(p.length, p.mass, p.g).map_err(|e| e.to_string())?;
        let (z1, z2, z3) = sol.turning_heights();
        let mut heights = vec![finite(z1), finite(z2)];
        if let Some(z) = z3 {
            heights.push(finite(z));
        }
        let (ph, note) = match sol.generic().map(phases) {
            Some(Ok(ph)) => (json!({ "total": ph.total, "dynamic": ph.dynamic, "geometric": ph.geometric }), Value::Null),
            Some(Err(e)) => (Value::Null, json!(e.to_string())),
            None => (
                Value::Null,
                json!(format!(
                    "phases are defined for orbits with J3 != 0 and g != 0 (kinds generic, conical); this orbit is {:?}",
                    sol.kind().name()
                )),
            ),
        };
        let period = sol.period_z();
        let advance = sol.azimuth_advance();
        Ok(json!({
            "kind": sol.kind().name(),
            "energy": energy(&model, &s),
            "j3": j3(&model, &s),
            "omega0": sol.omega0(),
            "turning_heights": heights,
            "modulus": sol.modulus().map_or(Value::Null, finite),
            "period_z": period.map_or(Value::Null, finite),
            "period_z_infinite": period == Some(f64::INFINITY),
            "azimuth_advance": advance.map_or(Value::Null, finite),
            "rotation_number": advance.map_or(Value::Null, |d| finite(d / (2.0 * PI))),
            "phases": ph,
            "phases_note": note,
        }))
    })();
    result.map_or_else(unprocessable, |v| (200, v))
}

/// `POST /api/effective_potential`: V_eff on n angles θ ∈ (0, π) (the poles left out) and its minimum.
pub fn effective_potential(body: &Value) -> Answer {
    let result = (|| -> Result<Value, String> {
        let p = params(body)?;
        let j = body
            .get("j3")
            .map_or(Some(0.0), Value::as_f64)
            .filter(|j| j.abs() <= 1e9)
            .ok_or("j3: a number from -1e9 to 1e9 kg m^2/s")?;
        let n = body
            .get("n")
            .map_or(Some(400), Value::as_u64)
            .filter(|n| (16..=4000).contains(n))
            .ok_or("n: an integer from 16 to 4000")?;
        let (m, l, g) = (p.mass, p.length, p.g);
        let theta: Vec<f64> = (1..=n).map(|i| PI * i as f64 / (n + 1) as f64).collect();
        let v: Vec<f64> = theta
            .iter()
            .map(|t| -m * g * l * t.cos() + j * j / (2.0 * m * l * l * t.sin().powi(2)))
            .collect();
        let k = (0..v.len()).fold(0, |k, i| if v[i] < v[k] { i } else { k });
        Ok(json!({
            "theta": theta,
            "v_eff": v,
            "minimum": { "theta": theta[k], "v_eff": v[k] },
            "units": { "theta": "rad", "v_eff": "J" },
        }))
    })();
    result.map_or_else(unprocessable, |v| (200, v))
}

/// Longest stretch of the orbit \[s\] the reduced view shows (the server's `MAX_ORBIT_TIME`).
pub const MAX_ORBIT_TIME: f64 = 30.0;

fn count(body: &Value, key: &str, default: u64, lo: u64, hi: u64) -> Result<u64, String> {
    body.get(key)
        .map_or(Some(default), Value::as_u64)
        .filter(|n| (lo..=hi).contains(n))
        .ok_or(format!("{key}: an integer from {lo} to {hi}"))
}

/// `POST /api/em_map`.
pub fn em_view(body: &Value) -> Answer {
    let result = (|| -> Result<Value, String> {
        let p = params(body)?;
        let s = state(body, &p)?;
        let n = count(body, "n", 401, 16, 4001)? as usize;
        if p.g == 0.0 {
            return Err(
                "the energy-momentum map needs gravity: g = 0 m/s^2 has no potential (every orbit is a \
                        great circle); give g > 0 (or g < 0, the mirror image)"
                    .into(),
            );
        }
        let (eu, mu) = (p.mass * p.g.abs() * p.length, p.mass * p.length * p.length * p.omega0());
        // heights u = z/l ∈ (−1, 0) spaced to resolve both ends, as pendulab.theory.em_map
        let half: Vec<(f64, f64)> = (1..n - 1)
            .map(|i| {
                let s = i as f64 / (n - 1) as f64;
                conical_boundary(-(0.5 * PI * s).cos().powi(2))
            })
            .collect();
        let mut j: Vec<f64> = half.iter().rev().map(|(j, _)| -j * mu).collect();
        let mut e: Vec<f64> = half.iter().rev().map(|(_, e)| e * eu).collect();
        j.push(0.0);
        e.push(-eu);
        j.extend(half.iter().map(|(j, _)| j * mu));
        e.extend(half.iter().map(|(_, e)| e * eu));
        let model = IdealPendulum::new(p.length, p.mass, p.g).map_err(|e| e.to_string())?;
        Ok(json!({
            "boundary": { "j3": j, "energy": e },
            "bottom": { "j3": 0.0, "energy": -eu },
            "top": { "j3": 0.0, "energy": eu },
            "point": { "j3": j3(&model, &s), "energy": energy(&model, &s) },
            "units": { "j3": "kg m^2/s", "energy": "J" },
        }))
    })();
    result.map_or_else(unprocessable, |v| (200, v))
}

/// `POST /api/reduced`.
pub fn reduced_view(body: &Value) -> Answer {
    let result = (|| -> Result<Value, String> {
        let p = params(body)?;
        let s = state(body, &p)?;
        let n = count(body, "n", 400, 16, 4000)? as usize;
        let grid = count(body, "grid", 41, 5, 121)? as usize;
        let sol = ExactSolution::new(&p, &s).map_err(|e| e.to_string())?;
        let span = match sol.period_z() {
            Some(t) if t.is_finite() && t > 0.0 => t.min(MAX_ORBIT_TIME),
            _ => MAX_ORBIT_TIME,
        };
        let mut orbit = [Vec::with_capacity(n), Vec::with_capacity(n), Vec::with_capacity(n)];
        for i in 0..n {
            let t = span * i as f64 / (n - 1) as f64;
            let sigma = invariants(p.length, &sol.state(t).map_err(|e| e.to_string())?);
            for (k, o) in orbit.iter_mut().enumerate() {
                o.push(sigma[k]);
            }
        }
        let sigma = invariants(p.length, &s);
        let (j, gamma) = (sigma[5], p.g / p.length);
        let h = 0.5 * sigma[2] + gamma * sigma[0];
        let s2max = (1.5 * orbit[1].iter().fold(0.0f64, |m, v| m.max(v.abs()))).max(1.0).max(j.abs());
        let line = |a: f64, b: f64| -> Vec<f64> {
            (0..grid).map(|i| a + (b - a) * i as f64 / (grid - 1) as f64).collect()
        };
        let (s1, s2) = (line(-0.95, 0.95), line(-s2max, s2max));
        let s3: Vec<Vec<f64>> =
            s1.iter().map(|a| s2.iter().map(|b| (b * b + j * j) / (1.0 - a * a)).collect()).collect();
        Ok(json!({
            "orbit": { "sigma1": orbit[0], "sigma2": orbit[1], "sigma3": orbit[2] },
            "orbit_time": span,
            "surface": { "sigma1": s1, "sigma2": s2, "sigma3": s3 },
            "plane": { "h": h, "gamma": gamma },
            "point": [sigma[0], sigma[1], sigma[2]],
            "j": j,
            "units": { "sigma1": "1", "sigma2": "1/s", "sigma3": "1/s^2", "h": "1/s^2", "gamma": "1/s^2", "j": "1/s" },
        }))
    })();
    result.map_or_else(unprocessable, |v| (200, v))
}

/// The answer to a request `{"path": "api/…", "body": {…}}` (404 for paths not answered here).
pub fn request(text: &str) -> Answer {
    let Ok(req) = serde_json::from_str::<Value>(text) else {
        return unprocessable("the request body is not JSON".into());
    };
    match req["path"].as_str().unwrap_or("") {
        "api/exact" => exact_quantities(&req["body"]),
        "api/effective_potential" => effective_potential(&req["body"]),
        "api/em_map" => em_view(&req["body"]),
        "api/reduced" => reduced_view(&req["body"]),
        other => (404, json!({ "detail": format!("{other} is not answered in the page") })),
    }
}
