//! The ensemble kernel with the symmetric compositions of RATTLE (`RattleSettings::method` =
//! rattle4, rattle6, rattle8; ensemble/stages.rs, T-8.2): each trajectory gets exactly the numbers
//! of the single-trajectory composition (`Stepper` with the same method and arithmetic), bit for bit
//! (signed zeros included), in every form of the tiles' parameters (one pendulum; lengths and g per
//! trajectory; damping per trajectory, its factor per sub-step size), with lanes beyond the
//! multiplier's series range, and g < 0. SI units.

use pendulab_core::ensemble::{run, EnsembleSave, RattleSettings, LANES};
use pendulab_core::integrate::rattle_kernel::Arithmetic;
use pendulab_core::model::AnyModel;
use pendulab_core::{DVec3, Method, Params, SolveOptions, State, Stepper};
use std::sync::atomic::{AtomicBool, AtomicU64};

const COMPOSITIONS: [Method; 3] = [Method::Rattle4, Method::Rattle6, Method::Rattle8];

/// `n` starts on the sphere of radius `length` in the field g (polar angles 0.2…2.7 rad from the
/// lower pole, mixed azimuthal and polar rates; `speed` scales the velocities).
fn starts(n: usize, length: f64, g: f64, speed: f64) -> Vec<State> {
    let p = Params::new(length, 1.0, g).unwrap();
    (0..n)
        .map(|k| {
            let f = k as f64 / n as f64;
            let (th, ph) = (0.2 + 2.5 * f, 0.3 * k as f64);
            State::from_angles(&p, th, ph, speed * (0.5 - f), speed * (2.0 * f - 0.7)).unwrap()
        })
        .collect()
}

/// The saved states of `res` against the single-trajectory stepper (method, arithmetic, the
/// `damped` model with trajectory k's damping, or the ideal pendulum when none), bit for bit.
fn assert_matches_single(
    res: &pendulab_core::ensemble::EnsembleResult,
    starts: &[State],
    set: &RattleSettings<'_>,
    what: &str,
) {
    let pick = |a: &[f64], k: usize| a[k.min(a.len() - 1)];
    for (k, start) in starts.iter().enumerate() {
        let params = Params::new(pick(set.length, k), 1.0, pick(set.g, k)).unwrap();
        let c = if set.damping.is_empty() { 0.0 } else { pick(set.damping, k) };
        let m = if c == 0.0 {
            AnyModel::build("ideal", params, &[]).unwrap()
        } else {
            AnyModel::build("damped", params, &[("damping", c)]).unwrap()
        };
        let opts = SolveOptions { method: set.method, dt: set.dt, ..SolveOptions::default() };
        let mut st = Stepper::new(m, 0.0, *start, &opts).unwrap();
        st.set_arithmetic(set.arithmetic).unwrap();
        for (j, &t) in res.t.iter().enumerate() {
            st.step_to(t).unwrap();
            let (a, b) = (res.trajectory(k)[j], st.state());
            let bits = |s: State| [s.x.x, s.x.y, s.x.z, s.v.x, s.v.y, s.v.z].map(f64::to_bits);
            assert_eq!(
                bits(a),
                bits(b),
                "{what}, {:?} {:?}: trajectory {k} at t = {t}",
                set.method,
                set.arithmetic
            );
        }
    }
}

#[test]
fn compositions_match_the_single_path_bit_for_bit_in_every_form() {
    let n = LANES + 5; // a partial second block
    let lengths: Vec<f64> = (0..n).map(|k| 0.5 + k as f64 / n as f64).collect();
    let gs: Vec<f64> = (0..n).map(|k| 9.81 - 3.0 * k as f64 / n as f64).collect();
    let damping: Vec<f64> =
        (0..n).map(|k| if k % 3 == 0 { 0.0 } else { 0.3 * k as f64 / n as f64 }).collect();
    let one = starts(n, 1.0, 9.81, 1.0);
    let per_lane: Vec<State> =
        one.iter().zip(&lengths).map(|(s, &l)| State { x: s.x * l, v: s.v * l }).collect();
    for method in COMPOSITIONS {
        for arithmetic in Arithmetic::ALL {
            let base = RattleSettings {
                save: EnsembleSave::Every(40),
                with_summary: true,
                arithmetic,
                method,
                ..RattleSettings::new(&[1.0], &[9.81], 0.01, 120)
            };
            let forms: [(&str, RattleSettings<'_>, &[State]); 4] = [
                ("one pendulum", base, &one),
                (
                    "lengths and g per trajectory",
                    RattleSettings { length: &lengths, g: &gs, ..base },
                    &per_lane,
                ),
                ("damping per trajectory", RattleSettings { damping: &damping, ..base }, &one),
                ("one damping rate", RattleSettings { damping: &[0.2], ..base }, &one),
            ];
            for (what, set, s) in forms {
                let (p, c) = (AtomicU64::new(0), AtomicBool::new(false));
                let res = run(s, &set, &p, &c).unwrap();
                assert_eq!(res.t.len(), 4);
                assert_matches_single(&res, s, &set, what);
            }
        }
    }
}

#[test]
fn compositions_match_beyond_the_series_range_and_in_an_upward_field() {
    // dt = 40 ms and fast starts: some sub-steps leave the multiplier's Catalan series and take the
    // closed form (integrate::rattle_kernel); g < 0 pulls up (the stable equilibrium is the top)
    let n = LANES + 3;
    for (g, speed) in [(9.81, 4.0), (-9.81, 1.0)] {
        let (mut s, gs) = (starts(n, 1.0, g, speed), [g]);
        // planar swings in the y–z plane with x = vₓ = −0 (the zeros' signs are compared too)
        for (k, th) in [(1, 0.4), (7, 2.0)] {
            let (sn, cs, w) = (f64::sin(th), f64::cos(th), speed * 2.0);
            s[k] = State { x: DVec3::new(-0.0, sn, -cs), v: DVec3::new(-0.0, w * cs, w * sn) };
        }
        for method in COMPOSITIONS {
            for arithmetic in Arithmetic::ALL {
                let set = RattleSettings {
                    save: EnsembleSave::Every(25),
                    arithmetic,
                    method,
                    ..RattleSettings::new(&[1.0], &gs, 0.04, 50)
                };
                let (p, c) = (AtomicU64::new(0), AtomicBool::new(false));
                let res = run(&s, &set, &p, &c).unwrap();
                assert_matches_single(&res, &s, &set, &format!("g = {g}, speed ×{speed}"));
            }
        }
    }
}

#[test]
fn methods_without_an_ensemble_kernel_are_refused_by_name() {
    let s = starts(3, 1.0, 9.81, 1.0);
    for method in [Method::Dop853, Method::Rk4, Method::Rkmk4, Method::Rk4Angles] {
        let set = RattleSettings { method, ..RattleSettings::new(&[1.0], &[9.81], 1e-3, 10) };
        let (p, c) = (AtomicU64::new(0), AtomicBool::new(false));
        let e = run(&s, &set, &p, &c).unwrap_err().to_string();
        assert!(e.contains(method.info().name) && e.contains("rattle4") && e.contains("dop853"), "{e}");
    }
}
