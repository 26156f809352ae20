//! The RATTLE kernel's arithmetic is plain IEEE a·b + c (two roundings), never a fused multiply-add:
//! the stepper (at the best instruction-set level of this CPU, and restricted to the baseline) and the
//! ensemble kernel give, bit for bit, the numbers of a reference step written out below with explicit
//! unfused `*` and `+` in the kernel's order of operations (T-2.1, T-2.2; the module doc of
//! `integrate::rattle_kernel`). Because + − × ÷ are correctly rounded on every CPU and in
//! WebAssembly, these are then the numbers of every x86-64 level, of aarch64 and of the page's engine
//! (docs/performance.md, "No CPU left behind"). The opt-in fused arithmetic (`Arithmetic::Fused`:
//! `f64::mul_add` and its own shorter forms of the series and the projection polynomial) is checked
//! the same way against the reference written with it. The test has teeth: each arithmetic's
//! reference gives other bits than the other's. SI units: \[m\], [m/s], \[s\].

use pendulab_core::ensemble::{run, RattleSettings};
use pendulab_core::integrate::rattle_kernel::Arithmetic;
use pendulab_core::isa;
use pendulab_core::Model;
use pendulab_core::{IdealPendulum, Method, Params, SolveOptions, State, Stepper};
use std::sync::atomic::{AtomicBool, AtomicU64};

type V = [f64; 3];

