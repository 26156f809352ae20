//! Forward sensitivities of the real pendulum on a rod (docs/theory.md T-10.7): the motion x(t) \[m\],
//! v(t) [m/s] from the start at t = 0 together with its exact derivatives with respect to the start
//! angles θ₀, φ₀ \[rad\], their rates θ̇₀, φ̇₀ [rad/s] and the parameters l \[m\], g [m/s²], c [1/s],
//! c_q [1/m] and ε_f [rad/s²] ([`PARAMS`]), for the Jacobian of a fit (`pl.fit`, docs/fit.md).
//!
//! The equations are T-2.4, ẋ = v, v̇ = a = f + λ x with λ = −(|v|² + x·f)/l², for the applied
//! acceleration f of [`Extended`] (T-7.1, T-7.3, T-7.6). Their variational equations for
//! S = (∂x/∂p, ∂v/∂p) are
//!
//! Ẋ = V,  V̇ = (F_x + λ I + x ⊗ ∇ₓλ) X + (F_v + x ⊗ ∇ᵥλ) V + (∂f/∂p + x ∂λ/∂p),
//!
//! with ∇ₓλ = −(f + F_xᵀx)/l², ∇ᵥλ = −(2v + F_vᵀx)/l², ∂λ/∂p = −x·∂f/∂p/l² (+ 2(|v|² + x·f)/l³ for
//! p = l), F_x = |Ω|²I − ΩΩᵀ (centrifugal), and F_v = −cI − c_q(sI + v̂vᵀ) − ε_f l(ψI + ψ′ v̂vᵀ) −
//! 2\[Ω\]ₓ where s = |v|, v̂ = v/s, ψ(s) = tanh(s/s_ε)/s, s_ε = l ω_ε. S starts at the derivatives of the
//! start state T-1.1. State and sensitivities are integrated together by the DOP853 tableau with the
//! error controlled on the state (as the plain method does; the variational equations are the
//! linearisation of the same flow and need no smaller steps), every save time a step end, and the
//! state projected onto TS² after each step (T-8.5).

use crate::error::{Error, Result};
use crate::integrate::dop853_tableau::{A, B, C, E3, E5, STAGES};
use crate::model::{Extended, Model};
use crate::state::project_onto_tangent_bundle;
use glam::{DMat3, DVec3};

/// The quantities the sensitivities are taken with respect to, in this order.
pub const PARAMS: [&str; 9] =
    ["theta0", "phi0", "theta_dot0", "phi_dot0", "length", "g", "damping", "drag", "friction"];
const K: usize = PARAMS.len();
const N: usize = 6 + 6 * K;
const LENGTH: usize = 4;

/// The motion at the save times and its derivatives: `dx[i][k]` = ∂x(tᵢ)/∂pₖ, `dv[i][k]` = ∂v(tᵢ)/∂pₖ
/// (units of x or v over those of pₖ, [`PARAMS`]).
#[derive(Debug, Clone, Default)]
pub struct Sensitivities {
    /// Positions \[m\].
    pub x: Vec<DVec3>,
    /// Velocities [m/s].
    pub v: Vec<DVec3>,
    /// ∂x/∂pₖ per save time.
    pub dx: Vec<[DVec3; K]>,
    /// ∂v/∂pₖ per save time.
    pub dv: Vec<[DVec3; K]>,
    /// Accepted steps.
    pub steps: usize,
}

fn outer(a: DVec3, b: DVec3) -> DMat3 {
    DMat3::from_cols(a * b.x, a * b.y, a * b.z)
}

fn skew(w: DVec3) -> DMat3 {
    // the matrix of u ↦ w × u
    DMat3::from_cols(DVec3::new(0.0, w.z, -w.y), DVec3::new(-w.z, 0.0, w.x), DVec3::new(w.y, -w.x, 0.0))
}

