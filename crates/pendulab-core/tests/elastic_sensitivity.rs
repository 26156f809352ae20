//! The swinging spring's forward sensitivities (docs/theory.md T-10.8, `elastic::sensitivity`): the
//! states are the plain run's bit for bit, and every tangent — by the start's position and velocity
//! and by κ = k/m, l₀, g — is the derivative of the plain run, checked against central differences of
//! `SwingingSpring::simulate` with perturbed starts and parameters (an independent path: no tangent
//! code) at orders 2 and 4, over many swings near the 1:1:2 resonance. Bad requests are refused with
//! the value named. SI units: equilibrium length 1 m, g = 9.81 m/s², m = 1 kg.

use pendulab_core::elastic::{SwingingSpring, Tangent, SPRING_PARAMS};
use pendulab_core::{DVec3, Error, State};

fn spring() -> SwingingSpring {
    SwingingSpring::resonant(1.0, 9.81, 1.0).unwrap()
}

fn start() -> State {
    State { x: DVec3::new(0.3, 0.1, -1.02), v: DVec3::new(0.05, 0.4, 0.2) }
}

/// The six unit tangents of the start: ∂/∂x₀ᵢ and ∂/∂v₀ᵢ.
fn unit_tangents() -> Vec<Tangent> {
    let e = [DVec3::X, DVec3::Y, DVec3::Z];
    e.iter().map(|&u| (u, DVec3::ZERO)).chain(e.iter().map(|&u| (DVec3::ZERO, u))).collect()
}

fn plain(sp: &SwingingSpring, s0: State, dt: f64, n: u64, order: u32) -> Vec<State> {
    sp.simulate(s0, dt, n, 1, order).unwrap().1
}

/// The plain runs moved by ±h along direction `d` (0–5: the start, 6–8: κ, l₀, g), differenced: the
/// position's, the velocity's and the acceleration's derivative at every step.
fn differenced(sp: &SwingingSpring, d: usize, h: f64, dt: f64, n: u64, order: u32) -> Vec<[DVec3; 3]> {
    let moved = |sign: f64| {
        let (mut s, mut p) = (start(), *sp);
        match d {
            0..=2 => s.x[d] += sign * h,
            3..=5 => s.v[d - 3] += sign * h,
            6 => p.k_over_m += sign * h,
            7 => p.rest_length += sign * h,
            _ => p.g += sign * h,
        }
        (p, plain(&p, s, dt, n, order))
    };
    let ((p_up, up), (p_down, down)) = (moved(1.0), moved(-1.0));
    let quotient = |a: DVec3, b: DVec3| (a - b) / (2.0 * h);
    up.iter()
        .zip(&down)
        .map(|(a, b)| {
            let accel = quotient(p_up.acceleration(a.x), p_down.acceleration(b.x));
            [quotient(a.x, b.x), quotient(a.v, b.v), accel]
        })
        .collect()
}

#[test]
fn the_states_are_the_plain_runs_bit_for_bit() {
    let sp = spring();
    for order in [2, 4] {
        let keep: Vec<u64> = (0..=2000).step_by(7).collect();
        let run = sp.sensitivities(start(), &unit_tangents(), 1e-3, order, &keep).unwrap();
        let states = plain(&sp, start(), 1e-3, 2000, order);
        assert_eq!(run.directions, 6 + SPRING_PARAMS.len());
        for (j, &k) in keep.iter().enumerate() {
            assert_eq!(run.states[j], states[k as usize], "order {order}, step {k}");
        }
    }
}

#[test]
fn the_states_at_step_numbers_are_the_plain_runs_bit_for_bit() {
    let sp = spring();
    let keep = [0, 0, 1, 2, 500, 501, 1999, 2000];
    for order in [2, 4] {
        let at = sp.states_at(start(), 1e-3, order, &keep).unwrap();
        let states = plain(&sp, start(), 1e-3, 2000, order);
        let expected: Vec<State> = keep.iter().map(|&k| states[k as usize]).collect();
        assert_eq!(at, expected, "order {order}");
    }
    let err = sp.states_at(start(), 1e-3, 4, &[3, 2]).unwrap_err();
    assert!(matches!(err, Error::InvalidParameter { name: "keep", .. }), "{err}");
    let stiff = SwingingSpring::new(1e12, 1.0, 9.81, 1.0).unwrap();
    assert!(matches!(stiff.states_at(start(), 1.0, 2, &[10_000]).unwrap_err(), Error::Diverged { .. }));
}

