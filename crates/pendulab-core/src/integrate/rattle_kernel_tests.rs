//! Unit tests of `rattle_kernel.rs`: the series multiplier against the closed form, its range, and
//! the uniform-field path against the general path (round-off only). SI units.

use super::*;
use crate::integrate::rattle::Rattle;
use crate::model::{IdealPendulum, Model};
use crate::state::{Params, State};

/// The position quadratics (with arithmetic `A`) of positions on a sphere of l = 1.3 m, velocities
/// over a range of speeds and step sizes of both signs (the compositions take negative substeps),
/// g = 9.81 m/s²: `check(quad, h, what)` for each, `what` naming the case.
fn quadratic_cases<A: MulAdd>(mut check: impl FnMut(&PositionQuadratic, f64, &str)) {
    let (l, g) = (1.3, 9.81);
    for i in 0..40 {
        let th = 0.05 + 3.0 * i as f64 / 40.0;
        let x0 = DVec3::new(th.sin() * 0.6f64.cos(), th.sin() * 0.6f64.sin(), -th.cos()) * l;
        let tangent = DVec3::Z.cross(x0).normalize();
        let along = x0.cross(tangent).normalize();
        for speed in [0.0, 0.3, 2.0, 7.0, 20.0] {
            let v0 = (tangent * 0.8 + along * 0.6) * speed;
            for h in [1e-6, -3e-5, 1e-4, 1e-3, -2e-3, 5e-3, 2e-2] {
                let w = v0 + DVec3::new(0.0, 0.0, -g) * (0.5 * h);
                let quad = PositionQuadratic::new::<A>(x0, w, h, l * l);
                check(&quad, h, &format!("th {th} speed {speed} h {h}"));
            }
        }
    }
}

/// Over [`quadratic_cases`]: the series and the closed form give the same μ.
#[test]
fn series_multiplier_agrees_with_the_closed_form() {
    let mut checked = 0;
    let mut max_rel: f64 = 0.0;
    quadratic_cases::<Unfused>(|quad, h, what| {
        let (series, ok) = quad.multiplier_series::<Unfused>(h);
        let exact = quad.multiplier_exact::<Unfused>(h);
        if ok {
            let rel = (series - exact).abs() / exact.abs().max(1e-300);
            max_rel = max_rel.max(rel);
            assert!(rel <= 8.0 * f64::EPSILON, "{what}: {series} vs {exact}");
            checked += 1;
        }
        assert_eq!(quad.multiplier::<Unfused>(h).to_bits(), if ok { series } else { exact }.to_bits());
    });
    assert!(checked > 1000, "the series applied to only {checked} cases");
    eprintln!("series vs closed form: max relative difference {max_rel:.2e} over {checked} cases");
}

/// The fused arithmetic's series, short (up to y³, |y| ≤ SHORT_SERIES_LIMIT) and full, against the
/// closed form over [`quadratic_cases`]: within a few ulp where each applies, the short form applying
/// in a part of the cases only (the test's teeth), and where it applies the full form gives the same
/// bits (it takes the short polynomial there).
#[test]
fn fused_series_short_and_full_agree_with_the_closed_form() {
    let (mut short_cases, mut full_cases) = (0, 0);
    quadratic_cases::<Fused>(|quad, h, what| {
        let exact = quad.multiplier_exact::<Fused>(h);
        let (short, short_ok) = quad.multiplier_series_with::<Fused>(h, SeriesTerms::Short);
        let (full, full_ok) = quad.multiplier_series_with::<Fused>(h, SeriesTerms::Full);
        let close = |mu: f64| (mu - exact).abs() <= 8.0 * f64::EPSILON * exact.abs().max(1e-300);
        if short_ok {
            assert!(full_ok && short.to_bits() == full.to_bits(), "{what}");
            assert!(close(short), "short: {what}: {short} vs {exact}");
            short_cases += 1;
        } else if full_ok {
            assert!(close(full), "full: {what}: {full} vs {exact}");
            full_cases += 1;
        }
        let want = if full_ok { full } else { exact };
        assert_eq!(quad.multiplier::<Fused>(h).to_bits(), want.to_bits());
    });
    assert!(short_cases > 500 && full_cases > 50, "short {short_cases}, full only {full_cases}");
}