/// ψ(s) = tanh(u)/s and ψ′(s)/s = (u sech²u − tanh u)/s³ for u = s/s_ε (series below u = 10⁻²).
fn friction_psi(s: f64, s_eps: f64) -> (f64, f64) {
    let u = s / s_eps;
    if u < 1e-2 {
        let u2 = u * u;
        let inv3 = 1.0 / (s_eps * s_eps * s_eps);
        ((1.0 - u2 / 3.0) / s_eps, (-2.0 / 3.0 + 8.0 * u2 / 15.0) * inv3)
    } else {
        let sech2 = 1.0 / (u.cosh() * u.cosh());
        (u.tanh() / s, (u * sech2 - u.tanh()) / (s * s * s))
    }
}

/// ∂/∂l of the friction acceleration −ε_f l tanh(s/(l ω_ε)) v/s: −ε_f (tanh u − u sech²u) v/s.
fn friction_dl(eps: f64, s: f64, s_eps: f64, v: DVec3) -> DVec3 {
    let u = s / s_eps;
    let g = if u < 1e-2 {
        // (tanh u − u sech² u)/s = (2u³/3 − 8u⁵/15)/s
        let u2 = u * u;
        (2.0 / 3.0 - 8.0 * u2 / 15.0) * u2 / s_eps
    } else {
        (u.tanh() - u / (u.cosh() * u.cosh())) / s
    };
    -eps * g * v
}

/// The right-hand side of state + variational equations (module doc).
fn rhs(m: &Extended, t: f64, y: &[f64; N], out: &mut [f64; N]) {
    let x = DVec3::new(y[0], y[1], y[2]);
    let v = DVec3::new(y[3], y[4], y[5]);
    let p = m.params();
    let (l, inv_l2) = (p.length, 1.0 / (p.length * p.length));
    let f = m.applied_acceleration(t, x, v);
    let lam = -(v.length_squared() + x.dot(f)) * inv_l2;
    let a = f + x * lam;
    let (c, cq) = (m.damping(), m.drag());
    let (eps, w_eps) = m.friction();
    let omega = m.frame();
    let s = v.length();
    let s_eps = l * w_eps;
    let fx = DMat3::from_diagonal(DVec3::splat(omega.length_squared())) - outer(omega, omega);
    let mut fv = DMat3::from_diagonal(DVec3::splat(-c)) - skew(omega) * 2.0;
    let mut psi = 0.0;
    if cq != 0.0 && s > 0.0 {
        fv -= (DMat3::from_diagonal(DVec3::splat(s)) + outer(v / s, v)) * cq;
    }
    if eps != 0.0 {
        let (ps, dps) = friction_psi(s, s_eps);
        psi = ps;
        fv -= (DMat3::from_diagonal(DVec3::splat(ps)) + outer(v * dps, v)) * (eps * l);
    }
    let dlam_dx = -(f + fx.transpose() * x) * inv_l2;
    let dlam_dv = -(v * 2.0 + fv.transpose() * x) * inv_l2;
    let ax = fx + DMat3::from_diagonal(DVec3::splat(lam)) + outer(x, dlam_dx);
    let av = fv + outer(x, dlam_dv);
    let fp = |k: usize| -> DVec3 {
        match k {
            LENGTH if eps != 0.0 => friction_dl(eps, s, s_eps, v),
            5 => m.gravity_direction(),
            6 => -v,
            7 => -v * s,
            8 => -v * (l * psi_or(psi, eps, s, s_eps)),
            _ => DVec3::ZERO,
        }
    };
    out[0..3].copy_from_slice(&v.to_array());
    out[3..6].copy_from_slice(&a.to_array());
    for k in 0..K {
        let o = 6 + 6 * k;
        let xs = DVec3::new(y[o], y[o + 1], y[o + 2]);
        let vs = DVec3::new(y[o + 3], y[o + 4], y[o + 5]);
        let fpk = fp(k);
        let mut dlam = -x.dot(fpk) * inv_l2;
        if k == LENGTH {
            dlam += 2.0 * (v.length_squared() + x.dot(f)) * inv_l2 / l;
        }
        let acc = ax * xs + av * vs + fpk + x * dlam;
        out[o..o + 3].copy_from_slice(&vs.to_array());
        out[o + 3..o + 6].copy_from_slice(&acc.to_array());
    }
}

/// ψ(s) for the ∂f/∂ε_f column, also when ε_f = 0 (the friction is off but its derivative is not).
fn psi_or(psi: f64, eps: f64, s: f64, s_eps: f64) -> f64 {
    if eps != 0.0 {
        psi
    } else {
        friction_psi(s, s_eps).0
    }
}

