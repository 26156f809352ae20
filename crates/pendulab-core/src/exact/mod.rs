//! The exact solution of the ideal spherical pendulum (docs/theory.md §4) from any state on TS², for any
//! g: positions and velocities at any time t \[s\] (negative too) at a cost independent of t, the
//! turning heights, the parameter m, the z-period and the azimuthal advance per z-period.
//!
//! Cases (T-4.6), chosen from the start:
//! - `GreatCircle`, g = 0 (or gravity negligible, [`GRAVITY_NEGLIGIBLE`]): x = x₀ cos ωt + (v₀/ω) sin ωt,
//!   ω = |v₀|/l.
//! - `Rest`: v₀ = 0 at a pole (or anywhere when g = 0); the bottom is stable, the top unstable but
//!   an equilibrium all the same.
//! - `Planar` (J₃ = 0), `PlanarRotating` (over the top), `Separatrix` (ε = 1): see [`planar`].
//! - `Generic` (J₃ ≠ 0) and `Conical` (u₂ − u₁ at round-off): see [`generic`] and [`cubic`].
//! - g < 0: the mirror image z → −z of the solution with gravity |g| (the equations map onto each
//!   other; J₃ and φ are unchanged).
//!
//! Scalings (§1): ω₀ = √(|g|/l), τ = ω₀t, u = z/l, ε = E/(m|g|l) in the mirrored frame,
//! j = J₃/(m l² ω₀).

pub mod cubic;
pub mod energy_momentum;
pub mod generic;
pub mod phases;
pub mod planar;
pub mod weierstrass;

use crate::error::{Error, Result};
use crate::state::{Params, State};
use cubic::StartData;
use generic::{Generic, UnitState};
use glam::DVec3;
use planar::{Planar, PlanarMotion};
use weierstrass::Weierstrass;

/// The argument s = F(ϕ | m) of the amplitude ϕ with sin ϕ = `sn`, cos ϕ = `cn` ≥ 0 (|ϕ| ≤ π/2);
/// `k` = K(m). Past |ϕ| = π/4 it is K − F(ψ | m) with tan ψ = cot ϕ / k′ (DLMF 19.7.8's complement,
/// cot ϕ cot ψ = k′), because near m = 1 F climbs steeply to K at π/2: ∂F/∂ϕ = 1/√(1 − m sin²ϕ)
/// reaches 1/k′, and the 6e-17 by which fl(π/2) misses π/2 would cost a turning point 6e-17/k′ of
/// its argument (1.2e-10 for a start at rest 1e-6 rad from the top). Both amplitudes enter as their
/// sine and cosine (sin ψ = cn/r, cos ψ = k′|sn|/r, r = √(cn² + m′sn²)), never as an angle: fl(ψ)
/// next to π/2 cost a start near the separatrix (m′ = 5e-16) 6e-9 of its argument.
pub(crate) fn amplitude_argument(sn: f64, cn: f64, param: crate::elliptic::Param, k: f64) -> Result<f64> {
    // m = 1 (the separatrix): K = ∞ and F(ϕ|1) = artanh(sin ϕ) straight from sn and cn (K − F(ψ)
    // would be ∞ − ∞, a NaN for every start above the equator).
    if cn >= sn.abs() || param.m1 == 0.0 {
        return crate::elliptic::ellipf_sc(sn, cn, param);
    }
    let kp = param.m1.sqrt();
    let r = cn.hypot(kp * sn);
    if r == 0.0 {
        return Ok(k.copysign(sn));
    }
    Ok((k - crate::elliptic::ellipf_sc(cn / r, kp * sn.abs() / r, param)?).copysign(sn))
}

/// Kind of motion, as named in docs/theory.md T-4.6.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Kind {
    /// J₃ ≠ 0: the bob moves between two heights while the azimuth advances.
    Generic,
    /// J₃ ≠ 0 at constant height (u₂ − u₁ at round-off).
    Conical,
    /// J₃ = 0, swinging through the bottom.
    Planar,
    /// J₃ = 0, going over the top.
    PlanarRotating,
    /// J₃ = 0 at exactly the energy of the top: creeps towards it forever.
    Separatrix,
    /// At rest at an equilibrium (bottom or top), or at rest anywhere with g = 0.
    Rest,
    /// g = 0: uniform motion on a great circle.
    GreatCircle,
}

