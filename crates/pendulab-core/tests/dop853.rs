//! DOP853 on its own: error proportional to the tolerance, dense output against stepping to the
//! same time, projection onto TS², step-size control with a bad first step, and its input checks.
//! Reference: the great circle of g = 0, x(t) = x₀ cos ωt + (v₀/ω) sin ωt with ω = |v₀|/l (SI units).

use crate::common;

use common::rosette;
use pendulab_core::error::Time;
use pendulab_core::integrate::dop853::Dop853;
use pendulab_core::{IdealPendulum, Method, Model, SolveOptions, State, Stats, Stepper};

fn great_circle() -> (IdealPendulum, State, impl Fn(f64) -> State) {
    let model = IdealPendulum::new(1.5, 1.0, 0.0).unwrap();
    let s0 = State::from_angles(model.params(), 1.0, 0.5, 0.7, 1.3).unwrap();
    let w = s0.v.length() / 1.5;
    let exact = move |t: f64| State {
        x: s0.x * (w * t).cos() + s0.v / w * (w * t).sin(),
        v: s0.v * (w * t).cos() - s0.x * w * (w * t).sin(),
    };
    (model, s0, exact)
}

fn options(rtol: f64, project: bool) -> SolveOptions {
    SolveOptions { method: Method::Dop853, dt: 0.0, rtol, atol: rtol * 1e-2, project }
}

#[test]
fn global_error_follows_the_tolerance() {
    let (model, s0, exact) = great_circle();
    let mut last = f64::INFINITY;
    for rtol in [1e-6, 1e-8, 1e-10, 1e-12, 1e-13] {
        let mut st = Stepper::new(model, 0.0, s0, &options(rtol, false)).unwrap();
        st.step_to(20.0).unwrap();
        let err = (st.state().x - exact(20.0).x).length() / 1.5;
        eprintln!(
            "rtol {rtol:e}: error {err:e} after {} steps ({} rejected)",
            st.stats().steps,
            st.stats().rejected
        );
        // Tolerance proportionality: within a modest factor of rtol, and shrinking with it.
        assert!(err < 50.0 * rtol.max(1e-14), "rtol {rtol:e}: error {err:e}");
        assert!(err < last, "error did not decrease at rtol {rtol:e}");
        last = err;
    }
}

#[test]
fn dense_output_agrees_with_stepping_to_the_same_time() {
    let (model, s0) = rosette();
    let opts = options(1e-12, true);
    let mut a = Stepper::new(model, 0.0, s0, &opts).unwrap();
    for _ in 0..40 {
        a.step().unwrap();
    }
    let (t_end, s_end) = (a.t(), a.state());
    // The interpolant passes through the step's end point exactly.
    let at_end = a.dense_output(t_end).unwrap();
    assert_eq!(at_end, s_end);
    let mut t_start = t_end;
    // find the start of the last step: outside it there is no dense output
    while a.dense_output(t_start - 1e-6).is_some() {
        t_start -= 1e-6;
    }
    assert!(a.dense_output(t_end + 1e-9).is_none());
    for frac in [0.1, 0.37, 0.5, 0.9] {
        let t = t_start + frac * (t_end - t_start);
        let dense = a.dense_output(t).unwrap();
        let mut b = Stepper::new(model, 0.0, s0, &opts).unwrap();
        b.step_to(t).unwrap();
        let d = (dense.x - b.state().x).length().max((dense.v - b.state().v).length() / 3.13);
        assert!(d < 1e-10, "dense output at t = {t} s off by {d:e}");
        let r = dense.residuals(1.0);
        assert!(r.length.abs() < 1e-14 && r.tangency.abs() < 1e-13, "{r:?}");
    }
}

