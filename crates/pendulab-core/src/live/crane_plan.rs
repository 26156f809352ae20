//! The lab crane's commanded motions (docs/cranes.md "The lab's crane mode", docs/theory.md T-11.1 –
//! T-11.3): acceleration-limited plans of the trolley and the hoist, and the trolley's command shaped
//! by a ZV or ZVD shaper designed for the rope length when each acceleration change happens.
//!
//! A motion q(t) ∈ R³ (the trolley's position \[m\]; the rope length \[m\] in the first component) is
//! piecewise quadratic: its acceleration is piecewise constant and changes by Δa_k at times τ_k
//! ([`Kinematics`]). The operator's commands give a *reference* motion (unshaped): to a velocity
//! (|a| = a_max until it is reached) or by a distance (the time-optimal trapezoid or triangle of
//! velocity under v_max, a_max from the current velocity, stopping first when it overshoots; T-11.3).
//! The trolley follows the reference convolved with the shaper (T-11.2): each change Δa of the
//! reference at τ becomes the changes A_i Δa at τ + t_i, so the trolley's acceleration stays within
//! a_max (Σ A_i = 1, A_i > 0) and it ends where the reference ends. A change of the shaper (shaping
//! on/off, a new rope length) applies to the reference's later changes only: the motion stays C¹.
//!
//! For a pendulum of angular frequency ω = √(g/l) starting at rest, the residual sway angle after a
//! motion with acceleration changes Δa_k at τ_k (Σ Δa_k = 0) is, linearised (T-11.1 with ζ = 0),
//!
//!   θ_res = |Σ_k Δa_k e^{iωτ_k}| / g        \[rad\]           ([`residual_sway`]),
//!
//! the shaped one the unshaped one times |Σ A_i e^{iωt_i}|. Units: SI (m, s, m/s, m/s², rad/s).

use crate::DVec3;

/// Acceleration changes closer in time than this \[s\] are merged.
const SAME_TIME: f64 = 1e-12;

/// A piecewise-quadratic motion: state (q, q̇, q̈) at time `t` \[s\] and the future changes of q̈.
#[derive(Debug, Clone, PartialEq)]
pub struct Kinematics {
    /// Time \[s\] of the state.
    pub t: f64,
    /// Position q.
    pub q: DVec3,
    /// Rate q̇.
    pub dq: DVec3,
    /// Acceleration q̈ (constant until the next change).
    pub ddq: DVec3,
    /// Future acceleration changes (τ \[s\], Δq̈), in time order.
    pub steps: Vec<(f64, DVec3)>,
}

impl Kinematics {
    /// At rest at `q` at time `t` \[s\].
    pub fn at_rest(t: f64, q: DVec3) -> Self {
        Kinematics { t, q, dq: DVec3::ZERO, ddq: DVec3::ZERO, steps: Vec::new() }
    }

    /// (q, q̇) at `t` ≥ self.t with the current acceleration held (no change on the way).
    fn drift(&self, t: f64) -> (DVec3, DVec3) {
        let h = t - self.t;
        (self.q + self.dq * h + self.ddq * (0.5 * h * h), self.dq + self.ddq * h)
    }

    /// Adds the change `da` at `tau` \[s\] (merged with one at the same time).
    pub fn add_step(&mut self, tau: f64, da: DVec3) {
        let tau = tau.max(self.t);
        if let Some(s) = self.steps.iter_mut().find(|s| (s.0 - tau).abs() <= SAME_TIME) {
            s.1 += da;
            return;
        }
        let at = self.steps.partition_point(|s| s.0 < tau);
        self.steps.insert(at, (tau, da));
    }

    /// Advances to `t` \[s\] (≥ self.t), applying the changes up to and including `t`.
    pub fn advance_to(&mut self, t: f64) {
        while let Some(&(tau, da)) = self.steps.first().filter(|s| s.0 <= t) {
            (self.q, self.dq) = self.drift(tau);
            self.t = tau;
            self.ddq += da;
            self.steps.remove(0);
        }
        if t > self.t {
            (self.q, self.dq) = self.drift(t);
            self.t = t;
        }
    }

    /// The motion on [self.t, t1] as (time, q, q̇, q̈ left, q̈ right) at self.t, at each change before
    /// t1 and at t1: a quintic Hermite through them is the motion exactly (T-11.4).
    pub fn samples(&self, t1: f64) -> Vec<(f64, DVec3, DVec3, DVec3, DVec3)> {
        let mut k = self.clone();
        let mut out = vec![(k.t, k.q, k.dq, k.ddq, k.ddq)];
        while let Some(&(tau, da)) = k.steps.first().filter(|s| s.0 < t1) {
            (k.q, k.dq) = k.drift(tau);
            k.t = tau;
            let left = k.ddq;
            k.ddq += da;
            k.steps.remove(0);
            if tau > out[out.len() - 1].0 {
                out.push((tau, k.q, k.dq, left, k.ddq));
            } else {
                let last = out.len() - 1;
                out[last].4 = k.ddq;
            }
        }
        if t1 > k.t {
            let (q, dq) = k.drift(t1);
            out.push((t1, q, dq, k.ddq, k.ddq));
        }
        out
    }