impl Kind {
    /// Lower-case name used in Python, files and the CLI.
    pub fn name(self) -> &'static str {
        match self {
            Kind::Generic => "generic",
            Kind::Conical => "conical",
            Kind::Planar => "planar",
            Kind::PlanarRotating => "planar_rotating",
            Kind::Separatrix => "separatrix",
            Kind::Rest => "rest",
            Kind::GreatCircle => "great_circle",
        }
    }
}

/// Times per batch of [`ExactSolution::states_at`] (one dispatched loop, one rayon task).
pub const BATCH: usize = 1024;

/// u₂ − u₁ below this counts as conical (the label only; the formulas are the same).
const CONICAL_WIDTH: f64 = 1e-12;

/// |j| below this (j = J₃/(m l² ω₀)) is solved as planar motion. The spherical orbit then differs
/// from the planar one by O(j/√(1 + ε)) ≤ 1e-132 l even for swings of 1e-8 rad, while its roots
/// would sit j²/(4(1 + ε)) ≈ 1e-280 from the poles, next to the end of the float range (at
/// j = 1e-160, j² underflows to 0 and 1 + u₁ with it).
pub const PLANAR_J: f64 = 1e-140;

/// κ = |v₀|²/(2|g|l) above this solves the motion as a great circle (g taken as 0): gravity then
/// changes the period by a relative O(1/κ) ≤ 1e-100, so the phase after the most revolutions a time
/// within the limits allows (t ≤ 1e12 s at |v₀|/l ≤ 1e9 1/s) is off by less than 1e-70 rad, while the
/// elliptic form's dimensionless velocity √(2κ) ≥ 1e50 would square its cubic's coefficients towards
/// the end of the float range (at |g| = 1e-200 m/s² and |v₀| = 1 m/s they overflowed: a "conical" orbit
/// with a z-period of 0 s).
pub const GRAVITY_NEGLIGIBLE: f64 = 1e100;

/// A start at rest whose distance from the vertical axis is at most this × |x| is at the pole
/// (the equilibrium): a few ulps, e.g. l·sin(fl(π)) = 1.2e-16 l for θ = fl(π).
pub const AXIS_ROUNDING: f64 = 4.0 * f64::EPSILON;

#[derive(Debug, Clone)]
enum Flow {
    Rest,
    GreatCircle { omega: f64 },
    Planar(Planar),
    Generic(Box<Generic>),
}

/// The exact solution through a state at t = 0.
#[derive(Debug, Clone)]
pub struct ExactSolution {
    params: Params,
    start: State,
    kind: Kind,
    /// +1, or −1 when g < 0 (solved in the mirrored frame).
    mirror: f64,
    /// ω₀ = √(|g|/l) [1/s] (0 when g = 0).
    omega0: f64,
    flow: Flow,
    /// The dimensionless start data of the cubic T-4.1 (planar and generic motions).
    cubic: Option<StartData>,
}

