//! Property tests (proptest) of the core's entry points under hostile and extreme input: parameters,
//! states from Cartesian values and from angles, projection onto TS², stepper construction and
//! stepping with every method of the registry, the batch solver's up-front checks and the exact
//! solution. Each property: no panic, no hang (work is bounded by the inputs), and every `Ok`
//! result is finite — a non-finite number only ever leaves as an `Err` naming the input.
//!
//! Cases per property: `PROPTEST_CASES` (proptest's default, 256, in CI; `make fuzz` runs 10 000).
//! Units: SI (m, kg, m/s², s, rad).

use pendulab_core::exact::ExactSolution;
use pendulab_core::model::registry::{limit, COMMON};
use pendulab_core::solve::DEFAULT_MAX_SAVED_BYTES;
use pendulab_core::{
    DVec3, IdealPendulum, Method, Model, Params, SaveAt, SolveOptions, Solver, State, Stepper,
};
use proptest::prelude::*;

/// Any f64 a fuzzer would try: ordinary values, the extremes, subnormals, ±0, ±inf, NaN.
fn hostile() -> impl Strategy<Value = f64> + Clone {
    prop_oneof![
        4 => -10.0f64..10.0,
        2 => proptest::num::f64::ANY,
        1 => prop::sample::select(vec![
            0.0, -0.0, 1e308, -1e308, f64::MAX, f64::MIN_POSITIVE, 5e-324, -5e-324, 1e-300, 1e300,
            f64::NAN, f64::INFINITY, f64::NEG_INFINITY, 1e16, 1e-16,
        ]),
    ]
}

/// A value within [lo, hi] (log-uniform in magnitude for wide ranges, both signs where allowed).
fn within(lo: f64, hi: f64) -> impl Strategy<Value = f64> + Clone {
    (0.0f64..=1.0, -20.0f64..=20.0).prop_map(move |(u, e)| {
        let x = lo + (hi - lo) * u;
        let y = 10f64.powf(e) * if u < 0.5 { -1.0 } else { 1.0 };
        if (lo..=hi).contains(&y) {
            y
        } else {
            x
        }
    })
}

fn params() -> impl Strategy<Value = Params> {
    let [l, m, g] = [COMMON[0], COMMON[1], COMMON[2]];
    (within(l.min, l.max), within(m.min, m.max), within(g.min, g.max))
        .prop_map(|(l, m, g)| Params::new(l, m, g).expect("within the registry's limits"))
}

fn vec3(s: impl Strategy<Value = f64> + Clone) -> impl Strategy<Value = DVec3> {
    (s.clone(), s.clone(), s).prop_map(|(a, b, c)| DVec3::new(a, b, c))
}

fn finite(s: &State) -> bool {
    s.x.is_finite() && s.v.is_finite()
}

fn method() -> impl Strategy<Value = Method> {
    prop::sample::select(Method::ALL.to_vec())
}

/// A start on TS² from angles within the limits (or `None` when the rates give no finite velocity).
fn start(p: &Params, a: [f64; 4]) -> Option<State> {
    State::from_angles(p, a[0], a[1], a[2], a[3]).ok()
}

fn angles() -> impl Strategy<Value = [f64; 4]> {
    let (ang, rate) = (limit("angle"), limit("angle_rate"));
    (
        within(ang.min, ang.max),
        within(ang.min, ang.max),
        within(rate.min, rate.max),
        within(rate.min, rate.max),
    )
        .prop_map(|(a, b, c, d)| [a, b, c, d])
}

proptest! {
    #[test]
    fn parameters_are_accepted_only_within_the_registry(l in hostile(), m in hostile(), g in hostile()) {
        let ok = Params::new(l, m, g).is_ok();
        let inside = [l, m, g].iter().zip(COMMON).all(|(v, s)| *v >= s.min && *v <= s.max);
        prop_assert_eq!(ok, inside);
    }

    #[test]
    fn states_from_values_are_finite_or_refused(p in params(), x in vec3(hostile()), v in vec3(hostile())) {
        if let Ok(s) = State::on_tangent_bundle(&p, x, v) {
            prop_assert!(finite(&s));
        }
        if let Ok((s, pr)) = State::projected(&p, x, v) {
            prop_assert!(finite(&s) && pr.dx.is_finite() && pr.dv.is_finite(), "{s:?} {pr:?}");
            let r = (s.x.length() - p.length).abs() / p.length;
            prop_assert!(r < 1e-12, "|x| - l = {r} l after projection from {x:?}");
        }
    }

    #[test]
    fn states_from_angles_are_finite_or_refused(p in params(), a in vec3(hostile()), b in hostile()) {
        if let Ok(s) = State::from_angles(&p, a.x, a.y, a.z, b) {
            prop_assert!(finite(&s), "{s:?}");
        }
    }

    #[test]
    fn steppers_step_to_finite_states_or_stop_with_an_error(
        p in params(), a in angles(), m in method(), dt in hostile(), rtol in hostile(), atol in hostile(),
        n in 0u64..64,
    ) {
        let Some(s0) = start(&p, a) else { return Ok(()) };
        let model = IdealPendulum::from_params(p);
        let opts = SolveOptions { method: m, dt, rtol, atol, project: true };
        if let Ok(mut st) = Stepper::new(model, 0.0, s0, &opts) {
            if st.step_n(n).and_then(|_| st.check_finite()).is_ok() {
                prop_assert!(finite(&st.state()) && st.t().is_finite(), "{m:?} dt = {dt}: {:?}", st.state());
            }
        }
    }

    #[test]
    fn solvers_refuse_unbounded_work_up_front(
        p in params(), a in angles(), m in method(), dt in hostile(), t_end in hostile(), every in 0u64..4,
    ) {
        let Some(s0) = start(&p, a) else { return Ok(()) };
        let opts = SolveOptions { method: m, dt, rtol: 1e-8, atol: 1e-10, project: true };
        let solver = Solver::new(
            IdealPendulum::from_params(p), 0.0, s0, t_end, &opts, SaveAt::Every(every), DEFAULT_MAX_SAVED_BYTES,
        );
        if solver.is_ok() && !m.info().adaptive {
            prop_assert!(t_end / dt <= limit("steps").max, "planned {} steps", t_end / dt);
        }
    }

    #[test]
    fn the_exact_solution_is_finite_or_refused(p in params(), a in angles(), t in hostile()) {
        let Some(s0) = start(&p, a) else { return Ok(()) };
        let v = limit("velocity").max;
        if s0.v.abs().max_element() > v {
            return Ok(());
        }
        if let Ok(sol) = ExactSolution::new(&p, &s0) {
            let time = limit("time");
            let t = if t.is_finite() { t.clamp(time.min, time.max) } else { t };
            if let Ok(s) = sol.state(t) {
                prop_assert!(finite(&s), "{p:?} from {s0:?} at t = {t}: {s:?}");
            }
        }
    }
}

#[test]
fn the_model_of_a_stepper_keeps_its_params() {
    // a plain check that the generators above build what they say (the registry's bounds are inclusive)
    let p = Params::new(COMMON[0].max, COMMON[1].min, COMMON[2].min).unwrap();
    let m = IdealPendulum::from_params(p);
    assert_eq!(m.params().length, COMMON[0].max);
}
