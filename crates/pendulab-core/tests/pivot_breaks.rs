//! Fixed-step methods on a pivot path with breaks (docs/models.md, *Accuracy on a sampled path*): a
//! sampled pivot's spline p̈ kinks at every inner sample (`Model::next_break`). A fixed step that
//! straddles a sample is split into sub-steps ending on it, and every step runs on the spline's
//! cubic of its own sample interval (`Model::smooth_piece`), so the RATTLE compositions' substeps that
//! reach past the step see one smooth force. Each method then keeps its order against DOP853 (which
//! ends its steps on the samples), the structure-preserving ones stay on TS², the outputs stay on the
//! grid t₀ + k·dt, and a run without breaks takes exactly the bare method's steps (bits unchanged).
//! SI units: l = 1 m, g = 9.81 m/s², samples every 50 ms.

use crate::common;

use common::fixed;
use common::sampled::{params, path, start};
use pendulab_core::integrate::composition::Composition;
use pendulab_core::integrate::rattle::Rattle;
use pendulab_core::integrate::rk4::Rk4;
use pendulab_core::integrate::rkmk4::Rkmk4;
use pendulab_core::integrate::FixedStep;
use pendulab_core::model::registry::AnyModel;
use pendulab_core::model::ModelVisitor;
use pendulab_core::{DVec3, Method, Model, SolveOptions, State, Stepper};

const T_END: f64 = 4.0;

/// A smooth 3-D path (0.3 sin 1.3t, 0.2 sin(0.7t + 0.5), 0.1 cos 2t) m sampled every 50 ms on
/// [−0.1, 14.9] s, damping 0.03 1/s.
fn sampled() -> AnyModel {
    let times: Vec<f64> = (0..=300).map(|k| -0.1 + 0.05 * k as f64).collect();
    path(&times)
}

/// The state at T_END after n = T_END/dt full steps (`step_n`, the bulk loop).
fn run(model: &AnyModel, method: Method, dt: f64) -> State {
    let mut st = Stepper::new(model.clone(), 0.0, start(), &fixed(method, dt)).unwrap();
    st.step_n((T_END / dt).round() as u64).unwrap();
    assert_eq!(st.t(), (T_END / dt).round() * dt, "{method:?}: the outputs stay on the grid k·dt");
    st.state()
}

#[test]
fn every_fixed_step_method_keeps_its_order_on_a_sampled_path() {
    // dt never divides the 50 ms spacing, so most samples fall inside a step. Before the split every
    // method fell to order 2 or below here (a kink inside a step costs O(dt²) once per sample).
    let m = sampled();
    let o = SolveOptions { method: Method::Dop853, dt: 0.0, rtol: 1e-14, atol: 1e-14, project: true };
    let mut reference = Stepper::new(m.clone(), 0.0, start(), &o).unwrap();
    reference.step_to(T_END).unwrap();
    let want = reference.state().x;
    for (method, order, dt) in [
        (Method::Rattle, 2.0, 8e-3),
        (Method::Rk4, 4.0, 8e-3),
        (Method::Rkmk4, 4.0, 8e-3),
        (Method::Rattle4, 4.0, 8e-3),
        (Method::Rattle6, 6.0, 1.6e-2),
        (Method::Rattle8, 8.0, 2e-2),
    ] {
        let err = |dt: f64| (run(&m, method, dt).x - want).length();
        let (e1, e2) = (err(dt), err(dt / 2.0));
        let observed = (e1 / e2).log2();
        eprintln!(
            "{method:?}: |dx| = {e1:.2e}, {e2:.2e} m at dt = {dt}, {} s: order {observed:.2}",
            dt / 2.0
        );
        assert!((observed - order).abs() < 0.5, "{method:?}: observed order {observed} (declared {order})");
    }
}

#[test]
fn split_steps_keep_the_sphere_and_both_drivers_agree() {
    // rattle, rattle4/6/8 and rkmk4 keep |x| = l and x·v = 0 to round-off across the split steps; the
    // bulk loop (`step_n`) and the stepping towards a time (`step_to`) take the same steps, bit for bit
    let m = sampled();
    for method in [Method::Rattle, Method::Rattle4, Method::Rattle6, Method::Rattle8, Method::Rkmk4] {
        let s = run(&m, method, 7e-3);
        assert!((s.x.length() - 1.0).abs() < 1e-14, "{method:?}: |x| − l = {:e}", s.x.length() - 1.0);
        assert!(s.x.dot(s.v).abs() < 1e-13, "{method:?}: x·v = {:e}", s.x.dot(s.v));
        let mut st = Stepper::new(m.clone(), 0.0, start(), &fixed(method, 7e-3)).unwrap();
        st.step_to((T_END / 7e-3).round() * 7e-3).unwrap();
        assert_eq!(st.state(), s, "{method:?}: step_to and step_n differ");
        // every (sub-)step counts: more steps than the grid's
        assert!(st.stats().steps > (T_END / 7e-3).round() as u64, "{:?}", st.stats());
    }
}