#[test]
fn every_tangent_and_acceleration_derivative_is_that_of_the_plain_run() {
    let sp = spring();
    let (dt, n) = (2e-3, 5000); // 10 s: about five swings and ten bounces at the resonance
    let keep: Vec<u64> = (0..=n).step_by(250).collect();
    for order in [2, 4] {
        let run = sp.sensitivities(start(), &unit_tangents(), dt, order, &keep).unwrap();
        for d in 0..run.directions {
            let fd = differenced(&sp, d, 1e-6, dt, n, order);
            let scale = fd.iter().flatten().map(|c| c.length()).fold(1e-3, f64::max);
            for (j, &k) in keep.iter().enumerate() {
                let (tx, tv) = run.tangents[j * run.directions + d];
                let ta = run.accelerations[j * run.directions + d];
                let [fx, fv, fa] = fd[k as usize];
                let off = (tx - fx).length().max((tv - fv).length()).max((ta - fa).length()) / scale;
                assert!(off < 1e-6, "order {order}, direction {d}, step {k}: {off:e} of {scale:e}");
            }
        }
    }
}

#[test]
fn a_start_tangent_is_carried_linearly() {
    // the tangent of a combination of start directions is that combination of their tangents
    let sp = spring();
    let mixed = vec![(DVec3::new(0.5, -2.0, 1.0), DVec3::new(3.0, 0.0, -1.5))];
    let keep = [0, 100, 1000];
    let one = sp.sensitivities(start(), &mixed, 1e-3, 4, &keep).unwrap();
    let units = sp.sensitivities(start(), &unit_tangents(), 1e-3, 4, &keep).unwrap();
    let w = [0.5, -2.0, 1.0, 3.0, 0.0, -1.5];
    for j in 0..keep.len() {
        let (mut x, mut v) = (DVec3::ZERO, DVec3::ZERO);
        for (d, wd) in w.iter().enumerate() {
            let (ux, uv) = units.tangents[j * units.directions + d];
            (x, v) = (x + ux * *wd, v + uv * *wd);
        }
        let (tx, tv) = one.tangents[j * one.directions];
        assert!(
            (tx - x).length() < 1e-9 * (1.0 + x.length()) && (tv - v).length() < 1e-9 * (1.0 + v.length())
        );
    }
}

#[test]
fn bad_requests_are_refused_with_the_value_named() {
    let sp = spring();
    let err = sp.sensitivities(start(), &[], 1e-3, 4, &[5, 3]).unwrap_err();
    assert!(matches!(err, Error::InvalidParameter { name: "keep", value, .. } if value == 3.0), "{err}");
    let err = sp.sensitivities(start(), &[], 1e-3, 4, &[1 << 27]).unwrap_err();
    assert!(err.to_string().contains("2^26"), "{err}");
    let many = vec![(DVec3::X, DVec3::ZERO); 62];
    let err = sp.sensitivities(start(), &many, 1e-3, 4, &[1]).unwrap_err();
    assert!(err.to_string().contains("at most 61 start tangents"), "{err}");
    let nan = [(DVec3::new(0.0, f64::INFINITY, 0.0), DVec3::ZERO)];
    let err = sp.sensitivities(start(), &nan, 1e-3, 4, &[1]).unwrap_err();
    assert!(err.to_string().contains("start_tangents[0] = inf"), "{err}");
    let err = sp.sensitivities(start(), &[], 1e-3, 3, &[1]).unwrap_err();
    assert!(err.to_string().contains("order"), "{err}");
    let err = sp.sensitivities(start(), &[], -1e-3, 4, &[1]).unwrap_err();
    assert!(err.to_string().contains("dt"), "{err}");
}

#[test]
fn a_diverging_run_names_the_last_finite_time() {
    // a huge step through the pivot's neighbourhood blows the stiff spring up
    let sp = SwingingSpring::new(1e12, 1.0, 9.81, 1.0).unwrap();
    let err = sp.sensitivities(start(), &[], 1.0, 2, &[0, 10_000]).unwrap_err();
    assert!(matches!(err, Error::Diverged { .. }), "{err}");
}