impl ExactSolution {
    /// The solution through `start` at t = 0. The state must be on TS² within [`TS2_TOLERANCE`](crate::state::TS2_TOLERANCE)
    /// (relative); use [`State::projected`] first otherwise. `TS2_TOLERANCE`: [`crate::state::TS2_TOLERANCE`].
    pub fn new(params: &Params, start: &State) -> Result<Self> {
        let s = State::on_tangent_bundle(params, start.x, start.v)?;
        let (l, g) = (params.length, params.g);
        let speed2 = s.v.length_squared();
        let rho2_abs = s.x.x * s.x.x + s.x.y * s.x.y;
        // At rest within rounding of the axis is the equilibrium: θ = fl(π) puts the bob
        // l·sin(fl(π)) = 1.2e-16 l off it, from where (at rest) the exact motion would fall off the
        // top after ~37/ω₀ — an artefact of rounding π, not the state meant.
        let at_pole = rho2_abs <= (AXIS_ROUNDING * s.x.length()).powi(2);
        let (mirror, omega0) = (if g < 0.0 { -1.0 } else { 1.0 }, (g.abs() / l).sqrt());
        let base = Self {
            params: *params,
            start: s,
            kind: Kind::Rest,
            mirror,
            omega0,
            flow: Flow::Rest,
            cubic: None,
        };
        if speed2 == 0.0 && (at_pole || g == 0.0) {
            return Ok(base);
        }
        // κ = speed2/(2|g|l) > GRAVITY_NEGLIGIBLE, written without dividing by a |g|l that may underflow
        if g == 0.0 || speed2 > 2.0 * GRAVITY_NEGLIGIBLE * (g.abs() * l) {
            let omega = speed2.sqrt() / l;
            return Ok(Self { kind: Kind::GreatCircle, flow: Flow::GreatCircle { omega }, ..base });
        }
        // Unit frame: x/|x|, v/(lω₀), z mirrored for g < 0. Dividing by |x| (not l) and removing the
        // radial part of v projects the start onto TS² exactly as the golden data do; p± = 1 ∓ u₀
        // are then formed from ρ² = x² + y² and |x| ± z without cancellation (near a pole p± ≈ 1e-4
        // would otherwise carry the start's own |x| − l, 1e-16, as a relative 1e-12).
        let r = s.x.length();
        let zm = mirror * s.x.z;
        let vt = s.v - s.x * (s.x.dot(s.v) / (r * r));
        let x = [s.x.x / r, s.x.y / r, zm / r];
        let lw = l * omega0;
        let v = [vt.x / lw, vt.y / lw, mirror * vt.z / lw];
        let kappa = 0.5 * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        let mut j = x[0] * v[1] - x[1] * v[0];
        // A J₃ within the rounding of x₁v₂ − x₂v₁ is zero: the start is planar to its own precision
        // (e.g. a start built from angles with φ̇ = 0).
        if j.abs() <= 4.0 * f64::EPSILON * ((x[0] * v[1]).abs() + (x[1] * v[0]).abs()) {
            j = 0.0;
        }
        // Below PLANAR_J the planar motion is the exact one to far below the float64 floor, while
        // the spherical formulas would need 1 + u₁ ≈ j²/(2(1 + ε)) below the smallest float.
        if j.abs() < PLANAR_J {
            j = 0.0;
        }
        let (p_minus, p_plus) = if zm < 0.0 {
            (rho2_abs / (r * (r - zm)), (r - zm) / r)
        } else {
            ((r + zm) / r, rho2_abs / (r * (r + zm)))
        };
        let start = StartData::from_parts(x[2], p_minus, p_plus, kappa, j, v[2]);
        if j == 0.0 {
            let p = Planar::new(x, v, kappa, start.p_minus, start.p_plus)?;
            let kind = match p.motion {
                PlanarMotion::Libration => Kind::Planar,
                PlanarMotion::Rotation => Kind::PlanarRotating,
                PlanarMotion::Separatrix => Kind::Separatrix,
            };
            return Ok(Self { kind, flow: Flow::Planar(p), cubic: Some(start), ..base });
        }
        let phi0 = x[1].atan2(x[0]);
        let gen = Generic::new(start, phi0)?;
        let kind = if gen.a < CONICAL_WIDTH { Kind::Conical } else { Kind::Generic };
        Ok(Self { kind, flow: Flow::Generic(Box::new(gen)), cubic: Some(start), ..base })
    }

    /// Like [`new`](Self::new) but returns an error naming non-finite parameters first.
    pub fn from_parts(length: f64, mass: f64, g: f64, x: DVec3, v: DVec3) -> Result<Self> {
        let p = Params::new(length, mass, g)?;
        Self::new(&p, &State { x, v })
    }

