//! Reduction by the S¹ symmetry about the vertical (docs/theory.md §3), in Holm's unit-length setting:
//! positions in units of l, so σ₁ = z/l, σ₂ = ż/l [1/s], σ₃ = |v|²/l² [1/s²], σ₄ = (x² + y²)/l²,
//! σ₅ = (x ẋ + y ẏ)/l² [1/s], σ₆ = (x ẏ − y ẋ)/l² = J₃/(m l²) [1/s], and γ = g/l [1/s²] in place of g.
//!
//! - T-3.1 invariants σ₁ … σ₆; T-3.2 relations (as residuals, zero on TS²):
//!   σ₅² + σ₆² − σ₄(σ₃ − σ₂²), σ₄ + σ₁² − 1, σ₅ + σ₁σ₂, σ₂² + σ₆² − σ₃(1 − σ₁²).
//! - T-3.3 Casimir C = σ₃(1 − σ₁²) − σ₂² − σ₆² (zero on the orbit manifold), H = ½σ₃ + γσ₁.
//! - T-3.4 reduced flow σ̇ = ∇H × ∇C on (σ₁, σ₂, σ₃):
//!   σ̇₁ = σ₂, σ̇₂ = −γ(1 − σ₁²) − σ₁σ₃, σ̇₃ = −2γσ₂ (Holm's printed (H1.19)–(H1.21) has the opposite
//!   sign; the test `reduced_flow_is_the_derivative_along_the_full_flow` pins it down), and the
//!   Nambu bracket {F, H} = ∇C · (∇F × ∇H).
//! - T-3.5 the oscillator σ̈₁ = 3γσ₁² − 2Hσ₁ − γ with σ̇₁² = 2(H − γσ₁)(1 − σ₁²) − σ₆².
//! - T-3.6 reconstruction φ̇ = σ₆/(1 − σ₁²): [`reduced_flow`] integrates (σ₁, σ₂, σ₃, φ) with RK4 — a
//!   path to x(t) independent of both the Cartesian integrators and the elliptic solution (singular
//!   at the poles like the angle form: it refuses J₃ = 0, and stops with an error where φ̇·dt would
//!   exceed 0.05 rad).

use crate::error::{Error, Result};
use crate::state::State;
use glam::DVec3;

/// The six S¹-invariants (T-3.1), in units of l (see the module doc).
pub fn invariants(length: f64, s: &State) -> [f64; 6] {
    let (x, v) = (s.x / length, s.v / length);
    [x.z, v.z, v.length_squared(), x.x * x.x + x.y * x.y, x.x * v.x + x.y * v.y, x.x * v.y - x.y * v.x]
}

/// Residuals of the relations T-3.2 (H1.12, H1.14 twice, H1.15); all zero on TS².
pub fn relation_residuals(s: &[f64; 6]) -> [f64; 4] {
    let [s1, s2, s3, s4, s5, s6] = *s;
    [
        s5 * s5 + s6 * s6 - s4 * (s3 - s2 * s2),
        s4 + s1 * s1 - 1.0,
        s5 + s1 * s2,
        s2 * s2 + s6 * s6 - s3 * (1.0 - s1 * s1),
    ]
}

/// The Casimir C(σ₁, σ₂, σ₃) = σ₃(1 − σ₁²) − σ₂² − J² (T-3.3), J = σ₆.
pub fn casimir(s: [f64; 3], j: f64) -> f64 {
    s[2] * (1.0 - s[0] * s[0]) - s[1] * s[1] - j * j
}

/// The reduced Hamiltonian H = ½σ₃ + γσ₁ (T-3.3) [1/s²], γ = g/l.
pub fn hamiltonian(s: [f64; 3], gamma: f64) -> f64 {
    0.5 * s[2] + gamma * s[0]
}

/// ∇H and ∇C at σ.
pub fn gradients(s: [f64; 3], gamma: f64) -> (DVec3, DVec3) {
    (DVec3::new(gamma, 0.0, 0.5), DVec3::new(-2.0 * s[0] * s[2], -2.0 * s[1], 1.0 - s[0] * s[0]))
}

/// The reduced vector field σ̇ = ∇H × ∇C (T-3.4).
pub fn reduced_vector_field(s: [f64; 3], gamma: f64) -> [f64; 3] {
    let (dh, dc) = gradients(s, gamma);
    dh.cross(dc).to_array()
}

