//! The pendulum on a string (model `string`): a motion that never goes slack is the rod pendulum's
//! bit for bit; a planar launch with too little energy to loop leaves the circle exactly where the
//! tension T = (m/l)(2E/m − 3 g z) of T-2.3/T-2.6 vanishes, z* = 2E/(3 m g); the flight is the exact
//! parabola and ends on the sphere after τ* = 4 v_z/g; an elastic snap keeps E, an inelastic one loses
//! exactly the radial kinetic energy ½ m (x̂·v)²; J₃ survives every event. SI units, l = 1 m.

use crate::common;

use common::rosette;
use pendulab_core::model::{energy, j3, AnyModel, StringPendulum};
use pendulab_core::string_run::{EventKind, StringSettings};
use pendulab_core::{
    DVec3, Error, IdealPendulum, Method, Model, Params, SaveAt, SolveOptions, State, Stepper,
};

const G: f64 = 9.81;

fn string(restitution: f64) -> StringPendulum {
    StringPendulum::new(Params::new(1.0, 2.0, G).unwrap(), restitution).unwrap()
}

/// Planar launch from the bottom with speed v0 [m/s] along e₁.
fn launch(v0: f64) -> State {
    State { x: DVec3::new(0.0, 0.0, -1.0), v: DVec3::new(v0, 0.0, 0.0) }
}

#[test]
fn never_slack_is_the_rod_pendulum_bit_for_bit() {
    let (_, s0) = rosette();
    let sp = string(0.0);
    for method in [Method::Rattle, Method::Rattle4, Method::Rkmk4] {
        let run = sp.simulate(0.0, s0, 3.0, &StringSettings::new(method, 1e-3)).unwrap();
        assert!(run.events.is_empty() && run.taut.iter().all(|&t| t));
        let rod = IdealPendulum::from_params(*sp.params());
        let opts = SolveOptions { method, dt: 1e-3, ..SolveOptions::default() };
        let mut st = Stepper::new(rod, 0.0, s0, &opts).unwrap();
        assert_eq!(run.t.len(), 3001);
        for (k, s) in run.states.iter().enumerate().skip(1) {
            st.step_n(1).unwrap();
            assert_eq!(run.t[k], st.t());
            assert_eq!(*s, st.state(), "{} differs from the rod at step {k}", method.info().name);
        }
    }
}

#[test]
fn leaves_where_the_tension_vanishes_then_flies_a_parabola_back_to_the_sphere() {
    // v0² = 3.5 g l: enough to pass the horizontal (2 g l), not to loop (5 g l). E/m = v0²/2 − g l,
    // so T = 0 at z* = 2E/(3 m g) = (v0² − 2 g l)/(3 g) = l/2, i.e. 30° above the horizontal.
    let sp = string(0.0);
    let s0 = launch((3.5 * G).sqrt());
    let e0 = energy(&sp, &s0);
    let run = sp.simulate(0.0, s0, 3.0, &StringSettings::new(Method::Rattle8, 1e-3)).unwrap();
    let leave = run.events[0];
    assert_eq!(leave.kind, EventKind::Slack);
    let z_star = sp.slack_height(e0);
    assert!((z_star - 0.5).abs() < 1e-15);
    eprintln!("left at t = {} s, z = {:.16} m (T = 0 at {z_star} m)", leave.t, leave.before.x.z);
    assert!((leave.before.x.z - z_star).abs() < 1e-12, "{} vs {z_star}", leave.before.x.z);
    assert!(sp.tension(&leave.before).abs() < 1e-12 * 2.0 * G, "T = {}", sp.tension(&leave.before));
    // the step before the event is taut with T > 0; the leave is inside one step of dt
    // the flight: an exact parabola inside the sphere, arriving after τ* = 4 v_z/g on |x| = l
    let snap = run.events[1];
    assert_eq!(snap.kind, EventKind::Taut);
    let tau = snap.t - leave.t;
    assert!((tau - 4.0 * leave.before.v.z / G).abs() < 1e-15 * 4.0, "{tau}");
    assert!((snap.before.x.length() - 1.0).abs() < 1e-15);
    let flight: Vec<usize> = (0..run.t.len()).filter(|&i| run.t[i] > leave.t && run.t[i] < snap.t).collect();
    assert!(flight.len() > 100 && flight.iter().all(|&i| !run.taut[i]));
    for &i in &flight {
        let s = run.states[i];
        let dt = run.t[i] - leave.t;
        let want = leave.before.x + leave.before.v * dt + DVec3::new(0.0, 0.0, -0.5 * G * dt * dt);
        assert!((s.x - want).length() < 4e-16 * (1.0 + dt * dt * G), "not on the parabola at {}", run.t[i]);
        assert!(s.x.length() < 1.0, "outside the sphere while slack at t = {}", run.t[i]);
        assert!((energy(&sp, &s) - e0).abs() < 1e-13 * e0.abs().max(G), "E in flight");
    }
    // the inelastic snap removes exactly the radial velocity and its kinetic energy
    let n = snap.before.x / snap.before.x.length();
    let radial_ke = 0.5 * 2.0 * n.dot(snap.before.v).powi(2);
    assert!(n.dot(snap.before.v) > 0.0);
    assert!((snap.energy_lost - radial_ke).abs() < 1e-14 * radial_ke, "{} vs {radial_ke}", snap.energy_lost);
    let de = energy(&sp, &snap.before) - energy(&sp, &snap.after);
    assert!((de - radial_ke).abs() < 1e-13 * radial_ke, "{de} vs {radial_ke}");
    assert!(snap.after.x.dot(snap.after.v).abs() < 1e-15);
}

