//! The ensemble call of a tree whose `ensemble::run_with` takes its settings as loose arguments
//! (before issue 25's settings structs).

use pendulab_core::ensemble::{run_with, EnsembleSave, Extras};
use pendulab_core::State;
use std::sync::atomic::{AtomicBool, AtomicU64};

/// `n_steps` RATTLE steps of `dt` [s] from `starts` (l = 1 m, g = 9.81 m/s²), final states kept.
pub fn ensemble_final(starts: &[State], dt: f64, n_steps: u64) {
    let (p, c) = (AtomicU64::new(0), AtomicBool::new(false));
    let extras = Extras::default();
    let res = run_with(starts, &[1.0], &[9.81], &extras, dt, n_steps, EnsembleSave::Final, false, &p, &c);
    std::hint::black_box(res.unwrap());
}
