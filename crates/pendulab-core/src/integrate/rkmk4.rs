//! Runge–Kutta–Munthe-Kaas of order 4 on TS² (Munthe-Kaas 1999; Iserles, Munthe-Kaas, Nørsett &
//! Zanna, *Lie-group methods*, Acta Numerica 2000, §5), with the exponential map of SO(3).
//!
//! The state is written as (x, ω) with the angular velocity ω = x × v / l², so that v = ω × x.
//! The group G = SO(3) × R³ acts by (R, b)·(x, ω) = (R x, ω + b), and the equations of motion
//! (from T-2.2: d/dt (x × v) = x × f because x × λx = 0) read
//!
//! ```text
//! ẋ = ω × x,            ω̇ = x × f(t, x, ω × x) / l²,
//! ```
//!
//! i.e. ẏ = F(y)·y with F = (ω, x × f / l²) in the Lie algebra so(3) × R³, whose bracket is
//! [(a₁, b₁), (a₂, b₂)] = (a₁ × a₂, 0). RKMK applies the classic RK4 tableau to the algebra ODE
//! u̇ = dexp⁻¹_u(F(exp(u)·y₀)), with dexp⁻¹_u(w) = w − ½[u, w] + (1/12)[u, [u, w]] + O(u⁴) (enough
//! for order 4), and sets y₁ = exp(u₁)·y₀. The exponential of a ∈ so(3) is Rodrigues' rotation.
//!
//! Each step sets ω₁ = P(x₁)(ω₀ + u₁'), where u = (u₁, u₁') and P(x) w = w − x (x·w)/l² removes
//! the component of ω along x. In exact arithmetic x·ω is a first integral of the equations above
//! (it is 0 on TS²), so P changes only the O(h⁵) local error; it is exactly what computing
//! ω₁ = x₁ × v₁ / l² from v₁ = ω₁ × x₁ did in earlier versions.
//!
//! Round-off. Only small increments enter the state: x₁ = x₀ + Δx with the rotation increment
//! Δx = exp(û₁)x₀ − x₀ = s u₁ × x₀ + c u₁ × (u₁ × x₀) (s = sin θ/θ, c = (1 − cos θ)/θ² = ½(sin(θ/2)/(θ/2))²,
//! θ = |u₁|), never formed as a difference, and ω₁ = ω₀ + Δω with Δω = u₁' − x₁(x₁·(ω₀ + u₁'))/l².
//! Both sums are compensated (Kahan): the bits that rounding drops from each increment are carried
//! in the integrator and added back on the next step, and ω is carried between steps (with its
//! compensation) instead of being recomputed as x × v / l² from the rounded state. The sphere
//! constraint is kept by a radial correction of the compensated x: the defect |x|² − l² is
//! evaluated without rounding error (Dekker's exact products) and x is scaled by 1 − δ,
//! δ = (|x|² − l²)/(2l²), inside the compensation. Each of the former per-step operations
//! (ω = x × v/l², x₁ formed in one expression, x₁ scaled to |x₁| = l in floating point) injected an
//! O(ε) error per step, partly biased in energy, so that the error grew like ε·(number of steps):
//! on `near_top` to t = 100 s it rose from 6e-7 at dt = 1e-3 s to 2e-4 at dt = 3e-6 s. Now the
//! error falls like h⁴ down to a round-off floor of ~1e-11 there and stays near it.
//!
//! The carried ω and compensations are used only while the state passed to
//! [`FixedStep::step`] is bit for bit the one the previous step returned; a state changed from
//! outside (or [`FixedStep::reset`]) starts afresh from ω = x × v / l².
//!
//! Properties: order 4; x stays on the sphere (rotations, plus the radial correction above that
//! keeps |x| = l to round-off without accumulating) and v = ω × x is tangent by construction.
//! Not symplectic; energy and J₃ drift like O(h⁴) per unit time.

use super::FixedStep;
use crate::error::{Error, Result};
use crate::model::Model;
use crate::state::State;
use glam::DVec3;

/// RKMK4 on TS², 4 evaluations per step.
///
/// Carries ω between steps and the Kahan compensations of x and ω (see the module doc); `last` is
/// the state the previous step returned, to recognise a state changed from outside.
#[derive(Debug, Clone, Copy, Default)]
pub struct Rkmk4 {
    omega: DVec3,
    comp_x: DVec3,
    comp_omega: DVec3,
    last: Option<State>,
}

/// Rodrigues' formula: exp(â) x, the rotation of x by angle |a| about a/|a|.
#[inline]
pub fn rotate(a: DVec3, x: DVec3) -> DVec3 {
    x + rotation_increment(a, x)
}