#[test]
fn elastic_snaps_keep_the_energy_and_every_event_keeps_j3() {
    // a 3D launch that goes slack; e = 1: the bob bounces inside the sphere, E constant throughout
    let sp = string(1.0);
    let s0 = State::from_angles(sp.params(), 0.2, 0.0, 5.5, 3.0).unwrap();
    let (e0, j0) = (energy(&sp, &s0), j3(&sp, &s0));
    let run = sp.simulate(0.0, s0, 4.0, &StringSettings::new(Method::Rattle8, 1e-3)).unwrap();
    let snaps: Vec<_> = run.events.iter().filter(|e| e.kind == EventKind::Taut).collect();
    assert!(snaps.len() >= 3, "{} snaps", snaps.len());
    for ev in &run.events {
        assert!((energy(&sp, &ev.after) - energy(&sp, &ev.before)).abs() < 1e-13 * e0.abs(), "E at a snap");
        assert!(ev.energy_lost.abs() < 1e-13 * e0.abs());
        assert!((j3(&sp, &ev.after) - j0).abs() < 1e-12 * j0.abs(), "J3 at t = {}", ev.t);
    }
    let worst_e = run.states.iter().map(|s| (energy(&sp, s) - e0).abs()).fold(0.0, f64::max);
    let worst_j = run.states.iter().map(|s| (j3(&sp, s) - j0).abs()).fold(0.0, f64::max);
    eprintln!(
        "elastic: {} events, max |E − E0| = {worst_e:e} J, max |J3 − J3_0| = {worst_j:e}",
        run.events.len()
    );
    assert!(worst_e < 1e-11 * e0.abs() && worst_j < 1e-12 * j0.abs());
    // inelastic from the same start: E drops by exactly the sum of the snaps' losses
    let sp0 = string(0.0);
    let run = sp0.simulate(0.0, s0, 4.0, &StringSettings::new(Method::Rattle8, 1e-3)).unwrap();
    let lost: f64 = run.events.iter().map(|e| e.energy_lost).sum();
    let e_end = energy(&sp0, run.states.last().unwrap());
    assert!(lost > 1.0, "lost {lost} J");
    assert!((e0 - e_end - lost).abs() < 1e-11 * e0.abs(), "{} vs {lost}", e0 - e_end);
}