    /// Kind of motion.
    pub fn kind(&self) -> Kind {
        self.kind
    }

    /// Parameters.
    pub fn params(&self) -> &Params {
        &self.params
    }

    /// The start (t = 0).
    pub fn start(&self) -> &State {
        &self.start
    }

    /// The state at time `t` \[s\] (any finite t, negative too).
    pub fn state(&self, t: f64) -> Result<State> {
        if !t.is_finite() {
            return Err(Error::InvalidParameter { name: "t", value: t, allowed: "a finite time in s" });
        }
        Ok(self.state_and_azimuth(t)?.0)
    }

    /// The state at `t` \[s\] and the continuous azimuth φ(t) \[rad\].
    pub fn state_and_azimuth(&self, t: f64) -> Result<(State, f64)> {
        // compiled for the CPU's best instruction set (crate::isa; the numbers are the same at every level)
        crate::isa::fastest(
            #[inline(always)]
            || self.state_and_azimuth_here(t),
        )
    }

    /// [`Self::state_and_azimuth`], inlined into the dispatched caller together with everything it
    /// calls on the way (the Jacobi functions, F and Π, Carlson's R_F, R_J, R_C).
    #[inline(always)]
    fn state_and_azimuth_here(&self, t: f64) -> Result<(State, f64)> {
        if !t.is_finite() {
            return Err(Error::InvalidParameter { name: "t", value: t, allowed: "a finite time in s" });
        }
        let l = self.params.length;
        let s0 = &self.start;
        match &self.flow {
            Flow::Rest => Ok((*s0, s0.x.y.atan2(s0.x.x))),
            Flow::GreatCircle { omega } => {
                let (sw, cw) = (omega * t).sin_cos();
                let x = s0.x * cw + s0.v * (sw / omega);
                let v = s0.v * cw - s0.x * (omega * sw);
                Ok((State { x, v }, x.y.atan2(x.x)))
            }
            Flow::Planar(p) => Ok(self.to_si(p.at(self.omega0 * t)?, l)),
            Flow::Generic(g) => Ok(self.to_si(g.at(self.omega0 * t)?, l)),
        }
    }

    /// States and continuous azimuths at many times \[s\]; long arrays are split over all cores
    /// (feature `parallel`, on by default) in batches of [`BATCH`] times, each batch's loop compiled
    /// for the CPU's best instruction set ([`crate::isa`]). Fails on a non-finite time.
    pub fn states_at(&self, t: &[f64]) -> Result<Vec<(State, f64)>> {
        #[cfg(feature = "parallel")]
        if t.len() >= 4 * BATCH {
            use rayon::prelude::*;
            let parts: Vec<Vec<(State, f64)>> =
                t.par_chunks(BATCH).map(|c| self.batch(c)).collect::<Result<_>>()?;
            return Ok(parts.concat());
        }
        self.batch(t)
    }

    /// The states at the times `t` [s], in one dispatched loop.
    fn batch(&self, t: &[f64]) -> Result<Vec<(State, f64)>> {
        crate::isa::fastest(
            #[inline(always)]
            || t.iter().map(|&ti| self.state_and_azimuth_here(ti)).collect(),
        )
    }

    #[inline(always)]
    fn to_si(&self, u: UnitState, l: f64) -> (State, f64) {
        let lw = l * self.omega0;
        let x = DVec3::new(u.x[0] * l, u.x[1] * l, self.mirror * u.x[2] * l);
        let v = DVec3::new(u.v[0] * lw, u.v[1] * lw, self.mirror * u.v[2] * lw);
        (State { x, v }, u.phi)
    }

