//! What an ensemble run hands back besides the states: the sample times \[s\] of a run saving every
//! n-th step (and the last), and per trajectory the summary (extremes of z \[m\], E/m [J/kg], J₃/m
//! [m²/s], crossings of the pivot's plane) and the settle time \[s\], read off the blocks.

use super::block_state::Block;
use super::Summary;

/// The number of samples of a full run of `n_steps` saving every `every`-th step and the last: the
/// start, then ⌈n_steps / every⌉ more ([`sample_times`] of the whole run has this length).
pub(super) fn sample_count(n_steps: u64, every: u64) -> usize {
    1 + n_steps.div_ceil(every) as usize
}

/// The sample times [s] of a run that took `steps` of `n_steps` steps of `dt`, saving every `every`-th
/// step and the last: 0, then every multiple of `every` (and n_steps) up to `steps`.
pub(super) fn sample_times(steps: u64, every: u64, n_steps: u64, dt: f64) -> Vec<f64> {
    let mut t: Vec<f64> = vec![0.0];
    let mut k = 0;
    while k < steps {
        k = (k + every - k % every).min(n_steps);
        if k > steps {
            break;
        }
        t.push(k as f64 * dt);
    }
    t
}

/// The extremes and plane crossings of a block's real lanes, in order.
pub(super) fn summaries(b: &Block) -> Vec<Summary> {
    (0..b.len)
        .map(|i| Summary {
            z: (b.summary[0][i], b.summary[1][i]),
            energy_per_mass: (b.summary[2][i], b.summary[3][i]),
            j3_per_mass: (b.summary[4][i], b.summary[5][i]),
            crossings: b.crossings[i] as u64,
        })
        .collect()
}

/// Every trajectory's settle time [s] after `steps` steps of `dt` (+∞: outside at the last sample),
/// from the index of the last sample outside the band of each (−1: never outside; `Block::last_out`).
pub(super) fn settle_times(last_out: &[f64], steps: u64, dt: f64) -> Vec<f64> {
    last_out
        .iter()
        .map(|&k| {
            // outside at the last sample: not settled within the run
            if k >= steps as f64 {
                f64::INFINITY
            } else {
                (k + 1.0) * dt
            }
        })
        .collect()
}