#[test]
fn bad_input_is_refused() {
    let p = Params::new(1.0, 1.0, G).unwrap();
    for e in [-0.1, 1.5, f64::NAN] {
        let msg = StringPendulum::new(p, e).unwrap_err().to_string();
        assert!(msg.contains("restitution") && msg.contains("[0, 1]"), "{msg}");
    }
    assert!(AnyModel::build("string", p, &[("restitution", 2.0)]).is_err());
    let m = AnyModel::build("string", p, &[("restitution", 0.5)]).unwrap();
    let (_, s0) = rosette();
    let err = Stepper::new(m, 0.0, s0, &SolveOptions::default()).unwrap_err();
    assert!(matches!(err, Error::HybridModel { .. }) && err.to_string().contains("string"), "{err}");
    let sp = string(0.0);
    let dop = sp.simulate(0.0, s0, 1.0, &StringSettings::new(Method::Dop853, 1e-3)).unwrap_err();
    assert!(dop.to_string().contains("dop853"), "{dop}");
    let outside = State { x: DVec3::new(0.0, 0.0, -1.1), v: DVec3::ZERO };
    assert!(sp.simulate(0.0, outside, 1.0, &StringSettings::new(Method::Rattle, 1e-3)).is_err());
    assert!(sp.simulate(0.0, s0, 1.0, &StringSettings::new(Method::Rattle, 0.0)).is_err());
    assert!(sp
        .simulate(
            0.0,
            s0,
            1.0,
            &StringSettings { save_every: 0, ..StringSettings::new(Method::Rattle, 1e-3) }
        )
        .is_err());
    // a start inside the sphere, at rest: it falls straight down and snaps at the bottom
    let inside = State { x: DVec3::new(0.0, 0.0, -0.5), v: DVec3::ZERO };
    let run = sp.simulate(0.0, inside, 1.0, &StringSettings::new(Method::Rattle, 1e-3)).unwrap();
    let snap = run.events[0];
    assert_eq!(snap.kind, EventKind::Taut);
    assert!((snap.t - (2.0 * 0.5 / G).sqrt()).abs() < 1e-15, "{}", snap.t);
    assert!(run.states.last().unwrap().v.length() < 1e-15, "at rest after the inelastic snap");
}

#[test]
fn partial_restitution_loses_one_minus_e_squared_and_settles_taut() {
    // e = 0.5: every snap loses exactly ½ m (1 − e²) u² and reverses u to −e u; the rebounds shrink
    // geometrically until the string is taut again (finite number of events), and E0 − E_end is the
    // sum of the losses.
    let e = 0.5;
    let sp = string(e);
    let s0 = launch((3.5 * G).sqrt());
    let e0 = energy(&sp, &s0);
    let run = sp.simulate(0.0, s0, 6.0, &StringSettings::new(Method::Rattle8, 1e-3)).unwrap();
    let snaps: Vec<_> = run.events.iter().filter(|ev| ev.kind == EventKind::Taut).collect();
    assert!(snaps.len() >= 3, "{} snaps", snaps.len());
    for ev in &snaps {
        let n = ev.before.x / ev.before.x.length();
        let (u_in, u_out) = (n.dot(ev.before.v), n.dot(ev.after.v));
        let expected = 0.5 * 2.0 * (1.0 - e * e) * u_in * u_in;
        let settled = u_out.abs() <= 1e-14 * ev.after.v.length().max(1.0);
        let lost = if settled { 0.5 * 2.0 * u_in * u_in } else { expected };
        // u = n·v is a small difference of O(|v|) terms: its rounding, ~ε|v|, bounds how well two
        // formulas for ½m(1 − e²)u² can agree when the rebound is slow (m = 2 kg here)
        let radial_rounding = 8.0 * f64::EPSILON * 2.0 * u_in.abs() * ev.before.v.length();
        assert!(
            (ev.energy_lost - lost).abs() <= 1e-13 * lost + radial_rounding + 1e-300,
            "{} vs {lost}",
            ev.energy_lost
        );
        assert!(
            settled || (u_out + e * u_in).abs() <= 1e-14 * u_in.abs().max(1.0),
            "{u_out} vs {}",
            -e * u_in
        );
    }
    assert!(*run.taut.last().unwrap(), "the string ends taut");
    let lost: f64 = run.events.iter().map(|ev| ev.energy_lost).sum();
    let e_end = energy(&sp, run.states.last().unwrap());
    assert!((e0 - e_end - lost).abs() < 1e-11 * e0.abs(), "{} vs {lost}", e0 - e_end);
}