/// `n` bare steps of `scheme` on `model`, on the grid k·dt: what the driver took before breaks existed.
fn bare<S: FixedStep>(mut scheme: S, model: &AnyModel, dt: f64, n: u64) -> State {
    let mut s = start();
    for k in 0..n {
        scheme.step(model, k as f64 * dt, &mut s, dt).unwrap();
    }
    s
}

#[test]
fn a_run_without_breaks_takes_the_bare_steps_bit_for_bit() {
    // A fixed pivot, the analytic slewing and vibrating paths, and a sampled path past its last kink
    // have no break ahead: the driver takes the method's own steps, numbers unchanged.
    let b = |name: &str, extra: &[(&str, f64)]| AnyModel::build(name, params(), extra).unwrap();
    let times = [-1.0, 0.0, 1.0, 2.0, 10.0];
    let line: Vec<DVec3> = times.iter().map(|&t| DVec3::new(0.2 * t, 0.0, 0.0)).collect();
    let models = [
        b("ideal", &[]),
        b("slewing", &[("radius", 0.5), ("rate", 0.8), ("damping", 0.1)]),
        b("vibrating", &[("amplitude", 0.05), ("frequency", 30.0)]),
        // a straight line: p⃛ = 0 everywhere, so no sample is a kink
        AnyModel::sampled_pivot(params(), &times, &line, 0.0).unwrap(),
    ];
    let (dt, n) = (3e-3, 700);
    for m in &models {
        let stepped = |method: Method| {
            let mut st = Stepper::new(m.clone(), 0.0, start(), &fixed(method, dt)).unwrap();
            st.step_n(n).unwrap();
            assert_eq!(st.stats().steps, n);
            st.state()
        };
        assert_eq!(stepped(Method::Rattle), bare(Rattle::default(), m, dt, n), "{}", m.name());
        assert_eq!(stepped(Method::Rattle4), bare(Composition::of_order(4), m, dt, n), "{}", m.name());
        assert_eq!(stepped(Method::Rattle8), bare(Composition::of_order(8), m, dt, n), "{}", m.name());
        assert_eq!(stepped(Method::Rk4), bare(Rk4, m, dt, n), "{}", m.name());
        assert_eq!(stepped(Method::Rkmk4), bare(Rkmk4::default(), m, dt, n), "{}", m.name());
    }
}

#[test]
fn the_piece_of_a_step_is_the_spline_inside_and_its_cubic_beyond() {
    // Model::smooth_piece of [1.0, 1.05] s: the model's own force inside, bit for bit; beyond, the
    // piece's p̈ continued linearly, not the next piece's
    let m = sampled();
    let times = [1.0, 1.01, 1.02, 1.04, 1.05, 1.08, 1.11];
    let piece = m.visit(PieceAt { t_mid: 1.02, times: &times });
    let x = DVec3::new(0.0, 0.0, -1.0);
    for (k, &t) in times[..4].iter().enumerate() {
        assert_eq!(piece[k], m.kick_acceleration(t, x), "inside [1.0, 1.05] at {t}");
    }
    assert!(((piece[4] + piece[6]) * 0.5 - piece[5]).length() < 1e-12, "p̈ of one piece is linear");
    let next = m.kick_acceleration(1.08, x);
    assert!((piece[5] - next).length() > 1e-6, "the next piece's p̈ differs (the kink): {next}");
}

/// The kick accelerations at `times` of the model's smooth piece at `t_mid`, through the concrete model.
struct PieceAt<'a> {
    t_mid: f64,
    times: &'a [f64],
}

impl ModelVisitor for PieceAt<'_> {
    type Output = Vec<DVec3>;
    fn visit<M: Model>(self, model: &M) -> Vec<DVec3> {
        let piece = model.smooth_piece(self.t_mid).expect("a sampled pivot has pieces");
        self.times.iter().map(|&t| piece.kick_acceleration(t, DVec3::new(0.0, 0.0, -1.0))).collect()
    }
}
