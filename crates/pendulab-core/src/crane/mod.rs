//! Cranes (docs/cranes.md, docs/theory.md §11): the load on a hoisted rope below a moving pivot, as one
//! body or as hook + payload (a double spherical pendulum), with wind drag and damping, integrated by
//! an adaptive DOP853 with projection onto the rheonomic constraints |x₁ − P(t)| = l(t), |x₂ − x₁| = l₂.
//! SI units (m, kg, s, N, J, W).
//!
//! - [`hermite`]: prescribed motions (pivot path, rope length) as piecewise quintic Hermite (T-11.4);
//! - [`dynamics`]: the equations of motion, tensions, energy and the works of hoist, pivot, wind and
//!   damping (T-11.5 – T-11.7);
//! - [`mod@run`]: the integrator;
//! - [`grid`]: the residual sway of moves over a grid of rope lengths and payload ratios, in parallel.
//!
//! The command shapers, moves and crane kinematics (T-11.1 – T-11.3) are pure functions of time and live
//! in the Python package (`pendulab.crane`); they reach this module as knots of the prescribed motions.

pub mod dynamics;
pub mod grid;
pub mod hermite;
pub mod run;

pub use dynamics::{Body, CraneSystem, Wind};
pub use grid::{residual_grid, GridSpec};
pub use hermite::{Hermite5, Knot};
pub use run::{run, CraneOutput, Tolerances};

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    fn fixed(name: &str, q: DVec3, dq: DVec3, t_end: f64) -> Hermite5 {
        let k = |t: f64| Knot { t, q: q + dq * t, dq, ddq: DVec3::ZERO };
        Hermite5::new(name, vec![k(0.0), k(t_end)]).unwrap()
    }

    fn system(hook: bool, hoist_rate: f64) -> CraneSystem {
        CraneSystem {
            pivot: fixed("pivot", DVec3::new(0.0, 0.0, 20.0), DVec3::new(0.3, 0.0, 0.0), 100.0),
            hoist: fixed("hoist", DVec3::new(8.0, 0.0, 0.0), DVec3::new(hoist_rate, 0.0, 0.0), 100.0),
            body1: Body { mass: if hook { 50.0 } else { 500.0 }, drag_area: 0.3 },
            body2: hook.then_some((Body { mass: 500.0, drag_area: 1.0 }, 2.0)),
            g: 9.81,
            damping: 0.01,
            wind: Wind {
                steady: DVec3::new(5.0, 1.0, 0.0),
                turbulence: vec![(0.7, DVec3::new(1.0, 0.5, 0.1), DVec3::new(0.3, 1.0, 2.0))],
                ..Wind::CALM
            },
        }
    }

    fn start(sys: &CraneSystem, theta: f64) -> dynamics::Y {
        let mut y = [0.0; dynamics::DIM];
        let (p, dp, _) = sys.pivot.eval(0.0);
        let l = sys.hoist.eval(0.0).0.x;
        let u = DVec3::new(theta.sin(), 0.0, -theta.cos());
        let x1 = p + u * l;
        let v1 = dp + u * sys.hoist.eval(0.0).1.x;
        y[0..3].copy_from_slice(&x1.to_array());
        y[3..6].copy_from_slice(&v1.to_array());
        if let Some((_, l2)) = sys.body2 {
            y[6..9].copy_from_slice(&(x1 + u * l2).to_array());
            y[9..12].copy_from_slice(&v1.to_array());
        }
        y
    }

    #[test]
    fn energy_balance_with_hoist_pivot_wind_and_damping() {
        for hook in [false, true] {
            let sys = system(hook, -0.05);
            let save: Vec<f64> = (0..=40).map(|i| i as f64 * 0.5).collect();
            let tol = Tolerances { rtol: 1e-12, atol: 1e-12, max_steps: 1_000_000 };
            let out = run(&sys, 0.0, start(&sys, 0.2), &save, tol).unwrap();
            let e0 = sys.energy(&out.y[0]);
            for y in &out.y {
                let works: f64 = y[12..16].iter().sum();
                let residual = sys.energy(y) - e0 - works;
                assert!(residual.abs() < 1e-8 * e0.abs(), "hook {hook}: {residual}");
            }
            assert!(out.y.last().unwrap()[12].abs() > 1.0, "the hoist did work");
        }
    }

    #[test]
    fn a_hanging_load_pulls_with_its_weight() {
        let mut sys = system(true, 0.0);
        sys.pivot = fixed("pivot", DVec3::ZERO, DVec3::ZERO, 10.0);
        sys.wind = Wind::CALM;
        let out = run(
            &sys,
            0.0,
            start(&sys, 0.0),
            &[0.0, 5.0],
            Tolerances { rtol: 1e-12, atol: 1e-12, max_steps: 10_000 },
        )
        .unwrap();
        for &(t1, t2) in &out.tension {
            assert!((t1 - 550.0 * 9.81).abs() < 1e-8 && (t2 - 500.0 * 9.81).abs() < 1e-8, "{t1} {t2}");
        }
    }

    #[test]
    fn lowering_faster_than_free_fall_is_a_slack_rope() {
        let mut sys = system(false, 0.0);
        let k = |t: f64| Knot {
            t,
            q: DVec3::new(2.0 + 10.0 * t * t, 0.0, 0.0),
            dq: DVec3::new(20.0 * t, 0.0, 0.0),
            ddq: DVec3::new(20.0, 0.0, 0.0),
        };
        sys.hoist = Hermite5::new("hoist", vec![k(0.0), k(1.0)]).unwrap();
        let err = run(
            &sys,
            0.0,
            start(&sys, 0.0),
            &[0.0, 1.0],
            Tolerances { rtol: 1e-9, atol: 1e-9, max_steps: 10_000 },
        )
        .unwrap_err();
        assert!(err.to_string().contains("slack"), "{err}");
    }

    #[test]
    fn save_times_a_rounding_error_apart_are_both_saved() {
        let sys = system(false, 0.0);
        let tol = Tolerances { rtol: 1e-10, atol: 1e-10, max_steps: 100_000 };
        let out = run(&sys, 0.0, start(&sys, 0.1), &[0.0, 1e-16, 2e-16, 1.0], tol).unwrap();
        assert_eq!(out.t, vec![0.0, 1e-16, 2e-16, 1.0]);
        assert_eq!(out.y[0], out.y[2]);
    }

    #[test]
    fn zero_gravity_at_rest_is_not_slack() {
        let mut sys = system(true, 0.0);
        sys.g = 0.0;
        sys.wind = Wind::CALM;
        sys.pivot = fixed("pivot", DVec3::ZERO, DVec3::ZERO, 10.0);
        let tol = Tolerances { rtol: 1e-10, atol: 1e-10, max_steps: 100_000 };
        let out = run(&sys, 0.0, start(&sys, 0.3), &[0.0, 5.0], tol).unwrap();
        assert_eq!(out.y[1][0..12], out.y[0][0..12]);
    }
}