    /// True when at rest with no change to come.
    pub fn resting(&self) -> bool {
        self.steps.is_empty() && self.dq == DVec3::ZERO && self.ddq == DVec3::ZERO
    }

    /// Replaces the future changes with a plan of accelerations per axis: `plans[i]` lists (τ \[s\],
    /// q̈_i from τ on) for axis i (an empty list keeps that axis's acceleration).
    pub fn replan(&mut self, plans: [Vec<(f64, f64)>; 3]) {
        self.steps.clear();
        let mut times: Vec<f64> = plans.iter().flatten().map(|p| p.0).collect();
        times.sort_by(f64::total_cmp);
        times.dedup_by(|a, b| (*a - *b).abs() <= SAME_TIME);
        let mut a = self.ddq;
        for tau in times {
            let mut next = a;
            for (i, plan) in plans.iter().enumerate() {
                if let Some(&(_, ai)) = plan.iter().rev().find(|p| p.0 <= tau + SAME_TIME) {
                    next[i] = ai;
                }
            }
            if next != a {
                self.add_step(tau, next - a);
                a = next;
            }
        }
    }
}

/// Plan of one axis from velocity `v0` to velocity `v1` with |q̈| = `a_max`: (τ, q̈) pairs from `t`.
pub fn plan_velocity(t: f64, v0: f64, v1: f64, a_max: f64) -> Vec<(f64, f64)> {
    let dv = v1 - v0;
    if dv.abs() < 1e-12 {
        return vec![(t, 0.0)];
    }
    vec![(t, a_max.copysign(dv)), (t + dv.abs() / a_max, 0.0)]
}

/// Plan of one axis from (q0, v0) to rest at `q1` under |q̇| ≤ v_max, |q̈| ≤ a_max (T-11.3): stop
/// first if the target cannot be reached without overshooting, then accelerate to the peak speed
/// (v_max or less: a triangle), cruise, and decelerate to rest at q1.
pub fn plan_position(t: f64, q0: f64, v0: f64, q1: f64, v_max: f64, a_max: f64) -> Vec<(f64, f64)> {
    let mut plan = Vec::new();
    let (mut t, mut q, mut w0) = (t, q0, v0);
    let d = q1 - q;
    let overshoot = w0 * d < 0.0 || w0 * w0 / (2.0 * a_max) > d.abs() + 1e-12;
    if w0 != 0.0 && overshoot {
        plan.push((t, -a_max.copysign(w0)));
        q += w0 * w0.abs() / (2.0 * a_max);
        t += w0.abs() / a_max;
        w0 = 0.0;
    }
    let d = q1 - q;
    if d.abs() < 1e-12 && w0 == 0.0 {
        plan.push((t, 0.0));
        return plan;
    }
    let s = d.signum();
    let (dist, w0) = (d.abs(), s * w0); // forward speed w0 ≥ 0 (no overshoot left)
    let peak = v_max.min((a_max * dist + 0.5 * w0 * w0).sqrt());
    let t1 = (peak - w0).abs() / a_max;
    let d1 = (peak * peak - w0 * w0).abs() / (2.0 * a_max);
    let t3 = peak / a_max;
    let d3 = peak * peak / (2.0 * a_max);
    let cruise = ((dist - d1 - d3).max(0.0)) / peak;
    plan.push((t, if peak >= w0 { s * a_max } else { -s * a_max }));
    plan.push((t + t1, 0.0));
    plan.push((t + t1 + cruise, -s * a_max));
    plan.push((t + t1 + cruise + t3, 0.0));
    plan
}

/// The lab's shapers (T-11.2, undamped): none, ZV or ZVD, by the `shaping` parameter 0, 1, 2.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Shaping {
    /// No shaping: one impulse of 1 at 0.
    Off,
    /// Zero vibration: ½, ½ at 0, T/2.
    Zv,
    /// Zero vibration and derivative: ¼, ½, ¼ at 0, T/2, T.
    Zvd,
}

impl Shaping {
    /// From the `shaping` parameter (0 off, 1 ZV, 2 ZVD; rounded).
    pub fn from_code(code: f64) -> Shaping {
        match code.round() as i64 {
            1 => Shaping::Zv,
            2 => Shaping::Zvd,
            _ => Shaping::Off,
        }
    }

    /// The status's name.
    pub fn name(self) -> &'static str {
        match self {
            Shaping::Off => "off",
            Shaping::Zv => "zv",
            Shaping::Zvd => "zvd",
        }
    }

    /// Impulses (t_i \[s\], A_i) designed for the angular frequency ω [rad/s] (T-11.2, ζ = 0).
    pub fn impulses(self, omega: f64) -> Vec<(f64, f64)> {
        let half = std::f64::consts::PI / omega;
        match self {
            Shaping::Off => vec![(0.0, 1.0)],
            Shaping::Zv => vec![(0.0, 0.5), (half, 0.5)],
            Shaping::Zvd => vec![(0.0, 0.25), (half, 0.5), (2.0 * half, 0.25)],
        }
    }
}