/// The Nambu bracket {F, H} = ∇C · (∇F × ∇H) for a function with gradient `grad_f` at σ.
pub fn nambu_bracket(grad_f: DVec3, s: [f64; 3], gamma: f64) -> f64 {
    let (dh, dc) = gradients(s, gamma);
    dc.dot(grad_f.cross(dh))
}

/// σ̈₁ of the oscillator T-3.5 on the plane H = `h`.
pub fn oscillator_acceleration(s1: f64, h: f64, gamma: f64) -> f64 {
    3.0 * gamma * s1 * s1 - 2.0 * h * s1 - gamma
}

/// σ̇₁² = 2(H − γσ₁)(1 − σ₁²) − J² (T-3.5).
pub fn oscillator_velocity_squared(s1: f64, h: f64, j: f64, gamma: f64) -> f64 {
    2.0 * (h - gamma * s1) * (1.0 - s1 * s1) - j * j
}

/// Largest azimuth increment per step \[rad\] before [`reduced_flow`] refuses (accuracy near a pole).
pub const MAX_AZIMUTH_STEP: f64 = 0.05;

/// (σ̇₁, σ̇₂, σ̇₃, φ̇) of the reduced flow with reconstruction.
fn rhs(y: [f64; 4], gamma: f64, j: f64) -> [f64; 4] {
    let [a, b, c] = reduced_vector_field([y[0], y[1], y[2]], gamma);
    [a, b, c, j / (1.0 - y[0] * y[0])]
}

/// Integrates the reduced flow T-3.4 with the reconstruction T-3.6 from `start` over `n` RK4 steps
/// of `dt` \[s\] and returns the states at every step (n + 1 of them, t = 0, dt, …), rebuilt as
/// x = l(√(1 − σ₁²) cos φ, √(1 − σ₁²) sin φ, σ₁) and v from σ₂, σ₆ and the sign of the radial motion.
pub fn reduced_flow(length: f64, g: f64, start: &State, dt: f64, n: usize) -> Result<Vec<State>> {
    if !(dt.is_finite() && dt > 0.0) {
        return Err(Error::InvalidParameter { name: "dt", value: dt, allowed: "a finite step > 0 s" });
    }
    let sig = invariants(length, start);
    let (gamma, j) = (g / length, sig[5]);
    if j == 0.0 {
        // Planar: the orbit runs through a pole, where φ jumps by π; the reconstruction cannot follow.
        return Err(Error::ReducedFlowPole { t: 0.0, sigma1: sig[0] });
    }
    let mut y = [sig[0], sig[1], sig[2], start.x.y.atan2(start.x.x)];
    let mut out = Vec::with_capacity(n + 1);
    out.push(*start);
    for k in 0..n {
        let k1 = rhs(y, gamma, j);
        let step = |y: [f64; 4], k: [f64; 4], h: f64| std::array::from_fn::<f64, 4, _>(|i| y[i] + h * k[i]);
        let k2 = rhs(step(y, k1, 0.5 * dt), gamma, j);
        let k3 = rhs(step(y, k2, 0.5 * dt), gamma, j);
        let k4 = rhs(step(y, k3, dt), gamma, j);
        for i in 0..4 {
            y[i] += dt / 6.0 * (k1[i] + 2.0 * (k2[i] + k3[i]) + k4[i]);
        }
        // Near a pole φ̇ = J/(1 − σ₁²) outruns any fixed step: stop before the result is garbage.
        let rho2 = 1.0 - y[0] * y[0];
        let fine = rho2 > 0.0 && j.abs() / rho2 * dt < MAX_AZIMUTH_STEP && y.iter().all(|v| v.is_finite());
        if !fine {
            return Err(Error::ReducedFlowPole { t: (k + 1) as f64 * dt, sigma1: y[0] });
        }
        out.push(rebuild(length, y, j));
    }
    Ok(out)
}

/// x and v from (σ₁, σ₂, σ₃, φ) and J: ρ = √(1 − σ₁²), ρ̇ = −σ₁σ₂/ρ, ρφ̇ = J/ρ.
fn rebuild(length: f64, y: [f64; 4], j: f64) -> State {
    let [s1, s2, _s3, phi] = y;
    let rho = (1.0 - s1 * s1).sqrt();
    let (sp, cp) = phi.sin_cos();
    let (rho_dot, w) = (-s1 * s2 / rho, j / rho);
    State {
        x: DVec3::new(rho * cp, rho * sp, s1) * length,
        v: DVec3::new(rho_dot * cp - w * sp, rho_dot * sp + w * cp, s2) * length,
    }
}
