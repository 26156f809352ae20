//! The ensemble kernel: each trajectory gets exactly the numbers of the single-trajectory RATTLE
//! (same operations, so bit-for-bit), per-trajectory l and g, saving rules, summaries, cancellation
//! and bad input. SI units; ideal pendulum.

use pendulab_core::ensemble::{
    check, per_lane_tile_lanes, run, run_checked, tile_lanes, EnsembleSave, RattleSettings, LANES, TILE,
};
use pendulab_core::integrate::rattle_kernel::{Arithmetic, PositionQuadratic, Unfused};
use pendulab_core::isa::Level;
use pendulab_core::model::energy;
use pendulab_core::DVec3;
use pendulab_core::{IdealPendulum, Method, Model, SolveOptions, State, Stepper};
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};

fn starts(n: usize, length: f64) -> Vec<State> {
    let m = IdealPendulum::new(length, 1.0, 9.81).unwrap();
    (0..n)
        .map(|k| {
            let f = k as f64 / n as f64;
            State::from_angles(m.params(), 0.2 + 2.5 * f, 0.3 * k as f64, 0.5 - f, 2.0 * f - 0.7).unwrap()
        })
        .collect()
}

#[test]
fn every_trajectory_matches_the_single_path_bit_for_bit() {
    for arithmetic in Arithmetic::ALL {
        per_lane_parameters_match_the_single_path(arithmetic);
    }
}

/// Per-trajectory l and g (each tile holds them as rows, ensemble/block.rs), with `arithmetic`.
fn per_lane_parameters_match_the_single_path(arithmetic: Arithmetic) {
    let n = 2 * LANES + 7; // a partial last block too
    let s = starts(n, 1.0);
    let lengths: Vec<f64> = (0..n).map(|k| 0.5 + k as f64 / n as f64).collect();
    let gs: Vec<f64> = (0..n).map(|k| 9.81 - 3.0 * k as f64 / n as f64).collect();
    // rescale starts onto each length
    let s: Vec<State> = s.iter().zip(&lengths).map(|(st, &l)| State { x: st.x * l, v: st.v * l }).collect();
    let (p, c) = (AtomicU64::new(0), AtomicBool::new(false));
    let res = run(
        &s,
        &RattleSettings {
            save: EnsembleSave::Every(1000),
            with_summary: true,
            arithmetic,
            ..RattleSettings::new(&lengths, &gs, 1e-3, 3000)
        },
        &p,
        &c,
    )
    .unwrap();
    assert_eq!(res.t, vec![0.0, 1.0, 2.0, 3.0]);
    assert_eq!(p.load(Ordering::Relaxed), 3000 * n as u64);
    for k in 0..n {
        let m = IdealPendulum::new(lengths[k], 1.0, gs[k]).unwrap();
        let opts = SolveOptions { method: Method::Rattle, dt: 1e-3, ..SolveOptions::default() };
        let mut st = Stepper::new(m, 0.0, s[k], &opts).unwrap();
        st.set_arithmetic(arithmetic).unwrap();
        for (j, &t) in res.t.iter().enumerate() {
            st.step_to(t).unwrap();
            assert_eq!(res.trajectory(k)[j], st.state(), "{arithmetic:?}: trajectory {k} at t = {t}");
        }
        let sum = res.summary.as_ref().unwrap()[k];
        let e = energy(&m, &st.state());
        assert!(sum.energy_per_mass.0 <= e && e <= sum.energy_per_mass.1);
        assert!(sum.z.0 >= -lengths[k] - 1e-12 && sum.z.1 <= lengths[k] + 1e-12);
        assert!(sum.j3_per_mass.1 - sum.j3_per_mass.0 < 1e-13, "J₃ not conserved: {sum:?}");
    }
}