#[test]
fn projection_keeps_the_state_on_ts2() {
    let (model, s0) = rosette();
    for project in [true, false] {
        let mut st = Stepper::new(model, 0.0, s0, &options(1e-8, project)).unwrap();
        st.step_to(200.0).unwrap();
        let r = st.state().residuals(1.0);
        eprintln!("project = {project}: |x| − l = {:e} m, x·v = {:e} m²/s", r.length, r.tangency);
        if project {
            assert!(r.length.abs() < 1e-14 && r.tangency.abs() < 1e-13);
        } else {
            // T-2.4 off TS² drifts: without projection the residual is visible above round-off.
            assert!(r.length.abs() > 1e-12, "expected drift without projection, got {:e}", r.length);
        }
    }
}

#[test]
fn a_far_too_large_first_step_is_rejected_and_recovered() {
    let (model, s0, exact) = great_circle();
    let opts = SolveOptions { dt: 5.0, ..options(1e-11, false) };
    let mut st = Stepper::new(model, 0.0, s0, &opts).unwrap();
    st.step_to(10.0).unwrap();
    assert!(st.stats().rejected > 0, "a 5 s first step should be rejected");
    let err = (st.state().x - exact(10.0).x).length() / 1.5;
    assert!(err < 1e-9, "{err:e}");
    // 12 evaluations per accepted step (11 stages and f at the new point, first same as last),
    // 11 per rejected one, plus f at the start.
    let s = st.stats();
    assert_eq!(s.rhs_evals, 12 * s.steps + 11 * s.rejected + 1, "{s:?}");
}

#[test]
fn lands_exactly_on_the_stop_time() {
    let (model, s0) = rosette();
    let mut d = Dop853::new(1e-10, 1e-12, true, f64::INFINITY, None).unwrap();
    let (mut t, mut s, mut stats) = (0.0, s0, Stats::default());
    while t < 0.7 {
        d.step(&model, &mut t, &mut s, 0.7, &mut stats).unwrap();
    }
    assert_eq!(t, 0.7);
    let e = d.step(&model, &mut t, &mut s, 0.7, &mut stats).unwrap_err().to_string();
    assert!(e.contains("t_stop"), "{e}");
}

#[test]
fn rejects_bad_tolerances_by_name() {
    for (rtol, atol, name) in [
        (0.0, 1e-12, "rtol"),
        (1e-16, 1e-12, "rtol"),
        (f64::NAN, 1e-12, "rtol"),
        (2.0, 1e-12, "rtol"),
        (1e-10, -1.0, "atol"),
        (1e-10, f64::INFINITY, "atol"),
    ] {
        let e = Dop853::new(rtol, atol, true, f64::INFINITY, None).unwrap_err().to_string();
        assert!(e.contains(name), "rtol {rtol}, atol {atol}: {e}");
    }
    assert!(Dop853::new(1e-10, 0.0, true, 0.0, None).unwrap_err().to_string().contains("h_max"));
    assert!(Dop853::new(1e-10, 0.0, true, 1.0, Some(-1.0)).unwrap_err().to_string().contains("dt"));
}

#[test]
fn invariant_projection_keeps_energy_and_j3_and_removes_the_phase_drift() {
    // Near the separatrix (`near_top`'s start) the energy error of plain DOP853 becomes a phase error
    // (∂T/∂E ≈ 700 s/J); with E and J₃ projected after each step it does not. Reference: RATTLE8.
    use pendulab_core::model::{energy, j3};
    let m = IdealPendulum::new(1.0, 1.0, 9.81).unwrap();
    let s0 = State::from_angles(m.params(), 179f64.to_radians(), 0.0, 0.0, 0.5).unwrap();
    let reference = {
        let opts = SolveOptions { method: Method::Rattle8, dt: 1e-3, ..SolveOptions::default() };
        let mut st = Stepper::new(m, 0.0, s0, &opts).unwrap();
        st.step_to(30.0).unwrap();
        st.state()
    };
    let mut errors = vec![];
    for conserve in [false, true] {
        let mut st = Stepper::new(m, 0.0, s0, &options(1e-12, true)).unwrap();
        st.set_invariant_projection(conserve);
        st.step_to(30.0).unwrap();
        let s = st.state();
        let (de, dj) = ((energy(&m, &s) - energy(&m, &s0)).abs(), (j3(&m, &s) - j3(&m, &s0)).abs());
        let err = (s.x - reference.x).length();
        eprintln!("conserve = {conserve}: |ΔE| = {de:e} J, |ΔJ₃| = {dj:e}, error vs RATTLE8 {err:e} m");
        if conserve {
            assert!(de < 1e-13 && dj < 1e-15, "invariants not kept: {de:e}, {dj:e}");
        }
        errors.push(err);
    }
    assert!(errors[1] < 0.01 * errors[0], "projection should cut the phase error: {errors:?}");
}