#[test]
fn the_series_covers_the_usual_steps_and_leaves_large_ones_to_the_closed_form() {
    let p = Params::new(1.0, 1.0, 9.81).unwrap();
    let s = State::from_angles(&p, 1.0, 0.0, 0.0, 2.0).unwrap();
    let at = |h: f64| {
        let w = s.v + DVec3::new(0.0, 0.0, -9.81) * (0.5 * h);
        PositionQuadratic::new::<Unfused>(s.x, w, h, 1.0).multiplier_series::<Unfused>(h).1
    };
    assert!(at(1e-3) && at(1e-2), "rosette at dt ≤ 10 ms should use the series");
    assert!(!at(0.2), "dt = 0.2 s is outside the series' range");
    // no real root: NaN, also through `multiplier`
    let w = s.v * 1e3;
    let quad = PositionQuadratic::new::<Unfused>(s.x, w, 1.0, 1.0);
    assert!(quad.multiplier::<Unfused>(1.0).is_nan());
}

/// The ideal pendulum, but declaring its kick non-uniform: RATTLE takes the general path.
#[derive(Clone, Copy)]
struct General(IdealPendulum);
impl Model for General {
    fn name(&self) -> &'static str {
        "general"
    }
    fn params(&self) -> &Params {
        self.0.params()
    }
    fn applied_acceleration(&self, t: f64, x: DVec3, v: DVec3) -> DVec3 {
        self.0.applied_acceleration(t, x, v)
    }
    fn potential_per_mass(&self, x: DVec3) -> f64 {
        self.0.potential_per_mass(x)
    }
    fn is_conservative(&self) -> bool {
        true
    }
    fn is_axisymmetric(&self) -> bool {
        true
    }
}

#[test]
fn the_uniform_field_path_agrees_with_the_general_path_to_round_off() {
    let ideal = IdealPendulum::new(1.0, 1.0, 9.81).unwrap();
    assert!(ideal.kick_is_uniform() && !General(ideal).kick_is_uniform());
    let s0 = State::from_angles(ideal.params(), 60f64.to_radians(), 0.0, 0.0, 2.0).unwrap();
    for h in [1e-3, -1e-3, 1e-2] {
        // one step: the two paths differ only by rounding
        let (mut a, mut b) = (s0, s0);
        assert!(Rattle::default().advance(&ideal, 0.0, &mut a, h));
        assert!(Rattle::default().advance(&General(ideal), 0.0, &mut b, h));
        let scale = s0.v.length();
        assert!((a.x - b.x).length() <= 4.0 * f64::EPSILON, "h {h}: {:?} vs {:?}", a.x, b.x);
        assert!((a.v - b.v).length() <= 8.0 * f64::EPSILON * scale, "h {h}: {:?} vs {:?}", a.v, b.v);
        // and the constraint x·v = 0 holds as well on the uniform path
        assert!(a.x.dot(a.v).abs() <= 4.0 * f64::EPSILON * scale, "{}", a.x.dot(a.v));
    }
    // 10⁵ steps: round-off of both paths accumulates only in the phase, to ≪ the step error
    let (mut a, mut b) = (s0, s0);
    let (mut ra, mut rb) = (Rattle::default(), Rattle::default());
    for k in 0..100_000 {
        let t = k as f64 * 1e-3;
        assert!(ra.advance(&ideal, t, &mut a, 1e-3) && rb.advance(&General(ideal), t, &mut b, 1e-3));
    }
    assert!((a.x - b.x).length() < 1e-10, "{:?} vs {:?}", a.x, b.x);
}