#[test]
fn the_incremental_stepper_cut_into_pieces_is_the_one_run_bit_for_bit() {
    // a launch that leaves, flies, snaps back elastically, again and again: the stepper taken in
    // pieces of 1, 7 and 100 grid steps (pieces ending taut and ending in flight) gives the states of
    // one `simulate` run at the same grid points, and the same events
    use pendulab_core::string_run::StringStepper;
    let sp = string(1.0);
    let s0 = launch((3.5 * G).sqrt());
    let dt = 1e-3;
    let run = sp.simulate(0.0, s0, 3.0, &StringSettings::new(Method::Rattle, dt)).unwrap();
    assert!(run.events.len() >= 4, "{} events", run.events.len());
    let mut st = StringStepper::new(sp, 0.0, s0, Method::Rattle, dt).unwrap();
    let (mut k, mut slack_ends, mut events) = (0u64, 0, Vec::new());
    for piece in [1u64, 7, 100].iter().cycle() {
        if k + piece > 3000 {
            break;
        }
        st.step(*piece).unwrap();
        k += piece;
        events.extend(st.take_events());
        let t = k as f64 * dt;
        assert_eq!(st.t(), t);
        let i = run.t.iter().position(|&ti| ti == t).expect("a grid sample");
        assert_eq!(st.state(), run.states[i], "state at t = {t}");
        assert_eq!(st.is_taut(), run.taut[i], "mode at t = {t}");
        if !st.is_taut() {
            slack_ends += 1;
            assert_eq!(st.tension(), 0.0);
            assert_eq!(st.acceleration(), DVec3::new(0.0, 0.0, -G));
        }
    }
    assert!(slack_ends > 3, "pieces ending in flight: {slack_ends}");
    let n = events.len();
    assert_eq!(events[..], run.events[..n]);
}

/// The run as `simulate` made it before [`StringRunner`]: one `StringStepper::advance` to t_end, an
/// event's sample replacing a grid sample at the same time.
fn reference_run(
    sp: StringPendulum,
    s0: State,
    t_end: f64,
    method: Method,
    dt: f64,
    save_every: u64,
) -> (Vec<f64>, Vec<State>, Vec<bool>) {
    use pendulab_core::string_run::StringStepper;
    let mut st = StringStepper::new(sp, 0.0, s0, method, dt).unwrap();
    let mut out = (vec![0.0], vec![st.state()], vec![st.is_taut()]);
    st.advance(t_end, save_every, &mut |t, s, taut| {
        if out.0.last() == Some(&t) {
            out.0.pop();
            out.1.pop();
            out.2.pop();
        }
        out.0.push(t);
        out.1.push(s);
        out.2.push(taut);
        Ok(())
    })
    .unwrap();
    out
}

#[test]
fn a_run_in_chunks_is_the_one_shot_run_bit_for_bit() {
    // leaves, flights, snaps (elastic, partly elastic, inelastic), chunks of 1, 2, 7, 100 grid steps
    // (ending taut, in flight, on events): the same samples, events and work as `simulate`, which
    // is also the single `StringStepper::advance` run it was before chunking existed
    use pendulab_core::string_run::{StringRunner, StringStepper};
    let dt = 1e-3;
    for (e, s0) in [
        (1.0, launch((3.5 * G).sqrt())),
        (0.5, launch((3.5 * G).sqrt())),
        (0.0, State::from_angles(&Params::new(1.0, 2.0, G).unwrap(), 0.2, 0.0, 5.5, 3.0).unwrap()),
    ] {
        let sp = string(e);
        for save_every in [1u64, 3] {
            let one = sp
                .simulate(
                    0.0,
                    s0,
                    3.0,
                    &StringSettings { save_every, ..StringSettings::new(Method::Rattle, dt) },
                )
                .unwrap();
            assert!(!one.events.is_empty());
            let (t, states, taut) = reference_run(sp, s0, 3.0, Method::Rattle, dt, save_every);
            assert_eq!((&one.t, &one.states, &one.taut), (&t, &states, &taut), "simulate changed");
            for chunk in [1u64, 2, 7, 100] {
                let st = StringStepper::new(sp, 0.0, s0, Method::Rattle, dt).unwrap();
                let mut runner = StringRunner::new(st, 3.0, SaveAt::Every(save_every), u64::MAX).unwrap();
                let mut parts = Vec::new();
                let mut calls = 0;
                loop {
                    let done = runner.advance(chunk).unwrap();
                    parts.push(runner.take());
                    calls += 1;
                    if done {
                        break;
                    }
                }
                assert!(calls as u64 >= 3000 / chunk, "{calls} chunks of {chunk}");
                let cat = |f: &dyn Fn(&pendulab_core::string_run::StringRun) -> usize| {
                    parts.iter().map(f).sum::<usize>()
                };
                assert_eq!(cat(&|p| p.t.len()), one.t.len());
                let t: Vec<f64> = parts.iter().flat_map(|p| p.t.clone()).collect();
                let states: Vec<State> = parts.iter().flat_map(|p| p.states.clone()).collect();
                let taut: Vec<bool> = parts.iter().flat_map(|p| p.taut.clone()).collect();
                let events: Vec<_> = parts.iter().flat_map(|p| p.events.clone()).collect();
                let what = format!("e = {e}, save_every = {save_every}, chunks of {chunk}");
                assert_eq!(t, one.t, "{what}");
                assert_eq!(states, one.states, "{what}");
                assert_eq!(taut, one.taut, "{what}");
                assert_eq!(events, one.events, "{what}");
                assert_eq!(parts.last().unwrap().stats, one.stats, "{what}");
            }
        }
    }
}