/// The linear residual sway angle \[rad\] (module doc) of acceleration changes `steps` (τ \[s\], Δa
/// [m/s²]) for a pendulum of angular frequency ω [rad/s] in gravity g [m/s²], starting at rest:
/// |Σ Δa_k e^{iωτ_k}| / g over both horizontal axes.
pub fn residual_sway(steps: &[(f64, DVec3)], omega: f64, g: f64) -> f64 {
    let (mut re, mut im) = (DVec3::ZERO, DVec3::ZERO);
    for &(tau, da) in steps {
        let (s, c) = (omega * tau).sin_cos();
        re += da * c;
        im += da * s;
    }
    (re.x * re.x + re.y * re.y + im.x * im.x + im.y * im.y).sqrt() / g
}

/// The changes `steps` convolved with the shaper `impulses` (each Δa at τ becomes A_i Δa at τ + t_i).
pub fn shaped(steps: &[(f64, DVec3)], impulses: &[(f64, f64)]) -> Vec<(f64, DVec3)> {
    steps.iter().flat_map(|&(tau, da)| impulses.iter().map(move |&(ti, ai)| (tau + ti, da * ai))).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn run(plan: Vec<(f64, f64)>, q0: f64, v0: f64) -> Kinematics {
        let mut k = Kinematics::at_rest(0.0, DVec3::new(q0, 0.0, 0.0));
        k.dq.x = v0;
        k.replan([plan, Vec::new(), Vec::new()]);
        k
    }

    #[test]
    fn a_position_plan_ends_at_rest_on_the_target_within_the_limits() {
        // trapezoid, triangle, a moving start towards and away from the target, an overshoot
        for (q0, v0, q1) in
            [(0.0, 0.0, 5.0), (0.0, 0.0, 0.1), (1.0, 0.3, 4.0), (1.0, -0.4, 4.0), (0.0, 0.5, 0.2)]
        {
            let (v_max, a_max) = (0.5, 0.3);
            let mut k = run(plan_position(0.0, q0, v0, q1, v_max, a_max), q0, v0);
            let mut t = 0.0;
            while t < 60.0 {
                t += 0.01;
                k.advance_to(t);
                assert!(k.dq.x.abs() <= v_max.max(v0.abs()) + 1e-12 && k.ddq.x.abs() <= a_max + 1e-12);
            }
            assert!((k.q.x - q1).abs() < 1e-9, "{q0} {v0} {q1}: {}", k.q.x);
            assert!(k.dq.x.abs() < 1e-12 && k.ddq.x == 0.0 && k.steps.is_empty());
        }
    }

    #[test]
    fn a_trapezoid_takes_the_time_optimal_duration() {
        // 5 m at 0.5 m/s, 0.25 m/s²: 2 s accelerating, 8 s cruising, 2 s braking
        let plan = plan_position(1.0, 0.0, 0.0, 5.0, 0.5, 0.25);
        let times: Vec<f64> = plan.iter().map(|p| p.0).collect();
        assert_eq!(times, vec![1.0, 3.0, 11.0, 13.0]);
    }

    #[test]
    fn samples_reproduce_the_motion_with_the_jumps_of_acceleration() {
        let k = run(plan_position(0.0, 0.0, 0.0, 2.0, 1.0, 0.5), 0.0, 0.0);
        let s = k.samples(10.0);
        assert_eq!(s.len(), 4, "start, two changes (triangle), end: {s:?}");
        let mut m = k.clone();
        for &(t, q, dq, _, right) in &s {
            m.advance_to(t);
            assert!((m.q - q).length() < 1e-14 && (m.dq - dq).length() < 1e-14 && m.ddq == right);
        }
    }

    /// The residual of a trapezoid is (4a/g)|sin(ωT₁/2) sin(ωT₂/2)| (T₁ the ramp, T₂ = T₁ + cruise);
    /// ZV and ZVD designed for ω leave none.
    #[test]
    fn residual_sway_of_a_trapezoid_and_of_its_shaped_versions() {
        let (g, l, a): (f64, f64, f64) = (9.81, 10.0, 0.25);
        let omega = (g / l).sqrt();
        let plan = plan_position(0.0, 0.0, 0.0, 5.0, 0.5, a);
        let k = run(plan, 0.0, 0.0);
        let (t1, t2) = (2.0, 10.0);
        let want = 4.0 * a / g * ((omega * t1 / 2.0).sin() * (omega * t2 / 2.0).sin()).abs();
        assert!((residual_sway(&k.steps, omega, g) - want).abs() < 1e-15);
        for s in [Shaping::Zv, Shaping::Zvd] {
            let r = residual_sway(&shaped(&k.steps, &s.impulses(omega)), omega, g);
            assert!(r < 1e-15, "{s:?}: {r}");
        }
    }
}
