//! The swinging spring (docs/theory.md T-7.4): observed orders 2 and 4, E bounded and J₃ kept to round-off
//! over 10⁶ steps (symplectic, axisymmetric), and at the 1:1:2 resonance the energy exchange between
//! bouncing and swinging and the stepwise turning of the swing plane. SI units: l = 1 m equilibrium,
//! g = 9.81 m/s², m = 1 kg.

use pendulab_core::elastic::SwingingSpring;
use pendulab_core::{DVec3, State};

fn spring() -> SwingingSpring {
    SwingingSpring::resonant(1.0, 9.81, 1.0).unwrap()
}

fn run(sp: &SwingingSpring, s0: State, t: f64, dt: f64, order: u32) -> State {
    let n = (t / dt).round() as u64;
    *sp.simulate(s0, dt, n, n, order).unwrap().1.last().unwrap()
}

#[test]
fn observed_orders() {
    let sp = spring();
    let s0 = State { x: DVec3::new(0.1, 0.05, -1.05), v: DVec3::new(0.0, 0.2, 0.1) };
    let reference = run(&sp, s0, 2.0, 1e-4, 4);
    for (order, dt) in [(2u32, 4e-3), (4, 2e-2)] {
        let err = |dt: f64| (run(&sp, s0, 2.0, dt, order).x - reference.x).length();
        let observed = (err(dt) / err(dt / 2.0)).log2();
        assert!((observed - order as f64).abs() < 0.3, "order {order}: observed {observed}");
    }
}

#[test]
fn energy_bounded_and_j3_kept_over_a_million_steps() {
    let sp = spring();
    let s0 = State { x: DVec3::new(0.1, 0.05, -1.05), v: DVec3::new(0.0, 0.2, 0.1) };
    let (_, states) = sp.simulate(s0, 1e-3, 1_000_000, 1000, 2).unwrap();
    let (e0, j0) = (sp.energy(&s0), sp.j3(&s0));
    let de: Vec<f64> = states.iter().map(|s| (sp.energy(s) - e0).abs()).collect();
    let half = de.len() / 2;
    let (first, second) =
        (de[..half].iter().cloned().fold(0.0, f64::max), de[half..].iter().cloned().fold(0.0, f64::max));
    assert!(second <= 1.5 * first, "energy drifts: {first:e} then {second:e}");
    let dj = states.iter().map(|s| (sp.j3(s) - j0).abs()).fold(0.0, f64::max);
    assert!(dj < 1e-12 * j0.abs().max(1e-3), "J₃ changed by {dj:e}");
}

/// Bouncing energy: spring stretch and radial motion about the equilibrium length [J].
fn bounce(sp: &SwingingSpring, s: &State) -> f64 {
    let r = s.x.length();
    let rdot = s.x.dot(s.v) / r;
    let dl = r - sp.equilibrium_length();
    sp.mass * (0.5 * rdot * rdot + 0.5 * sp.k_over_m * dl * dl)
}

#[test]
fn resonance_exchanges_energy_and_turns_the_swing_plane_in_steps() {
    let sp = spring();
    // mostly bouncing, with a small swing slightly out of one plane
    let s0 = State { x: DVec3::new(0.01, 0.002, -1.0 - 0.05), v: DVec3::new(0.0, 0.003, 0.0) };
    let (t, states) = sp.simulate(s0, 1e-3, 200_000, 10, 4).unwrap();
    let b: Vec<f64> = states.iter().map(|s| bounce(&sp, s)).collect();
    let b0 = b[0];
    // the bouncing energy drains to a small fraction and comes back, periodically
    let coarse: Vec<String> = b.iter().step_by(500).map(|v| format!("{:.2}", v / b0)).collect();
    eprintln!("bouncing energy / start, every 5 s: {}", coarse.join(" "));
    let first_low = b.iter().position(|&v| v < 0.1 * b0).expect("bouncing energy never fell below 10 %");
    let back = b[first_low..].iter().cloned().fold(0.0, f64::max);
    assert!(back > 0.8 * b0, "energy did not return to bouncing ({:.2})", back / b0);
    // swing plane azimuth during each swinging episode (bouncing energy < 20 %): nearly constant
    // inside an episode, different between successive episodes
    let mut episodes: Vec<Vec<f64>> = vec![];
    let mut starts: Vec<f64> = vec![];
    let mut inside = false;
    for (k, s) in states.iter().enumerate() {
        let swinging = b[k] < 0.2 * b0;
        if swinging && !inside {
            episodes.push(vec![]);
            starts.push(t[k]);
        }
        inside = swinging;
        let rho = s.x.x.hypot(s.x.y);
        if swinging && rho > 0.5 * 0.1 {
            // direction of the swing (a line: fold to (−π/2, π/2])
            let mut a = s.x.y.atan2(s.x.x);
            if a > std::f64::consts::FRAC_PI_2 {
                a -= std::f64::consts::PI;
            } else if a <= -std::f64::consts::FRAC_PI_2 {
                a += std::f64::consts::PI;
            }
            episodes.last_mut().unwrap().push(a);
        }
    }
    let mean = |v: &Vec<f64>| v.iter().sum::<f64>() / v.len() as f64;
    let full: Vec<&Vec<f64>> = episodes.iter().filter(|e| e.len() > 20).collect();
    eprintln!(
        "{} swinging episodes in {} s; plane azimuths {:?}",
        full.len(),
        t.last().unwrap(),
        full.iter().map(|e| mean(e)).collect::<Vec<_>>()
    );
    assert!(full.len() >= 2, "expected at least two swinging episodes");
    // the exchange is periodic: successive swinging episodes start a fixed time apart
    let gaps: Vec<f64> = starts.windows(2).map(|w| w[1] - w[0]).collect();
    let mean_gap = gaps.iter().sum::<f64>() / gaps.len() as f64;
    eprintln!("exchange period {mean_gap:.2} s (gaps {gaps:?})");
    assert!(gaps.iter().all(|g| (g - mean_gap).abs() < 0.1 * mean_gap), "not periodic: {gaps:?}");
    for w in full.windows(2) {
        let step = (mean(w[1]) - mean(w[0])).abs();
        let spread = w[0].iter().map(|a| (a - mean(w[0])).abs()).fold(0.0, f64::max);
        assert!(step > 2.0 * spread, "plane turned by {step} between episodes, spread {spread} inside one");
    }
}

