//! Many crane runs at once: the residual sway of moves over a grid of cases (docs/cranes.md "A grid
//! of cases", docs/performance.md). Each case is a hook + payload crane (T-11.5) at rest under a
//! pivot that makes one of the given moves (knots, T-11.4), with a constant rope length l and payload
//! ratio R = m₂/m₁; its residual sway is the largest horizontal distance \[m\] of the payload from the
//! pivot over the saved times in [t_move_end, t_move_end + settle]. Cases run in parallel (rayon,
//! feature `parallel`), each with [`fn@super::run`]; the result is indexed \[move\]\[rope\]\[ratio\].

use super::dynamics::{Body, CraneSystem, Wind, DIM};
use super::hermite::{Hermite5, Knot};
use super::run::{run, Tolerances};
use crate::error::{Error, Result};
use glam::DVec3;

/// The grid's common settings.
#[derive(Debug, Clone, Copy)]
pub struct GridSpec {
    /// Hook mass m₁ \[kg\] (> 0).
    pub hook_mass: f64,
    /// Rigging length l₂ \[m\] (> 0).
    pub rigging: f64,
    /// Gravity [m/s²].
    pub g: f64,
    /// Time after each move's end over which the sway is measured \[s\] (> 0).
    pub settle: f64,
    /// Save interval for the measurement \[s\] (> 0).
    pub dt: f64,
    /// Tolerances of each run.
    pub tol: Tolerances,
}

/// One case: (move index, rope \[m\], ratio) → the residual sway \[m\].
fn case(pivot: &Hermite5, t_end_move: f64, rope: f64, ratio: f64, spec: &GridSpec) -> Result<f64> {
    let constant = |t: f64| Knot { t, q: DVec3::new(rope, 0.0, 0.0), dq: DVec3::ZERO, ddq: DVec3::ZERO };
    let (t0, _) = pivot.span();
    let t1 = t_end_move + spec.settle;
    let sys = CraneSystem {
        pivot: pivot.clone(),
        hoist: Hermite5::new("hoist", vec![constant(t0), constant(t1)])?,
        body1: Body { mass: spec.hook_mass, drag_area: 0.0 },
        body2: Some((Body { mass: spec.hook_mass * ratio, drag_area: 0.0 }, spec.rigging)),
        g: spec.g,
        damping: 0.0,
        wind: Wind::CALM,
    };
    let (p, dp, _) = pivot.eval(t0);
    let mut y = [0.0; DIM];
    let x1 = p - DVec3::Z * rope;
    let x2 = x1 - DVec3::Z * spec.rigging;
    y[0..3].copy_from_slice(&x1.to_array());
    y[3..6].copy_from_slice(&dp.to_array());
    y[6..9].copy_from_slice(&x2.to_array());
    y[9..12].copy_from_slice(&dp.to_array());
    let n = (spec.settle / spec.dt).ceil() as usize;
    let mut save: Vec<f64> = (0..=n).map(|i| (t_end_move + i as f64 * spec.dt).min(t1)).collect();
    save.dedup();
    if save[0] > t0 {
        save.insert(0, t0);
    }
    let out = run(&sys, t0, y, &save, spec.tol)?;
    let mut worst: f64 = 0.0;
    for (t, y) in out.t.iter().zip(&out.y) {
        if *t >= t_end_move {
            let off = DVec3::new(y[6], y[7], 0.0) - DVec3::new(pivot.eval(*t).0.x, pivot.eval(*t).0.y, 0.0);
            worst = worst.max(off.length());
        }
    }
    Ok(worst)
}

/// The residual sway \[m\] of every (move, rope, ratio), flattened as \[move\]\[rope\]\[ratio\].
/// `moves` pairs each pivot path with the time its move ends \[s\].
pub fn residual_grid(
    moves: &[(Hermite5, f64)],
    ropes: &[f64],
    ratios: &[f64],
    spec: &GridSpec,
) -> Result<Vec<f64>> {
    let bad = |name: &'static str, value: f64, allowed: &'static str| Error::InvalidParameter {
        name,
        value,
        allowed,
    };
    if let Some(&l) = ropes.iter().find(|l| !(l.is_finite() && **l > 0.0)) {
        return Err(bad("rope", l, "rope lengths > 0 m"));
    }
    if let Some(&r) = ratios.iter().find(|r| !(r.is_finite() && **r > 0.0)) {
        return Err(bad("ratio", r, "payload/hook mass ratios > 0"));
    }
    if !(spec.settle.is_finite() && spec.settle > 0.0 && spec.dt.is_finite() && spec.dt > 0.0) {
        return Err(bad("settle/dt", spec.settle, "settle > 0 s and dt > 0 s"));
    }
    let cases: Vec<(usize, usize, usize)> = (0..moves.len())
        .flat_map(|m| (0..ropes.len()).flat_map(move |l| (0..ratios.len()).map(move |r| (m, l, r))))
        .collect();
    let work = |&(m, l, r): &(usize, usize, usize)| case(&moves[m].0, moves[m].1, ropes[l], ratios[r], spec);
    #[cfg(feature = "parallel")]
    let out: Vec<Result<f64>> = {
        use rayon::prelude::*;
        cases.par_iter().with_max_len(1).map(work).collect() // every case its own task (costs differ)
    };
    #[cfg(not(feature = "parallel"))]
    let out: Vec<Result<f64>> = cases.iter().map(work).collect();
    out.into_iter().collect()
}
