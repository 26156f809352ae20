//! The ensemble's per-call work around the steps (`ensemble/plan.rs`, `ensemble/mod.rs`): each worker
//! fills one block in place for every block it runs, so nothing of one block (damping, summaries,
//! settle records, compensations) may reach the next; the starts are checked in parts on both cores,
//! and the error is still the first failing start's. SI units; ideal and damped pendulum.

use pendulab_core::ensemble::{check, run, EnsembleResult, RattleSettings, LANES};
use pendulab_core::integrate::rattle_kernel::Arithmetic;
use pendulab_core::{IdealPendulum, Model, State};
use std::sync::atomic::{AtomicBool, AtomicU64};

fn starts(n: usize) -> Vec<State> {
    let m = IdealPendulum::new(1.0, 1.0, 9.81).unwrap();
    (0..n)
        .map(|k| {
            let f = k as f64 / n as f64;
            State::from_angles(m.params(), 0.1 + 2.6 * f, 0.2 * k as f64, 0.4 - f, 1.5 * f - 0.5).unwrap()
        })
        .collect()
}

fn run_in(threads: usize, starts: &[State], settings: &RattleSettings<'_>) -> EnsembleResult {
    let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
    pool.install(|| run(starts, settings, &AtomicU64::new(0), &AtomicBool::new(false)).unwrap())
}

/// One worker runs all blocks of a run with one block filled anew each time: damped lanes in the
/// first block only, small swings in the last ones, summaries and settle tracking on. Every trajectory must get the numbers a run of
/// its block alone gives (bit for bit: states, summaries, settle times).
#[test]
fn a_reused_block_carries_nothing_into_the_next() {
    let n = 3 * LANES + 9;
    let mut all = starts(n);
    // the last blocks swing within the settle band from the start (settle time 0) after a block
    // whose swings never settle
    let m = IdealPendulum::new(1.0, 1.0, 9.81).unwrap();
    for (k, s) in all.iter_mut().enumerate().skip(2 * LANES) {
        *s = State::from_angles(m.params(), 0.05 + 1e-3 * (k % LANES) as f64, 0.0, 0.0, 0.1).unwrap();
    }
    // damping in the first block only; lengths 1 m; a settle angle the damped swings reach
    let damping: Vec<f64> = (0..n).map(|k| if k < LANES { 2.0 + 0.01 * k as f64 } else { 0.0 }).collect();
    fn settings(damping: &[f64]) -> RattleSettings<'_> {
        RattleSettings {
            damping,
            with_summary: true,
            settle_angle: Some(0.3),
            ..RattleSettings::new(&[1.0], &[9.81], 2e-3, 3000)
        }
    }
    for arithmetic in Arithmetic::ALL {
        let whole = run_in(1, &all, &RattleSettings { arithmetic, ..settings(&damping) });
        for b in 0..n.div_ceil(LANES) {
            let (lo, hi) = (b * LANES, ((b + 1) * LANES).min(n));
            let alone = run_in(1, &all[lo..hi], &RattleSettings { arithmetic, ..settings(&damping[lo..hi]) });
            let (ns, nt) = (whole.states.len() / n, alone.states.len() / (hi - lo));
            assert_eq!(ns, nt);
            for k in lo..hi {
                for j in 0..ns {
                    let (s, t) = (whole.states[k * ns + j], alone.states[(k - lo) * ns + j]);
                    assert!(s.x == t.x && s.v == t.v, "{arithmetic:?}: trajectory {k}, sample {j}");
                }
                let (s, t) = (&whole.summary.as_ref().unwrap()[k], &alone.summary.as_ref().unwrap()[k - lo]);
                assert_eq!(format!("{s:?}"), format!("{t:?}"), "{arithmetic:?}: summary of {k}");
                let (s, t) =
                    (whole.settle_time.as_ref().unwrap()[k], alone.settle_time.as_ref().unwrap()[k - lo]);
                assert_eq!(s.to_bits(), t.to_bits(), "{arithmetic:?}: settle time of {k}");
            }
        }
        // the damped block settles, the undamped large swings do not, the small ones are settled from
        // the start: the test sees all three kinds
        let settle = whole.settle_time.unwrap();
        let (s0, s1, s2) = (settle[LANES - 1], settle[LANES], settle[n - 1]);
        assert!(s0 > 0.0 && s0.is_finite() && s1.is_infinite() && s2 == 0.0, "{s0} {s1} {s2}");
    }
}

/// The starts are checked in parts on both cores; the error reported is the first bad start's (an
/// off-sphere start at 700) although a later part (a non-finite velocity at 2500) fails too.
#[test]
fn the_first_bad_start_is_reported_however_the_check_is_split() {
    let good = starts(3000);
    let mut s = good.clone();
    s[700].x *= 1.01;
    s[2500].v.x = f64::NAN;
    let settings = RattleSettings::new(&[1.0], &[9.81], 1e-3, 10);
    for threads in [1, 2] {
        let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
        let err = pool.install(|| check(&s, &settings)).unwrap_err().to_string();
        assert!(err.contains("(|x| - l)/l"), "{threads} threads: {err}");
    }
    s[700] = good[700];
    let err = check(&s, &settings).unwrap_err().to_string();
    assert!(err.contains("v"), "{err}");
    s[2500] = good[2500];
    assert!(check(&s, &settings).is_ok());
}
