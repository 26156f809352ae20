//! Long-run structure preservation of RATTLE and its compositions (10⁶ steps each).
//!
//! Physics checked: RATTLE re-imposes |x| = l and x·v = 0 every step (so they hold to round-off,
//! | |x| − l | ≤ 1e-13 l), keeps J₃ exactly in exact arithmetic for the axisymmetric pendulum
//! (relative error ≤ 1e-12 after 10⁶ steps of round-off), and being symplectic has a bounded
//! energy error with no secular drift: the largest |E − E₀| over the second half of the run is not
//! above 1.5× the largest over the first half. Steps are chosen so the energy error (≈ 1e-9 … 1e-6)
//! is far above round-off, so the drift test sees the method, not the arithmetic. The unprojected
//! RK4 on T-2.4 fails the same checks (it drifts off TS²), which shows the diagnostics are real.

use crate::common;

use common::{fixed, rosette};
use pendulab_core::model::{energy, j3};
use pendulab_core::{Method, Model, State, Stepper};

struct RunReport {
    max_radius_error: f64,
    max_tangency: f64,
    max_j3_rel: f64,
    energy_first_half: f64,
    energy_second_half: f64,
}

fn long_run(method: Method, dt: f64, steps: u64, s0: State) -> RunReport {
    let (model, _) = rosette();
    let l = model.params().length;
    let (e0, j0) = (energy(&model, &s0), j3(&model, &s0));
    let mut st = Stepper::new(model, 0.0, s0, &fixed(method, dt)).unwrap();
    let mut r = RunReport {
        max_radius_error: 0.0,
        max_tangency: 0.0,
        max_j3_rel: 0.0,
        energy_first_half: 0.0,
        energy_second_half: 0.0,
    };
    let chunk = 100;
    for k in 0..steps / chunk {
        st.step_n(chunk).unwrap();
        let s = &st.state();
        let res = s.residuals(l);
        r.max_radius_error = r.max_radius_error.max(res.length.abs() / l);
        r.max_tangency = r.max_tangency.max(res.tangency.abs() / (l * s.v.length().max(1e-300)));
        r.max_j3_rel = r.max_j3_rel.max(((j3(&model, s) - j0) / j0).abs());
        let de = (energy(&model, s) - e0).abs();
        if k < steps / chunk / 2 {
            r.energy_first_half = r.energy_first_half.max(de);
        } else {
            r.energy_second_half = r.energy_second_half.max(de);
        }
    }
    r
}

#[test]
fn rattle_and_compositions_keep_ts2_j3_and_bounded_energy_over_a_million_steps() {
    let (_, s0) = rosette();
    for (method, dt) in
        [(Method::Rattle, 1e-3), (Method::Rattle4, 0.02), (Method::Rattle6, 0.05), (Method::Rattle8, 0.08)]
    {
        let r = long_run(method, dt, 1_000_000, s0);
        let name = method.info().name;
        eprintln!(
            "{name}: |x|-l {:.1e}, x.v {:.1e}, J3 {:.1e}, dE first half {:.2e}, second half {:.2e}",
            r.max_radius_error, r.max_tangency, r.max_j3_rel, r.energy_first_half, r.energy_second_half
        );
        assert!(r.max_radius_error <= 1e-13, "{name}: | |x| - l |/l = {:e}", r.max_radius_error);
        assert!(r.max_tangency <= 1e-13, "{name}: x.v/(l|v|) = {:e}", r.max_tangency);
        assert!(r.max_j3_rel <= 1e-12, "{name}: relative J3 error {:e}", r.max_j3_rel);
        assert!(
            r.energy_first_half > 1e-12,
            "{name}: energy error {:e} is at round-off; the drift test would see nothing",
            r.energy_first_half
        );
        assert!(
            r.energy_second_half <= 1.5 * r.energy_first_half,
            "{name}: energy drifts: {:e} in the second half vs {:e} in the first",
            r.energy_second_half,
            r.energy_first_half
        );
    }
}

#[test]
fn unprojected_rk4_drifts_off_ts2_where_rattle_does_not() {
    // Near the top (T-2.4: the constraint error grows like exp(√(2(gz − |v|²)) t / l)).
    let (model, _) = rosette();
    let s0 = State::from_angles(model.params(), 179f64.to_radians(), 0.0, 0.0, 0.5).unwrap();
    let rk4 = long_run(Method::Rk4, 1e-3, 5_000, s0);
    let rattle = long_run(Method::Rattle, 1e-3, 5_000, s0);
    eprintln!(
        "5 s near the top: rk4 |x|-l {:.1e}, rattle {:.1e}",
        rk4.max_radius_error, rattle.max_radius_error
    );
    assert!(rk4.max_radius_error > 1e-9, "rk4 stayed on the sphere: {:e}", rk4.max_radius_error);
    assert!(rattle.max_radius_error < 1e-14);
    // Far from the top RK4 still drifts secularly in energy (no structure).
    let (_, rosette0) = rosette();
    let r = long_run(Method::Rk4, 0.02, 200_000, rosette0);
    assert!(
        r.energy_second_half > 1.5 * r.energy_first_half,
        "rk4 energy did not drift: {} vs {}",
        r.energy_second_half,
        r.energy_first_half
    );
}
