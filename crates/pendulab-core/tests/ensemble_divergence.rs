//! A diverged trajectory of an ensemble is named as a single run names it: by the time of its last
//! finite state (the start of the step that was not finite), not by where the run ended. SI units;
//! ideal pendulum.

use pendulab_core::ensemble::{run, EnsembleSave, RattleSettings};
use pendulab_core::{Error, IdealPendulum, Method, Model, SaveAt, SolveOptions, Solver, State};
use std::sync::atomic::{AtomicBool, AtomicU64};

/// Starts from rest at growing angles; `dt` far too long for the fast ones.
fn starts(n: usize) -> Vec<State> {
    let m = IdealPendulum::new(1.0, 1.0, 9.81).unwrap();
    (0..n)
        .map(|k| State::from_angles(m.params(), 0.1 + 3.0 * k as f64 / n as f64, 0.0, 0.0, 0.0).unwrap())
        .collect()
}

#[test]
fn a_diverged_trajectory_is_named_by_its_last_finite_state_as_a_single_run_names_it() {
    // RATTLE at dt = 0.9 s (a period is 2 s): the position equation loses its root in the first or
    // second step, the state turns NaN and stays so
    let (dt, n_steps) = (0.9, 40);
    let end = n_steps as f64 * dt;
    let s = starts(9);
    let m = IdealPendulum::new(1.0, 1.0, 9.81).unwrap();
    for (save, every) in
        [(EnsembleSave::Every(2), 2), (EnsembleSave::Every(1), 1), (EnsembleSave::Final, n_steps)]
    {
        let (p, c) = (AtomicU64::new(0), AtomicBool::new(false));
        let settings = RattleSettings { save, ..RattleSettings::new(&[1.0], &[9.81], dt, n_steps) };
        let e = run(&s, &settings, &p, &c).unwrap_err();
        let Error::Diverged { t, method: "rattle (ensemble)", dt: named } = e else { panic!("{e}") };
        assert_eq!(named, dt);
        assert!(t < end, "{save:?}: t = {t} s is the run's end, not the last finite state");
        // the first diverging start, run alone (each trajectory has the single run's numbers): the
        // same time, the start of the step that failed (0.9 s for the first start, whose sample at
        // 1.8 s is the first not finite: named was 36 s, the run's end)
        let single = |k: usize| {
            let opts = SolveOptions { method: Method::Rattle, dt, ..SolveOptions::default() };
            let mut solver = Solver::new(m, 0.0, s[k], end, &opts, SaveAt::Every(every), 1 << 30).unwrap();
            solver.advance(u64::MAX).err()
        };
        let first = (0..s.len()).find_map(single).expect("some start diverges alone too");
        let Error::Diverged { t: t_single, .. } = first else { panic!("{first}") };
        assert_eq!((t, t_single), (0.9, 0.9), "{save:?}: ensemble {t} s, single run {t_single} s");
    }
}