fn add(a: V, b: V) -> V {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}
fn sub(a: V, b: V) -> V {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
/// a·b + c: unfused, or fused when `fused` (the test's teeth: the kernel before 2026-11-26).
fn fm(a: f64, b: f64, c: f64, fused: bool) -> f64 {
    if fused {
        a.mul_add(b, c)
    } else {
        a * b + c
    }
}
/// a·s + c componentwise.
fn fm3(a: V, s: f64, c: V, fused: bool) -> V {
    [fm(a[0], s, c[0], fused), fm(a[1], s, c[1], fused), fm(a[2], s, c[2], fused)]
}
/// a_z b_z + (a_y b_y + a_x b_x).
fn dot(a: V, b: V, fused: bool) -> f64 {
    fm(a[2], b[2], fm(a[1], b[1], a[0] * b[0], fused), fused)
}

/// The ideal pendulum's RATTLE steps from (x, v), compensations carried, uniform-field path with the
/// Catalan series for μ (asserted to apply); with `fused`, every multiply-add fused and the fused
/// arithmetic's own forms of the series (short or full) and the projection polynomial
/// (`rattle_kernel` module doc) in a vertical field (`rattle_vertical` module doc). Also returns in
/// how many steps the fused series stopped after y³.
fn reference(x: V, v: V, l: f64, g: f64, h: f64, steps: usize, fused: bool) -> (V, V, usize) {
    let f = fused;
    let (mut x, mut v) = (x, v);
    let (mut cx, mut cv) = ([0.0; 3], [0.0; 3]);
    let half = 0.5 * h;
    let l2 = l * l;
    let inv_l2 = 1.0 / l2;
    let kick = [0.0 * half, 0.0 * half, -g * half];
    let mut short_steps = 0;
    for _ in 0..steps {
        // the fused arithmetic takes the vertical-field form (integrate/rattle_vertical.rs): the
        // kicks' zero components not added, x₀·e and w·e from x₀·w and |w|²
        let w = if f { [v[0], v[1], v[2] + kick[2]] } else { add(v, kick) };
        let q = dot(x, x, f);
        let xw = dot(x, w, f);
        let ww = dot(w, w, f);
        let b = fm(h, xw, q, f);
        let c = fm(h, fm(h, ww, xw + xw, f), q - l2, f);
        let ib = 1.0 / b;
        let mu = if f {
            // the fused arithmetic's forms: y = 4z = (q/b)(c/b), C(y) with Catₙ/4ⁿ by Estrin's
            // scheme (pairs in y, then y², then y⁴)
            let t = c * ib;
            let y = (q * ib) * t;
            assert!(y.abs() <= 4e-3 && b > 0.0, "the series must apply (y = {y:e})");
            let y2 = y * y;
            let (p01, p23) = (fm(0.25, y, 1.0, f), fm(5.0 / 64.0, y, 0.125, f));
            let p45 = fm(21.0 / 512.0, y, 7.0 / 128.0, f);
            let (p03, p46) = (fm(p23, y2, p01, f), fm(33.0 / 1024.0, y2, p45, f));
            // up to y³ where |y| ≤ 10⁻⁴ (SHORT_SERIES_LIMIT), up to y⁶ elsewhere
            let short = y.abs() <= 1e-4;
            short_steps += usize::from(short);
            let series = if short { p03 } else { fm(p46, y2 * y2, p03, f) };
            t * (-0.5 / h) * series
        } else {
            let z = 0.25 * q * c * (ib * ib);
            assert!(z.abs() <= 1e-3 && b > 0.0, "the series must apply (z = {z:e})");
            let z2 = z * z;
            let low = fm(z2, fm(5.0, z, 2.0, f), 1.0 + z, f);
            let high = fm(z2, 132.0, fm(42.0, z, 14.0, f), f);
            let series = fm(z2 * z2, high, low, f);
            c * (ib * (-0.5 / h)) * series
        };
        let v_half = fm3(x, mu, w, f);
        let y = fm3(v_half, h, [-cx[0], -cx[1], -cx[2]], f);
        let x1 = add(x, y);
        cx = sub(sub(x1, x), y);
        let (p, inner) = if f {
            // fused: x₀·e = x₀·w + x₀_z κ, w·e = |w|² + w_z κ, the coefficients unscaled, one
            // product by 1/l²; the kicks' zero components not subtracted from
            let (xe, we) = (fm(x[2], kick[2], xw, f), fm(w[2], kick[2], ww, f));
            let (pa, pb, pc) = (fm(h, we, xe, f), fm(h, xe, b, f), h * q);
            let inner = [
                fm(x[0], mu, -cv[0], f),
                fm(x[1], mu, -cv[1], f),
                fm(x[2], mu, (kick[2] + kick[2]) - cv[2], f),
            ];
            (fm(mu, fm(mu, pc, pb, f), pa, f) * inv_l2, inner)
        } else {
            let e = add(w, kick);
            let xe = dot(x, e, f);
            let (pa, pb, pc) =
                (fm(h, dot(w, e, f), xe, f) * inv_l2, fm(h, xe, b, f) * inv_l2, h * q * inv_l2);
            (fm(mu, fm(mu, pc, pb, f), pa, f), fm3(x, mu, sub(add(kick, kick), cv), f))
        };
        let yv = fm3(x1, -p, inner, f);
        let v1 = add(v, yv);
        cv = sub(sub(v1, v), yv);
        (x, v) = (x1, v1);
    }
    (x, v, short_steps)
}

fn bits(x: V, v: V) -> Vec<u64> {
    x.iter().chain(v.iter()).map(|a| a.to_bits()).collect()
}

fn state_bits(s: &State) -> Vec<u64> {
    bits(s.x.to_array(), s.v.to_array())
}

/// Each arithmetic (the default unfused one, and the opt-in fused one) against its reference: the
/// stepper at the best level and at the baseline (where `f64::mul_add` is the C library's exact fma),
/// a RATTLE4 stepper's reset keeping the choice, and the ensemble.
#[test]
fn rattle_is_the_reference_of_its_arithmetic_bit_for_bit_at_every_level_and_in_the_ensemble() {
    let (l, g, steps) = (1.3, 9.81, 2000);
    let params = Params::new(l, 0.7, g).unwrap();
    let starts: Vec<State> = [(1.1, 0.2, 0.3, 1.4), (0.4, 0.0, 0.0, 2.5), (2.7, 1.0, -0.5, 0.3)]
        .iter()
        .map(|&(th, ph, thd, phd)| State::from_angles(&params, th, ph, thd, phd).unwrap())
        .collect();
    let ideal = IdealPendulum::new(l, 0.7, g).unwrap();
    for arithmetic in Arithmetic::ALL {
        let fused = arithmetic == Arithmetic::Fused;
        // h = 1 ms: the fused series stops after y³ at every step; h = 10 ms: at some steps of some
        // trajectories only (the ensemble's tiles then mix both forms, lane by lane)
        for (h, all_short) in [(1e-3, true), (1e-2, false)] {
            let opts = SolveOptions { method: Method::Rattle, dt: h, ..SolveOptions::default() };
            let mut expected = Vec::new();
            let mut short_steps = 0;
            for s0 in &starts {
                let (x0, v0) = (s0.x.to_array(), s0.v.to_array());
                let (x, v, short) = reference(x0, v0, l, g, h, steps, fused);
                short_steps += short;
                let want = bits(x, v);
                let (xo, vo, _) = reference(x0, v0, l, g, h, steps, !fused);
                assert_ne!(bits(xo, vo), want, "the other arithmetic gives other bits (the test's teeth)");
                for baseline in [false, true] {
                    isa::set_baseline_only(baseline);
                    let mut st = Stepper::new(ideal, 0.0, *s0, &opts).unwrap();
                    st.set_arithmetic(arithmetic).unwrap();
                    st.step_n(steps as u64).unwrap();
                    isa::set_baseline_only(false);
                    assert_eq!(
                        state_bits(&st.state()),
                        want,
                        "{arithmetic:?} stepper ({}) from {s0:?}, h = {h}",
                        isa::selected()
                    );
                }
                expected.push(want);
            }
            if fused {
                let total = steps * starts.len();
                if all_short {
                    assert_eq!(short_steps, total, "h = {h}: the short series at every step");
                } else {
                    assert!(
                        0 < short_steps && short_steps < total,
                        "h = {h}: {short_steps} of {total} short"
                    );
                }
            }
            let (progress, cancel) = (AtomicU64::new(0), AtomicBool::new(false));
            let (ls, gs) = ([l], [g]);
            let set = RattleSettings { arithmetic, ..RattleSettings::new(&ls, &gs, h, steps as u64) };
            let ens = run(&starts, &set, &progress, &cancel).unwrap();
            for (k, want) in expected.iter().enumerate() {
                assert_eq!(
                    &state_bits(ens.trajectory(k).last().unwrap()),
                    want,
                    "{arithmetic:?} ensemble, trajectory {k}, h = {h}"
                );
            }
        }
        let h = 1e-3;
        // RATTLE4 keeps the choice through a reset (set_state), and it changes its numbers
        let opts4 = SolveOptions { method: Method::Rattle4, dt: h, ..SolveOptions::default() };
        let run4 = |a: Arithmetic| {
            let mut st = Stepper::new(ideal, 0.0, starts[0], &opts4).unwrap();
            st.set_arithmetic(a).unwrap();
            st.step_n(10).unwrap();
            st.set_state(starts[0]);
            st.step_n(100).unwrap();
            state_bits(&st.state())
        };
        let mut fresh = Stepper::new(ideal, 0.0, starts[0], &opts4).unwrap();
        fresh.set_arithmetic(arithmetic).unwrap();
        fresh.step_n(100).unwrap();
        assert_eq!(
            run4(arithmetic),
            state_bits(&fresh.state()),
            "{arithmetic:?}: reset keeps the arithmetic"
        );
        assert_ne!(run4(Arithmetic::Unfused), run4(Arithmetic::Fused));
    }
}

/// Fused arithmetic is for the RATTLE family only; unfused is every method's.
#[test]
fn fused_arithmetic_is_refused_outside_the_rattle_family() {
    let ideal = IdealPendulum::new(1.0, 1.0, 9.81).unwrap();
    let s0 = State::from_angles(ideal.params(), 1.0, 0.0, 0.0, 1.0).unwrap();
    for method in Method::ALL {
        let opts = SolveOptions { method, dt: 1e-3, ..SolveOptions::default() };
        let mut st = Stepper::new(ideal, 0.0, s0, &opts).unwrap();
        assert!(st.set_arithmetic(Arithmetic::Unfused).is_ok());
        let fused = st.set_arithmetic(Arithmetic::Fused);
        if method.info().name.starts_with("rattle") {
            assert!(fused.is_ok(), "{method:?}");
        } else {
            let msg = fused.unwrap_err().to_string();
            assert!(msg.contains("fused") && msg.contains(method.info().name), "{msg}");
        }
    }
    assert_eq!(Arithmetic::from_name("fused").unwrap(), Arithmetic::Fused);
    assert!(Arithmetic::from_name("fma").unwrap_err().to_string().contains("unfused"));
}