    /// Turning heights \[m\], ascending: (z₁, z₂) between which z moves, and z₃ (the third root of
    /// T-4.1, outside [−l, l]) for the generic case. For planar motion (−l, z₂) or (−l, l).
    pub fn turning_heights(&self) -> (f64, f64, Option<f64>) {
        let l = self.params.length;
        let mz = |u: f64| self.mirror * u * l;
        let sorted = |a: f64, b: f64| if a <= b { (a, b) } else { (b, a) };
        match &self.flow {
            Flow::Rest => (self.start.x.z, self.start.x.z, None),
            Flow::GreatCircle { omega } => {
                let amp = (self.start.x.z.powi(2) + (self.start.v.z / omega).powi(2)).sqrt().min(l);
                (-amp, amp, None)
            }
            Flow::Planar(p) => {
                let top = match p.motion {
                    PlanarMotion::Libration => -1.0 + 2.0 * p.m,
                    _ => 1.0,
                };
                let (a, b) = sorted(mz(-1.0), mz(top));
                (a, b, None)
            }
            Flow::Generic(g) => {
                let [r1, r2, r3] = g.roots;
                let (a, b) = sorted(mz(g.start.value(r1)), mz(g.start.value(r2)));
                (a, b, Some(mz(g.start.value(r3))))
            }
        }
    }

    /// The parameter m = k² of the Jacobi functions (None for rest and great circles).
    pub fn modulus(&self) -> Option<f64> {
        match &self.flow {
            Flow::Planar(p) => Some(p.m),
            Flow::Generic(g) => Some(g.m),
            _ => None,
        }
    }

    /// The period of z(t) \[s\]: T-4.3 (generic), 4K/ω₀ for a planar swing (z itself repeats after
    /// half of it, 2K/ω₀; the swing period is returned), one revolution over the top, 2π/ω on a great
    /// circle; ∞ on the separatrix; None at rest and on an exactly conical orbit's constant z.
    pub fn period_z(&self) -> Option<f64> {
        match &self.flow {
            Flow::Rest => None,
            Flow::GreatCircle { omega } => Some(2.0 * std::f64::consts::PI / omega),
            Flow::Planar(p) => Some(p.period_tau() / self.omega0),
            Flow::Generic(g) => Some(g.period_tau() / self.omega0),
        }
    }

    /// Azimuthal advance per z-period Δφ \[rad\] (T-4.5) for generic and conical orbits; None otherwise.
    pub fn azimuth_advance(&self) -> Option<f64> {
        match &self.flow {
            Flow::Generic(g) => Some(g.delta_phi),
            _ => None,
        }
    }

    /// The generic orbit's constants (roots, m, λ, n±, …), for the phases and tests.
    pub fn generic(&self) -> Option<&Generic> {
        match &self.flow {
            Flow::Generic(g) => Some(g),
            _ => None,
        }
    }

    /// ω₀ = √(|g|/l) [1/s].
    pub fn omega0(&self) -> f64 {
        self.omega0
    }

    /// The Weierstrass form of the height (T-4.7, [`weierstrass`]), dimensionless (u = z/l, or −z/l
    /// when g < 0; τ = ω₀t): invariants g₂, g₃, roots e₁ ≥ e₂ ≥ e₃ and the real half-period ω₁.
    /// None at rest and on a great circle (g = 0), where there is no cubic.
    pub fn weierstrass(&self) -> Option<Weierstrass> {
        self.cubic.as_ref().map(Weierstrass::new)
    }

    /// The height z(t) \[m\] and its rate ż(t) [m/s] from the Weierstrass form, an independent second
    /// path to the z of [`state`](Self::state); None where [`weierstrass`](Self::weierstrass) is
    /// None.
    pub fn height_weierstrass(&self, t: &[f64]) -> Result<Option<Vec<(f64, f64)>>> {
        if let Some(&bad) = t.iter().find(|ti| !ti.is_finite()) {
            return Err(Error::InvalidParameter { name: "t", value: bad, allowed: "a finite time in s" });
        }
        let Some(w) = self.weierstrass() else { return Ok(None) };
        let (l, lw) = (self.params.length, self.params.length * self.omega0);
        Ok(Some(
            t.iter()
                .map(|&ti| {
                    let (u, u_tau) = w.at(self.omega0 * ti);
                    (self.mirror * u * l, self.mirror * u_tau * lw)
                })
                .collect(),
        ))
    }
}