/// The start state T-1.1 and its derivatives with respect to θ₀, φ₀, θ̇₀, φ̇₀ and l.
fn start(l: f64, [th, ph, thd, phd]: [f64; 4]) -> [f64; N] {
    let (st, ct) = th.sin_cos();
    let (sp, cp) = ph.sin_cos();
    let mut y = [0.0; N];
    let x = DVec3::new(st * cp, st * sp, -ct) * l;
    let v = DVec3::new(thd * ct * cp - phd * st * sp, thd * ct * sp + phd * st * cp, thd * st) * l;
    let cols: [(DVec3, DVec3); 5] = [
        (
            DVec3::new(ct * cp, ct * sp, st) * l,
            DVec3::new(-thd * st * cp - phd * ct * sp, -thd * st * sp + phd * ct * cp, thd * ct) * l,
        ),
        (
            DVec3::new(-st * sp, st * cp, 0.0) * l,
            DVec3::new(-thd * ct * sp - phd * st * cp, thd * ct * cp - phd * st * sp, 0.0) * l,
        ),
        (DVec3::ZERO, DVec3::new(ct * cp, ct * sp, st) * l),
        (DVec3::ZERO, DVec3::new(-st * sp, st * cp, 0.0) * l),
        (x / l, v / l),
    ];
    y[0..3].copy_from_slice(&x.to_array());
    y[3..6].copy_from_slice(&v.to_array());
    for (k, (dx, dv)) in cols.iter().enumerate() {
        y[6 + 6 * k..9 + 6 * k].copy_from_slice(&dx.to_array());
        y[9 + 6 * k..12 + 6 * k].copy_from_slice(&dv.to_array());
    }
    y
}

/// The largest number of steps a run may take before it is refused as stuck.
const MAX_STEPS: usize = 100_000_000;

/// Integrates the model from the start angles `angles` = (θ₀, φ₀ \[rad\], θ̇₀, φ̇₀ [rad/s]) at t = 0
/// through the save times `times` \[s\] (finite, non-decreasing, ≥ 0) at relative tolerance `rtol` and
/// absolute tolerance `atol` [m, m/s], returning the motion and its sensitivities (module doc).
pub fn sensitivities(
    model: &Extended,
    angles: [f64; 4],
    times: &[f64],
    rtol: f64,
    atol: f64,
) -> Result<Sensitivities> {
    check(angles, times, rtol, atol)?;
    let p = *model.params();
    let mut out = Sensitivities {
        x: Vec::with_capacity(times.len()),
        v: Vec::with_capacity(times.len()),
        dx: Vec::with_capacity(times.len()),
        dv: Vec::with_capacity(times.len()),
        steps: 0,
    };
    let mut y = start(p.length, angles);
    let mut t = 0.0;
    let period_scale = (p.length / p.g.abs().max(1e-300)).sqrt().min(1.0);
    let mut h = 1e-3 * period_scale.max(1e-6);
    let mut k = [[0.0; N]; STAGES];
    let mut tries = 0usize;
    for &target in times {
        while t < target {
            tries += 1;
            if tries > MAX_STEPS {
                return Err(Error::Diverged { t, method: "dop853 (sensitivities)", dt: h });
            }
            let clamped = target - t < h;
            let ht = if clamped { target - t } else { h };
            let (y1, err) = attempt(model, t, &y, ht, &mut k, (rtol, atol));
            if !err.is_finite() || y1.iter().any(|z| !z.is_finite()) {
                return Err(Error::Diverged { t, method: "dop853 (sensitivities)", dt: ht });
            }
            let root = err.powf(0.125);
            if err <= 1.0 {
                t = if clamped { target } else { t + ht };
                y = y1;
                let s = project_onto_tangent_bundle(
                    p.length,
                    DVec3::from_slice(&y[0..3]),
                    DVec3::from_slice(&y[3..6]),
                )
                .ok_or(Error::Diverged { t, method: "dop853 (sensitivities)", dt: ht })?;
                y[0..3].copy_from_slice(&s.x.to_array());
                y[3..6].copy_from_slice(&s.v.to_array());
                out.steps += 1;
                let grown = ht / (root / 0.9).clamp(1.0 / 6.0, 1.0 / 0.333);
                h = if clamped { h.max(grown) } else { grown };
            } else {
                h = ht / (root / 0.9).min(1.0 / 0.333);
            }
        }
        out.x.push(DVec3::from_slice(&y[0..3]));
        out.v.push(DVec3::from_slice(&y[3..6]));
        let col = |o: usize| DVec3::from_slice(&y[o..o + 3]);
        out.dx.push(std::array::from_fn(|k| col(6 + 6 * k)));
        out.dv.push(std::array::from_fn(|k| col(9 + 6 * k)));
    }
    Ok(out)
}