#[test]
fn lanes_beyond_the_series_range_take_the_closed_form_and_still_match_bit_for_bit() {
    // dt = 20 ms: the slow lanes stay within the multiplier's Catalan series (|z| ≤ 1e-3), the fast
    // ones (up to 12 m/s) do not, so a block mixes both (integrate::rattle_kernel)
    let m = IdealPendulum::new(1.0, 1.0, 9.81).unwrap();
    let n = LANES + 5;
    // 12/69 m/s apart (the 64-lane layout's ramp, kept for 48 lanes): the border between the series
    // and the closed form falls inside a tile of every width (asserted below)
    let s: Vec<State> = (0..n)
        .map(|k| State::from_angles(m.params(), 1.0, 0.0, 0.0, 12.0 * k as f64 / 69.0).unwrap())
        .collect();
    let dt = 0.02;
    let in_series = |st: &State| {
        let w = st.v + DVec3::new(0.0, 0.0, -9.81) * (0.5 * dt);
        PositionQuadratic::new::<Unfused>(st.x, w, dt, 1.0).multiplier_series::<Unfused>(dt).1
    };
    assert!(in_series(&s[0]) && !in_series(&s[LANES - 1]), "the first block must mix both cases");
    // and some tile of lanes stepped together in registers too, at every level's tile size
    // (ensemble/block.rs; this run's is tile_lanes(isa::current(), Unfused))
    let levels = [Level::Baseline, Level::V3, Level::V4];
    let tiles = levels.iter().flat_map(|&l| {
        [tile_lanes(l, Arithmetic::Unfused), tile_lanes(l, Arithmetic::Fused), per_lane_tile_lanes(l)]
    });
    for tile in tiles {
        assert!(LANES.is_multiple_of(tile) && tile <= TILE);
        let mixed = s.chunks(tile).any(|t| t.iter().any(in_series) && !t.iter().all(in_series));
        assert!(mixed, "no tile of {tile} lanes mixes the series and the closed form");
    }
    // both arithmetics, and the parameters shared (one length) or per lane (lengths 1 m and 1.02 m
    // alternating, each start scaled onto its sphere): every lane of a tile where one is outside the
    // range gets the closed form's or the series' bits as its single path does (ensemble/tile.rs:
    // two halves with shared parameters, one pass kept aside with rows of fused parameters)
    let per_lane: Vec<f64> = (0..n).map(|k| 1.0 + 0.02 * (k % 2) as f64).collect();
    let scaled: Vec<State> =
        s.iter().zip(&per_lane).map(|(st, &l)| State { x: st.x * l, v: st.v * l }).collect();
    let in_range = |st: &State, l: f64| {
        let w = st.v + DVec3::new(0.0, 0.0, -9.81) * (0.5 * dt);
        PositionQuadratic::new::<Unfused>(st.x, w, dt, l * l).multiplier_series::<Unfused>(dt).1
    };
    let flags: Vec<bool> = scaled.iter().zip(&per_lane).map(|(st, &l)| in_range(st, l)).collect();
    for tile in [8, 16] {
        let mixed = flags.chunks(tile).any(|t| t.iter().any(|&f| f) && !t.iter().all(|&f| f));
        assert!(mixed, "per-lane lengths: no tile of {tile} lanes mixes the series and the closed form");
    }
    for (lengths, starts) in [(&[1.0][..], &s), (&per_lane[..], &scaled)] {
        for arithmetic in Arithmetic::ALL {
            let (p, c) = (AtomicU64::new(0), AtomicBool::new(false));
            let settings = RattleSettings { arithmetic, ..RattleSettings::new(lengths, &[9.81], dt, 50) };
            let res = run(starts, &settings, &p, &c).unwrap();
            let opts = SolveOptions { method: Method::Rattle, dt, ..SolveOptions::default() };
            for (k, start) in starts.iter().enumerate() {
                let l = lengths[k.min(lengths.len() - 1)];
                let mk = IdealPendulum::new(l, 1.0, 9.81).unwrap();
                let mut st = Stepper::new(mk, 0.0, *start, &opts).unwrap();
                st.set_arithmetic(arithmetic).unwrap();
                st.step_n(50).unwrap();
                let what = format!("{arithmetic:?}, {} lengths: trajectory {k}", lengths.len());
                assert_eq!(res.trajectory(k)[1], st.state(), "{what}");
            }
        }
    }
}

