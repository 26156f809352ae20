//! The ensemble call of a tree whose `ensemble::run` takes one `RattleSettings` (issue 25).

use pendulab_core::ensemble::{run, RattleSettings};
use pendulab_core::State;
use std::sync::atomic::{AtomicBool, AtomicU64};

/// `n_steps` RATTLE steps of `dt` [s] from `starts` (l = 1 m, g = 9.81 m/s²), final states kept.
pub fn ensemble_final(starts: &[State], dt: f64, n_steps: u64) {
    let (p, c) = (AtomicU64::new(0), AtomicBool::new(false));
    std::hint::black_box(run(starts, &RattleSettings::new(&[1.0], &[9.81], dt, n_steps), &p, &c).unwrap());
}