/// The arguments of [`sensitivities`] checked: tolerances finite and > 0, finite start angles and
/// rates, save times finite, ≥ 0 and non-decreasing \[s\].
fn check(angles: [f64; 4], times: &[f64], rtol: f64, atol: f64) -> Result<()> {
    for (name, value, ok) in
        [("rtol", rtol, rtol.is_finite() && rtol > 0.0), ("atol", atol, atol.is_finite() && atol > 0.0)]
    {
        if !ok {
            return Err(Error::InvalidParameter { name, value, allowed: "a finite tolerance > 0" });
        }
    }
    for w in angles {
        crate::error::require_finite("start angle or rate", w, "finite angles [rad] and rates [rad/s]")?;
    }
    if let Some((i, &t)) =
        times.iter().enumerate().find(|&(i, &t)| !t.is_finite() || t < 0.0 || (i > 0 && t < times[i - 1]))
    {
        return Err(Error::InvalidParameter {
            name: "save times",
            value: t,
            allowed: if i == 0 || !t.is_finite() || t < 0.0 {
                "finite times >= 0 s"
            } else {
                "non-decreasing times in s"
            },
        });
    }
    Ok(())
}

/// One DOP853 attempt of step `ht` \[s\] from (t, y) on all 60 equations: the 12 stages into `k`,
/// y₁ = y + ht Σ bᵢ kᵢ and the blended error estimate of the motion's six components (T-8.5), with
/// weights atol + rtol·max(|y|, |y₁|) from `tol` = (rtol, atol).
#[inline(always)]
fn attempt(
    model: &Extended,
    t: f64,
    y: &[f64; N],
    ht: f64,
    k: &mut [[f64; N]; STAGES],
    tol: (f64, f64),
) -> ([f64; N], f64) {
    let (rtol, atol) = tol;
    rhs(model, t, y, &mut k[0]);
    for i in 1..STAGES {
        // y + h Σ_j A[i][j] k_j, one stage at a time over all components (A has many zeros)
        let mut yi = *y;
        for (j, kj) in k.iter().enumerate().take(i) {
            let c = ht * A[i][j];
            if c != 0.0 {
                for (z, kz) in yi.iter_mut().zip(kj) {
                    *z += c * kz;
                }
            }
        }
        rhs(model, t + C[i] * ht, &yi, &mut k[i]);
    }
    let (mut incr, mut e5, mut e3) = ([0.0; N], [0.0; 6], [0.0; 6]);
    for (i, ki) in k.iter().enumerate() {
        if B[i] != 0.0 {
            for (z, kz) in incr.iter_mut().zip(ki) {
                *z += B[i] * kz;
            }
        }
        for n in 0..6 {
            e5[n] += E5[i] * ki[n];
            e3[n] += E3[i] * ki[n];
        }
    }
    let (mut n5, mut n3) = (0.0, 0.0);
    let mut y1 = [0.0; N];
    for n in 0..N {
        y1[n] = y[n] + ht * incr[n];
    }
    for n in 0..6 {
        let sk = atol + rtol * y[n].abs().max(y1[n].abs());
        n5 += (e5[n] / sk) * (e5[n] / sk);
        n3 += (e3[n] / sk) * (e3[n] / sk);
    }
    let err = if n5 == 0.0 && n3 == 0.0 { 0.0 } else { ht * n5 / (6.0 * (n5 + 0.01 * n3)).sqrt() };
    (y1, err)
}