#[test]
fn crossings_count_passages_through_the_pivot_plane() {
    // planar swings over the top (speed at the bottom above 2√(g l)) cross z = 0 twice per turn;
    // a swing that stays below the pivot never does
    let m = IdealPendulum::new(1.0, 1.0, 9.81).unwrap();
    let speeds = [1.0, 2.5, 6.5, 7.0, 9.0, 15.0];
    let s: Vec<State> =
        speeds.iter().map(|&w| State::from_angles(m.params(), 0.0, 0.0, w, 0.0).unwrap()).collect();
    let (p, c) = (AtomicU64::new(0), AtomicBool::new(false));
    let steps = 10_000;
    let res = run(
        &s,
        &RattleSettings { with_summary: true, ..RattleSettings::new(&[1.0], &[9.81], 1e-3, steps) },
        &p,
        &c,
    )
    .unwrap();
    let opts = SolveOptions { method: Method::Rattle, dt: 1e-3, ..SolveOptions::default() };
    for (k, summary) in res.summary.unwrap().iter().enumerate() {
        // the same count along the single path (same numbers, bit for bit)
        let mut st = Stepper::new(m, 0.0, s[k], &opts).unwrap();
        let mut count = 0;
        for _ in 0..steps {
            let before = st.state().x.z > 0.0;
            st.step().unwrap();
            count += u64::from(before != (st.state().x.z > 0.0));
        }
        assert_eq!(summary.crossings, count, "speed {}", speeds[k]);
        // parity: odd exactly when the run ends on the other side
        assert_eq!(summary.crossings % 2 == 1, st.state().x.z > 0.0, "speed {}", speeds[k]);
        let over_the_top = speeds[k] > 2.0 * 9.81f64.sqrt();
        let reaches_plane = speeds[k] > (2.0 * 9.81f64).sqrt();
        assert_eq!(summary.crossings == 0, !reaches_plane, "speed {}: {}", speeds[k], summary.crossings);
        if over_the_top {
            // ω ≥ (v_top)/l at the top and ≤ v_bottom/l: turns in 10 s between those bounds
            let v_top = (speeds[k] * speeds[k] - 4.0 * 9.81).sqrt();
            let turns = summary.crossings as f64 / 2.0;
            assert!(turns <= 10.0 * speeds[k] / (2.0 * std::f64::consts::PI) + 1.0, "{turns}");
            assert!(turns >= 10.0 * v_top / (2.0 * std::f64::consts::PI) - 1.0, "{turns}");
        }
    }
}

#[test]
fn final_only_and_cancellation() {
    let s = starts(100, 1.0);
    let (p, c) = (AtomicU64::new(0), AtomicBool::new(false));
    let res = run(&s, &RattleSettings::new(&[1.0], &[9.81], 1e-3, 2500), &p, &c).unwrap();
    assert_eq!(res.t, vec![0.0, 2.5]);
    assert!(res.len() == 100 && res.states.len() == 200 && res.summary.is_none() && !res.cancelled);
    c.store(true, Ordering::Relaxed);
    let res = run(&s, &RattleSettings::new(&[1.0], &[9.81], 1e-3, 1_000_000), &p, &c).unwrap();
    assert!(res.cancelled && res.steps < 1_000_000);
    // cancelled while saving every 100 steps: each block stops after its first sample, and every
    // trajectory keeps the samples all reached (the flat result compacted), with the single path's bits
    let res = run(
        &s,
        &RattleSettings {
            save: EnsembleSave::Every(100),
            ..RattleSettings::new(&[1.0], &[9.81], 1e-3, 1_000_000)
        },
        &p,
        &c,
    )
    .unwrap();
    assert!(res.cancelled && res.t == vec![0.0, 0.1] && res.len() == 100 && res.states.len() == 200);
    let m = IdealPendulum::new(1.0, 1.0, 9.81).unwrap();
    let opts = SolveOptions { method: Method::Rattle, dt: 1e-3, ..SolveOptions::default() };
    for k in [0, LANES - 1, LANES, 99] {
        let mut st = Stepper::new(m, 0.0, s[k], &opts).unwrap();
        st.step_n(100).unwrap();
        assert_eq!(res.trajectory(k), &[s[k], st.state()], "trajectory {k}");
    }
}