#[test]
fn save_times_are_hit_exactly_on_the_parabola_in_flight_and_as_a_fine_run_when_taut() {
    use pendulab_core::string_run::{StringRunner, StringStepper};
    let sp = string(0.0);
    let s0 = launch((3.5 * G).sqrt());
    let dt = 1e-3;
    let dense = sp.simulate(0.0, s0, 3.0, &StringSettings::new(Method::Rattle8, dt)).unwrap();
    let (leave, snap) = (dense.events[0], dense.events[1]);
    // off-grid times: before the leave (taut), in the flight, after the snap (taut), t_end
    let mid = 0.5 * (leave.t + snap.t);
    let times = vec![0.0, 0.123_456_7, leave.t - 0.010_5, mid, mid + 1.3e-4, snap.t + 0.2345, 3.0];
    for chunk in [5u64, u64::MAX] {
        let st = StringStepper::new(sp, 0.0, s0, Method::Rattle8, dt).unwrap();
        let mut runner = StringRunner::new(st, 3.0, SaveAt::Times(times.clone()), u64::MAX).unwrap();
        let mut run = runner.take();
        while !runner.advance(chunk).unwrap() {
            let part = runner.take();
            run.t.extend(part.t);
            run.states.extend(part.states);
            run.taut.extend(part.taut);
            run.events.extend(part.events);
        }
        let part = runner.take();
        run.t.extend(part.t);
        run.states.extend(part.states);
        run.taut.extend(part.taut);
        run.events.extend(part.events);
        assert_eq!(run.t, times, "exactly the save times");
        // the events are still found (the same leave and snap times to round-off)
        assert_eq!(run.events.len(), dense.events.len());
        for (a, b) in run.events.iter().zip(&dense.events) {
            assert_eq!(a.kind, b.kind);
            assert!((a.t - b.t).abs() < 1e-12, "{} vs {}", a.t, b.t);
        }
        assert_eq!(run.taut, vec![true, true, true, false, false, true, true]);
        for (i, &t) in times.iter().enumerate() {
            let s = run.states[i];
            if !run.taut[i] {
                let want = sp.flight(&leave.before, t - leave.t);
                assert!(
                    (s.x - want.x).length() < 1e-14 && (s.v - want.v).length() < 1e-14,
                    "parabola at {t}"
                );
            } else if t == 0.0 {
                assert_eq!(s, s0);
            } else {
                // taut: as a run 10× finer that lands on t (rattle8: the difference is round-off)
                let fine = sp.simulate(0.0, s0, t, &StringSettings::new(Method::Rattle8, dt / 10.0)).unwrap();
                let f = fine.states.last().unwrap();
                let (dx, dv) = ((s.x - f.x).length(), (s.v - f.v).length());
                assert!(dx < 1e-14 && dv < 1e-13, "taut at {t}: |dx| = {dx:e}, |dv| = {dv:e}");
                assert!((s.x.length() - 1.0).abs() < 1e-14, "on the sphere at {t}");
            }
        }
    }
}

#[test]
fn bad_save_times_are_refused_naming_the_time() {
    use pendulab_core::string_run::{StringRunner, StringStepper};
    let sp = string(0.0);
    for (times, needle) in [
        (vec![0.5, 0.2], "0.5 s is followed by 0.2 s"),
        (vec![0.1, f64::NAN], "nan s is not a finite time"),
        // numbers as a user writes them (error::Shown), not 300 digits of {}
        (vec![-1e-300, 1.0], "-1e-300 s is not a finite time"),
        (vec![0.1, 1e15], "1e15 s is not a finite time"),
        (vec![0.1, 4.0], "4 s is not a finite time within [t0, t_end] = [0, 3] s"),
        (vec![-0.5, 1.0], "-0.5 s is not a finite time"),
        (vec![], "no save times"),
    ] {
        let st = StringStepper::new(sp, 0.0, launch(3.0), Method::Rattle, 1e-3).unwrap();
        let err = StringRunner::new(st, 3.0, SaveAt::Times(times), u64::MAX).unwrap_err();
        assert!(err.to_string().contains(needle), "{err}");
    }
}