/// exp(â) x − x = s a × x + c a × (a × x), computed without forming the difference, so that a
/// small rotation has a small increment with full relative precision.
#[inline]
pub fn rotation_increment(a: DVec3, x: DVec3) -> DVec3 {
    let angle2 = a.length_squared();
    // s = sin(θ)/θ and c = (1 − cos θ)/θ² with series near θ = 0 (accurate to round-off below
    // θ = 1e-4); otherwise c = ½ (sin(θ/2)/(θ/2))², which has no cancellation (1 − cos θ loses
    // ε/θ² relative precision).
    let (s, c) = if angle2 < 1e-8 {
        (1.0 - angle2 / 6.0, 0.5 - angle2 / 24.0)
    } else {
        let angle = angle2.sqrt();
        let half = 0.5 * angle;
        let sinc_half = half.sin() / half;
        (angle.sin() / angle, 0.5 * sinc_half * sinc_half)
    };
    let ax = a.cross(x);
    ax * s + a.cross(ax) * c
}

/// Kahan summation: returns s + d with the running compensation `c` (true sum ≈ result − c).
#[inline(always)]
fn compensated_add(s: DVec3, d: DVec3, c: &mut DVec3) -> DVec3 {
    let y = d - *c;
    let t = s + y;
    *c = (t - s) - y;
    t
}

/// Dekker's split of a into hi + lo with 26-bit halves (products of halves are exact).
#[inline(always)]
fn split(a: f64) -> (f64, f64) {
    let c = 134_217_729.0 * a; // 2^27 + 1
    let hi = c - (c - a);
    (hi, a - hi)
}

/// a² = p + e exactly (Dekker 1971), without relying on a hardware fused multiply-add.
#[inline(always)]
fn exact_square(a: f64) -> (f64, f64) {
    let p = a * a;
    let (hi, lo) = split(a);
    (p, ((hi * hi - p) + 2.0 * hi * lo) + lo * lo)
}

/// a + b = s + e exactly (Knuth's TwoSum).
#[inline(always)]
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

/// |x|² − l², accurate to a few ulp of the result itself (not of l²), for |x| ≈ l.
#[inline]
fn sphere_defect(x: DVec3, l: f64) -> f64 {
    let (p0, e0) = exact_square(x.x);
    let (p1, e1) = exact_square(x.y);
    let (p2, e2) = exact_square(x.z);
    let (pl, el) = exact_square(l);
    let (s1, f1) = two_sum(p0, p1);
    let (s2, f2) = two_sum(s1, p2);
    let (s3, f3) = two_sum(s2, -pl);
    s3 + (((f1 + f2) + f3) + ((e0 + e1) + (e2 - el)))
}

/// The algebra element F(t, x, ω) = (ω, x × f / l²) of the equations above.
#[inline]
fn field<M: Model>(model: &M, t: f64, x: DVec3, omega: DVec3) -> (DVec3, DVec3) {
    let l2 = model.params().length.powi(2);
    let v = omega.cross(x);
    (omega, x.cross(model.applied_acceleration(t, x, v)) / l2)
}

/// dexp⁻¹_u(w) truncated after the second commutator; only the so(3) part has a bracket.
#[inline]
fn dexp_inv(u: (DVec3, DVec3), w: (DVec3, DVec3)) -> (DVec3, DVec3) {
    let uw = u.0.cross(w.0);
    (w.0 - uw * 0.5 + u.0.cross(uw) / 12.0, w.1)
}

impl FixedStep for Rkmk4 {
    fn step<M: Model>(&mut self, model: &M, t: f64, s: &mut State, h: f64) -> Result<()> {
        let l = model.params().length;
        let l2 = l * l;
        if self.last != Some(*s) {
            // A new state, or one changed from outside: start the carried quantities afresh.
            *self = Self { omega: s.x.cross(s.v) / l2, ..Self::default() };
        }
        let (x0, omega0) = (s.x, self.omega);
        let act = |u: (DVec3, DVec3)| (rotate(u.0, x0), omega0 + u.1);
        let scale = |k: (DVec3, DVec3), c: f64| (k.0 * c, k.1 * c);
        let stage = |u: (DVec3, DVec3), tau: f64| {
            let (x, om) = act(u);
            scale(dexp_inv(u, field(model, tau, x, om)), h)
        };
        let k1 = scale(field(model, t, x0, omega0), h);
        let k2 = stage(scale(k1, 0.5), t + 0.5 * h);
        let k3 = stage(scale(k2, 0.5), t + 0.5 * h);
        let k4 = stage(k3, t + h);
        let u = ((k1.0 + (k2.0 + k3.0) * 2.0 + k4.0) / 6.0, (k1.1 + (k2.1 + k3.1) * 2.0 + k4.1) / 6.0);
        // x₁ = x₀ + Δx and ω₁ = ω₀ + Δω as compensated sums of small increments (module doc).
        let x1 = compensated_add(x0, rotation_increment(u.0, x0), &mut self.comp_x);
        let omega_dot_x = x1.dot(omega0) + x1.dot(u.1);
        let omega1 = compensated_add(omega0, u.1 - x1 * (omega_dot_x / l2), &mut self.comp_omega);
        // Radial correction of the compensated x = x₁ − comp_x: scale by 1 − δ with
        // δ = (|x|² − l²)/(2l²) (the error, O(δ²), is far below round-off), applied to the
        // compensation, then fold the compensation into x₁ where it reaches an ulp of x₁ (Fast2Sum,
        // exact where |comp_x| ≤ |x₁| componentwise, and otherwise off by far less than an ulp of l).
        // A start off the sphere by more than round-off (within the TS² tolerance) is scaled onto it
        // directly, as before.
        let delta = (sphere_defect(x1, l) - 2.0 * x1.dot(self.comp_x)) / (2.0 * l2);
        let x1 = if delta.abs() < 1e-12 {
            let comp = self.comp_x + x1 * delta;
            let x1_folded = x1 - comp;
            self.comp_x = comp - (x1 - x1_folded);
            x1_folded
        } else {
            self.comp_x = DVec3::ZERO;
            x1 * (l / x1.length())
        };
        self.omega = omega1;
        s.x = x1;
        s.v = omega1.cross(x1);
        if !s.is_finite() {
            self.last = None;
            return Err(Error::Diverged { t, method: "rkmk4", dt: h });
        }
        self.last = Some(*s);
        Ok(())
    }