#[test]
fn bad_input_is_named() {
    let s = starts(3, 1.0);
    let (p, c) = (AtomicU64::new(0), AtomicBool::new(false));
    let e = |r: Result<_, pendulab_core::Error>| {
        r.map(|_: pendulab_core::ensemble::EnsembleResult| ()).unwrap_err().to_string()
    };
    assert!(e(run(&s, &RattleSettings::new(&[1.0, 2.0], &[9.81], 1e-3, 10), &p, &c)).contains("length"));
    assert!(e(run(&s, &RattleSettings::new(&[1.0], &[9.81], -1.0, 10), &p, &c)).contains("dt"));
    assert!(e(run(
        &s,
        &RattleSettings { save: EnsembleSave::Every(0), ..RattleSettings::new(&[1.0], &[9.81], 1e-3, 10) },
        &p,
        &c
    ))
    .contains("save_every"));
    assert!(e(run(&s, &RattleSettings::new(&[2.0], &[9.81], 1e-3, 10), &p, &c)).contains("TS"));
    assert!(e(run(&s, &RattleSettings::new(&[1.0], &[9.81], 50.0, 10), &p, &c)).contains("non-finite"));
    // a token of `check` for other starts or settings is refused by its sizes, not run
    let set = RattleSettings::new(&[1.0], &[9.81], 1e-3, 10);
    let token = check(&s, &set).unwrap();
    assert!(e(run_checked(&s[..2], &set, token, &p, &c)).contains("checked"));
    let per = RattleSettings::new(&[1.0, 1.0, 1.0], &[9.81], 1e-3, 10);
    assert!(e(run_checked(&s[..2], &per, check(&s, &per).unwrap(), &p, &c)).contains("checked"));
    assert!(run_checked(&s, &set, token, &p, &c).is_ok());
}

#[test]
fn damped_trajectories_match_the_damped_model_bit_for_bit() {
    use pendulab_core::model::AnyModel;
    use pendulab_core::Params;
    let n = LANES + 5;
    let s = starts(n, 1.0);
    // per-trajectory damping, including undamped lanes inside a damped block; with one length
    // (the tiles' `Damping` form: ensemble/tile_params.rs) and with lengths per trajectory too
    // (`PerLane`), both arithmetics
    let damping: Vec<f64> =
        (0..n).map(|k| if k % 3 == 0 { 0.0 } else { 0.05 * k as f64 / n as f64 }).collect();
    let per_lane: Vec<f64> = (0..n).map(|k| 1.0 + 0.02 * (k % 2) as f64).collect();
    let scaled: Vec<State> =
        s.iter().zip(&per_lane).map(|(st, &l)| State { x: st.x * l, v: st.v * l }).collect();
    for (lengths, starts) in [(&[1.0][..], &s), (&per_lane[..], &scaled)] {
        for arithmetic in Arithmetic::ALL {
            let (p, c) = (AtomicU64::new(0), AtomicBool::new(false));
            let set = RattleSettings {
                damping: &damping,
                save: EnsembleSave::Every(500),
                with_summary: true,
                arithmetic,
                ..RattleSettings::new(lengths, &[9.81], 1e-3, 2000)
            };
            let res = run(starts, &set, &p, &c).unwrap();
            for k in 0..n {
                let l = lengths[k.min(lengths.len() - 1)];
                let params = Params::new(l, 1.0, 9.81).unwrap();
                let m = AnyModel::build("damped", params, &[("damping", damping[k])]).unwrap();
                let opts = SolveOptions { method: Method::Rattle, dt: 1e-3, ..SolveOptions::default() };
                let mut st = Stepper::new(m, 0.0, starts[k], &opts).unwrap();
                st.set_arithmetic(arithmetic).unwrap();
                for (j, &t) in res.t.iter().enumerate() {
                    st.step_to(t).unwrap();
                    let what = format!("{arithmetic:?}, {} lengths: trajectory {k}", lengths.len());
                    assert_eq!(res.trajectory(k)[j], st.state(), "{what} (c = {}) at t = {t}", damping[k]);
                }
            }
            // energy decays where c > 0 (E/m max is the start, min is far below it)
            let sum = res.summary.unwrap();
            assert!(sum[1].energy_per_mass.1 - sum[1].energy_per_mass.0 > 1e-4);
        }
    }
}