#[test]
fn the_incremental_stepper_is_the_run_step_for_step() {
    use pendulab_core::elastic::SpringStepper;
    let sp = spring();
    let s0 = State { x: DVec3::new(0.1, 0.05, -1.05), v: DVec3::new(0.0, 0.2, 0.1) };
    for order in [2u32, 4] {
        let (t, states) = sp.simulate(s0, 1e-3, 1000, 1, order).unwrap();
        let mut st = SpringStepper::new(sp, s0, 0.0, 1e-3, order).unwrap();
        let mut k = 0usize;
        for piece in [1usize, 3, 50].iter().cycle() {
            if k + piece > 1000 {
                break;
            }
            st.step(*piece as u64).unwrap();
            k += piece;
            assert_eq!(st.t(), t[k]);
            assert_eq!(st.state(), states[k], "order {order}, step {k}");
        }
        assert_eq!(sp.tension(&s0), (s0.x.length() - sp.rest_length) * sp.k_over_m * sp.mass);
    }
    assert!(SpringStepper::new(sp, s0, 0.0, 1e-3, 3).is_err());
    assert!(SpringStepper::new(sp, State { x: DVec3::ZERO, v: DVec3::ZERO }, 0.0, 1e-3, 2).is_err());
}

#[test]
fn the_equilibrium_length_is_where_the_bob_rests_for_either_sign_of_g() {
    // l = l₀ + |g|/(k/m), on the side of the pivot gravity pulls to (above it for g < 0): r̈ = 0 there;
    // for g < 0 the old l₀ + g/(k/m) was the compressed, unstable point (r̈ = 8 m/s² up at its mirror)
    for g in [9.81, -4.0] {
        let sp = SwingingSpring::new(20.0, 0.8, g, 1.0).unwrap();
        let ell = sp.equilibrium_length();
        assert!((ell - (0.8 + g.abs() / 20.0)).abs() < 1e-15, "g = {g}: l = {ell}");
        let a = sp.acceleration(DVec3::new(0.0, 0.0, -g.signum() * ell));
        assert!(a.length() < 1e-14, "g = {g}: r̈ = {a} at the equilibrium");
    }
}

#[test]
fn the_resonance_for_negative_g_is_the_mirror_image() {
    // k/m = 4|g|/l at the stable rest length above the pivot (was: refused, 'needs gravity g > 0');
    // g = 0 has no swing frequency and is refused naming g
    let (up, down) = (SwingingSpring::resonant(1.0, -9.81, 1.0).unwrap(), spring());
    assert_eq!((up.k_over_m, up.rest_length, up.g), (down.k_over_m, down.rest_length, -9.81));
    assert!((up.equilibrium_length() - 1.0).abs() < 1e-15);
    let err = SwingingSpring::resonant(1.0, 0.0, 1.0).unwrap_err().to_string();
    assert!(err.contains("g") && err.contains("other than 0"), "{err}");
}

#[test]
fn the_registry_says_where_the_spring_rests() {
    // the rest point is l0 + m|g|/k, above the pivot for g < 0 (was: 'hangs at l = l0 + m g/k')
    let spec = pendulab_core::model::registry::spec("spring").unwrap();
    let text = spec.params.iter().find(|p| p.name == "stiffness").unwrap().description;
    assert!(text.contains("l = l0 + m|g|/k") && text.contains("above it for g < 0"), "{text}");
    assert!(text.contains("k = 3 m|g|/l0") && !text.contains("m g/k"), "{text}");
}

/// A spring run that blows up (ω·dt = 100: Störmer–Verlet is unstable) names the last finite state's
/// time and the step (the spring's own step named t = NaN), in a batch run and in the lab's stepper.
#[test]
fn a_divergence_names_the_last_finite_time_and_the_step() {
    use pendulab_core::elastic::SpringStepper;
    use pendulab_core::Error;
    let sp = SwingingSpring::new(1e6, 1.0, 9.81, 1.0).unwrap();
    let s0 = State { x: DVec3::new(0.1, 0.0, -1.0), v: DVec3::ZERO };
    let dt = 0.1;
    let e = sp.simulate(s0, dt, 1000, 1, 2).unwrap_err();
    let Error::Diverged { t, method: "spring verlet", dt: named } = e else { panic!("{e}") };
    assert_eq!(named, dt, "{e}");
    let k = (t / dt).round();
    assert!(t.is_finite() && k > 0.0 && (t - k * dt).abs() < 1e-9, "{e}");
    let mut lab = SpringStepper::new(sp, s0, 0.0, dt, 2).unwrap();
    assert_eq!(lab.step(1000).unwrap_err(), e, "the lab's stepper names the same");
    assert_eq!(lab.t(), t, "it stands at the time named");
    assert!(lab.state().is_finite());
    let mut s = lab.state();
    let step = sp.step(t, &mut s, dt, 2).unwrap_err();
    assert_eq!(step, e, "one step of the spring from there names the same");
}