    fn evals_per_step(&self) -> u64 {
        4
    }

    fn reset(&mut self) {
        *self = Self::default();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rodrigues_rotates_by_the_right_angle() {
        let x = DVec3::X;
        let r = rotate(DVec3::Z * std::f64::consts::FRAC_PI_2, x);
        assert!((r - DVec3::Y).length() < 1e-15);
        let small = rotate(DVec3::Z * 1e-6, x);
        assert!((small - DVec3::new(1e-6f64.cos(), 1e-6f64.sin(), 0.0)).length() < 1e-17);
        // The increment keeps full relative precision for a tiny angle (no 1 − cos cancellation).
        let d = rotation_increment(DVec3::Z * 1e-3, x);
        let want = DVec3::new(-2.0 * 5e-4f64.sin().powi(2), 1e-3f64.sin(), 0.0);
        assert!((d - want).length() <= 1e-15 * want.length(), "{d:?} vs {want:?}");
    }

    #[test]
    fn sphere_defect_is_exact_where_plain_arithmetic_rounds() {
        // Components in [0.5, 1) are integers m times 2⁻⁵³, so |x|² − 1 = (Σ m² − 2¹⁰⁶)/2¹⁰⁶ exactly.
        let scale = 2f64.powi(53);
        for (a, b) in [(0.6, 0.8), (0.6 + 1e-16, 0.8), (0.75, 0.6614378277661477)] {
            let (ma, mb) = ((a * scale) as i128, (b * scale) as i128);
            let exact = (ma * ma + mb * mb - (1i128 << 106)) as f64 / 2f64.powi(106);
            let got = sphere_defect(DVec3::new(a, b, 0.0), 1.0);
            assert!((got - exact).abs() <= 1e-3 * exact.abs(), "{a}, {b}: {got:e} vs {exact:e}");
        }
        assert_eq!(sphere_defect(DVec3::new(0.0, 0.0, 3.0), 3.0), 0.0);
    }

    #[test]
    fn a_state_changed_from_outside_restarts_the_carried_omega() {
        use crate::model::IdealPendulum;
        let model = IdealPendulum::new(1.3, 1.0, 9.81).unwrap();
        let a = State::from_angles(model.params(), 1.0, 0.0, 0.3, 1.5).unwrap();
        let b = State::from_angles(model.params(), 2.0, 0.5, -0.4, 0.7).unwrap();
        let (mut carried, mut fresh) = (Rkmk4::default(), Rkmk4::default());
        let mut s = a;
        for k in 0..10 {
            carried.step(&model, k as f64 * 1e-2, &mut s, 1e-2).unwrap();
        }
        // Replaced without reset(): the integrator must notice and not use its carried ω.
        let (mut s1, mut s2) = (b, b);
        carried.step(&model, 0.1, &mut s1, 1e-2).unwrap();
        fresh.step(&model, 0.1, &mut s2, 1e-2).unwrap();
        assert_eq!(s1, s2);
        // Continuing from its own output it carries ω: x·v = 0 and |x| = l to round-off.
        for k in 0..1000 {
            carried.step(&model, 0.11 + k as f64 * 1e-2, &mut s1, 1e-2).unwrap();
        }
        assert!((s1.x.length() - 1.3).abs() < 4.0 * f64::EPSILON, "{}", s1.x.length());
        assert!(s1.x.dot(s1.v).abs() < 1e-14 * s1.v.length(), "{}", s1.x.dot(s1.v));
        // A start off the sphere by more than round-off is put on it by the first step.
        let mut off = State { x: b.x * (1.0 + 1e-9), v: b.v };
        Rkmk4::default().step(&model, 0.0, &mut off, 1e-2).unwrap();
        assert!((off.x.length() - 1.3).abs() < 4.0 * f64::EPSILON, "{}", off.x.length());
    }
}