#[test]
fn zero_atol_works_from_rest_and_with_zero_components() {
    // atol = 0 leaves zero weights on components that are exactly 0 (here: the start at rest has
    // v = 0, and y = 0): a purely relative error control must still start and converge.
    let m = IdealPendulum::new(1.0, 1.0, 9.81).unwrap();
    let s0 = State::from_angles(m.params(), 0.5, 0.0, 0.0, 0.0).unwrap();
    let opts = SolveOptions { method: Method::Dop853, dt: 0.0, rtol: 1e-12, atol: 0.0, project: true };
    let mut st = Stepper::new(m, 0.0, s0, &opts).unwrap();
    st.step_to(5.0).unwrap();
    let reference = {
        let mut r = Stepper::new(m, 0.0, s0, &options(1e-13, true)).unwrap();
        r.step_to(5.0).unwrap();
        r.state()
    };
    assert!((st.state().x - reference.x).length() < 1e-10, "{:?}", st.state());
}

#[test]
fn invariant_projection_leaves_a_decaying_j3_alone() {
    // With linear damping J₃ is not conserved but decays as e^{−ct}: conserve must not pin it.
    use pendulab_core::model::j3;
    use pendulab_core::model::registry::AnyModel;
    let m =
        AnyModel::build("damped", pendulab_core::Params::new(1.0, 1.0, 9.81).unwrap(), &[("damping", 0.3)])
            .unwrap();
    let s0 = State::from_angles(m.params(), 1.0, 0.0, 0.0, 2.0).unwrap();
    let mut st = Stepper::new(m.clone(), 0.0, s0, &options(1e-12, true)).unwrap();
    st.set_invariant_projection(true);
    st.step_to(5.0).unwrap();
    let want = j3(&m, &s0) * (-0.3f64 * 5.0).exp();
    assert!((j3(&m, &st.state()) - want).abs() < 1e-9 * want.abs(), "{} vs {want}", j3(&m, &st.state()));
}

#[test]
fn capped_step_to_stops_at_the_cap_and_resumes_into_the_same_run() {
    let (model, s0, _) = great_circle();
    let opts = options(1e-10, true);
    let mut whole = Stepper::new(model, 0.0, s0, &opts).unwrap();
    whole.step_to(5.0).unwrap();
    let steps = whole.stats().steps;
    assert!(steps > 20, "{steps} steps");
    let mut cut = Stepper::new(model, 0.0, s0, &opts).unwrap();
    let mut calls = 0;
    while !cut.step_to_capped(5.0, 7).unwrap() {
        calls += 1;
        assert!(cut.t() < 5.0 && cut.stats().steps == 7 * calls, "{} steps", cut.stats().steps);
    }
    assert_eq!(calls, (steps - 1) / 7);
    // the same steps: bit for bit the uncapped run
    assert_eq!((cut.t(), cut.state(), cut.stats()), (whole.t(), whole.state(), whole.stats()));
    assert!(cut.step_to_capped(5.0, 0).unwrap(), "already there: no step needed");
    assert!(!cut.step_to_capped(6.0, 0).unwrap() && cut.t() == 5.0);
    assert!(cut.step_to_capped(4.0, 10).is_err(), "a target in the past is refused");
}