/// θ(t) of the linearised damped pendulum θ'' + c θ' + ω₀² θ = 0 from θ₀ at rest.
fn linear_sway(theta0: f64, c: f64, omega0: f64, t: f64) -> f64 {
    let gamma = 0.5 * c;
    let wd = (omega0 * omega0 - gamma * gamma).sqrt();
    theta0 * (-gamma * t).exp() * ((wd * t).cos() + gamma / wd * (wd * t).sin())
}

#[test]
fn settle_time_of_a_small_damped_swing_matches_linear_theory() {
    let (g, l, c, theta_s, dt) = (9.81, 1.0, 0.2, 0.003, 1e-3);
    let thetas = [0.01, 0.007, 0.002];
    let p0 = IdealPendulum::new(l, 1.0, g).unwrap();
    let s: Vec<State> =
        thetas.iter().map(|&th| State::from_angles(p0.params(), th, 0.4, 0.0, 0.0).unwrap()).collect();
    let (p, cn) = (AtomicU64::new(0), AtomicBool::new(false));
    let (ls, gs, cs) = ([l], [g], [c]);
    let set = RattleSettings {
        damping: &cs,
        settle_angle: Some(theta_s),
        ..RattleSettings::new(&ls, &gs, dt, 40_000)
    };
    let res = run(&s, &set, &p, &cn).unwrap();
    let settle = res.settle_time.unwrap();
    for (k, &th0) in thetas.iter().enumerate() {
        let omega0 = (g / l).sqrt();
        // last time the linear sway exceeds the threshold, on a fine grid
        let expected = if th0 <= theta_s {
            0.0
        } else {
            let h = 1e-5;
            let last =
                (0..4_000_000).rev().find(|&i| linear_sway(th0, c, omega0, i as f64 * h).abs() > theta_s);
            (last.unwrap() as f64 + 1.0) * h
        };
        // nonlinear corrections O(θ₀²) shift the crossing by ≲ 1e-4 s here; resolution is one step
        assert!(
            (settle[k] - expected).abs() <= dt + 5e-4,
            "θ₀ = {th0}: settle time {} s, linear theory {expected} s",
            settle[k]
        );
    }
    assert!(settle[0] > 10.0, "the damped swing must take a while to settle: {}", settle[0]);
    // undamped: a swing outside the band never settles; one inside is settled from the start
    let set = RattleSettings { settle_angle: Some(theta_s), ..RattleSettings::new(&ls, &gs, dt, 5000) };
    let res = run(&s, &set, &p, &cn).unwrap();
    let settle = res.settle_time.unwrap();
    assert!(settle[0].is_infinite() && settle[2] == 0.0, "{settle:?}");
    // negative g: the stable equilibrium is on top, the sway is measured from there
    let up: Vec<State> = s.iter().map(|st| State { x: -st.x, v: -st.v }).collect();
    let minus_g = [-g];
    let set = RattleSettings { settle_angle: Some(theta_s), ..RattleSettings::new(&ls, &minus_g, dt, 100) };
    let res = run(&up, &set, &p, &cn).unwrap();
    assert_eq!(res.settle_time.unwrap()[2], 0.0);
}

#[test]
fn bad_damping_and_settle_angle_are_named() {
    let s = starts(3, 1.0);
    let (p, c) = (AtomicU64::new(0), AtomicBool::new(false));
    let go = |damping: &[f64], settle_angle: Option<f64>| {
        let set = RattleSettings { damping, settle_angle, ..RattleSettings::new(&[1.0], &[9.81], 1e-3, 10) };
        run(&s, &set, &p, &c).unwrap_err().to_string()
    };
    assert!(go(&[-0.1], None).contains("damping"));
    assert!(go(&[f64::NAN], None).contains("damping"));
    assert!(go(&[0.1, 0.2], None).contains("damping"));
    assert!(go(&[], Some(0.0)).contains("settle_angle"));
    assert!(go(&[], Some(4.0)).contains("settle_angle"));
}