/// A first step near f64::MAX, or a state at rest (which accepts any step, so the step grows by the
/// largest factor each time until t overflows): `step_n` with t_stop = ∞ returns an error instead of
/// dividing an infinite step for ever (tests/fuzz_props.rs hung on such a case).
#[test]
fn a_step_that_overflows_the_time_is_an_error_not_a_hang() {
    use pendulab_core::Params;
    let p = Params::new(1.0, 1.0, 9.81).unwrap();
    for (theta, dt) in [(0.0, f64::MAX), (0.0, 1e300), (0.5, f64::MAX), (0.0, 0.0)] {
        let s0 = State::from_angles(&p, theta, 0.0, 0.0, 0.0).unwrap();
        let opts = SolveOptions { method: Method::Dop853, dt, rtol: 1e-8, atol: 1e-10, project: true };
        let mut st = Stepper::new(IdealPendulum::from_params(p), 0.0, s0, &opts).unwrap();
        match st.step_n(2000) {
            Ok(()) => assert!(st.t().is_finite(), "theta {theta}, dt {dt:e}: t = {}", st.t()),
            Err(e) => assert!(e.to_string().contains("dop853"), "{e}"),
        }
    }
}

/// The ideal pendulum whose physical state ([`Model::to_physical`], as a hoisted rope's rate enters
/// it) is not finite after `bad` [s]: the integrator's state stays finite, the state saved does not.
#[derive(Debug, Clone)]
struct NotFiniteAfter {
    inner: IdealPendulum,
    bad: f64,
}

impl Model for NotFiniteAfter {
    fn name(&self) -> &'static str {
        "not finite after"
    }
    fn params(&self) -> &pendulab_core::Params {
        self.inner.params()
    }
    fn applied_acceleration(&self, t: f64, x: glam::DVec3, v: glam::DVec3) -> glam::DVec3 {
        self.inner.applied_acceleration(t, x, v)
    }
    fn potential_per_mass(&self, x: glam::DVec3) -> f64 {
        self.inner.potential_per_mass(x)
    }
    fn is_conservative(&self) -> bool {
        true
    }
    fn is_axisymmetric(&self) -> bool {
        true
    }
    fn to_physical(&self, t: f64, s: State) -> State {
        if t > self.bad {
            State { x: s.x, v: s.v * f64::NAN }
        } else {
            s
        }
    }
}

#[test]
fn the_solver_names_the_start_of_the_step_whose_state_is_not_finite_not_its_last_sample() {
    // saved every 100 steps (or at 0 and 2.5 s only), the first state not finite is the end of the
    // step that crosses 1 s: named was the last saved sample (0 s), many steps back
    use pendulab_core::{Error, SaveAt, Solver};
    let m = NotFiniteAfter { inner: IdealPendulum::new(1.0, 1.0, 9.81).unwrap(), bad: 1.0 };
    let s0 = State::from_angles(m.params(), 1.0, 0.0, 0.0, 1.0).unwrap();
    let opts = SolveOptions { method: Method::Dop853, dt: 0.0, rtol: 1e-10, atol: 1e-12, project: true };
    // the steps alone: the one that crosses 1 s
    let mut st = Stepper::new(m.clone(), 0.0, s0, &opts).unwrap();
    let mut start = 0.0;
    while st.t() <= 1.0 {
        start = st.t();
        st.step().unwrap();
    }
    let (h, steps) = (st.t() - start, st.stats().steps);
    assert!(steps > 20 && start > 0.9, "{steps} steps, the last from {start} s");
    for save in [SaveAt::Every(100), SaveAt::Times(vec![0.0, 2.5])] {
        let mut solver = Solver::new(m.clone(), 0.0, s0, 3.0, &opts, save.clone(), 1 << 30).unwrap();
        let e = solver.advance(u64::MAX).unwrap_err();
        let Error::Diverged { t, method: "dop853", dt } = e else { panic!("{save:?}: {e}") };
        assert_eq!((t, dt), (start, h), "{save:?}: {e}");
        assert!(e.to_string().starts_with(&format!("the integration diverged after t = {} s", Time(t))));
    }
}
